//! Errors of the statics layer.

use thiserror::Error;

/// What went wrong in a statics computation, with what would be valid.
///
/// Book: §6.2 (Facts 6.2.7–6.2.8), §6.7, §6.10, §6.12.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum StaticsError {
    /// A mass that is negative, NaN or infinite.
    #[error("{what}: mass = {mass} is invalid; a mass must be a finite number ≥ 0")]
    InvalidMass {
        /// Which mass.
        what: &'static str,
        /// The value given.
        mass: f64,
    },
    /// A body whose total mass is zero, so its centre of mass (6.1.2) is undefined.
    #[error("{what}: total mass is zero; a centre of mass needs a total mass > 0")]
    ZeroMass {
        /// Which body.
        what: &'static str,
    },
    /// A length, radius or coefficient that is negative, NaN or infinite.
    #[error("{what} = {value} is invalid: valid is {valid}")]
    OutOfRange {
        /// Which parameter.
        what: &'static str,
        /// Its value.
        value: f64,
        /// The valid range.
        valid: &'static str,
    },
    /// A vector, point or dyadic with a NaN or infinite component.
    #[error("non-finite value in {what}: every component must be a finite number")]
    NonFinite {
        /// Which input.
        what: &'static str,
    },
    /// An inertia dyadic that is not symmetric.
    #[error(
        "inertia is not symmetric: ‖J − J′‖ = {asymmetry:e} exceeds {tol:e}; a physical inertia matrix is symmetric"
    )]
    NotSymmetric {
        /// ‖J − J′‖ (Frobenius).
        asymmetry: f64,
        /// The tolerance.
        tol: f64,
    },
    /// An inertia dyadic with a negative principal moment (Fact 6.2.7 i).
    #[error(
        "inertia is not positive semidefinite: smallest principal moment {min_moment:e} is below −{tol:e} (Fact 6.2.7 i)"
    )]
    NotPositiveSemidefinite {
        /// The smallest eigenvalue.
        min_moment: f64,
        /// The tolerance.
        tol: f64,
    },
    /// An inertia dyadic of rank one, which no body has (Fact 6.2.7 iii).
    #[error(
        "inertia has rank 1 (principal moments {moments:?}); no body has rank 1: valid ranks are 0, 2, 3 (Fact 6.2.7 iii)"
    )]
    RankOne {
        /// The principal moments λ1 ≥ λ2 ≥ λ3.
        moments: [f64; 3],
    },
    /// Principal moments violating λ1 ≤ λ2 + λ3 (6.2.19).
    #[error(
        "principal moments {moments:?} violate the triangle inequality λ1 ≤ λ2 + λ3 (6.2.19) by {excess:e}"
    )]
    TriangleInequality {
        /// The principal moments λ1 ≥ λ2 ≥ λ3.
        moments: [f64; 3],
        /// λ1 − λ2 − λ3.
        excess: f64,
    },
    /// Removing a part heavier than the body (6.2.24).
    #[error(
        "cannot remove a part of mass {removed} from a body of mass {mass}: the part must be lighter than the body"
    )]
    RemovalExceedsMass {
        /// The body's mass.
        mass: f64,
        /// The mass of the part removed.
        removed: f64,
    },
    /// Two points that must be distinct coincide (spring with d > 0, dashpot, gravity, dipoles).
    #[error("{what}: the two points coincide (|r| = {distance:e}); the force direction r̂ is undefined")]
    CoincidentPoints {
        /// Which element.
        what: &'static str,
        /// The distance found.
        distance: f64,
    },
    /// A direction or axis that must be nonzero is zero.
    #[error("{what} must be a nonzero vector")]
    ZeroVector {
        /// Which input.
        what: &'static str,
    },
    /// A body index that was not created by this problem.
    #[error("body {index} does not exist: this free-body problem has {bodies} bodies")]
    UnknownBody {
        /// The index given.
        index: usize,
        /// Bodies in the problem.
        bodies: usize,
    },
    /// The equilibrium equations have no solution: the unknown reactions cannot balance the loads.
    #[error(
        "statically inconsistent: no reactions balance the loads (least-squares residual {residual:e} > tolerance {tol:e}); add supports or release loads"
    )]
    Inconsistent {
        /// ‖A x − b‖ of the least-squares solution.
        residual: f64,
        /// The tolerance it was compared with.
        tol: f64,
    },
    /// The equilibrium equations do not determine the reactions.
    #[error(
        "statically indeterminate of degree {degree}: {unknowns} unknowns but only {rank} independent equilibrium equations"
    )]
    Indeterminate {
        /// Degree of indeterminacy (unknowns − rank).
        degree: usize,
        /// Number of unknowns.
        unknowns: usize,
        /// Rank of the equilibrium equations.
        rank: usize,
    },
    /// The dense solver failed (should not happen for finite input).
    #[error("linear solver failed: {detail}")]
    Solver {
        /// What failed.
        detail: String,
    },
    /// A true result that exceeds the largest finite `f64` (≈ 1.8e308), reported instead of a
    /// silent ∞ (docs/robustness.md).
    #[error("{what} overflows: its true value exceeds the largest finite number (≈ 1.8e308)")]
    Overflow {
        /// Which result.
        what: &'static str,
    },
    /// An error from the frames layer.
    #[error(transparent)]
    Frame(#[from] vectrix_frames::FrameError),
    /// An error from the kernel.
    #[error(transparent)]
    Tensor(#[from] vectrix_tensor::TensorError),
}
