//! The work–precision frontier against every peer (issue 24): what a given accuracy costs in
//! wall time on each problem, for vectrix (library and scenes) and for MuJoCo, scipy's
//! `solve_ivp`, Pinocchio + scipy and the sympy.physics.mechanics pipeline (the Python side is
//! `scripts/peers/frontier_*.py`; everything is run by `scripts/peers/frontier.sh`).
//!
//! ```sh
//! cargo run --release --example frontier -- run  [--quick] [--out DIR] [--only a,b] [--cap S]
//! cargo run --release --example frontier -- plot [--data DIR] [--svg DIR] [--doc docs/frontier.md]
//! ```
//!
//! `run` writes `DIR/reference.json` (the chains' reference end states: the
//! extended-precision reference (scripts/peers/chain_reference_mp.py, committed as
//! `tests/data/chain_reference_mp.json`), with vectrix's DOP853 at 1e-13 beside it as a check)
//! and `DIR/vectrix.json` (the points); `plot` reads every `DIR/*.json` tool file, draws
//! `peers-<problem>.svg` and writes the time-to-error table between the markers
//! `<!-- frontier-table:begin -->` and `<!-- frontier-table:end -->` of the document. The
//! default DIR is `docs/accuracy/peers-data`, the default SVG folder `docs/accuracy`.
//! A timing harness, not a test: medians of repeated whole runs (see `timing.rs`).
//! `FRONTIER_ROUTE=scene` (or `library`) times that route alone, e.g. two builds of the scene
//! route back to back in one sitting.

mod problems;
mod report;
mod routes;
mod table;
mod timing;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use nalgebra::SVector;
use serde_json::{Value, json};
use vectrix::ode::explicit::Adaptive;
use vectrix::ode::harness::{Pendulum, Reference};

use problems::{
    ARM7_Q0, CHAIN_NS, CHAIN_T, CLOSED_FORMS, GRAVITY, LINK, MASS, QUADRUPED_Q0, QUADRUPED_V0, RADIUS,
    TREE_T, capsule_inertia, chain_model, chain_q0, chain_y0, closed_form_f64, closed_form_mp, max_abs_diff,
    spatial_reference, tree_model, tree_rhs,
};
use report::{Pt, figure};
use routes::Ctx;
use table::{FAMILIES, reference_floors, table};

const DATA: &str = "docs/accuracy/peers-data";
const SVG: &str = "docs/accuracy";
const BEGIN: &str = "<!-- frontier-table:begin -->";
const END: &str = "<!-- frontier-table:end -->";

/// The problems in table order: id, figure title, x label.
const PROBLEMS: [(&str, &str, &str); 11] = [
    (
        "rigid-body",
        "Torque-free asymmetric body, I = (1, 2, 3), t ≤ 20",
        "max |ω − ω_exact| at t = 20 (exact: Jacobi elliptic)",
    ),
    (
        "kepler-e0.9",
        "Kepler, e = 0.9, t ≤ 20",
        "max-norm error of (r, ṙ) at t = 20 (exact: Kepler's equation)",
    ),
    (
        "pendulum",
        "Pendulum released at θ₀ = 3 rad, t ≤ 10",
        "max-norm error of (θ, θ̇) at t = 10 (exact: Jacobi elliptic)",
    ),
    (
        "chain-1",
        "1-link hinge chain (MuJoCo's capsule), t ≤ 1 s",
        "max-norm error of (q, v) at t = 1 s (extended-precision reference)",
    ),
    (
        "chain-2",
        "Double pendulum (2-link chain), t ≤ 1 s",
        "max-norm error of (q, v) at t = 1 s (extended-precision reference)",
    ),
    (
        "chain-6",
        "6-link hinge chain, t ≤ 1 s",
        "max-norm error of (q, v) at t = 1 s (extended-precision reference)",
    ),
    (
        "chain-12",
        "12-link hinge chain, t ≤ 1 s",
        "max-norm error of (q, v) at t = 1 s (extended-precision reference)",
    ),
    (
        "chain-30",
        "30-link hinge chain, t ≤ 1 s",
        "max-norm error of (q, v) at t = 1 s (extended-precision reference)",
    ),
    (
        "arm7",
        "7-DOF arm (examples/models/arm7.urdf) from rest, t ≤ 1 s",
        "max-norm error of (q, v) at t = 1 s (extended-precision reference)",
    ),
    (
        "quadruped",
        "Floating quadruped (examples/models/quadruped.urdf) falling and turning, t ≤ 1 s",
        "max-norm error of (position, attitude, angles, velocities) at t = 1 s (extended-precision reference)",
    ),
    (
        "energy-pendulum",
        "Pendulum θ₀ = 1 rad over 10⁴ periods: energy",
        "max |E − E₀|/E₀ at every 10th period",
    ),
];

