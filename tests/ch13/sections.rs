//! §13.1–13.5 on an aircraft with arbitrary coefficients: force and moment coefficients, the
//! steady coefficients, and the dimensional force and moment perturbations of §13.3 and §13.5
//! as exact (dual-number) derivatives of vectrix's aerodynamic model; (13.3.13) and (13.3.31)
//! in corrected form.

use std::f64::consts::PI;

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::nalgebra::Vector3;
use vectrix::num_dual::Dual64;
use vectrix::prelude::*;

use crate::common::{GEOMETRY, RHO, U0, Var, aircraft, coefficients, partials, qs};
use crate::support::EPS;

/// |got − want| ≤ tol (absolute).
#[track_caller]
fn assert_abs(what: &str, got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol,
        "{what}: got {got:e}, want {want:e}, |err| = {:e} > {tol:e}",
        (got - want).abs()
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// §13.1–13.2: C_D = D/(p_dS), C_E = E/(p_dS), C_L = L/(p_dS) (13.1.1–3), C_x, C_y, C_z =
    /// F_A{x,y,z}/(p_dS) (13.1.4–6), related by (13.2.11) C_x = −cαcβC_D + cαsβC_E + sαC_L,
    /// (13.3.35) C_y = −sβC_D − cβC_E and (13.3.45) C_z = −sαcβC_D + sαsβC_E − cαC_L, at random
    /// flight states of the nonlinear model.
    #[test]
    fn section_13_1_force_coefficients_in_wind_and_aircraft_frames(
        v in 200.0..800.0f64, alpha in -PI..PI, beta in -1.5..1.5f64,
        pqr in [-0.5..0.5f64, -0.5..0.5f64, -0.5..0.5f64], de in -0.3..0.3f64,
    ) {
        let ac = aircraft(coefficients());
        let uvw = AeroAngles { airspeed: v, alpha, beta }.body_velocity();
        let x = AircraftState { position: [0.0; 3], velocity: uvw, attitude: Euler321::default(), omega: pqr };
        let u = Controls { elevator: de, aileron: 0.0, rudder: 0.0, thrust: 0.0 };
        let fm = ac.forces(&x, &u, 0.0, 0.0);
        let a = x.aero_angles();
        let pds = ac.dynamic_pressure(v) * GEOMETRY.area;
        prop_assert!((pds - 0.5 * RHO * v * v * GEOMETRY.area).abs() <= 4.0 * EPS * pds);
        let (cd, ce, cl) = (fm.drag / pds, fm.side_drag / pds, fm.lift / pds);
        let f = o_w_ac(a.alpha, a.beta).transpose() * Vector3::new(-fm.drag, -fm.side_drag, -fm.lift);
        let c = f / pds;
        let (sa, ca, sb, cb) = (a.alpha.sin(), a.alpha.cos(), a.beta.sin(), a.beta.cos());
        let tol = 64.0 * EPS * (cd.abs() + ce.abs() + cl.abs());
        prop_assert!((c[0] - (-ca * cb * cd + ca * sb * ce + sa * cl)).abs() <= tol);
        prop_assert!((c[1] - (-sb * cd - cb * ce)).abs() <= tol);
        prop_assert!((c[2] - (-sa * cb * cd + sa * sb * ce - ca * cl)).abs() <= tol);
    }
}

/// (13.2.9)–(13.2.12), (13.3.36), (13.3.46): in straight steady flight with F_AC chosen so that
/// α₀ = β₀ = 0, C_x0 = −C_D0, C_y0 = −C_E0 = 0 (a symmetric aircraft has no steady side force)
/// and C_z0 = −C_L0.
#[test]
fn eq_13_2_12_steady_force_coefficients() {
    let ac = aircraft(coefficients());
    let p = partials(&ac, Var::U);
    let pds = qs();
    let (cd0, ce0, cl0) = (p.del0[0] / pds, p.del0[1] / pds, p.del0[2] / pds);
    let c = coefficients();
    assert_abs("C_D0", cd0, c.cd_par + c.k_induced * c.cl0 * c.cl0, 8.0 * EPS);
    assert_abs("C_E0", ce0, 0.0, 0.0);
    assert_abs("C_x0", p.force0[0] / pds, -cd0, 8.0 * EPS);
    assert_abs("C_y0", p.force0[1] / pds, 0.0, 0.0);
    assert_abs("C_z0", p.force0[2] / pds, -cl0, 8.0 * EPS);
}

