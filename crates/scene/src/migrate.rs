//! The old flight-scene form (a file with an `[aircraft]` table, bare numbers in ft, slug,
//! lbf) is no longer read: an aircraft is a free body with `aero` and `thrust` effects in the
//! one scene format. A file in the old form is refused with the same scene written in the new
//! form, so that nothing the user wrote is reinterpreted silently or lost.
//!
//! What maps: `name`, `duration`, `view`; `samples` (rows, both ends) → intervals (rows − 1);
//! `accuracy` (the old DOP853 tolerance, rtol = atol) → `method = { name = "dop853", rtol }`; the
//! `[aircraft]` model → `mass = { shape = "aircraft" }` and the `aero` effect, its overrides →
//! `mass = { shape = "value" }`, the `aero` effect's `rho`, `area`, `chord`, `span`,
//! `coefficients`, the gravity effect and the thrust `angle`; `[trim]` → the body's initial
//! velocity along the flight path and `trim.free` (pitch, elevator, thrust; a turn adds the
//! attitude, body rates, aileron and rudder with `trim.hold` for β = 0 and ω = Ψ̇ ẑ);
//! `[[inputs]]` → the effects' control profiles; outputs → the body's outputs. Bare numbers
//! are written with the old form's units as quantity strings; quantity strings are kept.
//!
//! Book: §12.1 (trim conditions), §14.2 (control inputs), §15.19 (units).

use std::fmt::Write;

use toml::Value;

/// The body that the translation names.
const BODY: &str = "aircraft";

/// The message of the error for an old flight-scene file: what changed and the file in the
/// new form.
pub(crate) fn message(doc: &Value) -> String {
    format!(
        "`[aircraft]` is the old flight-scene form, which is no longer read: an aircraft is now a free \
         body with `aero` and `thrust` effects in the one scene format, where a bare number is SI (the old \
         form's were ft, slug, lbf; the text below states them as quantity strings). Valid: this file \
         written in the new form (docs/scenes.md, \"Aircraft\"):\n\n{}",
        translate(doc)
    )
}

/// A value as written: a bare number with the old form's `unit`, a quantity string as is.
fn quantity(v: &Value, unit: &str) -> String {
    // seconds and radians are SI already: the number stands alone
    let unit = if matches!(unit, "s" | "rad" | "rad/s") { "" } else { unit };
    match v {
        Value::Float(x) if unit.is_empty() => format!("{x:?}"),
        Value::Float(x) => format!("\"{x:?} {unit}\""),
        Value::Integer(x) if unit.is_empty() => format!("{x}"),
        Value::Integer(x) => format!("\"{x} {unit}\""),
        other => other.to_string(),
    }
}

/// A value in SI, for the arithmetic of the flight path (a bare number in `unit`, or a
/// quantity string).
fn si(v: Option<&Value>, unit: &str, dim: vectrix_units::Dimension) -> Option<f64> {
    let text = match v? {
        Value::Float(x) => format!("{x:?} {unit}"),
        Value::Integer(x) => format!("{x} {unit}"),
        Value::String(s) => s.clone(),
        _ => return None,
    };
    vectrix_units::Quantity::parse(text.trim()).ok()?.to_si(dim).ok()
}

/// The old output names and what replaces each.
fn output(name: &str) -> Result<String, String> {
    let o = |kind: &str| Ok(format!("{kind}:{BODY}"));
    match name {
        "x" | "y" | "z" => o("position"),
        "u" | "v" | "w" => o("velocity_body"),
        "phi" | "theta" | "psi" => o("euler321"),
        "p" | "q" | "r" => o("omega_body"),
        "alpha" | "beta" | "airspeed" => o("air"),
        "gamma" => Err("`gamma` has no column: γ = asin(−ż/V) from `velocity:aircraft`".into()),
        "elevator" | "aileron" | "rudder" | "thrust" => {
            Err(format!("`{name}` has no column: it is the effect's profile, written below"))
        }
        other => Err(format!("`{other}` was not an output of the old form either")),
    }
}

