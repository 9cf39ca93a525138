//! The simple line chart: one line per named series, optional log–log axes with decade ticks.
//! It is what work–precision diagrams (error against time, one line per method) are drawn with.

use crate::chart::{Chart, Curve, Stroke};
use crate::error::PlotError;

/// One named line of a [`LineChart`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// Points (x, y) in drawing order.
    pub points: Vec<(f64, f64)>,
}

impl Series {
    /// A series from a name and points.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self { name: name.into(), points }
    }
}

/// A line chart with a legend, drawn as deterministic SVG.
///
/// Series get colours from a fixed colour-blind-safe palette in order (Okabe–Ito, seven
/// colours; when they repeat the line style changes: dashed, dotted, dash-dot); a series with at most
/// [`LineChart::MARKER_LIMIT`] points also gets a circle at each point, which is what a
/// work–precision diagram wants (one marker per tolerance).
///
/// ```
/// use vectrix_plot::prelude::*;
/// let chart = LineChart {
///     title: "Work–precision".into(),
///     x_label: "error".into(),
///     y_label: "time [s]".into(),
///     log_x: true,
///     log_y: true,
///     series: vec![Series::new("RK4", vec![(1e-3, 1e-4), (1e-6, 1e-3), (1e-9, 1e-2)])],
/// };
/// let svg = chart.to_svg().unwrap();
/// assert!(svg.starts_with("<svg") && svg.contains("RK4"));
/// assert_eq!(svg, chart.to_svg().unwrap()); // deterministic
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LineChart {
    /// Title above the plot.
    pub title: String,
    /// Label of the x axis.
    pub x_label: String,
    /// Label of the y axis.
    pub y_label: String,
    /// Logarithmic x axis with decade ticks.
    pub log_x: bool,
    /// Logarithmic y axis with decade ticks.
    pub log_y: bool,
    /// The lines, one per series.
    pub series: Vec<Series>,
}

impl LineChart {
    /// Series with at most this many points are drawn with a marker at every point.
    pub const MARKER_LIMIT: usize = 40;

    /// An empty chart with linear axes.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> Self {
        Self { title: title.into(), x_label: x_label.into(), y_label: y_label.into(), ..Self::default() }
    }

    /// The same chart with log–log axes.
    pub fn log_log(mut self) -> Self {
        self.log_x = true;
        self.log_y = true;
        self
    }

    /// The same chart with one more series.
    pub fn with_series(mut self, name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        self.series.push(Series::new(name, points));
        self
    }

    /// The general [`Chart`] this line chart draws, after checking every point.
    ///
    /// # Errors
    /// [`PlotError::Empty`] with no points at all; [`PlotError::NonFinite`] for a NaN or
    /// infinite coordinate; [`PlotError::NonPositiveOnLogAxis`] for a value ≤ 0 on a log axis.
    pub fn to_chart(&self) -> Result<Chart, PlotError> {
        if self.series.iter().all(|s| s.points.is_empty()) {
            return Err(PlotError::Empty { figure: self.title.clone() });
        }
        for s in &self.series {
            for (index, &(x, y)) in s.points.iter().enumerate() {
                if !(x.is_finite() && y.is_finite()) {
                    return Err(PlotError::NonFinite { series: s.name.clone(), index, x, y });
                }
                for (axis, log, value) in [("x", self.log_x, x), ("y", self.log_y, y)] {
                    if log && value <= 0.0 {
                        return Err(PlotError::NonPositiveOnLogAxis {
                            series: s.name.clone(),
                            index,
                            axis,
                            value,
                        });
                    }
                }
            }
        }
        let curves = self
            .series
            .iter()
            .enumerate()
            .map(|(i, s)| Curve {
                name: Some(s.name.clone()),
                points: s.points.clone(),
                color: i,
                stroke: Stroke::Solid,
                markers: s.points.len() <= Self::MARKER_LIMIT,
            })
            .collect();
        Ok(Chart {
            title: self.title.clone(),
            x_label: self.x_label.clone(),
            y_label: self.y_label.clone(),
            log_x: self.log_x,
            log_y: self.log_y,
            curves,
            ..Chart::default()
        })
    }

    /// The chart as a deterministic SVG document (same input, same bytes).
    ///
    /// # Errors
    /// As [`LineChart::to_chart`].
    pub fn to_svg(&self) -> Result<String, PlotError> {
        self.to_chart()?.to_svg()
    }
}
