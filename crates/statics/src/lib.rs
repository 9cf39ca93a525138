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
//!
//! ```
//! use vectrix_frames::{Frame, Resolve};
//! use vectrix_statics::{INERTIA_REL_TOL, InertiaComponents, MassProperties, Point};
//!
//! // Problem 6.14.8: a 3 × 2 × 1 box of mass 6, inertia about a vertex.
//! let a = Frame::new();
//! let bx = MassProperties::solid_box(6.0, [3.0, 2.0, 1.0], &a, Point::origin())?;
//! let vertex = Point::at(a.vector([1.5, 1.0, 0.5]));
//! let j = bx.inertia_about(&vertex);
//! // The sign trap: the book's product J_xy = Σ m x̄ȳ = 9 is the matrix entry −9.
//! assert!((InertiaComponents::of(&j, &a).products[0] - 9.0).abs() < 1e-12);
//! assert!((j.resolve(&a)[(0, 1)] + 9.0).abs() < 1e-12);
//! // Principal moments λ1 ≥ λ2 ≥ λ3 and a right-handed principal frame.
//! let p = bx.principal_axes(&vertex, INERTIA_REL_TOL)?;
//! assert!((p.moments[2] - 3.41320).abs() < 1e-5);
//! # Ok::<(), vectrix_statics::StaticsError>(())
//! ```
//!
//! Bad input: every public function returns a correct value or a typed error (never a panic,
//! hang, NaN or ∞ inside `Ok`); the contract — which functions return `Result`, how overflow
//! and tolerances are reported — is `docs/robustness.md` in the repository.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod basis;
mod check;
mod damper;
mod dipole;
mod error;
mod force_pair;
mod freebody;
mod gravity;
mod inertia;
mod mass;
mod point;
mod principal;
#[cfg(feature = "serde")]
mod serde_impl;
mod shapes;
mod spatial;
mod spring;
mod wrench;

pub use damper::{Dashpot, Inerter, RotationalDashpot, RotationalInerter};
pub use dipole::{DipolePair, dipole_field, dipole_field_dyadic, dipole_interaction, dipole_potential};
pub use error::StaticsError;
pub use force_pair::ForcePair;
pub use freebody::{BodyId, Determinacy, FREE_BODY_REL_TOL, FreeBodyProblem, FreeBodySolution, UnknownId};
pub use gravity::{
    CentralGravity, GRAVITATIONAL_CONSTANT, MutualGravitation, UniformGravity, centre_of_gravity,
    gravity_between, mutual_gravitation, mutual_gravitation_potential,
};
pub use inertia::{
    INERTIA_REL_TOL, InertiaCheck, InertiaComponents, check_inertia, moment_of_inertia, parallel_axis,
    particle_inertia, product_of_inertia, shift_inertia,
};
pub use mass::MassProperties;
pub use point::Point;
pub use principal::PrincipalAxes;
pub use spatial::SpatialInertia;
pub use spring::{RotationalSpring, Spring};
pub use wrench::{AppliedForce, Wrench};

/// `use vectrix_statics::prelude::*;`
pub mod prelude {
    pub use crate::{
        AppliedForce, CentralGravity, Dashpot, FreeBodyProblem, Inerter, InertiaComponents, MassProperties,
        Point, PrincipalAxes, RotationalDashpot, RotationalInerter, RotationalSpring, SpatialInertia, Spring,
        StaticsError, UniformGravity, Wrench,
    };
}
