//! Loops that come from model files (issue 35): URDF `<mimic>` and MJCF `<equality><joint>`
//! as a coupler (q_follower = m q_leader + offset), MJCF `<equality><weld>` as a weld, each
//! checked against the closed form of the one rigid system it makes.
//!
//! * A pendulum geared to a flywheel whose centre of mass is on its axis is one pendulum of
//!   inertia I_eff = I_arm + m² I_wheel: ½ I_eff θ̇² + m g ℓ sin θ is constant (θ from +x,
//!   gravity −y), so θ̇² = 2 m g ℓ (sin θ₀ − sin θ)/I_eff along the whole swing, and the gear's
//!   torque on the wheel's joint is I_wheel · m · θ̈ with θ̈ = −m g ℓ cos θ / I_eff (§6.10).
//! * A ball welded to a bar pendulum's tip is the merged body: inertia I_bar + I_ball +
//!   m_ball ℓ² about the pivot (parallel axes, §6.2); the ball's centre is the tip, its angular
//!   velocity θ̇ ẑ, and the weld's force on the bar is −m_ball (a_ball − g), its couple
//!   −I_ball θ̈ ẑ (Newton–Euler for the ball, §7.3).
//!
//! Book: §9.11 (holonomic constraints), §8 (energy), §6.2 (parallel axes), §6.10 (reactions).

mod support;

use support::{nan_max, nan_min};
use vectrix::scene::{Run, Scene};

const G: f64 = 9.81;

fn run_model_scene(toml: &str) -> Run {
    let scene = Scene::from_toml(toml, "examples/models/scene.toml").unwrap_or_else(|e| panic!("{e}"));
    scene.run(&mut |_| {}).unwrap_or_else(|e| panic!("{e}"))
}

fn col(run: &Run, name: &str) -> Vec<f64> {
    run.column(name).unwrap_or_else(|| panic!("no column {name} in {:?}", run.columns))
}

/// The largest |f(i)| over the samples, NaN-propagating.
fn worst(n: usize, f: impl Fn(usize) -> f64) -> f64 {
    (0..n).fold(0.0, |m, i| nan_max(m, f(i).abs()))
}

/// The geared pendulum of examples/models/geared_pendulum.*: arm J = 1/3 about the pivot,
/// m g ℓ = 1 · 9.81 · 0.5; wheel J = 0.25 on its axis; ratio −2, offset 0.3; θ₀ = 1.
fn check_geared(run: &Run, arm: &str, wheel: &str, gear: &str) {
    let (i_arm, i_wheel, ratio, offset, mgl, th0): (f64, f64, f64, f64, f64, f64) =
        (1.0 / 3.0, 0.25, -2.0, 0.3, G * 0.5, 1.0);
    let i_eff = i_arm + ratio * ratio * i_wheel;
    let (th, w) = (col(run, &format!("coordinates:{arm}.0")), col(run, &format!("speeds:{arm}.0")));
    let phi = col(run, &format!("coordinates:{wheel}.0"));
    let tau = col(run, &format!("reaction:{gear}"));
    // the swing reaches the far side (θ = −π − 1), so the check covers the whole arc
    assert!(th.iter().fold(0.0, |m, x| nan_min(m, *x)) < -3.5, "the pendulum did not swing through");
    let n = th.len();
    // the gear holds: projection keeps φ within its tolerance (1e-10 relative); measured 5e-14
    let e_gear = worst(n, |i| phi[i] - (ratio * th[i] + offset));
    assert!(e_gear <= 1e-10, "gear violated by {e_gear:e}");
    // θ̇² against the closed form with I_eff; scale 2 m g ℓ · 2 / I_eff ≈ 14.7 (rad/s)²
    // accuracy = 1e-10 bounds the integration error; measured 4e-12 relative
    let scale = 4.0 * mgl / i_eff;
    let e_w = worst(n, |i| w[i] * w[i] - 2.0 * mgl * (th0.sin() - th[i].sin()) / i_eff) / scale;
    assert!(e_w <= 1e-9, "θ̇² off the one-pendulum closed form by {e_w:e} relative");
    // the gear's torque on the wheel: I_wheel m θ̈ (scale I_wheel |m| m g ℓ / I_eff ≈ 1.8 N m),
    // a function of the sampled θ: rounding only (measured 7e-16)
    let t_scale = i_wheel * ratio.abs() * mgl / i_eff;
    let e_t = worst(n, |i| tau[i] - i_wheel * ratio * (-mgl * th[i].cos() / i_eff)) / t_scale;
    assert!(e_t <= 1e-12, "gear torque off the closed form by {e_t:e} relative");
}

