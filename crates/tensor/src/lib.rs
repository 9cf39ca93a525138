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
#![warn(missing_docs)]

mod angle;
mod bivector;
mod covector;
mod dyadic;
mod error;
mod rotor;
mod scalar;
mod tensor;
mod vector;

pub use angle::{congruent, wrap_angle};
pub use bivector::Bivector;
pub use covector::Covector;
pub use dyadic::Dyadic;
pub use error::TensorError;
pub use rotor::Rotor;
pub use scalar::Scalar;
pub use tensor::{DEFAULT_MAX_COMPONENTS, Tensor};
pub use vector::Vector;

/// Everything a user of the kernel needs: `use vectrix_tensor::prelude::*;`.
pub mod prelude {
    pub use crate::{
        Bivector, Covector, Dyadic, Rotor, Scalar, Tensor, TensorError, Vector, congruent, wrap_angle,
    };
}
