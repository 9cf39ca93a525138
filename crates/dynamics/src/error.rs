//! Errors of the dynamics layer.

use thiserror::Error;

/// What went wrong in a dynamics computation, with what would be valid.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum DynamicsError {
    /// A state, force or parameter with a NaN or infinite component.
    #[error("non-finite value in {what}: every component must be a finite number")]
    NonFinite {
        /// Which input.
        what: &'static str,
    },
    /// A mass, coefficient or length outside its valid range.
    #[error("{what} = {value} is invalid: valid is {valid}")]
    InvalidParameter {
        /// Which parameter.
        what: &'static str,
        /// Its value.
        value: f64,
        /// The valid range.
        valid: &'static str,
    },
    /// An inertia that no body has (not symmetric, not PSD, rank 1, triangle inequality).
    #[error("invalid inertia of {what}: {source}")]
    InvalidInertia {
        /// Which body.
        what: String,
        /// Why (from the statics layer).
        source: vectrix_statics::StaticsError,
    },
    /// A joint axis or direction of (near) zero length.
    #[error("joint of link {link}: {what} has length {length:e}; a joint axis must be a nonzero vector")]
    ZeroAxis {
        /// Index of the link.
        link: usize,
        /// Which axis.
        what: &'static str,
        /// Its length.
        length: f64,
    },
    /// Two joint directions that must be parallel or perpendicular are not (collar, slot).
    #[error("joint of link {link}: {detail}")]
    JointGeometry {
        /// Index of the link.
        link: usize,
        /// What is wrong and what is valid.
        detail: String,
    },
    /// A link whose parent does not exist.
    #[error(
        "link {link} names parent {parent}, but the tree has only {links} links: the tree is disconnected"
    )]
    Disconnected {
        /// The link.
        link: usize,
        /// The parent named.
        parent: usize,
        /// How many links exist.
        links: usize,
    },
    /// A link that is its own ancestor.
    #[error("link {link} is its own ancestor: a kinematic tree must not contain cycles")]
    Cyclic {
        /// A link on the cycle.
        link: usize,
    },
    /// Vectors whose lengths do not match the model.
    #[error("{what} has length {got}, expected {expected}")]
    DimensionMismatch {
        /// Which argument.
        what: &'static str,
        /// Its length.
        got: usize,
        /// The length the model needs.
        expected: usize,
    },
    /// A mass matrix (generalized or joint-space) that is singular or not positive definite.
    #[error(
        "mass matrix is singular or not positive definite ({detail}); the coordinates are degenerate here \
         (e.g. Euler angles at gimbal lock, a massless leaf body) and q̈ is not determined"
    )]
    SingularMassMatrix {
        /// Pivot or conditioning information.
        detail: String,
    },
    /// A torque about the axis of zero inertia of a thin body (rank-deficient J⃗).
    #[error(
        "moment component {component:e} about an axis of zero inertia (principal moments {moments:?}); \
         a thin body cannot take a torque about its own axis"
    )]
    TorqueOnInertAxis {
        /// The moment component along the null axis.
        component: f64,
        /// The principal moments λ1 ≥ λ2 ≥ λ3.
        moments: [f64; 3],
    },
    /// A result that overflowed to ∞ or NaN although every input was finite (e.g. velocities
    /// near 1e200, whose squares in the bias forces exceed the f64 range).
    #[error(
        "{what} is not finite although the inputs are: the computation overflowed; scale the inputs \
         (velocities, masses, lengths) into a range whose products stay below ~1e300"
    )]
    Overflow {
        /// Which result.
        what: &'static str,
    },
    /// A generalized force along a joint direction that carries no inertia (a particle on a
    /// ball joint turned about its own radius, a pin whose axis passes through a point mass,
    /// two coaxial pins joined by a massless link with unequal torques): the acceleration
    /// would be infinite.
    #[error(
        "generalized force {force:e} acts at velocity coordinate {coordinate} along a direction that \
         carries no inertia (articulated inertia SᵀIᴬS is singular there; tolerance {tolerance:e}): the \
         acceleration would be infinite; remove the force, or give the link inertia about that axis"
    )]
    InertJointForce {
        /// The first velocity coordinate of the joint.
        coordinate: usize,
        /// The component of u = τ − Sᵀpᴬ along the inert direction.
        force: f64,
        /// The rounding tolerance it was compared with.
        tolerance: f64,
    },
    /// An impact that does not close the gap (the bodies separate already).
    #[error("the bodies are separating (normal approach speed {approach:e} ≤ 0): no impact")]
    Separating {
        /// −v_rel·n̂ (positive when approaching).
        approach: f64,
    },
    /// No centre of percussion exists for this impulse.
    #[error("no centre of percussion: {detail}")]
    NoPercussionCentre {
        /// Why.
        detail: &'static str,
    },
    /// An error from the statics layer.
    #[error(transparent)]
    Statics(#[from] vectrix_statics::StaticsError),
    /// An error from the kinematics layer.
    #[error(transparent)]
    Kinematics(#[from] vectrix_kinematics::KinematicsError),
    /// An error from an integrator.
    #[error(transparent)]
    Ode(#[from] vectrix_ode::OdeError),
}

/// `Err(NonFinite)` unless every value is finite.
pub(crate) fn check_finite(values: &[f64], what: &'static str) -> Result<(), DynamicsError> {
    if values.iter().all(|v| v.is_finite()) { Ok(()) } else { Err(DynamicsError::NonFinite { what }) }
}

/// `Err(NonFinite)` unless every value's real part is finite (generic scalars).
pub(crate) fn check_finite_t<T: vectrix_tensor::Scalar>(
    values: &[T],
    what: &'static str,
) -> Result<(), DynamicsError> {
    if all_finite(values) { Ok(()) } else { Err(DynamicsError::NonFinite { what }) }
}

/// `true` when every value's real part is finite.
pub(crate) fn all_finite<T: vectrix_tensor::Scalar>(values: &[T]) -> bool {
    values.iter().all(|v| v.re().is_finite())
}

/// `Err(DimensionMismatch)` unless `got == expected`.
pub(crate) fn check_len(got: usize, expected: usize, what: &'static str) -> Result<(), DynamicsError> {
    if got == expected { Ok(()) } else { Err(DynamicsError::DimensionMismatch { what, got, expected }) }
}
