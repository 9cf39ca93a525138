//! # vectrix-lti: linear time-invariant systems
//!
//! Polynomials, transfer functions, zero–pole–gain and state-space models, time responses
//! with exact discretisation, Laplace tools, stability (classes, Routh), frequency response,
//! Nyquist, margins and root loci, after Bernstein, Goel and Ansari, ch. 15–16 (solutions
//! ch. 17–18), with the errata listed in the chapter notes corrected.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod axis;
mod convert;
mod equilibria;
mod error;
mod expm;
mod freq;
mod hqr;
mod laplace;
pub mod linalg;
mod margins;
mod placement;
mod poly;
mod realroots;
mod rlocus;
mod routh;
mod sdof;
mod sensitivity;
#[cfg(feature = "serde")]
mod serde_impl;
mod shift;
mod ss;
mod stability;
mod sweep;
mod tf;
mod time;
mod zpk;

pub use equilibria::{AffineEquilibria, affine_equilibria};
pub use error::LtiError;
pub use expm::expm;
pub use freq::{FrequencyResponse, Nyquist, logspace};
pub use laplace::{
    CLUSTER_RTOL, FinalValue, Illegal, PartialFractions, PfTerm, RealTerm, TimeFunction, cluster_roots,
    final_value,
};
pub use margins::{GainCrossover, Margins, PhaseCrossover, StabilityPoint, wrap_deg};
pub use num_complex::Complex64;
pub use poly::{Polynomial, TRIM_RTOL};
pub use rlocus::{RootLocus, departure_angles, root_locus};
pub use routh::{RouthArray, routh, stable_gain_intervals};
pub use sdof::{Mode, Sdof, SdofKind, SdofOutput, modes};
pub use sensitivity::sensitivity_integral;
pub use shift::{leads, time_shift};
pub use ss::StateSpace;
pub use stability::{AXIS_RTOL, StabilityClass, stability_of_matrix, stability_of_polynomial};
pub use tf::TransferFunction;
pub use time::{Hold, InputKind, MAX_VALUES, TimeResponse, initial, lsim, response, time_grid};
pub use zpk::Zpk;

/// `use vectrix_lti::prelude::*;`
pub mod prelude {
    pub use crate::{Complex64, LtiError, Polynomial, TransferFunction, Zpk};
}
