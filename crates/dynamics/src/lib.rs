//! # vectrix-dynamics: Newton–Euler, multibody trees, collisions, Lagrange and Hamilton
//!
//! * [`RigidBody`]: momentum and angular momentum about any point (§7.4, §7.6), Euler's
//!   equation about c and about any body point (§7.8), rank-aware for thin bodies; the 6D
//!   form [`newton_euler_6d`] (§7.10); the eigenaxis form [`eigenaxis_acceleration`] (§7.9);
//!   energy and work (§8.1–8.3).
//! * [`multibody`]: trees of links joined by the book's joints (pin, sleeve, collar, slot,
//!   ball, weld, free) in reduced coordinates; RNEA with joint reaction wrenches, ABA in O(n)
//!   (exact for singular joint inertia: particles on ball and free joints, massless links),
//!   CRBA + Cholesky, forward kinematics and energies (§7.11); the analytical derivatives
//!   ∂τ/∂(q, v, v̇) and ∂v̇/∂(q, v, τ); all generic over the scalar (`Model<Dual64>` by
//!   [`Model::cast`]); [`Network`]: spring–dashpot–inerter networks (§7.5).
//! * [`lagrange`]: Lagrange's and Hamilton's equations from user energies, differentiated
//!   exactly by dual numbers (ch. 9), and the kinematic-map form that builds T itself.
//! * [`constraints`]: holonomic and nonholonomic constraints with multipliers (§9.11–9.12),
//!   Kane's equations with user-chosen speeds (§9.14), and integration with drift projected
//!   away ([`constraints::ConstrainedIntegrator`]).
//! * Collisions and impulses (§7.13–7.14) and impacts during integration with Zeno
//!   protection ([`simulate_with_impacts`]).
//!
//! Book: ch. 7–9.
//!
//! Bad input: every public function returns a correct value or a typed error (never a panic,
//! hang, NaN or ∞ inside `Ok`); the contract — which functions return `Result`, how overflow
//! and tolerances are reported — is `docs/robustness.md` in the repository.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod collision;
pub mod constraints;
mod eigenaxis;
mod energy;
mod error;
mod impact;
pub mod lagrange;
pub mod multibody;
mod network;
mod rigid;
mod sixd;

pub use collision::{
    Impact, centre_of_percussion, collision_energy_loss, impulse_response, restitution_1d, rigid_impact,
    sphere_collision,
};
pub use eigenaxis::eigenaxis_acceleration;
pub use energy::{kinetic_energy_about_centre_pairwise, particles_kinetic_energy, power, work_along_path};
pub use error::DynamicsError;
pub use impact::{ImpactEnd, ImpactRun, ZenoGuard, simulate_with_impacts};
pub use lagrange::{KinematicMap, Lagrangian, MapMasses};
pub use multibody::{AbaDerivatives, Joint, Link, Model, RneaDerivatives};
pub use network::{Element, Network, NetworkMatrices};
pub use rigid::{RigidBody, particle_acceleration};
pub use sixd::{newton_euler_6d, twist_cross_matrix};

/// `use vectrix_dynamics::prelude::*;`
pub mod prelude {
    pub use crate::constraints::Constraints;
    pub use crate::constraints::kane::KaneSystem;
    pub use crate::{DynamicsError, Joint, KinematicMap, Lagrangian, Link, MapMasses, Model, RigidBody};
}
