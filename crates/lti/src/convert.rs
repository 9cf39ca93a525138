//! Conversions between the N/D and zero–pole–gain forms of a transfer function, and the
//! zero–pole cancellation (`minreal`) that goes from one to the other and back. Kept apart from
//! both forms so that neither depends on the other.
//!
//! Book: (15.14.15), (15.18.1)–(15.18.6); 15.20.37, 15.20.38.

use crate::error::{LtiError, check_finite};
use crate::poly::Polynomial;
use crate::tf::TransferFunction;
use crate::zpk::Zpk;

impl TransferFunction {
    /// Zero–pole–gain form G = k∏(s − zᵢ)/∏(s − pᵢ)·e^{−τs}.
    ///
    /// # Errors
    /// [`LtiError::NoConvergence`] if a root computation fails.
    pub fn to_zpk(&self) -> Result<Zpk, LtiError> {
        let k = if self.num().is_zero() { 0.0 } else { self.num().leading() / self.den().leading() };
        Zpk::new(self.zeros()?, self.poles()?, k)?.with_delay(self.delay())
    }

    /// Cancels zero–pole pairs closer than `tol·max(1, |p|)` (Matlab `minreal`); the result is
    /// rebuilt from the remaining roots with the same high-frequency gain.
    ///
    /// Book: (15.14.15), 15.20.37, 15.20.38.
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] for a non-finite or negative tolerance;
    /// [`LtiError::NoConvergence`] if a root computation fails.
    pub fn minreal(&self, tol: f64) -> Result<Self, LtiError> {
        check_finite("tolerance", [&tol])?;
        if tol < 0.0 {
            return Err(LtiError::InvalidArgument { what: "tolerance", reason: format!("{tol} < 0") });
        }
        if self.num().is_zero() {
            let zero = Self::from_polynomials(Polynomial::constant(0.0), Polynomial::constant(1.0))?;
            return Ok(zero.with_delay_unchecked(self.delay()));
        }
        let zpk = self.to_zpk()?.minreal(tol);
        Ok(zpk.to_tf()?.with_delay_unchecked(self.delay()))
    }
}

impl Zpk {
    /// Back to N/D with N = k∏(s − zᵢ), D = ∏(s − pᵢ).
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] (cannot happen for a validated Zpk).
    pub fn to_tf(&self) -> Result<TransferFunction, LtiError> {
        let num = Polynomial::from_roots(self.zeros())?.scaled(self.gain());
        let den = Polynomial::from_roots(self.poles())?;
        TransferFunction::from_polynomials(num, den)?.with_delay(self.delay())
    }
}
