//! Closed loops in scenes (issue 17, items 4–5): the example scenes `four_bar.toml`,
//! `slider_crank.toml` and `pendulum_ball_loop.toml` against closed forms that share nothing
//! with the simulator: Freudenstein's equation and the Grashof limits of the rocker, the
//! slider-crank's piston position x(θ) = r cos θ + √(l² − r² sin² θ), Euler's equations about a
//! fixed point for the reaction of a ball pivot, and free-body balances (§6.10) of the loop
//! reactions with accelerations taken by central differences of the written speeds.
//!
//! Book: §9.11 (constraints and multipliers), §6.10 (reactions), §7.8 (Euler's equations).

mod support;

use crate::support::{nan_max, nan_min};
use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use vectrix::scene::{Run, Scene, SceneError};

fn example(name: &str) -> (String, String) {
    let path = format!("{}/examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    (std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}")), path)
}

fn load(name: &str) -> Scene {
    let (text, path) = example(name);
    Scene::from_toml(&text, &path).unwrap_or_else(|e| panic!("{e}"))
}

fn run(scene: &Scene) -> Run {
    scene.run(&mut |_| {}).unwrap_or_else(|e| panic!("{e}"))
}

fn col(run: &Run, name: &str) -> Vec<f64> {
    run.column(name).unwrap_or_else(|| panic!("no column {name} in {:?}", run.columns))
}

/// Fourth-order central differences of samples spaced `h` apart (interior points only:
/// index k ↦ k + 2): (−x₊₂ + 8x₊₁ − 8x₋₁ + x₋₂)/(12h), error h⁴/30·|x⁽⁵⁾|.
fn central(x: &[f64], h: f64) -> Vec<f64> {
    x.windows(5).map(|w| (-w[4] + 8.0 * w[3] - 8.0 * w[1] + w[0]) / (12.0 * h)).collect()
}

// Four-bar: crank a, coupler b, rocker c, ground d (examples/scenes/four_bar.toml).
const A: f64 = 1.0;
const B: f64 = 3.5;
const C: f64 = 3.0;
const D: f64 = 4.0;

/// The rocker's extreme angles, where crank and coupler are collinear: |O₂P| = b ± a and
/// |O₂P|² = d² + c² + 2dc cos θ₄ (P = O₄ + c e(θ₄), O₄ = (d, 0)).
fn rocker_limits() -> (f64, f64) {
    let theta4 = |r: f64| ((r * r - D * D - C * C) / (2.0 * D * C)).acos();
    (theta4(B + A), theta4(B - A))
}

#[test]
fn section_9_11_four_bar_scene_freudenstein_and_grashof() {
    let run = run(&load("four_bar.toml"));
    let (t2, t4) = (col(&run, "coordinates:crank.0"), col(&run, "coordinates:rocker.0"));
    // Freudenstein: K₁ cos θ₄ − K₂ cos θ₂ + K₃ = cos(θ₂ − θ₄) with K₁ = d/a, K₂ = d/c,
    // K₃ = (a² − b² + c² + d²)/(2ac)
    let (k1, k2, k3) = (D / A, D / C, (A * A - B * B + C * C + D * D) / (2.0 * A * C));
    let worst = t2
        .iter()
        .zip(&t4)
        .map(|(a2, a4)| (k1 * a4.cos() - k2 * a2.cos() + k3 - (a2 - a4).cos()).abs())
        .fold(0.0, nan_max);
    // absolute: the residual is a sum of O(K) terms, each exact to the projection tolerance
    assert!(worst <= 1e-9, "Freudenstein residual {worst:e}");
    // Grashof (s + l = 5 ≤ p + q = 6.5, crank shortest): the crank turns round and round ...
    assert!(t2.windows(2).all(|w| w[1] > w[0]), "the crank turns one way");
    assert!(t2[t2.len() - 1] - t2[0] > 4.0 * std::f64::consts::TAU, "the crank makes full turns");
    // ... and the rocker swings between the collinear positions
    let (lo, hi) = rocker_limits();
    let (min, max) =
        t4.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (nan_min(a, *x), nan_max(b, *x)));
    assert!(min >= lo - 1e-9 && max <= hi + 1e-9, "rocker in [{min}, {max}], limits [{lo}, {hi}]");
    // sampled every 2.5 ms the extremes are met to second order in the sample spacing
    assert!(min - lo <= 1e-4 && hi - max <= 1e-4, "rocker reaches [{min}, {max}] of [{lo}, {hi}]");
}

