//! Running a scene: **one** adaptive integration over [0, duration] (the method from the
//! declared accuracy through `vectrix_ode::Accuracy`, or named). Output samples come from the
//! dense output of the accepted steps, so their number does not change the steps taken;
//! impacts are located events (zeros of the contact gaps on the interpolant), and the known
//! discontinuities of applied-load profiles are step ends; at both the integration restarts.
//! Budgets (steps, wall time) and cancellation stop a run cleanly with what was computed.
//!
//! Book: §4.11 (integration), §7.13 (impacts), §8.3 (energy), §7.4/§7.6 (momenta).

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use nalgebra::Vector3;
use serde::Serialize;
use vectrix_ode::{AnyStepper, Method, OdeError};
use vectrix_units::{Dimension, UnitSystem};

use super::build::Src;
use super::contacts::{ContactEvent, ContactEventKind, Contacts, NextContact};
use super::kin::{Kin, kinematics, normalize};
use super::project::{ConstraintViolation, ProjectScratch};
use super::rhs::RhsScratch;
use super::spec::SceneSpec;
use super::{Invariant, Scene, SceneError};

/// Default bound on the steps of a run (accepted + rejected).
pub const DEFAULT_MAX_STEPS: usize = 10_000_000;
/// Default bound on the wall time of a run [s].
pub const DEFAULT_MAX_WALL_SECONDS: f64 = 600.0;
/// Most output samples of a scene (rows of trajectory.csv after the first).
pub const MAX_SAMPLES: usize = 1_000_000;
/// Most output values of a scene (rows × columns), which bounds its memory (8 bytes each).
pub const MAX_SAMPLE_VALUES: usize = 50_000_000;
/// A run whose pace predicts more than this multiple of a budget stops at once (fail fast).
const FAIL_FAST_FACTOR: f64 = 10.0;
/// Largest relative drift (`Drift::max_rel`) of a checked invariant that a complete run may
/// have: beyond it the numbers no longer conserve what the declared effects conserve, and
/// the run is marked incomplete ([`StopReason::InvariantDrift`]).
pub const MAX_TRUSTED_DRIFT: f64 = 1e-3;
/// Largest magnitude of a state component (q or v, SI) that a complete run may reach: about
/// √f64::MAX, beyond which squared speeds and lengths (T = ½ m v², |r|²) overflow and an
/// angle has no digit left below a turn ([`StopReason::StateOutOfRange`]).
pub const MAX_TRUSTED_STATE: f64 = 1e154;

/// The solver a scene asks for: `method` (with the reason, "named"), else the explicit method
/// of the accuracy table for `accuracy` (default 1e-6; the stiffness test may switch it to
/// RADAU5 once the scene is built, `Scene::choose_method`); with the scene's step budget.
pub(crate) fn solver(spec: &SceneSpec, src: &Src) -> Result<(Method, Option<String>), SceneError> {
    let (a, named) = match super::stiff::named(spec, src)? {
        Some((m, why)) => (m, Some(why)),
        None => (super::stiff::from_accuracy(spec, src)?, None),
    };
    let max_steps = spec.max_steps.unwrap_or(DEFAULT_MAX_STEPS);
    if max_steps == 0 {
        return Err(src.invalid("max_steps", "max_steps = 0; valid: ≥ 1"));
    }
    Ok((a.with_max_steps(max_steps), named))
}

/// Checks the run's sizes: duration, samples (and samples × columns), wall-time budget.
pub(crate) fn check_bounds(
    spec: &SceneSpec,
    built: &super::build::Built,
    outputs: &[super::outputs::Output],
    src: &Src,
) -> Result<(), SceneError> {
    if !(spec.duration > 0.0 && spec.duration.is_finite()) {
        return Err(
            src.invalid("duration", format!("duration = {} s; valid: a finite number > 0", spec.duration))
        );
    }
    if !(1..=MAX_SAMPLES).contains(&spec.samples) {
        return Err(src.invalid("samples", format!("samples = {}; valid: 1 ..= {MAX_SAMPLES}", spec.samples)));
    }
    let columns = super::outputs::count_columns(outputs, built);
    if (spec.samples + 1).saturating_mul(columns.max(1)) > MAX_SAMPLE_VALUES {
        return Err(src.invalid(
            "samples",
            format!(
                "samples = {} with {columns} output columns is {} values; valid: (samples + 1) × columns ≤ \
                 {MAX_SAMPLE_VALUES}",
                spec.samples,
                (spec.samples + 1).saturating_mul(columns)
            ),
        ));
    }
    check_breakpoints(spec, src)?;
    if let Some(w) = spec.max_wall_seconds
        && !(w > 0.0 && w.is_finite())
    {
        return Err(
            src.invalid("max_wall_seconds", format!("max_wall_seconds = {w}; valid: a finite number > 0"))
        );
    }
    Ok(())
}

