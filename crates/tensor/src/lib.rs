//! # vectrix-tensor: the frame-free kernel
//!
//! Physical vectors, covectors, dyadics (physical matrices), tensors of any order,
//! bivectors, multivectors and rotors after Bernstein, Goel and Ansari, *Geometry,
//! Kinematics, Statics, and Dynamics*, ch. 1–3. None of these objects has components: they are
//! kept in one hidden reference basis that no user sees. Numbers appear only when an object is
//! resolved in a frame (crate `vectrix-frames`).
//!
//! Every type is generic over [`Scalar`] (default `f64`; also `f32` and num-dual's dual
//! numbers).
//!
//! Bad input: every public function returns a correct value or a typed error (never a panic,
//! hang, NaN or ∞ inside `Ok`); the contract — which functions return `Result`, how overflow
//! and tolerances are reported — is `docs/robustness.md` in the repository.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod angle;
mod bivector;
mod covector;
mod dyadic;
mod elasticity;
mod error;
mod f64;
mod multivector;
mod pauli;
mod rotor;
mod scalar;
#[cfg(feature = "serde")]
mod serde_impl;
mod tensor;
mod trivector;
mod vector;
mod wedge;

pub use angle::{congruent, wrap_angle};
pub use bivector::Bivector;
pub use covector::Covector;
pub use dyadic::{Dyadic, adjugate};
pub use elasticity::{HookeMap, Isotropic, hooke};
pub use error::{TensorError, check_tolerance};
pub use multivector::Multivector;
pub use rotor::{Rotor, reflect};
#[doc(hidden)]
pub use scalar::FastPath;
pub use scalar::Scalar;
pub use tensor::{Arg, DEFAULT_MAX_COMPONENTS, Tensor};
pub use trivector::Trivector;
pub use vector::Vector;

/// Everything a user of the kernel needs: `use vectrix_tensor::prelude::*;`.
pub mod prelude {
    pub use crate::{
        Arg, Bivector, Covector, Dyadic, HookeMap, Isotropic, Multivector, Rotor, Scalar, Tensor,
        TensorError, Trivector, Vector, congruent, hooke, reflect, wrap_angle,
    };
}
