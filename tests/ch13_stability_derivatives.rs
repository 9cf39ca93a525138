//! Chapter 13: stability and control derivatives — coefficients and nondimensionalisation,
//! the drag polar, static margin, dimensional derivatives (Tables 14.1–14.2 definitions),
//! cross-control cancellation; and the approximations of §14.7 built on them.
mod support;

use num_dual::Dual64;
use support::{EPS, assert_abs, assert_printed, assert_rel};
use vectrix::flight::*;

fn level(ac: &Aircraft) -> Trim {
    trim(ac, TrimSpec::Straight { airspeed: BUSINESS_JET_U0, gamma: 0.0 }, TrimLimits::default()).unwrap()
}

#[test]
fn eq_13_3_1_coefficients_nondimensionalise_forces() {
    // §13.3: C_L = L/(p_d S), C_m = M_A/(p_d S c̄), C_l = L_A/(p_d S b), p_d = ½ρV².
    let ac = business_jet();
    let t = level(&ac);
    let fm = ac.forces(&t.state, &t.controls, 0.0, 0.0);
    let pd = 0.5 * ac.rho * BUSINESS_JET_U0 * BUSINESS_JET_U0;
    assert_rel(ac.dynamic_pressure(BUSINESS_JET_U0), pd, 4.0 * EPS);
    let cl = fm.lift / (pd * ac.geometry.area);
    assert_abs(cl, ac.lift_coefficient(&t.state, &t.controls, 0.0), 8.0 * EPS);
    // level trim: C_L0 = W/(p_d S)
    assert_abs(cl, BUSINESS_JET_WEIGHT / (pd * ac.geometry.area), 1e-12);
    assert_abs(fm.pitch / (pd * ac.geometry.area * ac.geometry.chord), 0.0, 1e-12);
}

#[test]
fn eq_13_3_9_drag_polar_and_induced_drag_derivative() {
    // (13.3.9–12): C_D = C_Dpar + K C_L², K = 1/(πe AR), AR = b²/S, so C_Dα = 2K C_L0 C_Lα.
    let ac = business_jet();
    let t = level(&ac);
    assert_rel(ac.geometry.aspect_ratio(), 34.0 * 34.0 / 230.0, 4.0 * EPS);
    assert_abs(induced_drag_factor(0.8, 5.0), 1.0 / (std::f64::consts::PI * 4.0), 4.0 * EPS);
    // dual-number ∂C_D/∂α at the trim, through W = V sin α
    let v = BUSINESS_JET_U0;
    // x = [0, 0, 0, V cos α, 0, V sin α, 0, …] with α = 0 + ε
    let z = Dual64::from(0.0);
    let (sa, ca) = (Dual64::new(0.0, 1.0), Dual64::from(1.0));
    let mut xs = [z; 12];
    xs[3] = ca * v;
    xs[5] = sa * v;
    let x = AircraftState::from_array(xs);
    let u = Controls::from_array([z, z, z, Dual64::from(t.controls.thrust)]);
    let fm = ac.forces(&x, &u, Dual64::from(0.0), Dual64::from(0.0));
    let qs = ac.dynamic_pressure(v) * ac.geometry.area;
    let c = ac.coefficients;
    let cl0 = BUSINESS_JET_WEIGHT / qs;
    // the dual part is the exact derivative: a product of four factors, rounded
    assert_rel(fm.drag.eps / qs, 2.0 * c.k_induced * cl0 * c.cl_alpha, 16.0 * EPS);
}

#[test]
fn eq_13_5_30_static_margin() {
    // (13.5.30): C_mα = ((x_c − x_ac)/c̄)C_Lα < 0 iff the c.g. is ahead of the aerodynamic
    // centre (stations measured aft from the leading edge, so ahead means x_c < x_ac).
    let cl_alpha = 5.8;
    assert!(cm_alpha_from_static_margin(1.0, 0.5, 7.0, cl_alpha) > 0.0); // c.g. behind: unstable
    assert!(cm_alpha_from_static_margin(0.5, 1.0, 7.0, cl_alpha) < 0.0); // c.g. ahead: stable
    let cm = cm_alpha_from_static_margin(0.3, 1.0, 7.0, cl_alpha);
    assert_abs(static_margin(cm, cl_alpha), (1.0 - 0.3) / 7.0, 4.0 * EPS);
    // the business jet is statically stable
    assert!(business_jet().coefficients.cm_alpha < 0.0);
}