/// The scene of an old flight file, written in the new form.
pub(crate) fn translate(doc: &Value) -> String {
    let get = |k: &str| doc.get(k);
    let mut t = String::new();
    let mut notes = Vec::new();
    let name = get("name").map_or("\"aircraft\"".to_string(), Value::to_string);
    let _ = writeln!(t, "name = {name}");
    if let Some(d) = get("duration") {
        let _ = writeln!(t, "duration = {}", quantity(d, "s"));
    }
    match get("samples") {
        Some(Value::Integer(n)) if *n >= 2 => {
            let _ = writeln!(t, "samples = {}   # intervals: the old form counted rows", n - 1);
        }
        Some(other) => notes.push(format!("`samples = {other}` was not a whole number ≥ 2 (rows)")),
        None => {
            let _ = writeln!(t, "samples = 600   # the old form's default of 601 rows");
        }
    }
    if let Some(a) = get("accuracy") {
        let a = quantity(a, "");
        let _ = writeln!(t, "method = {{ name = \"dop853\", rtol = {a} }}   # atol = rtol, as before");
    }
    if let Some(Value::Boolean(false)) = get("view") {
        let _ = writeln!(t, "view = false");
    }
    // outputs: each old name → its body output, once
    let old: Vec<String> = match get("outputs") {
        Some(Value::Array(a)) => a.iter().map(|v| v.as_str().unwrap_or("?").to_string()).collect(),
        _ => ["u", "alpha", "q", "theta"].map(String::from).to_vec(),
    };
    let mut outs: Vec<String> = Vec::new();
    for o in &old {
        match output(o) {
            Ok(n) if !outs.contains(&n) => outs.push(n),
            Ok(_) => {}
            Err(note) => notes.push(note),
        }
    }
    if get("trim").and_then(|x| x.get("turn_rate")).is_some() {
        // the turn's `trim.hold` reads these columns
        for o in [format!("air:{BODY}"), format!("omega:{BODY}")] {
            if !outs.contains(&o) {
                outs.push(o);
            }
        }
    }
    let outs: Vec<String> = outs.iter().map(|o| format!("\"{o}\"")).collect();
    let _ = writeln!(t, "outputs = [{}]", outs.join(", "));
    trim_section(&mut t, get("trim").and_then(|x| x.get("turn_rate")), &mut notes);
    body_section(&mut t, doc, &mut notes);
    effects_section(&mut t, doc, &mut notes);
    for n in notes {
        let _ = writeln!(t, "# note: {n}");
    }
    t
}

/// `[trim]`: pitch, elevator and thrust for straight flight; a turn frees the attitude, the
/// body rates and all controls and holds β = 0 and ω = Ψ̇ ẑ (§12.1).
fn trim_section(t: &mut String, turn_rate: Option<&Value>, notes: &mut Vec<String>) {
    let b = BODY;
    match turn_rate {
        None => {
            let _ =
                writeln!(t, "trim = {{ free = [\"dq:{b}.4\", \"effects[1].elevator\", \"effects[2]\"] }}");
        }
        Some(rate) => {
            let _ = writeln!(t, "\n[trim]");
            let _ = writeln!(
                t,
                "free = [\"dq:{b}.3\", \"dq:{b}.4\", \"dq:{b}.5\", \"v:{b}.3\", \"v:{b}.4\", \"v:{b}.5\",\n        \
                 \"effects[1].elevator\", \"effects[1].aileron\", \"effects[1].rudder\", \"effects[2]\"]"
            );
            let rate = match rate {
                Value::String(_) => rate.to_string(),
                other => quantity(other, "rad/s"),
            };
            let _ = writeln!(
                t,
                "hold = {{ \"air:{b}.beta\" = 0.0, \"omega:{b}.x\" = 0.0, \"omega:{b}.y\" = 0.0, \"omega:{b}.z\" = {rate} }}"
            );
            if !rate.starts_with(|c: char| c.is_ascii_digit() || c == '-') {
                notes.push("`trim.hold` takes SI numbers: write the turn rate in rad/s".into());
            }
        }
    }
}

/// `[[bodies]]`: the free body, its airframe and its initial velocity along the flight path.
fn body_section(t: &mut String, doc: &Value, notes: &mut Vec<String>) {
    use vectrix_units::Dimension as D;
    let ac = doc.get("aircraft");
    let acv = |k: &str| ac.and_then(|a| a.get(k));
    let model = acv("model").and_then(Value::as_str).unwrap_or("business_jet");
    let _ = writeln!(t, "\n[[bodies]]\nname = \"{BODY}\"\njoint = {{ type = \"free\" }}");
    match (acv("mass"), acv("inertia")) {
        (None, None) => {
            let _ = writeln!(t, "mass = {{ shape = \"aircraft\", model = \"{model}\" }}");
        }
        (m, j) => {
            let cat = super::aero::catalogue(model);
            let (mass, inertia) = match &cat {
                Some(c) => {
                    let (jx, jy, jz, jxz) = c.airframe.inertia();
                    (format!("\"{:?} kg\"", c.airframe.mass()), [jx, jy, jz, jxz].map(|x| format!("{x:?}")))
                }
                None => ("?".into(), ["?".to_string(), "?".into(), "?".into(), "?".into()]),
            };
            let mass = m.map_or(mass, |m| quantity(m, "slug"));
            let j: [String; 4] = match j.and_then(Value::as_array) {
                Some(a) if a.len() == 4 => std::array::from_fn(|k| quantity(&a[k], "slug*ft^2")),
                _ => inertia.map(|x| format!("\"{x} kg m^2\"")),
            };
            let neg = |s: &str| match s.strip_prefix('"') {
                Some(r) if r.starts_with('-') => format!("\"{}", &r[1..]),
                Some(r) => format!("\"-{r}"),
                None => format!("-{s}"),
            };
            let _ = writeln!(
                t,
                "mass = {{ shape = \"value\", mass = {mass}, matrix = [[{}, 0.0, {}], [0.0, {}, 0.0], [{}, 0.0, {}]] }}",
                j[0],
                neg(&j[3]),
                j[1],
                neg(&j[3]),
                j[2]
            );
        }
    }
    let trim = doc.get("trim");
    let airspeed = trim.and_then(|t| t.get("airspeed"));
    let gamma = trim.and_then(|t| t.get("gamma"));
    let speed = match (airspeed, gamma) {
        (Some(v), None) => format!("{}, 0.0, 0.0", quantity(v, "ft/s")),
        (Some(v), Some(g)) if g.as_float() == Some(0.0) || g.as_integer() == Some(0) => {
            format!("{}, 0.0, 0.0", quantity(v, "ft/s"))
        }
        (v, g) => match (si(v, "ft/s", D::VELOCITY), si(g, "rad", D::ANGLE)) {
            (Some(v), Some(g)) => format!("\"{:?} m/s\", 0.0, \"{:?} m/s\"", v * g.cos(), -v * g.sin()),
            _ => {
                notes.push("`trim.airspeed` or `trim.gamma` could not be read; write v by hand".into());
                "0.0, 0.0, 0.0".into()
            }
        },
    };
    let _ = writeln!(t, "v = [{speed}, 0.0, 0.0, 0.0]   # ground velocity (z down) and ω");
}

