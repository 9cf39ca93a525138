//! The `vectrix` command through its library entry `vectrix_cli::run_with_args`, with a
//! temporary output directory: run (default and file), check, sweep, bad files, atomic output.
//!
//! Book: §7.8 (the default scene), §7.11/ch. 6 (scenes).

use std::path::{Path, PathBuf};

use vectrix::scene::Scene;
use vectrix_cli::run_with_args;

/// A fresh temporary directory for one test.
fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("vectrix-cli-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

fn cli(args: &[&str]) -> Result<String, String> {
    let mut out = Vec::new();
    let r = run_with_args(std::iter::once("vectrix").chain(args.iter().copied()), &mut out);
    let text = String::from_utf8_lossy(&out).to_string();
    r.map(|_| text).map_err(|e| e.to_string())
}

fn example(name: &str) -> String {
    format!("{}/examples/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"))
}

/// Writes a shortened copy of an example scene into `dir` (tests keep runs short).
fn short_copy(dir: &Path, name: &str, duration: f64, samples: usize) -> String {
    let text = std::fs::read_to_string(example(name)).unwrap();
    let scene = Scene::from_toml(&text, name).unwrap();
    let mut spec = scene.spec().clone();
    spec.duration = duration;
    spec.samples = samples;
    let p = dir.join(format!("{name}.toml"));
    std::fs::write(&p, Scene::from_spec(spec).unwrap().to_toml().unwrap()).unwrap();
    p.display().to_string()
}

