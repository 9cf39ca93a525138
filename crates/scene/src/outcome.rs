//! What a run gives back: the sampled rows with their columns and units, the drift of the
//! checked invariants, the work done, why it stopped early if it did, and the contact events;
//! and the controls a caller passes in (progress, cancellation).
//!
//! Book: §4.11 (the work of an integration), §8.3 (invariants), §7.4/§7.6 (momenta).

use std::sync::atomic::AtomicBool;

use serde::Serialize;
use vectrix_units::{Dimension, UnitSystem};

use super::contacts::{ContactEvent, ContactEventKind};
use super::project::ConstraintViolation;
use super::{Invariant, Scene, SceneError};

/// A value of an invariant: energy is a scalar, momenta are vectors (ground components).
///
/// Book: §8.3, §7.4, §7.6.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(untagged)]
pub enum InvariantValue {
    /// T + U [J], or a component of H along an axis [kg m²/s].
    Scalar(f64),
    /// p [kg m/s] or H [kg m²/s].
    Vector([f64; 3]),
}

impl InvariantValue {
    /// The components: one for a scalar, three (ground) for a vector.
    pub fn as_slice(&self) -> &[f64] {
        match self {
            Self::Scalar(x) => std::slice::from_ref(x),
            Self::Vector(v) => v,
        }
    }
}

/// Drift of one checked invariant over the run (at the output samples).
///
/// Book: §8.3, §7.4, §7.6.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Drift {
    /// The invariant.
    pub invariant: Invariant,
    /// Its signed value at t = 0.
    pub initial: InvariantValue,
    /// Its signed value at the last sample.
    #[serde(rename = "final")]
    pub last: InvariantValue,
    /// max |x(t) − x(0)| (vector norm for vectors).
    pub max_abs: f64,
    /// The scale of the relative drift: max(|x(0)|, the largest sum over the samples of the
    /// magnitudes of its terms) (T for energy, Σ m|v_c| for momentum, Σ |r||m v| + |J ω| for
    /// H), so that an invariant whose value is zero still gets a meaningful relative drift.
    pub scale: f64,
    /// max_abs / scale.
    pub max_rel: f64,
}

/// What the run cost.
///
/// Book: §4.11.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct RunWork {
    /// Right-hand side evaluations.
    pub fevals: usize,
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Impacts resolved.
    pub impacts: usize,
    /// Restarts of the integrator: impacts and discontinuities of load profiles.
    pub restarts: usize,
    /// Steps after which the state was projected back onto the loop and rolling constraints
    /// (each restarts the integrator: one more f-eval).
    pub projections: usize,
    /// Wall time [s].
    pub wall_seconds: f64,
}

/// Why a run stopped before its end.
///
/// Book: — (run control).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StopReason {
    /// Cancelled (Ctrl-C).
    Interrupted,
    /// The step budget `max_steps` was reached, or the pace predicted it would be.
    MaxSteps,
    /// The wall-time budget `max_wall_seconds` was reached, or the pace predicted it would be.
    MaxWallSeconds,
    /// The run reached its duration, but a checked invariant drifted by more than
    /// [`MAX_TRUSTED_DRIFT`] (relative): its numbers do not mean what they say.
    InvariantDrift,
    /// The run reached its duration, but a state component exceeded [`MAX_TRUSTED_STATE`] in
    /// magnitude, where energies and squared lengths overflow.
    StateOutOfRange,
}

/// A run that ended early, or whose numbers cannot be trusted: why, when, and what to do
/// about it.
///
/// Book: — (run control).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Stop {
    /// Why.
    pub reason: StopReason,
    /// Simulated time reached [s].
    pub t: f64,
    /// What happened and what would be valid.
    pub message: String,
}