/// The control channels of the old `[[inputs]]`, as (control, profile text).
fn inputs(doc: &Value, notes: &mut Vec<String>) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    let Some(Value::Array(items)) = doc.get("inputs") else { return out };
    for (k, i) in items.iter().enumerate() {
        let s = |f: &str| i.get(f).and_then(Value::as_str).unwrap_or("?").to_string();
        let (control, shape) = (s("control"), s("shape"));
        let unit = if control == "thrust" { "lbf" } else { "" };
        let num = |f: &str, u: &str| i.get(f).map_or("0.0".to_string(), |v| quantity(v, u));
        let (start, width, amp) = (num("start", "s"), num("width", "s"), num("amplitude", unit));
        let profile = match shape.as_str() {
            "doublet" | "pulse" => {
                format!("{{ kind = \"{shape}\", start = {start}, width = {width}, amplitude = {amp} }}")
            }
            "step" => format!("{{ kind = \"step\", at = {start}, after = {amp} }}"),
            other => {
                notes.push(format!("inputs[{k}] has shape `{other}`: valid were doublet, step, pulse"));
                continue;
            }
        };
        if out.iter().any(|(c, _)| *c == control) {
            notes.push(format!(
                "inputs[{k}] is a second `{control}` input: profiles do not add; write the sum as a `table` profile"
            ));
            continue;
        }
        out.push((control, profile));
    }
    out
}

/// `[[effects]]`: gravity, the aerodynamics with the controls, and the thrust.
fn effects_section(t: &mut String, doc: &Value, notes: &mut Vec<String>) {
    let ac = doc.get("aircraft");
    let acv = |k: &str| ac.and_then(|a| a.get(k));
    let model = acv("model").and_then(Value::as_str).unwrap_or("business_jet");
    let controls = inputs(doc, notes);
    let g = acv("g").map_or("\"32.2 ft/s^2\"".into(), |g| quantity(g, "ft/s^2"));
    let _ = writeln!(t, "\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, 0.0, {g}]");
    let _ = writeln!(t, "\n[[effects]]\ntype = \"aero\"\nbody = \"{BODY}\"\naircraft = \"{model}\"");
    for (key, unit) in [("rho", "slug/ft^3"), ("area", "ft^2"), ("chord", "ft"), ("span", "ft")] {
        if let Some(v) = acv(key) {
            let _ = writeln!(t, "{key} = {}", quantity(v, unit));
        }
    }
    if let Some(Value::Table(c)) = acv("coefficients") {
        let items: Vec<String> = c
            .iter()
            .map(|(k, v)| format!("{k} = {}", quantity(v, if k == "u_ref" { "ft/s" } else { "" })))
            .collect();
        let _ = writeln!(t, "coefficients = {{ {} }}", items.join(", "));
    }
    for (control, profile) in controls.iter().filter(|(c, _)| c != "thrust") {
        let _ = writeln!(t, "{control} = {profile}");
    }
    let _ = writeln!(t, "\n[[effects]]\ntype = \"thrust\"\nbody = \"{BODY}\"");
    match controls.iter().find(|(c, _)| c == "thrust") {
        Some((_, p)) => {
            let _ = writeln!(t, "profile = {p}");
        }
        None => {
            let _ = writeln!(t, "profile = {{ kind = \"constant\", value = 0.0 }}   # the trim sets it");
        }
    }
    if let Some(a) = acv("thrust_angle") {
        let _ = writeln!(t, "angle = {}", quantity(a, "rad"));
    }
}
