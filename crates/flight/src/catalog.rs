//! Ready-made aircraft: the business jet of Tables 14.1–14.2 and the 747 of §14.7.3.
//!
//! Book: §14.1 Table 14.1, §14.3 Table 14.2 (source "[10, p.330]"), §14.7.3 (747-100,
//! 40,000 ft, M 0.8); notes ch9-14 §4.

use nalgebra::DMatrix;
use vectrix_units::{Quantity, UnitSystem};

use crate::{LateralDerivatives, LongitudinalDerivatives};

/// A catalogue datum as the book prints it (`"-445.7224 ft/s^2/rad"`), in the unit `system`
/// uses for its dimension, converted exactly (one rounding; none when the units already
/// match, so the imperial data are the printed numbers bit for bit).
///
/// The data are constants of this file, every one parsed by the test `catalog_data_parse`:
/// a failure here is a typo in the table, not a user error.
fn datum(text: &str, system: UnitSystem) -> f64 {
    match Quantity::parse(text).and_then(|q| q.in_system(system)) {
        Ok(v) => v,
        Err(e) => unreachable!("catalog datum `{text}`: {e}"),
    }
}

/// Business-jet cruise speed U₀ = 400 kt in ft/s: 400 · 1852/(3600 · 0.3048) =
/// 675.12394284… ft/s, the `f64` nearest to it (the knot is exactly 1852/3600 m/s; an earlier
/// 1 kt = 1.68781 ft/s gave 675.124).
///
/// Book: Table 14.1 ("U₀ = 400 kt"), §15.19.
pub const BUSINESS_JET_U0: f64 = 675.123_942_840_478_3;

/// U₀ as printed under Tables 14.1–14.2.
const U0: &str = "400 kt";
/// g as §14's numbers use it (32.2 ft/s², the book's rounding of g₀ = 32.174 ft/s²).
const G: &str = "32.2 ft/s^2";

