//! An aircraft as a body: a free body with the `aero` and `thrust` effects runs through the one
//! scene pipeline. Its motion must be the motion of the 12-state flight equations of
//! `vectrix-flight` (11.5.3–16, the library's reference model), and its trim the flight
//! trim (§12.3).
//!
//! Both sides are vectrix code, so these are consistency checks between two independent
//! formulations (quaternion free body with ABA and exactly solved α̇/β̇ terms, against Euler
//! 3-2-1 angles with body-axis velocities and a fixed-point α̇/β̇); the flight equations
//! themselves are tested against the book in tests/ch11_* to ch14_*.

mod support;

use nalgebra::{UnitQuaternion, Vector3};
use support::nan_max;
use vectrix::scene::Scene;
use vectrix_flight::{Aircraft, AircraftState, Controls, Trim, TrimLimits, TrimSpec, business_jet_in, trim};
use vectrix_ode::explicit::{Adaptive, Stepper};
use vectrix_units::UnitSystem;

/// U₀ = 400 kt in m/s (the knot is exactly 1852/3600 m/s).
const U0: f64 = 400.0 * 1852.0 / 3600.0;

fn jet() -> Aircraft {
    business_jet_in(UnitSystem::Si)
}

fn level_trim() -> Trim {
    trim(&jet(), TrimSpec::Straight { airspeed: U0, gamma: 0.0 }, TrimLimits::default()).unwrap()
}

/// The free body's rotation R = 𝓞_{AC/E}ᵀ (link to ground) of Euler 3-2-1 angles.
fn attitude(x: &AircraftState) -> UnitQuaternion<f64> {
    let e = x.attitude;
    UnitQuaternion::from_euler_angles(e.phi, e.theta, e.psi)
}

/// A scene file of the jet from state x with the controls u₀ and an elevator doublet.
fn scene_text(x: &AircraftState, u: &Controls, doublet: f64, duration: f64, extra: &str) -> String {
    let ac = jet();
    let r = attitude(x);
    let vw = r * Vector3::from(x.velocity);
    let (p, qq) = (x.position, r.quaternion());
    let [wx, wy, wz] = x.omega;
    format!(
        r#"
name = "jet"
duration = {duration:?}
samples = 40
method = {{ name = "dop853", rtol = 1e-12 }}
outputs = ["q", "v"]
{extra}

[[bodies]]
name = "jet"
joint = {{ type = "free" }}
mass = {{ shape = "aircraft", model = "business_jet" }}
q = [{:?}, {:?}, {:?}, {:?}, {:?}, {:?}, {:?}]
v = [{:?}, {:?}, {:?}, {wx:?}, {wy:?}, {wz:?}]

[[effects]]
type = "uniform_gravity"
g = [0.0, 0.0, {:?}]

[[effects]]
type = "aero"
body = "jet"
aircraft = "business_jet"
elevator = {{ kind = "doublet", start = 1.0, width = 1.0, amplitude = {doublet:?}, offset = {:?} }}
aileron = {{ kind = "constant", value = {:?} }}
rudder = {{ kind = "constant", value = {:?} }}

[[effects]]
type = "thrust"
body = "jet"
profile = {{ kind = "constant", value = {:?} }}
angle = {:?}
"#,
        p[0],
        p[1],
        p[2],
        qq.w,
        qq.i,
        qq.j,
        qq.k,
        vw[0],
        vw[1],
        vw[2],
        ac.g,
        u.elevator,
        u.aileron,
        u.rudder,
        u.thrust,
        ac.thrust_angle,
    )
}

/// The 12-state flight equations integrated by DOP853 at rtol = atol = 1e-13, restarted at the
/// doublet's corners, sampled at `times`.
fn flight_reference(x0: &AircraftState, u0: &Controls, doublet: f64, times: &[f64]) -> Vec<[f64; 12]> {
    let ac = jet();
    let solver = Adaptive::dop853().rtol(1e-13).atol(1e-13);
    let end = *times.last().unwrap();
    let cuts = [0.0, 1.0, 2.0, 3.0, end];
    let mut x = x0.to_array();
    let mut out = vec![x];
    let mut k = 1;
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let mid = 0.5 * (a + b);
        let de = if (1.0..2.0).contains(&mid) {
            doublet
        } else if (2.0..3.0).contains(&mid) {
            -doublet
        } else {
            0.0
        };
        let u = Controls { elevator: u0.elevator + de, ..*u0 };
        let f = |_t: f64, y: &[f64; 12]| {
            ac.dynamics(&AircraftState::from_array(*y), &u).expect("flight equations").to_array()
        };
        let mut st = Stepper::new(&solver, f, a, x, b).unwrap();
        while !st.done() {
            st.step().unwrap();
            let t = st.t();
            while k < times.len() && times[k] <= t {
                out.push(if times[k] == t { *st.y() } else { st.dense().unwrap().eval(times[k]) });
                k += 1;
            }
        }
        x = *st.y();
    }
    out
}

