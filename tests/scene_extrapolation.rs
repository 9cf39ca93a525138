//! Scenes under the methods that keep no interpolant, `method = { name = "gbs" }`
//! (Gragg–Bulirsch–Stoer extrapolation) and `{ name = "vern9" }` (Verner's 9(8) pair), through
//! the one scene pipeline: the run lands on every sample time and every corner of a load
//! profile (restarting only at the corners), and a scene with contacts is refused; the samples
//! are checked against closed forms.
//!
//! Book: §4.11 (integration), §7.4 (the pendulum); HNW §II.9 (extrapolation); Verner, Numer.
//! Algorithms 53 (2010).

use vectrix::ode::harness::{Pendulum, Reference};
use vectrix::scene::{Run, Scene, SceneError};

fn load(text: &str) -> Scene {
    Scene::from_toml(text, "gbs.toml").unwrap_or_else(|e| panic!("{e}"))
}

fn run(scene: &Scene) -> Run {
    scene.run(&mut |_| {}).unwrap_or_else(|e| panic!("{e}"))
}

/// The pendulum θ̈ = −sin θ (a unit particle on a unit pin, g = 1) from rest at θ₀ = 3 over
/// 10 time units, `samples` rows, under `method`.
fn pendulum(samples: usize, method: &str, rtol: f64) -> String {
    format!(
        "name = \"pendulum\"\nduration = 10.0\nsamples = {samples}\nmethod = {{ name = \"{method}\", rtol = {rtol:e} }}\n\
         outputs = [\"coordinates:bob\", \"speeds:bob\"]\n\n\
         [[bodies]]\nname = \"bob\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         mass = {{ shape = \"particle\", mass = 1.0 }}\ncom = [0.0, -1.0, 0.0]\nq = [3.0]\n\n\
         [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -1.0, 0.0]\n"
    )
}

// Every sample of the θ₀ = 3 pendulum (near the top: a hard, strongly nonlinear swing) lies on
// the closed form θ = 2 asin(k sn(K − t, k²)) at each sample time, within 1500·rtol (the spread
// of global over local error GBS shows on this problem in
// tests/integrators.rs `gbs_extrapolation_error_follows_the_tolerance_on_closed_forms` and
// `vern9_error_follows_the_tolerance_on_closed_forms`); the samples are step ends (no
// restarts), and the run's final state is the same with 1 sample.
#[test]
fn scene_without_an_interpolant_lands_on_every_sample_on_the_pendulums_closed_form() {
    for method in ["gbs", "vern9"] {
        assert_eq!(lands_on_every_sample(method), 41, "{method}: samples checked");
    }
}

/// The checks above for one method; returns how many samples it checked.
fn lands_on_every_sample(method: &str) -> usize {
    let exact = Pendulum { theta0: 3.0 };
    let rtol = 1e-12;
    let r = run(&load(&pendulum(40, method, rtol)));
    assert!(r.is_complete(), "{:?}", r.stop);
    assert_eq!(r.method.name, method);
    assert_eq!(r.work.restarts, 0, "{method}: samples are landings, not restarts: {:?}", r.work);
    let theta = r.column("coordinates:bob.0").unwrap_or_else(|| panic!("columns: {:?}", r.columns));
    let omega = r.column("speeds:bob.0").unwrap_or_else(|| panic!("columns: {:?}", r.columns));
    assert_eq!(r.t.len(), 41);
    for (k, &t) in r.t.iter().enumerate() {
        assert_eq!(t, 10.0 * (k as f64 / 40.0), "sample {k} time");
        let y = exact.exact(t);
        let e = (theta[k] - y[0]).abs().max((omega[k] - y[1]).abs());
        assert!(e <= 1500.0 * rtol, "{method}: t = {t}: error {e:e}");
    }
    // one sample: fewer, longer steps, the same end to the tolerance
    let one = run(&load(&pendulum(1, method, rtol)));
    assert!(one.work.accepted < r.work.accepted, "{:?} vs {:?}", one.work, r.work);
    let y = exact.exact(10.0);
    let e = (one.final_state[0] - y[0]).abs().max((one.final_state[1] - y[1]).abs());
    assert!(e <= 1500.0 * rtol, "{method}: one sample: error {e:e}");
    r.t.len()
}

