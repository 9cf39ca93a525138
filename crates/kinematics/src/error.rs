//! Errors of the kinematics layer.

use thiserror::Error;

use crate::FrameLabel;

/// What went wrong in a kinematics computation, with what would be valid.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
///
/// Book: ch. 4–5 (DESIGN §5: one error enum per crate).
pub enum KinematicsError {
    /// A frame derivative or motion was used with the wrong frame: never a silent mix.
    #[error(
        "frame mismatch in {context}: expected a quantity with respect to frame {expected}, got frame {found}"
    )]
    FrameMismatch {
        /// Where the check failed.
        context: &'static str,
        /// The frame the operation needs.
        expected: FrameLabel,
        /// The frame the quantity carried.
        found: FrameLabel,
    },
    /// A relative motion of a frame with respect to itself.
    #[error("a frame motion needs two different frames: both are labelled {label}")]
    SameFrame {
        /// The label used twice.
        label: FrameLabel,
    },
    /// A chain of motions was empty.
    #[error("empty chain: {what} needs at least one link")]
    EmptyChain {
        /// Which operation.
        what: &'static str,
    },
    /// A component was NaN or infinite.
    #[error("non-finite value in {what}: every component must be a finite number")]
    NonFinite {
        /// Which input held the value.
        what: &'static str,
    },
    /// A curve point where the speed |r′| vanishes (stationary point or cusp).
    #[error("zero speed: |r′| = {speed:e} is not above the tolerance {tol:e}; the tangent is undefined")]
    ZeroSpeed {
        /// The speed found.
        speed: f64,
        /// The tolerance.
        tol: f64,
    },
    /// A curve point where the curvature vanishes (straight segment or inflection).
    #[error(
        "zero curvature: κ = {kappa:e} is not above the tolerance {tol:e}; the Frenet–Serret normal is undefined there (use the Bishop frame)"
    )]
    ZeroCurvature {
        /// The curvature found.
        kappa: f64,
        /// The tolerance.
        tol: f64,
    },
    /// Euler-angle rates at a gimbal lock: the rate matrix S is singular.
    #[error(
        "gimbal lock for Euler sequence {sequence}: |det S| = {det:e} is not above the tolerance {tol:e} (condition number {condition:e}); the middle angle must stay away from {singular_at}"
    )]
    GimbalLock {
        /// The sequence, e.g. "3-2-1 intrinsic".
        sequence: String,
        /// det S (±cos β for Tait–Bryan, ±sin β for symmetric sequences).
        det: f64,
        /// 2-norm condition number of S (∞ at the exact singularity).
        condition: f64,
        /// The tolerance on |det S|.
        tol: f64,
        /// Where the middle angle makes S singular.
        singular_at: &'static str,
    },
    /// A rate map (Jacobian) that cannot be inverted at this attitude.
    #[error("singular rate map for {representation}: {detail}")]
    SingularRateMap {
        /// Which attitude representation.
        representation: &'static str,
        /// What is singular and what would be valid.
        detail: String,
    },
    /// A true result beyond the largest finite `f64` (≈ 1.8e308), reported instead of a
    /// silent ∞ (docs/robustness.md).
    #[error("{what} overflows: its true value exceeds the largest finite number (≈ 1.8e308)")]
    Overflow {
        /// Which result.
        what: &'static str,
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
    /// An error from the frames layer.
    #[error(transparent)]
    Frame(#[from] vectrix_frames::FrameError),
}
