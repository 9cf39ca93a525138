//! Dimensional derivatives from nondimensional coefficients: the definitions of Tables 14.1
//! and 14.2 (with the ∂p_d/∂(u/U₀) = 2p_d0 terms of (13.3.30–52)).
//!
//! Book: §13.3–13.5, (13.3.30)–(13.3.52), (13.5.14); Tables 14.1, 14.2.
//!
//! # Conventions
//! Valid in the stability axes of a straight, wings-level trim (§12.4: W₀ = 0, β₀ = 0, body
//! frame = the frame the coefficients are referred to, α₀ = 0). The erratum in the signs of
//! X_q, X_α̇, X_δe of (14.1.1) is avoided: they follow from the drag polar, and are zero for
//! the polar of [`Aircraft::wing_lift_coefficient`].

use crate::{Aircraft, FlightError, LateralDerivatives, LongitudinalDerivatives, Trim};

struct Cond {
    u0: f64,
    qs: f64,
    m: f64,
    cl0: f64,
    cd0: f64,
    cm0: f64,
}

fn condition(ac: &Aircraft, trim: &Trim) -> Result<Cond, FlightError> {
    if !(trim.state.to_array().iter().chain(trim.controls.to_array().iter()).all(|x| x.is_finite())) {
        return Err(FlightError::NonFinite { what: "trim state or controls" });
    }
    let [u0, v0, w0] = trim.state.velocity;
    if w0.abs() > 1e-9 * u0.abs() || v0.abs() > 1e-9 * u0.abs() || u0 <= 0.0 {
        return Err(FlightError::OutOfRange {
            what: "trim α₀ (W₀/U₀)",
            value: w0 / u0,
            valid: "0: Table 14.1 holds in the stability axes of the trim (§12.4)",
        });
    }
    let x = &trim.state;
    let c = &ac.coefficients;
    let qs = ac.dynamic_pressure(u0) * ac.geometry.area;
    let cl0 = ac.lift_coefficient(x, &trim.controls, 0.0);
    let clw = ac.wing_lift_coefficient(x);
    let cd0 = c.cd_par + c.k_induced * clw * clw;
    // trimmed (Q̇ = 0, thrust through c): the total C_m is zero; this is its value from the model
    let cm0 = c.cm0 + c.cm_alpha * x.aero_angles().alpha + c.cm_de * trim.controls.elevator;
    Ok(Cond { u0, qs, m: ac.airframe.mass(), cl0, cd0, cm0 })
}

