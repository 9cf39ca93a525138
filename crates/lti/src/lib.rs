//! vectrix-lti (in progress).
#![warn(missing_docs)]

/// `use vectrix_lti::prelude::*;`
pub mod prelude {}
