//! Chapter 10: aircraft frames and angles (earth, aircraft, stability, wind frames), angle of
//! attack and sideslip, heading/flight-path/bank angles, angular velocity and attitude rates.
//!
//! Problem answers are the chapter notes' [C] values (the book prints no answers), at the
//! notes' printed precision.
mod support;

use nalgebra::{Matrix3, Vector3};
use support::{EPS, NanAmax, assert_abs, assert_printed, assert_printed_slice, assert_rel};
use vectrix::flight::*;

fn deg(x: f64) -> f64 {
    x.to_radians()
}

#[test]
fn problem_10_11_1_alpha_beta_and_stability_wind_velocity() {
    // P10.11.1: V = (72, −6.3, −43) m/s ⇒ α = −30.847°, β = −4.296°, V|_S = (83.863, −6.3, 0),
    // V|_W = (84.099, 0, 0).
    let a: AeroAngles = AeroAngles::from_body_velocity([72.0, -6.3, -43.0]);
    assert_printed(a.alpha.to_degrees(), "-30.847");
    assert_printed(a.beta.to_degrees(), "-4.296");
    let v = Vector3::new(72.0, -6.3, -43.0);
    let v_s = o_s_ac(a.alpha) * v;
    // the zero components are exact in the mathematics: checked at ε times |V|
    assert_printed_slice(&v_s.as_slice()[..2], &["83.863", "-6.3"]);
    assert_abs(v_s[2], 0.0, 8.0 * EPS * v.norm());
    let v_w = o_w_ac(a.alpha, a.beta) * v;
    assert_printed(v_w[0], "84.099");
    assert_abs(v_w[1], 0.0, 8.0 * EPS * v.norm());
    assert_abs(v_w[2], 0.0, 8.0 * EPS * v.norm());
}

#[test]
fn problem_10_11_2_and_3_body_velocity_from_alpha_beta() {
    // P10.11.2: α = 14°, V = 94 ⇒ V|_AC = (91.208, 0, 22.741). P10.11.3: α = 10°, β = −19°,
    // V = 80 ⇒ V|_AC = (74.492, −26.045, 13.135), V|_S = (75.641, −26.045, 0).
    let a = AeroAngles { airspeed: 94.0, alpha: deg(14.0), beta: 0.0 };
    let v = a.body_velocity();
    assert_printed(v[0], "91.208");
    assert_eq!(v[1], 0.0, "β = 0: no side velocity");
    assert_printed(v[2], "22.741");
    let a = AeroAngles { airspeed: 80.0, alpha: deg(10.0), beta: deg(-19.0) };
    let v = a.body_velocity();
    // V sin β = 80 sin(−19°) = −26.04545 and V_S,x = 75.64149: the notes' −26.046 and 75.642
    // round twice (via four decimals); three decimals give −26.045 and 75.641.
    assert_printed_slice(&v, &["74.492", "-26.045", "13.135"]);
    let v_s = o_s_ac(a.alpha) * Vector3::from(v);
    assert_printed_slice(&v_s.as_slice()[..2], &["75.641", "-26.045"]);
    assert_abs(v_s[2], 0.0, 8.0 * EPS * 80.0); // exact zero, at ε times V
}

#[test]
fn problem_10_11_4_gravity_in_aircraft_and_stability_frames() {
    // P10.11.4: (Ψ, Θ, Φ) = (22, 5, −24)°, α = −17°, g = 9.8 ⇒ g|_AC = (−0.8541, −3.9709, 8.9187),
    // g|_S = (−3.4244, −3.9709, 8.2793) m/s².
    let e = Euler321::new(deg(22.0), deg(5.0), deg(-24.0));
    let g_ac = e.o_ac_e() * Vector3::new(0.0, 0.0, 9.8);
    assert_printed_slice(g_ac.as_slice(), &["-0.8541", "-3.9709", "8.9187"]);
    let g_s = o_s_ac(deg(-17.0)) * g_ac;
    assert_printed_slice(g_s.as_slice(), &["-3.4244", "-3.9709", "8.2793"]);
}

