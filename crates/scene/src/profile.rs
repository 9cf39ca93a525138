//! Profiles: scalar functions of time for applied loads and control inputs, their values,
//! their checks and their corners (where the integration restarts).
//!
//! Book: §14.2 (doublet, step and pulse inputs); §7.x (applied loads as functions of time).

use serde::{Deserialize, Serialize};

use super::SceneError;
use super::source::SceneSource as Src;

/// A scalar function of time for applied forces and torques and for control deflections.
///
/// Book: §7.x (applied loads as functions of time); §14.2 (doublet, pulse, step inputs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Profile {
    /// f(t) = value.
    Constant {
        /// Value.
        value: f64,
    },
    /// f(t) = before for t < at, after otherwise.
    Step {
        /// Switching time.
        at: f64,
        /// Value before.
        #[serde(default)]
        before: f64,
        /// Value after.
        after: f64,
    },
    /// Linear from `from` at t0 to `to` at t1, constant outside.
    Ramp {
        /// Start time.
        t0: f64,
        /// End time (> t0).
        t1: f64,
        /// Value until t0.
        #[serde(default)]
        from: f64,
        /// Value from t1.
        to: f64,
    },
    /// offset + amplitude sin(ω t + phase).
    Sine {
        /// Amplitude.
        amplitude: f64,
        /// Angular frequency ω [rad/s].
        omega: f64,
        /// Phase [rad].
        #[serde(default)]
        phase: f64,
        /// Offset.
        #[serde(default)]
        offset: f64,
    },
    /// Piecewise-linear through (t, value) points (t increasing), constant outside.
    Table {
        /// Times, strictly increasing.
        t: Vec<f64>,
        /// Values.
        value: Vec<f64>,
    },
    /// The doublet of §14.2: offset + amplitude on [start, start + width), offset − amplitude
    /// on [start + width, start + 2 width), offset elsewhere.
    Doublet {
        /// Start time t₀.
        start: f64,
        /// Width w (> 0) of each half.
        width: f64,
        /// Amplitude A.
        amplitude: f64,
        /// Value outside the doublet (a trim setting).
        #[serde(default)]
        offset: f64,
    },
    /// A pulse: offset + amplitude on [start, start + width), offset elsewhere (§14.2).
    Pulse {
        /// Start time t₀.
        start: f64,
        /// Width w (> 0).
        width: f64,
        /// Amplitude A.
        amplitude: f64,
        /// Value outside the pulse.
        #[serde(default)]
        offset: f64,
    },
}

impl Profile {
    /// The profile plus a constant `du` at every t (an input perturbation for linearization).
    pub fn shifted(&self, du: f64) -> Profile {
        match self.clone() {
            Profile::Constant { value } => Profile::Constant { value: value + du },
            Profile::Step { at, before, after } => {
                Profile::Step { at, before: before + du, after: after + du }
            }
            Profile::Ramp { t0, t1, from, to } => Profile::Ramp { t0, t1, from: from + du, to: to + du },
            Profile::Sine { amplitude, omega, phase, offset } => {
                Profile::Sine { amplitude, omega, phase, offset: offset + du }
            }
            Profile::Table { t, value } => {
                Profile::Table { t, value: value.into_iter().map(|v| v + du).collect() }
            }
            Profile::Doublet { start, width, amplitude, offset } => {
                Profile::Doublet { start, width, amplitude, offset: offset + du }
            }
            Profile::Pulse { start, width, amplitude, offset } => {
                Profile::Pulse { start, width, amplitude, offset: offset + du }
            }
        }
    }

    /// f(t).
    ///
    /// Book: §14.2 for the doublet and pulse.
    pub fn eval(&self, t: f64) -> f64 {
        match self {
            Profile::Constant { value } => *value,
            Profile::Step { at, before, after } => {
                if t < *at {
                    *before
                } else {
                    *after
                }
            }
            Profile::Ramp { t0, t1, from, to } => from + (to - from) * ((t - t0) / (t1 - t0)).clamp(0.0, 1.0),
            Profile::Sine { amplitude, omega, phase, offset } => {
                offset + amplitude * (omega * t + phase).sin()
            }
            Profile::Table { t: ts, value } => {
                let k = ts.partition_point(|&x| x <= t);
                if k == 0 {
                    value[0]
                } else if k == ts.len() {
                    value[k - 1]
                } else {
                    let s = (t - ts[k - 1]) / (ts[k] - ts[k - 1]);
                    value[k - 1] + s * (value[k] - value[k - 1])
                }
            }
            Profile::Doublet { start, width, amplitude, offset } => {
                let s = t - start;
                if s < 0.0 || s >= 2.0 * width {
                    *offset
                } else if s < *width {
                    offset + amplitude
                } else {
                    offset - amplitude
                }
            }
            Profile::Pulse { start, width, amplitude, offset } => {
                if t >= *start && t < start + width {
                    offset + amplitude
                } else {
                    *offset
                }
            }
        }
    }

    /// f on the piece [lo, hi] of the run between two corners (`piece`), as the integrator
    /// must see it: the jumps' sides are those of the piece's interior, so a step that ends
    /// at a corner sees the value before it (its left limit) and a step that starts there the
    /// value after it, though `eval` is right-continuous. `None`: [`Profile::eval`].
    pub(crate) fn eval_on(&self, t: f64, piece: Option<(f64, f64)>) -> f64 {
        match (self, piece) {
            // piecewise constant: the value inside the piece (no corner lies strictly inside)
            (Profile::Step { .. } | Profile::Doublet { .. } | Profile::Pulse { .. }, Some((lo, hi))) => {
                self.eval(0.5 * (lo + hi))
            }
            // continuous (ramp, table, sine, constant): the same from either side
            _ => self.eval(t),
        }
    }

    /// Every corner and jump, with the key that declares it (relative to the profile's path).
    pub(crate) fn corners(&self) -> Vec<(f64, String)> {
        match self {
            Profile::Step { at, .. } => vec![(*at, "at".into())],
            Profile::Ramp { t0, t1, .. } => vec![(*t0, "t0".into()), (*t1, "t1".into())],
            Profile::Table { t, .. } => t.iter().enumerate().map(|(i, x)| (*x, format!("t[{i}]"))).collect(),
            Profile::Doublet { start, width, .. } => vec![
                (*start, "start".into()),
                (start + width, "width".into()),
                (start + 2.0 * width, "width".into()),
            ],
            Profile::Pulse { start, width, .. } => {
                vec![(*start, "start".into()), (start + width, "width".into())]
            }
            Profile::Constant { .. } | Profile::Sine { .. } => vec![],
        }
    }

    /// Checks the profile declared at `path` (errors located at its keys).
    pub(crate) fn check(&self, path: &str, src: &Src) -> Result<(), SceneError> {
        match self {
            Profile::Ramp { t0, t1, .. } if t1 <= t0 => {
                Err(src.invalid(format!("{path}.t1"), format!("t1 = {t1} ≤ t0 = {t0}; valid: t1 > t0")))
            }
            Profile::Table { t, value }
                if t.len() != value.len() || t.is_empty() || t.windows(2).any(|w| w[1] <= w[0]) =>
            {
                Err(src.invalid(
                    format!("{path}.t"),
                    "valid: `t` and `value` of equal nonzero length, `t` strictly increasing",
                ))
            }
            Profile::Doublet { width, .. } | Profile::Pulse { width, .. }
                if width.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) =>
            {
                Err(src.invalid(format!("{path}.width"), format!("width = {width}; valid: a width > 0")))
            }
            _ => Ok(()),
        }
    }
}
