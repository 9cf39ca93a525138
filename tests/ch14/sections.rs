//! §14.1–14.7 statements the chapter root leaves untested, and the chapter's errata in
//! corrected form: Γ⁻¹ (14.3.10) and the input term of (14.3.7); the lateral transfer matrix
//! (14.4.4); the six-state models (14.1.15) (θ̇ row missing) and (14.3.17) with their range,
//! altitude and drift transfer functions (14.2.16), (14.4.24); the signs of Table 14.1's X row;
//! the short-period transfer functions (14.7.28)–(14.7.29).

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::lti::{Complex64, FinalValue, StateSpace, final_value};
use vectrix::nalgebra::DMatrix;
use vectrix::num_dual::Dual64;

use crate::common::{augment, lateral, longitudinal, resolvent_b};
use crate::support::{EPS, NanAmax, nan_max};

/// Sample points s off the poles. The frequency-domain identities below compare complex linear
/// solves of (sI − A) (or the book's 3 × 3 matrix) for derivatives spanning ≈ 1e6 in size; at
/// these points the systems are well conditioned (κ ≲ 1e5), so a relative 1e-9 keeps a factor
/// of ≈ 100 over the rounding they lose.
const S: [(f64, f64); 4] = [(0.0, 0.3), (0.1, 1.7), (-0.2, 4.0), (2.0, -0.5)];

