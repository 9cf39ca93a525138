//! Example 12.2.1 and Problems 12.7.1–8. P12.7.1–3 print no answers; the chapter notes'
//! computed values ([C]) are checked at their printed precision (half a unit of the last
//! digit) and against closed forms. P12.7.4–8 ("derive …") become checks of the derived
//! linear relations against the exact Jacobian of vectrix's nonlinear model.

use std::f64::consts::{FRAC_PI_2, PI};

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::kinematics::{FrameLabel, FrameMotion, LabeledFrame, VectorJet};
use vectrix::num_dual::Dual64;
use vectrix::prelude::*;
use vectrix::rotation::{Axis, orientation_about};
use vectrix::statics::CentralGravity;

use crate::linearization::{G, P, PHI, PSI, Q, R, THETA, U, V, W, airframe, entry, jacobians, steady};
use crate::support::{EPS, NanAmax};

/// Half a unit in the last printed digit of a value printed with `digits` decimals.
fn printed(digits: i32) -> f64 {
    0.5 * 10f64.powi(-digits)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Ex 12.2.1: sin(Φ₀ + φ) ≈ sin Φ₀ + (cos Φ₀)φ, cos(Φ₀ + φ) ≈ cos Φ₀ − (sin Φ₀)φ (12.2.3–4),
    /// for Φ₀ = 0 sin φ ≈ φ, cos φ ≈ 1 (12.2.5–6), and the same linear terms from the sum formulas
    /// (12.2.7–8). In vectrix these are the bank-angle entries of gravity in the aircraft frame,
    /// g⃗|_AC = 𝓞_{AC/E}(0, 0, g) = g(0, sin Φ, cos Φ) for Ψ = Θ = 0 (`Euler321::o_ac_e`), the
    /// terms linearized in §12.3. Checked: the dual-number derivative of vectrix's g⃗|_AC at Φ₀
    /// is g(0, cos Φ₀, −sin Φ₀); the linearization misses vectrix's g⃗|_AC(Φ₀ + φ) by at most gφ²/2
    /// (Taylor's remainder, |f″| ≤ g); and the sum formulas are vectrix's composition
    /// 𝓞₁(Φ₀ + φ) = 𝓞₁(φ)𝓞₁(Φ₀) with the small-angle 𝓞₁(φ) ≈ I + φ𝓞₁′(0) (12.2.5–6), which
    /// gives the same linear term.
    #[test]
    fn example_12_2_1_small_angle_linearization(
        phi0 in -PI..PI, phi in prop_oneof![3 => -0.5..0.5f64, 1 => Just(0.0), 1 => Just(1e-8)],
    ) {
        let z = Dual64::from(0.0);
        let gravity = |bank: Dual64| Euler321::new(z, z, bank).o_ac_e() * nalgebra::Vector3::new(z, z, Dual64::from(G));
        let at = gravity(Dual64::new(phi0, 1.0));
        let exact = gravity(Dual64::from(phi0 + phi)).map(|x| x.re);
        // the entries are g sin Φ₀, g cos Φ₀ and their derivatives (12.2.3–4)
        prop_assert!((at[1].re - G * phi0.sin()).abs() <= 4.0 * EPS * G && (at[2].re - G * phi0.cos()).abs() <= 4.0 * EPS * G);
        prop_assert!((at[1].eps - G * phi0.cos()).abs() <= 4.0 * EPS * G);
        prop_assert!((at[2].eps + G * phi0.sin()).abs() <= 4.0 * EPS * G);
        prop_assert!(at[0].re == 0.0 && at[0].eps == 0.0);
        let linear = |k: usize| at[k].re + at[k].eps * phi;
        let bound = 0.5 * G * phi * phi + 8.0 * EPS * G;
        prop_assert!((exact[1] - linear(1)).abs() <= bound, "sin: {} vs {}", exact[1], linear(1));
        prop_assert!((exact[2] - linear(2)).abs() <= bound, "cos: {} vs {}", exact[2], linear(2));
        // (12.2.5–6): at Φ₀ = 0 the small-angle 𝓞₁(φ) ≈ I + φ𝓞₁′(0), 𝓞₁′(0) = −e₁^×
        let small = o1(Dual64::new(0.0, 1.0));
        let d_o1 = small.map(|x| x.eps);
        prop_assert!(small.map(|x| x.re) == nalgebra::Matrix3::identity());
        prop_assert!((d_o1 + nalgebra::Vector3::x().cross_matrix()).nan_amax() == 0.0);
        // (12.2.7–8): 𝓞₁(Φ₀ + φ) = 𝓞₁(φ)𝓞₁(Φ₀), and with the small-angle factor the same
        // linear terms as (12.2.3–4)
        let o_phi0 = o1(phi0);
        prop_assert!((o1(phi) * o_phi0 - o1(phi0 + phi)).nan_amax() <= 8.0 * EPS);
        let summed = (nalgebra::Matrix3::identity() + d_o1 * phi) * o_phi0 * nalgebra::Vector3::new(0.0, 0.0, G);
        prop_assert!((summed[1] - linear(1)).abs() <= 8.0 * EPS * G && (summed[2] - linear(2)).abs() <= 8.0 * EPS * G);
    }
}

