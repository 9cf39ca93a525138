//! `Scene::linearize` and `vectrix linearize` (issue 18, items 4–5) against closed forms: the
//! double pendulum's ω² = (g/l)(2 ∓ √2), the inverted pendulum on a cart's unstable pole
//! √((M + m)g/(Ml)), the physical pendulum's ω² = 3g/(2L), the heavy symmetric top's nutation
//! about steady precession ω² = a² − 4aΩ cos θ₀ + Ω²(1 + 3cos²θ₀) (a = I₃ω₃/I₁, derived from the
//! Lagrangian in Euler angles), the torque-free body about each principal axis
//! λ² = ω₀²(I₂ − I₃)(I₃ − I₁)/(I₁I₂), and flight scenes against the flight crate's trim
//! linearization. The derivatives are exact (dual numbers), so every closed form is met to
//! 1e-12 relative; `Scene::jacobian` is checked against the closed-form Jacobian of a
//! pendulum and a cart with a force input.
//!
//! Book: §12.6 (linearization), §7.8 (torque-free motion), §9.10 (Lagrange's equations).

use std::path::PathBuf;
use std::process::Command;

use vectrix::scene::{LinearModel, Scene, SceneError};

const G: f64 = 9.81;

fn lin(text: &str) -> LinearModel {
    Scene::from_toml(text, "lin.toml")
        .unwrap_or_else(|e| panic!("{e}"))
        .linearize()
        .unwrap_or_else(|e| panic!("{e}"))
}

/// Imaginary parts of the eigenvalues with im > 0, ascending.
fn frequencies(m: &LinearModel) -> Vec<f64> {
    let mut w: Vec<f64> = m.eigenvalues.iter().filter(|l| l[1] > 1e-6).map(|l| l[1]).collect();
    w.sort_by(f64::total_cmp);
    w
}

fn assert_rel(got: f64, want: f64, tol: f64, what: &str) {
    assert!((got - want).abs() <= tol * want.abs(), "{what}: got {got}, want {want} (rel. tol {tol:e})");
}

#[test]
fn section_12_6_double_pendulum_frequencies() {
    // two 1 kg particles on massless 1 m rods, hanging: ω² = (g/l)(2 ∓ √2)
    let text = "name = \"dp\"\nduration = 1.0\n\n\
        [[bodies]]\nname = \"upper\"\njoint = { type = \"pin\", axis = [0.0, 0.0, 1.0] }\n\
        mass = { shape = \"particle\", mass = 1.0 }\ncom = [0.0, -1.0, 0.0]\n\n\
        [[bodies]]\nname = \"lower\"\nparent = \"upper\"\njoint = { type = \"pin\", axis = [0.0, 0.0, 1.0] }\n\
        offset = [0.0, -1.0, 0.0]\nmass = { shape = \"particle\", mass = 1.0 }\ncom = [0.0, -1.0, 0.0]\n\n\
        [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n";
    let m = lin(text);
    assert!(m.residual.ok, "{:?}", m.residual);
    let w = frequencies(&m);
    let r2 = std::f64::consts::SQRT_2;
    assert_eq!(w.len(), 2);
    // exact derivatives (dual numbers): the eigenvalues to a few ulps; 1e-12 relative asserted
    assert_rel(w[0], (G * (2.0 - r2)).sqrt(), 1e-12, "slow mode");
    assert_rel(w[1], (G * (2.0 + r2)).sqrt(), 1e-12, "fast mode");
    // conservative: both modes marginal
    assert!(m.modes.iter().all(|md| md.damping_ratio == Some(0.0)), "{:?}", m.modes);
    assert_eq!(m.state, ["dq:upper.0", "dq:lower.0", "v:upper.0", "v:lower.0"]);
}

