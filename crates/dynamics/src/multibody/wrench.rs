//! Wrenches on links: what a joint transmits, and the external loads the tree algorithms take.
//!
//! Book: §7.11, (7.11.20)–(7.11.22).

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

/// The wrench a joint transmits from the parent to the link: force and moment about the link
/// frame origin (the joint point), components in the link frame. Also the form of external
/// wrenches on links ([`LinkWrenches`]).
///
/// Book: §7.11, (7.11.20)–(7.11.22) (ℱ_int, the joint reaction wrenches).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointWrench<T: Scalar = f64> {
    /// Force on the link from its parent, resolved in the link frame.
    pub force: Vector3<T>,
    /// Moment on the link from its parent about the joint point, resolved in the link frame.
    pub moment: Vector3<T>,
}

impl<T: Scalar> Default for JointWrench<T> {
    /// The zero wrench.
    fn default() -> Self {
        Self { force: Vector3::zeros(), moment: Vector3::zeros() }
    }
}

/// External wrenches on links for the tree algorithms: force and moment about the link frame
/// origin, both resolved in the link frame.
pub type LinkWrenches<T = f64> = [JointWrench<T>];
