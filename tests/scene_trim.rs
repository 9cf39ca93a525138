//! Trim (issue 32 item 3): `[trim] free = [...]` solves for the named coordinates, speeds and
//! input magnitudes that make the initial state steady (every joint acceleration zero), by
//! Newton with exact Jacobians, against closed forms: a pendulum's equilibria (θ = 0 and π),
//! the torque that holds it at θ₀ (m g l sin θ₀), a cart-pole balanced upright with zero force
//! (then its unstable pole √((M + m)g/(Ml))), and a heavy top's steady precession rate (the
//! slow root of I₁ cos θ₀ Ω² − C ω₃ Ω + m g l = 0).
//!
//! Book: §12.3 (trim), §12.6, §8.5 (equilibria), §9.10 (the top).

use vectrix::scene::{Scene, SceneError, TRIM_TOL};

const G: f64 = 9.81;

/// A particle m = 2 at l = 0.7 on a pin about z, gravity −y, released at θ₀, with a torque
/// effect (effects[1]) of constant magnitude 0 and the `[trim]` table `trim`.
fn pendulum(theta: f64, trim: &str) -> String {
    format!(
        "name = \"p\"\nduration = 1.0\n{trim}\n[[bodies]]\nname = \"b\"\n\
         joint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\nmass = {{ shape = \"particle\", mass = 2.0 }}\n\
         com = [0.0, -0.7, 0.0]\nq = [{theta:e}]\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n\
         [[effects]]\ntype = \"torque\"\nbody = \"b\"\ndirection = [0.0, 0.0, 1.0]\n\
         profile = {{ kind = \"constant\", value = 0.0 }}\n"
    )
}

