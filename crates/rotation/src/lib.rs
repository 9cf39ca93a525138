//! # vectrix-rotation: every attitude representation, exact where peers are not
//!
//! Book: §2.8–2.22 (Bernstein, Goel, Ansari), notes ch1-2a and ch2b with errata.
//!
//! - [`Rotation`] is the physical, frame-free rotation R⃗_{B/A} (a unit rotor inside; why:
//!   see the module docs of `rotation`). Numbers come out only through a frame:
//!   `r.rotation_matrix_in(&a)` = 𝓡_{B/A}, `r.quaternion_in(&a)` = q_{B/A}, …
//! - Numeric representations resolved in one frame: [`Quaternion`] (Hamilton, scalar first,
//!   η ≥ 0), [`AxisAngle`], angle vectors (`nalgebra::Vector3`), Gibbs vectors (`Option` at
//!   π), modified Rodrigues parameters with the shadow set, [`EulerAngles`] in all 12
//!   sequences (intrinsic as the book, extrinsic as an option), elementary 𝓞_i and 𝓡_i.
//! - Rigid displacements, [`Screw`]s (Chasles made constructive), chains and homogeneous
//!   transforms.
//! - Batched conversions in SIMD for many rotations per call (scipy's batched `Rotation` is the
//!   peer): [`Quaternion::from_angle_vectors`] and [`EulerAngles::from_quaternions`] (an
//!   [`EulerBatch`]), each equal to the one-rotation function to a few ulps.
//!
//! # Conventions
//! - 𝓡_{B/A} = R⃗_{B/A}|_A is active (columns = B's axes resolved in A); 𝓞_{B/A} = 𝓡_{B/A}ᵀ is
//!   passive (x|_B = 𝓞_{B/A} x|_A). Composition: R⃗_{C/A} = R⃗_{C/B}R⃗_{B/A};
//!   𝓞_{C/A} = 𝓞_{C/B}𝓞_{B/A}; 𝓡_{C/A} = 𝓡_{B/A}𝓡_{C/B}; q_{C/A} = ±q_{B/A}⊗q_{C/B}.
//! - Eigenangle θ ∈ [0, π]; at θ = π the axis has the canonical sign (first nonzero component
//!   positive in the frame of resolution).
//! - Euler sequence i-j-k, angles in the order applied, each about the new frame's axis:
//!   𝓞_{D/A} = 𝓞_k(γ)𝓞_j(β)𝓞_i(α).
//!
//! ```
//! use vectrix_frames::{Frame, Resolve};
//! use vectrix_rotation::prelude::*;
//!
//! let a = Frame::new();
//! // F_B = R⃗ F_A, a half turn about (1, 2, 2)/3: the case peers turn into the identity.
//! let r_ba = Rotation::from_axis_angle(&a.vector([1.0, 2.0, 2.0]), std::f64::consts::PI)?;
//! let b = r_ba.apply_frame(&a);
//! assert_eq!(Rotation::between(&b, &a).axis_angle_in(&a).angle(), std::f64::consts::PI);
//! // 𝓡_{B/A} (active, columns = B's axes in A) and q_{B/A} (Hamilton, scalar first, η ≥ 0).
//! let r = r_ba.rotation_matrix_in(&a);
//! let q = Quaternion::from_rotation_matrix(&r, ROTATION_TOL)?;
//! assert!((q.rotation_matrix() - r).amax() < 1e-15);
//! // Euler angles: principal and alternate solutions, or gimbal lock as a value.
//! match r_ba.euler_in(&a, EulerSequence::S321) {
//!     EulerSolution::Regular { principal, .. } => assert!((principal.rotation_matrix() - r).amax() < 1e-15),
//!     EulerSolution::GimbalLock { combination, .. } => println!("only Ψ ± Φ = {combination}"),
//! }
//! # Ok::<(), RotationError>(())
//! ```
//!
//! Bad input: every public function returns a correct value or a typed error (never a panic,
//! hang, NaN or ∞ inside `Ok`); the contract — which functions return `Result`, how overflow
//! and tolerances are reported — is `docs/robustness.md` in the repository.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod axis;
mod axis_angle;
mod batch;
mod carry;
mod compose;
mod error;
mod euler;
mod euler_extract;
mod euler_parameters;
mod f64;
mod interop;
mod matrix;
mod mrp;
mod quaternion;
mod resolved;
mod rigid;
mod rotation;
#[cfg(feature = "serde")]
mod serde_impl;
mod series;

pub use axis::{Axis, orientation_about, quaternion_about, rotation_about};
pub use axis_angle::AxisAngle;
pub use batch::{EulerBatch, sin_cos_slices};
pub use compose::{
    compose_angle_vector, compose_coplanar, compose_euler, compose_gibbs, compose_mrp, compose_orientation,
    compose_quaternion, compose_rotation_matrix,
};
pub use error::RotationError;
pub use euler::{EulerAngles, EulerKind, EulerSequence};
pub use euler_extract::{EulerSolution, GIMBAL_LOCK_TOL};
pub use euler_parameters::canonical_half_turn_axis;
pub use interop::scaled_axis;
pub use matrix::{ROTATION_TOL, check_rotation_matrix, nearest_rotation};
pub use mrp::mrp_shadow;
pub use quaternion::Quaternion;
pub use rigid::{
    ChainLink, RigidDisplacement, Screw, chain_backward, chain_forward, homogeneous, homogeneous_inverse,
};
pub use rotation::Rotation;
pub use series::sin_cos;

/// `use vectrix_rotation::prelude::*;`
pub mod prelude {
    pub use crate::{
        Axis, AxisAngle, ChainLink, EulerAngles, EulerBatch, EulerKind, EulerSequence, EulerSolution,
        GIMBAL_LOCK_TOL, Quaternion, ROTATION_TOL, RigidDisplacement, Rotation, RotationError, Screw,
        canonical_half_turn_axis, chain_backward, chain_forward, check_rotation_matrix, compose_angle_vector,
        compose_coplanar, compose_euler, compose_gibbs, compose_mrp, compose_orientation, compose_quaternion,
        compose_rotation_matrix, homogeneous, homogeneous_inverse, mrp_shadow, nearest_rotation,
        orientation_about, quaternion_about, rotation_about,
    };
}
