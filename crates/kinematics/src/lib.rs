//! # vectrix-kinematics: frame derivatives, angular velocity, attitude rates, chains, curves
//!
//! Book ch. 4–5 (Bernstein, Goel, Ansari), notes ch4-5 with errata.
//!
//! - [`FrameMotion`]: 𝓞_{B/A}, ω⃗_{B/A}, α⃗_{B/A}; inverse (4.3.8), summation along chains
//!   (4.6.2–7), the mixed α⃗_{B/A/C} (4.4.4), the dyad Ω⃗_{B/A}; ω from orientation rates
//!   (Poisson, 4.3.17–20) and from axis rates (P4.20.5).
//! - Frame derivatives as tagged data: [`VectorJet`] (x⃗, x⃗^{A•}, x⃗^{A••}) and [`DyadicJet`]
//!   carry the [`FrameLabel`] of their frame; the transport theorems (4.4.1, 4.4.12, 4.5.1,
//!   P4.20.12), point velocity and (mixed) acceleration, rigid-body points (4.4.9–11, 4.5.3).
//! - [`attitude`]: rate equations of Euler angles (12 sequences, `Err(GimbalLock)`), angle
//!   vectors, Euler parameters, Gibbs vectors, MRPs, eigenaxis, rotation matrices, each in body
//!   and spatial form with inverses; propagation with RK4, the exact step and the Lie-group
//!   methods of `vectrix-ode`.
//! - 6D chains ([`chain_kinematics`], §4.13–4.14), screw axis, IVCR, IACR (§4.15–4.17),
//!   rolling (§4.18), cylindrical and spherical frames (§5.1–5.4), Frenet–Serret (§5.5) and
//!   Bishop frames.
//!
//! # Conventions
//! - A frame is its axes at an instant; its identity is a [`FrameLabel`]. Every operation that
//!   needs "the derivative with respect to F_A" checks the label: a mix-up is
//!   [`KinematicsError::FrameMismatch`], never a silent wrong number (the ω_{B/A}|_B versus
//!   ω_{A/B}|_A bug of Fact 4.3.2 cannot be written).
//! - Argument order is subscript order: `FrameMotion::new(b, a, ω_{B/A}, α_{B/A})`,
//!   `c_b.compose(&b_a)` is C/A.
//! - 𝓞_{B/A} passive (x|_B = 𝓞_{B/A}x|_A), 𝓡_{B/A} = 𝓞_{B/A}ᵀ; "body form" means ω_{B/A}|_B,
//!   "spatial form" ω_{B/A}|_A.
//! - Spherical φ is positive below the î–ĵ plane (book §5.3).
//!
//! ```
//! use vectrix_frames::Frame;
//! use vectrix_kinematics::{FrameMotion, KinematicsError, LabeledFrame, VectorJet};
//! use vectrix_tensor::Vector;
//! let a = LabeledFrame::new("A", Frame::new());
//! let b = LabeledFrame::new("B", Frame::new());
//! let k = a.frame.k();
//! // F_B spins about k̂ at 2 rad/s relative to F_A
//! let b_a = FrameMotion::new(b, a, k * 2.0, Vector::zero()).unwrap();
//! // x⃗ = î fixed in F_B: with respect to F_A it moves, x⃗^{A•} = ω⃗ × x⃗ = 2ĵ (4.4.1)
//! let x = VectorJet::fixed_in(b.label, a.frame.i());
//! let x_a = x.transported(&b_a).unwrap();
//! assert!((x_a.rate_wrt(a.label).unwrap() - a.frame.j() * 2.0).norm() < 1e-15);
//! // asking it for a derivative with respect to F_B is an error, not a silent mix
//! assert!(matches!(x_a.rate_wrt(b.label), Err(KinematicsError::FrameMismatch { .. })));
//! ```
//!
//! Bad input: every public function returns a correct value or a typed error (never a panic,
//! hang, NaN or ∞ inside `Ok`); the contract — which functions return `Result`, how overflow
//! and tolerances are reported — is `docs/robustness.md` in the repository.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

/// `Ok(v)` when every component of the matrix or vector `v` is finite, else
/// [`KinematicsError::Overflow`]: finite inputs whose true result exceeds f64::MAX
/// (docs/robustness.md).
macro_rules! finite_or_overflow {
    ($v:expr, $what:expr) => {{
        let v = $v;
        if v.iter().all(|x| vectrix_tensor::Scalar::re(x).is_finite()) {
            Ok(v)
        } else {
            Err($crate::KinematicsError::Overflow { what: $what })
        }
    }};
}
pub(crate) use finite_or_overflow;

pub mod attitude;
mod bishop;
mod chain;
mod curvilinear;
mod error;
mod frenet;
mod jet;
mod label;
mod motion;
mod poisson;
mod rolling;
mod screw;
mod transport;

pub use bishop::bishop_frames;
pub use chain::{
    ChainKinematics, JointAccel, JointTwist, LinkMotion, ResolvedLink, chain_kinematics,
    chain_velocity_resolved,
};
pub use curvilinear::{Cylindrical, Spherical};
pub use error::KinematicsError;
pub use frenet::FrenetSerret;
pub use jet::{DyadicJet, VectorJet};
pub use label::{FrameLabel, LabeledFrame};
pub use motion::FrameMotion;
pub use poisson::{
    alpha_body_from_orientation_rates, axis_rates, omega_body_from_orientation_rate, omega_from_axis_rates,
    omega_from_axis_rates_projections, omega_spatial_from_rotation_rate, poisson_rate, poisson_rate_spatial,
};
pub use rolling::{
    chasles_velocity, contact_point_velocity, no_slip_velocity, rolls_without_slip, slip_velocity,
};
pub use screw::{
    Iacr, InstantaneousMotion, Line, ScrewAxis, body_point_acceleration, iacr, ivcr, ivcr_coefficient,
    screw_axis,
};
pub use transport::{double_transport, transport, transport_dyadic, triple_transport};

/// `use vectrix_kinematics::prelude::*;`
pub mod prelude {
    pub use crate::attitude::{Propagator, propagate_attitude};
    pub use crate::{
        Cylindrical, DyadicJet, FrameLabel, FrameMotion, FrenetSerret, Iacr, InstantaneousMotion,
        KinematicsError, LabeledFrame, ScrewAxis, Spherical, VectorJet,
    };
}
