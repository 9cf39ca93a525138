//! vectrix-plot (in progress).
#![warn(missing_docs)]

/// `use vectrix_plot::prelude::*;`
pub mod prelude {}