#[test]
fn problem_10_11_5_position_in_aircraft_frame() {
    // P10.11.5: r_E = (6.2, −14.1, 65.2), (Ψ, Θ, Φ) = (62, 7, −12)° ⇒ r_AC = (−17.414, −25.043,
    // 59.648); |r| = 66.995 in both frames.
    let e = Euler321::new(deg(62.0), deg(7.0), deg(-12.0));
    let r_e = Vector3::new(6.2, -14.1, 65.2);
    let r_ac = e.o_ac_e() * r_e;
    assert_printed_slice(r_ac.as_slice(), &["-17.414", "-25.043", "59.648"]);
    assert_printed(r_ac.norm(), "66.995");
    assert_rel(r_e.norm(), r_ac.norm(), 8.0 * EPS);
}

#[test]
fn problem_10_11_6_roll_changes_alpha_and_beta() {
    // P10.11.6: α = −13°, β = 24°, V = 85 ⇒ V_AC = (75.661, 34.573, −17.468); after a +23°
    // roll V_AC = (75.661, 24.999, −29.588), α = −21.358°, β = 17.104°.
    let a = AeroAngles { airspeed: 85.0, alpha: deg(-13.0), beta: deg(24.0) };
    let v = a.body_velocity();
    assert_printed_slice(&v, &["75.661", "34.573", "-17.468"]);
    let v2 = o1(deg(23.0)) * Vector3::from(v);
    assert_printed_slice(v2.as_slice(), &["75.661", "24.999", "-29.588"]);
    let a2: AeroAngles = AeroAngles::from_body_velocity([v2[0], v2[1], v2[2]]);
    assert_printed(a2.alpha.to_degrees(), "-21.358");
    assert_printed(a2.beta.to_degrees(), "17.104");
}

#[test]
fn problem_10_11_7_body_rates_and_inverse() {
    // P10.11.7: (Φ, Θ, Ψ) = (−52, −29, 14)°, rates (16, −7, 19)°/s ⇒ (P, Q, R) =
    // (25.2114, −17.4046, 4.7148)°/s; the inverse (10.9.9) round-trips.
    let e = Euler321::new(deg(14.0), deg(-29.0), deg(-52.0));
    let rates = [deg(16.0), deg(-7.0), deg(19.0)];
    let pqr = body_rates(&e, rates);
    let pqr_deg: Vec<f64> = pqr.iter().map(|r| r.to_degrees()).collect();
    assert_printed_slice(&pqr_deg, &["25.2114", "-17.4046", "4.7148"]);
    let back = euler_rates(&e, pqr).unwrap();
    for (g, w) in back.iter().zip(rates) {
        assert_abs(*g, w, 8.0 * EPS);
    }
}

#[test]
fn eq_10_6_18_alpha_beta_defined_at_zero_speed() {
    // (10.6.18): if the velocity has no component in the plane of symmetry, the book sets
    // α = 0; at zero speed also β = 0. No NaN.
    let a: AeroAngles = AeroAngles::from_body_velocity([0.0, 0.0, 0.0]);
    assert_eq!((a.airspeed, a.alpha, a.beta), (0.0, 0.0, 0.0));
    let a: AeroAngles = AeroAngles::from_body_velocity([0.0, 5.0, 0.0]);
    assert_eq!(a.alpha, 0.0);
    assert_rel(a.beta, std::f64::consts::FRAC_PI_2, 2.0 * EPS);
    // flying backwards: α = π (never −π for W = +0)
    let a: AeroAngles = AeroAngles::from_body_velocity([-10.0, 0.0, 0.0]);
    assert_rel(a.alpha, std::f64::consts::PI, 2.0 * EPS);
}

#[test]
fn eq_10_9_9_gimbal_lock_is_an_error_quaternion_is_not() {
    // (10.9.9) divides by cos Θ (det S = cos Θ): Err at Θ = ±90°; the quaternion rates of
    // (9.7.37) are regular there.
    let e = Euler321::new(0.3, std::f64::consts::FRAC_PI_2, 0.2);
    assert!(matches!(euler_rates(&e, [0.1, 0.2, 0.3]), Err(FlightError::GimbalLock { .. })));
    let q = quaternion_from_euler321(&e);
    let qd = quaternion_rates(q, [0.1, 0.2, 0.3]);
    assert!(qd.iter().all(|v| v.is_finite()));
    // q·q̇ = 0: the rate keeps |q| = 1
    let dot: f64 = q.iter().zip(qd).map(|(a, b)| a * b).sum();
    assert_abs(dot, 0.0, 8.0 * EPS);
}