/// §13.3.4–13.3.6: the dimensional force perturbations, with C_D0 = C_Dpar + KC_L0² (13.3.10),
/// C_Du = C_Du,par + 2KC_L0C_Lu and C_Dα = 2KC_L0C_Lα (13.3.12), and p_du0 = ρU₀² = 2p_d0
/// (13.3.29):
/// ∂f_Ax/∂(u/U₀) = −p_d0S(2C_D0 + C_Du) (13.3.30), ∂f_Ax/∂δα = p_d0S(C_L0 − C_Dα) (13.3.32),
/// ∂f_Ay/∂δβ = −p_d0S(C_D0 + C_Eβ) (13.3.39), ∂f_Ay/∂(bp/2U₀) = −p_d0SC_Ep (13.3.37),
/// ∂f_Ay/∂(br/2U₀) = −p_d0SC_Er (13.3.38), ∂f_Ay/∂δr = −p_d0SC_Eδr (13.3.42),
/// ∂f_Az/∂(u/U₀) = −p_d0S(2C_L0 + C_Lu) (13.3.47), ∂f_Az/∂(c̄q/2U₀) = −p_d0SC_Lq (13.3.48),
/// ∂f_Az/∂δα = −p_d0S(C_Lα + C_D0) (13.3.50). The book prints (13.3.31) as
/// ∂f_Ax/∂(c̄q/2U₀) = −p_d0SC_Du; the derivative with respect to q is −p_d0SC_Dq (erratum,
/// notes [T]) — zero for this model, whose pitch-rate lift adds no drag, while C_Du ≠ 0.
#[test]
fn eq_13_3_30_force_perturbations() {
    let c = coefficients();
    let ac = aircraft(c);
    let pds = qs();
    let (hc, hb) = (GEOMETRY.chord / (2.0 * U0), GEOMETRY.span / (2.0 * U0));
    let cd0 = c.cd_par + c.k_induced * c.cl0 * c.cl0;
    let cd_u = c.cd_u + 2.0 * c.k_induced * c.cl0 * c.cl_u;
    let cd_alpha = 2.0 * c.k_induced * c.cl0 * c.cl_alpha;
    // (13.3.29): ∂p_d/∂(u/U₀) = ρU₀²
    let pd = ac.dynamic_pressure(Dual64::new(U0, U0));
    assert_abs("p_du0", pd.eps, 2.0 * pd.re, 4.0 * EPS * pd.re);
    let tol = 64.0 * EPS * pds * 10.0;
    let pu = partials(&ac, Var::U);
    assert_abs("(13.3.30)", pu.force[0] * U0, -pds * (2.0 * cd0 + cd_u), tol);
    assert_abs("(13.3.47)", pu.force[2] * U0, -pds * (2.0 * c.cl0 + c.cl_u), tol);
    let pa = partials(&ac, Var::Alpha);
    // δα = w/U₀: ∂/∂δα = U₀ ∂/∂w
    assert_abs("(13.3.32)", pa.force[0], pds * (c.cl0 - cd_alpha), tol);
    assert_abs("(13.3.50)", pa.force[2], -pds * (c.cl_alpha + cd0), tol);
    let pq = partials(&ac, Var::Q);
    assert_abs("(13.3.48)", pq.force[2] / hc, -pds * c.cl_q, tol);
    assert_abs("(13.3.31) corrected: C_Dq = 0", pq.force[0] / hc, 0.0, tol);
    assert!((pq.force[0] / hc + pds * cd_u).abs() > 1.0, "the printed −p_d0 S C_Du would not be zero");
    let pb = partials(&ac, Var::Beta);
    assert_abs("(13.3.39)", pb.force[1], -pds * (cd0 + c.ce_beta), tol);
    assert_abs("(13.3.37)", partials(&ac, Var::P).force[1] / hb, -pds * c.ce_p, tol);
    assert_abs("(13.3.38)", partials(&ac, Var::R).force[1] / hb, -pds * c.ce_r, tol);
    assert_abs("(13.3.42)", partials(&ac, Var::Rudder).force[1], -pds * c.ce_dr, tol);
    assert_abs("(13.3.41)", partials(&ac, Var::Aileron).force[1], -pds * c.ce_da, tol);
    assert_abs("(13.3.40)", partials(&ac, Var::BetaDot).force[1] / hb, -pds * c.ce_beta_dot, tol);
}