/// max |a − b| over entries, relative to max |b|.
fn rel_diff(a: &DMatrix<Complex64>, b: &DMatrix<Complex64>) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, z| nan_max(m, z.norm()));
    a.iter().zip(b.iter()).fold(0.0f64, |m, (x, y)| nan_max(m, (x - y).norm())) / scale
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// (14.3.10) corrected: Γ⁻¹ = (1/Γ_J)[[J_xxJ_zz, J_xx(J_zzN_β̇ + J_xzL_β̇)/(U₀ − Y_β̇), J_xzJ_xx, 0],
    /// [0, Γ_J/(U₀ − Y_β̇), 0, 0], [J_xzJ_zz, J_zz(J_xxL_β̇ + J_xzN_β̇)/(U₀ − Y_β̇), J_xxJ_zz, 0],
    /// [0, 0, 0, Γ_J]] with Γ_J = J_xxJ_zz − J_xz². The book's (1,2) entry has J_xz in front where
    /// J_xx belongs (erratum, notes [T, C]). With it, B = Γ⁻¹B₀ entry by entry as (14.3.16) —
    /// so the Γ multiplying the input matrix on the right of (14.3.7) is a slip: Γẋ = A₀x + B₀u.
    #[test]
    fn eq_14_3_10_gamma_inverse_corrected(d in lateral()) {
        let desc = d.descriptor().unwrap();
        let inv = desc.e.clone().try_inverse().unwrap();
        let gj = d.jxx * d.jzz - d.jxz * d.jxz;
        let uy = d.u0 - d.y_beta_dot;
        #[rustfmt::skip]
        let want = DMatrix::from_row_slice(4, 4, &[
            d.jxx * d.jzz / gj, d.jxx * (d.jzz * d.n_beta_dot + d.jxz * d.l_beta_dot) / (uy * gj), d.jxz * d.jxx / gj, 0.0,
            0.0, 1.0 / uy, 0.0, 0.0,
            d.jxz * d.jzz / gj, d.jzz * (d.jxx * d.l_beta_dot + d.jxz * d.n_beta_dot) / (uy * gj), d.jxx * d.jzz / gj, 0.0,
            0.0, 0.0, 0.0, 1.0,
        ]);
        let tol = 64.0 * EPS * (1.0 + want.nan_amax());
        prop_assert!((&inv - &want).nan_amax() <= tol, "Γ⁻¹ = {inv} vs {want}");
        let printed_12 = d.jxz * (d.jzz * d.n_beta_dot + d.jxz * d.l_beta_dot) / (uy * gj);
        if (d.jxx - d.jxz).abs() > 1.0 && (d.jzz * d.n_beta_dot + d.jxz * d.l_beta_dot).abs() > 1e-3 {
            prop_assert!((printed_12 - inv[(0, 1)]).abs() > tol);
        }
        // (14.3.16): B = Γ⁻¹B₀
        let b = d.state_space().unwrap().b().clone();
        prop_assert!((&b - &want * &desc.b0).nan_amax() <= 64.0 * EPS * (1.0 + b.nan_amax()));
    }

    /// (14.4.4) corrected: Laplace-transforming (14.3.4)–(14.3.6) with sφ̂ = p̂, sψ̂ = r̂ gives
    /// [[s − N_r, −N_β̇s − (N_β + N_Tβ), −(J_xz/J_zz)s² − N_ps],
    ///  [U₀ − Y_r, (U₀ − Y_β̇)s − Y_β, −(Y_ps + g)],
    ///  [−(J_xz/J_xx)s − L_r, −L_β̇s − (L_β + L_Tβ), s² − L_ps]] [r̂, δβ̂, φ̂] =
    /// [[N_δa, N_δr], [Y_δa, Y_δr], [L_δa, L_δr]] [δâ, δr̂].
    /// The book lists the right-hand rows as Y, L, N (in the order of the unknowns' equations they
    /// must be N, Y, L) and writes −N_βs, (U₀ − Y_β)s for −N_β̇s, (U₀ − Y_β̇)s (errata, notes [T]).
    /// Checked against C(sI − A)⁻¹B of the state-space model at sample s.
    #[test]
    fn eq_14_4_4_lateral_transfer_matrix_corrected(d in lateral()) {
        let sys = d.state_space().unwrap();
        for (re, im) in S {
            let s = Complex64::new(re, im);
            let c = |x: f64| Complex64::new(x, 0.0);
            #[rustfmt::skip]
            let m = DMatrix::from_row_slice(3, 3, &[
                s - d.n_r, -(s * d.n_beta_dot) - c(d.n_beta + d.n_tbeta), -(s * s * (d.jxz / d.jzz)) - s * d.n_p,
                c(d.u0 - d.y_r), s * (d.u0 - d.y_beta_dot) - d.y_beta, -(s * d.y_p + d.g),
                -(s * (d.jxz / d.jxx)) - d.l_r, -(s * d.l_beta_dot) - c(d.l_beta + d.l_tbeta), s * s - s * d.l_p,
            ]);
            let rhs = DMatrix::from_row_slice(3, 2, &[c(d.n_da), c(d.n_dr), c(d.y_da), c(d.y_dr), c(d.l_da), c(d.l_dr)]);
            let sol = m.clone().lu().solve(&rhs).unwrap();
            let g = resolvent_b(sys.a(), sys.b(), s);
            // outputs r, δβ, φ are states 0, 1, 3
            let want = DMatrix::from_fn(3, 2, |i, j| g[([0, 1, 3][i], j)]);
            prop_assert!(rel_diff(&sol, &want) <= 1e-9, "s = {s}: {sol} vs {want}");
            // the printed right-hand side order Y, L, N solves a different system
            let printed = DMatrix::from_row_slice(3, 2, &[c(d.y_da), c(d.y_dr), c(d.l_da), c(d.l_dr), c(d.n_da), c(d.n_dr)]);
            let wrong = m.lu().solve(&printed).unwrap();
            prop_assert!(rel_diff(&wrong, &want) > 1e-3);
        }
    }

    /// (14.1.15) corrected and (14.2.10)–(14.2.16): the six-state longitudinal model adds
    /// ẋ = u and ḣ = U₀(θ − δα) to the four rows of (14.1.13) — the printed matrix drops the
    /// θ̇ = q row (erratum, notes [T]); its range and altitude transfer functions are
    /// G_x = G_u/s and G_h = (U₀/s)(G_θ − G_δα).
    #[test]
    fn eq_14_1_15_six_state_longitudinal_corrected(d in longitudinal()) {
        let sys4 = d.state_space().unwrap();
        let (a, b) = augment(sys4.a(), sys4.b(), &[&[(0, 1.0)], &[(1, -d.u0), (3, d.u0)]]);
        prop_assert_eq!(a[(3, 2)], 1.0);
        for (re, im) in S {
            let s = Complex64::new(re, im);
            let g6 = resolvent_b(&a, &b, s);
            let g4 = resolvent_b(sys4.a(), sys4.b(), s);
            let gx = g4[(0, 0)] / s;
            let gh = (g4[(3, 0)] - g4[(1, 0)]) * d.u0 / s;
            prop_assert!((g6[(4, 0)] - gx).norm() <= 1e-9 * gx.norm().max(1.0));
            prop_assert!((g6[(5, 0)] - gh).norm() <= 1e-9 * gh.norm().max(1.0));
        }
    }

    /// (14.3.17) and (14.4.22)–(14.4.25): the six-state lateral model adds ψ̇ = r and
    /// ẏ = U₀(δβ + ψ) = U₀δη; G_y = (U₀/s)(G_ψ + G_δβ) with G_ψ = G_r/s (14.4.24).
    #[test]
    fn eq_14_3_17_six_state_lateral_drift(d in lateral()) {
        let sys4 = d.state_space().unwrap();
        let (a, b) = augment(sys4.a(), sys4.b(), &[&[(0, 1.0)], &[(1, d.u0), (4, d.u0)]]);
        for (re, im) in S {
            let s = Complex64::new(re, im);
            let g6 = resolvent_b(&a, &b, s);
            let g4 = resolvent_b(sys4.a(), sys4.b(), s);
            for j in 0..2 {
                let gpsi = g4[(0, j)] / s;
                let gy = (gpsi + g4[(1, j)]) * d.u0 / s;
                prop_assert!((g6[(4, j)] - gpsi).norm() <= 1e-9 * gpsi.norm().max(1.0));
                prop_assert!((g6[(5, j)] - gy).norm() <= 1e-9 * gy.norm().max(1.0));
            }
        }
    }
}

