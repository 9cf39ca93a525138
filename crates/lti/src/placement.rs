//! Pole placement by full-state feedback: Ackermann's formula for one input.
//!
//! Book: 15.20.54 (Matlab `place`); notes §2 (SISO Ackermann, the documented limit).

use crate::error::LtiError;
use crate::linalg::{rank, to_faer};
use crate::poly::Polynomial;
use crate::ss::StateSpace;
use faer::linalg::solvers::Solve;
use nalgebra::DMatrix;
use num_complex::Complex64;

impl StateSpace {
    /// The state-feedback gain K (1 × n) that places the eigenvalues of A − bK at `poles`, for
    /// u = −Kx through input column b = B[:, input] (Matlab `place`/`acker` conventions):
    /// Ackermann's formula K = e_nᵀ 𝒞⁻¹ p(A), with 𝒞 = [b Ab … Aⁿ⁻¹b] the controllability
    /// matrix and p(s) = ∏(s − pᵢ) the desired characteristic polynomial.
    ///
    /// # Conventions
    /// One input only (the other inputs are left open); complex poles in conjugate pairs. The
    /// formula is exact in exact arithmetic and fine for the small systems of the book; its
    /// conditioning is that of 𝒞, which grows quickly with n.
    ///
    /// Book: 15.20.54; (15.7.3) (for a companion realisation K is the difference of the
    /// coefficient vectors).
    ///
    /// # Errors
    /// [`LtiError::IndexOutOfRange`] for a bad input; [`LtiError::DimensionMismatch`] unless
    /// there are n poles; [`LtiError::UnpairedComplexRoot`], [`LtiError::NonFinite`] for the
    /// poles; [`LtiError::InvalidArgument`] when (A, b) is not controllable (rank 𝒞 < n at the
    /// relative tolerance 1e-12); [`LtiError::Overflow`].
    pub fn place(&self, input: usize, poles: &[Complex64]) -> Result<DMatrix<f64>, LtiError> {
        if input >= self.n_inputs() {
            return Err(LtiError::IndexOutOfRange { what: "input", index: input, len: self.n_inputs() });
        }
        let n = self.n_states();
        if poles.len() != n {
            return Err(LtiError::DimensionMismatch {
                what: "poles",
                expected: format!("{n} (one per state)"),
                found: format!("{}", poles.len()),
            });
        }
        let p = Polynomial::from_roots(poles)?;
        if n == 0 {
            return Ok(DMatrix::zeros(1, 0));
        }
        let single = self.channel(0, input)?;
        let ctrb = single.ctrb();
        let r = rank(&ctrb, 1e-12)?;
        if r < n {
            return Err(LtiError::InvalidArgument {
                what: "pole placement",
                reason: format!("(A, b) is not controllable: rank [b Ab … Aⁿ⁻¹b] = {r} < n = {n}"),
            });
        }
        // p(A) by Horner's rule on matrices
        let a = self.a();
        let mut pa = DMatrix::<f64>::zeros(n, n);
        for &c in p.coeffs() {
            pa = &pa * a;
            for i in 0..n {
                pa[(i, i)] += c;
            }
        }
        // q = 𝒞⁻ᵀ e_n, so e_nᵀ𝒞⁻¹ = qᵀ; then K = qᵀ p(A)
        let mut en = faer::Mat::<f64>::zeros(n, 1);
        en[(n - 1, 0)] = 1.0;
        let q = to_faer(&ctrb.transpose()).partial_piv_lu().solve(&en);
        let k: DMatrix<f64> = DMatrix::from_fn(1, n, |_, j| (0..n).map(|i| q[(i, 0)] * pa[(i, j)]).sum());
        if k.iter().all(|x| x.is_finite()) {
            Ok(k)
        } else {
            Err(LtiError::Overflow { what: "feedback gain" })
        }
    }
}
