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
//! # Sealed components
//!
//! The hidden components are read and written only by `vectrix-frames` (DESIGN §1.5), through
//! the traits of a module that exists only with the non-default cargo feature `frames-access`,
//! which only `vectrix-frames` enables. Rust has no friend crates, and nothing the kernel
//! hands out (a key, a token) can be kept from the other crates of the same build; so the
//! seal is the feature, the module's absence from every re-export and from the docs, and the
//! source scan `tests/adversarial/sealed.rs`, which fails when any file outside
//! `crates/tensor` and `crates/frames` names the module or the feature. Everyone else gets
//! numbers with `x.resolve(&frame)` and builds objects with `frame.vector([..])`.
//!
//! The kernel keeps no process-wide mutable state: the cap on a tensor's stored components is
//! carried by each tensor ([`Tensor::max_components`]).
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
#[cfg(feature = "frames-access")]
#[doc(hidden)]
pub mod frames_access;
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
