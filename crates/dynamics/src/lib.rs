//! vectrix-dynamics (in progress).
#![warn(missing_docs)]

/// `use vectrix_dynamics::prelude::*;`
pub mod prelude {}
