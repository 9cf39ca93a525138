//! Quantities in scene files: wherever a scene takes a number it also takes a quantity string
//! `"<number> <unit>"` (`mass = "2.2046226218487757 lb"`, `q = ["30 deg"]`,
//! `g = ["0 ft/s^2", "-32.174 ft/s^2", "0 m/s^2"]`), converted exactly (`vectrix_units`) into
//! the number the key means; a bare number keeps its meaning (SI, radians for angles, in body
//! scenes). Every numeric key has an expected dimension: a string of another dimension, an
//! unknown unit or a malformed quantity is an error at the character where it goes wrong.
//!
//! Book: §15.19 (dimensions and units).

use vectrix_units::{Dimension, Quantity, UnitSystem};

use super::path::{ItemPath, PathSeg};
use super::tree::{Node, NodeValue};
use super::{SceneError, SceneSource};

/// The dimensions a numeric position accepts (the first is the one named in messages) and
/// the unit system its bare numbers are in.
///
/// Book: §15.19.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expect {
    /// Accepted dimensions; a quantity is converted with the first that matches.
    pub dims: &'static [Dimension],
    /// The system the converted number is written in (SI for body scenes).
    pub system: UnitSystem,
}

/// The schema of a kind of scene file: the expected dimensions of the number at `path`, given
/// the whole document (to read a joint's or an effect's `type`).
pub type Schema<'a> = dyn Fn(&ItemPath, &Node) -> Option<Expect> + 'a;

/// Converts every quantity string at a numeric position of `doc` (a document of `src`) into
/// its number; returns how many were converted.
///
/// Book: §15.19.
///
/// # Errors
/// [`SceneError::Invalid`] located at the offending character of the string: unknown unit,
/// malformed quantity, a dimension other than the key's, overflow.
pub fn convert(src: &SceneSource, doc: &mut Node, schema: &Schema) -> Result<usize, SceneError> {
    // the schema reads tags (`type`), which are never numbers: a copy of the document as it
    // was answers for every position
    let root = doc.clone();
    convert_on(src, doc, &root, schema)
}

/// [`convert`] with the document the schema reads given (`root`: `doc` before conversion, or
/// any document with the same tags).
pub(crate) fn convert_on(
    src: &SceneSource,
    doc: &mut Node,
    root: &Node,
    schema: &Schema,
) -> Result<usize, SceneError> {
    let mut count = 0;
    walk(src, doc, &mut ItemPath::root(), root, schema, &mut count)?;
    Ok(count)
}

fn walk(
    src: &SceneSource,
    v: &mut Node,
    path: &mut ItemPath,
    root: &Node,
    schema: &Schema,
    count: &mut usize,
) -> Result<(), SceneError> {
    match &mut v.value {
        NodeValue::Table(t) => {
            for e in t.iter_mut() {
                path.push(PathSeg::Key(e.key.clone()));
                walk(src, &mut e.node, path, root, schema, count)?;
                path.pop();
            }
        }
        NodeValue::Array(a) => {
            for (i, x) in a.iter_mut().enumerate() {
                path.push(PathSeg::Index(i));
                walk(src, x, path, root, schema, count)?;
                path.pop();
            }
        }
        NodeValue::String(s) => {
            if let Some(expect) = schema(path, root) {
                let x = quantity(src, s, v.span.clone(), path, expect)?;
                v.value = NodeValue::Float(x);
                *count += 1;
            }
        }
        _ => {}
    }
    Ok(())
}

/// The number a quantity string (whose literal spans `literal`) stands for, or an error
/// located inside the string.
fn quantity(
    src: &SceneSource,
    text: &str,
    literal: std::ops::Range<usize>,
    path: &ItemPath,
    expect: Expect,
) -> Result<f64, SceneError> {
    let fail = |e: vectrix_units::UnitError| {
        let at = e.span_in_source(src.text(), literal.clone());
        let expected = expect.dims[0];
        let name = expected.name().map(|n| format!("{n}, ")).unwrap_or_default();
        src.invalid_at(
            at.start,
            path,
            format!(
                "{}; valid: a number, or a quantity string of {name}e.g. \"1 {}\"",
                super::error::unit_message(&e),
                expect.system.label(expected)
            ),
        )
    };
    let q = Quantity::parse(text).map_err(fail)?;
    let dim = expect.dims.iter().copied().find(|d| *d == q.dimension()).unwrap_or(expect.dims[0]);
    let si = q.to_si(dim).map_err(fail)?;
    expect.system.value_from_si(dim, si).map_err(fail)
}

