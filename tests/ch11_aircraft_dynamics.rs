//! Chapter 11: aerodynamic and thrust forces and moments, and the nonlinear 12-state
//! equations of motion (11.5.1–16), built on the rigid-body layer.
mod support;

use nalgebra::{Matrix3, Vector3};
use support::{EPS, NanAmax, assert_abs, assert_printed_slice, assert_rel};
use vectrix::flight::*;

fn airframe() -> Airframe {
    Airframe::new(2.0, 3.0, 5.0, 6.0, 0.4).unwrap()
}

#[test]
fn notes_ch9_rigid_body_euler_vector_with_product_of_inertia() {
    // Notes §4 [C]: J = [[3, 0, −.4], [0, 5, 0], [−.4, 0, 6]], M = (.2, −.1, .3),
    // (Φ, Θ, Ψ) = (.3, −.5, 1.1), rates (.2, .4, −.3) ⇒ ω̇ = (0.1143759696, −0.0217777147,
    // 0.0594279733) (Lagrange with Q = SᵀM and Euler agree, (9.7.33–34)).
    let e: Euler321 = Euler321::new(1.1, -0.5, 0.3);
    let omega = body_rates(&e, [0.2, 0.4, -0.3]);
    let x = AircraftState { position: [0.0; 3], velocity: [0.0; 3], attitude: e, omega };
    let fm = ForcesMoments { roll: 0.2, pitch: -0.1, yaw: 0.3, ..Default::default() };
    let f = state_derivative(&airframe(), 0.0, &x, &fm).unwrap();
    assert_printed_slice(&f.omega, &["0.1143759696", "-0.0217777147", "0.0594279733"]);
}

#[test]
fn eq_11_5_12_rotational_equations_with_gamma() {
    // (11.5.12–14) with Γ = J_xx J_zz − J_xz²:
    // ΓṖ = (J_yyJ_zz − J_zz² − J_xz²)QR + J_xz(J_xx − J_yy + J_zz)PQ + J_zz L + J_xz N,
    // J_yyQ̇ = (J_zz − J_xx)PR + J_xz(R² − P²) + M,
    // ΓṘ = (J_xx² − J_xxJ_yy + J_xz²)PQ + J_xz(J_yy − J_xx − J_zz)QR + J_xz L + J_xx N.
    let (jxx, jyy, jzz, jxz) = (3.0, 5.0, 6.0, 0.4);
    let [p, q, r] = [0.7, -0.3, 0.9];
    let (l, m, n) = (0.2, -0.5, 0.8);
    let x = AircraftState { omega: [p, q, r], velocity: [10.0, 0.0, 0.0], ..Default::default() };
    let fm = ForcesMoments { roll: l, pitch: m, yaw: n, ..Default::default() };
    let f = state_derivative(&airframe(), 9.8, &x, &fm).unwrap();
    let gamma = jxx * jzz - jxz * jxz;
    let pd =
        ((jyy * jzz - jzz * jzz - jxz * jxz) * q * r + jxz * (jxx - jyy + jzz) * p * q + jzz * l + jxz * n)
            / gamma;
    let qd = ((jzz - jxx) * p * r + jxz * (r * r - p * p) + m) / jyy;
    let rd =
        ((jxx * jxx - jxx * jyy + jxz * jxz) * p * q + jxz * (jyy - jxx - jzz) * q * r + jxz * l + jxx * n)
            / gamma;
    for (g, w) in f.omega.iter().zip([pd, qd, rd]) {
        assert_abs(*g, w, 16.0 * EPS);
    }
}

#[test]
fn eq_11_1_21_aerodynamic_force_in_aircraft_frame() {
    // (11.1.21): F_A|_AC = [−cαcβD + cαsβE + sαL, −sβD − cβE, −sαcβD + sαsβE − cαL].
    let (alpha, beta, d, e, l): (f64, f64, f64, f64, f64) = (0.2, -0.1, 3.0, 0.7, 20.0);
    let (sa, ca, sb, cb) = (alpha.sin(), alpha.cos(), beta.sin(), beta.cos());
    let want = Vector3::new(
        -ca * cb * d + ca * sb * e + sa * l,
        -sb * d - cb * e,
        -sa * cb * d + sa * sb * e - ca * l,
    );
    let got: Vector3<f64> = o_w_ac(alpha, beta).transpose() * Vector3::new(-d, -e, -l);
    assert!((got - want).nan_amax() <= 16.0 * EPS * l);
}

