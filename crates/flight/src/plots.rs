//! A doublet input, the linear response to it, and SVG figures of the response and of the
//! modes (pole map), drawn with `vectrix-plot`.
//!
//! Book: §14.2 (elevator inputs), §14.6–14.7 (modes); plots follow the figures of §14.7.

use vectrix_lti::{Complex64, Hold, StateSpace, TimeResponse, lsim, time_grid};
use vectrix_plot::control::{pole_zero_map, time_series};

use crate::FlightError;

/// A doublet of amplitude A and half-width w starting at t₀: +A on [t₀, t₀ + w), −A on
/// [t₀ + w, t₀ + 2w), 0 elsewhere.
///
/// Book: §14.2 (control inputs).
pub fn doublet(t: f64, t0: f64, width: f64, amplitude: f64) -> f64 {
    if t >= t0 && t < t0 + width {
        amplitude
    } else if t >= t0 + width && t < t0 + 2.0 * width {
        -amplitude
    } else {
        0.0
    }
}

/// The response of a linear model to a doublet on `input` (zero-order hold, exact
/// discretisation by `vectrix-lti`), on n + 1 samples over [0, t_end].
///
/// Book: §14.2; (15.8.3)–(15.8.4).
///
/// # Errors
/// From `vectrix-lti` (bad input index, grid, non-finite values).
pub fn doublet_response(
    sys: &StateSpace,
    input: usize,
    amplitude: f64,
    width: f64,
    t_end: f64,
    n: usize,
) -> Result<TimeResponse, FlightError> {
    let t = time_grid(t_end, n)?;
    let u: Vec<f64> = t.iter().map(|&ti| doublet(ti, 1.0, width, amplitude)).collect();
    Ok(lsim(sys, input, &u, &t, &vec![0.0; sys.n_states()], Hold::Zoh, 0.0)?)
}

/// SVG of a doublet response: one curve per state, labelled by `names`.
///
/// Book: §14.2, §14.7.
///
/// # Errors
/// As [`doublet_response`]; [`FlightError::OutOfRange`] unless there is one name per
/// state; [`FlightError::Plot`] if the figure cannot be drawn.
pub fn doublet_response_svg(
    title: &str,
    sys: &StateSpace,
    input: usize,
    amplitude: f64,
    width: f64,
    t_end: f64,
    names: &[&str],
) -> Result<String, FlightError> {
    if names.len() != sys.n_states() {
        // one label per curve: extra or missing names would silently drop or mislabel curves
        return Err(FlightError::OutOfRange {
            what: "number of state names",
            value: names.len() as f64,
            valid: "one name per state of the system",
        });
    }
    let r = doublet_response(sys, input, amplitude, width, t_end, 800)?;
    let signals: Vec<(&str, &[f64])> = names.iter().zip(&r.y).map(|(n, y)| (*n, y.as_slice())).collect();
    time_series(title, &r.t, &signals).to_svg().map_err(|e| FlightError::Plot { reason: e.to_string() })
}

/// SVG pole map of the flight modes (× at each eigenvalue).
///
/// Book: §14.6–14.7, (14.2.18), (14.4.26).
///
/// # Errors
/// [`FlightError::Plot`] without eigenvalues.
pub fn modes_svg(title: &str, eigenvalues: &[Complex64]) -> Result<String, FlightError> {
    pole_zero_map(title, eigenvalues, &[])
        .and_then(|f| f.to_svg())
        .map_err(|e| FlightError::Plot { reason: e.to_string() })
}
