//! vectrix-flight (in progress).
#![warn(missing_docs)]

/// `use vectrix_flight::prelude::*;`
pub mod prelude {}
