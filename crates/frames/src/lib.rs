//! # vectrix-frames: frames and resolution
//!
//! A frame F_A = [î_A ĵ_A k̂_A] is three orthonormal right-handed physical vectors (book §2.4).
//! This crate is the only layer that sees the kernel's hidden basis: it turns frame-free
//! objects into numbers (`x.resolve(&a)`) and numbers into objects (`a.vector([..])`). It reads
//! the components through `vectrix_tensor::frames_access`, which exists only with the feature
//! `frames-access` that this crate alone enables (vectrix-tensor's docs, "Sealed components").
//! Comparisons of components live here too ([`max_abs_diff_in`]): they depend on the frame.
//!
//! # Conventions (proved by the example below)
//!
//! - `x.resolve(&a)` is x⃗|_A = [î_A·x⃗, ĵ_A·x⃗, k̂_A·x⃗]ᵀ (2.4.14); `a.vector([..])` is F_A x (2.4.15).
//! - `b.orientation_rel(&a)` is 𝓞_{B/A}, **passive**: x|_B = 𝓞_{B/A} x|_A (2.10.31); its rows
//!   are B's axes resolved in A. Same matrix as sympy `B.dcm(A)` and Drake `R_BA`.
//! - `b.rotation_rel(&a)` is 𝓡_{B/A} = 𝓞ᵀ_{B/A}, **active**; its columns are B's axes resolved
//!   in A. Same matrix as Drake `R_AB` and scipy `Rotation.as_matrix()` of the rotation taking
//!   A's axes to B's. See `docs/notation.md`.
//!
//! ```
//! use vectrix_frames::prelude::*;
//! use vectrix_tensor::Rotor;
//! let a = Frame::new();
//! // B: A turned by +90° about k̂_A, so î_B = ĵ_A.
//! let b = a.rotated_by_rotor(&Rotor::from_axis_angle(&a.k(), std::f64::consts::FRAC_PI_2).unwrap());
//! let x = a.vector([1.0, 0.0, 0.0]); // x⃗ = î_A
//! let o_ba = b.orientation_rel(&a);
//! assert!((x.resolve(&b) - o_ba * x.resolve(&a)).norm() < 1e-15); // passive
//! assert!((x.resolve(&b) - nalgebra::Vector3::new(0.0, -1.0, 0.0)).norm() < 1e-15); // î_A = −ĵ_B
//! let r_ba = b.rotation_rel(&a);
//! assert!((r_ba.column(0) - b.i().resolve(&a)).norm() < 1e-15); // columns: B's axes in A
//! assert_eq!(r_ba, o_ba.transpose());
//! ```
//!
//! Bad input: every public function returns a correct value or a typed error (never a panic,
//! hang, NaN or ∞ inside `Ok`); the contract — which functions return `Result`, how overflow
//! and tolerances are reported — is `docs/robustness.md` in the repository.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod error;
mod frame;
mod gradient;
mod nonstandard;
mod resolve;
#[cfg(feature = "serde")]
mod serde_impl;
mod tensor_resolve;

pub use error::FrameError;
pub use frame::{Frame, ORTHONORMAL_TOL};
pub use gradient::{gradient, gradient_central_difference, gradient_of_inverse_power, gradient_of_norm};
pub use nonstandard::{Components, MAX_CONDITION, NonstandardFrame, resolve_dyadic_mixed};
pub use resolve::{Resolve, change_frame_covector, change_frame_dyadic, change_frame_vector};
pub use tensor_resolve::{change_frame_tensor, max_abs_diff_in};

/// `use vectrix_frames::prelude::*;`
///
/// Book: §2.4.
pub mod prelude {
    pub use crate::{Components, Frame, FrameError, NonstandardFrame, ORTHONORMAL_TOL, Resolve};
}