#[test]
fn eq_11_5_6_translational_equations() {
    // (11.5.6–8) with side drag E = 0, thrust tilt Φ_T:
    // U̇ = VR − WQ − g sΘ + (−cβcαD + sαL + cΦ_T F_T)/m, V̇ = −UR + WP + g sΦcΘ − sβD/m,
    // Ẇ = UQ − VP + g cΦcΘ + (−cβsαD − cαL − sΦ_T F_T)/m.
    let ac = airframe();
    let (m, g) = (ac.mass(), 9.8);
    let e: Euler321 = Euler321::new(0.4, 0.2, -0.3);
    let x: AircraftState = AircraftState {
        position: [0.0; 3],
        velocity: [50.0, 3.0, 6.0],
        attitude: e,
        omega: [0.1, -0.2, 0.05],
    };
    let fm = ForcesMoments { drag: 4.0, lift: 30.0, thrust: 7.0, thrust_angle: 0.05, ..Default::default() };
    let f = state_derivative(&ac, g, &x, &fm).unwrap();
    let a = x.aero_angles();
    let (sa, ca, sb, cb) = (a.alpha.sin(), a.alpha.cos(), a.beta.sin(), a.beta.cos());
    let [u, v, w] = x.velocity;
    let [p, q, r] = x.omega;
    let (st, ct, sp, cp) = (e.theta.sin(), e.theta.cos(), e.phi.sin(), e.phi.cos());
    let ud = v * r - w * q - g * st + (-cb * ca * fm.drag + sa * fm.lift + 0.05f64.cos() * fm.thrust) / m;
    let vd = -u * r + w * p + g * sp * ct - sb * fm.drag / m;
    let wd =
        u * q - v * p + g * cp * ct + (-cb * sa * fm.drag - ca * fm.lift - 0.05f64.sin() * fm.thrust) / m;
    for (gt, wt) in f.velocity.iter().zip([ud, vd, wd]) {
        assert_rel(*gt, wt, 64.0 * EPS);
    }
    // (11.5.3): [Ẋ, Ẏ, Ż] = 𝓞_{E/AC}[U, V, W]; speed is preserved by the rotation
    let r_dot = Vector3::from(f.position);
    assert_rel(r_dot.norm(), Vector3::from(x.velocity).norm(), 16.0 * EPS);
}

#[test]
fn eq_11_3_6_bad_mass_properties_are_errors() {
    // (11.3.6): mass and moments of inertia must be positive and physical.
    assert!(matches!(
        Airframe::new(-1.0, 3.0, 5.0, 6.0, 0.0),
        Err(FlightError::OutOfRange { what: "mass", .. })
    ));
    assert!(matches!(Airframe::new(1.0, -3.0, 5.0, 6.0, 0.0), Err(FlightError::OutOfRange { .. })));
    assert!(matches!(Airframe::new(1.0, 3.0, 5.0, 6.0, 5.0), Err(FlightError::OutOfRange { .. })));
    // J_zz > J_xx + J_yy is not a rigid body (triangle inequality, Fact 6.2.8)
    assert!(matches!(Airframe::new(1.0, 1.0, 1.0, 3.0, 0.0), Err(FlightError::OutOfRange { .. })));
    assert!(matches!(Airframe::new(f64::NAN, 3.0, 5.0, 6.0, 0.0), Err(FlightError::OutOfRange { .. })));
    let j = airframe().inertia_matrix();
    assert_eq!(j, Matrix3::new(3.0, 0.0, -0.4, 0.0, 5.0, 0.0, -0.4, 0.0, 6.0));
}

#[test]
fn eq_11_5_9_gimbal_lock_in_the_equations_of_motion() {
    // The Euler-angle kinematics (10.9.9) inside (11.5) fail at Θ = ±90°: Err, not NaN.
    let x = AircraftState {
        velocity: [50.0, 0.0, 0.0],
        attitude: Euler321::new(0.0, std::f64::consts::FRAC_PI_2, 0.0),
        ..Default::default()
    };
    let r = state_derivative(&airframe(), 9.8, &x, &ForcesMoments::default());
    assert!(matches!(r, Err(FlightError::GimbalLock { .. })));
}

