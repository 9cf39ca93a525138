//! §12.3–12.6: the aircraft equations linearized at straight, horizontal, wings-level,
//! zero-sideslip steady flight. The reference is the book's linear equations; vectrix's side is
//! the exact (dual-number) Jacobian of its nonlinear 12-state model (11.5.1–16) with the applied
//! forces and moments of (12.6.2) as inputs. Errata checked in corrected form: (12.3.20) (the v
//! coefficient is −sin Ψ₀), (12.3.53) (U₀ missing on the left), (12.4.11) (ẏ, not ψ̇), (12.6.4)
//! (rows p, q, r of B carry J⁻¹, printed as zeros).

#![allow(clippy::needless_range_loop)] // matrix entries read as the book's A(i, j)

use std::f64::consts::FRAC_PI_2;

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::nalgebra::{DMatrix, Vector3};
use vectrix::num_dual::Dual64;
use vectrix::prelude::*;

use crate::support::EPS;

/// Indices of the state (11.5.1)/(12.6.1): x = [X Y Z U V W Φ Θ Ψ P Q R].
pub const X: usize = 0;
pub const Y: usize = 1;
pub const Z: usize = 2;
pub const U: usize = 3;
pub const V: usize = 4;
pub const W: usize = 5;
pub const PHI: usize = 6;
pub const THETA: usize = 7;
pub const PSI: usize = 8;
pub const P: usize = 9;
pub const Q: usize = 10;
pub const R: usize = 11;

/// Gravity used throughout (m/s²).
pub const G: f64 = 9.8;

/// An airframe with a product of inertia, so that J⁻¹ couples roll and yaw.
pub fn airframe() -> Airframe {
    Airframe::new(5000.0, 9000.0, 25000.0, 30000.0, 1200.0).unwrap()
}

/// ẋ = f(x, u) of (11.5.3–14) with the inputs of (12.6.2),
/// u = [f_Ax f_Ay f_Az l_A m_A n_A f_Tx f_Tz l_T m_T n_T]: body-axis forces are handed to the
/// model as drag, side drag and lift, (−D, −E, −L) = F|_W = 𝓞_{W/AC}F|_AC (11.1.6).
pub fn xdot<T: Scalar>(frame: &Airframe, x: &[T; 12], u: &[T; 11]) -> [T; 12] {
    let state = AircraftState::from_array(*x);
    let a = state.aero_angles();
    let f_w = o_w_ac(a.alpha, a.beta) * Vector3::new(u[0] + u[6], u[1], u[2] + u[7]);
    let fm = ForcesMoments {
        drag: -f_w[0],
        side_drag: -f_w[1],
        lift: -f_w[2],
        thrust: T::zero(),
        thrust_angle: T::zero(),
        roll: u[3] + u[8],
        pitch: u[4] + u[9],
        yaw: u[5] + u[10],
    };
    state_derivative(frame, G, &state, &fm).expect("away from gimbal lock").to_array()
}

/// The steady point of (12.3.1)–(12.3.8): Ψ₀, Θ₀ = α₀, Φ₀ = β₀ = 0, V₀ = 0,
/// W₀ = U₀ tan α₀, P₀ = Q₀ = R₀ = 0, with the forces that balance gravity (12.3.47):
/// F₀|_AC = −m g|_AC, split as aerodynamic force (no thrust perturbation is steady).
pub fn steady(frame: &Airframe, u0: f64, theta0: f64, psi0: f64) -> ([f64; 12], [f64; 11]) {
    let mut x = [0.0; 12];
    x[U] = u0;
    x[W] = u0 * theta0.tan();
    x[THETA] = theta0;
    x[PSI] = psi0;
    let m = frame.mass();
    let mut u = [0.0; 11];
    u[0] = m * G * theta0.sin();
    u[2] = -m * G * theta0.cos();
    (x, u)
}