#[test]
fn section_12_6_inverted_pendulum_on_a_cart_unstable_pole() {
    let (big_m, m, l) = (2.0, 0.5, 0.8);
    let text = format!(
        "name = \"cartpole\"\nduration = 1.0\noutputs = [\"coordinates:cart\", \"coordinates:pole\"]\n\n\
         [[bodies]]\nname = \"cart\"\njoint = {{ type = \"sleeve\", axis = [1.0, 0.0, 0.0] }}\n\
         mass = {{ shape = \"box\", mass = {big_m}, sides = [0.4, 0.2, 0.2] }}\n\n\
         [[bodies]]\nname = \"pole\"\nparent = \"cart\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         mass = {{ shape = \"particle\", mass = {m} }}\ncom = [0.0, {l}, 0.0]\n\n\
         [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n\n\
         [[effects]]\ntype = \"force\"\nat = {{ body = \"cart\" }}\ndirection = [1.0, 0.0, 0.0]\n\
         profile = {{ kind = \"constant\", value = 0.0 }}\n"
    );
    let lm = lin(&text);
    let unstable: Vec<f64> = lm.eigenvalues.iter().filter(|l| l[0] > 1e-6).map(|l| l[0]).collect();
    assert_eq!(unstable.len(), 1, "{:?}", lm.eigenvalues);
    assert_rel(unstable[0], ((big_m + m) * G / (big_m * l)).sqrt(), 1e-12, "unstable pole");
    // the force on the cart is the input: B = [0; 0; 1/M; 1/(M l)] (ẍ = F/M; θ about +z, the
    // pole above the cart: pushed along +x the cart leaves the pole behind, θ̈ = F/(M l))
    assert_eq!(lm.inputs, ["effects[1]"]);
    let b: Vec<f64> = lm.b.column(0).iter().copied().collect();
    for (got, want) in b.iter().zip([0.0, 0.0, 1.0 / big_m, 1.0 / (big_m * l)]) {
        assert!((got - want).abs() <= 1e-9, "B = {b:?}");
    }
    // outputs: the two coordinates, C = [I 0], D = 0
    assert!((lm.c[(0, 0)] - 1.0).abs() <= 1e-12 && (lm.c[(1, 1)] - 1.0).abs() <= 1e-12);
    assert!(lm.d.iter().all(|x| x.abs() <= 1e-12));
}

#[test]
fn section_12_6_physical_pendulum() {
    // a uniform rod of length L pinned at its end: ω² = m g (L/2)/(m L²/3) = 3g/(2L)
    let len = 1.3;
    let text = format!(
        "name = \"rod\"\nduration = 1.0\n\n[[bodies]]\nname = \"rod\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         mass = {{ shape = \"rod\", mass = 2.0, length = {len} }}\ncom = [{}, 0.0, 0.0]\n\n\
         [[effects]]\ntype = \"uniform_gravity\"\ng = [9.81, 0.0, 0.0]\n",
        len / 2.0
    );
    let w = frequencies(&lin(&text));
    assert_rel(w[0], (1.5 * G / len).sqrt(), 1e-12, "physical pendulum");
}

/// A body in a gimbal of two massless rings (ψ about ground y, θ about the ring's x) spinning
/// about its own link y (the last pin): Euler angles in which steady motions are steady.
fn gimbal(
    principal: [f64; 3],
    com_y: f64,
    mass: f64,
    gravity: bool,
    psi_dot: f64,
    theta: f64,
    phi_dot: f64,
) -> String {
    let mut t = format!(
        "name = \"gimbal\"\nduration = 1.0\nlinearize = {{ steady = true }}\n\n\
         [[bodies]]\nname = \"ring1\"\njoint = {{ type = \"pin\", axis = [0.0, 1.0, 0.0] }}\nmass = {{ shape = \"massless\" }}\n\
         v = [{psi_dot:e}]\n\n\
         [[bodies]]\nname = \"ring2\"\nparent = \"ring1\"\njoint = {{ type = \"pin\", axis = [1.0, 0.0, 0.0] }}\n\
         mass = {{ shape = \"massless\" }}\nq = [{theta:e}]\n\n\
         [[bodies]]\nname = \"body\"\nparent = \"ring2\"\njoint = {{ type = \"pin\", axis = [0.0, 1.0, 0.0] }}\n\
         mass = {{ shape = \"value\", mass = {mass}, principal = [{}, {}, {}] }}\ncom = [0.0, {com_y}, 0.0]\nv = [{phi_dot:e}]\n",
        principal[0], principal[1], principal[2]
    );
    if gravity {
        t.push_str("\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n");
    }
    t
}

