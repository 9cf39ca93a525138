//! Sections of chapter 11 checked frame-free: the aerodynamic force in the wind, stability and
//! aircraft frames (§11.1, with (11.1.18) corrected), the translational momentum equations
//! (§11.2) from Newton's law with physical vectors, and the summary (§11.4, with the rate order
//! of (11.4.2) corrected).

use std::f64::consts::{FRAC_PI_2, PI};

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::nalgebra::Vector3;
use vectrix::prelude::*;

use crate::support::{EPS, NanAmax, nan_max};

fn any_angle() -> impl Strategy<Value = f64> {
    prop_oneof![4 => -PI..PI, 1 => prop::sample::select(vec![0.0, FRAC_PI_2, -FRAC_PI_2, PI])]
}

fn pitch() -> impl Strategy<Value = f64> {
    prop_oneof![4 => -1.56..1.56f64, 1 => prop::sample::select(vec![0.0, 1.5607, -1.5607])]
}

fn speed() -> impl Strategy<Value = f64> {
    prop_oneof![4 => -300.0..300.0f64, 1 => Just(0.0)]
}

fn airframe() -> Airframe {
    Airframe::new(5000.0, 9000.0, 25000.0, 30000.0, 1200.0).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// §11.1: F⃗_A = −Dî_W − Eĵ_W − Lk̂_W (11.1.5). L = −F̄_Az (11.1.12); D² + E² = F̄_Ax² + F̄_Ay²
    /// (11.1.14); F_Ay = F̄_Ay (11.1.16); and F_Ax² + F_Az² = F̄_Ax² + F̄_Az² — the book prints
    /// (11.1.18) with bars on both sides, a tautology (erratum): the aircraft-frame components
    /// belong on the left. With E = 0, D = √(F̄_Ax² + F̄_Ay²) (11.1.22).
    #[test]
    fn eq_11_1_18_force_components_in_s_and_ac_corrected(
        alpha in any_angle(), beta in -FRAC_PI_2..FRAC_PI_2, d in 0.0..1e4f64, e in -1e3..1e3f64, l in -1e4..1e5f64,
    ) {
        let ac = Frame::new();
        let s = Frame::from_orientation_rel(&ac, &o_s_ac(alpha), 1e-12).unwrap();
        let w = Frame::from_orientation_rel(&s, &o_w_s(beta), 1e-12).unwrap();
        let f = -(w.i() * d) - w.j() * e - w.k() * l;
        let (f_s, f_ac) = (f.resolve(&s), f.resolve(&ac));
        let big = (d * d + e * e + l * l).sqrt();
        let tol = 64.0 * EPS * big;
        prop_assert!((f_s[2] + l).abs() <= tol);
        prop_assert!((f_s[0].hypot(f_s[1]) - d.hypot(e)).abs() <= tol);
        prop_assert!((f_ac[1] - f_s[1]).abs() <= tol);
        prop_assert!((f_ac[0].hypot(f_ac[2]) - f_s[0].hypot(f_s[2])).abs() <= tol);
        // (11.1.21)
        let (sa, ca, sb, cb) = (alpha.sin(), alpha.cos(), beta.sin(), beta.cos());
        let want = Vector3::new(-ca * cb * d + ca * sb * e + sa * l, -sb * d - cb * e, -sa * cb * d + sa * sb * e - ca * l);
        prop_assert!((f_ac - want).nan_amax() <= tol);
        // (11.1.22) when E = 0
        let f0 = -(w.i() * d) - w.k() * l;
        let f0_s = f0.resolve(&s);
        prop_assert!((f0_s[0].hypot(f0_s[1]) - d).abs() <= 64.0 * EPS * d.hypot(l));
    }

    /// §11.2, (11.2.4)–(11.2.15): m(V⃗^{AC•} + ω⃗ × V⃗) = m g⃗ + F⃗_A + F⃗_T, built from physical
    /// vectors — g⃗ = g k̂_E, F⃗_A = −Dî_W − Eĵ_W − Lk̂_W from the wind frame, the thrust tilted Φ_T
    /// up from î_AC (11.2.11) — and resolved in F_AC, equals the equations of motion's
    /// [U̇, V̇, Ẇ] (with side drag E, which (11.2.16–18) then drop).
    #[test]
    fn section_11_2_translational_equations_from_newton(
        psi in any_angle(), theta in pitch(), phi in any_angle(),
        uvw in [speed(), speed(), speed()], pqr in [-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64],
        d in 0.0..2e4f64, e in -2e3..2e3f64, l in -1e4..8e4f64, ft in 0.0..3e4f64, phi_t in -0.2..0.2f64,
    ) {
        prop_assume!(uvw[0] * uvw[0] + uvw[2] * uvw[2] > 0.0);
        let frame = airframe();
        let g = 9.8;
        let euler = Euler321::new(psi, theta, phi);
        let x = AircraftState { position: [0.0; 3], velocity: uvw, attitude: euler, omega: pqr };
        let fm = ForcesMoments { drag: d, side_drag: e, lift: l, thrust: ft, thrust_angle: phi_t, ..Default::default() };
        let got = state_derivative(&frame, g, &x, &fm).unwrap();
        let earth = Frame::new();
        let ac = Frame::from_orientation_rel(&earth, &euler.o_ac_e(), 1e-12).unwrap();
        let a = x.aero_angles();
        let s = Frame::from_orientation_rel(&ac, &o_s_ac(a.alpha), 1e-12).unwrap();
        let w = Frame::from_orientation_rel(&s, &o_w_s(a.beta), 1e-12).unwrap();
        let f_a = -(w.i() * d) - w.j() * e - w.k() * l;
        let f_t = (ac.i() * phi_t.cos() - ac.k() * phi_t.sin()) * ft;
        let m = frame.mass();
        let vel = ac.vector(uvw);
        let omega = ac.vector(pqr);
        let v_dot = (earth.k() * g + (f_a + f_t) / m - omega.cross(&vel)).resolve(&ac);
        let tol = 64.0 * EPS * (g + (d + e.abs() + l.abs() + ft) / m + omega.norm() * vel.norm());
        prop_assert!((Vector3::from(got.velocity) - v_dot).nan_amax() <= tol, "{:?} vs {v_dot}", got.velocity);
    }

    /// §11.4 summary: (11.4.1) [Ẋ, Ẏ, Ż] = 𝓞_{E/AC}[U, V, W]; (11.4.2) [P, Q, R] = S(Φ, Θ)
    /// [Φ̇, Θ̇, Ψ̇] — the book orders the rates [Ψ̇, Θ̇, Φ̇] there (erratum, notes [T]; (10.9.8)
    /// is right); (11.4.6)–(11.4.8) J_xxṖ + (J_zz − J_yy)QR − J_xz(Ṙ + PQ) = L_AC,
    /// J_yyQ̇ + (J_xx − J_zz)PR + J_xz(P² − R²) = M_AC, J_zzṘ + (J_yy − J_xx)PQ + J_xz(QR − Ṗ) = N_AC.
    #[test]
    fn section_11_4_summary_of_the_equations_of_motion(
        psi in any_angle(), theta in pitch(), phi in any_angle(),
        uvw in [speed(), speed(), speed()], pqr in [-2.0..2.0f64, -2.0..2.0f64, -2.0..2.0f64],
        lmn in [-1e4..1e4f64, -1e4..1e4f64, -1e4..1e4f64],
    ) {
        let frame = airframe();
        let (jxx, jyy, jzz, jxz) = frame.inertia();
        let euler = Euler321::new(psi, theta, phi);
        let x = AircraftState { position: [0.0; 3], velocity: uvw, attitude: euler, omega: pqr };
        let fm = ForcesMoments { roll: lmn[0], pitch: lmn[1], yaw: lmn[2], ..Default::default() };
        let f = state_derivative(&frame, 9.8, &x, &fm).unwrap();
        let r_dot = euler.o_ac_e().transpose() * Vector3::from(uvw);
        let vmax = uvw.iter().fold(0.0f64, |m, v| nan_max(m, v.abs()));
        prop_assert!((Vector3::from(f.position) - r_dot).nan_amax() <= 16.0 * EPS * vmax);
        let rates = [f.attitude.phi, f.attitude.theta, f.attitude.psi];
        let pqr_back = body_rates(&euler, rates);
        // the rates carry 1/cos Θ ≤ 100
        let wtol = 64.0 * EPS * 2.0 * 100.0;
        for k in 0..3 {
            prop_assert!((pqr_back[k] - pqr[k]).abs() <= wtol);
        }
        let [p, q, r] = pqr;
        let [pd, qd, rd] = f.omega;
        let res = [
            jxx * pd + (jzz - jyy) * q * r - jxz * (rd + p * q) - lmn[0],
            jyy * qd + (jxx - jzz) * p * r + jxz * (p * p - r * r) - lmn[1],
            jzz * rd + (jyy - jxx) * p * q + jxz * (q * r - pd) - lmn[2],
        ];
        let scale = 1e4 + jzz * 4.0 * 8.0;
        for v in res {
            prop_assert!(v.abs() <= 64.0 * EPS * scale, "residual {v}");
        }
    }
}

/// (11.4.2) as printed, with the rates in the order [Ψ̇, Θ̇, Φ̇], gives the wrong body rates
/// unless Φ̇ = Ψ̇: one attitude where it fails.
#[test]
fn eq_11_4_2_printed_rate_order_is_an_erratum() {
    let euler: Euler321 = Euler321::new(0.4, 0.3, -0.5);
    let rates: [f64; 3] = [0.2, -0.1, 0.7]; // [Φ̇, Θ̇, Ψ̇]
    let right = body_rates(&euler, rates);
    let printed = body_rates(&euler, [rates[2], rates[1], rates[0]]);
    assert!((right[0] - printed[0]).abs() > 0.1, "{right:?} vs {printed:?}");
}
