//! Errors of the frames layer.

use thiserror::Error;

/// What went wrong building or using a frame, with what would be valid.
///
/// Book: §2.4 (standard frames), §2.23 (nonstandard frames); DESIGN §5.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum FrameError {
    /// A component was NaN or infinite.
    #[error("non-finite value in {what}: every component must be a finite number")]
    NonFinite {
        /// Which input.
        what: &'static str,
    },
    /// Axes (or a matrix) that are not orthonormal within the tolerance.
    #[error(
        "not orthonormal: ‖MᵀM − I‖ = {defect:e} exceeds the tolerance {tol:e}; a standard frame needs unit, mutually perpendicular axes"
    )]
    NotOrthonormal {
        /// The measured defect ‖MᵀM − I‖_max.
        defect: f64,
        /// The tolerance.
        tol: f64,
    },
    /// Orthonormal but left-handed (det = −1).
    #[error("left-handed: det = {det}; every vectrix frame is right-handed (î × ĵ = k̂, det = +1)")]
    LeftHanded {
        /// The determinant found.
        det: f64,
    },
    /// A nonstandard frame whose axes are (nearly) linearly dependent.
    #[error(
        "degenerate nonstandard frame: condition number {cond:e} exceeds {limit:e}; the three axes must be linearly independent"
    )]
    Degenerate {
        /// The 2-norm condition number of the axis matrix.
        cond: f64,
        /// The limit it was compared with.
        limit: f64,
    },
    /// A resolved array whose shape does not fit the object asked for.
    #[error("shape mismatch: {detail}")]
    Shape {
        /// What did not match and what would.
        detail: String,
    },
    /// A frame axis (or other input that must be nonzero) was the zero vector.
    #[error("{what} is zero: a frame axis must be a nonzero vector")]
    ZeroAxis {
        /// Which input.
        what: &'static str,
    },
    /// A true result beyond the largest finite `f64` (≈ 1.8e308), reported instead of a
    /// silent ∞ (docs/robustness.md).
    #[error("{what} overflows: its true value exceeds the largest finite number (≈ 1.8e308)")]
    Overflow {
        /// Which result.
        what: &'static str,
    },
    /// An error from the tensor kernel.
    #[error(transparent)]
    Tensor(#[from] vectrix_tensor::TensorError),
}
