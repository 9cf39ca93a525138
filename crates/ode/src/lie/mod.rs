//! Lie-group methods for attitude: the [`LieGroup`] interface, exponential Euler, RKMK4,
//! Crouch–Grossman 3 and the exact quaternion step for constant ω (4.11.17).
//!
//! Book: §4.11; HLW §IV.8.

mod group;
mod methods;
mod quaternion;

pub use group::LieGroup;
pub use methods::{LieMethod, dexpinv, integrate_lie};
pub use quaternion::quaternion_exact_step;