fn arg(args: &[String], key: &str) -> Option<String> {
    args.iter().position(|a| a == key).and_then(|i| args.get(i + 1).cloned())
}

fn shell(cmd: &str, args: &[&str]) -> String {
    std::process::Command::new(cmd)
        .args(args)
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_default()
}

fn loadavg() -> Vec<f64> {
    std::fs::read_to_string("/proc/loadavg")
        .unwrap_or_default()
        .split_whitespace()
        .take(3)
        .filter_map(|x| x.parse().ok())
        .collect()
}

fn cpu_model() -> String {
    shell("lscpu", &[])
        .lines()
        .find_map(|l| l.strip_prefix("Model name:").map(|m| m.trim().to_string()))
        .unwrap_or_default()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("run") => run(&args),
        Some("plot") => plot(&args),
        _ => {
            eprintln!(
                "usage: frontier run [--quick] [--out DIR] [--only a,b] [--cap S]\n       frontier plot [--data DIR] [--svg DIR] [--doc FILE]"
            );
            std::process::exit(2);
        }
    }
}

/// The chains' extended-precision reference end states (scripts/peers/chain_reference_mp.py:
/// Gragg–Bulirsch–Stoer extrapolation in mpmath at 34 digits on a Lagrangian that shares no
/// code and no formula with vectrix's ABA), committed as this file.
const MP_REFERENCE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/chain_reference_mp.json");

/// A JSON array of numbers (a reference's state or initial state).
fn floats(v: &Value) -> Vec<f64> {
    v.as_array().expect("array").iter().map(|x| x.as_f64().expect("number")).collect()
}

/// The `chain-n` entry of `tests/data/chain_reference_mp.json`.
fn mp_reference(id: &str) -> Value {
    let text = std::fs::read_to_string(MP_REFERENCE).expect("tests/data/chain_reference_mp.json");
    // serde_json's float_roundtrip feature (a dev-dependency of the workspace): the numbers
    // are read exactly, each the nearest double of the extended-precision value
    let doc: Value = serde_json::from_str(&text).expect("chain_reference_mp.json parses");
    let entry = doc["chains"][id].clone();
    assert!(entry.is_object(), "{MP_REFERENCE} has no {id}: run scripts/peers/chain_reference_mp.py");
    json!({ "entry": entry, "method": doc["method"].clone() })
}