/// P12.7.1: a vertical loop in 83 s with radius 4100 ft, α = β = Φ = 0, the pilot's head toward
/// the ground at the bottom. Notes [C]: V|_AC = (310.37, 0, 0) ft/s and, because k̂_AC (head to
/// feet) points to the centre there, ω|_AC = (0, −0.07570, 0) rad/s. Built frame-free: the centre
/// is at +R k̂_AC from the aircraft, v⃗ = V î_AC, and ω⃗ = (r⃗ × v⃗)/|r⃗|² for r⃗ the aircraft
/// relative to the centre (ω⃗ ⟂ r⃗); the flight is circular (ω⃗ ⟂ V⃗, §12.1).
#[test]
fn problem_12_7_1_vertical_loop() {
    let (period, radius) = (83.0, 4100.0);
    let speed = 2.0 * PI * radius / period;
    assert!((speed - 310.37).abs() <= printed(2));
    let ac = Frame::new();
    let v = ac.i() * speed;
    let r = ac.k() * (-radius);
    let omega = r.cross(&v) / r.norm_squared();
    let w = omega.resolve(&ac);
    assert!(w[0].abs() <= 4.0 * EPS && w[2].abs() <= 4.0 * EPS);
    assert!((w[1] - (-0.07570)).abs() <= printed(5));
    assert!((w[1] + 2.0 * PI / period).abs() <= 4.0 * EPS);
    // circular flight: V⃗ ⟂ ω⃗, and ω⃗ × r⃗ = v⃗ (r⃗ fixed in F_AC)
    assert!(v.dot(&omega).abs() <= 4.0 * EPS * speed);
    assert!((omega.cross(&r) - v).norm() <= 16.0 * EPS * speed);
}

/// P12.7.2: g = 9.8 m/s² at R_E = 6.3e6 m gives μ_E = gR_E² = 3.890e14 m³/s² (notes [C]);
/// vectrix's central gravity with that μ pulls 9.8 m/s² at R_E.
#[test]
fn problem_12_7_2_earth_gravitational_parameter() {
    let mu: f64 = 9.8 * 6.3e6 * 6.3e6;
    assert!((mu / 1e14 - 3.890).abs() <= printed(3));
    let earth = CentralGravity::new(mu).unwrap();
    let a = Frame::new();
    let f = earth.force(1.0, &(a.k() * 6.3e6)).unwrap();
    assert!((f.norm() - 9.8).abs() <= 8.0 * EPS * 9.8);
    assert!((f.unit().unwrap() + a.k()).norm() <= 4.0 * EPS);
}

