//! The scene engine as a simulator people trust with their files and their time (issue 16):
//! output safety, one integration per run, bounded runs, honest outputs, state queries and
//! error positions. Physics references are closed forms (Kepler's equation, Jacobi elliptic
//! functions for the torque-free body, Lagrange's equations of the double pendulum derived by
//! hand), never another vectrix route.
//!
//! Book: §7.8 (torque-free body), §6.12 (central gravity, Kepler), §9.3–9.9 (T, M q̈ = Q),
//! §4.11 (integration).

mod support;

use crate::support::nan_max;
use std::path::{Path, PathBuf};

use std::process::Command;
use support::snapshot;

use vectrix::scene::{InvariantValue, Run, Scene, SceneError, StopReason};
use vectrix_ode::harness::RigidBody;

fn run(scene: &Scene) -> Run {
    scene.run(&mut |_| {}).unwrap_or_else(|e| panic!("{e}"))
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("vectrix-engine-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn vectrix(cwd: &Path, args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_vectrix")).current_dir(cwd).args(args).output().expect("the binary runs")
}

/// A small valid scene (a pendulum) with the given name line.
fn pendulum(name_line: &str) -> String {
    format!(
        "{name_line}\nduration = 0.2\nsamples = 4\noutputs = [\"energy\"]\n\n[[bodies]]\nname = \"bob\"\njoint = {{ type = \
         \"pin\", axis = [0.0, 0.0, 1.0] }}\nmass = {{ shape = \"particle\", mass = 1.0 }}\ncom = [0.0, -1.0, 0.0]\nq = \
         [0.5]\n\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n"
    )
}

// ---------------------------------------------------------------- item 1: output safety

#[test]
fn issue_16_empty_or_path_like_names_are_refused_with_their_position() {
    for (line, what) in [
        ("name = \"\"", "is empty"),
        ("name = \"../../x\"", "starts with `.`"),
        ("name = \"/tmp/x\"", "contains '/'"),
        ("name = \"..\"", "starts with `.`"),
        ("name = \"a/b\"", "contains '/'"),
        ("name = \"a\\\\b\"", "contains '\\\\'"),
    ] {
        let e = Scene::from_toml(&pendulum(line), "s.toml").unwrap_err();
        match &e {
            SceneError::Invalid { line, column, path, message, .. } => {
                assert_eq!((*line, *column, path.as_str()), (1, 1, "name"), "{e}");
                assert!(message.contains(what) && message.contains("valid:"), "{e}");
            }
            _ => panic!("{e}"),
        }
    }
}