/// The chains' reference: the extended-precision end state of `chain_reference_mp.json` (its
/// uncertainty: the convergence difference of its two runs or the rounding of the stored
/// doubles, whichever is larger). Beside it, as checks: vectrix's DOP853 at rtol = atol =
/// 1e-13 through `Model::aba_into` (the old reference, good to ~1e-12), and for the one link
/// the exact physical-pendulum solution in f64. `check_reference.py` adds scipy's DOP853 on a
/// numpy Lagrangian and on Pinocchio's ABA (checks of those tools).
fn chain_reference<const N: usize>() -> Value {
    let n = N / 2;
    let id = format!("chain-{n}");
    let mp = mp_reference(&id);
    let e = &mp["entry"];
    let state = floats(&e["state"]);
    assert_eq!(state.len(), N, "{id}: the reference state has 2n numbers");
    assert_eq!(floats(&e["q0"]), chain_q0(n), "{id}: the reference starts from chain_q0");
    assert_eq!(e["t_end"].as_f64(), Some(CHAIN_T), "{id}: the reference ends at CHAIN_T");
    let convergence = e["convergence"].as_f64().expect("convergence");
    // the stored doubles are within half an ulp of the extended-precision values
    let rounding = state.iter().fold(0.0f64, |a, x| a.max(x.abs() * f64::EPSILON / 2.0));

    let model = chain_model(n);
    let tau = vec![0.0; n];
    let y0 = chain_y0::<N>();
    let mut scratch = model.aba_scratch();
    let f = |_: f64, y: &SVector<f64, N>| tree_rhs(&model, &tau, &mut scratch, y);
    let y = *Adaptive::dop853()
        .rtol(1e-13)
        .atol(1e-13)
        .solve(f, 0.0, &y0, CHAIN_T)
        .expect("the DOP853 check run")
        .last();
    let mut v = json!({
        "t_end": CHAIN_T, "q0": chain_q0(n), "v0": vec![0.0; n],
        "state": state,
        "state_mp": e["state_mp"].clone(),
        "method": format!(
            "extended-precision reference (scripts/peers/chain_reference_mp.py): {}",
            mp["method"].as_str().unwrap_or("?")
        ),
        "source": "tests/data/chain_reference_mp.json",
        "convergence": convergence,
        "uncertainty": convergence.max(rounding),
        "check_dop853_1e-13": {
            "method": "vectrix DOP853, rtol = atol = 1e-13, Model::aba_into (ABA)",
            "state": y.as_slice(),
            "diff": max_abs_diff(y.as_slice(), &state),
        },
    });
    if n == 1 {
        // a physical pendulum: θ̈ = −ω₀² sin θ, ω₀² = m g c / (I_c + m c²)
        let (perp, _) = capsule_inertia(RADIUS, LINK, MASS);
        let c = LINK / 2.0;
        let w0 = (MASS * GRAVITY * c / (perp + MASS * c * c)).sqrt();
        let p = Pendulum { theta0: chain_q0(1)[0] };
        let e = p.exact(w0 * CHAIN_T);
        let exact = [e[0], w0 * e[1]];
        v["exact"] = json!(exact);
        v["diff_to_exact"] = json!(max_abs_diff(&exact, &state));
    }
    v
}

fn reference_for(n: usize) -> Value {
    match n {
        1 => chain_reference::<2>(),
        2 => chain_reference::<4>(),
        6 => chain_reference::<12>(),
        12 => chain_reference::<24>(),
        30 => chain_reference::<60>(),
        _ => unreachable!("CHAIN_NS"),
    }
}

