//! Stiff scenes: the example scenes `stiff_spring_pendulum` and `damped_chain` under the
//! default accuracy pick RADAU5 by the stiffness test, with the exact (dual-number) Jacobian,
//! and match their closed forms; a non-stiff scene keeps DOP853; `method = { name = "radau5" }`
//! and `method = { name = "bdf" }` force an implicit method.
//!
//! Book: §4.11; §6.7 (springs), §6.8 (dashpots); HW = Hairer & Wanner, *Solving ODEs II*,
//! §IV.1 (stiffness), §IV.8 (RADAU5); the elastic pendulum's linear modes: Lynch, "The
//! swinging spring", Physica D 2002, §2.

use std::f64::consts::PI;

use vectrix::scene::{Run, STIFF_RATIO, Scene};

fn example(name: &str) -> Scene {
    let path = format!("{}/examples/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("example scene exists");
    Scene::from_toml(&text, &path).unwrap_or_else(|e| panic!("{e}"))
}

fn run(scene: &Scene) -> Run {
    scene.run(&mut |_| {}).unwrap_or_else(|e| panic!("{e}"))
}

/// Complete elliptic integral of the first kind K(k) = π / (2 AGM(1, √(1−k²))).
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..40 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

/// Times where x crosses `level` downward, by linear interpolation between samples.
fn down_crossings(t: &[f64], x: &[f64], level: f64) -> Vec<f64> {
    (1..x.len())
        .filter(|&i| x[i - 1] > level && x[i] <= level)
        .map(|i| t[i - 1] + (t[i] - t[i - 1]) * (x[i - 1] - level) / (x[i - 1] - x[i]))
        .collect()
}

#[test]
fn stiff_spring_pendulum_swings_with_the_stretched_rigid_period() {
    let scene = example("stiff_spring_pendulum");
    let choice = scene.method_choice();
    assert_eq!(choice.name, "radau5", "{choice}");
    assert_eq!(choice.jacobian, "exact (dual numbers)");
    assert!(choice.reason.starts_with("stiff"), "{choice}");
    let r = run(&scene);
    assert!(r.stop.is_none(), "{:?}", r.stop);
    assert_eq!(r.method.name, "radau5");
    // m = 1, g = 9.81, k = 4e5, l₀ = 1, θ₀ = 0.1 (the scene file). The swing about the
    // stretched equilibrium L = l₀ + mg/k is the rigid pendulum of length L to O(θ₀² mg/k)
    // (Lynch §2: swing and stretch decouple at linear order); the amplitude enters through
    // K(sin(θ₀/2)) exactly as for the rigid pendulum.
    let (g, k, l0, theta0): (f64, f64, f64, f64) = (9.81, 4e5, 1.0, 0.1);
    let big_l = l0 + g / k;
    let t_pred = 4.0 * (big_l / g).sqrt() * elliptic_k((theta0 / 2.0).sin());
    let t_rigid = 4.0 * (l0 / g).sqrt() * elliptic_k((theta0 / 2.0).sin());
    let theta = r.column("coordinates:arm.0").expect("arm angle column");
    let zeros = down_crossings(&r.t, &theta, 0.0);
    assert!(zeros.len() >= 3, "{zeros:?}");
    let period = (zeros[2] - zeros[0]) / 2.0;
    let rel = (period / t_pred - 1.0).abs();
    // 2e-6: the accuracy 1e-6 of the run (RADAU5 at rtol 1e-7) plus the neglected
    // O(θ₀² mg/(k l₀)) ≈ 2e-7 coupling
    assert!(rel < 2e-6, "period {period} vs {t_pred}: {rel:e}");
    // the O(mg/k) correction is resolved: the rigid period misses by mg/(2kl₀) = 1.2e-5
    let miss = period / t_rigid - 1.0;
    assert!((miss / (0.5 * g / (k * l0)) - 1.0).abs() < 0.2, "rigid miss {miss:e}");
    // energy is conserved to the accuracy (RADAU5 damps only what it does not resolve)
    let e = r.drift.iter().find(|d| d.invariant.name() == "energy").expect("energy checked");
    assert!(e.max_rel < 1e-5, "energy drift {:e}", e.max_rel);
    // cheap: far fewer steps than DOP853's stability bound ρ·T/6 ≈ 632·10/6 ≈ 1000
    assert!(r.work.accepted < 1000, "{:?}", r.work);
}

#[test]
fn damped_chain_settles_to_the_static_stretch() {
    let scene = example("damped_chain");
    let choice = scene.method_choice();
    assert_eq!(choice.name, "radau5", "{choice}");
    assert_eq!(choice.jacobian, "exact (dual numbers)");
    let r = run(&scene);
    assert!(r.stop.is_none(), "{:?}", r.stop);
    assert_static_stretch(&r);
}

/// At rest each spring of `damped_chain` carries F = 10 N: xᵢ = i (1 + F/k), k = 1e4; the
/// slowest mode (rate ≈ 11 /s) has decayed by e^{-22} from an amplitude of 3e-3 m by t = 2 s.
fn assert_static_stretch(r: &Run) {
    for (i, c) in ["c1", "c2", "c3"].iter().enumerate() {
        let x = *r.column(&format!("coordinates:{c}.0")).expect("column").last().expect("rows");
        let want = (i + 1) as f64 * (1.0 + 10.0 / 1e4);
        assert!((x - want).abs() < 1e-8, "{c}: {x} vs {want}");
    }
}

#[test]
fn a_non_stiff_scene_keeps_the_explicit_method_and_says_why() {
    let scene = example("simple_pendulum");
    let choice = scene.method_choice();
    assert_eq!(choice.name, "dop853", "{choice}");
    assert!(choice.reason.contains("not stiff"), "{choice}");
    assert!(choice.reason.contains(&format!("stiff from {STIFF_RATIO}")), "{choice}");
}

#[test]
fn method_bdf_is_forced_by_name_and_settles_the_damped_chain() {
    let mut spec = example("damped_chain").spec().clone();
    spec.method = Some(vectrix::scene::spec::MethodSpec { name: "bdf".into(), rtol: 1e-9 });
    spec.accuracy = None;
    let scene = Scene::from_spec(spec).expect("valid");
    let choice = scene.method_choice();
    assert_eq!(choice.name, "bdf", "{choice}");
    assert_eq!(choice.jacobian, "exact (dual numbers)");
    assert!(choice.to_string().contains("Jacobian exact"), "{choice}");
    let r = run(&scene);
    assert!(r.stop.is_none(), "{:?}", r.stop);
    assert_static_stretch(&r);
}

#[test]
fn method_radau5_is_forced_by_name() {
    let mut spec = example("simple_pendulum").spec().clone();
    spec.method = Some(vectrix::scene::spec::MethodSpec { name: "radau5".into(), rtol: 1e-10 });
    spec.accuracy = None;
    let scene = Scene::from_spec(spec).expect("valid");
    assert_eq!(scene.method_choice().name, "radau5");
    assert!(scene.method_choice().reason.contains("named"));
    let r = run(&scene);
    // the rigid pendulum at θ₀ = 1 rad: T = 4 √(L/g) K(sin(θ₀/2)); 2.5 periods in 5 s
    let t_exact = 4.0 * (1.0 / 9.81f64).sqrt() * elliptic_k(0.5f64.sin());
    let theta = r.column("coordinates:bob.0").expect("column");
    let zeros = down_crossings(&r.t, &theta, 0.0);
    let period = zeros[1] - zeros[0];
    assert!((period / t_exact - 1.0).abs() < 1e-6, "{period} vs {t_exact}");
    // and a misspelt name says what is valid
    let mut spec = example("simple_pendulum").spec().clone();
    spec.method = Some(vectrix::scene::spec::MethodSpec { name: "radau".into(), rtol: 1e-6 });
    let Err(e) = Scene::from_spec(spec) else { panic!("method `radau` accepted") };
    let e = e.to_string();
    assert!(e.contains("radau5"), "{e}");
}
