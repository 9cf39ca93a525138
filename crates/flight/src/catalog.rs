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