#[test]
fn table_14_1_definitions_round_trip() {
    // Table 14.1/14.2 definitions applied to the jet's coefficients at the level trim give back
    // the printed dimensional derivatives (M_Tu folded into M_u: A uses M_u + M_Tu).
    let ac = business_jet();
    let t = level(&ac);
    let d = LongitudinalDerivatives::from_aircraft(&ac, &t).unwrap();
    let b = business_jet_longitudinal();
    let pairs = [
        (d.x_u, b.x_u),
        (d.x_alpha, b.x_alpha),
        (d.z_u, b.z_u),
        (d.z_q, b.z_q),
        (d.z_alpha, b.z_alpha),
        (d.z_alpha_dot, b.z_alpha_dot),
        (d.z_de, b.z_de),
        (d.m_u, b.m_u + b.m_tu),
        (d.m_q, b.m_q),
        (d.m_alpha, b.m_alpha),
        (d.m_alpha_dot, b.m_alpha_dot),
        (d.m_de, b.m_de),
    ];
    // the coefficients invert Table 14.1, so each derivative comes back to rounding
    for (g, w) in pairs {
        assert_rel(g, w, 64.0 * EPS);
    }
    let d = LateralDerivatives::from_aircraft(&ac, &t).unwrap();
    let b = business_jet_lateral();
    for (g, w) in [
        (d.y_beta, b.y_beta),
        (d.y_r, b.y_r),
        (d.y_dr, b.y_dr),
        (d.l_beta, b.l_beta),
        (d.l_p, b.l_p),
        (d.l_r, b.l_r),
        (d.l_da, b.l_da),
        (d.l_dr, b.l_dr),
        (d.n_beta, b.n_beta),
        (d.n_p, b.n_p),
        (d.n_r, b.n_r),
        (d.n_da, b.n_da),
        (d.n_dr, b.n_dr),
    ] {
        assert_rel(g, w, 64.0 * EPS);
    }
    // Table 14.1 needs stability axes: a trim with α₀ ≠ 0 is refused
    let t2 = trim(&ac, TrimSpec::Straight { airspeed: 600.0, gamma: 0.0 }, TrimLimits::default()).unwrap();
    assert!(LongitudinalDerivatives::from_aircraft(&ac, &t2).is_err());
}

#[test]
fn table_13_longitudinal_signs_of_the_business_jet() {
    // Table 13.x (printed signs): C_m [u >, q <, δα <, δα̇ <, δe <]; C_L [all >].
    // C_mu > 0 holds for the jet (M_u + M_Tu = 0.0009 > 0).
    let c = business_jet().coefficients;
    assert!(c.cm_u > 0.0 && c.cm_q < 0.0 && c.cm_alpha < 0.0 && c.cm_alpha_dot < 0.0 && c.cm_de < 0.0);
    assert!(c.cl_u > 0.0 && c.cl_q > 0.0 && c.cl_alpha > 0.0 && c.cl_alpha_dot > 0.0 && c.cl_de > 0.0);
    // Lateral: C_lp < 0, C_lβ < 0 (dihedral), C_lδa > 0, C_nβ > 0 (weathercock), C_nδr < 0.
    // The printed C_E signs contradict the data (notes [T]): with Y_β < 0, C_Eβ > −C_D0.
    assert!(c.croll_p < 0.0 && c.croll_beta < 0.0 && c.croll_da > 0.0);
    assert!(c.cn_beta > 0.0 && c.cn_dr < 0.0 && c.cn_r < 0.0);
    assert!(c.ce_beta > -0.03);
}

#[test]
fn eq_13_6_2_cross_control_cancels_adverse_yaw() {
    // (13.6.2): δr = −(C_nδa/C_nδr)δa zeroes the yawing moment of an aileron input.
    let ac = business_jet();
    let t = level(&ac);
    let c = ac.coefficients;
    let da = 0.05;
    let mut u = t.controls;
    u.aileron = da;
    u.rudder = -(c.cn_da / c.cn_dr) * da;
    let fm = ac.forces(&t.state, &u, 0.0, 0.0);
    assert_abs(fm.yaw, 0.0, 1e-9);
}

#[test]
fn section_14_7_short_period_and_phugoid_approximations() {
    // [C]: short period ω = 2.839, ζ = 0.282; √(−M_α) = 2.728. Phugoid (14.7.14):
    // λ = −0.0037 ± 0.0815j; √(−Z_u g/U₀) = 0.0814.
    let d = business_jet_longitudinal();
    let sp = d.short_period_approximation().unwrap();
    let (wn, c1) = (sp.coeffs()[2].sqrt(), sp.coeffs()[1]);
    assert_printed(wn, "2.839");
    assert_printed(c1 / (2.0 * wn), "0.282");
    assert_printed((-d.m_alpha).sqrt(), "2.728");
    let ph = d.phugoid_approximation().unwrap();
    let roots = ph.roots().unwrap();
    let r = roots.iter().find(|z| z.im > 0.0).unwrap();
    assert_printed(r.re, "-0.0037");
    assert_printed(r.im, "0.0815");
    assert_printed((-d.z_u * d.g / d.u0).sqrt(), "0.0814");
}

#[test]
fn non_finite_derivatives_are_errors() {
    // A NaN coefficient is refused by trim and linearization, not propagated.
    let mut ac = business_jet();
    let t = level(&ac);
    ac.coefficients.cm_q = f64::NAN;
    assert!(matches!(linearize(&ac, &t), Err(FlightError::NonFinite { .. })));
    assert!(matches!(
        trim(&ac, TrimSpec::Straight { airspeed: 600.0, gamma: 0.0 }, TrimLimits::default()),
        Err(FlightError::NonFinite { .. })
    ));
    let mut ac = business_jet();
    ac.rho = -1.0;
    assert!(matches!(ac.check(), Err(FlightError::OutOfRange { .. })));
}

#[path = "ch13/common.rs"]
mod common;

#[path = "ch13/sections.rs"]
mod sections;

#[path = "ch13/problems.rs"]
mod problems;