#[test]
fn section_9_11_four_bar_scene_long_run_energy_and_drift() {
    // one minute (about 60 crank turns): the violation stays at the projection level
    let mut spec = load("four_bar.toml").spec().clone();
    spec.duration = 60.0;
    spec.samples = 600;
    spec.outputs = vec!["energy".into()];
    let run = run(&Scene::from_spec(spec).unwrap_or_else(|e| panic!("{e}")));
    let v = run.max_constraint_violation.expect("a scene with loops reports its violation");
    assert!(v.position <= 1e-10 && v.velocity <= 1e-9, "{v:?}");
    let e = &run.drift[0];
    assert!(e.max_rel <= 1e-9, "energy drift {e:?}");
    assert!(run.work.fevals > 0);
}

#[test]
fn section_6_10_four_bar_rocker_moment_balance() {
    // The rocker alone (§6.10): J_O₄ θ̈₄ = ((P − O₄) × F)_z + ((c − O₄) × m g)_z, F the force of
    // the loop pin on the rocker = −(the reported force on the coupler). θ̈₄ by central
    // differences of the written rocker speed; J_O₄ = m c²/3 for a uniform bar.
    let scene = load("four_bar.toml");
    let run = run(&scene);
    let h = scene.spec().duration / scene.spec().samples as f64;
    let (t4, w4) = (col(&run, "coordinates:rocker.0"), col(&run, "speeds:rocker.0"));
    let (fx, fy) = (col(&run, "reaction:coupler_rocker.x"), col(&run, "reaction:coupler_rocker.y"));
    let mz = col(&run, "reaction:coupler_rocker.mz");
    let (m, g) = (1.0, 9.81);
    let alpha = central(&w4, h);
    let mut worst: f64 = 0.0;
    let mut scale: f64 = 0.0;
    for (k, a4) in alpha.iter().enumerate() {
        let i = k + 2;
        let e = Vector3::new(t4[i].cos(), t4[i].sin(), 0.0);
        let f_rocker = -Vector3::new(fx[i], fy[i], 0.0);
        let torque = (e * C).cross(&f_rocker).z + (e * (C / 2.0)).cross(&Vector3::new(0.0, -m * g, 0.0)).z;
        worst = nan_max(worst, (m * C * C / 3.0 * a4 - torque).abs());
        scale = nan_max(scale, torque.abs());
        // a planar pin's couple rows are dependent: dropped, reported as 0
        assert_eq!(mz[i], 0.0);
    }
    // fourth-order differences at h = 2.5 ms: truncation about 1e-7 of the torques here
    assert!(worst <= 1e-5 * scale, "moment balance off by {worst:e} (torques up to {scale:e})");
}

