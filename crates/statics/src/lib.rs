//! # vectrix-statics: mass properties, wrenches, force elements and equilibrium
//!
//! Book ch. 6 (with §7.10.8 spatial inertia and §7.12 inerters) of Bernstein, Goel and Ansari,
//! *Geometry, Kinematics, Statics, and Dynamics*. Every quantity is frame-free: inertia is a
//! [`Dyadic`](vectrix_tensor::Dyadic), forces and moments are vectors, and points are
//! [`Point`]s located by r⃗_{y/o} relative to one reference point of the problem (frames have
//! no origin, book §2.4).
//!
//! # Conventions
//! - Subscript order is argument order: `y.position_rel(&x)` is r⃗_{y/x}; `Spring::force(r_y_w)`
//!   is f⃗_{y/w}, the force on y.
//! - Products of inertia: the book's J_xy ≜ Σ m x̄ȳ is a positive sum; the entry of the resolved
//!   inertia matrix is −J_xy ([`InertiaComponents`], [`product_of_inertia`]).
//! - Principal moments are sorted λ1 ≥ λ2 ≥ λ3 (Fact 6.2.8).
//! - Magnetic dipoles use Gaussian units, μ₀/4π = 1 (book §6.13); multiply by μ₀/4π for SI.
#![warn(missing_docs)]

mod basis;
mod damper;
mod dipole;
mod error;
mod freebody;
mod gravity;
mod inertia;
mod mass;
mod point;
mod principal;
mod shapes;
mod spatial;
mod spring;
mod wrench;

pub use damper::{Dashpot, Inerter, RotationalDashpot, RotationalInerter};
pub use dipole::{DipolePair, dipole_field, dipole_field_dyadic, dipole_interaction, dipole_potential};
pub use error::StaticsError;
pub use freebody::{BodyId, Determinacy, FREE_BODY_REL_TOL, FreeBodyProblem, FreeBodySolution, UnknownId};
pub use gravity::{
    CentralGravity, GRAVITATIONAL_CONSTANT, UniformGravity, centre_of_gravity, gravity_between,
    mutual_gravitation, mutual_gravitation_potential,
};
pub use inertia::{
    INERTIA_REL_TOL, InertiaCheck, InertiaComponents, check_inertia, moment_of_inertia, parallel_axis,
    particle_inertia, product_of_inertia, shift_inertia,
};
pub use mass::MassProperties;
pub use point::Point;
pub use principal::PrincipalAxes;
pub use spatial::SpatialInertia;
pub use spring::{ForcePair, RotationalSpring, Spring};
pub use wrench::{AppliedForce, Wrench};

/// `use vectrix_statics::prelude::*;`
pub mod prelude {
    pub use crate::{
        AppliedForce, CentralGravity, Dashpot, FreeBodyProblem, Inerter, InertiaComponents, MassProperties,
        Point, PrincipalAxes, RotationalDashpot, RotationalInerter, RotationalSpring, SpatialInertia, Spring,
        StaticsError, UniformGravity, Wrench,
    };
}