#[test]
fn section_12_6_spinning_top_nutation_about_steady_precession() {
    // I₁ = A + m l² about the pivot, I₃ = C; steady precession Ω at θ₀ solves
    // Ω² cos θ₀ − aΩ + m g l/I₁ = 0 (slow root); small nutation: ω² = a² − 4aΩc + Ω²(1 + 3c²)
    let (m, l, a_c, c_c, w3, th0) = (1.0, 0.5, 0.01, 0.02, 200.0, 0.5_f64);
    let i1 = a_c + m * l * l;
    let a = c_c * w3 / i1;
    let (c, k) = (th0.cos(), m * G * l / i1);
    let omega = (a - (a * a - 4.0 * c * k).sqrt()) / (2.0 * c);
    let phi_dot = w3 - omega * c;
    let lm = lin(&gimbal([a_c, c_c, a_c], l, m, true, omega, th0, phi_dot));
    assert!(lm.steady && lm.residual.ok, "steady precession: {:?}", lm.residual);
    let w = frequencies(&lm);
    let want = (a * a - 4.0 * a * omega * c + omega * omega * (1.0 + 3.0 * c * c)).sqrt();
    assert_eq!(w.len(), 1, "one nutation pair; the others are cyclic: {:?}", lm.eigenvalues);
    assert_rel(w[0], want, 1e-12, "nutation frequency");
}

#[test]
fn section_7_8_torque_free_spin_about_each_principal_axis() {
    // A free body on a ball joint spinning at ω₀ about its link y (moment I₃ = principal[1],
    // transverse I₁ = principal[0], I₂ = principal[2]). Torque-free, the accelerations do not
    // depend on the attitude (cyclic), so the steady spin linearizes in ω_link: Euler's
    // equations give λ² = ω₀²(I₂ − I₃)(I₃ − I₁)/(I₁I₂).
    let w0: f64 = 3.0;
    for (principal, name) in
        [([2.0, 3.0, 1.0], "largest"), ([2.0, 1.0, 3.0], "smallest"), ([1.0, 2.0, 3.0], "intermediate")]
    {
        let text = format!(
            "name = \"spin\"\nduration = 1.0\nlinearize = {{ steady = true }}\n\n[[bodies]]\nname = \"body\"\n\
             joint = {{ type = \"ball\" }}\nmass = {{ shape = \"value\", mass = 1.0, principal = [{}, {}, {}] }}\n\
             v = [0.0, {w0}, 0.0]\n",
            principal[0], principal[1], principal[2]
        );
        let lm = lin(&text);
        assert!(lm.residual.ok, "{name}: {:?}", lm.residual);
        let [i1, i3, i2] = principal;
        let lam2 = w0 * w0 * (i2 - i3) * (i3 - i1) / (i1 * i2);
        if lam2 < 0.0 {
            let w = frequencies(&lm);
            assert_eq!(w.len(), 1, "{name}: {:?}", lm.eigenvalues);
            assert_rel(w[0], (-lam2).sqrt(), 1e-12, name);
        } else {
            let grow: Vec<f64> = lm.eigenvalues.iter().filter(|l| l[0] > 1e-6).map(|l| l[0]).collect();
            assert_eq!(grow.len(), 1, "{name}: the intermediate axis is unstable: {:?}", lm.eigenvalues);
            assert_rel(grow[0], lam2.sqrt(), 1e-12, "intermediate-axis growth rate");
        }
    }
}

