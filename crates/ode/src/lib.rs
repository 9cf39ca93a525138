//! vectrix-ode (in progress).
#![warn(missing_docs)]

/// `use vectrix_ode::prelude::*;`
pub mod prelude {}