/// Reads the `type` (or another tag) of the table at `path` in `root`.
///
/// Book: — (file format).
pub fn tag<'v>(root: &'v Node, path: &ItemPath, key: &str) -> Option<&'v str> {
    root.at(path)?.get(key)?.as_str()
}

const fn si(dims: &'static [Dimension]) -> Option<Expect> {
    Some(Expect { dims, system: UnitSystem::Si })
}

const ONE: &[Dimension] = &[Dimension::DIMENSIONLESS];
const TIME: &[Dimension] = &[Dimension::TIME];
const LENGTH: &[Dimension] = &[Dimension::LENGTH];
const AREA: &[Dimension] = &[Dimension::AREA];
const MASS: &[Dimension] = &[Dimension::MASS];
const ANGLE: &[Dimension] = &[Dimension::ANGLE];
const VELOCITY: &[Dimension] = &[Dimension::VELOCITY];
const ANGULAR_VELOCITY: &[Dimension] = &[Dimension::ANGULAR_VELOCITY, Dimension::FREQUENCY];
const ACCELERATION: &[Dimension] = &[Dimension::ACCELERATION];
const INERTIA: &[Dimension] = &[Dimension::MOMENT_OF_INERTIA];
const FORCE: &[Dimension] = &[Dimension::FORCE];
const MOMENT: &[Dimension] = &[Dimension::MOMENT];
/// Rotational coefficients: per radian, or with the radian left out (as SI writes them).
const KAPPA: &[Dimension] = &[Dimension::ROTATIONAL_STIFFNESS, Dimension::MOMENT];
const XI: &[Dimension] = &[Dimension::ROTATIONAL_DAMPING, Dimension::new(1, 2, -1, 0)];
const BETA: &[Dimension] = &[Dimension::new(1, 2, 0, -1), Dimension::MOMENT_OF_INERTIA];
const MU: &[Dimension] = &[Dimension::GRAVITATIONAL_PARAMETER];
const BIG_G: &[Dimension] = &[Dimension::new(-1, 3, -2, 0)];
const STIFFNESS: &[Dimension] = &[Dimension::STIFFNESS];
const DAMPING: &[Dimension] = &[Dimension::DAMPING];
const DENSITY: &[Dimension] = &[Dimension::new(1, -3, 0, 0)];

/// The schema of body scenes (docs/scenes.md lists the unit of every key).
///
/// Book: §15.19.
pub fn body_schema(path: &ItemPath, root: &Node) -> Option<Expect> {
    let seg = path.segments();
    let keys: Vec<Option<&str>> = seg.iter().map(PathSeg::key).collect();
    match keys.as_slice() {
        [Some("duration")] | [Some("max_wall_seconds")] => si(TIME),
        [Some("accuracy")] | [Some("method"), Some("rtol")] => si(ONE),
        [Some("frames"), None, Some("angle")] => si(ANGLE),
        [Some("frames"), None, Some("axis"), None] => si(ONE),
        [Some("bodies"), None, Some("offset" | "com"), None] => si(LENGTH),
        [Some("bodies"), None, Some("joint"), Some("axis" | "direction"), None] => si(ONE),
        [Some("bodies"), None, Some("mass"), Some("mass")] => si(MASS),
        [Some("bodies"), None, Some("mass"), Some("radius" | "length")] => si(LENGTH),
        [Some("bodies"), None, Some("mass"), Some("sides"), None] => si(LENGTH),
        [Some("bodies"), None, Some("mass"), Some("principal"), None] => si(INERTIA),
        [Some("bodies"), None, Some("mass"), Some("matrix"), None, None] => si(INERTIA),
        [Some("bodies"), None, Some(qv @ ("q" | "v")), None] => {
            let (Some(b), Some(j)) = (seg[1].index(), seg[3].index()) else { return None };
            let joint = tag(root, &ItemPath::root().key("bodies").index(b).key("joint"), "type")?;
            let speed = *qv == "v";
            let (lin, ang) = if speed { (VELOCITY, ANGULAR_VELOCITY) } else { (LENGTH, ANGLE) };
            let d = match (joint, j) {
                ("pin", _) => ang,
                ("sleeve", _) => lin,
                ("collar" | "slot", 0) => lin,
                ("collar" | "slot", _) => ang,
                ("ball", _) if speed => ang,
                ("ball", _) => ONE,
                ("free", 0..3) => lin,
                ("free", _) if speed => ang,
                ("free", _) => ONE,
                _ => return None,
            };
            si(d)
        }
        [Some("loops"), None, Some("a" | "b"), Some("point"), None] => si(LENGTH),
        [Some("loops"), None, Some("axis" | "direction" | "normal"), None] => si(ONE),
        [Some("effects"), None, rest @ ..] => {
            let e = seg[1].index()?;
            let kind = tag(root, &ItemPath::root().key("effects").index(e), "type")?;
            effect_schema(kind, rest)
        }
        _ => None,
    }
}

