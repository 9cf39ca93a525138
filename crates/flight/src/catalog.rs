//! Ready-made aircraft: the business jet of Tables 14.1–14.2 and the 747 of §14.7.3.
//!
//! Book: §14.1 Table 14.1, §14.3 Table 14.2 (source "[10, p.330]"), §14.7.3 (747-100,
//! 40,000 ft, M 0.8); notes ch9-14 §4.

use nalgebra::DMatrix;

use crate::{LateralDerivatives, LongitudinalDerivatives};

/// Business-jet cruise speed U₀ = 400 kt = 675.124 ft/s (1 kt = 1.68781 ft/s).
///
/// Book: Table 14.1.
pub const BUSINESS_JET_U0: f64 = 400.0 * 1.687_81;

/// Business-jet longitudinal derivatives of Table 14.1 (ft, s, rad; g = 32.2 ft/s²).
///
/// Book: §14.1, Table 14.1.
pub fn business_jet_longitudinal() -> LongitudinalDerivatives {
    LongitudinalDerivatives {
        u0: BUSINESS_JET_U0,
        g: 32.2,
        theta0: 0.0,
        x_u: -0.0074,
        x_q: 0.0,
        x_alpha: 8.9782,
        x_alpha_dot: 0.0,
        x_de: 0.0,
        x_tu: 0.0,
        z_u: -0.1390,
        z_q: -1.8598,
        z_alpha: -445.7224,
        z_alpha_dot: -0.8705,
        z_de: -42.1968,
        z_tu: 0.0,
        m_u: 0.0011,
        m_q: -0.9397,
        m_alpha: -7.4416,
        m_alpha_dot: -0.4062,
        m_de: -17.6737,
        m_tu: -0.0002,
        m_talpha: 0.0,
    }
}

/// Business-jet lateral derivatives of Table 14.2 (J in slug·ft²).
///
/// Book: §14.3, Table 14.2.
pub fn business_jet_lateral() -> LateralDerivatives {
    LateralDerivatives {
        u0: BUSINESS_JET_U0,
        g: 32.2,
        jxx: 27_915.0,
        jzz: 47_085.0,
        jxz: 450.0,
        y_beta: -55.4022,
        y_p: 0.0,
        y_r: 0.7689,
        y_beta_dot: 0.0,
        y_da: 0.0,
        y_dr: 10.4733,
        l_beta: -4.1845,
        l_p: -0.4365,
        l_r: 0.1571,
        l_beta_dot: 0.0,
        l_da: 6.7714,
        l_dr: 0.6543,
        l_tbeta: 0.0,
        n_beta: 2.8643,
        n_p: 0.0046,
        n_r: -0.1148,
        n_beta_dot: 0.0,
        n_da: -0.3879,
        n_dr: -1.6847,
        n_tbeta: 0.0,
    }
}

/// The 747-100 longitudinal A at 40,000 ft, M 0.8, x = [u, δα, q, θ] as printed in §14.7.3.
///
/// Book: §14.7.3 (L14354–14400).
///
/// # Conventions
/// As printed: A(1,4) = −32.2 is in ft/s² although u is in m/s (a units erratum of the book,
/// notes [T]); the eigenvalues the book prints come from these numbers, so they are kept.
pub fn boeing_747_longitudinal_a() -> DMatrix<f64> {
    #[rustfmt::skip]
    let a = DMatrix::from_row_slice(4, 4, &[
        -2.02e-2, 7.88, -6.5e-1, -3.22e1,
        -2.54e-4, -1.02, 9.05e-1, 0.0,
        7.95e-11, -2.5, -1.39, 0.0,
        0.0, 0.0, 1.0, 0.0,
    ]);
    a
}

/// Assumed business-jet airframe behind Tables 14.1–14.2 (the book gives only the
/// dimensional derivatives and J_xx, J_zz, J_xz): weight 13,000 lb, S = 230 ft², c̄ = 7 ft,
/// b = 34 ft, J_yy = 25,000 slug·ft² (J_zz ≤ J_xx + J_yy needs J_yy ≥ 19,170), ρ = 0.000588 slug/ft³ (40,000 ft), C_D0 = 0.03.
///
/// Book: Tables 14.1, 14.2 (J_xx, J_zz, J_xz); the other values are assumptions of a
/// Learjet-class aircraft, chosen only to give the nondimensional model a scale.
pub const BUSINESS_JET_WEIGHT: f64 = 13_000.0;