/// §13.4–13.5: C_l = L_A/(p_dSb), C_m = M_A/(p_dSc̄), C_n = N_A/(p_dSb) (13.4.1–3) and the
/// moment perturbations (13.5.3), (13.5.14), (13.5.33):
/// l_A = (p_d0Sb²/2U₀)(C_lp p + C_lr r + C_lβ̇ δβ̇) + p_d0Sb(C_lβ δβ + C_lδa δa + C_lδr δr),
/// m_A = (p_d0Sc̄/U₀)(2C_m0 + C_mu)u + (p_d0Sc̄²/2U₀)(C_mq q + C_mα̇ δα̇) + p_d0Sc̄(C_mα δα + C_mδe δe),
/// n_A likewise with C_n and b. The 2C_m0 comes from ∂p_d/∂(u/U₀) = 2p_d0.
#[test]
fn eq_13_5_14_moment_perturbations() {
    let c = coefficients();
    let ac = aircraft(c);
    let pds = qs();
    let (cb, b) = (GEOMETRY.chord, GEOMETRY.span);
    let (hc, hb) = (cb * cb / (2.0 * U0), b * b / (2.0 * U0));
    let tol = 64.0 * EPS * pds * b * 20.0;
    let m = |v: Var| partials(&ac, v).moment;
    assert_abs("m_A/u", m(Var::U)[1], pds * cb / U0 * (2.0 * c.cm0 + c.cm_u), tol);
    assert_abs("m_A/q", m(Var::Q)[1], pds * hc * c.cm_q, tol);
    assert_abs("m_A/δα̇", m(Var::AlphaDot)[1], pds * hc * c.cm_alpha_dot, tol);
    assert_abs("m_A/δα", m(Var::Alpha)[1], pds * cb * c.cm_alpha, tol);
    assert_abs("m_A/δe", m(Var::Elevator)[1], pds * cb * c.cm_de, tol);
    for (k, coeff) in [
        (0usize, [c.croll_p, c.croll_r, c.croll_beta_dot, c.croll_beta, c.croll_da, c.croll_dr]),
        (2, [c.cn_p, c.cn_r, c.cn_beta_dot, c.cn_beta, c.cn_da, c.cn_dr]),
    ] {
        assert_abs("/p", m(Var::P)[k], pds * hb * coeff[0], tol);
        assert_abs("/r", m(Var::R)[k], pds * hb * coeff[1], tol);
        assert_abs("/δβ̇", m(Var::BetaDot)[k], pds * hb * coeff[2], tol);
        assert_abs("/δβ", m(Var::Beta)[k], pds * b * coeff[3], tol);
        assert_abs("/δa", m(Var::Aileron)[k], pds * b * coeff[4], tol);
        assert_abs("/δr", m(Var::Rudder)[k], pds * b * coeff[5], tol);
        // a symmetric aircraft: no lateral moment from longitudinal perturbations
        for v in [Var::U, Var::Alpha, Var::Q, Var::Elevator] {
            assert_abs("longitudinal → lateral", m(v)[k], 0.0, tol);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// (13.3.13) corrected: expanding the polar C_D = C_Dpar + KC_L² (13.3.9) with C_L of (13.3.1)
    /// gives C_D ≈ C_D0 + (2/U₀)KC_L0C_Lu u + (c̄/U₀)KC_L0C_Lq q + (b/U₀)KC_L0C_Lr r + 2KC_L0C_Lα δα
    /// + (c̄/U₀)KC_L0C_Lα̇ δα̇ + 2KC_L0C_Lβ δβ + (b/U₀)KC_L0C_Lβ̇ δβ̇ + 2KC_L0C_Lδe δe. The book's
    /// u-term carries C_Lα for C_Lu, and its δα̇, δβ̇ terms drop the c̄/2U₀, b/2U₀ factors of
    /// (13.3.1) (errata, notes [T]). Dual numbers differentiate the composition exactly.
    #[test]
    fn eq_13_3_13_drag_expansion_corrected(
        cl in [0.1..1.0f64, -0.2..0.2f64, -1.0..1.0f64, -0.5..0.5f64, 2.0..6.0f64, -1.0..3.0f64, -0.5..0.5f64, -0.5..0.5f64, 0.0..1.0f64],
        k in 0.01..0.1f64, u0 in 50.0..900.0f64, cbar in 1.0..12.0f64, b in 5.0..60.0f64,
    ) {
        let [cl0, clu, clq, clr, cla, clad, clb, clbd, clde] = cl;
        // variables (u, q, r, δα, δα̇, δβ, δβ̇, δe)
        let scale = [1.0 / u0, cbar / (2.0 * u0), b / (2.0 * u0), 1.0, cbar / (2.0 * u0), 1.0, b / (2.0 * u0), 1.0];
        let coeff = [clu, clq, clr, cla, clad, clb, clbd, clde];
        let corrected = [
            2.0 / u0 * k * cl0 * clu,
            cbar / u0 * k * cl0 * clq,
            b / u0 * k * cl0 * clr,
            2.0 * k * cl0 * cla,
            cbar / u0 * k * cl0 * clad,
            2.0 * k * cl0 * clb,
            b / u0 * k * cl0 * clbd,
            2.0 * k * cl0 * clde,
        ];
        for i in 0..8 {
            let lift = Dual64::from(cl0) + Dual64::new(0.0, scale[i] * coeff[i]);
            let drag = Dual64::from(0.02) + lift * lift * k;
            prop_assert!((drag.eps - corrected[i]).abs() <= 8.0 * EPS * corrected[i].abs().max(1e-300));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// §13.5.1.4, (13.5.4)–(13.5.11): dihedral Γ tilts the right wing's normal k̂_n toward ĵ_AC, so
    /// the normal component of the flow on it is V_n1 + V_n2 = V sin Γ + W cos Γ and the change due
    /// to dihedral is ΔV_n = W cos Γ + V sin Γ − W ≈ VΓ (13.5.8); the right wing's angle of attack
    /// grows by δα with tan δα = ΔV_n/U, δα ≈ δβΓ (13.5.10–11), the left wing's falls by as much:
    /// sideslip to the right rolls the aircraft left, C_lβ < 0. Frame-free: the wing frames are
    /// F_AC turned by ∓Γ about î_AC. The small-angle error is third order,
    /// |δα − δβΓ| ≤ |δβΓ|(δβ² + Γ²) for |δβ|, |Γ| ≤ 0.3 (from the Taylor series of atan(tan δβ sin Γ)).
    #[test]
    fn eq_13_5_11_dihedral_effect(
        u in 100.0..900.0f64, beta in -0.3..0.3f64, gamma in 0.0..0.3f64,
    ) {
        let ac = Frame::new();
        let vel = ac.vector(AeroAngles { airspeed: u, alpha: 0.0, beta }.body_velocity());
        let [_, v, w] = AeroAngles { airspeed: u, alpha: 0.0, beta }.body_velocity();
        let right = Frame::from_orientation_rel(&ac, &o1(-gamma), 1e-12).unwrap();
        let left = Frame::from_orientation_rel(&ac, &o1(gamma), 1e-12).unwrap();
        // right wing up: its span axis has a component along −k̂_AC (up)
        prop_assert!(right.j().dot(&ac.k()) <= 0.0);
        let vn = vel.dot(&right.k());
        prop_assert!((vn - (v * gamma.sin() + w * gamma.cos())).abs() <= 8.0 * EPS * u);
        let u_axis = vel.dot(&ac.i());
        let d_alpha_r = vn.atan2(u_axis) - w.atan2(u_axis);
        let d_alpha_l = vel.dot(&left.k()).atan2(u_axis) - w.atan2(u_axis);
        prop_assert!((d_alpha_r + d_alpha_l).abs() <= 8.0 * EPS);
        // W = 0: tan δα = ΔV_n/U = tan δβ sin Γ exactly (13.5.10)
        prop_assert!((d_alpha_r - (beta.tan() * gamma.sin()).atan()).abs() <= 8.0 * EPS);
        let approx = beta * gamma;
        prop_assert!((d_alpha_r - approx).abs() <= approx.abs() * (beta * beta + gamma * gamma) + 8.0 * EPS);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// §13.1, §13.4 and the nondimensional variables of §13.3: C_D, C_E, C_L = force/(p_dS),
    /// C_l = L_A/(p_dSb), C_m = M_A/(p_dSc̄), C_n = N_A/(p_dSb) (13.4.1–3) with the rates scaled
    /// as bp/2V, c̄q/2V, br/2V make the coefficients depend on the flight only through α, β,
    /// the nondimensional rates and the controls: a geometrically scaled copy of the aircraft
    /// (S ↦ k²S, b, c̄ ↦ kb, kc̄) flying at another speed and density with the same nondimensional
    /// state has the same coefficients (dynamic similarity).
    #[test]
    fn section_13_4_coefficients_are_similarity_invariants(
        k in 0.2..5.0f64, v1 in 200.0..800.0f64, v2 in 200.0..800.0f64, rho2 in 0.0003..0.003f64,
        alpha in -0.3..0.3f64, beta in -0.3..0.3f64, rates in [-0.05..0.05f64, -0.05..0.05f64, -0.05..0.05f64],
        ctrl in [-0.2..0.2f64, -0.2..0.2f64, -0.2..0.2f64],
    ) {
        // the speed derivatives are taken about each aircraft's own U₀ = its speed here
        let c = Coefficients { cl_u: 0.0, cd_u: 0.0, cm_u: 0.0, ..coefficients() };
        let a1 = aircraft(c);
        let geo2 = Geometry { area: k * k * GEOMETRY.area, chord: k * GEOMETRY.chord, span: k * GEOMETRY.span };
        let a2 = Aircraft { geometry: geo2, rho: rho2, ..aircraft(c) };
        let coeffs = |ac: &Aircraft, v: f64| {
            let g = ac.geometry;
            // nondimensional rates (bp/2V, c̄q/2V, br/2V) → dimensional
            let pqr = [rates[0] * 2.0 * v / g.span, rates[1] * 2.0 * v / g.chord, rates[2] * 2.0 * v / g.span];
            let x = AircraftState {
                position: [0.0; 3],
                velocity: AeroAngles { airspeed: v, alpha, beta }.body_velocity(),
                attitude: Euler321::default(),
                omega: pqr,
            };
            let u = Controls { elevator: ctrl[0], aileron: ctrl[1], rudder: ctrl[2], thrust: 0.0 };
            let fm = ac.forces(&x, &u, 0.0, 0.0);
            let pds = ac.dynamic_pressure(v) * g.area;
            [fm.drag / pds, fm.side_drag / pds, fm.lift / pds, fm.roll / (pds * g.span), fm.pitch / (pds * g.chord), fm.yaw / (pds * g.span)]
        };
        let (c1, c2) = (coeffs(&a1, v1), coeffs(&a2, v2));
        // each coefficient sums ≲ 10 terms of size ≤ 5 (coefficients ≤ 15 times angles, rates and
        // controls ≤ 0.3): an absolute rounding bound of 64 ε · 50
        for i in 0..6 {
            prop_assert!((c1[i] - c2[i]).abs() <= 64.0 * EPS * 50.0, "coefficient {i}: {} vs {}", c1[i], c2[i]);
        }
    }
}