impl LongitudinalDerivatives {
    /// Table 14.1 from coefficients at a stability-axis trim: e.g.
    /// X_u = −p_d0S(2C_D0 + C_Du)/(mU₀), X_α = p_d0S(C_L0 − C_Dα)/m,
    /// Z_u = −p_d0S(2C_L0 + C_Lu)/(mU₀), Z_α = −p_d0S(C_Lα + C_D0)/m, Z_q = −p_d0Sc̄C_Lq/(2mU₀),
    /// M_α = p_d0Sc̄C_mα/J_yy, M_q = p_d0Sc̄²C_mq/(2J_yyU₀), with C_D• = 2K C_Lw0 C_Lw• (13.3.12).
    ///
    /// Book: Table 14.1, (13.3.30)–(13.3.52), (13.5.14).
    ///
    /// # Errors
    /// [`FlightError::OutOfRange`] unless the trim has W₀ = V₀ = 0.
    pub fn from_aircraft(ac: &Aircraft, trim: &Trim) -> Result<Self, FlightError> {
        let k = condition(ac, trim)?;
        let c = &ac.coefficients;
        let (_, jyy, _, _) = ac.airframe.inertia();
        let (qs, m, u0, cb) = (k.qs, k.m, k.u0, ac.geometry.chord);
        let clw0 = ac.wing_lift_coefficient(&trim.state);
        // (13.3.12): C_D• = 2K C_L0 C_L• through the polar (wing lift only)
        let cd_u = c.cd_u + 2.0 * c.k_induced * clw0 * c.cl_u;
        let cd_alpha = 2.0 * c.k_induced * clw0 * c.cl_alpha;
        Ok(Self {
            u0,
            g: ac.g,
            theta0: trim.state.attitude.theta,
            x_u: -qs * (2.0 * k.cd0 + cd_u) / (m * u0),
            x_q: 0.0,
            x_alpha: qs * (k.cl0 - cd_alpha) / m,
            x_alpha_dot: 0.0,
            x_de: 0.0,
            x_tu: 0.0,
            z_u: -qs * (2.0 * k.cl0 + c.cl_u) / (m * u0),
            z_q: -qs * cb * c.cl_q / (2.0 * m * u0),
            z_alpha: -qs * (c.cl_alpha + k.cd0) / m,
            z_alpha_dot: -qs * cb * c.cl_alpha_dot / (2.0 * m * u0),
            z_de: -qs * c.cl_de / m,
            z_tu: 0.0,
            m_u: qs * cb * (2.0 * k.cm0 + c.cm_u) / (jyy * u0),
            m_q: qs * cb * cb * c.cm_q / (2.0 * jyy * u0),
            m_alpha: qs * cb * c.cm_alpha / jyy,
            m_alpha_dot: qs * cb * cb * c.cm_alpha_dot / (2.0 * jyy * u0),
            m_de: qs * cb * c.cm_de / jyy,
            m_tu: 0.0,
            m_talpha: 0.0,
        })
    }
}

impl LateralDerivatives {
    /// Table 14.2 from coefficients at a stability-axis trim: Y_β = −p_d0S(C_D0 + C_Eβ)/m,
    /// Y_p = −p_d0SbC_Ep/(2mU₀), L_β = p_d0SbC_lβ/J_xx, L_p = p_d0Sb²C_lp/(2J_xxU₀),
    /// N_β = p_d0SbC_nβ/J_zz, …
    ///
    /// Book: Table 14.2, (13.3.39), (13.5.3), (13.5.33).
    ///
    /// # Errors
    /// [`FlightError::OutOfRange`] unless the trim has W₀ = V₀ = 0.
    pub fn from_aircraft(ac: &Aircraft, trim: &Trim) -> Result<Self, FlightError> {
        let k = condition(ac, trim)?;
        let c = &ac.coefficients;
        let (jxx, _, jzz, jxz) = ac.airframe.inertia();
        let (qs, m, u0, b) = (k.qs, k.m, k.u0, ac.geometry.span);
        let rate = qs * b / (2.0 * u0);
        Ok(Self {
            u0,
            g: ac.g,
            jxx,
            jzz,
            jxz,
            y_beta: -qs * (k.cd0 + c.ce_beta) / m,
            y_p: -rate * c.ce_p / m,
            y_r: -rate * c.ce_r / m,
            y_beta_dot: -rate * c.ce_beta_dot / m,
            y_da: -qs * c.ce_da / m,
            y_dr: -qs * c.ce_dr / m,
            l_beta: qs * b * c.croll_beta / jxx,
            l_p: rate * b * c.croll_p / jxx,
            l_r: rate * b * c.croll_r / jxx,
            l_beta_dot: rate * b * c.croll_beta_dot / jxx,
            l_da: qs * b * c.croll_da / jxx,
            l_dr: qs * b * c.croll_dr / jxx,
            l_tbeta: 0.0,
            n_beta: qs * b * c.cn_beta / jzz,
            n_p: rate * b * c.cn_p / jzz,
            n_r: rate * b * c.cn_r / jzz,
            n_beta_dot: rate * b * c.cn_beta_dot / jzz,
            n_da: qs * b * c.cn_da / jzz,
            n_dr: qs * b * c.cn_dr / jzz,
            n_tbeta: 0.0,
        })
    }
}