#[test]
fn section_9_11_slider_crank_scene_piston_position_and_balance() {
    let mut spec = load("slider_crank.toml").spec().clone();
    spec.outputs.push("speeds:piston".into());
    let scene = Scene::from_spec(spec).unwrap_or_else(|e| panic!("{e}"));
    let run = run(&scene);
    let (r, l) = (0.5, 2.0);
    let (theta, x) = (col(&run, "coordinates:crank.0"), col(&run, "coordinates:piston.0"));
    let worst = theta
        .iter()
        .zip(&x)
        .map(|(t, x)| (x - (r * t.cos() + (l * l - r * r * t.sin().powi(2)).sqrt())).abs())
        .fold(0.0, nan_max);
    assert!(worst <= 1e-9, "piston position off the closed form by {worst:e} m");
    assert!(theta[theta.len() - 1] > 5.0 * std::f64::consts::TAU, "the crank turns");
    assert!(run.drift[0].max_rel <= 1e-9, "energy {:?}", run.drift[0]);
    // the piston alone (§6.10): m ẍ = F_x, F the pin's force on the piston = −(force on the rod)
    let h = scene.spec().duration / scene.spec().samples as f64;
    let (xd, fx) = (col(&run, "speeds:piston.0"), col(&run, "reaction:wrist_pin.x"));
    let xdd = central(&xd, h);
    let scale = fx.iter().fold(0.0_f64, |m, f| nan_max(m, f.abs()));
    let worst = xdd.iter().enumerate().map(|(k, a)| (1.5 * a + fx[k + 2]).abs()).fold(0.0, nan_max);
    // fourth-order differences at h = 2 ms: the piston's acceleration carries harmonics of the
    // crank rate up to ~4ω (ω ≈ 10 rad/s), truncation (4ωh)⁴/30 ≈ 1e-6 per harmonic; measured
    // 2e-5 of the largest force, asserted 1e-4
    assert!(worst <= 1e-4 * scale, "piston balance off by {worst:e} N (forces up to {scale:e} N)");
}

#[test]
fn section_6_10_pendulum_ball_loop_reaction_by_euler_about_the_pivot() {
    // A box on a free joint held at one end by a ball loop. About the fixed pivot O:
    // J_O α + ω × J_O ω = ρ × m g (ρ = c − O), and the pivot's force on the box is
    // F = m(α × ρ + ω × (ω × ρ)) − m g: computed here from the written state alone.
    let run = run(&load("pendulum_ball_loop.toml"));
    let (m, g) = (2.0, Vector3::new(0.0, -9.81, 0.0));
    // box 1 × 0.1 × 0.1 about its centre, link axes; parallel axes to the pivot at (−0.5, 0, 0)
    let jc = Matrix3::from_diagonal(&Vector3::new(
        m * (0.01 + 0.01) / 12.0,
        m * (1.0 + 0.01) / 12.0,
        m * (1.0 + 0.01) / 12.0,
    ));
    let d = Vector3::new(0.5, 0.0, 0.0); // centre relative to the pivot, link components
    let j_o_link = jc + m * (Matrix3::identity() * d.norm_squared() - d * d.transpose());
    let c = |k: &str| col(&run, k);
    let q: Vec<Vec<f64>> = (3..7).map(|k| c(&format!("coordinates:bar.{k}"))).collect();
    let (wx, wy, wz) = (c("omega:bar.x"), c("omega:bar.y"), c("omega:bar.z"));
    let (px, py, pz) = (c("position:bar.x"), c("position:bar.y"), c("position:bar.z"));
    let (fx, fy, fz) = (c("reaction:pivot.x"), c("reaction:pivot.y"), c("reaction:pivot.z"));
    let mut worst: f64 = 0.0;
    let mut off_pivot: f64 = 0.0;
    for i in 0..run.t.len() {
        // q: the quaternion of the link relative to the ground, scalar first; R maps link to ground
        let r = UnitQuaternion::from_quaternion(Quaternion::new(q[0][i], q[1][i], q[2][i], q[3][i]));
        let rot = r.to_rotation_matrix().into_inner();
        let j_o = rot * j_o_link * rot.transpose();
        let rho = Vector3::new(px[i], py[i], pz[i]); // the pivot is the origin
        off_pivot = nan_max(off_pivot, (rho - rot * d).norm());
        let w = Vector3::new(wx[i], wy[i], wz[i]);
        let alpha = j_o.lu().solve(&(rho.cross(&(g * m)) - w.cross(&(j_o * w)))).expect("J_O invertible");
        let f = m * (alpha.cross(&rho) + w.cross(&w.cross(&rho))) - m * g;
        worst = nan_max(worst, (f - Vector3::new(fx[i], fy[i], fz[i])).norm());
    }
    // the written states hold the pivot to the projection tolerance
    assert!(off_pivot <= 1e-10, "the bar's end is {off_pivot:e} m off the pivot");
    // relative to the weight m|g| ≈ 19.6 N: the multipliers' rounding, not truncation
    assert!(worst <= 1e-9 * m * 9.81, "reaction off the Euler balance by {worst:e} N");
}

