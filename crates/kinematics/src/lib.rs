//! # vectrix-kinematics: frame derivatives, angular velocity, attitude rates, chains, curves
//!
//! Book ch. 4–5 (Bernstein, Goel, Ansari). Frame derivatives are tagged with the frame they
//! are taken in ([`FrameLabel`]); every operation checks the tag, so a derivative with respect
//! to F_A is never silently used as one with respect to F_B (the classic ω_{B/A}|_B versus
//! ω_{A/B}|_A bug of Fact 4.3.2).
#![warn(missing_docs)]

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
    pub use crate::{DyadicJet, FrameLabel, FrameMotion, KinematicsError, LabeledFrame, VectorJet};
}
