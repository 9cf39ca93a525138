//! Errors of the rotation layer.

use thiserror::Error;

/// What went wrong building or converting a rotation, with what would be valid.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum RotationError {
    /// A component was NaN or infinite.
    #[error("non-finite value in {what}: every component must be a finite number")]
    NonFinite {
        /// Which input held the value.
        what: &'static str,
    },
    /// The true result is finite mathematics but exceeds the largest finite `f64` (≈ 1.8e308);
    /// reported instead of a silent ∞ (docs/robustness.md).
    #[error("{what} overflows: its true value exceeds the largest finite number (≈ 1.8e308)")]
    Overflow {
        /// Which result.
        what: &'static str,
    },
    /// A rotation axis (or a quaternion) of zero length.
    #[error("{what} has zero length: a rotation axis or quaternion must be nonzero")]
    Zero {
        /// Which input.
        what: &'static str,
    },
    /// A matrix that is not orthonormal within the tolerance.
    #[error(
        "not a rotation: ‖MᵀM − I‖_max = {defect:e} exceeds the tolerance {tol:e}; project noisy input explicitly with `nearest_rotation`"
    )]
    NotOrthonormal {
        /// The measured defect ‖MᵀM − I‖_max.
        defect: f64,
        /// The tolerance.
        tol: f64,
    },
    /// An orthonormal matrix with det = −1 (a reflection).
    #[error("not a proper rotation: det = {det}; a rotation has det = +1 (a reflection has −1)")]
    Reflection {
        /// The determinant found.
        det: f64,
    },
    /// A quaternion whose norm is not 1 within the tolerance.
    #[error("not a unit quaternion: |‖q‖ − 1| = {defect:e} exceeds {tol:e}; normalise it first")]
    NotUnit {
        /// |‖q‖ − 1|.
        defect: f64,
        /// The tolerance.
        tol: f64,
    },
    /// The Gibbs vector g = tan(θ/2) n̂ does not exist at θ = π (book §2.17, §2.18).
    #[error("the Gibbs vector is undefined at θ = π (η = {eta:e}); use a quaternion or MRP instead")]
    GibbsAtHalfTurn {
        /// The Euler parameter η = cos(θ/2) found.
        eta: f64,
    },
    /// An Euler sequence with two equal adjacent axes (e.g. 3-3-1), which is not a sequence.
    #[error(
        "Euler sequence {axes:?} has equal adjacent axes: the middle axis must differ from the first and the last"
    )]
    EqualAdjacentAxes {
        /// The axes given (1, 2, 3).
        axes: [u8; 3],
    },
    /// An axis index outside 1..=3.
    #[error("axis {index} does not exist: valid axes are 1 (î), 2 (ĵ), 3 (k̂)")]
    InvalidAxis {
        /// The index given.
        index: usize,
    },
    /// A batched conversion found bad input at one element.
    #[error("element {index} of the batch: {source}")]
    AtElement {
        /// Index of the offending element.
        index: usize,
        /// What was wrong with it.
        source: Box<RotationError>,
    },
    /// An output buffer whose length differs from the input's.
    #[error("output buffer holds {output} elements but the input has {input}: they must be equal")]
    LengthMismatch {
        /// Input length.
        input: usize,
        /// Output length.
        output: usize,
    },
    /// An error from the kernel (e.g. a tensor too large to rotate).
    #[error(transparent)]
    Tensor(#[from] vectrix_tensor::TensorError),
    /// An error from the frames layer.
    #[error(transparent)]
    Frame(#[from] vectrix_frames::FrameError),
}

impl RotationError {
    /// `err` at element `index` of a batch.
    pub(crate) fn at(index: usize, err: RotationError) -> Self {
        RotationError::AtElement { index, source: Box::new(err) }
    }
}
