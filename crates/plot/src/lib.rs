//! # vectrix-plot: deterministic SVG figures
//!
//! Hand-written SVG (no font metrics, no randomness, fixed number formatting), so the same
//! data always gives the same bytes and figures can be snapshot-tested.
//!
//! - [`LineChart`]: named series over linear or log–log axes (work–precision diagrams,
//!   time series);
//! - [`Chart`] and [`Figure`]: the general panel (curves, markers, reference lines, arrows)
//!   and vertical stacks of panels, used by the control figures of the book's ch. 15–16
//!   (Bode, Nyquist, step responses, root loci, pole–zero maps, phase portraits);
//! - [`Rounded`]: resolved numbers printed for reading (six significant digits, round-off
//!   shown as 0).
//!
//! Bad input: every public function returns a correct value or a typed error (never a panic,
//! hang, NaN or ∞ inside `Ok`); the contract — which functions return `Result`, how overflow
//! and tolerances are reported — is `docs/robustness.md` in the repository.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod axis;
mod chart;
pub mod control;
mod error;
mod line;
mod svg;
mod text;

pub use chart::{Arrow, Chart, Curve, Figure, Marker, RefLine, Shape, Stroke};
pub use error::PlotError;
pub use line::{LineChart, Series};
pub use text::{ROUND_OFF, Rounded, SIGNIFICANT};

/// `use vectrix_plot::prelude::*;`
pub mod prelude {
    pub use crate::{
        Arrow, Chart, Curve, Figure, LineChart, Marker, PlotError, RefLine, Rounded, Series, Shape, Stroke,
    };
}