#[test]
fn eq_10_3_16_orientation_matrix_entries() {
    // (10.3.16): 𝓞_{AC/E}(1,3) = −sin Θ, (2,3) = sin Φ cos Θ, (3,3) = cos Φ cos Θ, and the
    // quaternion of the same angles gives the same matrix.
    let e = Euler321::new(0.7, -0.4, 1.1);
    let o = e.o_ac_e();
    assert_abs(o[(0, 2)], -(-0.4f64).sin(), 4.0 * EPS);
    assert_abs(o[(1, 2)], 1.1f64.sin() * (-0.4f64).cos(), 4.0 * EPS);
    assert_abs(o[(2, 2)], 1.1f64.cos() * (-0.4f64).cos(), 4.0 * EPS);
    let oq = orientation_from_quaternion(quaternion_from_euler321(&e));
    assert!((o - oq).nan_amax() <= 8.0 * EPS);
    assert!((o * o.transpose() - Matrix3::identity()).nan_amax() <= 8.0 * EPS);
}

#[test]
fn eq_10_9_18_determinant_is_cos_gamma_and_10_9_20_22_invert_it() {
    // det[î_W ĵ_G k̂_F]|_AC = cos γ (below (10.9.22)), and the columns a, b, c of
    // (10.9.20)–(10.9.22) are its inverse: wind_angle_rates ∘ body_rates_from_wind_angle_rates
    // is the identity, with α̇ and β̇ entering through (10.9.17).
    for (alpha, beta, mu, gamma) in [(0.3, -0.2, 0.7, 0.4), (-0.1, 0.5, -2.0, -1.2), (0.0, 0.0, 0.0, 0.0)] {
        let w = wind_angle_rate_matrix(alpha, beta, mu, gamma);
        assert_abs(w.determinant(), f64::cos(gamma), 16.0 * EPS);
        // columns are unit vectors (10.9.14–16)
        for j in 0..3 {
            assert_abs(w.column(j).norm(), 1.0, 8.0 * EPS);
        }
        let aero = AeroAngles { airspeed: 100.0, alpha, beta };
        let path = FlightPathAngles { eta: 0.9, gamma, mu };
        let rates = [0.11, -0.07, 0.05];
        let (alpha_dot, beta_dot) = (0.02, -0.03);
        let pqr = body_rates_from_wind_angle_rates(&aero, &path, rates, alpha_dot, beta_dot);
        let back = wind_angle_rates(&aero, &path, pqr, alpha_dot, beta_dot).unwrap();
        for (b, r) in back.iter().zip(rates) {
            assert_abs(*b, r, 32.0 * EPS / f64::cos(gamma));
        }
    }
}

#[test]
fn eq_10_9_19_vertical_flight_path_is_an_error() {
    // det = cos γ: (10.9.19) has no solution on a vertical flight path.
    let aero = AeroAngles { airspeed: 50.0, alpha: 0.1, beta: 0.0 };
    let path = FlightPathAngles { eta: 0.0, gamma: std::f64::consts::FRAC_PI_2, mu: 0.0 };
    let e = wind_angle_rates(&aero, &path, [0.1, 0.0, 0.0], 0.0, 0.0).unwrap_err();
    assert!(matches!(e, FlightError::VerticalFlightPath { .. }), "{e}");
    assert!(e.to_string().contains("γ = ±90°"));
}

mod prop {
    use super::*;
    use proptest::prelude::*;