#[test]
fn urdf_mimic_geared_pendulum_swings_with_the_effective_inertia() {
    let text = std::fs::read_to_string("examples/models/geared_pendulum.toml").unwrap();
    let run = run_model_scene(&text);
    check_geared(&run, "arm", "wheel", "wheel_joint_mimic");
}

#[test]
fn mjcf_joint_equality_geared_pendulum_swings_with_the_effective_inertia() {
    let text = std::fs::read_to_string("examples/models/geared_pendulum_mjcf.toml").unwrap();
    let run = run_model_scene(&text);
    check_geared(&run, "arm", "wheel", "gear");
}

#[test]
fn mjcf_weld_ball_on_a_bar_moves_as_the_merged_body() {
    let text = std::fs::read_to_string("examples/models/welded_pendulum.toml").unwrap();
    let run = run_model_scene(&text);
    let (m_ball, i_ball, l, th0) = (2.0, 0.4 * 2.0 * 0.04, 1.0, 0.0);
    let i_eff = 1.0 / 3.0 + i_ball + m_ball * l * l;
    let mgl = G * (1.0 * 0.5 + m_ball * l);
    let (th, w) = (col(&run, "coordinates:bar.0"), col(&run, "speeds:bar.0"));
    let n = th.len();
    assert!(th.iter().fold(0.0, |m, x| nan_min(m, *x)) < -3.0, "the pendulum did not swing through");
    // integration error at accuracy = 1e-10 (measured 1e-12); the ball's motion and the
    // weld's reactions follow from the sampled θ, θ̇ by rounding (measured ≤ 1e-12)
    let scale = 4.0 * mgl / i_eff;
    let e_w = worst(n, |i| w[i] * w[i] - 2.0 * mgl * (f64::sin(th0) - th[i].sin()) / i_eff) / scale;
    assert!(e_w <= 1e-9, "θ̇² off the merged-body closed form by {e_w:e} relative");
    let c = |k: &str| col(&run, k);
    let (px, py, pz) = (c("position:ball.x"), c("position:ball.y"), c("position:ball.z"));
    let (wx, wy, wz) = (c("omega:ball.x"), c("omega:ball.y"), c("omega:ball.z"));
    let e_p = worst(n, |i| nan_max((px[i] - th[i].cos()).abs(), (py[i] - th[i].sin()).abs()) + pz[i].abs());
    assert!(e_p <= 1e-9, "the ball left the tip by {e_p:e} m");
    let e_o = worst(n, |i| nan_max(wx[i].abs(), wy[i].abs()) + (wz[i] - w[i]).abs());
    assert!(e_o <= 1e-9, "the ball turned unlike the bar by {e_o:e} rad/s");
    // the weld's force and couple on the bar, from Newton–Euler for the ball
    let (fx, fy, fz) = (c("reaction:tip.x"), c("reaction:tip.y"), c("reaction:tip.z"));
    let (mx, my, mz) = (c("reaction:tip.mx"), c("reaction:tip.my"), c("reaction:tip.mz"));
    let f_scale = m_ball * (G + scale);
    let e_f = worst(n, |i| {
        let (s, co) = th[i].sin_cos();
        let acc = -mgl * co / i_eff;
        let a = [-acc * s - w[i] * w[i] * co, acc * co - w[i] * w[i] * s];
        let want = [-m_ball * a[0], -m_ball * (a[1] + G)];
        nan_max((fx[i] - want[0]).abs(), (fy[i] - want[1]).abs()) + fz[i].abs()
    }) / f_scale;
    assert!(e_f <= 1e-9, "weld force off Newton's law for the ball by {e_f:e} relative");
    let e_m = worst(n, |i| {
        nan_max(mx[i].abs(), my[i].abs()) + (mz[i] + i_ball * (-mgl * th[i].cos() / i_eff)).abs()
    }) / (i_ball * mgl / i_eff);
    assert!(e_m <= 1e-9, "weld couple off Euler's law for the ball by {e_m:e} relative");
}