// A free body pushed by a force that steps from 0 to 2 N at t = 0.35 s: x = (F/2m)(t − 0.35)²
// after the step. The step that ends at the corner sees the force before it and the run
// restarts there with the force after it, so every method integrates two polynomials: GBS
// exactly, Vern9, DOP853 and DOPRI5 (order 9, 8 and 5, exact on quadratics) too. Every sample is then
// the closed form to a few roundings, and the run restarts once. (Before the piece was known
// to the right-hand side, the last step before the corner saw the 2 N at its end: x was
// 5e-9 m off at t = 1 under GBS, 2e-10 under DOP853.)
#[test]
fn load_step_restarts_once_and_every_method_samples_the_exact_parabola() {
    for method in ["gbs", "vern9", "dop853", "dopri5"] {
        let text = format!(
            "name = \"push\"\nduration = 1.0\nsamples = 10\nmethod = {{ name = \"{method}\", rtol = 1e-10 }}\n\
             outputs = [\"coordinates:box\"]\n\n\
             [[bodies]]\nname = \"box\"\njoint = {{ type = \"free\" }}\n\
             mass = {{ shape = \"value\", mass = 4.0, principal = [1.0, 1.0, 1.0] }}\n\n\
             [[effects]]\ntype = \"force\"\nat = {{ body = \"box\" }}\ndirection = [1.0, 0.0, 0.0]\n\
             profile = {{ kind = \"step\", at = 0.35, after = 2.0 }}\n"
        );
        let r = run(&load(&text));
        assert!(r.is_complete(), "{method}: {:?}", r.stop);
        assert_eq!(r.work.restarts, 1, "{method}: {:?}", r.work);
        let x = r.column("coordinates:box.0").unwrap_or_else(|| panic!("columns: {:?}", r.columns));
        for (k, &t) in r.t.iter().enumerate() {
            let exact = if t < 0.35 { 0.0 } else { 0.25 * (t - 0.35) * (t - 0.35) };
            // a few roundings of x ≤ 0.11 (4 ulps of 0.11 = 5.6e-17 each, over the steps)
            assert!((x[k] - exact).abs() <= 1e-15, "{method}: t = {t}: x = {:e}, exact {exact:e}", x[k]);
        }
    }
}

// Contacts are located on the interpolant, which extrapolation and Vern9 do not keep: the
// scene is refused where it names the method, with the methods that would do.
#[test]
fn scene_without_an_interpolant_with_a_contact_is_refused_at_its_method() {
    let text = "name = \"ball\"\nduration = 1.0\nmethod = { name = \"gbs\", rtol = 1e-10 }\n\n\
                [[bodies]]\nname = \"ball\"\njoint = { type = \"free\" }\n\
                mass = { shape = \"sphere\", mass = 1.0, radius = 0.1 }\nq = [0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0]\n\n\
                [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, 0.0, -9.81]\n\n\
                [[effects]]\ntype = \"contact_plane\"\nbody = \"ball\"\nradius = 0.1\npoint = [0.0, 0.0, 0.0]\n\
                normal = [0.0, 0.0, 1.0]\nrestitution = 0.5\n";
    for method in ["gbs", "vern9"] {
        let text = text.replace("\"gbs\"", &format!("\"{method}\""));
        let e =
            Scene::from_toml(&text, "ball.toml").expect_err("a method without an interpolant with a contact");
        let msg = e.to_string();
        assert!(matches!(e, SceneError::Invalid { .. }), "{e:?}");
        for part in ["method.name", method, "interpolant", "dop853"] {
            assert!(msg.contains(part), "`{part}` missing from: {msg}");
        }
    }
    // the same scene under dop853 is valid
    Scene::from_toml(&text.replace("\"gbs\"", "\"dop853\""), "ball.toml").unwrap_or_else(|e| panic!("{e}"));
}
