//! Errors of the linear-systems crate.

use thiserror::Error;

/// What was wrong with a linear-systems input, with what would be valid.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum LtiError {
    /// A coefficient or matrix entry was NaN or infinite.
    #[error("non-finite value in {what}: every coefficient must be a finite number")]
    NonFinite {
        /// Which input held the value.
        what: &'static str,
    },
    /// A transfer function's denominator is the zero polynomial.
    #[error("zero denominator: a transfer function needs a nonzero denominator polynomial")]
    ZeroDenominator,
    /// The numerator degree exceeds the denominator degree where a proper system is needed.
    #[error(
        "improper transfer function (numerator degree {num_degree} > denominator degree {den_degree}): {what} needs deg N ≤ deg D"
    )]
    Improper {
        /// Degree of the numerator.
        num_degree: usize,
        /// Degree of the denominator.
        den_degree: usize,
        /// The operation that needs a proper system.
        what: &'static str,
    },
    /// A matrix that must be square is not.
    #[error("{what} must be square, got {rows}×{cols}")]
    NotSquare {
        /// Which matrix.
        what: &'static str,
        /// Rows.
        rows: usize,
        /// Columns.
        cols: usize,
    },
    /// Matrix or vector dimensions do not fit together.
    #[error("dimension mismatch in {what}: expected {expected}, found {found}")]
    DimensionMismatch {
        /// Which input.
        what: &'static str,
        /// The size that would fit.
        expected: String,
        /// The size given.
        found: String,
    },
    /// An input or output channel index that does not exist.
    #[error("{what} index {index} out of range: valid indices are 0..{len}")]
    IndexOutOfRange {
        /// Input or output.
        what: &'static str,
        /// The index given.
        index: usize,
        /// Number of channels.
        len: usize,
    },
    /// A time delay makes the result irrational (not a ratio of polynomials).
    #[error(
        "{what} is not rational with time delays (τ = {delay}); remove the delay or use a Padé approximation"
    )]
    Delay {
        /// The operation.
        what: &'static str,
        /// The delay involved.
        delay: f64,
    },
    /// An argument outside its valid set.
    #[error("invalid {what}: {reason}")]
    InvalidArgument {
        /// The argument.
        what: &'static str,
        /// What is wrong and what would be valid.
        reason: String,
    },
    /// An iterative kernel (eigenvalues, SVD) did not converge.
    #[error("{what} did not converge")]
    NoConvergence {
        /// The kernel.
        what: &'static str,
    },
    /// The true result (or a quantity it needs) exceeds the floating-point range.
    #[error("overflow in {what}: the result exceeds the largest finite f64 (about 1.8e308)")]
    Overflow {
        /// The computation.
        what: &'static str,
    },
    /// A complex root without its conjugate where a real polynomial is to be formed.
    #[error(
        "unpaired complex root {re} + {im}j in {what}: a real polynomial needs every complex root together with its conjugate"
    )]
    UnpairedComplexRoot {
        /// Which input.
        what: &'static str,
        /// Real part of the root.
        re: f64,
        /// Imaginary part of the root.
        im: f64,
    },
    /// The zero polynomial where a nonzero one is needed (its roots are every number).
    #[error("the zero polynomial in {what}: every number is a root; give a nonzero polynomial")]
    ZeroPolynomial {
        /// The operation.
        what: &'static str,
    },
    /// A grid or simulation larger than the allowed number of values.
    #[error("{what} would hold {requested} values; at most {limit} are allowed (memory)")]
    TooLarge {
        /// Which buffer.
        what: &'static str,
        /// Values requested.
        requested: u128,
        /// The limit.
        limit: usize,
    },
}

/// Checks a tolerance (docs/robustness.md §3): finite and ≥ 0, else
/// [`LtiError::InvalidArgument`]. A NaN tolerance used to make every comparison false, so that
/// unstable poles were classified as stable and nothing counted toward a rank.
pub(crate) fn check_tolerance(what: &'static str, tol: f64) -> Result<(), LtiError> {
    if tol.is_finite() && tol >= 0.0 {
        Ok(())
    } else {
        Err(LtiError::InvalidArgument {
            what, reason: format!("{tol}; a tolerance must be finite and ≥ 0")
        })
    }
}

/// Checks that every value is finite.
pub(crate) fn check_finite<'a>(
    what: &'static str,
    v: impl IntoIterator<Item = &'a f64>,
) -> Result<(), LtiError> {
    if v.into_iter().all(|x| x.is_finite()) { Ok(()) } else { Err(LtiError::NonFinite { what }) }
}