/// Classic RK4 on the nonlinear model (test helper).
fn rk4(ac: &Aircraft, x0: [f64; 12], u: &Controls, dt: f64, steps: usize) -> [f64; 12] {
    let f = |x: [f64; 12]| ac.dynamics(&AircraftState::from_array(x), u).unwrap().to_array();
    let add = |x: [f64; 12], k: [f64; 12], h: f64| -> [f64; 12] { std::array::from_fn(|i| x[i] + h * k[i]) };
    let mut x = x0;
    for _ in 0..steps {
        let k1 = f(x);
        let k2 = f(add(x, k1, dt / 2.0));
        let k3 = f(add(x, k2, dt / 2.0));
        let k4 = f(add(x, k3, dt));
        x = std::array::from_fn(|i| x[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
    }
    x
}

mod prop {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        #[test]
        fn linear_model_matches_finite_differences(v in 600.0f64..760.0, gamma in -0.03f64..0.08, k in 0usize..12) {
            // The dual-number A (column k) equals central differences of the explicit nonlinear
            // ẋ = f(x, u) (which resolves α̇, β̇ by fixed point): step h = 1e-4·scale_k gives
            // O(h²) truncation ≈ 1e-8 relative. (Steeper descents need negative thrust: trim
            // then fails on U̇ = 0, as it should; see ch12.)
            let ac = business_jet();
            let t = trim(&ac, TrimSpec::Straight { airspeed: v, gamma }, TrimLimits::default()).unwrap();
            let lin = linearize(&ac, &t).unwrap();
            let x0 = t.state.to_array();
            let scale = if (3..6).contains(&k) { v } else { 1.0 };
            let h = 1e-4 * scale;
            let mut xp = x0;
            let mut xm = x0;
            xp[k] += h;
            xm[k] -= h;
            let fp = ac.dynamics(&AircraftState::from_array(xp), &t.controls).unwrap().to_array();
            let fm = ac.dynamics(&AircraftState::from_array(xm), &t.controls).unwrap().to_array();
            for i in 0..12 {
                let fd = (fp[i] - fm[i]) / (2.0 * h);
                let a = lin.state_space.a()[(i, k)];
                prop_assert!((fd - a).abs() <= 1e-6 * (1.0 + a.abs()), "A[{i},{k}] = {a} vs FD {fd}");
            }
        }

        #[test]
        fn small_perturbation_follows_linear_response(dalpha in -2e-3f64..2e-3, dbeta in -2e-3f64..2e-3) {
            // From the level trim, perturb α and β by ~0.1° and fly the nonlinear model for 4 s;
            // the linear model e^{At}δx₀ predicts the state to second order: |error| ≲ |δx|².
            let ac = business_jet();
            let t = trim(&ac, TrimSpec::Straight { airspeed: BUSINESS_JET_U0, gamma: 0.0 }, TrimLimits::default()).unwrap();
            let lin = linearize(&ac, &t).unwrap();
            let v = BUSINESS_JET_U0;
            let mut dx = [0.0; 12];
            dx[5] = v * dalpha;
            dx[4] = v * dbeta;
            let x0 = t.state.to_array();
            let start: [f64; 12] = std::array::from_fn(|i| x0[i] + dx[i]);
            let t_end = 4.0;
            let end = rk4(&ac, start, &t.controls, 0.01, 400);
            let phi = vectrix::lti::expm(&(lin.state_space.a() * t_end)).unwrap();
            let pred = &phi * nalgebra::DVector::from_row_slice(&dx);
            // compare W and V (the perturbed states) and Q, P, R
            for &i in &[4usize, 5, 9, 10, 11] {
                let got = end[i] - x0[i];
                let amp = v * (dalpha.abs() + dbeta.abs()) + 1e-12;
                // second-order terms ~ amp·(δα + δβ): allow 2% of the amplitude plus RK4 error
                prop_assert!((got - pred[i]).abs() <= 0.02 * amp + 1e-8, "state {i}: {got} vs {}", pred[i]);
            }
        }
    }
}

#[path = "ch11/problems.rs"]
mod problems;

#[path = "ch11/sections.rs"]
mod sections;