#[test]
fn issue_16_run_into_dot_never_touches_the_working_tree() {
    // `--out .` in a folder holding the user's files: a scene named like one of them is refused
    // before it runs, and nothing of the user's changes; a plain name writes only its folder.
    let dir = temp_dir("dot");
    std::fs::create_dir_all(dir.join("src")).unwrap();
    std::fs::write(dir.join("src/lib.rs"), "pub fn f() {}\n").unwrap();
    std::fs::write(dir.join("notes.txt"), "mine\n").unwrap();
    std::fs::write(dir.join("src.toml"), pendulum("name = \"src\"")).unwrap();
    std::fs::write(dir.join("empty.toml"), pendulum("name = \"\"")).unwrap();
    let before = snapshot(&dir);
    let o = vectrix(&dir, &["run", "src.toml", "--quiet", "--out", "."]);
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("refusing to replace") && err.contains("src"), "{err}");
    let o = vectrix(&dir, &["run", "empty.toml", "--quiet", "--out", "."]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("empty.toml:1:1"));
    assert_eq!(snapshot(&dir), before, "the user's tree changed");
    // a fresh name: exactly one new folder, with the marker
    std::fs::write(dir.join("ok.toml"), pendulum("name = \"pend\"")).unwrap();
    let o = vectrix(&dir, &["run", "ok.toml", "--quiet", "--out", "."]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(dir.join("pend/.vectrix-output").exists() && dir.join("pend/trajectory.csv").exists());
    let names: Vec<String> =
        std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
    assert!(!names.iter().any(|n| n.starts_with('.')), "temporary folder left: {names:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn issue_16_out_with_a_space_is_used_as_given() {
    let dir = temp_dir("space");
    std::fs::write(dir.join("p.toml"), pendulum("name = \"pend\"")).unwrap();
    let o = vectrix(&dir, &["run", "p.toml", "--quiet", "--out", "my out"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(dir.join("my out/pend/trajectory.csv").exists());
    assert!(!dir.join("myout").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn issue_16_a_failed_run_keeps_the_previous_output() {
    let dir = temp_dir("keep");
    std::fs::write(dir.join("p.toml"), pendulum("name = \"pend\"")).unwrap();
    assert!(vectrix(&dir, &["run", "p.toml", "--quiet", "--out", "o"]).status.success());
    let good = std::fs::read(dir.join("o/pend/trajectory.csv")).unwrap();
    // the same scene, now invalid: nothing is written, the good output stays
    std::fs::write(dir.join("p.toml"), pendulum("name = \"pend\"").replace("mass = 1.0", "mass = -1.0"))
        .unwrap();
    let o = vectrix(&dir, &["run", "p.toml", "--quiet", "--out", "o"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(std::fs::read(dir.join("o/pend/trajectory.csv")).unwrap(), good);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn issue_16_concurrent_sweeps_with_equal_parameters_never_collide() {
    let dir = temp_dir("race");
    std::fs::write(dir.join("p.toml"), pendulum("name = \"pend\"")).unwrap();
    let children: Vec<_> = (0..4)
        .map(|_| {
            Command::new(env!("CARGO_BIN_EXE_vectrix"))
                .current_dir(&dir)
                .args(["sweep", "p.toml", "--quiet", "--param", "effects.0.g.1=-9.81,-1.62", "--out", "o"])
                .output()
        })
        .collect();
    for c in children {
        let c = c.unwrap();
        assert!(c.status.success(), "{}", String::from_utf8_lossy(&c.stderr));
    }
    let sweep = dir.join("o/pend-sweep");
    assert!(sweep.join(".vectrix-output").exists());
    for k in 0..2 {
        assert!(sweep.join(format!("run-{k:03}/trajectory.csv")).exists());
    }
    let left: Vec<String> = std::fs::read_dir(dir.join("o"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n != "pend-sweep")
        .collect();
    assert!(left.is_empty(), "{left:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

// -------------------------------------------------------- item 2: one integration per run

/// Kepler's equation M = E − e sin E by Newton from E = M (e < 1, converges for every M).
fn kepler_position(a: f64, e: f64, mu: f64, t: f64) -> (f64, f64) {
    let n = (mu / (a * a * a)).sqrt();
    let m = n * t;
    let mut ea = m + e * m.sin();
    for _ in 0..60 {
        let d = (ea - e * ea.sin() - m) / (1.0 - e * ea.cos());
        ea -= d;
        if d.abs() < 1e-16 {
            break;
        }
    }
    // periapsis on +x at t = 0, motion counter-clockwise about +z
    (a * (ea.cos() - e), a * (1.0 - e * e).sqrt() * ea.sin())
}

fn kepler_scene(e: f64, periods: f64, samples: usize, accuracy: f64) -> Scene {
    let (a, mu) = (1.0, 1.0);
    let rp = a * (1.0 - e);
    let vp = (mu * (1.0 + e) / rp).sqrt();
    let text = format!(
        "name = \"kepler\"\nduration = {}\nsamples = {samples}\naccuracy = {accuracy:e}\noutputs = \
         [\"position:p\"]\n\n[[bodies]]\nname = \"p\"\njoint = {{ type = \"free\" }}\nmass = {{ shape = \"sphere\", \
         mass = 1.0, radius = 0.01 }}\nq = [{rp}, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]\nv = [0.0, {vp}, 0.0, 0.0, 0.0, 0.0]\n\n[[effects]]\ntype \
         = \"central_gravity\"\nmu = {mu}\n",
        periods * 2.0 * std::f64::consts::PI
    );
    Scene::from_toml(&text, "kepler.toml").unwrap_or_else(|e| panic!("{e}"))
}

/// Largest distance of the sampled positions from Kepler's closed form.
fn kepler_error(r: &Run, e: f64) -> f64 {
    let (x, y) = (r.column("position:p.x").unwrap(), r.column("position:p.y").unwrap());
    r.t.iter()
        .zip(x.iter().zip(&y))
        .map(|(&t, (&x, &y))| {
            let (ex, ey) = kepler_position(1.0, e, 1.0, t);
            (x - ex).hypot(y - ey)
        })
        .fold(0.0, nan_max)
}

#[test]
fn issue_16_samples_do_not_change_the_work() {
    // Kepler e = 0.9 over two periods: 4000 samples cost no more than 1.5× the f-evals of 40
    // (dense output: DOP853 pays 3 evaluations per step that holds a sample, 12 + 1 per step)
    let few = run(&kepler_scene(0.9, 2.0, 40, 1e-10));
    let many = run(&kepler_scene(0.9, 2.0, 4000, 1e-10));
    assert_eq!((few.t.len(), many.t.len()), (41, 4001));
    assert!(
        (many.work.fevals as f64) <= 1.5 * few.work.fevals as f64,
        "{} vs {}",
        many.work.fevals,
        few.work.fevals
    );
    // the same steps: the samples are read off, not integrated to
    assert_eq!(many.work.accepted, few.work.accepted);
    // and the interpolated samples are as accurate as the steps
    assert!(kepler_error(&many, 0.9) < 1e-6, "{}", kepler_error(&many, 0.9));
}

#[test]
fn issue_16_kepler_error_follows_the_requested_accuracy() {
    // the global error against Kepler's equation falls with the tolerance (the work–precision
    // line of docs/accuracy.md); e = 0.9 passes periapsis at 19 times the mean speed
    let mut last = f64::INFINITY;
    for acc in [1e-6, 1e-8, 1e-10] {
        let err = kepler_error(&run(&kepler_scene(0.9, 3.0, 300, acc)), 0.9);
        // a global error within a modest multiple of the local tolerance over three periods
        assert!(err < 1e3 * acc, "accuracy {acc:e}: error {err:e}");
        assert!(err < last, "accuracy {acc:e}: error {err:e} did not fall from {last:e}");
        last = err;
    }
}

#[test]
fn issue_16_torque_free_body_follows_the_elliptic_solution() {
    // principal moments 1 < 2 < 3 along the link axes, ω_B(0) = (1, 0, 0.5): the exact ω_B(t)
    // by Jacobi elliptic functions (Landau & Lifshitz §37)
    let exact = RigidBody { inertia: [1.0, 2.0, 3.0], omega13: [1.0, 0.5], t_end: 20.0 };
    for acc in [1e-8, 1e-11] {
        let text = format!(
            "name = \"tf\"\nduration = 20.0\nsamples = 200\naccuracy = {acc:e}\noutputs = [\"omega_body:b\"]\n\n[[bodies]]\n\
             name = \"b\"\njoint = {{ type = \"free\" }}\nmass = {{ shape = \"value\", mass = 1.0, principal = [1.0, 2.0, \
             3.0] }}\nv = [0.0, 0.0, 0.0, 1.0, 0.0, 0.5]\n"
        );
        let r = run(&Scene::from_toml(&text, "tf.toml").unwrap());
        let cols: Vec<Vec<f64>> =
            ["x", "y", "z"].iter().map(|c| r.column(&format!("omega_body:b.{c}")).unwrap()).collect();
        let err =
            r.t.iter()
                .enumerate()
                .map(|(k, &t)| {
                    let w = exact.exact_omega(t);
                    (0..3).map(|i| (cols[i][k] - w[i]).abs()).fold(0.0, nan_max)
                })
                .fold(0.0, nan_max);
        assert!(err < 100.0 * acc, "accuracy {acc:e}: error {err:e}");
    }
}

// ------------------------------------------------------------------- item 5: bounded runs

#[test]
fn issue_16_a_step_budget_stops_the_run_with_what_it_computed() {
    let mut spec = kepler_scene(0.9, 2.0, 100, 1e-10).spec().clone();
    spec.max_steps = Some(50);
    let r = run(&Scene::from_spec(spec).unwrap());
    let stop = r.stop.as_ref().expect("stopped");
    assert_eq!(stop.reason, StopReason::MaxSteps);
    assert!(stop.message.contains("max_steps = 50") && stop.message.contains("valid:"), "{}", stop.message);
    assert!(!r.is_complete() && r.t.len() < 101 && !r.t.is_empty());
    assert!(r.work.accepted + r.work.rejected <= 50);
}

#[test]
fn issue_16_a_huge_duration_fails_fast_with_one_message() {
    // 10⁹ s of a pendulum would need ~10¹⁰ steps: the pace after the first checks says so
    let text = pendulum("name = \"p\"").replace("duration = 0.2", "duration = 1e9");
    let r = run(&Scene::from_toml(&text, "p.toml").unwrap());
    let stop = r.stop.as_ref().expect("stopped");
    assert_eq!(stop.reason, StopReason::MaxSteps);
    assert!(r.work.accepted < 5_000, "{} steps before giving up", r.work.accepted);
    assert!(
        stop.message.contains("duration = 1000000000 s") && stop.message.contains("max_steps"),
        "{}",
        stop.message
    );
}

#[test]
fn issue_16_sizes_are_bounded_with_typed_errors() {
    for (from, to, key) in [
        ("samples = 4", "samples = 1000000000000", "samples"),
        ("samples = 4", "samples = 0", "samples"),
        ("duration = 0.2", "duration = -1.0", "duration"),
        ("duration = 0.2", "duration = 0.2\nmax_wall_seconds = -3.0", "max_wall_seconds"),
        ("duration = 0.2", "duration = 0.2\nmax_steps = 0", "max_steps"),
    ] {
        let text = pendulum("name = \"p\"").replace(from, to);
        match Scene::from_toml(&text, "p.toml") {
            Err(SceneError::Invalid { path, message, .. }) => {
                assert_eq!(path, key, "{message}");
                assert!(message.contains("valid:"), "{message}");
            }
            other => panic!("{key}: {other:?}"),
        }
    }
    // samples × columns bounds the memory: q and v of a 12-link chain at 10⁶ samples
    let mut text = String::from(
        "name = \"c\"\nduration = 1.0\nsamples = 1000000\noutputs = [\"q\", \"v\", \"energy\"]\n",
    );
    for k in 0..60 {
        let parent = if k == 0 { String::new() } else { format!("parent = \"l{}\"\n", k - 1) };
        text.push_str(&format!(
            "[[bodies]]\nname = \"l{k}\"\n{parent}joint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\nmass = {{ shape = \
             \"particle\", mass = 1.0 }}\ncom = [1.0, 0.0, 0.0]\noffset = [{}, 0.0, 0.0]\n",
            if k == 0 { 0.0 } else { 1.0 }
        ));
    }
    let e = Scene::from_toml(&text, "c.toml").unwrap_err();
    assert!(e.to_string().contains("columns"), "{e}");
}

// ---------------------------------------------------------------- item 6: honest outputs

#[test]
fn issue_16_summary_reports_signed_initial_values_and_the_rows_written() {
    let dir = temp_dir("summary");
    let text =
        std::fs::read_to_string(format!("{}/examples/scenes/kepler_orbit.toml", env!("CARGO_MANIFEST_DIR")))
            .unwrap()
            .replace("samples = 1000", "samples = 800");
    std::fs::write(dir.join("k.toml"), &text).unwrap();
    let o = vectrix(&dir, &["run", "k.toml", "--quiet", "--out", "o"]);
    assert!(o.status.success());
    let console = String::from_utf8_lossy(&o.stdout);
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("o/kepler_orbit/summary.json")).unwrap())
            .unwrap();
    let rows = s["rows"].as_u64().unwrap();
    assert_eq!(rows, 801);
    assert!(console.contains("801 rows"), "{console}");
    let csv = std::fs::read_to_string(dir.join("o/kepler_orbit/trajectory.csv")).unwrap();
    assert_eq!(csv.lines().count() as u64, rows + 1);
    assert_eq!(s["complete"], serde_json::Value::Bool(true));
    // the Kepler energy is −μ/(2a) = −0.5, signed
    let energy = s["drift"].as_array().unwrap().iter().find(|d| d["invariant"] == "Energy").unwrap();
    assert!((energy["initial"].as_f64().unwrap() + 0.5).abs() < 1e-12, "{energy}");
    for key in ["fevals", "accepted", "rejected", "impacts", "restarts", "wall_seconds"] {
        assert!(s["work"][key].is_number(), "{key}");
    }
    // every column with its unit
    assert!(s["columns"].as_array().unwrap().iter().all(|c| c["unit"].is_string()));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn issue_16_plots_carry_units_and_stay_small_for_long_runs() {
    let dir = temp_dir("plots");
    let text =
        std::fs::read_to_string(format!("{}/examples/scenes/kepler_orbit.toml", env!("CARGO_MANIFEST_DIR")))
            .unwrap()
            .replace("samples = 1000", "samples = 100000");
    std::fs::write(dir.join("k.toml"), &text).unwrap();
    assert!(vectrix(&dir, &["run", "k.toml", "--quiet", "--out", "o"]).status.success());
    let d = dir.join("o/kepler_orbit");
    let energy = std::fs::read_to_string(d.join("energy.svg")).unwrap();
    assert!(energy.contains("E = T + U [J]"), "y label");
    // the energy is constant to ~1e-11: offset notation instead of clipped equal labels
    assert!(energy.contains("offset "), "offset notation");
    let position = std::fs::read_to_string(d.join("position_planet.svg")).unwrap();
    assert!(position.contains("[m]"));
    // 100 001 samples drawn within half a pixel in far fewer points
    for f in ["energy.svg", "position_planet.svg", "angular_momentum.svg", "path_planet.svg"] {
        let len = std::fs::metadata(d.join(f)).unwrap().len();
        assert!(len < 300_000, "{f}: {len} bytes");
    }
    // the orbit's path in its plane
    assert!(std::fs::read_to_string(d.join("path_planet.svg")).unwrap().contains("path of planet"));
    let _ = std::fs::remove_dir_all(&dir);
}

// -------------------------------------------------------------- item 7: state queries

#[test]
fn issue_16_double_pendulum_query_matches_lagrange_by_hand() {
    // Two point masses m₁, m₂ on massless rods l₁, l₂; scene coordinates: θ₁ of the upper rod
    // from −ĵ, and the lower joint's relative angle φ = θ₂ − θ₁. Lagrange by hand in (θ₁, θ₂):
    //   M = [[(m₁+m₂)l₁², m₂l₁l₂c], [m₂l₁l₂c, m₂l₂²]], c = cos(θ₁ − θ₂),
    //   Q = [−m₂l₁l₂ s θ̇₂² − (m₁+m₂) g l₁ sin θ₁, m₂l₁l₂ s θ̇₁² − m₂ g l₂ sin θ₂], s = sin(θ₁ − θ₂).
    // With θ = Tφ, T = [[1, 0], [1, 1]]: M_φ = Tᵀ M T, Q_φ = Tᵀ(Q − M Ṫφ̇) with Ṫ = 0 here.
    let (m1, m2, l1, l2, g) = (1.3, 0.7, 1.1, 0.6, 9.81);
    let text = format!(
        "name = \"dp\"\nduration = 1.0\n[[bodies]]\nname = \"upper\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         mass = {{ shape = \"particle\", mass = {m1} }}\ncom = [0.0, -{l1}, 0.0]\n[[bodies]]\nname = \"lower\"\nparent = \
         \"upper\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\noffset = [0.0, -{l1}, 0.0]\nmass = {{ shape = \
         \"particle\", mass = {m2} }}\ncom = [0.0, -{l2}, 0.0]\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -{g}, 0.0]\n"
    );
    let scene = Scene::from_toml(&text, "dp.toml").unwrap();
    for (th1, phi, w1, wphi) in
        [(0.3f64, -0.4f64, 1.2f64, 0.5f64), (2.0, 1.0, -0.7, 2.2), (-1.1, 3.0, 0.0, -1.5)]
    {
        let (th2, w2) = (th1 + phi, w1 + wphi);
        let (s, c) = (th1 - th2).sin_cos();
        let m = [[(m1 + m2) * l1 * l1, m2 * l1 * l2 * c], [m2 * l1 * l2 * c, m2 * l2 * l2]];
        let q = [
            -m2 * l1 * l2 * s * w2 * w2 - (m1 + m2) * g * l1 * th1.sin(),
            m2 * l1 * l2 * s * w1 * w1 - m2 * g * l2 * th2.sin(),
        ];
        // to the scene's coordinates: M_φ = Tᵀ M T, Q_φ = Tᵀ Q
        let mphi = [[m[0][0] + 2.0 * m[0][1] + m[1][1], m[0][1] + m[1][1]], [m[0][1] + m[1][1], m[1][1]]];
        let qphi = [q[0] + q[1], q[1]];
        let t_kin = 0.5 * (m[0][0] * w1 * w1 + 2.0 * m[0][1] * w1 * w2 + m[1][1] * w2 * w2);
        let u = -m1 * g * l1 * th1.cos() - m2 * g * (l1 * th1.cos() + l2 * th2.cos());
        let r = scene.query(0.0, &[th1, phi, w1, wphi]).unwrap();
        let scale = mphi[0][0];
        for i in 0..2 {
            for (j, mij) in mphi[i].iter().enumerate() {
                assert!((r.mass_matrix[(i, j)] - mij).abs() < 16.0 * f64::EPSILON * scale, "M[{i}{j}]");
            }
            let qs = qphi[0].abs() + qphi[1].abs() + scale * (w1 * w1 + w2 * w2);
            assert!((r.generalized_forces[i] - qphi[i]).abs() < 32.0 * f64::EPSILON * qs, "Q[{i}]");
        }
        assert!((r.kinetic - t_kin).abs() < 16.0 * f64::EPSILON * t_kin.max(1.0));
        assert!((r.potential - u).abs() < 16.0 * f64::EPSILON * u.abs().max(1.0));
        // and the accelerations solve M v̇ = Q
        let mv: Vec<f64> =
            (0..2).map(|i| mphi[i][0] * r.accelerations[0] + mphi[i][1] * r.accelerations[1]).collect();
        for i in 0..2 {
            assert!((mv[i] - qphi[i]).abs() < 1e-12 * (qphi[i].abs() + scale), "M v̇ = Q, row {i}");
        }
    }
    // a state of the wrong length is a typed error
    assert!(matches!(scene.query(0.0, &[0.0; 3]), Err(SceneError::Run { .. })));
    assert!(matches!(scene.query(0.0, &[f64::NAN, 0.0, 0.0, 0.0]), Err(SceneError::Run { .. })));
}

// ------------------------------------------------------------ item 9: exact positions

#[test]
fn issue_16_errors_point_at_the_key_not_at_a_textual_match() {
    // the word `mass` appears first in a comment, and the bad mass is on the second of two
    // bodies whose name also appears earlier
    let text = "# bob: mass = -1 would be wrong\nname = \"t\"\nduration = 1.0\n\n[[bodies]]\nname = \"bob\"\njoint = { type \
                = \"ball\" }\nmass = { shape = \"sphere\", mass = 1.0, radius = 0.1 }\n\n[[bodies]]\nname = \"bob2\"\nparent \
                = \"bob\"\njoint = { type = \"ball\" }\nmass = { shape = \"sphere\", mass = -1.0, radius = 0.1 }\n";
    match Scene::from_toml(text, "t.toml").unwrap_err() {
        SceneError::Invalid { line, column, path, .. } => {
            assert_eq!(path, "bodies[1].mass.mass");
            assert_eq!((line, column), (14, 28));
        }
        e => panic!("{e}"),
    }
    // a repeated body name: the second one
    let dup = text.replace("name = \"bob2\"", "name = \"bob\"").replace("mass = -1.0", "mass = 1.0");
    match Scene::from_toml(&dup, "t.toml").unwrap_err() {
        SceneError::Invalid { line, column, path, .. } => {
            assert_eq!((line, column, path.as_str()), (11, 1, "bodies[1].name"))
        }
        e => panic!("{e}"),
    }
}

#[test]
fn issue_16_weld_only_scene_runs() {
    let text = "name = \"w\"\nduration = 1.0\nsamples = 10\noutputs = [\"position:a\", \"energy\"]\nchecks = \
                [\"energy\"]\n[[bodies]]\nname = \"a\"\njoint = { type = \"weld\" }\noffset = [1.0, 2.0, 3.0]\nmass = { \
                shape = \"sphere\", mass = 1.0, radius = 0.1 }\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, 0.0, \
                -9.81]\n";
    let r = run(&Scene::from_toml(text, "w.toml").unwrap());
    assert_eq!(r.t.len(), 11);
    assert!(r.is_complete());
    assert_eq!(r.column("position:a.z").unwrap(), vec![3.0; 11]);
    let d = &r.drift[0];
    assert_eq!(d.max_abs, 0.0);
    assert!(matches!(d.initial, InvariantValue::Scalar(u) if (u - 9.81 * 3.0).abs() < 1e-12));
}

// ----------------------------------------------------------- item 8: the format reference

/// The backticked names after "expected" or "valid:" in a loader message (`expected one of
/// `a`, `b``, `unknown key `k`; valid: `a`, `b` (did you mean `a`?)`).
fn expected_names(message: &str) -> Vec<String> {
    let Some((_, tail)) = message.split_once("expected").or_else(|| message.split_once("valid:")) else {
        return vec![];
    };
    let tail = tail.split(" (did you mean").next().unwrap_or(tail);
    tail.split('`').skip(1).step_by(2).map(str::to_string).collect()
}

/// The message of loading `text`, which must fail.
fn message_of(text: &str) -> String {
    match Scene::from_toml(text, "probe.toml") {
        Err(SceneError::Parse { message, .. }) | Err(SceneError::Invalid { message, .. }) => message,
        other => panic!("expected an error, got {other:?}"),
    }
}

#[test]
fn issue_16_scene_reference_documents_every_key_and_variant() {
    let doc = std::fs::read_to_string(format!("{}/docs/scenes.md", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let mut missing = Vec::new();
    let mut need = |what: &str, names: Vec<String>| {
        assert!(!names.is_empty(), "{what}: no names found (probe broken)");
        for n in names {
            if !doc.contains(&format!("`{n}`"))
                && !doc.contains(&format!("`{n} "))
                && !doc.contains(&format!("`{n}:"))
            {
                missing.push(format!("{what}: {n}"));
            }
        }
    };
    let base = "name = \"p\"\nduration = 1.0\n";
    let body = |joint: &str, mass: &str, extra: &str| {
        format!("{base}[[bodies]]\nname = \"b\"\njoint = {joint}\nmass = {mass}\n{extra}")
    };
    let sphere = "{ shape = \"sphere\", mass = 1.0, radius = 0.1 }";
    let free = "{ type = \"free\" }";
    need("top-level key", expected_names(&message_of(&format!("{base}zzz = 1\n"))));
    need("body key", expected_names(&message_of(&body(free, sphere, "zzz = 1\n"))));
    let joints = expected_names(&message_of(&body("{ type = \"zzz\" }", sphere, "")));
    for j in &joints {
        let fields =
            expected_names(&message_of(&body(&format!("{{ type = \"{j}\", zzz = 1 }}"), sphere, "")));
        need(&format!("joint {j} key"), if fields.is_empty() { vec![j.clone()] } else { fields });
    }
    need("joint type", joints);
    let shapes = expected_names(&message_of(&body(free, "{ shape = \"zzz\" }", "")));
    for s in &shapes {
        let fields = expected_names(&message_of(&body(free, &format!("{{ shape = \"{s}\", zzz = 1 }}"), "")));
        need(&format!("shape {s} key"), if fields.is_empty() { vec![s.clone()] } else { fields });
    }
    need("mass shape", shapes);
    let scene = |effect: &str| format!("{}\n[[effects]]\n{effect}\n", body(free, sphere, ""));
    let effects = expected_names(&message_of(&scene("type = \"zzz\"")));
    for e in &effects {
        need(
            &format!("effect {e} key"),
            expected_names(&message_of(&scene(&format!("type = \"{e}\"\nzzz = 1")))),
        );
    }
    need("effect type", effects);
    let with_loop = |l: &str| format!("{}\n[[loops]]\n{l}\n", body(free, sphere, ""));
    let loops = expected_names(&message_of(&with_loop("type = \"zzz\"")));
    for l in &loops {
        need(
            &format!("loop {l} key"),
            expected_names(&message_of(&with_loop(&format!("type = \"{l}\"\nzzz = 1")))),
        );
    }
    need("loop type", loops);
    let force = |profile: &str| {
        scene(&format!("type = \"torque\"\nbody = \"b\"\ndirection = [0.0, 0.0, 1.0]\nprofile = {profile}"))
    };
    let kinds = expected_names(&message_of(&force("{ kind = \"zzz\" }")));
    for k in &kinds {
        need(
            &format!("profile {k} key"),
            expected_names(&message_of(&force(&format!("{{ kind = \"{k}\", zzz = 1 }}")))),
        );
    }
    need("profile kind", kinds);
    need(
        "point key",
        expected_names(&message_of(&scene(
            "type = \"spring\"\nk = 1.0\na = { body = \"b\", zzz = 1 }\nb = { body = \"ground\" }",
        ))),
    );
    need(
        "method key",
        expected_names(&message_of(&format!(
            "{base}method = {{ name = \"dop853\", rtol = 1e-6, zzz = 1 }}\n"
        ))),
    );
    need(
        "frame key",
        expected_names(&message_of(&format!(
            "{base}[[frames]]\nname = \"f\"\naxis = [1.0, 0.0, 0.0]\nangle = 0.1\nzzz = 1\n"
        ))),
    );
    need(
        "dipole key",
        expected_names(&message_of(&scene(
            "type = \"dipoles\"\ndipoles = [{ body = \"b\", moment = [0.0, 0.0, 1.0], zzz = 1 }]",
        ))),
    );
    // outputs and checks: the valid lists of their error messages
    let valid = |m: String| -> Vec<String> {
        m.split("valid:")
            .nth(1)
            .unwrap_or("")
            .split(',')
            .map(|w| w.trim().trim_end_matches(":BODY").to_string())
            .filter(|w| !w.is_empty())
            .collect()
    };
    need(
        "output",
        valid(message_of(&format!(
            "{base}outputs = [\"zzz\"]\n[[bodies]]\nname = \"b\"\njoint = {free}\nmass = {sphere}\n"
        ))),
    );
    need(
        "check",
        valid(message_of(&format!(
            "{base}checks = [\"zzz\"]\n[[bodies]]\nname = \"b\"\njoint = {free}\nmass = {sphere}\n"
        ))),
    );
    // the aircraft: the aero effect's coefficient names
    need(
        "aero coefficient",
        valid(message_of(&scene(
            "type = \"aero\"\nbody = \"b\"\naircraft = \"business_jet\"\ncoefficients = { zzz = 1.0 }",
        ))),
    );
    assert!(missing.is_empty(), "docs/scenes.md lacks: {missing:#?}");
}

#[test]
fn issue_16_worked_example_bead_on_free_wire() {
    // Book Ex 7.15.3 with J = m = x₀ = θ̇₀ = 1: c₀ = (J + m x²)θ̇ = 2, E = 1, and the wire's
    // angle as a function of the bead's position is the elliptic integral
    // θ(x) = ∫₁ˣ √2 du/√(u⁴ − 1) = ∫₀^{acosh x} √2 ds/√(1 + cosh² s) (u = cosh s), θ∞ = K(½).
    let text = std::fs::read_to_string(format!(
        "{}/examples/scenes/bead_on_free_wire.toml",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let r = run(&Scene::from_toml(&text, "bead_on_free_wire.toml").unwrap());
    let (theta, x) = (r.column("coordinates:wire.0").unwrap(), r.column("coordinates:bead.0").unwrap());
    let theta_of = |x: f64| -> f64 {
        // composite Gauss–Legendre (5 points) on 400 panels of a smooth integrand
        let (a, b) = (0.0, x.acosh());
        let nodes = [
            (0.0, 128.0 / 225.0),
            (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
            (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
            (0.906_179_845_938_664, 0.236_926_885_056_189_1),
            (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
        ];
        let n = 400;
        let h = (b - a) / n as f64;
        (0..n)
            .map(|k| {
                let c = a + (k as f64 + 0.5) * h;
                nodes
                    .iter()
                    .map(|(z, w)| w * 0.5 * h * 2f64.sqrt() / (1.0 + (c + 0.5 * h * z).cosh().powi(2)).sqrt())
                    .sum::<f64>()
            })
            .sum()
    };
    let mut worst: f64 = 0.0;
    for k in (1..r.t.len()).step_by(50) {
        worst = nan_max(worst, (theta[k] - theta_of(x[k])).abs());
    }
    assert!(worst < 1e-8, "θ(x) off by {worst:e}");
    // θ approaches K(½) = 1.854074677301372 from below
    let last = *theta.last().unwrap();
    assert!(last < 1.854_074_677_301_372 && last > 1.80, "{last}");
    for d in &r.drift {
        assert!(d.max_rel < 1e-8, "{:?}", d);
    }
}

// --------------------------------------------------- issue 21: quantities in scene files

#[test]
fn issue_21_quantity_strings_give_the_si_trajectory_to_rounding() {
    // the same pendulum in SI numbers and in imperial quantity strings (exact factors: ft =
    // 0.3048 m, lb = 0.45359237 kg): the trajectories agree to a few roundings
    let si = "name = \"p\"\nduration = 2.0\nsamples = 20\naccuracy = 1e-10\noutputs = [\"coordinates:bob\", \
              \"energy\"]\n[[bodies]]\nname = \"bob\"\njoint = { type = \"pin\", axis = [0.0, 0.0, 1.0] }\nmass = { \
              shape = \"particle\", mass = 0.45359237 }\ncom = [0.0, -0.9144, 0.0]\nq = [0.5235987755982988]\n\
              [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.80665, 0.0]\n";
    let imperial = si
        .replace("mass = 0.45359237", "mass = \"1 lb\"")
        .replace("com = [0.0, -0.9144, 0.0]", "com = [\"0 ft\", \"-3 ft\", \"0 in\"]")
        .replace("q = [0.5235987755982988]", "q = [\"30 deg\"]")
        .replace("g = [0.0, -9.80665, 0.0]", "g = [\"0 ft/s^2\", \"-1 g0\", \"0 m/s^2\"]")
        .replace("duration = 2.0", "duration = \"2 s\"");
    let (a, b) = (
        run(&Scene::from_toml(si, "si.toml").unwrap()),
        run(&Scene::from_toml(&imperial, "imp.toml").unwrap()),
    );
    assert_eq!(a.t, b.t);
    for (ra, rb) in a.rows.iter().zip(&b.rows) {
        for (x, y) in ra.iter().zip(rb) {
            assert!((x - y).abs() <= 1e-12 * x.abs().max(1.0), "{x} vs {y}");
        }
    }
}

#[test]
fn issue_21_wrong_units_are_located_errors() {
    let base = pendulum("name = \"p\"");
    for (from, to, col, what) in [
        // a length given as a mass: the error names both dimensions, at the unit
        ("com = [0.0, -1.0, 0.0]", "com = [0.0, \"-1 kg\", 0.0]", 17, "length"),
        ("mass = 1.0", "mass = \"1 furlong\"", 37, "furlong"),
        ("q = [0.5]", "q = [\"thirty deg\"]", 6, "thirty"),
        ("q = [0.5]", "q = [\"1e400 deg\"]", 6, "1e400"),
    ] {
        let text = base.replace(from, to);
        assert_ne!(text, base, "{from}");
        match Scene::from_toml(&text, "p.toml").unwrap_err() {
            SceneError::Invalid { line, column, message, .. } => {
                let l =
                    text.lines().position(|l| l.contains(to.split('=').next().unwrap().trim())).unwrap() + 1;
                assert_eq!(line, l, "{message}");
                assert!(column >= col, "{to}: column {column}, {message}");
                assert!(message.contains(what) && message.contains("valid:"), "{message}");
            }
            e => panic!("{to}: {e}"),
        }
    }
}

#[test]
fn issue_21_outputs_in_imperial_units() {
    let dir = temp_dir("imperial");
    std::fs::write(
        dir.join("p.toml"),
        pendulum("name = \"pend\"").replace("[\"energy\"]", "[\"energy\", \"position:bob\"]"),
    )
    .unwrap();
    assert!(vectrix(&dir, &["run", "p.toml", "--quiet", "--out", "si"]).status.success());
    assert!(
        vectrix(&dir, &["run", "p.toml", "--quiet", "--out", "imp", "--units", "imperial"]).status.success()
    );
    let si = std::fs::read_to_string(dir.join("si/pend/trajectory.csv")).unwrap();
    let imp = std::fs::read_to_string(dir.join("imp/pend/trajectory.csv")).unwrap();
    assert!(si.lines().next().unwrap().contains("position:bob.y [m]"), "{si}");
    let head = imp.lines().next().unwrap();
    assert!(head.contains("position:bob.y [ft]") && head.contains("energy [ft*lbf]"), "{head}");
    // y = −cos(0.5) m at t = 0, written in feet (0.3048 m exactly)
    let col = head.split(',').position(|c| c.starts_with("position:bob.y")).unwrap();
    let y_ft: f64 = imp.lines().nth(1).unwrap().split(',').nth(col).unwrap().parse().unwrap();
    assert!((y_ft + 0.5f64.cos() / 0.3048).abs() < 4.0 * f64::EPSILON * y_ft.abs(), "{y_ft}");
    let summary = std::fs::read_to_string(dir.join("imp/pend/summary.json")).unwrap();
    assert!(summary.contains("\"units\": \"imperial\""), "{summary}");
    let o = vectrix(&dir, &["run", "p.toml", "--quiet", "--out", "x", "--units", "furlongs"]);
    assert_eq!(o.status.code(), Some(1));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn issue_16_a_cancelled_run_keeps_what_it_computed() {
    use std::sync::atomic::{AtomicBool, Ordering};
    use vectrix::scene::RunControl;
    let scene = kepler_scene(0.9, 4.0, 400, 1e-10);
    let cancel = AtomicBool::new(false);
    let mut progress = |f: f64| {
        if f > 0.3 {
            cancel.store(true, Ordering::Relaxed);
        }
    };
    let r = scene.run_with(RunControl { progress: &mut progress, cancel: Some(&cancel) }).unwrap();
    let stop = r.stop.as_ref().expect("stopped");
    assert_eq!(stop.reason, StopReason::Interrupted);
    assert!(r.t.len() > 100 && r.t.len() < 401, "{}", r.t.len());
    assert!(*r.t.last().unwrap() <= stop.t);
    // what was computed is right
    assert!(kepler_error(&r, 0.9) < 1e-6);
}

#[cfg(unix)]
#[test]
fn issue_16_ctrl_c_writes_the_rows_computed_marked_incomplete() {
    // a long run, interrupted by SIGINT: exit code 130, output written, "complete": false
    let dir = temp_dir("sigint");
    let text = pendulum("name = \"long\"").replace("duration = 0.2", "duration = 1e6\nmax_steps = 100000000");
    std::fs::write(dir.join("l.toml"), text).unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_vectrix"))
        .current_dir(&dir)
        .args(["run", "l.toml", "--quiet", "--out", "o"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(1500));
    let ok = Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
    assert!(ok.success());
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(130), "{}", String::from_utf8_lossy(&o.stderr));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("o/long/summary.json")).unwrap()).unwrap();
    assert_eq!(s["complete"], serde_json::Value::Bool(false));
    assert_eq!(s["stop"]["reason"], "interrupted");
    let rows = s["rows"].as_u64().unwrap();
    let csv = std::fs::read_to_string(dir.join("o/long/trajectory.csv")).unwrap();
    assert_eq!(csv.lines().count() as u64, rows + 1);
    let _ = std::fs::remove_dir_all(&dir);
}