fn run(args: &[String]) {
    let out = PathBuf::from(arg(args, "--out").unwrap_or_else(|| DATA.into()));
    std::fs::create_dir_all(&out).expect("output folder");
    let only: Option<Vec<String>> = arg(args, "--only").map(|s| s.split(',').map(str::to_string).collect());
    let want = |p: &str| only.as_ref().is_none_or(|o| o.iter().any(|x| x == p));
    let cap = arg(args, "--cap").and_then(|c| c.parse().ok()).unwrap_or(2.0);
    let load_start = loadavg();
    let date = shell("date", &["-u", "+%Y-%m-%dT%H:%M:%SZ"]);

    // the chains' reference end states (read from tests/data/chain_reference_mp.json, with the
    // DOP853 check run beside them)
    let ref_path = out.join("reference.json");
    let mut reference: BTreeMap<String, Value> = std::fs::read_to_string(&ref_path)
        .ok()
        .and_then(|s| serde_json::from_str(&s).ok())
        .unwrap_or_default();
    for n in CHAIN_NS {
        let id = format!("chain-{n}");
        if want(&id) {
            eprintln!("reference {id}");
            reference.insert(id, reference_for(n));
        }
    }
    // the closed-form problems: the extended-precision end states the peers measure against,
    // and how far vectrix's double-precision closed forms (its routes' reference) are from them
    for id in CLOSED_FORMS.into_iter().filter(|id| want(id)) {
        let mp = closed_form_mp(id).expect("tests/data/closed_form_reference_mp.json holds the problem");
        let f64s = closed_form_f64(id).expect("a closed-form problem");
        let diff = max_abs_diff(&f64s, &mp);
        reference.insert(
            id.to_string(),
            json!({
                "state": mp,
                "source": "tests/data/closed_form_reference_mp.json (scripts/peers/closed_form_reference_mp.py, mpmath 40 digits)",
                "vectrix_closed_form": f64s,
                "uncertainty": diff.max(mp.iter().fold(0.0f64, |a, x| a.max(x.abs() * f64::EPSILON / 2.0))),
            }),
        );
    }
    // the spatial trees: Pinocchio's ABA in quadruple precision (scripts/peers/spatial_reference.sh)
    for (id, file, q0, v0) in [
        ("arm7", "arm7.urdf", ARM7_Q0.to_vec(), vec![0.0; 7]),
        ("quadruped", "quadruped.urdf", QUADRUPED_Q0.to_vec(), QUADRUPED_V0.to_vec()),
    ] {
        if !want(id) {
            continue;
        }
        let (state, spread) =
            spatial_reference(id).expect("tests/data/spatial_reference.json holds the tree");
        let model = tree_model(file);
        assert_eq!((model.nq(), model.nv()), (q0.len(), v0.len()), "{id}: the initial state fits the model");
        assert_eq!(state.len(), q0.len() + v0.len(), "{id}: the reference has nq + nv numbers");
        reference.insert(
            id.into(),
            json!({
                "state": state, "t_end": TREE_T, "q0": q0, "v0": v0,
                "source": "tests/data/spatial_reference.json (scripts/peers/spatial_reference.sh: Pinocchio ABA in float128, fixed-step GBS, two step sizes apart by its `difference`)",
                // how far apart the end states of two equally valid double readings of the
                // file are (every model number moved within ±1 ulp): below it no f64 tool that
                // reads the file itself is measured
                "uncertainty": spread,
            }),
        );
    }
    std::fs::write(&ref_path, serde_json::to_string_pretty(&reference).expect("json"))
        .expect("write reference");

    let mut ctx = Ctx { points: Vec::new(), quick: args.iter().any(|a| a == "--quick"), cap };
    if want("rigid-body") {
        ctx.rigid_body();
    }
    if want("kepler-e0.9") {
        ctx.kepler();
    }
    if want("pendulum") {
        ctx.pendulum();
    }
    for n in CHAIN_NS {
        let id = format!("chain-{n}");
        if !want(&id) {
            continue;
        }
        let state: Vec<f64> = reference[&id]["state"]
            .as_array()
            .expect("state")
            .iter()
            .map(|x| x.as_f64().expect("number"))
            .collect();
        match n {
            1 => ctx.chain::<2>(&state),
            2 => ctx.chain::<4>(&state),
            6 => ctx.chain::<12>(&state),
            12 => ctx.chain::<24>(&state),
            30 => ctx.chain::<60>(&state),
            _ => unreachable!("CHAIN_NS"),
        }
    }
    let tree_state = |id: &str| -> Vec<f64> {
        reference[id]["state"]
            .as_array()
            .expect("state")
            .iter()
            .map(|x| x.as_f64().expect("number"))
            .collect()
    };
    if want("arm7") {
        ctx.arm7(&tree_state("arm7"));
    }
    if want("quadruped") {
        ctx.quadruped(&tree_state("quadruped"));
    }
    if want("energy-pendulum") {
        ctx.energy();
    }
    let doc = json!({
        "tool": "vectrix",
        "versions": { "vectrix": env!("CARGO_PKG_VERSION"), "rustc": shell("rustc", &["--version"]) },
        "machine": format!("{}, {} CPUs, {}", cpu_model(), std::thread::available_parallelism().map_or(0, |n| n.get()), shell("uname", &["-sr"])),
        "date": date,
        "load_start": load_start,
        "load_end": loadavg(),
        "threads": { "RAYON_NUM_THREADS": std::env::var("RAYON_NUM_THREADS").ok() },
        "points": ctx.points.iter().map(routes::Point::to_json).collect::<Vec<_>>(),
    });
    let path = out.join("vectrix.json");
    // a partial run (--only) merges into the points of the other problems
    let merged = merge(&path, doc, only.is_some());
    std::fs::write(&path, serde_json::to_string_pretty(&merged).expect("json")).expect("write points");
    eprintln!("wrote {} and {}", path.display(), ref_path.display());
}