/// The result of a run: sampled outputs, invariant drift, work.
///
/// Book: §4.11, §8.3.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Run {
    /// Scene name.
    pub scene: String,
    /// Column names (after `t`).
    pub columns: Vec<String>,
    /// The unit of each column (`rad/s`, `J`, `m`; `1` for a quaternion component): SI, unless
    /// converted by [`Run::in_units`].
    pub units: Vec<String>,
    /// The dimension of each column.
    #[serde(skip)]
    pub dimensions: Vec<Dimension>,
    /// The unit system of the columns and the drift values (`si` or `imperial`).
    pub unit_system: &'static str,
    /// Sample times (the rows written; `t = 0` is the first).
    pub t: Vec<f64>,
    /// One row of column values per sample.
    pub rows: Vec<Vec<f64>>,
    /// Invariants implied by the declared effects.
    pub invariants: Vec<Invariant>,
    /// Drift of the checked ones.
    pub drift: Vec<Drift>,
    /// Cost.
    pub work: RunWork,
    /// Final state y = (q, v) (quaternions normalized).
    pub final_state: Vec<f64>,
    /// `Some` when the run ended before its duration (budget or cancellation): the rows hold
    /// what was computed; or when it reached its duration with numbers outside the range
    /// where they mean anything (an invariant's drift above [`MAX_TRUSTED_DRIFT`], a state
    /// above [`MAX_TRUSTED_STATE`]).
    pub stop: Option<Stop>,
    /// For scenes with loops or rolling contacts: the largest constraint violation of the
    /// written rows and of the step ends, after projection (§9.11).
    pub max_constraint_violation: Option<ConstraintViolation>,
    /// For scenes with loops or rolling contacts: the largest violation the integrator left at
    /// a step end before it was projected away (the drift that projection corrects).
    pub max_constraint_drift: Option<ConstraintViolation>,
    /// The integrator used and why (named, accuracy table, or the stiffness test).
    pub method: super::MethodChoice,
    /// The contact events in time order (impacts, comes to rest, lift-off), at most
    /// [`super::MAX_CONTACT_EVENTS`] (impacts beyond are counted in [`RunWork::impacts`]).
    pub contacts: Vec<ContactEvent>,
}

impl Run {
    /// Records one projection of a step end: the violation before it (the drift) and after it.
    pub(crate) fn note_projection(&mut self, before: ConstraintViolation, after: ConstraintViolation) {
        self.max_constraint_drift = Some(self.max_constraint_drift.unwrap_or_default().max(before));
        self.max_constraint_violation = Some(self.max_constraint_violation.unwrap_or_default().max(after));
    }

