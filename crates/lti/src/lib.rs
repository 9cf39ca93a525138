//! # vectrix-lti: linear time-invariant systems
//!
//! Polynomials, transfer functions, zero–pole–gain and state-space models, time responses
//! with exact discretisation, Laplace tools, stability (classes, Routh), frequency response,
//! Nyquist, margins and root loci, after Bernstein, Goel and Ansari, ch. 15–16 (solutions
//! ch. 17–18), with the errata listed in the chapter notes corrected.
#![warn(missing_docs)]

mod error;
mod expm;
pub mod linalg;
mod poly;
mod sdof;
mod ss;
mod tf;
mod zpk;

pub use error::LtiError;
pub use expm::expm;
pub use num_complex::Complex64;
pub use poly::{Polynomial, TRIM_RTOL};
pub use sdof::{Mode, Sdof, SdofKind, SdofOutput, modes};
pub use ss::StateSpace;
pub use tf::TransferFunction;
pub use zpk::Zpk;

/// `use vectrix_lti::prelude::*;`
pub mod prelude {
    pub use crate::{Complex64, LtiError, Polynomial, TransferFunction, Zpk};
}