/// The corners and jumps of the load profiles are step ends: two of them (or one and t = 0 or
/// the end) closer than the time resolution 64 ε · duration, yet distinct, would need a step
/// below round-off. Refused at the later one, with what would be valid.
fn check_breakpoints(spec: &SceneSpec, src: &Src) -> Result<(), SceneError> {
    let resolution = 64.0 * f64::EPSILON * spec.duration;
    let mut times: Vec<(f64, String)> = vec![(0.0, String::new()), (spec.duration, String::new())];
    times.extend(profile_corners(spec));
    times.retain(|(t, _)| (0.0..=spec.duration).contains(t));
    times.sort_by(|a, b| a.0.total_cmp(&b.0));
    for w in times.windows(2) {
        let ((t1, p1), (t2, p2)) = (&w[0], &w[1]);
        if t2 > t1 && t2 - t1 < resolution {
            let (path, other) = if p2.is_empty() {
                (p1, "the end")
            } else {
                (p2, if p1.is_empty() { "t = 0" } else { p1.as_str() })
            };
            return Err(src.invalid(
                path.as_str(),
                format!(
                    "a profile corner {:e} s from {other}: closer than the time resolution 64 ε × duration = \
                     {resolution:e} s, so no integrator step fits between them; valid: the same time, or times at \
                     least {resolution:e} s apart",
                    t2 - t1
                ),
            ));
        }
    }
    Ok(())
}

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
    fn note_projection(&mut self, before: ConstraintViolation, after: ConstraintViolation) {
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

/// Tracked invariant values at the samples.
struct Tracker {
    inv: Invariant,
    x0: Option<Vector3<f64>>,
    last: Vector3<f64>,
    scale: f64,
    max: f64,
}

impl Tracker {
    fn value(&self, x: Vector3<f64>) -> InvariantValue {
        match self.inv {
            Invariant::Energy | Invariant::AngularMomentumAlong { .. } => InvariantValue::Scalar(x[0]),
            _ => InvariantValue::Vector(x.into()),
        }
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

/// Times in (0, duration) where an applied load profile is discontinuous or has a kink.
fn breakpoints(spec: &SceneSpec) -> Vec<f64> {
    let mut out: Vec<f64> = profile_corners(spec).into_iter().map(|(t, _)| t).collect();
    out.retain(|&t| t > 0.0 && t < spec.duration);
    out.sort_by(f64::total_cmp);
    out.dedup();
    out
}

/// Every corner and jump of the applied-load profiles, with the item path of the key that
/// declares it (`effects[k].profile.at`, `.t0`, `.t1`, `.t[i]`), in declaration order.
fn profile_corners(spec: &SceneSpec) -> Vec<(f64, String)> {
    let mut out = Vec::new();
    for (k, e) in spec.effects.iter().enumerate() {
        for (key, p) in e.profiles() {
            out.extend(p.corners().into_iter().map(|(t, at)| (t, format!("effects[{k}].{key}.{at}"))));
        }
    }
    out
}

impl Scene {
    fn invariant_value(&self, inv: &Invariant, kin: &Kin, q: &[f64], v: &[f64]) -> Vector3<f64> {
        match inv {
            Invariant::Energy => Vector3::new(self.energy(kin, q, v), 0.0, 0.0),
            Invariant::Momentum => self.momentum(kin),
            Invariant::AngularMomentum { about } => self.angular_momentum(kin, &Vector3::from(*about)),
            Invariant::AngularMomentumAlong { about, axis } => {
                let h = self.angular_momentum(kin, &Vector3::from(*about));
                Vector3::new(h.dot(&Vector3::from(*axis)), 0.0, 0.0)
            }
        }
    }

    /// Runs the scene; `progress` is called with the fraction done after every accepted step.
    ///
    /// Book: §4.11, §7.11, §7.13.
    ///
    /// # Errors
    /// [`SceneError::Run`] when the integrator or the dynamics fail. A run stopped by a budget
    /// is not an error: it returns the rows computed, with [`Run::stop`] set.
    pub fn run(&self, progress: &mut dyn FnMut(f64)) -> Result<Run, SceneError> {
        self.run_with(RunControl { progress, cancel: None })
    }

    /// [`Scene::run`] with a cancellation flag.
    ///
    /// # Errors
    /// As [`Scene::run`].
    pub fn run_with(&self, ctl: RunControl<'_>) -> Result<Run, SceneError> {
        let start = Instant::now();
        let b = &self.built;
        let nq = b.model.nq();
        let spec = self.spec();
        let duration = spec.duration;
        let max_wall = spec.max_wall_seconds.unwrap_or(DEFAULT_MAX_WALL_SECONDS);
        let mut trackers: Vec<Tracker> = self
            .invariants()
            .iter()
            .filter(|i| spec.checks.iter().any(|c| c == i.name()))
            .map(|i| Tracker { inv: i.clone(), x0: None, last: Vector3::zeros(), scale: 0.0, max: 0.0 })
            .collect();
        let mut run = Run {
            scene: spec.name.clone(),
            columns: self.columns(),
            units: self
                .column_dims()
                .iter()
                .zip(self.columns())
                .map(|(d, c)| label(UnitSystem::Si, *d, &c))
                .collect(),
            dimensions: self.column_dims(),
            unit_system: UnitSystem::Si.name(),
            t: Vec::with_capacity(spec.samples + 1),
            rows: Vec::with_capacity(spec.samples + 1),
            invariants: self.invariants().to_vec(),
            drift: Vec::new(),
            work: RunWork::default(),
            final_state: Vec::new(),
            stop: None,
            max_constraint_violation: None,
            max_constraint_drift: None,
            contacts: Vec::new(),
            method: self.choice.clone(),
        };
        let constrained = self.has_constraints();
        let mut sample_projection = ProjectScratch::default();
        let mut step_projection = ProjectScratch::default();
        let sample_time = |k: usize| duration * (k as f64 / spec.samples as f64);
        let fail = |t: f64, e: String| SceneError::Run { t, message: e };
        // the largest |y_i| at the samples, and where (time, index)
        let peak = std::cell::Cell::new((0.0_f64, 0.0_f64, 0_usize));

        // outputs and invariants at a sample
        let mut record = |run: &mut Run, t: f64, y: &[f64]| -> Result<(), SceneError> {
            let mut y = y.to_vec();
            normalize(&b.bodies, &mut y[..nq]);
            if let Some((i, x)) = y.iter().map(|x| x.abs()).enumerate().max_by(|a, b| a.1.total_cmp(&b.1))
                && x > peak.get().0
            {
                peak.set((x, t, i));
            }
            if constrained {
                // a sample between step ends comes from the interpolant: project it too
                let (_, after) = self.project(&mut y, &mut sample_projection).map_err(|e| fail(t, e))?;
                run.max_constraint_violation =
                    Some(run.max_constraint_violation.unwrap_or_default().max(after));
            }
            let lambda = if self.needs_multipliers() {
                Some(self.multipliers(t, &y).map_err(|e| fail(t, e))?)
            } else {
                None
            };
            let (q, v) = y.split_at(nq);
            let kin = kinematics(&b.model, &b.bodies, &self.order, q, v).map_err(|e| fail(t, e))?;
            let mut row = Vec::with_capacity(run.columns.len());
            self.row(&kin, q, v, lambda.as_ref(), &mut row);
            run.t.push(t);
            run.rows.push(row);
            for tr in &mut trackers {
                let x = self.invariant_value(&tr.inv, &kin, q, v);
                // the size of the invariant's terms over the run (at t = 0 alone a pendulum
                // released from rest has no kinetic term to measure a drift against)
                tr.scale = tr.scale.max(self.invariant_scale(&tr.inv, &kin, v));
                let x0 = *tr.x0.get_or_insert(x);
                tr.last = x;
                tr.max = tr.max.max((x - x0).norm());
            }
            Ok(())
        };

        let mut y0 = self.initial_state();
        // contacts: which rest, and what happened (the right-hand side reads `resting`)
        let contacts = std::cell::RefCell::new(Contacts {
            resting: vec![false; self.contacts.len()],
            events: Vec::new(),
        });
        // a rebound shorter than tau_min comes to rest; the contact scan splits no shorter piece
        // than a quarter of it, so a flight of tau_min is always seen
        let tau_min = super::REST_TIME_REL * duration;
        if self.needs.impacts {
            self.impact_at(0.0, &mut y0, &mut contacts.borrow_mut(), &mut run.work)
                .map_err(|e| fail(0.0, e))?;
            self.settle(0.0, &mut y0, &mut contacts.borrow_mut(), tau_min).map_err(|e| fail(0.0, e))?;
        }
        if constrained {
            let (before, after) = self.project(&mut y0, &mut step_projection).map_err(|e| fail(0.0, e))?;
            run.note_projection(before, after);
        }
        record(&mut run, 0.0, &y0)?;
        let mut next_sample = 1;
        let nv = b.model.nv();
        if nv == 0 {
            // nothing moves (every joint a weld): the state is constant
            while next_sample <= spec.samples {
                record(&mut run, sample_time(next_sample), &y0)?;
                next_sample += 1;
            }
            (ctl.progress)(1.0);
            return Ok(self.finish(run, trackers, y0, start, peak.get()));
        }

        let failure = std::cell::RefCell::new(None::<String>);
        let mut scratch = RhsScratch::new(self);
        let f = |t: f64, y: &Vec<f64>| {
            let mut out = vec![0.0; y.len()];
            if let Err(e) = self.deriv_resting(t, y, &mut out, &mut scratch, &contacts.borrow().resting) {
                failure.borrow_mut().get_or_insert(e);
                out.fill(f64::NAN);
            }
            out
        };
        let ode_err = |e: OdeError| -> SceneError {
            let t = match &e {
                OdeError::RhsNotFinite { t, .. }
                | OdeError::StepSizeUnderflow { t, .. }
                | OdeError::NonFiniteState { t, .. }
                | OdeError::SingularIterationMatrix { t, .. }
                | OdeError::NewtonStalled { t, .. }
                | OdeError::JacobianNotFinite { t, .. } => *t,
                _ => 0.0,
            };
            fail(t, failure.borrow_mut().take().unwrap_or_else(|| e.to_string()))
        };
        let mut stops = breakpoints(spec);
        stops.push(duration);
        let mut stop_at = 0;
        // implicit steps: ∂f/∂y from dual numbers for a tree; otherwise RADAU5's own finite
        // differences (through the same f, so they see the resting contacts too)
        let exact = self.solver.is_implicit() && self.tree_only() && !self.needs.impacts;
        let jac = exact.then_some(|t: f64, y: &Vec<f64>, out: &mut [f64]| match self.jacobian(t, y) {
            Ok((j, _)) => {
                let n = y.len();
                for r in 0..n {
                    for c in 0..n {
                        out[r * n + c] = j[(r, c)];
                    }
                }
            }
            Err(e) => {
                failure.borrow_mut().get_or_insert(e.to_string());
                out.fill(f64::NAN);
            }
        });
        let mut st = AnyStepper::new(&self.solver, f, jac, 0.0, y0, stops[0]).map_err(ode_err)?;
        let mut geo =
            if self.needs.impacts { self.gaps(st.y()).map_err(|e| fail(0.0, e))? } else { Vec::new() };
        let mut last_check = 0usize;

        loop {
            if st.done() {
                if stop_at + 1 == stops.len() {
                    break;
                }
                // a discontinuity of a load profile: continue from it with a fresh first stage
                stop_at += 1;
                let (t, y) = (st.t(), st.y().clone());
                st.set_end(stops[stop_at]).map_err(ode_err)?;
                st.restart(t, y).map_err(ode_err)?;
                run.work.restarts += 1;
            }
            match st.step() {
                Ok(()) => {}
                Err(OdeError::TooManySteps { t, max_steps }) => {
                    run.stop = Some(Stop {
                        reason: StopReason::MaxSteps,
                        t,
                        message: format!(
                            "max_steps = {max_steps} reached at t = {t:.6e} s of duration = {duration} s; valid: \
                             raise max_steps, loosen accuracy or shorten duration"
                        ),
                    });
                    break;
                }
                Err(e) => return Err(ode_err(e)),
            }
            let (t0, t1) = (st.step_start().unwrap_or(0.0), st.t());
            // the first contact event of the step: a touch located on the interpolant, or a
            // resting contact's lift-off
            let mut event = None;
            if self.needs.impacts {
                let g1 = self.gaps(st.y()).map_err(|e| fail(t1, e))?;
                let dense = st.dense().map_err(ode_err)?.clone();
                let found = self.next_contact_event(
                    &dense,
                    (t0, &geo),
                    (t1, &g1),
                    st.y(),
                    &contacts.borrow(),
                    tau_min,
                );
                event = found.map_err(|e| fail(t1, e))?;
                geo = g1;
            }
            let t_end = event.map_or(t1, |e: NextContact| e.t());
            // samples in (t0, t_end] from the dense output (exactly y at the step end)
            while next_sample <= spec.samples && sample_time(next_sample) <= t_end {
                let ts = sample_time(next_sample);
                if ts == t1 {
                    let y = st.y().clone();
                    record(&mut run, ts, &y)?;
                } else {
                    let y = st.dense().map_err(ode_err)?.eval(ts);
                    record(&mut run, ts, &y)?;
                }
                next_sample += 1;
            }
            match event {
                Some(NextContact::Touch(te)) => {
                    let mut y = st.dense().map_err(ode_err)?.eval(te);
                    let mut c = contacts.borrow_mut();
                    if self.impact_at(te, &mut y, &mut c, &mut run.work).map_err(|e| fail(te, e))? == 0 {
                        return Err(fail(te, "a contact closed but no impact could be resolved".into()));
                    }
                    if te <= t0 {
                        return Err(fail(
                            te,
                            "a contact's impacts accumulate at one instant and it cannot come to rest; valid: \
                             restitution 1, or a duration that ends before the bounces die out"
                                .into(),
                        ));
                    }
                    self.settle(te, &mut y, &mut c, tau_min).map_err(|e| fail(te, e))?;
                    run.work.restarts += 1;
                    if constrained {
                        let (before, after) =
                            self.project(&mut y, &mut step_projection).map_err(|e| fail(te, e))?;
                        run.note_projection(before, after);
                    }
                    geo = self.gaps(&y).map_err(|e| fail(te, e))?;
                    drop(c);
                    st.restart(te, y).map_err(ode_err)?;
                }
                Some(NextContact::LiftOff(te, k)) => {
                    let y = st.dense().map_err(ode_err)?.eval(te);
                    let mut c = contacts.borrow_mut();
                    c.resting[k] = false;
                    let effect = self.contacts[k];
                    let kind = ContactEventKind::LiftOff;
                    c.record(ContactEvent { t: te, effect, kind, closing_speed: 0.0, opening_speed: 0.0 });
                    run.work.restarts += 1;
                    geo = self.gaps(&y).map_err(|e| fail(te, e))?;
                    drop(c);
                    st.restart(te, y).map_err(ode_err)?;
                }
                None if contacts.borrow().resting.contains(&true) => {
                    // resting spheres that drifted off their planes are put back
                    let mut y = st.y().clone();
                    if self.hold_resting(t1, &mut y, &contacts.borrow()).map_err(|e| fail(t1, e))? {
                        geo = self.gaps(&y).map_err(|e| fail(t1, e))?;
                        st.restart(t1, y).map_err(ode_err)?;
                        run.work.projections += 1;
                    }
                }
                None if constrained => {
                    // drift control: back onto φ(q) = 0 and G v = 0, and restart from there
                    let mut y = st.y().clone();
                    let (before, after) =
                        self.project(&mut y, &mut step_projection).map_err(|e| fail(t1, e))?;
                    run.note_projection(before, after);
                    if before != after {
                        st.restart(t1, y).map_err(ode_err)?;
                        run.work.projections += 1;
                    }
                }
                None => {}
            }
            (ctl.progress)(st.t() / duration);
            // budgets: cancellation every step, wall time and the pace every 64 steps
            let steps = st.work().accepted + st.work().rejected;
            let t = st.t();
            let mut stop = None;
            if ctl.cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
                stop = Some((StopReason::Interrupted, format!("interrupted at t = {t} s of {duration} s")));
            } else if steps >= last_check + 64 || steps + 1 >= self.solver.max_steps() {
                last_check = steps;
                let wall = start.elapsed().as_secs_f64();
                let pace = duration / t.max(f64::MIN_POSITIVE);
                let (max_steps, s) = (self.solver.max_steps() as f64, steps as f64);
                if steps + 1 >= self.solver.max_steps()
                    || (steps >= 1024 && s * pace > FAIL_FAST_FACTOR * max_steps)
                {
                    stop = Some((
                        StopReason::MaxSteps,
                        format!(
                            "{steps} steps reached t = {t:.6e} s of duration = {duration} s; at this pace the run \
                             needs about {:.1e} steps, more than max_steps = {}; valid: raise max_steps, loosen \
                             accuracy or shorten duration",
                            s * pace,
                            self.solver.max_steps()
                        ),
                    ));
                } else if wall >= max_wall || (wall >= 0.5 && wall * pace > FAIL_FAST_FACTOR * max_wall) {
                    stop = Some((
                        StopReason::MaxWallSeconds,
                        format!(
                            "{wall:.1} s of wall time reached t = {t:.6e} s of duration = {duration} s; at this \
                             pace the run needs about {:.1e} s, more than max_wall_seconds = {max_wall}; valid: \
                             raise max_wall_seconds, loosen accuracy or shorten duration",
                            wall * pace
                        ),
                    ));
                }
            }
            if let Some((reason, message)) = stop {
                run.stop = Some(Stop { reason, t, message });
                break;
            }
        }
        let work = st.work();
        run.work.fevals = work.fevals;
        run.work.accepted = work.accepted;
        run.work.rejected = work.rejected;
        let y = st.y().clone();
        run.contacts = std::mem::take(&mut contacts.borrow_mut().events);
        Ok(self.finish(run, trackers, y, start, peak.get()))
    }

    /// The drift of the checked invariants, the final state and the wall time; a run that
    /// reached its duration with numbers outside their meaningful range is marked incomplete
    /// (`peak`: the largest |y_i| at the samples, its time and index).
    fn finish(
        &self,
        mut run: Run,
        trackers: Vec<Tracker>,
        mut y: Vec<f64>,
        start: Instant,
        peak: (f64, f64, usize),
    ) -> Run {
        run.drift = trackers
            .into_iter()
            .map(|tr| {
                let x0 = tr.x0.unwrap_or_default();
                Drift {
                    initial: tr.value(x0),
                    last: tr.value(tr.last),
                    max_abs: tr.max,
                    scale: x0.norm().max(tr.scale),
                    max_rel: tr.max / x0.norm().max(tr.scale).max(f64::MIN_POSITIVE),
                    invariant: tr.inv,
                }
            })
            .collect();
        if run.stop.is_none() {
            run.stop = self.untrusted(&run, peak);
        }
        normalize(&self.built.bodies, &mut y[..self.built.model.nq()]);
        run.final_state = y;
        run.work.wall_seconds = start.elapsed().as_secs_f64();
        run
    }

    /// Why a run that reached its duration cannot be trusted, if it cannot: a state component
    /// above [`MAX_TRUSTED_STATE`] (`peak`: its magnitude, time and index in y = (q, v)), or a
    /// checked invariant (conserved by the declared effects) whose relative drift reached
    /// [`MAX_TRUSTED_DRIFT`] or is not finite.
    fn untrusted(&self, run: &Run, (x, t, i): (f64, f64, usize)) -> Option<Stop> {
        let t_end = run.t.last().copied().unwrap_or(0.0);
        if x > MAX_TRUSTED_STATE || x.is_nan() {
            let nq = self.built.model.nq();
            let which = if i < nq { format!("q[{i}]") } else { format!("v[{}]", i - nq) };
            return Some(Stop {
                reason: StopReason::StateOutOfRange,
                t,
                message: format!(
                    "the state component {which} reached {x:e} at t = {t} s, beyond {MAX_TRUSTED_STATE:e} (about \
                     √ of the largest f64), where energies and squared lengths overflow and angles have no digits \
                     left; valid: an initial state and motion well inside ±{MAX_TRUSTED_STATE:e} (SI)"
                ),
            });
        }
        let d = run.drift.iter().find(|d| d.max_rel >= MAX_TRUSTED_DRIFT || d.max_rel.is_nan())?;
        Some(Stop {
            reason: StopReason::InvariantDrift,
            t: t_end,
            message: format!(
                "{} drifted by {:.2e} relative to its scale over the run, not below {MAX_TRUSTED_DRIFT:e}, although \
                 the declared effects conserve it: the numbers do not mean what they say; valid: a tighter \
                 accuracy, a shorter duration, or an initial state whose terms f64 can resolve",
                d.invariant.name(),
                d.max_rel
            ),
        })
    }
}