/// A = ∂f/∂x and B = ∂f/∂u at (x₀, u₀), one dual number per column (exact to rounding).
pub fn jacobians(frame: &Airframe, x0: &[f64; 12], u0: &[f64; 11]) -> (DMatrix<f64>, DMatrix<f64>) {
    let mut a = DMatrix::zeros(12, 12);
    let mut b = DMatrix::zeros(12, 11);
    for k in 0..23 {
        let x: [Dual64; 12] = std::array::from_fn(|i| Dual64::new(x0[i], f64::from(i == k)));
        let u: [Dual64; 11] = std::array::from_fn(|j| Dual64::new(u0[j], f64::from(j + 12 == k)));
        let f = xdot(frame, &x, &u);
        for i in 0..12 {
            if k < 12 {
                a[(i, k)] = f[i].eps;
            } else {
                b[(i, k - 12)] = f[i].eps;
            }
        }
    }
    (a, b)
}

/// Asserts |got − want| ≤ tol with a message naming the entry.
#[track_caller]
pub fn entry(what: &str, got: f64, want: f64, tol: f64) -> Result<(), TestCaseError> {
    prop_assert!((got - want).abs() <= tol, "{what}: got {got:e}, want {want:e} (tol {tol:e})");
    Ok(())
}

/// A trim pitch Θ₀ = α₀ in (−1.2, 1.2) with the hard value 0.
fn theta0() -> impl Strategy<Value = f64> {
    prop_oneof![4 => -1.2..1.2f64, 1 => Just(0.0)]
}