/// A coupler and a weld written in the scene format itself; bad couplers are refused with
/// the key and what is valid.
#[test]
fn scene_coupler_and_weld_refuse_bad_input() {
    let base = r#"name = "t"
duration = 0.1
[[bodies]]
name = "a"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
mass = { shape = "disk", mass = 1.0, radius = 0.5 }
[[bodies]]
name = "b"
joint = { type = "ball" }
offset = [2.0, 0.0, 0.0]
mass = { shape = "sphere", mass = 1.0, radius = 0.5 }
"#;
    let bad = [
        ("type = \"coupler\"\nname = \"g\"\nbody = \"a\"\nleader = \"a\"", "loops[0].leader", "another body"),
        ("type = \"coupler\"\nname = \"g\"\nbody = \"b\"", "loops[0].body", "pin or sleeve"),
        ("type = \"coupler\"\nname = \"g\"\nbody = \"a\"\nratio = nan", "loops[0].ratio", "finite"),
        ("type = \"coupler\"\nname = \"g\"\nbody = \"c\"", "loops[0].body", "c"),
    ];
    for (l, key, valid) in bad {
        let text = format!("{base}[[loops]]\n{l}\n");
        match Scene::from_toml(&text, "t.toml") {
            Err(e) => {
                let m = e.to_string();
                assert!(m.contains(key) && m.contains(valid), "{l}: message {m:?} lacks {key} or {valid}");
            }
            Ok(_) => panic!("{l}: accepted"),
        }
    }
    let stops = [
        ("body = \"a\"\nlower = 1.0\nupper = -1.0", "effects[0]", "lower < upper"),
        ("body = \"a\"", "effects[0]", "lower < upper"),
        ("body = \"b\"\nlower = 0.0", "effects[0].body", "pin or sleeve"),
        ("body = \"a\"\nlower = -1.0\nrestitution = 1.5", "effects[0].restitution", "0 ≤ e ≤ 1"),
    ];
    for (l, key, valid) in stops {
        let text = format!("{base}[[effects]]\ntype = \"joint_stop\"\n{l}\n");
        match Scene::from_toml(&text, "t.toml") {
            Err(e) => {
                let m = e.to_string();
                assert!(m.contains(key) && m.contains(valid), "{l}: message {m:?} lacks {key} or {valid}");
            }
            Ok(_) => panic!("{l}: accepted"),
        }
    }
    // a lock (no leader) at the initial angle loads, and holds the disk still
    let ok = format!("{base}[[loops]]\ntype = \"coupler\"\nname = \"g\"\nbody = \"a\"\noffset = 0.0\n");
    assert!(Scene::from_toml(&ok, "t.toml").is_ok());
}

/// The geared pendulum without gravity, a rotational spring κ on the joint named `shoulder`
/// (the body `arm`), started by joint name: a harmonic oscillator θ = θ₀ cos ωt with
/// ω² = κ / I_eff, I_eff = 1/3 + (−2)² · 0.25 (§8: I_eff θ̈ = −κ θ).
const BY_JOINT: &str = r#"name = "by_joint"
duration = 3.0
samples = 300
accuracy = 1e-10
outputs = ["coordinates:shoulder", "coordinates:wheel_joint"]

[model]
urdf = "geared_pendulum.urdf"

[model.q]
shoulder = [0.5]
wheel_joint = [-0.7]

[[effects]]
type = "rotational_spring"
body = "shoulder"
kappa = 3.0
"#;

