//! vectrix-statics (in progress).
#![warn(missing_docs)]

/// `use vectrix_statics::prelude::*;`
pub mod prelude {}