/// A heading Ψ₀, with the hard values 0, ±π/2 and π.
fn psi0() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -std::f64::consts::PI..std::f64::consts::PI,
        1 => prop::sample::select(vec![0.0, FRAC_PI_2, -FRAC_PI_2, std::f64::consts::PI]),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// (12.3.20)–(12.3.23) corrected:
    /// ẋ = cΘ₀cΨ₀u − sΨ₀v + sΘ₀cΨ₀w + W₀sΨ₀φ + (W₀cΘ₀ − U₀sΘ₀)cΨ₀θ − (U₀cΘ₀ + W₀sΘ₀)sΨ₀ψ,
    /// ẏ = cΘ₀sΨ₀u + cΨ₀v + sΘ₀sΨ₀w − W₀cΨ₀φ + (W₀cΘ₀ − U₀sΘ₀)sΨ₀θ + (U₀cΘ₀ + W₀sΘ₀)cΨ₀ψ,
    /// ż = −sΘ₀u + cΘ₀w − (U₀cΘ₀ + W₀sΘ₀)θ, ḣ = −ż. The book prints the v coefficient of ẋ as
    /// −sin Θ₀ (erratum, notes [T]); its own (12.3.24), −U₀sΨ₀/cΘ₀ δβ, confirms −sin Ψ₀. With
    /// (12.3.13) and (12.3.15) the same rows give (12.3.24)–(12.3.27) in δα and δβ.
    #[test]
    fn eq_12_3_20_translational_kinematics_corrected(u0 in 50.0..300.0f64, th0 in theta0(), ps0 in psi0()) {
        let frame = airframe();
        let (x0, u_0) = steady(&frame, u0, th0, ps0);
        let (a, _) = jacobians(&frame, &x0, &u_0);
        let w0 = x0[W];
        let (st, ct, sp, cp) = (th0.sin(), th0.cos(), ps0.sin(), ps0.cos());
        let tol = 64.0 * EPS * (u0 + w0.abs());
        let xrow = [(U, ct * cp), (V, -sp), (W, st * cp), (PHI, w0 * sp), (THETA, (w0 * ct - u0 * st) * cp), (PSI, -(u0 * ct + w0 * st) * sp)];
        let yrow = [(U, ct * sp), (V, cp), (W, st * sp), (PHI, -w0 * cp), (THETA, (w0 * ct - u0 * st) * sp), (PSI, (u0 * ct + w0 * st) * cp)];
        let zrow = [(U, -st), (V, 0.0), (W, ct), (PHI, 0.0), (THETA, -(u0 * ct + w0 * st)), (PSI, 0.0)];
        for (row, coeffs) in [(X, xrow), (Y, yrow), (Z, zrow)] {
            for (col, want) in coeffs {
                entry(&format!("A[{row},{col}]"), a[(row, col)], want, tol)?;
            }
        }
        // the printed −sin Θ₀ is wrong wherever sin Ψ₀ ≠ sin Θ₀
        if (sp - st).abs() > 1e-3 {
            prop_assert!((a[(X, V)] + st).abs() > 1e-4);
        }
        // (12.3.24)–(12.3.27): columns for u, δα, δβ after w = (W₀/U₀)u + ((U₀² + W₀²)/U₀)δα,
        // v = √(U₀² + W₀²)δβ
        let (k_alpha, k_beta) = ((u0 * u0 + w0 * w0) / u0, u0.hypot(w0));
        let u_col = |r: usize| a[(r, U)] + a[(r, W)] * w0 / u0;
        entry("ẋ/u", u_col(X), cp / ct, tol)?;
        entry("ẋ/δα", a[(X, W)] * k_alpha, w0 * cp / ct, tol)?;
        entry("ẋ/δβ", a[(X, V)] * k_beta, -u0 * sp / ct, tol)?;
        entry("ẏ/u", u_col(Y), sp / ct, tol)?;
        entry("ẏ/δα", a[(Y, W)] * k_alpha, w0 * sp / ct, tol)?;
        entry("ẏ/δβ", a[(Y, V)] * k_beta, u0 * cp / ct, tol)?;
        entry("ż/u", u_col(Z), 0.0, tol)?;
        entry("ż/δα", a[(Z, W)] * k_alpha, u0 / ct, tol * 10.0)?;
    }

    /// (12.3.28)–(12.3.32): perturbing (10.8.5) at the steady point gives θ = δα + δγ,
    /// ψ = (−cΘ₀δβ + sΘ₀δμ + cΘ₀δη)/cΘ₀, φ = δμ/cΘ₀ (notes [C]): δη, δγ, δμ are the dual parts of
    /// the (η, γ, μ) vectrix extracts from (10.8.4) along random perturbations of Ψ, Θ, Φ, α, β.
    #[test]
    fn eq_12_3_30_linearized_angle_relations(
        th0 in theta0(), ps0 in -3.0..3.0f64, d in [-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64],
    ) {
        // perturbation direction (ψ, θ, φ, δα, δβ)
        let euler = Euler321::new(Dual64::new(ps0, d[0]), Dual64::new(th0, d[1]), Dual64::new(0.0, d[2]));
        let fp = FlightPathAngles::from_attitude(&euler, Dual64::new(th0, d[3]), Dual64::new(0.0, d[4]));
        let (d_eta, d_gamma, d_mu) = (fp.eta.eps, fp.gamma.eps, fp.mu.eps);
        let (st, ct) = th0.sin_cos();
        let tol = 64.0 * EPS / ct;
        entry("θ", d[1], d[3] + d_gamma, tol)?;
        entry("ψ", d[0], (-ct * d[4] + st * d_mu + ct * d_eta) / ct, tol)?;
        entry("φ", d[2], d_mu / ct, tol)?;
    }

    /// (12.3.39)–(12.3.42): φ̇ = p + tan Θ₀ r, θ̇ = q, ψ̇ = sec Θ₀ r, and the Euler-angle rates do not
    /// depend on the attitude to first order (P₀ = Q₀ = R₀ = 0).
    #[test]
    fn eq_12_3_39_linearized_euler_angle_rates(u0 in 50.0..300.0f64, th0 in theta0(), ps0 in psi0()) {
        let frame = airframe();
        let (x0, u_0) = steady(&frame, u0, th0, ps0);
        let (a, _) = jacobians(&frame, &x0, &u_0);
        let (st, ct) = th0.sin_cos();
        let tol = 64.0 * EPS / ct;
        let want = [[1.0, 0.0, st / ct], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0 / ct]];
        for (i, row) in [PHI, THETA, PSI].into_iter().enumerate() {
            for (j, col) in [P, Q, R].into_iter().enumerate() {
                entry(&format!("A[{row},{col}]"), a[(row, col)], want[i][j], tol)?;
            }
            for col in [PHI, THETA, PSI, U, V, W] {
                entry(&format!("A[{row},{col}]"), a[(row, col)], 0.0, tol)?;
            }
        }
    }

    /// (12.3.45)–(12.3.50): the range-rate equation mu̇ = −mW₀q − cos Θ₀ mgθ + f_Ax + f_Tx.
    #[test]
    fn eq_12_3_50_range_rate_equation(u0 in 50.0..300.0f64, th0 in theta0(), ps0 in psi0()) {
        let frame = airframe();
        let (x0, u_0) = steady(&frame, u0, th0, ps0);
        let (a, b) = jacobians(&frame, &x0, &u_0);
        let m = frame.mass();
        let tol = 64.0 * EPS * (u0 + x0[W].abs() + G);
        for k in 0..12 {
            let want = match k {
                Q => -x0[W],
                THETA => -th0.cos() * G,
                _ => 0.0,
            };
            entry(&format!("A[U,{k}]"), a[(U, k)], want, tol)?;
        }
        for j in 0..11 {
            let want = if j == 0 || j == 6 { 1.0 / m } else { 0.0 };
            entry(&format!("B[U,{j}]"), b[(U, j)], want, 64.0 * EPS / m)?;
        }
    }

    /// (12.3.53) corrected: mU₀ sec²α₀ δα̇ = m(W₀²/U₀ + U₀)q + (cos Θ₀ W₀/U₀ − sin Θ₀)mgθ + f_Az + f_Tz
    /// − (W₀/U₀)(f_Ax + f_Tx). The book omits U₀ on the left (erratum, notes [T]): differentiating
    /// (12.3.13), w = (W₀/U₀)u + U₀ sec²α₀ δα, gives U₀ sec²α₀ δα̇ = ẇ − (W₀/U₀)u̇. Here δα̇ is the
    /// derivative of α = atan2(W, U) (a dual number) along the linearized u̇, ẇ.
    #[test]
    fn eq_12_3_53_angle_of_attack_rate_corrected(u0 in 50.0..300.0f64, th0 in theta0(), ps0 in psi0()) {
        let frame = airframe();
        let (x0, u_0) = steady(&frame, u0, th0, ps0);
        let (a, b) = jacobians(&frame, &x0, &u_0);
        let w0 = x0[W];
        // ∂α/∂U, ∂α/∂W at (U₀, W₀)
        let da_du = AeroAngles::from_body_velocity([Dual64::new(u0, 1.0), Dual64::from(0.0), Dual64::from(w0)]).alpha.eps;
        let da_dw = AeroAngles::from_body_velocity([Dual64::from(u0), Dual64::from(0.0), Dual64::new(w0, 1.0)]).alpha.eps;
        let m = frame.mass();
        let sec2 = 1.0 + th0.tan() * th0.tan();
        let lhs = m * u0 * sec2;
        let (st, ct) = th0.sin_cos();
        let tol = 64.0 * EPS * sec2 * (u0 + w0.abs() + G);
        // rows: δα̇ = (∂α/∂U) u̇ + (∂α/∂W) ẇ
        for k in 0..12 {
            let got = lhs * (da_du * a[(U, k)] + da_dw * a[(W, k)]);
            let want = match k {
                Q => m * (w0 * w0 / u0 + u0),
                THETA => (ct * w0 / u0 - st) * m * G,
                _ => 0.0,
            };
            entry(&format!("δα̇/x{k}"), got, want, tol * m)?;
        }
        for j in 0..11 {
            let got = lhs * (da_du * b[(U, j)] + da_dw * b[(W, j)]);
            let want = match j {
                2 | 7 => 1.0,
                0 | 6 => -w0 / u0,
                _ => 0.0,
            };
            entry(&format!("δα̇/u{j}"), got, want, tol)?;
        }
        // the printed left side m sec²α₀ δα̇ is off by the factor U₀
        let printed = m * sec2 * (da_du * b[(U, 2)] + da_dw * b[(W, 2)]);
        prop_assert!((printed - 1.0).abs() > 0.5);
    }
}

