//! The frontier's table: each tool's time to reach an error level, and the speed-ups of
//! vectrix's routes over the fastest compiled peer and over the fastest Python-driven peer,
//! separately (issue 39: the compiled peers have no interpreter between the peer and its
//! integrator, so their margin is the honest one).

use std::collections::BTreeMap;
use std::path::Path;

use serde_json::Value;

use crate::PROBLEMS;
use crate::problems::CHAIN_NS;
use crate::report::{Pt, family_time, fmt_time};

/// Target errors of the table.
pub const LEVELS: [f64; 4] = [1e-3, 1e-6, 1e-9, 1e-12];

/// Families in table order, with their names in the table.
pub const FAMILIES: [(&str, &str); 8] = [
    ("vectrix library", "vectrix (library)"),
    ("vectrix scene", "vectrix (scene file)"),
    ("odeint", "Boost.Odeint, C++ (Pinocchio ABA / hand-written RHS)"),
    ("mujoco-c", "MuJoCo C API (`mj_step` loop in C)"),
    ("mujoco", "MuJoCo from Python (`mj_step(nstep)`)"),
    ("scipy", "scipy solve_ivp (numpy RHS)"),
    ("pinocchio", "Pinocchio ABA + solve_ivp"),
    ("sympy", "sympy.physics.mechanics + solve_ivp"),
];

/// The peers with no interpreter between the peer and its integrator.
pub const COMPILED: [&str; 2] = ["odeint", "mujoco-c"];

/// The series name without its tool prefix.
fn short(series: &str) -> &str {
    [
        "vectrix scene ",
        "vectrix ",
        "Odeint ",
        "MuJoCo C ",
        "mujoco ",
        "MuJoCo ",
        "scipy ",
        "pinocchio+",
        "sympy+",
    ]
    .iter()
    .find_map(|p| series.strip_prefix(p))
    .unwrap_or(series)
}

/// How far each problem's reference can be trusted: the uncertainty `reference.json` states
/// for it. The chains: the extended-precision reference's convergence difference or the
/// rounding of its doubles (~1e-16). The body, Kepler and the pendulum: the distance of
/// vectrix's double-precision closed forms (which its routes measure against) to the
/// extended-precision end states (which the peers measure against). `reference_check.json`
/// (from `check_reference.py`) holds checks of the peers' tools, not of the reference.
pub fn reference_floors(data: &Path) -> BTreeMap<String, f64> {
    let reference: Value = std::fs::read_to_string(data.join("reference.json"))
        .ok()
        .and_then(|s| serde_json::from_str(&s).ok())
        .unwrap_or(Value::Null);
    CHAIN_NS
        .iter()
        .map(|n| format!("chain-{n}"))
        .chain(["rigid-body", "kepler-e0.9", "pendulum"].map(str::to_string))
        .filter_map(|id| reference[&id]["uncertainty"].as_f64().map(|u| (id, u)))
        .collect()
}

/// The machine, date and load of each tool's sitting.
fn sittings(tools: &[Value]) -> String {
    let mut s = String::new();
    s += "Machine, date and load of each tool's sitting (1-minute load average at its start and end):\n\n";
    s += "| tool | machine | date (UTC) | load start → end |\n|---|---|---|---|\n";
    for t in tools {
        let load = |k: &str| {
            t[k].as_array()
                .and_then(|a| a.first())
                .and_then(Value::as_f64)
                .map_or("?".into(), |x| format!("{x:.1}"))
        };
        s += &format!(
            "| {} | {} | {} | {} → {} |\n",
            t["tool"].as_str().unwrap_or("?"),
            t["machine"].as_str().unwrap_or("?"),
            t["date"].as_str().unwrap_or("?"),
            load("load_start"),
            load("load_end")
        );
    }
    s
}

/// The whole table: the sittings, then per problem a row per family and the speed-up rows.
pub fn table(pts: &[Pt], tools: &[Value], floors: &BTreeMap<String, f64>) -> String {
    let mut s = sittings(tools);
    s += "\nTime to reach a given error (the fastest method of each tool; ≤: even its cheapest run is that \
          accurate, so the time is an upper bound; blank: no run reached it). The speed-up rows divide the \
          fastest peer's time by vectrix's: over the compiled peers (Odeint, MuJoCo's C API) and over the \
          Python-driven ones (MuJoCo from Python, scipy, Pinocchio + scipy, sympy), separately.\n";
    for (id, title, _) in PROBLEMS {
        if !pts.iter().any(|p| p.problem == id) {
            continue;
        }
        s += &format!("\n**{title}** (`peers-{id}.svg`)");
        if let Some(u) = floors.get(id) {
            s += &format!("; reference checked to {u:.1e}");
        }
        s += "\n\n| tool | 1e-3 | 1e-6 | 1e-9 | 1e-12 |\n|---|---|---|---|---|\n";
        let mut best: BTreeMap<&str, [Option<f64>; 4]> = BTreeMap::new();
        for (fam, label) in FAMILIES {
            if !pts.iter().any(|p| p.problem == id && p.family() == fam) {
                continue;
            }
            let mut row = format!("| {label} |");
            let mut times = [None; 4];
            for (k, &lvl) in LEVELS.iter().enumerate() {
                // an error level within 10× of the reference's own uncertainty is not measured
                if floors.get(id).is_some_and(|u| *u > 0.1 * lvl) {
                    row += " (below the reference's accuracy) |";
                    continue;
                }
                match family_time(pts, id, fam, lvl) {
                    Some((t, ub, series)) => {
                        times[k] = Some(t);
                        row +=
                            &format!(" {}{} {} |", if ub { "≤ " } else { "" }, fmt_time(t), short(&series));
                    }
                    None => row += " |",
                }
            }
            best.insert(fam, times);
            s += &row;
            s += "\n";
        }
        s += &speedups(&best);
    }
    s
}

/// The speed-up rows of one problem from each family's times at the four levels.
fn speedups(best: &BTreeMap<&str, [Option<f64>; 4]>) -> String {
    let mut s = String::new();
    let group = |compiled: bool| -> Vec<[Option<f64>; 4]> {
        best.iter()
            .filter(|(f, _)| !f.starts_with("vectrix") && COMPILED.contains(*f) == compiled)
            .map(|(_, t)| *t)
            .collect()
    };
    for (compiled, over) in [(true, "compiled"), (false, "Python-driven")] {
        let peers = group(compiled);
        if peers.is_empty() {
            continue;
        }
        for (fam, route) in [("vectrix library", "library"), ("vectrix scene", "scene")] {
            let Some(ours) = best.get(fam) else { continue };
            let mut row = format!("| *speed-up over {over} peers, {route}* |");
            for k in 0..4 {
                let fastest = peers.iter().filter_map(|p| p[k]).min_by(f64::total_cmp);
                row += &match (ours[k], fastest) {
                    (Some(o), Some(p)) => format!(" {} |", ratio(p / o)),
                    (Some(_), None) => " no peer reaches it |".into(),
                    (None, Some(_)) => " **peer only** |".into(),
                    _ => " |".into(),
                };
            }
            s += &row;
            s += "\n";
        }
    }
    s
}

/// A speed-up with two significant digits (three below 10).
fn ratio(r: f64) -> String {
    if r >= 10.0 { format!("{r:.0}×") } else { format!("{r:.2}×") }
}