    /// The samples of one column.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let k = self.columns.iter().position(|c| c == name)?;
        Some(self.rows.iter().map(|r| r[k]).collect())
    }

    /// The run with every column and drift value written in `system` (`ft`, `slug*ft^2/s`, …),
    /// converted exactly (two roundings; vectrix_units). A run is in SI until converted.
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// [`SceneError::Run`] when a value overflows in the new unit.
    pub fn in_units(mut self, system: UnitSystem) -> Result<Run, SceneError> {
        let fail = |e: vectrix_units::UnitError| SceneError::Run { t: 0.0, message: e.to_string() };
        for (k, d) in self.dimensions.iter().enumerate() {
            let c = system.converter(*d).map_err(fail)?;
            for r in &mut self.rows {
                r[k] = c.from_si(r[k]).map_err(fail)?;
            }
            self.units[k] = label(system, *d, &self.columns[k]);
        }
        for dr in &mut self.drift {
            let d = match dr.invariant {
                Invariant::Energy => Dimension::ENERGY,
                Invariant::Momentum => Dimension::MOMENTUM,
                _ => Dimension::ANGULAR_MOMENTUM,
            };
            let c = system.converter(d).map_err(fail)?;
            let conv = |v: &mut InvariantValue| -> Result<(), SceneError> {
                match v {
                    InvariantValue::Scalar(x) => *x = c.from_si(*x).map_err(fail)?,
                    InvariantValue::Vector(x) => {
                        for e in x.iter_mut() {
                            *e = c.from_si(*e).map_err(fail)?;
                        }
                    }
                }
                Ok(())
            };
            conv(&mut dr.initial)?;
            conv(&mut dr.last)?;
            dr.max_abs = c.from_si(dr.max_abs).map_err(fail)?;
            dr.scale = c.from_si(dr.scale).map_err(fail)?;
        }
        let c = system.converter(Dimension::VELOCITY).map_err(fail)?;
        for e in &mut self.contacts {
            e.closing_speed = c.from_si(e.closing_speed).map_err(fail)?;
            e.opening_speed = c.from_si(e.opening_speed).map_err(fail)?;
        }
        self.unit_system = system.name();
        Ok(self)
    }

    /// contacts.csv: one line per contact event (impact, rest, lift-off) with the normal
    /// speeds before and after, in the run's units (see [`ContactEvent`]).
    pub fn contacts_csv(&self) -> String {
        let speed = if self.unit_system == UnitSystem::Si.name() {
            "m/s".to_string()
        } else {
            UnitSystem::Imperial.label(Dimension::VELOCITY)
        };
        let mut s = format!("t [s],effect,event,closing_speed [{speed}],opening_speed [{speed}]\n");
        for e in &self.contacts {
            let kind = match e.kind {
                ContactEventKind::Impact => "impact",
                ContactEventKind::Rest => "rest",
                ContactEventKind::LiftOff => "lift_off",
            };
            s.push_str(&format!(
                "{:e},{},{kind},{:e},{:e}\n",
                e.t, e.effect, e.closing_speed, e.opening_speed
            ));
        }
        s
    }

    /// `true` when the run reached its duration with trustworthy numbers (see [`Run::stop`]).
    pub fn is_complete(&self) -> bool {
        self.stop.is_none()
    }

    /// trajectory.csv: header `t [s],<column> [unit],…`, one line per sample, shortest
    /// round-trip decimal form of each number.
    pub fn to_csv(&self) -> String {
        let mut s = String::from("t [s]");
        for (c, u) in self.columns.iter().zip(&self.units) {
            s.push_str(&format!(",{c} [{u}]"));
        }
        s.push('\n');
        for (t, r) in self.t.iter().zip(&self.rows) {
            s.push_str(&format!("{t:e}"));
            for x in r {
                s.push_str(&format!(",{x:e}"));
            }
            s.push('\n');
        }
        s
    }
}

/// The unit label of a column in a system: `1` for a pure number, `J` for the SI energy
/// (whose dimension is that of a moment, N·m), the system's unit otherwise.
fn label(system: UnitSystem, d: Dimension, column: &str) -> String {
    if d == Dimension::DIMENSIONLESS {
        "1".into()
    } else if column == "energy" && system == UnitSystem::Si {
        "J".into()
    } else {
        system.label(d)
    }
}

/// Controls of a run beyond the scene file: a progress callback (fraction of the duration
/// done, after every accepted step) and a cancellation flag.
///
/// Book: — (run control).
pub struct RunControl<'a> {
    /// Called with t/duration after every accepted step.
    pub progress: &'a mut dyn FnMut(f64),
    /// When it becomes `true`, the run stops after the current step with
    /// [`StopReason::Interrupted`].
    pub cancel: Option<&'a AtomicBool>,
}

impl Run {
    /// A run of `scene` with no rows yet: its columns, their SI units and dimensions.
    pub(crate) fn empty(scene: &Scene) -> Self {
        let spec = scene.spec();
        let (columns, dims) = (scene.columns(), scene.column_dims());
        Run {
            scene: spec.name.clone(),
            units: dims.iter().zip(&columns).map(|(d, c)| label(UnitSystem::Si, *d, c)).collect(),
            columns,
            dimensions: dims,
            unit_system: UnitSystem::Si.name(),
            t: Vec::with_capacity(spec.samples + 1),
            rows: Vec::with_capacity(spec.samples + 1),
            invariants: scene.invariants().to_vec(),
            drift: Vec::new(),
            work: RunWork::default(),
            final_state: Vec::new(),
            stop: None,
            max_constraint_violation: None,
            max_constraint_drift: None,
            contacts: Vec::new(),
            method: scene.choice.clone(),
        }
    }
}