#[test]
fn section_12_6_steady_motion_needs_cyclic_moving_coordinates() {
    // an asymmetric body spinning in a gimbal: the spin angle moves, but the accelerations
    // depend on it (which transverse axis points where), so A at t = 0 is not the linearization
    // of a steady motion: refused, naming the coordinate
    match Scene::from_toml(
        &gimbal([1.0, 2.0, 3.0], 0.0, 1.0, false, 0.0, std::f64::consts::FRAC_PI_2, 3.0),
        "g.toml",
    )
    .and_then(|s| s.linearize())
    {
        Err(SceneError::Invalid { message, path, line, .. }) => {
            // located at the `linearize` table of the file
            assert_eq!((path.as_str(), line), ("linearize.steady", 3));
            assert!(message.contains("dq:body.0") && message.contains("cyclic"), "{message}")
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
}

#[test]
fn section_12_6_linearize_refuses_what_it_cannot_do() {
    // every refusal is located in the file (issue 33: they read "simulation failed at t = 0")
    let fails = |text: &str, needle: &str| match Scene::from_toml(text, "t.toml").and_then(|s| s.linearize())
    {
        Err(SceneError::Invalid { message, file, line, .. }) => {
            assert!(file == "t.toml" && line >= 1 && message.contains(needle), "{message}")
        }
        other => panic!("expected a refusal containing {needle:?}, got {other:?}"),
    };
    fails(
        "name = \"w\"\nduration = 1.0\n[[bodies]]\nname = \"b\"\njoint = { type = \"weld\" }\nmass = { shape = \"particle\", mass = 1.0 }\n",
        "no degrees of freedom",
    );
    let four_bar =
        std::fs::read_to_string(format!("{}/examples/scenes/four_bar.toml", env!("CARGO_MANIFEST_DIR")))
            .unwrap();
    fails(&four_bar, "loops");
    // a pendulum swinging through the bottom is not steady: its angle is not cyclic
    fails(
        "name = \"s\"\nduration = 1.0\nlinearize = { steady = true }\n[[bodies]]\nname = \"b\"\n\
         joint = { type = \"pin\", axis = [0.0, 0.0, 1.0] }\nmass = { shape = \"particle\", mass = 1.0 }\n\
         com = [0.0, -1.0, 0.0]\nv = [1.0]\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n",
        "cyclic",
    );
}

/// The shipped heavy symmetric top.
fn heavy_top(name: &str) -> String {
    std::fs::read_to_string(format!("{}/examples/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

#[test]
fn section_12_6_shipped_heavy_top_gimbal_linearizes_about_steady_precession() {
    // examples/scenes/heavy_top_gimbal.toml: m = 1, l = 0.5, A_c = 0.05, C = 0.1, θ₀ = 0.5,
    // ω₃ = 60; I₁ = A_c + m l², a = C ω₃/I₁, Ω the slow root of I₁ cos θ₀ Ω² − C ω₃ Ω + m g l = 0;
    // nutation ω² = a² − 4aΩ cos θ₀ + Ω²(1 + 3cos²θ₀).
    let (m, l, a_c, c_c, w3, th0): (f64, f64, f64, f64, f64, f64) = (1.0, 0.5, 0.05, 0.1, 60.0, 0.5);
    let i1 = a_c + m * l * l;
    let (a, c) = (c_c * w3 / i1, th0.cos());
    let omega = (c_c * w3 - ((c_c * w3).powi(2) - 4.0 * i1 * c * m * G * l).sqrt()) / (2.0 * i1 * c);
    let lm = lin(&heavy_top("heavy_top_gimbal"));
    assert!(lm.steady && lm.residual.ok, "steady precession: {:?}", lm.residual);
    let want = (a * a - 4.0 * a * omega * c + omega * omega * (1.0 + 3.0 * c * c)).sqrt();
    // the nutation pair; the precession and spin angles are cyclic (a double zero)
    let w = frequencies(&lm);
    let nutation = w.iter().copied().find(|w| *w > 1.0).expect("a nutation pair");
    assert_rel(nutation, want, 1e-12, "nutation frequency");
}

#[test]
fn section_12_6_shipped_heavy_top_on_a_ball_joint_is_refused_with_the_gimbal_form() {
    // heavy_top.toml's ball joint resolves ω in the spinning top: steady precession is periodic
    // there, so `steady = true` is refused, located, pointing at the gimbal form (issue 33)
    let text = heavy_top("heavy_top").replacen("checks = ", "linearize = { steady = true }\nchecks = ", 1);
    match Scene::from_toml(&text, "top.toml").and_then(|s| s.linearize()) {
        Err(SceneError::Invalid { message, path, .. }) => {
            assert_eq!(path, "linearize.steady");
            assert!(message.contains("heavy_top_gimbal.toml") && message.contains("periodic"), "{message}");
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("vectrix-lin-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn section_12_6_vectrix_linearize_on_an_aircraft_scene_writes_the_trim_linearization() {
    let path = format!("{}/examples/scenes/business_jet_doublet.toml", env!("CARGO_MANIFEST_DIR"));
    let dir = temp_dir("flight");
    let out = Command::new(env!("CARGO_BIN_EXE_vectrix"))
        .args(["linearize", &path, "--out"])
        .arg(&dir)
        .output()
        .expect("the binary runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let scene = Scene::from_toml(&std::fs::read_to_string(&path).unwrap(), &path).unwrap();
    let name = &scene.spec().name;
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join(name).join("linearization.json")).unwrap())
            .unwrap();
    // about the trimmed flight (the modes themselves are checked against the flight crate's
    // linearization in tests/scene_aircraft.rs and against the book in tests/ch14_flight_modes.rs)
    let a = scene.linearize().unwrap().a;
    let rows = json["A"].as_array().expect("A");
    assert_eq!(rows.len(), 12);
    for (i, row) in rows.iter().enumerate() {
        for (j, x) in row.as_array().unwrap().iter().enumerate() {
            // the JSON is read exactly (float_roundtrip): the same numbers
            assert_eq!(x.as_f64().unwrap(), a[(i, j)], "A[{i}][{j}]");
        }
    }
    for key in ["state", "A", "B", "C", "D", "eigenvalues", "modes"] {
        assert!(json.get(key).is_some(), "linearization.json lacks {key}");
    }
    assert!(dir.join(name).join("poles.svg").is_file() && dir.join(name).join("bode.svg").is_file());
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("ωn ="), "{stdout}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn section_12_6_vectrix_linearize_adds_to_a_run_folder_and_refuses_foreign_ones() {
    let path = format!("{}/examples/scenes/simple_pendulum.toml", env!("CARGO_MANIFEST_DIR"));
    let name = Scene::from_toml(&std::fs::read_to_string(&path).unwrap(), &path).unwrap().spec().name.clone();
    let dir = temp_dir("into-run");
    let vectrix = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_vectrix")).args(args).arg("--out").arg(&dir).output().expect("runs")
    };
    assert!(vectrix(&["run", &path, "--quiet"]).status.success());
    assert!(vectrix(&["linearize", &path]).status.success());
    // the run's files stay; the linear model joins them
    for f in ["trajectory.csv", "summary.json", "linearization.json", "poles.svg"] {
        assert!(dir.join(&name).join(f).is_file(), "{f} missing");
    }
    // a folder vectrix did not write is refused and left alone
    let foreign = temp_dir("foreign");
    std::fs::create_dir_all(foreign.join(&name)).unwrap();
    std::fs::write(foreign.join(&name).join("mine.txt"), "keep").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_vectrix"))
        .args(["linearize", &path, "--out"])
        .arg(&foreign)
        .output()
        .unwrap();
    assert!(!out.status.success());
    let left: Vec<_> =
        std::fs::read_dir(foreign.join(&name)).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(left, ["mine.txt"]);
    assert_eq!(std::fs::read_to_string(foreign.join(&name).join("mine.txt")).unwrap(), "keep");
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&foreign);
}

#[test]
fn section_12_6_scene_jacobian_is_exact() {
    // A pendulum (particle m at length l from a pin about z, gravity −y) with a torque input u:
    // y = (θ, ω), f = (ω, −(g/l) sin θ + u/(m l²)); ∂f/∂y = [[0, 1], [−(g/l) cos θ, 0]],
    // ∂f/∂u = [0, 1/(m l²)], exact at any state.
    let (m, l) = (2.0, 0.7);
    let text = format!(
        "name = \"p\"\nduration = 1.0\n[[bodies]]\nname = \"b\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         mass = {{ shape = \"particle\", mass = {m} }}\ncom = [0.0, -{l}, 0.0]\n[[effects]]\ntype = \"uniform_gravity\"\n\
         g = [0.0, -9.81, 0.0]\n[[effects]]\ntype = \"torque\"\nbody = \"b\"\ndirection = [0.0, 0.0, 1.0]\n\
         profile = {{ kind = \"constant\", value = 0.3 }}\n"
    );
    let scene = Scene::from_toml(&text, "p.toml").unwrap();
    for theta in [0.0, 0.4, 3.0, -2.5] {
        let (fy, fu) = scene.jacobian(0.0, &[theta, 1.3]).unwrap();
        let want = [0.0, 1.0, -G / l * f64::cos(theta), 0.0];
        for (k, w) in want.iter().enumerate() {
            let got = fy[(k / 2, k % 2)];
            assert!(
                (got - w).abs() <= 4.0 * f64::EPSILON * (G / l),
                "∂f/∂y[{k}] = {got}, want {w} at θ = {theta}"
            );
        }
        assert_eq!(fu.shape(), (2, 1));
        assert!(fu[(0, 0)] == 0.0 && (fu[(1, 0)] * m * l * l - 1.0).abs() <= 4.0 * f64::EPSILON, "{fu}");
    }
    // refused: a state of the wrong length, a non-finite state
    assert!(scene.jacobian(0.0, &[0.1]).is_err() && scene.jacobian(0.0, &[f64::NAN, 0.0]).is_err());
}
