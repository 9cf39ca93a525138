//! vectrix-kinematics (in progress).
#![warn(missing_docs)]

/// `use vectrix_kinematics::prelude::*;`
pub mod prelude {}
