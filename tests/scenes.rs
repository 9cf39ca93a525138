//! Scenes: the example scenes against their exact or published known quantities, round trips
//! of the file format, the declared-effects rule, error locations, and a proptest fuzz of
//! the loader (no input panics).
//!
//! Book: §7.8 (torque-free body), §7.11 (chains), §7.13 (collisions), §6.12 (gravitation),
//! §6.13 (dipoles), §8.3 (energy); pendulum periods by the complete elliptic integral.

use std::f64::consts::PI;

use vectrix::scene::{DEFAULT_SCENE, Invariant, Run, Scene, SceneError, SceneSpec};

/// Loads `examples/scenes/<name>.toml`.
fn example(name: &str) -> Scene {
    let path = format!("{}/examples/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("example scene exists");
    Scene::from_toml(&text, &path).unwrap_or_else(|e| panic!("{e}"))
}

/// The same scene with another duration and sample count (shorter runs in tests).
fn shortened(scene: &Scene, duration: f64, samples: usize) -> Scene {
    let mut spec = scene.spec().clone();
    spec.duration = duration;
    spec.samples = samples;
    Scene::from_spec(spec).expect("still valid")
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

/// Times where x crosses zero downward, by linear interpolation.
fn down_crossings(t: &[f64], x: &[f64]) -> Vec<f64> {
    (1..x.len())
        .filter(|&i| x[i - 1] > 0.0 && x[i] <= 0.0)
        .map(|i| t[i - 1] + (t[i] - t[i - 1]) * x[i - 1] / (x[i - 1] - x[i]))
        .collect()
}

fn drift(run: &Run, name: &str) -> f64 {
    run.drift
        .iter()
        .find(|d| d.invariant.name() == name)
        .map(|d| d.max_rel)
        .unwrap_or_else(|| panic!("{name} not checked"))
}

/// Relative tolerance for a period read off zero crossings: the integrator runs at 1e-9 and
/// the interpolation error at a zero crossing is O(Δt² θ″) with θ″ ≈ 0 there.
const PERIOD_TOL: f64 = 1e-6;

#[test]
fn example_simple_pendulum_period_is_elliptic() {
    // T = 4 K(sin(θ₀/2)) √(L/g) for the simple pendulum released from rest at θ₀.
    let run = run(&example("simple_pendulum"));
    let theta = run.column("coordinates:bob.0").unwrap();
    let c = down_crossings(&run.t, &theta);
    let exact = 4.0 * elliptic_k((0.5f64).sin()) * (1.0f64 / 9.81).sqrt();
    assert!((c[1] - c[0] - exact).abs() <= PERIOD_TOL * exact, "period {} vs {exact}", c[1] - c[0]);
    assert!(drift(&run, "energy") < 1e-8);
}

#[test]
fn example_physical_pendulum_period_is_elliptic() {
    // Rod pinned at an end: I_O = m l²/3, d = l/2, T = 4 K(sin(θ₀/2)) √(I_O/(m g d)).
    let run = run(&example("physical_pendulum"));
    let theta = run.column("coordinates:rod.0").unwrap();
    let c = down_crossings(&run.t, &theta);
    let (m, l, g) = (2.0f64, 0.8f64, 9.81f64);
    let exact = 4.0 * elliptic_k((0.3f64).sin()) * ((m * l * l / 3.0) / (m * g * l / 2.0)).sqrt();
    assert!((c[1] - c[0] - exact).abs() <= PERIOD_TOL * exact, "period {} vs {exact}", c[1] - c[0]);
}

#[test]
fn example_double_pendulum_conserves_energy() {
    // Gravity alone is conservative: T + U is the invariant derived from the declared effects.
    let scene = shortened(&example("double_pendulum"), 5.0, 500);
    assert_eq!(scene.invariants(), &[Invariant::Energy]);
    let run = run(&scene);
    assert!(drift(&run, "energy") < 1e-8, "{:?}", run.drift);
}

#[test]
fn example_heavy_top_steady_precession_rate() {
    // Steady precession: I₁ cosθ Ω² − C ω₃ Ω + m g l = 0 (slow root), I₁ = A_c + m l².
    let run = run(&example("heavy_top"));
    let (m, l, g, ac, c3, th, w3) = (1.0, 0.5, 9.81, 0.05, 0.1, 0.5f64, 60.0);
    let i1 = ac + m * l * l;
    let (a, b, c) = (i1 * th.cos(), -c3 * w3, m * g * l);
    let omega = (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
    let (x, y) = (run.column("position:top.x").unwrap(), run.column("position:top.y").unwrap());
    let n = run.t.len() - 1;
    // azimuth of the centre of mass, unwrapped over the run
    let mut phi = 0.0;
    for k in 1..=n {
        let d = y[k].atan2(x[k]) - y[k - 1].atan2(x[k - 1]);
        phi += (d + PI).rem_euclid(2.0 * PI) - PI;
    }
    let rate = phi / run.t[n];
    assert!((rate - omega).abs() <= 1e-6 * omega, "precession {rate} vs {omega}");
    assert!(drift(&run, "energy") < 1e-8);
    assert!(drift(&run, "angular_momentum") < 1e-8);
}

#[test]
fn example_torque_free_asymmetric_body_invariants() {
    // Euler's equations without torque (§7.8): T, p and H conserved.
    let scene = shortened(&example("torque_free_asymmetric"), 10.0, 200);
    let run = run(&scene);
    for name in ["energy", "angular_momentum"] {
        assert!(drift(&run, name) < 1e-8, "{:?}", run.drift);
    }
}

#[test]
fn example_bead_on_rotating_wire_cosh() {
    // r̈ = ω² r on a wire spinning at ω: r(t) = r₀ cosh(ω t).
    let run = run(&example("bead_on_rotating_wire"));
    let r = run.column("coordinates:bead.0").unwrap();
    for (t, r) in run.t.iter().zip(&r) {
        let exact = 0.1 * (2.0 * t).cosh();
        assert!((r - exact).abs() <= 1e-8 * exact, "t = {t}: {r} vs {exact}");
    }
}

#[test]
fn example_spring_dashpot_chain_static_deflection() {
    // At rest each spring carries F: x_i∞ = i (1 + F/k).
    let run = run(&example("spring_dashpot_chain"));
    for (i, name) in ["c1", "c2", "c3"].iter().enumerate() {
        let x = run.column(&format!("coordinates:{name}.0")).unwrap();
        let exact = (i + 1) as f64 * (1.0 + 10.0 / 50.0);
        assert!((x[x.len() - 1] - exact).abs() < 1e-6, "{name}: {} vs {exact}", x[x.len() - 1]);
    }
}

#[test]
fn example_kepler_orbit_period() {
    // T = 2π √(a³/μ): after one period the planet is back at periapsis; at T/2 at apoapsis a(1+e).
    let run = run(&example("kepler_orbit"));
    let (x, y) = (run.column("position:planet.x").unwrap(), run.column("position:planet.y").unwrap());
    let n = x.len() - 1;
    assert!((x[n] - 0.5).abs() < 1e-7 && y[n].abs() < 1e-7, "end ({}, {})", x[n], y[n]);
    assert!((x[n / 2] + 1.5).abs() < 1e-7 && y[n / 2].abs() < 1e-7, "half ({}, {})", x[n / 2], y[n / 2]);
    assert!(drift(&run, "energy") < 1e-9 && drift(&run, "angular_momentum") < 1e-9);
}

#[test]
fn example_colliding_spheres_restitution() {
    // Fact 7.13.1: u₁⁺ = ((m₁ − e m₂)u₁ + (1+e)m₂u₂)/(m₁+m₂), u₂⁺ = ((1+e)m₁u₁ + (m₂ − e m₁)u₂)/(m₁+m₂).
    let scene = example("colliding_spheres");
    assert!(!scene.invariants().contains(&Invariant::Energy), "e < 1 loses energy");
    let run = run(&scene);
    let (m1, m2, u1, u2, e) = (1.0, 2.0, 1.0, -0.5, 0.8);
    let u1p = ((m1 - e * m2) * u1 + (1.0 + e) * m2 * u2) / (m1 + m2);
    let u2p = ((1.0 + e) * m1 * u1 + (m2 - e * m1) * u2) / (m1 + m2);
    let (va, vb) = (run.column("velocity:a.x").unwrap(), run.column("velocity:b.x").unwrap());
    let n = va.len() - 1;
    assert!((va[n] - u1p).abs() < 1e-9 && (vb[n] - u2p).abs() < 1e-9, "{} {} vs {u1p} {u2p}", va[n], vb[n]);
    assert_eq!(run.work.impacts, 1);
    assert!(drift(&run, "momentum") < 1e-12);
}

#[test]
fn example_magnetic_dipoles_coaxial_force() {
    // Coaxial dipoles attract with |f| = 6 m₁ m₂ / r⁴ (6.13.11), units μ₀/4π = 1.
    let scene = example("magnetic_dipoles");
    let y = scene.initial_state();
    let d = scene.derivative(0.0, &y).unwrap();
    let nq = 14;
    let f = 6.0 * 0.1 * 0.1 / 1.0f64.powi(4);
    assert!((d[nq] - f).abs() < 1e-12 && (d[nq + 6] + f).abs() < 1e-12, "{} {}", d[nq], d[nq + 6]);
    let run = run(&scene);
    for name in ["energy", "momentum", "angular_momentum"] {
        assert!(drift(&run, name) < 1e-8, "{:?}", run.drift);
    }
}

#[test]
fn example_rolling_disk_on_incline() {
    // Rolling without slip down an incline: a = g sin α / (1 + J/(m r²)) = (2/3) g sin α.
    let run = run(&example("rolling_disk"));
    let alpha = 0.3f64;
    let a = 2.0 / 3.0 * 9.81 * alpha.sin();
    let (x, z) = (run.column("position:disk.x").unwrap(), run.column("position:disk.z").unwrap());
    let n = x.len() - 1;
    let s = (x[n] - x[0]) * alpha.cos() - (z[n] - z[0]) * alpha.sin();
    let t = run.t[n];
    assert!((s - 0.5 * a * t * t).abs() < 1e-6, "{s} vs {}", 0.5 * a * t * t);
    assert!(drift(&run, "energy") < 1e-6);
}

#[test]
fn default_scene_tennis_racket_flips() {
    // Near the intermediate axis the spin flips sign (Dzhanibekov): ω_y changes sign while
    // T and H stay constant.
    let scene = shortened(&Scene::from_toml(DEFAULT_SCENE, "default").unwrap(), 20.0, 400);
    let run = run(&scene);
    let wy = run.column("omega_body:racket.y").unwrap();
    assert!(wy.iter().any(|w| *w < -0.9), "no flip");
    assert!(drift(&run, "energy") < 1e-7 && drift(&run, "angular_momentum") < 1e-7);
}

#[test]
fn scene_round_trip_load_save_load() {
    for name in [
        "simple_pendulum",
        "physical_pendulum",
        "double_pendulum",
        "heavy_top",
        "torque_free_asymmetric",
        "bead_on_rotating_wire",
        "spring_dashpot_chain",
        "kepler_orbit",
        "colliding_spheres",
        "magnetic_dipoles",
        "rolling_disk",
        "tennis_racket",
    ] {
        let a = example(name);
        let text = a.to_toml().unwrap();
        let b = Scene::from_toml(&text, "saved").unwrap_or_else(|e| panic!("{name}: {e}\n{text}"));
        assert_eq!(a.spec(), b.spec(), "{name}");
    }
}

#[test]
fn declared_effects_without_gravity_have_no_gravity_term() {
    // A pendulum scene with the gravity effect removed: the model has no gravity and the
    // right-hand side equals the explicit ABA of the same tree with zero gravity and no loads.
    let mut spec: SceneSpec = example("double_pendulum").spec().clone();
    spec.effects.clear();
    let scene = Scene::from_spec(spec).unwrap();
    assert_eq!(scene.model().gravity, vectrix::nalgebra::Vector3::zeros());
    assert!(scene.invariants().contains(&Invariant::Energy));
    let y = scene.initial_state();
    let d = scene.derivative(0.0, &y).unwrap();
    let (nq, nv) = (scene.model().nq(), scene.model().nv());
    let explicit = scene.model().aba(&y[..nq], &y[nq..], &vec![0.0; nv], None).unwrap();
    assert_eq!(&d[nq..], explicit.as_slice());
    // at rest with no effects nothing moves
    assert!(d.iter().all(|x| *x == 0.0));
    // and with gravity declared the model carries exactly the declared g
    let with = example("double_pendulum");
    assert_eq!(with.model().gravity, vectrix::nalgebra::Vector3::new(0.0, -9.81, 0.0));
}

/// A cart on a sleeve tied to the ground by a spring k and `extra` effects.
fn cart(extra: &str) -> Scene {
    let text = format!(
        "name = \"cart\"\nduration = 2.0\nsamples = 400\naccuracy = 1e-10\noutputs = [\"coordinates:c\"]\n\
         [[bodies]]\nname = \"c\"\njoint = {{ type = \"sleeve\", axis = [1.0, 0.0, 0.0] }}\n\
         mass = {{ shape = \"particle\", mass = 2.0 }}\nq = [1.0]\n{extra}"
    );
    Scene::from_toml(&text, "cart").unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn inerter_adds_to_the_mass_period() {
    // Mass m, spring k (d = 0) and an inerter b to the ground (§6.8): m_eff = m + b, so
    // x(t) = cos(√(k/(m + b)) t) for x(0) = 1, ẋ(0) = 0.
    let s = cart(
        "[[effects]]\ntype = \"spring\"\na = { body = \"ground\" }\nb = { body = \"c\" }\nk = 8.0\n\
         [[effects]]\ntype = \"inerter\"\na = { body = \"ground\", point = [-5.0, 0.0, 0.0] }\nb = { body = \"c\" }\ninertance = 6.0\n",
    );
    assert!(s.invariants().contains(&Invariant::Energy));
    let run = run(&s);
    let x = run.column("coordinates:c.0").unwrap();
    let w = (8.0f64 / 8.0).sqrt();
    for (t, x) in run.t.iter().zip(&x) {
        // the inerter acts along the line from (−5,0,0): collinear with the motion
        assert!((x - (w * t).cos()).abs() < 1e-6, "t = {t}: {x}");
    }
}

#[test]
fn applied_force_profiles_ramp_equals_table() {
    // A ramp 0 → 4 N over [0, 1] s and the table through the same points give the same
    // motion; the exact one is x = 1 + (2/3) t³ / m for t ≤ 1 (F = 4t, m = 2).
    let ramp = cart(
        "[[effects]]\ntype = \"force\"\nat = { body = \"c\" }\ndirection = [1.0, 0.0, 0.0]\nprofile = { kind = \"ramp\", t0 = 0.0, t1 = 1.0, to = 4.0 }\n",
    );
    let table = cart(
        "[[effects]]\ntype = \"force\"\nat = { body = \"c\" }\ndirection = [1.0, 0.0, 0.0]\nprofile = { kind = \"table\", t = [0.0, 1.0], value = [0.0, 4.0] }\n",
    );
    assert!(ramp.invariants().is_empty());
    let (a, b) = (run(&ramp), run(&table));
    let (xa, xb) = (a.column("coordinates:c.0").unwrap(), b.column("coordinates:c.0").unwrap());
    for ((t, x), y) in a.t.iter().zip(&xa).zip(&xb) {
        assert!((x - y).abs() < 1e-9);
        if *t <= 1.0 {
            assert!((x - (1.0 + 4.0 * t.powi(3) / 6.0 / 2.0)).abs() < 1e-8, "t = {t}: {x}");
        }
    }
}

fn located(e: SceneError) -> (usize, usize, String) {
    match e {
        SceneError::Parse { line, column, message, .. } => (line, column, message),
        SceneError::Invalid { line, column, message, .. } => (line, column, message),
        other => panic!("unexpected {other}"),
    }
}

#[test]
fn bad_scene_unknown_key_has_line_and_column() {
    let text = "name = \"x\"\nduration = 1.0\n\n[[bodies]]\nname = \"b\"\njoint = { type = \"pin\", axis = [0.0, 0.0, 1.0] }\nmass = { shape = \"particle\", mass = 1.0 }\nmas = 2.0\n";
    let (line, col, msg) = located(Scene::from_toml(text, "t.toml").unwrap_err());
    assert_eq!((line, col), (8, 1), "{msg}");
    assert!(msg.starts_with("unknown key `mas`; valid:") && msg.ends_with("(did you mean `mass`?)"), "{msg}");
}

#[test]
fn bad_scene_unknown_parent_and_cycle() {
    let text = "name = \"x\"\nduration = 1.0\n[[bodies]]\nname = \"a\"\nparent = \"nowhere\"\njoint = { type = \"weld\" }\nmass = { shape = \"particle\", mass = 1.0 }\n";
    let (line, _, msg) = located(Scene::from_toml(text, "t.toml").unwrap_err());
    assert_eq!(line, 5, "{msg}");
    assert!(msg.contains("valid: ground, a"), "{msg}");
    let cyc = "name = \"x\"\nduration = 1.0\n[[bodies]]\nname = \"a\"\nparent = \"b\"\njoint = { type = \"ball\" }\nmass = { shape = \"sphere\", mass = 1.0, radius = 1.0 }\n[[bodies]]\nname = \"b\"\nparent = \"a\"\njoint = { type = \"ball\" }\nmass = { shape = \"sphere\", mass = 1.0, radius = 1.0 }\n";
    let (_, _, msg) = located(Scene::from_toml(cyc, "t.toml").unwrap_err());
    assert!(msg.contains("tree"), "{msg}");
}

#[test]
fn bad_scene_non_finite_and_wrong_shape() {
    let text = "name = \"x\"\nduration = inf\n[[bodies]]\nname = \"a\"\njoint = { type = \"free\" }\nmass = { shape = \"sphere\", mass = 1.0, radius = 1.0 }\n";
    let (line, _, msg) = located(Scene::from_toml(text, "t.toml").unwrap_err());
    assert_eq!(line, 2, "{msg}");
    let text = "name = \"x\"\nduration = 1.0\n[[bodies]]\nname = \"a\"\njoint = { type = \"hinge\" }\nmass = { shape = \"sphere\", mass = 1.0, radius = 1.0 }\n";
    let (line, _, msg) = located(Scene::from_toml(text, "t.toml").unwrap_err());
    assert_eq!(line, 5, "{msg}");
    assert!(msg.contains("pin"), "lists the valid joints: {msg}");
}

mod prop {
    use proptest::prelude::*;

    use super::*;

    /// Pieces of scene files: valid keys and values mixed with wrong ones.
    fn fragment() -> impl Strategy<Value = String> {
        prop_oneof![
            Just("name = \"s\"\n".to_string()),
            Just("duration = 1.0\n".to_string()),
            Just("duration = nan\n".to_string()),
            Just("samples = 0\n".to_string()),
            Just("[[bodies]]\nname = \"a\"\n".to_string()),
            Just("[[bodies]]\nname = \"b\"\nparent = \"a\"\n".to_string()),
            Just("joint = { type = \"free\" }\n".to_string()),
            Just("joint = { type = \"pin\", axis = [0.0, 0.0, 0.0] }\n".to_string()),
            Just("mass = { shape = \"sphere\", mass = 1.0, radius = 0.1 }\n".to_string()),
            Just("mass = { shape = \"box\", mass = -1.0, sides = [1.0, 1.0, 1.0] }\n".to_string()),
            Just("q = [1.0, 2.0]\n".to_string()),
            Just("v = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0]\n".to_string()),
            Just("[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, 0.0, -9.81]\n".to_string()),
            Just("[[effects]]\ntype = \"spring\"\na = { body = \"a\" }\nb = { body = \"ground\" }\nk = 1.0\n".to_string()),
            Just("[[effects]]\ntype = \"contact_plane\"\nbody = \"a\"\nradius = 0.1\nnormal = [0.0, 0.0, 1.0]\nrestitution = 2.0\n".to_string()),
            Just("outputs = [\"energy\", \"position:a\", \"bogus\"]\n".to_string()),
            "[a-z_=\\[\\]\" .0-9\n{},]{0,30}",
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// The loader never panics: every document is a scene or an error with a location.
        #[test]
        fn loader_never_panics(parts in proptest::collection::vec(fragment(), 0..10)) {
            let text: String = parts.concat();
            match Scene::from_toml(&text, "fuzz.toml") {
                Ok(scene) => {
                    let y = scene.initial_state();
                    let _ = scene.derivative(0.0, &y);
                }
                Err(SceneError::Parse { line, column, .. } | SceneError::Invalid { line, column, .. }) => {
                    prop_assert!(line >= 1 && column >= 1);
                }
                // several errors of one file: each located, in file order
                Err(SceneError::Many { errors }) => {
                    let at: Vec<(usize, usize)> = errors
                        .iter()
                        .map(|e| match e {
                            SceneError::Parse { line, column, .. } | SceneError::Invalid { line, column, .. } => {
                                (*line, *column)
                            }
                            _ => (0, 0),
                        })
                        .collect();
                    prop_assert!(at.len() >= 2 && at.iter().all(|&(l, c)| l >= 1 && c >= 1), "{at:?}");
                    prop_assert!(at.windows(2).all(|w| w[0] <= w[1]), "{at:?}");
                }
                Err(e) => prop_assert!(false, "unexpected {e}"),
            }
        }
    }
}
