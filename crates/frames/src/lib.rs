//! # vectrix-frames: frames and resolution
//!
//! A frame F_A = [î_A ĵ_A k̂_A] is three orthonormal right-handed physical vectors (book §2.4).
//! This crate is the only layer that sees the kernel's hidden basis: it turns frame-free
//! objects into numbers (`x.resolve(&a)`) and numbers into objects (`a.vector([..])`).
#![warn(missing_docs)]

mod error;
mod frame;
mod gradient;
mod nonstandard;
mod resolve;
mod tensor_resolve;

pub use error::FrameError;
pub use frame::{Frame, ORTHONORMAL_TOL};
pub use gradient::{gradient, gradient_central_difference, gradient_of_inverse_power, gradient_of_norm};
pub use nonstandard::{Components, MAX_CONDITION, NonstandardFrame, resolve_dyadic_mixed};
pub use resolve::{Resolve, change_frame_covector, change_frame_dyadic, change_frame_vector};
pub use tensor_resolve::change_frame_tensor;

/// `use vectrix_frames::prelude::*;`
pub mod prelude {
    pub use crate::{Components, Frame, FrameError, NonstandardFrame, ORTHONORMAL_TOL, Resolve};
}