/// The largest |a − b| over a group, failing on NaN.
fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, nan_max)
}

#[test]
fn aircraft_body_follows_the_flight_equations_through_an_elevator_doublet() {
    let tr = level_trim();
    let (x0, u0) = (tr.state, tr.controls);
    let doublet = 0.02;
    let scene = Scene::from_toml(&scene_text(&x0, &u0, doublet, 20.0, ""), "jet.toml").unwrap();
    let run = scene.run(&mut |_| {}).unwrap();
    assert!(run.stop.is_none(), "{:?}", run.stop);
    let reference = flight_reference(&x0, &u0, doublet, &run.t);
    assert_eq!(reference.len(), run.t.len());
    let (mut pos, mut vel, mut ang, mut rate) = (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    let (mut rate_scale, mut moved) = (0.0_f64, 0.0_f64);
    for (row, x) in run.rows.iter().zip(&reference) {
        let y = AircraftState::from_array(*x);
        let r = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(row[3], row[4], row[5], row[6]));
        // body-axis velocity U, V, W = 𝓞_{AC/E} v (the joint's speeds are ground components)
        let uvw = r.inverse() * Vector3::new(row[7], row[8], row[9]);
        let (phi, theta, psi) = r.euler_angles();
        pos = nan_max(pos, max_diff(&row[0..3], &y.position) / (U0 * 20.0));
        vel = nan_max(vel, max_diff(uvw.as_slice(), &y.velocity) / U0);
        ang = nan_max(ang, max_diff(&[phi, theta, psi], &[y.attitude.phi, y.attitude.theta, y.attitude.psi]));
        rate = nan_max(rate, max_diff(&row[10..13], &y.omega));
        rate_scale = nan_max(rate_scale, y.omega[1].abs());
        moved = nan_max(moved, (y.attitude.theta - x0.attitude.theta).abs());
    }
    eprintln!(
        "position {pos:.2e}, velocity {vel:.2e}, attitude {ang:.2e}, rates {rate:.2e} of {rate_scale:.2e}, θ moved {moved:.2e}"
    );
    // the doublet moves the aircraft: pitch rate and attitude change are not small
    assert!(rate_scale > 1e-3 && moved > 1e-3, "the doublet did not excite the short period");
    // relative 1e-9: positions to the distance flown, speeds to U₀, angles in rad, rates to
    // the largest pitch rate (measured: 1e-12 and below)
    assert!(
        pos <= 1e-9 && vel <= 1e-9 && ang <= 1e-9 && rate <= 1e-9 * rate_scale,
        "position {pos:.2e}, velocity {vel:.2e}, attitude {ang:.2e} rad, rates {:.2e} (relative)",
        rate / rate_scale
    );
}