/// (14.4.25): after an aileron impulse the drift grows without bound, y → sign(U₀D_r,δa/H′ δā)∞
/// (the final-value theorem sees a double pole at 0); the business jet of Table 14.2.
#[test]
fn eq_14_4_25_drift_diverges_after_an_aileron_impulse() {
    let d = business_jet_lateral();
    let sys4 = d.state_space().unwrap();
    let (a, b) = augment(sys4.a(), sys4.b(), &[&[(0, 1.0)], &[(1, d.u0), (4, d.u0)]]);
    let sys = StateSpace::new(a, b, DMatrix::identity(6, 6), DMatrix::zeros(6, 2)).unwrap();
    let gy = sys.to_tf(5, 0).unwrap();
    let gr = sys4.to_tf(0, 0).unwrap();
    // D_r,δa/H′ = ψ∞ per unit aileron impulse, [C] 584.6 > 0
    let psi_inf = gr.num().eval(0.0) / gr.den().eval(0.0);
    assert!(psi_inf > 0.0);
    assert_eq!(final_value(&gy, 1e-9).unwrap(), FinalValue::Infinite(1.0));
}

/// Table 14.1's X row from (13.3.33), the derivatives of f_Ax/m: X_q = −p_d0Sc̄C_Dq/(2mU₀),
/// X_α̇ = −p_d0Sc̄C_Dα̇/(2mU₀), X_δe = −p_d0SC_Dδe/m. The table prints them with + signs, and
/// X_α̇ without the 2 (errata, notes [T]; the business jet's values are all 0, so its data do
/// not show it). Checked by differentiating f_Ax = −p_dSC_D cos α + p_dSC_L sin α at α₀ = 0 with a
/// drag that depends on q, δα̇, δe (13.3.11).
#[test]
fn table_14_1_x_row_signs_corrected() {
    let (u0, rho, s, cbar, m) = (600.0, 0.001, 250.0, 7.0, 400.0);
    let (cd0, cdq, cdad, cdde) = (0.03, 0.2, 0.1, 0.05);
    let pd0 = 0.5 * rho * u0 * u0;
    // f_Ax/m at α = 0 as a function of (q, δα̇, δe): the lift term p_dSC_L sin α vanishes there
    // and α does not depend on q, δα̇ or δe
    let fx = |q: Dual64, ad: Dual64, de: Dual64| {
        let cd =
            Dual64::from(cd0) + q * (cdq * cbar / (2.0 * u0)) + ad * (cdad * cbar / (2.0 * u0)) + de * cdde;
        -(cd * pd0 * s) / m
    };
    let (one, zero) = (Dual64::new(0.0, 1.0), Dual64::from(0.0));
    let x_q = fx(one, zero, zero).eps;
    let x_ad = fx(zero, one, zero).eps;
    let x_de = fx(zero, zero, one).eps;
    let tol = 16.0 * EPS;
    assert!((x_q - -(pd0 * s * cbar * cdq / (2.0 * m * u0))).abs() <= tol * x_q.abs());
    assert!((x_ad - -(pd0 * s * cbar * cdad / (2.0 * m * u0))).abs() <= tol * x_ad.abs());
    assert!((x_de - -(pd0 * s * cdde / m)).abs() <= tol * x_de.abs());
    // the printed X_α̇ = +p_d0Sc̄C_Dα̇/(mU₀) has the wrong sign and twice the size
    assert!((x_ad - pd0 * s * cbar * cdad / (m * u0)).abs() > x_ad.abs());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// (14.7.24)–(14.7.29): with u = 0 and Z_α̇ = Z_q = M_α̇ = M_Tα = 0, the short-period model
    /// [U₀s − Z_α, −U₀s; −M_α, s² − M_qs][δα̂; θ̂] = [Z_δe; M_δe]δê has
    /// G_δα = (Z_δe s + M_δeU₀ − M_qZ_δe)/(U₀p(s)) (14.7.28) and
    /// G_θ = (U₀M_δe s + M_αZ_δe − Z_αM_δe)/(U₀ s p(s)) (14.7.29) with
    /// p(s) = s² − (M_q + Z_α/U₀)s + (M_qZ_α/U₀ − M_α) (14.7.27). Checked on vectrix's
    /// four-state model: random Table 14.1 data with u decoupled (Z_u = Z_Tu = M_u = M_Tu = 0, so
    /// u feeds neither δα nor q) and the four derivatives above zero, at Θ₀ = 0;
    /// `state_space().to_tf` for δα and θ evaluated at sample s against the printed closed forms,
    /// and `short_period_approximation` against (14.7.27).
    #[test]
    fn eq_14_7_28_short_period_transfer_functions(d in longitudinal()) {
        let d = LongitudinalDerivatives {
            theta0: 0.0,
            z_u: 0.0,
            z_tu: 0.0,
            m_u: 0.0,
            m_tu: 0.0,
            z_alpha_dot: 0.0,
            z_q: 0.0,
            m_alpha_dot: 0.0,
            m_talpha: 0.0,
            ..d
        };
        let (u0, za, ma, mq, zde, mde) = (d.u0, d.z_alpha, d.m_alpha, d.m_q, d.z_de, d.m_de);
        let sys = d.state_space().unwrap();
        let (g_alpha_v, g_theta_v) = (sys.to_tf(1, 0).unwrap(), sys.to_tf(3, 0).unwrap());
        let sp = d.short_period_approximation().unwrap();
        for (re, im) in S {
            let s = Complex64::new(re, im);
            let p = s * s - s * (mq + za / u0) + (mq * za / u0 - ma);
            let g_alpha = (s * zde + mde * u0 - mq * zde) / (p * u0);
            let g_theta = (s * (u0 * mde) + ma * zde - za * mde) / (p * s * u0);
            let (got_a, got_t) = (g_alpha_v.eval(s), g_theta_v.eval(s));
            prop_assert!((got_a - g_alpha).norm() <= 1e-9 * g_alpha.norm().max(1e-3), "G_δα({s}) = {got_a} vs {g_alpha}");
            prop_assert!((got_t - g_theta).norm() <= 1e-9 * g_theta.norm().max(1e-3), "G_θ({s}) = {got_t} vs {g_theta}");
            // (14.7.27): three terms of size ≲ |s|² + |M_q + Z_α/U₀||s| + |M_qZ_α/U₀ − M_α|
            let size = s.norm_sqr() + (mq + za / u0).abs() * s.norm() + (mq * za / u0 - ma).abs();
            prop_assert!((sp.eval_c(s) - p).norm() <= 16.0 * EPS * size);
        }
    }
}