/// §12.4 with F_AC chosen so that î_AC = V̂₀ (α₀ = Θ₀ = W₀ = 0): ẋ = u (12.4.5), ẏ = v + U₀ψ
/// (12.4.6), ż = U₀δα − U₀θ = −U₀δγ (12.4.7), ḣ = U₀(θ − δα) (12.4.8), δα = w/U₀ (12.4.9),
/// δβ = v/U₀ (12.4.10), hence ẏ = U₀(δβ + ψ) = U₀δη — the book prints the left side of
/// (12.4.11) as ψ̇ (erratum, notes [T]; ψ̇ = r by (12.4.17)). φ̇ = p, θ̇ = q, ψ̇ = r
/// (12.4.15–17); mu̇ = −mgθ + f_Ax + f_Tx, mU₀δβ̇ = −mU₀r + mgφ + f_Ay, mU₀δα̇ = mU₀q + f_Az +
/// f_Tz (12.4.18–22).
#[test]
fn section_12_4_stability_axes_and_erratum_12_4_11() {
    let frame = airframe();
    let m = frame.mass();
    for (u0, ps0) in [(120.0, 0.0), (250.0, 0.7), (80.0, -2.9)] {
        let (x0, u_0) = steady(&frame, u0, 0.0, ps0);
        let (a, b) = jacobians(&frame, &x0, &u_0);
        let tol = 64.0 * EPS * (u0 + G);
        let chk = |what: &str, got: f64, want: f64| {
            assert!((got - want).abs() <= tol, "{what}: {got} vs {want}");
        };
        // position rates in the heading frame of the trim (rotate by −Ψ₀: Ψ₀ is arbitrary)
        let (sp, cp) = ps0.sin_cos();
        let along = |k: usize| cp * a[(X, k)] + sp * a[(Y, k)];
        let across = |k: usize| -sp * a[(X, k)] + cp * a[(Y, k)];
        chk("ẋ/u", along(U), 1.0);
        for k in [V, W, PHI, THETA, PSI] {
            chk("ẋ", along(k), 0.0);
        }
        chk("ẏ/v", across(V), 1.0);
        chk("ẏ/ψ", across(PSI), u0);
        // ẏ = U₀(δβ + ψ): with v = U₀δβ the v column times U₀ is U₀ per unit δβ
        chk("ẏ/δβ", across(V) * u0, u0);
        chk("ż/δα", a[(Z, W)] * u0, u0);
        chk("ż/θ", a[(Z, THETA)], -u0);
        chk("ḣ/θ", -a[(Z, THETA)], u0);
        // (12.4.11) printed: ψ̇ = U₀(δβ + ψ); but ψ̇ has no v or ψ term
        assert!((a[(PSI, V)] * u0 - u0).abs() > 1.0 && a[(PSI, PSI)].abs() <= tol);
        chk("ψ̇/r", a[(PSI, R)], 1.0);
        chk("φ̇/p", a[(PHI, P)], 1.0);
        chk("θ̇/q", a[(THETA, Q)], 1.0);
        // the momentum equations divided by m (inputs scaled by m)
        chk("u̇/θ", a[(U, THETA)], -G);
        chk("mu̇/f_Ax", m * b[(U, 0)], 1.0);
        // δβ̇ = v̇/U₀, δα̇ = ẇ/U₀: U₀δβ̇ = −U₀r + gφ + f_Ay/m, U₀δα̇ = U₀q + (f_Az + f_Tz)/m
        chk("U₀δβ̇/r", a[(V, R)], -u0);
        chk("U₀δβ̇/φ", a[(V, PHI)], G);
        chk("mU₀δβ̇/f_Ay", m * b[(V, 1)], 1.0);
        chk("U₀δα̇/q", a[(W, Q)], u0);
        chk("mU₀δα̇/f_Tz", m * b[(W, 7)], 1.0);
        // (12.4.13): ψ = −δβ + δη, so δη = ψ + δβ: the heading of the velocity
        let euler = Euler321::new(Dual64::new(ps0, 0.3), Dual64::from(0.0), Dual64::from(0.0));
        let fp = FlightPathAngles::from_attitude(&euler, Dual64::from(0.0), Dual64::new(0.0, -0.2));
        assert!((fp.eta.eps - (0.3 - 0.2)).abs() <= 16.0 * EPS);
    }
}