#[test]
fn section_9_11_loop_points_take_quantity_strings() {
    // issue 21: every number of a scene may carry its unit, the loops' points too
    let (text, _) = example("four_bar.toml");
    let si = Scene::from_toml(&text, "si.toml").unwrap_or_else(|e| panic!("{e}"));
    let cm = text.replace(
        "a = { body = \"coupler\", point = [3.5, 0.0, 0.0] }",
        "a = { body = \"coupler\", point = [\"350 cm\", \"0 m\", \"0 ft\"] }",
    );
    assert_ne!(cm, text);
    let cm = Scene::from_toml(&cm, "cm.toml").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(cm.initial_state(), si.initial_state(), "350 cm is 3.5 m exactly");
    // a length where a direction is expected is an error naming both dimensions
    let bad = text.replace(
        "axis = [0.0, 0.0, 1.0]\n\n[[effects]]",
        "axis = [\"0 m\", \"0 m\", \"1 m\"]\n\n[[effects]]",
    );
    match Scene::from_toml(&bad, "bad.toml") {
        Err(SceneError::Invalid { path, .. }) => assert!(path.starts_with("loops[0].axis"), "{path}"),
        other => panic!("expected a dimension error, got {other:?}"),
    }
}

fn invalid(text: &str) -> (String, String) {
    match Scene::from_toml(text, "t.toml") {
        Err(SceneError::Invalid { path, message, .. }) => (path, message),
        other => panic!("expected a located error, got {other:?}"),
    }
}

#[test]
fn section_9_11_scene_loop_errors_are_located() {
    let (text, _) = example("four_bar.toml");
    // the same rounded start without `assemble`: refused, naming the loop
    let (path, message) = invalid(&text.replace("assemble = true\n", ""));
    assert_eq!(path, "loops[0]");
    assert!(message.contains("coupler_rocker") && message.contains("assemble = true"), "{message}");
    // a linkage that cannot close (ground longer than the other three bars together)
    let (path, message) = invalid(&text.replace("offset = [4.0, 0.0, 0.0]", "offset = [9.0, 0.0, 0.0]"));
    assert_eq!(path, "assemble", "{message}");
    // reactions of loops that do not exist
    let (path, message) = invalid(&text.replace("\"reaction:coupler_rocker\"", "\"reaction:crank_rocker\""));
    assert!(path.starts_with("outputs[") && message.contains("coupler_rocker"), "{path}: {message}");
    // both ends on the same body, or both on the ground
    let (path, _) = invalid(&text.replace("b = { body = \"rocker\"", "b = { body = \"coupler\""));
    assert_eq!(path, "loops[0].b.body");
    let (path, _) = invalid(
        &text
            .replace("a = { body = \"coupler\"", "a = { body = \"ground\"")
            .replace("b = { body = \"rocker\"", "b = { body = \"ground\""),
    );
    assert_eq!(path, "loops[0].a.body");
    // a zero pin axis
    let (path, message) = invalid(
        &text.replace("axis = [0.0, 0.0, 1.0]\n\n[[effects]]", "axis = [0.0, 0.0, 0.0]\n\n[[effects]]"),
    );
    assert!(path.starts_with("loops[0]"), "{path}: {message}");
}