#[test]
fn run_default_scene_writes_complete_output() {
    // `vectrix run` with no scene runs the embedded tennis-racket flip.
    let dir = temp_dir("default");
    let out = cli(&["run", "--quiet", "--out", dir.to_str().unwrap()]).unwrap();
    assert!(out.contains("tennis_racket") && out.contains("energy"), "{out}");
    let d = dir.join("tennis_racket");
    let csv = std::fs::read_to_string(d.join("trajectory.csv")).unwrap();
    // every column carries its SI unit
    assert!(
        csv.starts_with(
            "t [s],omega_body:racket.x [rad/s],omega_body:racket.y [rad/s],omega_body:racket.z [rad/s],energy [J]"
        ),
        "{}",
        csv.lines().next().unwrap_or("")
    );
    assert_eq!(csv.lines().count(), 1 + 801);
    // summary.json: three checked invariants, each with a small relative drift
    let summary = std::fs::read_to_string(d.join("summary.json")).unwrap();
    let rel: Vec<f64> = summary
        .lines()
        .filter_map(|l| l.trim().strip_prefix("\"max_rel\": "))
        .map(|x| x.trim_end_matches(',').parse().unwrap())
        .collect();
    assert_eq!(rel.len(), 3, "{summary}");
    assert!(rel.iter().all(|r| *r < 1e-6), "{rel:?}");
    assert!(summary.contains("\"fevals\"") && summary.contains("\"wall_seconds\""));
    for svg in ["omega_body_racket.svg", "energy.svg", "angular_momentum.svg"] {
        assert!(std::fs::read_to_string(d.join(svg)).unwrap().contains("<svg"), "{svg}");
    }
    // no temporary folder is left behind
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().starts_with('.'))
        .collect();
    assert!(leftovers.is_empty());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn run_scene_file_and_rerun_replaces_output() {
    let dir = temp_dir("file");
    let scene = short_copy(&dir, "kepler_orbit", 1.0, 20);
    let o = dir.join("out");
    cli(&["run", &scene, "--quiet", "--out", o.to_str().unwrap()]).unwrap();
    cli(&["run", &scene, "--quiet", "--out", o.to_str().unwrap()]).unwrap();
    let csv = std::fs::read_to_string(o.join("kepler_orbit/trajectory.csv")).unwrap();
    assert_eq!(csv.lines().count(), 22);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_valid_and_invalid_scenes() {
    let out = cli(&["check", &example("heavy_top")]).unwrap();
    assert!(out.contains("ok") && out.contains("energy, angular_momentum"), "{out}");
    let dir = temp_dir("check");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "name = \"b\"\nduration = 1.0\nbodys = []\n").unwrap();
    let e = cli(&["check", bad.to_str().unwrap()]).unwrap_err();
    assert!(e.contains("bad.toml:3:1") && e.contains("bodies"), "{e}");
    // a failed run writes nothing
    let o = dir.join("out");
    assert!(cli(&["run", bad.to_str().unwrap(), "--out", o.to_str().unwrap()]).is_err());
    assert!(!o.join("b").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn sweep_runs_every_value() {
    let dir = temp_dir("sweep");
    let scene = short_copy(&dir, "spring_dashpot_chain", 0.5, 10);
    let o = dir.join("out");
    let out =
        cli(&["sweep", &scene, "--quiet", "--param", "effects.0.k=1,2,4", "--out", o.to_str().unwrap()])
            .unwrap();
    assert_eq!(out.lines().filter(|l| l.contains("| effects.0.k=")).count(), 3, "{out}");
    let sweep = o.join("spring_dashpot_chain-sweep");
    for k in 0..3 {
        assert!(sweep.join(format!("run-{k:03}/trajectory.csv")).exists(), "{k}");
    }
    // one row per run in sweep.csv, with the parameter values
    let csv = std::fs::read_to_string(sweep.join("sweep.csv")).unwrap();
    assert!(csv.starts_with("run,effects.0.k,complete,"), "{csv}");
    assert_eq!(csv.lines().count(), 4, "{csv}");
    let e = cli(&["sweep", &scene, "--param", "effects.0.nope=1"]).unwrap_err();
    assert!(e.contains("nope"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn tour_and_unknown_subcommand() {
    assert!(cli(&["tour"]).unwrap().contains("tour"));
    assert!(cli(&["frobnicate"]).is_err());
}

/// An aircraft scene (a free body with `aero` and `thrust` effects) through `check`, `run`,
/// `--units imperial` and `sweep`; a file in the old flight form is refused with its new form.
#[test]
fn run_check_and_sweep_aircraft_scene() {
    let dir = temp_dir("flight");
    let text = std::fs::read_to_string(example("business_jet_doublet")).unwrap();
    let text = text.replacen("duration = 120.0", "duration = 10.0", 1).replacen(
        "samples = 1200",
        "samples = 100",
        1,
    );
    let path = dir.join("jet.toml");
    std::fs::write(&path, &text).unwrap();
    let p = path.display().to_string();
    let checked = cli(&["check", &p]).unwrap();
    assert!(checked.contains("ok — scene `business_jet_doublet`"), "{checked}");
    assert!(checked.contains("trimmed (") && checked.contains("effects[1].elevator"), "{checked}");
    let out_dir = dir.join("out").display().to_string();
    let printed = cli(&["run", &p, "--out", &out_dir, "--quiet"]).unwrap();
    assert!(printed.contains("trimmed ("), "{printed}");
    let dest = dir.join("out").join("business_jet_doublet");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dest.join("summary.json")).unwrap()).unwrap();
    assert!(summary["trim"]["residual"].as_f64().unwrap() <= 1e-10);
    assert_eq!(summary["trim"]["free"][2], "effects[2]");
    let csv = std::fs::read_to_string(dest.join("trajectory.csv")).unwrap();
    assert_eq!(csv.lines().count(), 102);
    assert!(csv.starts_with("t [s],velocity_body:jet.u [m/s]"), "{}", csv.lines().next().unwrap_or(""));
    assert_eq!(summary["units"], "si");
    let imperial = cli(&["run", &p, "--out", &out_dir, "--quiet", "--units", "imperial"]).unwrap();
    assert!(imperial.contains("wrote"));
    let csv_ft = std::fs::read_to_string(dest.join("trajectory.csv")).unwrap();
    assert!(csv_ft.starts_with("t [s],velocity_body:jet.u [ft/s]"));
    // u(0) is the file's 400 kt (1852/3600 m/s per knot, 0.3048 m per foot, both exact), to rounding
    let u0 = |c: &str| -> f64 { c.lines().nth(1).unwrap().split(',').nth(1).unwrap().parse().unwrap() };
    let kt400_ft = 400.0 * 1852.0 / 3600.0 / 0.3048;
    assert!((u0(&csv_ft) - kt400_ft).abs() <= 1e-9, "{}", u0(&csv_ft));
    assert!((u0(&csv) - u0(&csv_ft) * 0.3048).abs() <= 4.0 * f64::EPSILON * u0(&csv));
    // an aircraft scene sweeps like any other: two doublet amplitudes, each run trimmed
    let swept = cli(&["sweep", &p, "--param", "effects.1.elevator.amplitude=0.005,0.01", "--out", &out_dir]);
    assert!(
        swept.as_ref().is_ok_and(|s| s.contains("| 001 | effects.1.elevator.amplitude=0.01 | true |")),
        "{swept:?}"
    );
    // the old flight form is refused at its table with the new form, and nothing is written
    let old =
        "name = \"old\"\nduration = 1.0\n[aircraft]\nmodel = \"business_jet\"\n[trim]\nairspeed = 675.124\n";
    std::fs::write(&path, old).unwrap();
    let e = cli(&["run", &p, "--out", &out_dir]).unwrap_err();
    assert!(e.contains("jet.toml:3:2: aircraft:") && e.contains("[[bodies]]"), "{e}");
    assert!(!dir.join("out").join("old").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 23: the tour prints numbers rounded for reading. 𝓞_{B/A} of a quarter turn about k̂
/// is [[0, 1, 0], [−1, 0, 0], [0, 0, 1]] (2.12.16 with θ = π/2); its cos(π/2) = 6.1e-17 and
/// the round-off of the rotor sandwich print as 0, not as 17-digit noise.
#[test]
fn tour_prints_numbers_rounded_for_reading() {
    let text = cli(&["tour"]).unwrap();
    assert!(text.contains("x|_B = [0, -1, 0]"), "{text}");
    assert!(text.contains("𝓞_{B/A} =\n[  0  1  0 ]\n[ -1  0  0 ]\n[  0  0  1 ]"), "{text}");
    assert!(text.contains("R x R̄ |_A = [0, 1, 0]"), "{text}");
    assert!(text.contains("angle(x, y) = 1.5708 rad"), "{text}");
    assert!(!text.contains("e-1"), "no round-off noise in scientific form: {text}");
}