/// P12.7.3: the Moon in a 28-day circular orbit, the same side toward the Earth: r⃗_{M/E} is fixed
/// in the Moon frame F_M turning at ω = 2π/28 d, so r⃗^{M•} = 0 and (steady flight) V⃗_M^{M•} = 0;
/// V⃗_M = ω⃗ × r⃗, the centripetal acceleration ω⃗ × V⃗_M has magnitude ω²r, and equating it to
/// μ_E/r² gives r = (μ_E/ω²)^{1/3} = 3.863e8 m (notes [C]). The acceleration comes from the
/// double transport theorem and equals vectrix's central gravity there.
#[test]
fn problem_12_7_3_distance_to_the_moon() {
    let mu = 9.8 * 6.3e6 * 6.3e6;
    let omega = 2.0 * PI / (28.0 * 86400.0);
    let r = (mu / (omega * omega)).cbrt();
    assert!((r / 1e8 - 3.863).abs() <= printed(3));
    let e = LabeledFrame::new("E", Frame::new());
    let motion = FrameMotion::from_body_rates(
        FrameLabel::new("M"),
        &e,
        &orientation_about(Axis::Z, 0.4),
        [0.0, 0.0, omega],
        [0.0; 3],
    )
    .unwrap();
    let m = motion.body().frame;
    let r_me = m.i() * r;
    let jet = VectorJet::fixed_in(motion.body().label, r_me).transported(&motion).unwrap();
    let v = jet.rate();
    assert!((v - e.frame.vector([0.0, 0.0, omega]).cross(&r_me)).norm() <= 4.0 * EPS * omega * r);
    let a_cent = e.frame.vector([0.0, 0.0, omega]).cross(&v);
    assert!((jet.second_rate() - a_cent).norm() <= 16.0 * EPS * omega * omega * r);
    let g = CentralGravity::new(mu).unwrap().force(1.0, &r_me).unwrap();
    assert!((jet.second_rate() - g).norm() <= 64.0 * EPS * g.norm());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// P12.7.4: derive (12.3.10) and (12.3.14): linearizing α = atan2(W, U) and
    /// β = atan2(V, √(U² + W²)) at (U₀, 0, W₀): δα = −(cos²α₀ W₀/U₀²)u + (cos²α₀/U₀)w
    /// = (−W₀u + U₀w)/(U₀² + W₀²) (12.3.12) and δβ = v/√(U₀² + W₀²); α does not depend on v nor β
    /// on u, w to first order.
    #[test]
    fn problem_12_7_4_linearized_alpha_and_beta(u0 in 1.0..300.0f64, alpha0 in prop_oneof![4 => -1.4..1.4f64, 1 => Just(0.0)]) {
        let w0 = u0 * alpha0.tan();
        let grad = |k: usize| {
            let uvw: [Dual64; 3] = std::array::from_fn(|i| Dual64::new([u0, 0.0, w0][i], f64::from(i == k)));
            let a = AeroAngles::from_body_velocity(uvw);
            (a.alpha.eps, a.beta.eps)
        };
        let ((au, bu), (av, bv), (aw, bw)) = (grad(0), grad(1), grad(2));
        let c2 = alpha0.cos() * alpha0.cos();
        let tol = 16.0 * EPS / u0;
        entry("∂α/∂u", au, -c2 * w0 / (u0 * u0), tol)?;
        entry("∂α/∂w", aw, c2 / u0, tol)?;
        entry("(12.3.12) ∂α/∂u", au, -w0 / (u0 * u0 + w0 * w0), tol)?;
        entry("∂α/∂v", av, 0.0, tol)?;
        entry("∂β/∂v", bv, 1.0 / u0.hypot(w0), tol)?;
        entry("∂β/∂u", bu, 0.0, tol)?;
        entry("∂β/∂w", bw, 0.0, tol)?;
    }

    /// P12.7.5: derive (12.3.35): linearizing ω|_AC = S(Φ, Θ)[Φ̇, Θ̇, Ψ̇] (10.9.8) at Φ₀ = 0, Θ₀ and
    /// zero rates gives [p, q, r] = [[1, 0, −sin Θ₀], [0, 1, 0], [0, 0, cos Θ₀]][φ̇, θ̇, ψ̇]; the
    /// angle perturbations drop out because they multiply zero rates.
    #[test]
    fn problem_12_7_5_linearized_body_rates(th0 in -1.5..1.5f64, psi0 in -PI..PI) {
        let want = [[1.0, 0.0, -th0.sin()], [0.0, 1.0, 0.0], [0.0, 0.0, th0.cos()]];
        for k in 0..6 {
            // variables (φ, θ, ψ, φ̇, θ̇, ψ̇)
            let v: [Dual64; 6] = std::array::from_fn(|i| Dual64::new([0.0, th0, psi0, 0.0, 0.0, 0.0][i], f64::from(i == k)));
            let e = Euler321::new(v[2], v[1], v[0]);
            let w = body_rates(&e, [v[3], v[4], v[5]]);
            for i in 0..3 {
                let want_ik = if k >= 3 { want[i][k - 3] } else { 0.0 };
                entry(&format!("∂ω{i}/∂v{k}"), w[i].eps, want_ik, 4.0 * EPS)?;
            }
        }
    }

    /// P12.7.6: derive the sway and plunge equations (12.3.51)–(12.3.52):
    /// mv̇ = −mU₀r + mW₀p + cos Θ₀ mgφ + f_Ay, mẇ = mU₀q − sin Θ₀ mgθ + f_Az + f_Tz.
    #[test]
    fn problem_12_7_6_sway_and_plunge_equations(u0 in 50.0..300.0f64, th0 in prop_oneof![4 => -1.2..1.2f64, 1 => Just(0.0)], ps0 in -PI..PI) {
        let frame = airframe();
        let (x0, u_0) = steady(&frame, u0, th0, ps0);
        let (a, b) = jacobians(&frame, &x0, &u_0);
        let (m, w0) = (frame.mass(), x0[W]);
        let tol = 64.0 * EPS * (u0 + w0.abs() + G);
        for k in 0..12 {
            let v_want = match k {
                R => -u0,
                P => w0,
                PHI => th0.cos() * G,
                _ => 0.0,
            };
            let w_want = match k {
                Q => u0,
                THETA => -th0.sin() * G,
                _ => 0.0,
            };
            entry(&format!("A[V,{k}]"), a[(V, k)], v_want, tol)?;
            entry(&format!("A[W,{k}]"), a[(W, k)], w_want, tol)?;
        }
        for j in 0..11 {
            entry(&format!("mB[V,{j}]"), m * b[(V, j)], if j == 1 { 1.0 } else { 0.0 }, 64.0 * EPS)?;
            entry(&format!("mB[W,{j}]"), m * b[(W, j)], if j == 2 || j == 7 { 1.0 } else { 0.0 }, 64.0 * EPS)?;
        }
    }

    /// P12.7.7: derive (12.3.54)–(12.3.56): J_xxṗ − J_xzṙ = l_A + l_T, J_yyq̇ = m_A + m_T,
    /// J_zzṙ − J_xzṗ = n_A + n_T — the gyroscopic terms of (11.3.16–18) are products of rates
    /// and vanish to first order at P₀ = Q₀ = R₀ = 0.
    #[test]
    fn problem_12_7_7_roll_pitch_yaw_equations(u0 in 50.0..300.0f64, th0 in -1.2..1.2f64) {
        let frame = airframe();
        let (jxx, jyy, jzz, jxz) = frame.inertia();
        let (x0, u_0) = steady(&frame, u0, th0, 0.0);
        let (a, b) = jacobians(&frame, &x0, &u_0);
        for k in 0..12 {
            for row in [P, Q, R] {
                entry(&format!("A[{row},{k}]"), a[(row, k)], 0.0, 64.0 * EPS)?;
            }
        }
        // J [ṗ q̇ ṙ] per unit of each moment input
        for j in 0..11 {
            let (pd, qd, rd) = (b[(P, j)], b[(Q, j)], b[(R, j)]);
            let want = |col: usize| f64::from(j == col || j == col + 5);
            entry("roll", jxx * pd - jxz * rd, want(3), 64.0 * EPS)?;
            entry("pitch", jyy * qd, want(4), 64.0 * EPS)?;
            entry("yaw", jzz * rd - jxz * pd, want(5), 64.0 * EPS)?;
        }
    }

    /// P12.7.8: linearize Φ̇ = P + Q sin Φ tan Θ + R cos Φ tan Θ near steady (P₀, Q₀, R₀, Θ₀, Φ₀) (not
    /// necessarily zero): δΦ̇ = p + sΦ₀tΘ₀q + cΦ₀tΘ₀r + (Q₀cΦ₀ − R₀sΦ₀)tΘ₀φ + (Q₀sΦ₀ + R₀cΦ₀)sec²Θ₀θ
    /// (notes [C]), against the dual-number Jacobian of vectrix's (10.9.9).
    #[test]
    fn problem_12_7_8_linearized_roll_rate_kinematics(
        pqr in [-2.0..2.0f64, -2.0..2.0f64, -2.0..2.0f64], th0 in prop_oneof![4 => -1.4..1.4f64, 1 => Just(0.0)],
        phi0 in -PI..PI,
    ) {
        let (sp, cp, t, sec2) = (phi0.sin(), phi0.cos(), th0.tan(), 1.0 / (th0.cos() * th0.cos()));
        let [p0, q0, r0] = pqr;
        let want = [1.0, sp * t, cp * t, (q0 * cp - r0 * sp) * t, (q0 * sp + r0 * cp) * sec2];
        for k in 0..5 {
            // variables (p, q, r, φ, θ)
            let v: [Dual64; 5] = std::array::from_fn(|i| Dual64::new([p0, q0, r0, phi0, th0][i], f64::from(i == k)));
            let e = Euler321::new(Dual64::from(0.3), v[4], v[3]);
            let rates = euler_rates(&e, [v[0], v[1], v[2]]).unwrap();
            entry(&format!("∂Φ̇/∂v{k}"), rates[0].eps, want[k], 16.0 * EPS * sec2 * 10.0)?;
        }
    }
}

/// The steady point used above really is steady: ẋ = 0 except for the position rates, for
/// climbing attitudes too (Θ₀ = α₀, γ₀ = 0, (12.3.1)–(12.3.8)).
#[test]
fn eq_12_3_7_steady_point_is_steady() {
    let frame = airframe();
    for (u0, th0, ps0) in [(150.0, 0.1, 0.4), (90.0, -0.4, FRAC_PI_2), (220.0, 0.0, -3.0)] {
        let (x0, u_0) = steady(&frame, u0, th0, ps0);
        let f = crate::linearization::xdot(&frame, &x0, &u_0);
        for k in [U, V, W, PHI, THETA, PSI, P, Q, R] {
            assert!(f[k].abs() <= 64.0 * EPS * G, "ẋ[{k}] = {}", f[k]);
        }
        // horizontal: Ż₀ = 0 (12.3.18) with W₀ = U₀ tan Θ₀
        assert!(f[2].abs() <= 64.0 * EPS * u0);
    }
}
