//! Multibody trees in reduced coordinates: the book's joints, inverse dynamics (RNEA) with
//! joint reaction wrenches, forward dynamics (ABA, O(n)) and the mass matrix (CRBA).
//!
//! Book: §1.5 (joints), §7.11 (chains of rigid bodies).

mod aba;
mod crba;
mod model;
mod rnea;
mod spatial;

pub use aba::AbaScratch;
pub use model::{Joint, Link, Model, Pose};
pub use rnea::{InverseDynamics, JointWrench, LinkWrenches, Scratch};
