//! Running a scene: **one** adaptive integration over [0, duration] (the method from the
//! declared accuracy through `vectrix_ode::Accuracy`, or named). Output samples come from the
//! dense output of the accepted steps, so their number does not change the steps taken;
//! impacts are located events (zeros of the contact gaps on the interpolant), and the known
//! discontinuities of applied-load profiles are step ends; at both the integration restarts.
//! Budgets (steps, wall time) and cancellation stop a run cleanly with what was computed.
//!
//! Book: §4.11 (integration), §7.13 (impacts), §8.3 (energy), §7.4/§7.6 (momenta).

use std::sync::atomic::Ordering;
use std::time::Instant;

use nalgebra::Vector3;
use vectrix_ode::{AnyStepper, OdeError};

use super::contacts::{ContactEvent, ContactEventKind, Contacts, NextContact};
use super::kin::{Kin, kinematics};
use super::limits::breakpoints;
use super::outcome::{Drift, InvariantValue, Run, RunControl, Stop, StopReason};
use super::project::ProjectScratch;
use super::rhs::RhsScratch;
use super::{Invariant, Scene, SceneError};

/// Default bound on the wall time of a run [s].
pub const DEFAULT_MAX_WALL_SECONDS: f64 = 600.0;
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

/// What the samples keep besides the rows: the checked invariants, the largest |y_i| with its
/// time and index, and the projection's work space.
struct Sampler {
    trackers: Vec<Tracker>,
    peak: (f64, f64, usize),
    projection: ProjectScratch,
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
        let spec = self.spec();
        let duration = spec.duration;
        let mut run = Run::empty(self);
        let constrained = self.has_constraints();
        let mut step_projection = ProjectScratch::default();
        let sample_time = |k: usize| duration * (k as f64 / spec.samples as f64);
        let fail = |t: f64, e: String| SceneError::Run { t, message: e };
        let mut sampler = Sampler {
            trackers: self
                .invariants()
                .iter()
                .filter(|i| spec.checks.iter().any(|c| c == i.name()))
                .map(|i| Tracker { inv: i.clone(), x0: None, last: Vector3::zeros(), scale: 0.0, max: 0.0 })
                .collect(),
            peak: (0.0, 0.0, 0),
            projection: ProjectScratch::default(),
        };
        let mut record = |run: &mut Run, t: f64, y: &[f64]| self.record(&mut sampler, run, t, y);

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
            return Ok(self.finish(run, sampler.trackers, y0, start, sampler.peak));
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
            let stop = if ctl.cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
                Some((StopReason::Interrupted, format!("interrupted at t = {t} s of {duration} s")))
            } else if steps >= last_check + 64 || steps + 1 >= self.solver.max_steps() {
                last_check = steps;
                self.over_budget(steps, t, start.elapsed().as_secs_f64())
            } else {
                None
            };
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
        Ok(self.finish(run, sampler.trackers, y, start, sampler.peak))
    }

    /// The outputs and invariants at a sample (t, y) into `run` and `s`: the state normalized
    /// (and, with constraints, projected: a sample between step ends comes from the
    /// interpolant), then the row of the declared outputs.
    fn record(&self, s: &mut Sampler, run: &mut Run, t: f64, y: &[f64]) -> Result<(), SceneError> {
        let b = &self.built;
        let nq = b.model.nq();
        let fail = |e: String| SceneError::Run { t, message: e };
        let mut y = y.to_vec();
        b.model.normalize_quaternions(&mut y[..nq]);
        if let Some((i, x)) = y.iter().map(|x| x.abs()).enumerate().max_by(|a, b| a.1.total_cmp(&b.1))
            && x > s.peak.0
        {
            s.peak = (x, t, i);
        }
        if self.has_constraints() {
            let (_, after) = self.project(&mut y, &mut s.projection).map_err(fail)?;
            run.max_constraint_violation = Some(run.max_constraint_violation.unwrap_or_default().max(after));
        }
        let lambda =
            if self.needs_multipliers() { Some(self.multipliers(t, &y).map_err(fail)?) } else { None };
        let (q, v) = y.split_at(nq);
        let kin = kinematics(&b.model, q, v).map_err(fail)?;
        let mut row = Vec::with_capacity(run.columns.len());
        self.row(&kin, q, v, lambda.as_ref(), &mut row);
        run.t.push(t);
        run.rows.push(row);
        for tr in &mut s.trackers {
            let x = self.invariant_value(&tr.inv, &kin, q, v);
            // the size of the invariant's terms over the run (at t = 0 alone a pendulum
            // released from rest has no kinetic term to measure a drift against)
            tr.scale = tr.scale.max(self.invariant_scale(&tr.inv, &kin, v));
            let x0 = *tr.x0.get_or_insert(x);
            tr.last = x;
            tr.max = tr.max.max((x - x0).norm());
        }
        Ok(())
    }

    /// A run past its budgets after `steps` steps at simulated time `t` and `wall` seconds:
    /// `max_steps` or `max_wall_seconds` reached, or the pace so far predicting more than
    /// [`FAIL_FAST_FACTOR`] times either (a run that cannot finish stops at once).
    fn over_budget(&self, steps: usize, t: f64, wall: f64) -> Option<(StopReason, String)> {
        let spec = self.spec();
        let duration = spec.duration;
        let max_wall = spec.max_wall_seconds.unwrap_or(DEFAULT_MAX_WALL_SECONDS);
        let pace = duration / t.max(f64::MIN_POSITIVE);
        let (max_steps, s) = (self.solver.max_steps() as f64, steps as f64);
        if steps + 1 >= self.solver.max_steps() || (steps >= 1024 && s * pace > FAIL_FAST_FACTOR * max_steps)
        {
            Some((
                StopReason::MaxSteps,
                format!(
                    "{steps} steps reached t = {t:.6e} s of duration = {duration} s; at this pace the run \
                     needs about {:.1e} steps, more than max_steps = {}; valid: raise max_steps, loosen \
                     accuracy or shorten duration",
                    s * pace,
                    self.solver.max_steps()
                ),
            ))
        } else if wall >= max_wall || (wall >= 0.5 && wall * pace > FAIL_FAST_FACTOR * max_wall) {
            Some((
                StopReason::MaxWallSeconds,
                format!(
                    "{wall:.1} s of wall time reached t = {t:.6e} s of duration = {duration} s; at this \
                     pace the run needs about {:.1e} s, more than max_wall_seconds = {max_wall}; valid: \
                     raise max_wall_seconds, loosen accuracy or shorten duration",
                    wall * pace
                ),
            ))
        } else {
            None
        }
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
        self.built.model.normalize_quaternions(&mut y[..self.built.model.nq()]);
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