/// §12.5 (Ψ₀ = 0): the summary (12.5.1)–(12.5.12), assembled as the state matrix A of the
/// state-space model (12.6.1) — which §12.6 leaves out — equals the Jacobian of the nonlinear
/// model. ((12.5.7) prints mü for mu̇.)
#[test]
fn section_12_5_summary_is_the_jacobian_at_psi0_zero() {
    let frame = airframe();
    for (u0, th0) in [(150.0, 0.12), (90.0, -0.3), (220.0, 0.0)] {
        let (x0, u_0) = steady(&frame, u0, th0, 0.0);
        let (a, _) = jacobians(&frame, &x0, &u_0);
        let w0 = x0[W];
        let (st, ct) = th0.sin_cos();
        let mut a_book = DMatrix::<f64>::zeros(12, 12);
        let mut set = |r: usize, c: usize, v: f64| a_book[(r, c)] = v;
        // (12.5.1)–(12.5.3)
        set(X, U, ct);
        set(X, W, st);
        set(X, THETA, w0 * ct - u0 * st);
        set(Y, V, 1.0);
        set(Y, PHI, -w0);
        set(Y, PSI, u0 * ct + w0 * st);
        set(Z, U, -st);
        set(Z, W, ct);
        set(Z, THETA, -(u0 * ct + w0 * st));
        // (12.5.7)–(12.5.9) divided by m ((12.5.7) prints mü for mu̇)
        set(U, Q, -w0);
        set(U, THETA, -ct * G);
        set(V, R, -u0);
        set(V, P, w0);
        set(V, PHI, ct * G);
        set(W, Q, u0);
        set(W, THETA, -st * G);
        // (12.5.4)–(12.5.6) inverted, (12.3.39)
        set(PHI, P, 1.0);
        set(PHI, R, st / ct);
        set(THETA, Q, 1.0);
        set(PSI, R, 1.0 / ct);
        let tol = 64.0 * EPS * (u0 + w0.abs() + G) / ct;
        for i in 0..12 {
            for j in 0..12 {
                assert!(
                    (a[(i, j)] - a_book[(i, j)]).abs() <= tol,
                    "A[{i},{j}] = {} vs {}",
                    a[(i, j)],
                    a_book[(i, j)]
                );
            }
        }
    }
}