#[test]
fn model_joints_are_named_in_effects_initial_state_and_outputs() {
    let run = run_model_scene(BY_JOINT);
    // joint names stand for their bodies: the columns carry the body's name
    let (th, phi) = (col(&run, "coordinates:arm.0"), col(&run, "coordinates:wheel.0"));
    let omega = (3.0_f64 / (1.0 / 3.0 + 4.0 * 0.25)).sqrt();
    // integration error at accuracy = 1e-10 over ~2 periods, relative to θ₀
    let e = worst(th.len(), |i| th[i] - 0.5 * (omega * run.t[i]).cos()) / 0.5;
    assert!(e <= 1e-8, "θ off θ₀ cos ωt by {e:e} relative");
    let e_gear = worst(th.len(), |i| phi[i] - (-2.0 * th[i] + 0.3));
    assert!(e_gear <= 1e-10, "gear violated by {e_gear:e}");
}

#[test]
fn misspelt_joint_names_get_located_did_you_mean() {
    for (from, to, key) in [
        ("shoulder = [0.5]", "sholder = [0.5]", "model.q.sholder"),
        ("body = \"shoulder\"", "body = \"sholder\"", "effects[0].body"),
    ] {
        let text = BY_JOINT.replace(from, to);
        match Scene::from_toml(&text, "examples/models/scene.toml") {
            Err(e) => {
                let m = e.to_string();
                assert!(m.contains(key), "{to}: {m:?} does not name {key}");
                assert!(m.contains("did you mean `shoulder`"), "{to}: {m:?} has no hint");
            }
            Ok(_) => panic!("{to}: accepted"),
        }
    }
}

/// examples/models/stop_pendulum.toml: the bar falls from θ₀ = 0 onto its lower stop θ_s = −1
/// with ω₀ = √(2 m g ℓ (sin θ₀ − sin θ_s) / J); between impacts the flight is conservative and
/// returns to the stop at the speed it left with, so the k-th impact closes at eᵏ ω₀ (§7.13,
/// (7.13.18)), until the bounces accumulate and the bar rests on the stop; it never passes it.
#[test]
fn urdf_limit_as_contact_bounces_with_e_scaled_speeds_then_rests() {
    let text = std::fs::read_to_string("examples/models/stop_pendulum.toml").unwrap();
    let run = run_model_scene(&text);
    let (e, lower, j, mgl) = (0.8_f64, -1.0_f64, 1.0 / 3.0, G * 0.5);
    let w0 = (2.0 * mgl * (0.0_f64.sin() - lower.sin()) / j).sqrt();
    let impacts: Vec<f64> = run
        .contacts
        .iter()
        .filter(|c| c.kind == vectrix::scene::ContactEventKind::Impact)
        .map(|c| c.closing_speed)
        .collect();
    assert!(impacts.len() >= 30, "only {} impacts", impacts.len());
    // the integration error at accuracy = 1e-10 of the located touches, over the 76 flights;
    // measured 6e-10 relative to ω₀
    let e_k = worst(impacts.len(), |k| impacts[k] - e.powi(k as i32) * w0) / w0;
    assert!(e_k <= 5e-9, "impact speeds off eᵏ ω₀ by {e_k:e} relative to ω₀");
    for (k, c) in
        run.contacts.iter().enumerate().filter(|(_, c)| c.kind == vectrix::scene::ContactEventKind::Impact)
    {
        assert!((c.opening_speed - e * c.closing_speed).abs() <= 1e-15 * w0, "impact {k}: not e-scaled");
    }
    assert!(
        run.contacts.iter().any(|c| c.kind == vectrix::scene::ContactEventKind::Rest),
        "the bounces never came to rest"
    );
    let th = col(&run, "coordinates:bar.0");
    // never through the stop (the located touch leaves at most rounding), and resting at the end
    let through = th.iter().fold(0.0, |m: f64, x| nan_max(m, lower - x));
    assert!(through <= 1e-12, "the bar passed its stop by {through:e} rad");
    let last = th[th.len() - 1];
    assert!((last - lower).abs() <= 1e-12, "the bar ends at {last}, not on its stop");
}