/// Table 14.1, each field of [`LongitudinalDerivatives`] with its value and units column as
/// printed ("ft/sec²-rad" is written `ft/s^2/rad`, "rad/ft-sec" `rad/ft/s`). X_q and X_α̇
/// are printed in "1/sec", a units slip (X_q q is an acceleration, so X_q is in ft/(s·rad));
/// they are 0, entered in the consistent unit.
fn table_14_1(d: &mut LongitudinalDerivatives) -> [(&mut f64, &'static str); 19] {
    [
        (&mut d.x_u, "-0.0074 1/s"),              // X_u
        (&mut d.x_q, "0 ft/s/rad"),               // X_q (printed 1/sec)
        (&mut d.x_alpha, "8.9782 ft/s^2/rad"),    // X_α
        (&mut d.x_alpha_dot, "0 ft/s/rad"),       // X_α̇ (printed 1/sec)
        (&mut d.x_de, "0 ft/s^2/rad"),            // X_δe
        (&mut d.x_tu, "0 1/s"),                   // X_Tu
        (&mut d.z_u, "-0.1390 1/s"),              // Z_u
        (&mut d.z_q, "-1.8598 ft/s/rad"),         // Z_q
        (&mut d.z_alpha, "-445.7224 ft/s^2/rad"), // Z_α
        (&mut d.z_alpha_dot, "-0.8705 ft/s/rad"), // Z_α̇
        (&mut d.z_de, "-42.1968 ft/s^2/rad"),     // Z_δe
        (&mut d.z_tu, "0 1/s"),                   // Z_Tu
        (&mut d.m_u, "0.0011 rad/ft/s"),          // M_u
        (&mut d.m_q, "-0.9397 1/s"),              // M_q
        (&mut d.m_alpha, "-7.4416 1/s^2"),        // M_α
        (&mut d.m_alpha_dot, "-0.4062 1/s"),      // M_α̇
        (&mut d.m_de, "-17.6737 1/s^2"),          // M_δe
        (&mut d.m_tu, "-0.0002 1/ft/s"),          // M_Tu
        (&mut d.m_talpha, "0 1/s^2"),             // M_Tα
    ]
}

/// Table 14.2, each field of [`LateralDerivatives`] with its value and units as printed.
fn table_14_2(d: &mut LateralDerivatives) -> [(&mut f64, &'static str); 23] {
    [
        (&mut d.jxx, "27915 slug*ft^2"),        // J_xx ("slg-ft²")
        (&mut d.jzz, "47085 slug*ft^2"),        // J_zz
        (&mut d.jxz, "450 slug*ft^2"),          // J_xz
        (&mut d.y_beta, "-55.4022 ft/s^2/rad"), // Y_β
        (&mut d.y_p, "0 ft/s/rad"),             // Y_p
        (&mut d.y_r, "0.7689 ft/s/rad"),        // Y_r
        (&mut d.y_beta_dot, "0 ft/s/rad"),      // Y_β̇
        (&mut d.y_da, "0 ft/s^2/rad"),          // Y_δa
        (&mut d.y_dr, "10.4733 ft/s^2/rad"),    // Y_δr
        (&mut d.l_beta, "-4.1845 1/s^2"),       // L_β
        (&mut d.l_p, "-0.4365 1/s"),            // L_p
        (&mut d.l_r, "0.1571 1/s"),             // L_r
        (&mut d.l_beta_dot, "0 1/s"),           // L_β̇
        (&mut d.l_da, "6.7714 1/s^2"),          // L_δa
        (&mut d.l_dr, "0.6543 1/s^2"),          // L_δr
        (&mut d.l_tbeta, "0 1/s^2"),            // L_Tβ
        (&mut d.n_beta, "2.8643 1/s^2"),        // N_β
        (&mut d.n_p, "0.0046 1/s"),             // N_p
        (&mut d.n_r, "-0.1148 1/s"),            // N_r
        (&mut d.n_beta_dot, "0 1/s"),           // N_β̇
        (&mut d.n_da, "-0.3879 1/s^2"),         // N_δa
        (&mut d.n_dr, "-1.6847 1/s^2"),         // N_δr
        (&mut d.n_tbeta, "0 1/s^2"),            // N_Tβ
    ]
}

/// Business-jet longitudinal derivatives of Table 14.1 in the book's units (ft, s, rad;
/// g = 32.2 ft/s²): [`business_jet_longitudinal_in`] with [`UnitSystem::Imperial`].
///
/// Book: §14.1, Table 14.1.
pub fn business_jet_longitudinal() -> LongitudinalDerivatives {
    business_jet_longitudinal_in(UnitSystem::Imperial)
}

/// Table 14.1 in a unit system: the printed quantities converted exactly (ft → m for every
/// derivative with a length, 400 kt → m/s or ft/s, 32.2 ft/s² → 9.81456 m/s²). The modes, in
/// 1/s, are the same in both systems to rounding.
///
/// Book: §14.1, Table 14.1; §15.19.
pub fn business_jet_longitudinal_in(system: UnitSystem) -> LongitudinalDerivatives {
    let mut d = LongitudinalDerivatives { u0: datum(U0, system), g: datum(G, system), ..Default::default() };
    for (field, printed) in table_14_1(&mut d) {
        *field = datum(printed, system);
    }
    d
}

/// Business-jet lateral derivatives of Table 14.2 in the book's units (J in slug·ft²):
/// [`business_jet_lateral_in`] with [`UnitSystem::Imperial`].
///
/// Book: §14.3, Table 14.2.
pub fn business_jet_lateral() -> LateralDerivatives {
    business_jet_lateral_in(UnitSystem::Imperial)
}

/// Table 14.2 in a unit system, converted exactly (slug·ft² → kg·m², ft → m).
///
/// Book: §14.3, Table 14.2; §15.19.
pub fn business_jet_lateral_in(system: UnitSystem) -> LateralDerivatives {
    let mut d = LateralDerivatives { u0: datum(U0, system), g: datum(G, system), ..Default::default() };
    for (field, printed) in table_14_2(&mut d) {
        *field = datum(printed, system);
    }
    d
}

/// The 747-100 longitudinal A at 40,000 ft, M 0.8, x = [u, δα, q, θ] as printed in §14.7.3.
///
/// Book: §14.7.3 (L14354–14400).
///
/// # Conventions
/// As printed, numbers only: the book prints no units in (14.7.3) and states u in m/s for the
/// same matrix in P14.9.5, while A(1,4) = −32.2 is g in ft/s² (a units erratum, notes [T]).
/// The eigenvalues the book prints come from these numbers, so they are kept and not
/// converted; a units-consistent matrix (−32.2 ft/s² = −9.81456 m/s²) has another phugoid.
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

/// Assumed business-jet weight, 13,000 lbf (in lbf; see [`business_jet_in`]).
///
/// Book: Tables 14.1, 14.2 give only the dimensional derivatives and J_xx, J_zz, J_xz; this
/// and the other airframe values are assumptions of a Learjet-class aircraft, chosen only to
/// give the nondimensional model a scale.
pub const BUSINESS_JET_WEIGHT: f64 = 13_000.0;

/// The assumed airframe behind Tables 14.1–14.2, with units: weight, wing area S, chord c̄,
/// span b, J_yy (J_zz ≤ J_xx + J_yy needs J_yy ≥ 19,170 slug·ft²), density ρ at 40,000 ft.
const AIRFRAME: [&str; 6] =
    ["13000 lbf", "230 ft^2", "7 ft", "34 ft", "25000 slug*ft^2", "0.000588 slug/ft^3"];

/// A nonlinear business-jet [`crate::Aircraft`] in the book's units (slug, ft, s):
/// [`business_jet_in`] with [`UnitSystem::Imperial`].
///
/// Book: Tables 14.1, 14.2; §12.4; (13.3.9)–(13.3.12).
pub fn business_jet() -> crate::Aircraft {
    business_jet_in(UnitSystem::Imperial)
}

/// A nonlinear business-jet [`crate::Aircraft`] whose coefficients invert the definitions of
/// Tables 14.1–14.2 at U₀ = 400 kt, so that its dual-number linearization at the level trim
/// reproduces Tables 14.1–14.2 (the thrust-speed derivative M_Tu is folded into C_mu). Its
/// body frame is the stability frame of that trim (α₀ = 0, §12.4). Assumed airframe: weight
/// 13,000 lbf, S = 230 ft², c̄ = 7 ft, b = 34 ft, J_yy = 25,000 slug·ft²,
/// ρ = 0.000588 slug/ft³ (40,000 ft), C_D0 = 0.03. All data are converted exactly into
/// `system`; the coefficients are dimensionless, so both systems give the same ones to
/// rounding.
///
/// Book: Tables 14.1, 14.2; §12.4; (13.3.9)–(13.3.12); §15.19.
pub fn business_jet_in(system: UnitSystem) -> crate::Aircraft {
    use crate::{Aircraft, Airframe, Coefficients, Geometry};
    let lon = business_jet_longitudinal_in(system);
    let lat = business_jet_lateral_in(system);
    let (g, u0) = (lon.g, lon.u0);
    let [weight, area, chord, span, jyy, rho] = AIRFRAME.map(|t| datum(t, system));
    let m = weight / g;
    let geometry = Geometry { area, chord, span };
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

#[cfg(test)]
mod tests {
    use vectrix_units::{Quantity, Unit, UnitSystem};

    use super::*;

    // Every datum parses, and in the book's own system each is the printed number bit for bit
    // (the conversion factor is exactly 1): the catalogue is the book's table.
    #[test]
    fn catalog_data_parse() {
        let (mut lon, mut lat) = (LongitudinalDerivatives::default(), LateralDerivatives::default());
        let printed =
            table_14_1(&mut lon).map(|(_, t)| t).into_iter().chain(table_14_2(&mut lat).map(|(_, t)| t));
        for text in printed.chain(AIRFRAME).chain([G, U0]) {
            let q = Quantity::parse(text).unwrap_or_else(|e| panic!("{text}: {e}"));
            if text != U0 {
                assert_eq!(
                    q.in_system(UnitSystem::Imperial).unwrap().to_bits(),
                    q.value().to_bits(),
                    "{text}"
                );
            }
            assert!(q.in_system(UnitSystem::Si).is_ok());
        }
        assert_eq!(business_jet_longitudinal().z_alpha, -445.7224);
        assert_eq!(business_jet_lateral().jxx, 27_915.0);
        assert_eq!(datum(AIRFRAME[0], UnitSystem::Imperial), BUSINESS_JET_WEIGHT);
    }

    // U₀ = 400 kt is 675.12394284… ft/s, the constant rounded once.
    #[test]
    fn u0_is_400_knots_exactly() {
        let ft_s = Unit::parse("ft/s").unwrap();
        assert_eq!(Quantity::parse(U0).unwrap().to_unit(&ft_s).unwrap(), BUSINESS_JET_U0);
        assert_eq!(business_jet_longitudinal().u0, BUSINESS_JET_U0);
        assert_eq!(business_jet_longitudinal_in(UnitSystem::Si).u0, 400.0 * 1852.0 / 3600.0);
    }
}
