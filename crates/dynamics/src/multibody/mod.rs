//! Multibody trees in reduced coordinates: the book's joints, inverse dynamics (RNEA) with
//! joint reaction wrenches, forward dynamics (ABA, O(n)), the mass matrix (CRBA), forward
//! kinematics and energies, and the exact derivatives of the dynamics, all generic over the
//! scalar (f64 by default; num-dual's dual numbers through [`Model::cast`]).
//!
//! Book: §1.5 (joints), §7.11 (chains of rigid bodies).

mod aba;
mod articulated;
mod configuration;
mod crba;
mod derivatives;
mod joint;
mod kinematics;
mod model;
mod motion;
mod planar;
mod rnea;
mod segment;
mod singular;
mod spatial;
mod wrench;

pub use aba::AbaScratch;
pub use crba::CrbaScratch;
pub use derivatives::{AbaDerivatives, DerivativeScratch, RneaDerivatives};
pub use joint::{Joint, Link, Pose};
pub use kinematics::LinkTwist;
pub use model::{MAX_CHAIN_LINKS, Model, PosesScratch};
pub use motion::{LinkAcceleration, MotionScratch, QdotPlan, normalize_quaternion};
pub use rnea::{InverseDynamics, Scratch};
pub use wrench::{JointWrench, LinkWrenches};
