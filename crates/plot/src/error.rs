//! Errors of the plotting crate.

use thiserror::Error;

/// What was wrong with the data handed to a figure, with what would be valid.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum PlotError {
    /// The figure has nothing to draw.
    #[error("nothing to plot in '{figure}': give at least one series with at least one point")]
    Empty {
        /// Title of the figure.
        figure: String,
    },
    /// A coordinate was NaN or infinite.
    #[error(
        "point {index} of series '{series}' is not finite ({x}, {y}): every coordinate must be a finite number"
    )]
    NonFinite {
        /// Name of the series.
        series: String,
        /// Index of the point in the series.
        index: usize,
        /// Abscissa.
        x: f64,
        /// Ordinate.
        y: f64,
    },
    /// A coordinate on a logarithmic axis was zero or negative.
    #[error(
        "point {index} of series '{series}' has {axis} = {value} on a logarithmic {axis} axis: values there must be > 0"
    )]
    NonPositiveOnLogAxis {
        /// Name of the series.
        series: String,
        /// Index of the point.
        index: usize,
        /// `"x"` or `"y"`.
        axis: &'static str,
        /// The offending value.
        value: f64,
    },
    /// An explicit axis range was empty, reversed or not finite.
    #[error("invalid {axis} range [{lo}, {hi}]: need finite lo < hi (and lo > 0 on a log axis)")]
    InvalidRange {
        /// `"x"` or `"y"`.
        axis: &'static str,
        /// Lower end.
        lo: f64,
        /// Upper end.
        hi: f64,
    },
}