/// A nonlinear business-jet [`Aircraft`] whose coefficients invert the definitions of
/// Tables 14.1–14.2 at U₀ = 400 kt, so that its dual-number linearization at the level trim
/// reproduces Tables 14.1–14.2 (the thrust-speed derivative M_Tu is folded into C_mu). Its
/// body frame is the stability frame of that trim (α₀ = 0, §12.4).
///
/// Book: Tables 14.1, 14.2; §12.4; (13.3.9)–(13.3.12).
pub fn business_jet() -> crate::Aircraft {
    use crate::{Aircraft, Airframe, Coefficients, Geometry};
    let lon = business_jet_longitudinal();
    let lat = business_jet_lateral();
    let (g, u0) = (lon.g, lon.u0);
    let m = BUSINESS_JET_WEIGHT / g;
    let jyy = 25_000.0;
    let geometry = Geometry { area: 230.0, chord: 7.0, span: 34.0 };
    let rho = 0.000_588;
    let qs = 0.5 * rho * u0 * u0 * geometry.area;
    let (cb, b) = (geometry.chord, geometry.span);
    // level trim at α = 0: lift = weight
    let cl0 = m * g / qs;
    let cd0 = 0.03;
    // Z_α = −p_d0S(C_Lα + C_D0)/m; X_α = p_d0S(C_L0 − 2K C_L0 C_Lα)/m
    let cl_alpha = -lon.z_alpha * m / qs - cd0;
    let k_induced = (cl0 - lon.x_alpha * m / qs) / (2.0 * cl0 * cl_alpha);
    // Z_u = −p_d0S(2C_L0 + C_Lu)/(mU₀); X_u = −p_d0S(2C_D0 + C_Du + 2K C_L0 C_Lu)/(mU₀)
    let cl_u = -lon.z_u * m * u0 / qs - 2.0 * cl0;
    let cd_u = -lon.x_u * m * u0 / qs - 2.0 * cd0 - 2.0 * k_induced * cl0 * cl_u;
    let rate_l = 2.0 * m * u0 / (qs * cb);
    let rate_m = 2.0 * jyy * u0 / (qs * cb * cb);
    let rate_y = 2.0 * m * u0 / (qs * b);
    let (jxx, jzz) = (lat.jxx, lat.jzz);
    let rate_roll = 2.0 * jxx * u0 / (qs * b * b);
    let rate_n = 2.0 * jzz * u0 / (qs * b * b);
    let coefficients = Coefficients {
        u_ref: u0,
        cl0,
        cl_u,
        cl_alpha,
        cl_q: -lon.z_q * rate_l,
        cl_alpha_dot: -lon.z_alpha_dot * rate_l,
        cl_de: -lon.z_de * m / qs,
        cd_par: cd0 - k_induced * cl0 * cl0,
        k_induced,
        cd_u,
        cm0: 0.0,
        cm_u: (lon.m_u + lon.m_tu) * jyy * u0 / (qs * cb),
        cm_alpha: lon.m_alpha * jyy / (qs * cb),
        cm_q: lon.m_q * rate_m,
        cm_alpha_dot: lon.m_alpha_dot * rate_m,
        cm_de: lon.m_de * jyy / (qs * cb),
        ce_beta: -lat.y_beta * m / qs - cd0,
        ce_beta_dot: -lat.y_beta_dot * rate_y,
        ce_p: -lat.y_p * rate_y,
        ce_r: -lat.y_r * rate_y,
        ce_da: -lat.y_da * m / qs,
        ce_dr: -lat.y_dr * m / qs,
        croll_beta: lat.l_beta * jxx / (qs * b),
        croll_beta_dot: lat.l_beta_dot * rate_roll,
        croll_p: lat.l_p * rate_roll,
        croll_r: lat.l_r * rate_roll,
        croll_da: lat.l_da * jxx / (qs * b),
        croll_dr: lat.l_dr * jxx / (qs * b),
        cn_beta: lat.n_beta * jzz / (qs * b),
        cn_beta_dot: lat.n_beta_dot * rate_n,
        cn_p: lat.n_p * rate_n,
        cn_r: lat.n_r * rate_n,
        cn_da: lat.n_da * jzz / (qs * b),
        cn_dr: lat.n_dr * jzz / (qs * b),
    };
    // the data are fixed and physical: J_xz² ≪ J_xx J_zz, all moments positive
    let airframe = match Airframe::new(m, jxx, jyy, jzz, lat.jxz) {
        Ok(a) => a,
        Err(e) => unreachable!("business-jet data are valid: {e}"),
    };
    Aircraft { airframe, geometry, coefficients, rho, g, thrust_angle: 0.0 }
}
