//! vectrix-rotation (in progress).
#![warn(missing_docs)]

/// `use vectrix_rotation::prelude::*;`
pub mod prelude {}
