//! Dimensional stability derivatives and the linear longitudinal and lateral models in
//! descriptor form Υẋ = A₀x + B₀u (14.1.7) and Γẋ = A₀x + B₀u (14.3), with the explicit
//! state space ẋ = Υ⁻¹A₀x + Υ⁻¹B₀u built through `vectrix-lti`.
//!
//! Book: §14.1, (14.1.1)–(14.1.15), Table 14.1; §14.3, Table 14.2; notes ch9-14 §2.
//!
//! # Conventions
//! Longitudinal state x = [u, δα, q, θ] (u in ft/s or m/s, angles in rad), input δe.
//! Lateral state x = [r, δβ, p, φ], inputs [δa, δr]. Derivatives are the book's dimensional
//! ones (X_u = ∂(f_x/m)/∂u, M_α = ∂(m_A/J_yy)/∂δα, …), in the stability axes of the trim
//! (§12.4: W₀ = 0, Θ₀ = γ₀).
//!
//! # Errata corrected
//! Row 3 of the printed A = Υ⁻¹A₀ (14.1.13) carries (U₀ − Z_α̇)²; the correct single power
//! is what Υ⁻¹ gives (and what reproduces P14.9.4). The printed Γ⁻¹ (14.3.10) (1,2) entry has
//! J_xz where J_xx belongs; we never print Γ⁻¹, we solve with it.

use nalgebra::DMatrix;
use vectrix_lti::StateSpace;

use crate::FlightError;

/// Dimensional longitudinal derivatives of Table 14.1 at a trim speed U₀.
///
/// Book: §14.1, (14.1.1)–(14.1.7), Table 14.1.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[allow(missing_docs)] // each field is the book's symbol, named in the struct doc above
pub struct LongitudinalDerivatives {
    /// Trim speed U₀.
    pub u0: f64,
    /// Gravity g (32.2 ft/s² or 9.8 m/s²).
    pub g: f64,
    /// Trim pitch angle Θ₀ (0 in level flight): gravity enters as −g cos Θ₀ θ (12.3.50).
    pub theta0: f64,
    pub x_u: f64,
    pub x_q: f64,
    pub x_alpha: f64,
    pub x_alpha_dot: f64,
    pub x_de: f64,
    pub x_tu: f64,
    pub z_u: f64,
    pub z_q: f64,
    pub z_alpha: f64,
    pub z_alpha_dot: f64,
    pub z_de: f64,
    pub z_tu: f64,
    pub m_u: f64,
    pub m_q: f64,
    pub m_alpha: f64,
    pub m_alpha_dot: f64,
    pub m_de: f64,
    pub m_tu: f64,
    pub m_talpha: f64,
}

/// Dimensional lateral derivatives of Table 14.2 at a trim speed U₀.
///
/// Book: §14.3, Table 14.2.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[allow(missing_docs)] // each field is the book's symbol, named in the struct doc above
pub struct LateralDerivatives {
    /// Trim speed U₀.
    pub u0: f64,
    /// Gravity g.
    pub g: f64,
    /// J_xx, J_zz, J_xz of (11.3.6) (J_xz = ∫xz dm).
    pub jxx: f64,
    pub jzz: f64,
    pub jxz: f64,
    pub y_beta: f64,
    pub y_p: f64,
    pub y_r: f64,
    pub y_beta_dot: f64,
    pub y_da: f64,
    pub y_dr: f64,
    pub l_beta: f64,
    pub l_p: f64,
    pub l_r: f64,
    pub l_beta_dot: f64,
    pub l_da: f64,
    pub l_dr: f64,
    pub l_tbeta: f64,
    pub n_beta: f64,
    pub n_p: f64,
    pub n_r: f64,
    pub n_beta_dot: f64,
    pub n_da: f64,
    pub n_dr: f64,
    pub n_tbeta: f64,
}

/// A linear descriptor system E ẋ = A₀x + B₀u with nonsingular E.
///
/// Book: (14.1.7), (14.3.x); notes ch9-14 §3 (implicit α̇/β̇ dependence).
#[derive(Debug, Clone, PartialEq)]
pub struct Descriptor {
    /// E (Υ or Γ).
    pub e: DMatrix<f64>,
    /// A₀.
    pub a0: DMatrix<f64>,
    /// B₀.
    pub b0: DMatrix<f64>,
}