fn load(text: &str) -> Scene {
    Scene::from_toml(text, "t.toml").unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn section_8_5_pendulum_trims_to_its_equilibria() {
    for (start, want) in [(0.3, 0.0), (-1.0, 0.0), (3.0, std::f64::consts::PI)] {
        let s = load(&pendulum(start, "trim = { free = [\"dq:b.0\"] }"));
        let r = s.trim_report().expect("trimmed");
        assert!(r.residual <= TRIM_TOL && r.iterations >= 1, "{r:?}");
        let theta = s.initial_state()[0];
        assert!((theta - want).abs() <= 1e-12, "from {start}: θ = {theta}, want {want}");
        assert!((r.change[0] - (want - start)).abs() <= 1e-12, "{r:?}");
    }
}

#[test]
fn section_12_3_torque_that_holds_a_pendulum_at_an_angle() {
    // m g l sin θ₀ against gravity's −m g l sin θ₀: the trimmed torque profile's value
    let theta0: f64 = 0.5;
    let s = load(&pendulum(theta0, "trim = { free = [\"effects[1]\"] }"));
    let want = 2.0 * G * 0.7 * theta0.sin();
    let r = s.trim_report().unwrap();
    assert!((r.change[0] - want).abs() <= 1e-12 * want, "{r:?}, want {want}");
    // the scene's own torque is now that value, and it stays at θ₀
    let run = s.run(&mut |_| {}).unwrap();
    let th = run.final_state[0];
    assert!((th - theta0).abs() <= 1e-9, "θ(1 s) = {th}");
    // the trimmed scene written out and read back is already trim (no Newton step)
    let again = load(&s.to_toml().unwrap());
    assert_eq!(again.trim_report().unwrap().iterations, 0);
}

#[test]
fn section_12_6_cart_pole_balanced_upright_with_zero_force() {
    let (big_m, m, l) = (2.0, 0.5, 0.8);
    let text = format!(
        "name = \"cartpole\"\nduration = 1.0\ntrim = {{ free = [\"dq:pole.0\"] }}\n\n\
         [[bodies]]\nname = \"cart\"\njoint = {{ type = \"sleeve\", axis = [1.0, 0.0, 0.0] }}\n\
         mass = {{ shape = \"box\", mass = {big_m}, sides = [0.4, 0.2, 0.2] }}\n\n\
         [[bodies]]\nname = \"pole\"\nparent = \"cart\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         mass = {{ shape = \"particle\", mass = {m} }}\ncom = [0.0, {l}, 0.0]\nq = [0.2]\n\n\
         [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n\n\
         [[effects]]\ntype = \"force\"\nat = {{ body = \"cart\" }}\ndirection = [1.0, 0.0, 0.0]\n\
         profile = {{ kind = \"constant\", value = 0.0 }}\n"
    );
    let s = load(&text);
    // the pole, leaning 0.2 rad, is brought upright: θ = 0 (the centre above the pin)
    assert!(s.initial_state()[1].abs() <= 1e-12, "{:?}", s.initial_state());
    let lm = s.linearize().unwrap();
    assert!(lm.residual.ok);
    let unstable: Vec<f64> = lm.eigenvalues.iter().filter(|l| l[0] > 1e-6).map(|l| l[0]).collect();
    let want = ((big_m + m) * G / (big_m * l)).sqrt();
    assert!(unstable.len() == 1 && (unstable[0] - want).abs() <= 1e-12 * want, "{unstable:?} vs {want}");
}

#[test]
fn section_9_10_heavy_top_steady_precession_rate() {
    // examples/scenes/heavy_top_gimbal.toml with its precession rate replaced by 1.0 rad/s and
    // `[trim] free = ["v:precession.0"]`: Newton finds the slow root Ω.
    let path = format!("{}/examples/scenes/heavy_top_gimbal.toml", env!("CARGO_MANIFEST_DIR"));
    let text =
        std::fs::read_to_string(path).unwrap().replace("v = [0.8491384345611137]", "v = [1.0]").replace(
            "\nlinearize = { steady = true }\n",
            "\nlinearize = { steady = true }\ntrim = { free = [\"v:precession.0\"] }\n",
        );
    let s = load(&text);
    let (m, l, a_c, c_c, w3, th0): (f64, f64, f64, f64, f64, f64) = (1.0, 0.5, 0.05, 0.1, 60.0, 0.5);
    let (i1, c) = (a_c + m * l * l, th0.cos());
    let omega = (c_c * w3 - ((c_c * w3).powi(2) - 4.0 * i1 * c * m * G * l).sqrt()) / (2.0 * i1 * c);
    // the state is (q: precession, nutation, spin; v: the same rates)
    let got = s.initial_state()[3];
    assert!((got - omega).abs() <= 1e-12 * omega, "Ω = {got}, want {omega}");
}

#[test]
fn trim_refusals_are_located_and_say_what_stays() {
    let located = |text: &str| match Scene::from_toml(text, "t.toml") {
        Err(SceneError::Invalid { path, message, line, .. }) => (path, message, line),
        other => panic!("expected a located refusal, got {other:?}"),
    };
    let (path, message, line) = located(&pendulum(0.3, "trim = { free = [\"dq:c.0\"] }"));
    assert_eq!((path.as_str(), line), ("trim.free[0]", 3));
    assert!(
        message.starts_with(
            "unknown `dq:c.0`; valid: a state (dq:b.0, v:b.0) or a force or torque input (effects[1])"
        ),
        "{message}"
    );
    let (path, message, _) = located(&pendulum(0.3, "trim = { free = [\"v:b.0\", \"v:b.0\"] }"));
    assert_eq!(path, "trim.free[1]");
    assert!(message.contains("named twice"), "{message}");
    // a speed cannot hold a pendulum away from its equilibrium
    let (path, message, _) = located(&pendulum(0.3, "trim = { free = [\"v:b.0\"] }"));
    assert_eq!(path, "trim.free");
    assert!(
        message.contains("cannot be made steady by v:b.0") && message.contains("v:b.0 (v̇ = "),
        "{message}"
    );
}