/// With `partial`, keeps the existing file's points of the problems this run did not do.
fn merge(path: &Path, mut doc: Value, partial: bool) -> Value {
    if !partial {
        return doc;
    }
    let Some(old) = std::fs::read_to_string(path).ok().and_then(|s| serde_json::from_str::<Value>(&s).ok())
    else {
        return doc;
    };
    let new_problems: Vec<String> = doc["points"]
        .as_array()
        .map(|a| a.iter().filter_map(|p| p["problem"].as_str().map(str::to_string)).collect())
        .unwrap_or_default();
    let mut points: Vec<Value> = old["points"]
        .as_array()
        .map(|a| {
            a.iter().filter(|p| !new_problems.iter().any(|n| p["problem"] == n.as_str())).cloned().collect()
        })
        .unwrap_or_default();
    points.extend(doc["points"].as_array().cloned().unwrap_or_default());
    doc["points"] = Value::Array(points);
    doc
}

/// Every tool file of `data` (not the reference files).
fn read_tools(data: &Path) -> Vec<Value> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(data)
        .expect("data folder")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .filter(|p| !p.file_stem().is_some_and(|s| s.to_string_lossy().starts_with("reference")))
        .collect();
    files.sort();
    files.iter().filter_map(|p| serde_json::from_str(&std::fs::read_to_string(p).ok()?).ok()).collect()
}

fn plot(args: &[String]) {
    let data = PathBuf::from(arg(args, "--data").unwrap_or_else(|| DATA.into()));
    let svg_dir = PathBuf::from(arg(args, "--svg").unwrap_or_else(|| SVG.into()));
    let tools = read_tools(&data);
    let mut pts: Vec<Pt> = Vec::new();
    // vectrix first, then the peers in FAMILIES order: the figures' legends follow it
    for fam in FAMILIES.map(|f| f.0) {
        for t in &tools {
            for p in t["points"].as_array().into_iter().flatten().filter_map(Pt::from_json) {
                if p.family() == fam {
                    pts.push(p);
                }
            }
        }
    }
    for (id, title, x_label) in PROBLEMS {
        if !pts.iter().any(|p| p.problem == id) {
            continue;
        }
        let svg = figure(&pts, id, title, x_label).to_svg().expect("figure");
        let path = svg_dir.join(format!("peers-{id}.svg"));
        std::fs::write(&path, svg).expect("write svg");
        eprintln!("wrote {}", path.display());
    }
    let floors = reference_floors(&data);
    let table = table(&pts, &tools, &floors);
    println!("{table}");
    if let Some(doc) = arg(args, "--doc") {
        let text = std::fs::read_to_string(&doc).expect("document");
        let (Some(a), Some(b)) = (text.find(BEGIN), text.find(END)) else {
            panic!("{doc} has no {BEGIN} … {END} markers");
        };
        let new = format!("{}{BEGIN}\n{table}\n{}", &text[..a], &text[b..]);
        std::fs::write(&doc, new).expect("write document");
        eprintln!("updated {doc}");
    }
}