    fn angle() -> impl Strategy<Value = f64> {
        prop_oneof![-3.1f64..3.1, Just(0.0), Just(1e-9), Just(-1e-9)]
    }
    fn pitch() -> impl Strategy<Value = f64> {
        prop_oneof![
            -1.5f64..1.5,
            Just(std::f64::consts::FRAC_PI_2),
            Just(-std::f64::consts::FRAC_PI_2 + 1e-9),
            Just(0.0)
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        #[test]
        fn fact_10_8_5_wings_level_no_sideslip(psi in angle(), theta in -1.2f64..1.2, alpha in -0.3f64..0.3) {
            // Fact 10.8.5(i): Φ = β = 0 ⇒ μ = 0, η = Ψ, Θ = α + γ.
            let e = Euler321::new(psi, theta, 0.0);
            let fp = FlightPathAngles::from_attitude(&e, alpha, 0.0);
            prop_assert!(fp.mu.abs() <= 64.0 * EPS);
            prop_assert!((fp.eta - psi).abs() <= 64.0 * EPS);
            prop_assert!((theta - (alpha + fp.gamma)).abs() <= 64.0 * EPS);
        }

        #[test]
        fn fact_10_8_6_level_path_no_bank(psi in -1.0f64..1.0, beta in -0.4f64..0.4, theta in -0.5f64..0.5) {
            // Fact 10.8.6(ii): Φ = μ = γ = 0 ⇒ Θ = α, Ψ = η − β. With Φ = 0 and α = Θ the
            // path is level; then μ = 0 and η = Ψ + β.
            let e = Euler321::new(psi, theta, 0.0);
            let fp = FlightPathAngles::from_attitude(&e, theta, beta);
            prop_assert!(fp.gamma.abs() <= 64.0 * EPS);
            prop_assert!(fp.mu.abs() <= 64.0 * EPS);
            prop_assert!((psi - (fp.eta - beta)).abs() <= 64.0 * EPS);
        }

        #[test]
        fn eq_10_8_4_wind_frame_two_ways(psi in angle(), theta in -1.4f64..1.4, phi in angle(),
                                         alpha in -0.5f64..0.5, beta in -0.5f64..0.5) {
            // (10.8.4): 𝓞₁(μ)𝓞₂(γ)𝓞₃(η) = 𝓞₃(β)𝓞₂(−α)𝓞₁(Φ)𝓞₂(Θ)𝓞₃(Ψ) (away from γ = ±90°),
            // and P10.11.10 [C]: sin μ = (sin Φ cos Θ + sin β sin γ)/(cos β cos γ).
            let e = Euler321::new(psi, theta, phi);
            let fp = FlightPathAngles::from_attitude(&e, alpha, beta);
            prop_assume!(fp.gamma.cos() > 1e-3);
            let lhs = fp.o_w_e();
            let rhs = o_w_ac(alpha, beta) * e.o_ac_e();
            prop_assert!((lhs - rhs).nan_amax() <= 1e3 * EPS);
            let sin_mu = (phi.sin() * theta.cos() + beta.sin() * fp.gamma.sin()) / (beta.cos() * fp.gamma.cos());
            prop_assert!((fp.mu.sin() - sin_mu).abs() <= 1e4 * EPS);
        }

        #[test]
        fn eq_10_6_28_alpha_beta_round_trip(v in 0.1f64..300.0, alpha in -3.1f64..3.1, beta in -1.5f64..1.5) {
            // (10.6.28) and (10.6.18), (10.6.27) are inverse for α ∈ (−π, π], |β| < π/2.
            let a = AeroAngles { airspeed: v, alpha, beta };
            let b: AeroAngles = AeroAngles::from_body_velocity(a.body_velocity());
            prop_assert!((b.airspeed - v).abs() <= 16.0 * EPS * v);
            prop_assert!((b.alpha - alpha).abs() <= 1e3 * EPS);
            prop_assert!((b.beta - beta).abs() <= 1e3 * EPS);
        }

        #[test]
        fn eq_10_9_8_rates_round_trip_or_gimbal_lock(phi in angle(), theta in pitch(), psi in angle(),
                                                     p in -1.0f64..1.0, q in -1.0f64..1.0, r in -1.0f64..1.0) {
            // (10.9.8)/(10.9.9) are inverse where cos Θ ≠ 0; near ±90° either Err or finite.
            let e = Euler321::new(psi, theta, phi);
            match euler_rates(&e, [p, q, r]) {
                Ok(rates) => {
                    let back = body_rates(&e, rates);
                    let tol = 64.0 * EPS / theta.cos().abs().max(1e-300);
                    for (b, w) in back.iter().zip([p, q, r]) {
                        prop_assert!((b - w).abs() <= tol);
                    }
                }
                Err(FlightError::GimbalLock { cos_theta }) => prop_assert!(cos_theta.abs() < GIMBAL_LOCK_TOL),
                Err(e) => prop_assert!(false, "{e}"),
            }
        }

        #[test]
        fn eq_10_9_17_wind_angle_rates_are_the_derivatives_of_eta_gamma_mu(
            psi in angle(), theta in -1.2f64..1.2, phi in angle(), alpha in -0.5f64..0.5, beta in -0.5f64..0.5,
            rates in proptest::array::uniform3(-1.0f64..1.0), alpha_dot in -0.5f64..0.5, beta_dot in -0.5f64..0.5,
        ) {
            // Differentiate (η, γ, μ) of (10.8.4) exactly with dual numbers along a motion with
            // Euler-angle rates [Φ̇, Θ̇, Ψ̇] and α̇, β̇, and compare with (10.9.19)–(10.9.22)
            // fed with ω|_AC = S(Φ, Θ)[Φ̇, Θ̇, Ψ̇] (10.9.8).
            use num_dual::Dual64;
            let [phi_dot, theta_dot, psi_dot] = rates;
            let d = |x: f64, dx: f64| Dual64::new(x, dx);
            let e = Euler321::new(d(psi, psi_dot), d(theta, theta_dot), d(phi, phi_dot));
            let path_d = FlightPathAngles::from_attitude(&e, d(alpha, alpha_dot), d(beta, beta_dot));
            let path = FlightPathAngles { eta: path_d.eta.re, gamma: path_d.gamma.re, mu: path_d.mu.re };
            prop_assume!(path.gamma.cos() > 1e-2);
            let pqr = body_rates(&Euler321::new(psi, theta, phi), [phi_dot, theta_dot, psi_dot]);
            let aero = AeroAngles { airspeed: 1.0, alpha, beta };
            let [mu_dot, gamma_dot, eta_dot] = wind_angle_rates(&aero, &path, pqr, alpha_dot, beta_dot).unwrap();
            // conditioning 1/cos γ ≤ 100 and 1/cos Θ (from the atan2 extraction)
            let tol = 1e4 * EPS / path.gamma.cos();
            prop_assert!((mu_dot - path_d.mu.eps).abs() <= tol, "μ̇ {} vs {}", mu_dot, path_d.mu.eps);
            prop_assert!((gamma_dot - path_d.gamma.eps).abs() <= tol, "γ̇ {} vs {}", gamma_dot, path_d.gamma.eps);
            prop_assert!((eta_dot - path_d.eta.eps).abs() <= tol, "η̇ {} vs {}", eta_dot, path_d.eta.eps);
        }

        #[test]
        fn eq_10_9_23_quaternion_rate_matches_poisson(phi in angle(), theta in pitch(), psi in angle(),
                                                      p in -1.0f64..1.0, q in -1.0f64..1.0, r in -1.0f64..1.0) {
            // Poisson (10.9.23): 𝓞̇ = −ω^× 𝓞 for 𝓞 = 𝓞_{AC/E}; check d/dt of the quaternion's
            // orientation matrix against it, through the chain rule in the direction q̇.
            let e = Euler321::new(psi, theta, phi);
            let q0 = quaternion_from_euler321(&e);
            let qd = quaternion_rates(q0, [p, q, r]);
            let h = 1e-6;
            let qp: [f64; 4] = std::array::from_fn(|i| q0[i] + h * qd[i]);
            let qm: [f64; 4] = std::array::from_fn(|i| q0[i] - h * qd[i]);
            let od = (orientation_from_quaternion(qp) - orientation_from_quaternion(qm)) / (2.0 * h);
            let w = Vector3::new(p, q, r);
            let poisson = -w.cross_matrix() * orientation_from_quaternion(q0);
            // central difference: O(h²) ≈ 1e-12 plus roundoff ε/h ≈ 2e-10
            prop_assert!((od - poisson).nan_amax() <= 1e-8);
        }
    }
}

#[path = "ch10/problems.rs"]
mod problems;

#[path = "ch10/sections.rs"]
mod sections;