fn effect_schema(kind: &str, rest: &[Option<&str>]) -> Option<Expect> {
    let profile_value = match kind {
        "force" | "thrust" => FORCE,
        "torque" => MOMENT,
        "aero" => ANGLE,
        _ => ONE,
    };
    let profile = |tail: &[Option<&str>]| match tail {
        [Some("at" | "t0" | "t1" | "start" | "width")] | [Some("t"), None] => si(TIME),
        [Some("value" | "before" | "after" | "from" | "to" | "amplitude" | "offset")]
        | [Some("value"), None] => si(profile_value),
        [Some("omega")] => si(ANGULAR_VELOCITY),
        [Some("phase")] => si(ANGLE),
        _ => None,
    };
    match (kind, rest) {
        ("uniform_gravity", [Some("g"), None]) => si(ACCELERATION),
        ("central_gravity", [Some("mu")]) => si(MU),
        ("central_gravity", [Some("centre"), None]) => si(LENGTH),
        ("mutual_gravitation", [Some("g")]) => si(BIG_G),
        ("spring", [Some("k")]) => si(STIFFNESS),
        ("spring", [Some("length")]) => si(LENGTH),
        ("dashpot", [Some("c")]) => si(DAMPING),
        ("inerter", [Some("inertance")]) => si(MASS),
        (_, [Some("a" | "b" | "at"), Some("point"), None]) => si(LENGTH),
        ("rotational_spring", [Some("kappa")]) => si(KAPPA),
        ("rotational_spring", [Some("angle")]) => si(ANGLE),
        ("rotational_dashpot", [Some("xi")]) => si(XI),
        ("rotational_inerter", [Some("beta")]) => si(BETA),
        ("dipoles", [Some("dipoles"), None, Some("moment"), None]) => si(ONE),
        ("force" | "torque", [Some("direction"), None]) => si(ONE),
        ("force" | "torque" | "thrust", [Some("profile"), tail @ ..]) => profile(tail),
        ("aero", [Some("elevator" | "aileron" | "rudder"), tail @ ..]) => profile(tail),
        ("aero", [Some("rho")]) => si(DENSITY),
        ("aero", [Some("area")]) => si(AREA),
        ("aero", [Some("chord" | "span")]) => si(LENGTH),
        ("aero", [Some("coefficients"), Some("u_ref")]) => si(VELOCITY),
        ("aero", [Some("coefficients"), Some(_)]) => si(ONE),
        ("thrust", [Some("angle")]) => si(ANGLE),
        ("contact_spheres", [Some("radius_a" | "radius_b")]) => si(LENGTH),
        ("contact_plane" | "rolling", [Some("radius")]) => si(LENGTH),
        ("contact_plane" | "rolling", [Some("point"), None]) => si(LENGTH),
        ("contact_plane" | "rolling", [Some("normal"), None]) => si(ONE),
        ("contact_spheres" | "contact_plane", [Some("restitution" | "friction")]) => si(ONE),
        _ => None,
    }
}