/// §12.6, (12.6.4) corrected: the input matrix B of ẋ = Ax + Bu for u of (12.6.2). The book
/// prints rows 10–12 (ṗ, q̇, ṙ) all zero; the rotational equations (12.5.10)–(12.5.12) put J⁻¹
/// there (erratum, notes [T]): [ṗ, ṙ] = (1/Γ)[[J_zz, J_xz], [J_xz, J_xx]][l, n],
/// Γ = J_xxJ_zz − J_xz², q̇ = m/J_yy, for the aerodynamic and the thrust moments alike.
#[test]
fn section_12_6_input_matrix_and_erratum_12_6_4() {
    let frame = airframe();
    let (jxx, jyy, jzz, jxz) = frame.inertia();
    let gam = jxx * jzz - jxz * jxz;
    let m = frame.mass();
    for (u0, th0) in [(150.0, 0.12), (90.0, -0.3), (220.0, 0.0)] {
        let (x0, u_0) = steady(&frame, u0, th0, 0.0);
        let (_, b) = jacobians(&frame, &x0, &u_0);
        let mut b_book = DMatrix::<f64>::zeros(12, 11);
        // rows 4–6 of (12.6.4) as printed
        b_book[(U, 0)] = 1.0 / m;
        b_book[(U, 6)] = 1.0 / m;
        b_book[(V, 1)] = 1.0 / m;
        b_book[(W, 2)] = 1.0 / m;
        b_book[(W, 7)] = 1.0 / m;
        // rows 10–12 corrected: J⁻¹ on [l_A m_A n_A] and on [l_T m_T n_T]
        for (l_col, n_col, m_col) in [(3, 5, 4), (8, 10, 9)] {
            b_book[(P, l_col)] = jzz / gam;
            b_book[(P, n_col)] = jxz / gam;
            b_book[(Q, m_col)] = 1.0 / jyy;
            b_book[(R, l_col)] = jxz / gam;
            b_book[(R, n_col)] = jxx / gam;
        }
        for i in 0..12 {
            for j in 0..11 {
                let scale = b_book[(i, j)].abs().max(1.0 / m);
                assert!(
                    (b[(i, j)] - b_book[(i, j)]).abs() <= 64.0 * EPS * scale,
                    "B[{i},{j}] = {} vs {}",
                    b[(i, j)],
                    b_book[(i, j)]
                );
            }
        }
        // the printed zeros in rows 10–12 would leave the aircraft unable to roll, pitch or yaw
        assert!(b[(P, 3)] > 0.0 && b[(Q, 4)] > 0.0 && b[(R, 5)] > 0.0);
    }
}