#[test]
fn aircraft_body_trim_equals_the_flight_trim() {
    let tr = level_trim();
    // start from wings level at U₀ with the attitude, elevator and thrust at zero: the scene's
    // trim must find θ = α₀, δe₀ and F_T₀ of the flight trim
    let x = AircraftState::from_array([0.0, 0.0, 0.0, U0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    let u = Controls { elevator: 0.0, aileron: 0.0, rudder: 0.0, thrust: 0.0 };
    let extra = r#"trim = { free = ["dq:jet.4", "effects[1].elevator", "effects[2]"] }"#;
    let scene = Scene::from_toml(&scene_text(&x, &u, 0.0, 10.0, extra), "jet.toml").unwrap();
    let report = scene.trim_report().expect("the scene is trimmed");
    let [theta, de, ft] = [report.change[0], report.change[1], report.change[2]];
    let theta0 = tr.state.attitude.theta;
    // the catalogue's level trim has α₀ = 0 (§12.4 stability axes); θ = α₀ + γ
    assert!((theta - theta0).abs() <= 1e-10, "θ = {theta:e}, flight trim {theta0:e}");
    assert!(
        (de - tr.controls.elevator).abs() <= 1e-10 * (1.0 + tr.controls.elevator.abs()),
        "δe {de:e} vs {:e}",
        tr.controls.elevator
    );
    assert!(
        (ft - tr.controls.thrust).abs() <= 1e-10 * tr.controls.thrust,
        "F_T {ft:e} vs {:e}",
        tr.controls.thrust
    );
    assert!(report.residual <= vectrix::scene::TRIM_TOL);
}

#[test]
fn aircraft_body_trim_in_a_climb_equals_the_flight_trim() {
    let gamma = 0.05;
    let tr = trim(&jet(), TrimSpec::Straight { airspeed: U0, gamma }, TrimLimits::default()).unwrap();
    // climbing at γ: the ground velocity is fixed along the flight path, the attitude is free
    let x = AircraftState::from_array([
        0.0,
        0.0,
        0.0,
        U0 * gamma.cos(),
        0.0,
        -U0 * gamma.sin(),
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ]);
    let u = Controls { elevator: 0.0, aileron: 0.0, rudder: 0.0, thrust: 0.0 };
    let extra = r#"trim = { free = ["dq:jet.4", "effects[1].elevator", "effects[2]"] }"#;
    let text = scene_text(&x, &u, 0.0, 10.0, extra);
    let scene = Scene::from_toml(&text, "jet.toml").unwrap();
    let report = scene.trim_report().expect("trimmed");
    let theta0 = tr.state.attitude.theta;
    eprintln!(
        "climb trim: θ {:e} vs {theta0:e}, δe {:e} vs {:e}, F_T {:e} vs {:e}",
        report.change[0], report.change[1], tr.controls.elevator, report.change[2], tr.controls.thrust
    );
    assert!((report.change[0] - theta0).abs() <= 1e-10, "θ = {:e}, flight {theta0:e}", report.change[0]);
    assert!((report.change[1] - tr.controls.elevator).abs() <= 1e-10, "δe");
    assert!((report.change[2] - tr.controls.thrust).abs() <= 1e-10 * tr.controls.thrust, "F_T");
}

#[test]
fn aero_effect_refusals_name_the_key() {
    let tr = level_trim();
    let good = scene_text(&tr.state, &tr.controls, 0.0, 1.0, "");
    for (from, to, key) in [
        (r#"aircraft = "business_jet""#, r#"aircraft = "glider""#, "unknown aircraft `glider`"),
        (r#"model = "business_jet""#, r#"model = "glider""#, "unknown aircraft `glider`"),
        (
            r#"kind = "doublet", start = 1.0, width = 1.0"#,
            r#"kind = "doublet", start = 1.0, width = 0.0"#,
            "width",
        ),
    ] {
        let bad = good.replacen(from, to, 1);
        assert_ne!(bad, good);
        let e = Scene::from_toml(&bad, "jet.toml").unwrap_err().to_string();
        assert!(e.contains(key) && e.contains("jet.toml:"), "{e}");
    }
    // at rest the angle of attack is undefined: a run error naming the effect's body, not NaN
    let still = good.replacen("v = [", "v = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0] # ", 1);
    let e = Scene::from_toml(&still, "jet.toml").and_then(|s| s.run(&mut |_| {})).unwrap_err().to_string();
    assert!(e.contains("airspeed") && e.contains("`jet`"), "{e}");
}

/// The eigenvalues with |λ| > 1e-6 (the flight modes; the zeros are position and heading),
/// sorted by real then imaginary part.
fn flight_modes(mut l: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    l.retain(|z| z[0].hypot(z[1]) > 1e-6);
    l.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    l
}

#[test]
fn aircraft_body_modes_equal_the_flight_linearization() {
    let tr = level_trim();
    let extra = "linearize = { steady = true }";
    let scene = Scene::from_toml(&scene_text(&tr.state, &tr.controls, 0.0, 10.0, extra), "jet.toml").unwrap();
    let lm = scene.linearize().unwrap();
    let ours = flight_modes(lm.eigenvalues.clone());
    let lin = vectrix_flight::linearize(&jet(), &tr).unwrap();
    let theirs =
        flight_modes(lin.state_space.a().complex_eigenvalues().iter().map(|z| [z.re, z.im]).collect());
    // short period (2), phugoid (2), Dutch roll (2), roll and spiral: eight modes on each side
    assert_eq!(ours.len(), 8, "{ours:?}");
    assert_eq!(theirs.len(), 8, "{theirs:?}");
    let mut worst = 0.0_f64;
    for (a, b) in ours.iter().zip(&theirs) {
        let d = (a[0] - b[0]).hypot(a[1] - b[1]) / b[0].hypot(b[1]);
        worst = nan_max(worst, d);
    }
    eprintln!("largest relative eigenvalue difference {worst:.2e}");
    // both linearizations are exact (dual numbers), in different coordinates (quaternion and
    // ground velocity against Euler angles and body velocity); what differs is the eigenvalue
    // solvers' absolute error, about ε‖A‖ with ‖A‖ ~ U₀, which is largest relative to the
    // slowest mode (measured 8e-11)
    assert!(worst <= 1e-10, "{worst:e}\nscene {ours:?}\nflight {theirs:?}");
    // the control inputs are the aircraft's: B has the elevator, aileron, rudder and thrust columns
    assert_eq!(lm.inputs, ["effects[1].elevator", "effects[1].aileron", "effects[1].rudder", "effects[2]"]);
}

#[test]
fn aircraft_body_level_turn_trim_equals_the_flight_trim() {
    // a coordinated level turn at 400 kt and 3°/s: steady in the body's axes (the ground
    // velocity turns with the aircraft), β = 0, ω vertical at the turn rate (§12.5)
    let turn_rate = 3f64.to_radians();
    let tr = trim(&jet(), TrimSpec::LevelTurn { airspeed: U0, turn_rate }, TrimLimits::default()).unwrap();
    let x = AircraftState::from_array([0.0, 0.0, 0.0, U0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    let u = Controls { elevator: 0.0, aileron: 0.0, rudder: 0.0, thrust: 0.0 };
    let extra = format!(
        r#"outputs = ["air:jet", "omega:jet"]
[trim]
free = ["dq:jet.3", "dq:jet.4", "dq:jet.5", "v:jet.3", "v:jet.4", "v:jet.5",
        "effects[1].elevator", "effects[1].aileron", "effects[1].rudder", "effects[2]"]
hold = {{ "air:jet.beta" = 0.0, "omega:jet.x" = 0.0, "omega:jet.y" = 0.0, "omega:jet.z" = {turn_rate:?} }}"#
    );
    let text = scene_text(&x, &u, 0.0, 10.0, "").replace(r#"outputs = ["q", "v"]"#, &extra);
    let scene = Scene::from_toml(&text, "jet.toml").unwrap();
    let report = scene.trim_report().expect("trimmed");
    let body = &scene.spec().bodies[0];
    let (q, v) = (body.q.as_ref().unwrap(), body.v.as_ref().unwrap());
    let r = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(q[3], q[4], q[5], q[6]));
    let (phi, theta, _) = r.euler_angles();
    let e = tr.state.attitude;
    let c = tr.controls;
    let got = [phi, theta, v[3], v[4], v[5], report.change[6], report.change[7], report.change[8]];
    let want = [
        e.phi,
        e.theta,
        tr.state.omega[0],
        tr.state.omega[1],
        tr.state.omega[2],
        c.elevator,
        c.aileron,
        c.rudder,
    ];
    eprintln!(
        "turn trim: scene {got:?}\n           flight {want:?}; F_T {} vs {}",
        report.change[9], c.thrust
    );
    for (k, (a, b)) in got.iter().zip(&want).enumerate() {
        // angles (rad), rates (rad/s) and deflections (rad): absolute 1e-10
        assert!((a - b).abs() <= 1e-10, "unknown {k}: scene {a:e}, flight {b:e}");
    }
    assert!(
        (report.change[9] - c.thrust).abs() <= 1e-10 * c.thrust,
        "F_T {} vs {}",
        report.change[9],
        c.thrust
    );
    // the bank is the turn's: tan φ = V Ψ̇ / g (a coordinated turn)
    assert!(phi > 0.1, "φ = {phi}");
}