impl Descriptor {
    /// The explicit state space ẋ = E⁻¹A₀x + E⁻¹B₀u, y = x (C = I, D = 0).
    ///
    /// Book: (14.1.13) corrected, (14.3.10) corrected.
    ///
    /// # Errors
    /// [`FlightError::SingularDescriptor`] if E is singular; [`FlightError::NonFinite`].
    pub fn to_state_space(&self, what: &'static str) -> Result<StateSpace, FlightError> {
        if self.e.iter().chain(self.a0.iter()).chain(self.b0.iter()).any(|x| !x.is_finite()) {
            return Err(FlightError::NonFinite { what });
        }
        let lu = self.e.clone().lu();
        let (a, b) = match (lu.solve(&self.a0), lu.solve(&self.b0)) {
            (Some(a), Some(b)) => (a, b),
            _ => {
                return Err(FlightError::SingularDescriptor {
                    what,
                    reason: "E is singular (U₀ − Z_α̇ = 0 or U₀ − Y_β̇ = 0, or J_xx J_zz = J_xz²)".into(),
                });
            }
        };
        if a.iter().chain(b.iter()).any(|x| !x.is_finite()) {
            return Err(FlightError::SingularDescriptor { what, reason: "E⁻¹ overflowed".into() });
        }
        let n = a.nrows();
        let m = b.ncols();
        Ok(StateSpace::new(a, b, DMatrix::identity(n, n), DMatrix::zeros(n, m))?)
    }
}

fn check_all(values: &[f64], what: &'static str) -> Result<(), FlightError> {
    if values.iter().all(|v| v.is_finite()) { Ok(()) } else { Err(FlightError::NonFinite { what }) }
}

impl LongitudinalDerivatives {
    fn values(&self) -> [f64; 22] {
        [
            self.u0,
            self.g,
            self.theta0,
            self.x_u,
            self.x_q,
            self.x_alpha,
            self.x_alpha_dot,
            self.x_de,
            self.x_tu,
            self.z_u,
            self.z_q,
            self.z_alpha,
            self.z_alpha_dot,
            self.z_de,
            self.z_tu,
            self.m_u,
            self.m_q,
            self.m_alpha,
            self.m_alpha_dot,
            self.m_de,
            self.m_tu,
            self.m_talpha,
        ]
    }

    /// The descriptor form Υẋ = A₀x + B₀δe of (14.1.7), x = [u, δα, q, θ]:
    /// Υ = [[1, −X_α̇, 0, 0], [0, U₀ − Z_α̇, 0, 0], [0, −M_α̇, 1, 0], [0, 0, 0, 1]],
    /// A₀ = [[X_u+X_Tu, X_α, X_q, −g cos Θ₀], [Z_u+Z_Tu, Z_α, U₀+Z_q, −g sin Θ₀],
    ///       [M_u+M_Tu, M_α+M_Tα, M_q, 0], [0, 0, 1, 0]], B₀ = [X_δe, Z_δe, M_δe, 0]ᵀ.
    ///
    /// Book: (14.1.7), Table 14.1; gravity terms of (12.3.50), (12.3.52) (zero for Θ₀ = 0
    /// except −g).
    ///
    /// # Errors
    /// [`FlightError::NonFinite`]; [`FlightError::OutOfRange`] unless U₀ > 0.
    pub fn descriptor(&self) -> Result<Descriptor, FlightError> {
        check_all(&self.values(), "longitudinal derivatives")?;
        if self.u0 <= 0.0 {
            return Err(FlightError::OutOfRange { what: "U₀", value: self.u0, valid: "a speed > 0" });
        }
        let (s0, c0) = self.theta0.sin_cos();
        #[rustfmt::skip]
        let e = DMatrix::from_row_slice(4, 4, &[
            1.0, -self.x_alpha_dot, 0.0, 0.0,
            0.0, self.u0 - self.z_alpha_dot, 0.0, 0.0,
            0.0, -self.m_alpha_dot, 1.0, 0.0,
            0.0, 0.0, 0.0, 1.0,
        ]);
        // (14.1.7): the δα row is U₀δα̇ = ẇ, so its gravity term is −g sin Θ₀ θ (12.3.52).
        #[rustfmt::skip]
        let a0 = DMatrix::from_row_slice(4, 4, &[
            self.x_u + self.x_tu, self.x_alpha, self.x_q, -self.g * c0,
            self.z_u + self.z_tu, self.z_alpha, self.u0 + self.z_q, -self.g * s0,
            self.m_u + self.m_tu, self.m_alpha + self.m_talpha, self.m_q, 0.0,
            0.0, 0.0, 1.0, 0.0,
        ]);
        let b0 = DMatrix::from_column_slice(4, 1, &[self.x_de, self.z_de, self.m_de, 0.0]);
        Ok(Descriptor { e, a0, b0 })
    }

    /// The explicit model ẋ = Ax + Bδe with A = Υ⁻¹A₀, B = Υ⁻¹B₀, outputs y = x.
    ///
    /// Book: (14.1.13) with the erratum (U₀ − Z_α̇)² → (U₀ − Z_α̇) corrected.
    ///
    /// # Errors
    /// As [`LongitudinalDerivatives::descriptor`]; [`FlightError::SingularDescriptor`] when
    /// U₀ = Z_α̇.
    pub fn state_space(&self) -> Result<StateSpace, FlightError> {
        self.descriptor()?.to_state_space("longitudinal model")
    }
}

