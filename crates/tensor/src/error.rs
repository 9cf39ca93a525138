//! Errors of the kernel.

use thiserror::Error;

/// What went wrong in a kernel operation, with what would be valid.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum TensorError {
    /// A component was NaN or infinite.
    #[error("non-finite value in {what}: every component must be a finite number")]
    NonFinite {
        /// Which input held the value.
        what: &'static str,
    },
    /// A tolerance that is NaN, infinite or negative (docs/robustness.md: a tolerance is a
    /// finite number ≥ 0).
    #[error("tolerance {what} = {value} is invalid: a tolerance must be a finite number ≥ 0")]
    InvalidTolerance {
        /// Which tolerance.
        what: &'static str,
        /// Its value.
        value: f64,
    },
    /// A true result that exceeds the largest finite `f64` (≈ 1.8e308), reported instead of
    /// a silent ∞ (docs/robustness.md).
    #[error("{what} overflows: its true value exceeds the largest finite number (≈ 1.8e308)")]
    Overflow {
        /// Which result.
        what: &'static str,
    },
    /// A dyadic (physical matrix) has no inverse.
    #[error(
        "singular dyadic: |det| = {det:e} is not above the tolerance {tol:e}; an inverse exists only for det ≠ 0"
    )]
    Singular {
        /// The determinant found.
        det: f64,
        /// The tolerance it was compared with.
        tol: f64,
    },
    /// A slot index outside `1..=order`.
    #[error("slot {slot} is not a slot of a tensor of order {order}: valid slots are 1..={order}")]
    InvalidSlot {
        /// The requested slot (1-based, the book's numbering).
        slot: usize,
        /// The tensor's order p + q.
        order: usize,
    },
    /// Contraction needs one vector slot and one covector slot.
    #[error("slots {i} and {j} cannot be contracted: contraction pairs one vector slot (1..={p}) with one covector slot ({first_covector}..={order})", first_covector = p + 1, order = p + q)]
    ContractionTypes {
        /// First slot.
        i: usize,
        /// Second slot.
        j: usize,
        /// Vector slots of the tensor.
        p: usize,
        /// Covector slots of the tensor.
        q: usize,
    },
    /// The tensor's storage would exceed the cap it carries (`Tensor::max_components`).
    #[error(
        "a tensor of order {order} needs 3^{order} = {needed} components, above the limit of {limit}; raise the operand's cap with Tensor::with_max_components (or build with Tensor::zeros_with_limit) or lower the order"
    )]
    TooLarge {
        /// Requested order p + q.
        order: usize,
        /// Components needed (saturating).
        needed: u128,
        /// The cap that refused it.
        limit: usize,
    },
    /// Two tensors or arrays whose shapes do not fit together.
    #[error("shape mismatch: {detail}")]
    Shape {
        /// What did not match and what would.
        detail: String,
    },
    /// A slot permutation that is not a permutation of 1..=order.
    #[error("{perm:?} is not a permutation of 1..={order}")]
    InvalidPermutation {
        /// The given permutation.
        perm: Vec<usize>,
        /// Tensor order.
        order: usize,
    },
    /// A geometric input that must be nonzero was zero.
    #[error("{what} must be nonzero")]
    Zero {
        /// Which input.
        what: &'static str,
    },
    /// A parameter outside its valid range.
    #[error("{what} = {value} is out of range: valid is {valid}")]
    OutOfRange {
        /// Which parameter.
        what: &'static str,
        /// Its value.
        value: f64,
        /// The valid range.
        valid: &'static str,
    },
}

/// Validates a tolerance argument: finite and ≥ 0 (docs/robustness.md). Every vectrix function
/// that takes a tolerance and returns a `Result` calls this first, so a NaN or negative
/// tolerance is a typed error instead of a comparison that silently never (or always) holds.
///
/// Book: DESIGN §5 (tolerances are explicit arguments).
///
/// # Errors
/// [`TensorError::InvalidTolerance`] for NaN, ±∞ or a negative value.
#[inline]
pub fn check_tolerance(tol: f64, what: &'static str) -> Result<f64, TensorError> {
    if tol.is_finite() && tol >= 0.0 {
        Ok(tol)
    } else {
        Err(TensorError::InvalidTolerance { what, value: tol })
    }
}