impl LateralDerivatives {
    fn values(&self) -> [f64; 26] {
        [
            self.u0,
            self.g,
            self.jxx,
            self.jzz,
            self.jxz,
            self.y_beta,
            self.y_p,
            self.y_r,
            self.y_beta_dot,
            self.y_da,
            self.y_dr,
            self.l_beta,
            self.l_p,
            self.l_r,
            self.l_beta_dot,
            self.l_da,
            self.l_dr,
            self.l_tbeta,
            self.n_beta,
            self.n_p,
            self.n_r,
            self.n_beta_dot,
            self.n_da,
            self.n_dr,
            self.n_tbeta,
            0.0,
        ]
    }

    /// The descriptor form Γẋ = A₀x + B₀[δa, δr] of §14.3, x = [r, δβ, p, φ]:
    /// Γ = [[1, −N_β̇, −J_xz/J_zz, 0], [0, U₀ − Y_β̇, 0, 0], [−J_xz/J_xx, −L_β̇, 1, 0], [0, 0, 0, 1]],
    /// A₀ = [[N_r, N_β+N_Tβ, N_p, 0], [Y_r − U₀, Y_β, Y_p, g], [L_r, L_β+L_Tβ, L_p, 0], [0, 0, 1, 0]].
    ///
    /// Book: §14.3, (14.3.x), Table 14.2.
    ///
    /// # Errors
    /// [`FlightError::NonFinite`]; [`FlightError::OutOfRange`] unless U₀, J_xx, J_zz > 0.
    pub fn descriptor(&self) -> Result<Descriptor, FlightError> {
        check_all(&self.values(), "lateral derivatives")?;
        for (what, value) in [("U₀", self.u0), ("J_xx", self.jxx), ("J_zz", self.jzz)] {
            if value <= 0.0 {
                return Err(FlightError::OutOfRange { what, value, valid: "a number > 0" });
            }
        }
        #[rustfmt::skip]
        let e = DMatrix::from_row_slice(4, 4, &[
            1.0, -self.n_beta_dot, -self.jxz / self.jzz, 0.0,
            0.0, self.u0 - self.y_beta_dot, 0.0, 0.0,
            -self.jxz / self.jxx, -self.l_beta_dot, 1.0, 0.0,
            0.0, 0.0, 0.0, 1.0,
        ]);
        #[rustfmt::skip]
        let a0 = DMatrix::from_row_slice(4, 4, &[
            self.n_r, self.n_beta + self.n_tbeta, self.n_p, 0.0,
            self.y_r - self.u0, self.y_beta, self.y_p, self.g,
            self.l_r, self.l_beta + self.l_tbeta, self.l_p, 0.0,
            0.0, 0.0, 1.0, 0.0,
        ]);
        #[rustfmt::skip]
        let b0 = DMatrix::from_row_slice(4, 2, &[
            self.n_da, self.n_dr,
            self.y_da, self.y_dr,
            self.l_da, self.l_dr,
            0.0, 0.0,
        ]);
        Ok(Descriptor { e, a0, b0 })
    }

    /// The explicit lateral model ẋ = Γ⁻¹A₀x + Γ⁻¹B₀[δa, δr], outputs y = x.
    ///
    /// Book: (14.3.10) with the Γ⁻¹(1,2) erratum (J_xz → J_xx) avoided by solving.
    ///
    /// # Errors
    /// As [`LateralDerivatives::descriptor`]; [`FlightError::SingularDescriptor`].
    pub fn state_space(&self) -> Result<StateSpace, FlightError> {
        self.descriptor()?.to_state_space("lateral model")
    }
}

impl LongitudinalDerivatives {
    /// Short-period approximation (u = 0, Z_α̇ = Z_q = M_α̇ = M_Tα = 0):
    /// p(s) = s² − (M_q + Z_α/U₀)s + (M_qZ_α/U₀ − M_α), so ω_sp = √(M_qZ_α/U₀ − M_α),
    /// ζ_sp = −(M_q + Z_α/U₀)/(2ω_sp).
    ///
    /// Book: §14.7, (14.7.23)–(14.7.29).
    ///
    /// # Errors
    /// From `vectrix-lti` for non-finite data.
    pub fn short_period_approximation(&self) -> Result<vectrix_lti::Polynomial, FlightError> {
        let za = self.z_alpha / self.u0;
        Ok(vectrix_lti::Polynomial::new(&[1.0, -(self.m_q + za), self.m_q * za - self.m_alpha])?)
    }

    /// Phugoid approximation (δα ≈ 0) (14.7.14):
    /// p(s) = s² − (X_u + X_Tu − (Z_u + Z_Tu)X_q/(U₀ + Z_q))s − (Z_u + Z_Tu)g/(U₀ + Z_q).
    ///
    /// Book: (14.7.14)–(14.7.22).
    ///
    /// # Errors
    /// From `vectrix-lti` for non-finite data.
    pub fn phugoid_approximation(&self) -> Result<vectrix_lti::Polynomial, FlightError> {
        let zu = self.z_u + self.z_tu;
        let d = self.u0 + self.z_q;
        Ok(vectrix_lti::Polynomial::new(&[
            1.0,
            -(self.x_u + self.x_tu - zu * self.x_q / d),
            -zu * self.g / d,
        ])?)
    }
}
