//! Running a scene: **one** adaptive integration over [0, duration] (the method from the
//! declared accuracy through `vectrix_ode::Accuracy`, or named). Output samples come from the
//! dense output of the accepted steps, so their number does not change the steps taken;
//! impacts are located events (zeros of the contact gaps on the interpolant), and the known
//! discontinuities of applied-load profiles are step ends; at both the integration restarts.
//! Budgets (steps, wall time) and cancellation stop a run cleanly with what was computed.
//!
//! Book: §4.11 (integration), §7.13 (impacts), §8.3 (energy), §7.4/§7.6 (momenta).

use std::cell::{Cell, RefCell};
use std::sync::atomic::Ordering;
use std::time::Instant;

use nalgebra::Vector3;
use vectrix_ode::{AnyStepper, OdeError};

use super::contacts::{ContactEvent, ContactEventKind, Contacts, Gap, NextContact};
use super::limits::breakpoints;
use super::outcome::{Run, RunControl, Stop, StopReason};
use super::project::ProjectScratch;
use super::rhs::{RhsScratch, RunRhs};
use super::sampling::{Sampler, Tracker};
use super::{Scene, SceneError};

/// Default bound on the wall time of a run [s].
pub const DEFAULT_MAX_WALL_SECONDS: f64 = 600.0;
/// A run whose pace predicts more than this multiple of a budget stops at once (fail fast).
const FAIL_FAST_FACTOR: f64 = 10.0;
/// A right-hand side as the run's steppers take it.
trait Rhs: vectrix_ode::Rhs<Vec<f64>> {}
impl<F: vectrix_ode::Rhs<Vec<f64>>> Rhs for F {}
/// A Jacobian as the implicit steppers take it (row-major into the slice).
trait Jac: FnMut(f64, &Vec<f64>, &mut [f64]) {}
impl<J: FnMut(f64, &Vec<f64>, &mut [f64])> Jac for J {}
/// The stepper of a run.
type Steps<F, J> = AnyStepper<Vec<f64>, F, J>;

/// A failure at time t.
fn fail(t: f64, message: String) -> SceneError {
    SceneError::Run { t, message }
}

/// One run's state besides the stepper: the rows so far, the samples' trackers, the contacts
/// (shared with the right-hand side, which reads which of them rest), the first failure of
/// the right-hand side, and the gaps at the last step end.
struct Pass<'a> {
    scene: &'a Scene,
    run: Run,
    sampler: Sampler,
    contacts: &'a RefCell<Contacts>,
    failure: &'a RefCell<Option<String>>,
    /// The drift projection's work space (step ends and events).
    projection: ProjectScratch,
    geo: Vec<Gap>,
    next_sample: usize,
    /// A rebound shorter than this comes to rest; the contact scan splits no shorter piece
    /// than a quarter of it, so a flight of `tau_min` is always seen.
    tau_min: f64,
}

impl<'a> Pass<'a> {
    fn new(scene: &'a Scene, contacts: &'a RefCell<Contacts>, failure: &'a RefCell<Option<String>>) -> Self {
        let spec = scene.spec();
        let trackers = scene
            .invariants()
            .iter()
            .filter(|i| spec.checks.iter().any(|c| c == i.name()))
            .map(|i| Tracker { inv: i.clone(), x0: None, last: Vector3::zeros(), scale: 0.0, max: 0.0 })
            .collect();
        Self {
            scene,
            run: Run::empty(scene),
            sampler: Sampler { trackers, peak: (0.0, 0.0, 0), projection: ProjectScratch::default() },
            contacts,
            failure,
            projection: ProjectScratch::default(),
            geo: Vec::new(),
            next_sample: 1,
            tau_min: super::REST_TIME_REL * spec.duration,
        }
    }

    /// The time of sample k.
    fn sample_time(&self, k: usize) -> f64 {
        let spec = self.scene.spec();
        spec.duration * (k as f64 / spec.samples as f64)
    }

    /// Where the integration stops, in order, and whether it restarts there: the corners and
    /// jumps of the load profiles (restart), the sample times for a method without an
    /// interpolant (`gbs`, `vern9`: they land on them), and the end.
    fn stops(&self) -> Vec<(f64, bool)> {
        let spec = self.scene.spec();
        let mut stops: Vec<(f64, bool)> = breakpoints(spec).into_iter().map(|t| (t, true)).collect();
        if !self.scene.solver.has_interpolant() {
            stops.extend((1..spec.samples).map(|k| (self.sample_time(k), false)));
            // a sample at a corner restarts there
            stops.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.cmp(&a.1)));
            stops.dedup_by(|b, a| a.0 == b.0);
        }
        stops.push((spec.duration, false));
        stops
    }

    /// At the stop `(t, restart)`: on to the next stop `end` (the load profiles see the piece
    /// between them), continuing with a fresh first stage at a corner of a load profile.
    fn next_piece<F: Rhs, J: Jac>(
        &mut self,
        st: &mut Steps<F, J>,
        ((t, restart), end): ((f64, bool), f64),
        piece: &Cell<(f64, f64)>,
    ) -> Result<(), SceneError> {
        st.set_end(end).map_err(|e| self.ode_err(e))?;
        piece.set((t, end));
        if restart {
            let (t, y) = (st.t(), st.y().clone());
            st.restart(t, y).map_err(|e| self.ode_err(e))?;
            self.run.work.restarts += 1;
        }
        Ok(())
    }

    /// Records the sample (t, y).
    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SceneError> {
        self.scene.record(&mut self.sampler, &mut self.run, t, y)
    }

    /// An integrator error, with the right-hand side's own message when it failed first.
    fn ode_err(&self, e: OdeError) -> SceneError {
        let t = match &e {
            OdeError::RhsNotFinite { t, .. }
            | OdeError::StepSizeUnderflow { t, .. }
            | OdeError::NonFiniteState { t, .. }
            | OdeError::SingularIterationMatrix { t, .. }
            | OdeError::NewtonStalled { t, .. }
            | OdeError::JacobianNotFinite { t, .. } => *t,
            _ => 0.0,
        };
        fail(t, self.failure.borrow_mut().take().unwrap_or_else(|| e.to_string()))
    }

    /// The initial state, its impacts resolved and resting contacts settled, projected onto the
    /// constraints; recorded as the first sample.
    fn start(&mut self) -> Result<Vec<f64>, SceneError> {
        let scene = self.scene;
        let mut y0 = scene.initial_state();
        if scene.needs.impacts {
            let mut c = self.contacts.borrow_mut();
            scene.impact_at(0.0, &mut y0, &mut c, &mut self.run.work).map_err(|e| fail(0.0, e))?;
            scene.settle(0.0, &mut y0, &mut c, self.tau_min).map_err(|e| fail(0.0, e))?;
        }
        if scene.has_constraints() {
            let (before, after) = scene.project(&mut y0, &mut self.projection).map_err(|e| fail(0.0, e))?;
            self.run.note_projection(before, after);
        }
        self.record(0.0, &y0)?;
        Ok(y0)
    }

    /// The first contact event of the step just taken: a touch located on the interpolant, or
    /// a resting contact's lift-off (the gaps at the step end are kept for the next step).
    fn contact_event<F: Rhs, J: Jac>(
        &mut self,
        st: &mut Steps<F, J>,
    ) -> Result<Option<NextContact>, SceneError> {
        if !self.scene.needs.impacts {
            return Ok(None);
        }
        let (t0, t1) = (st.step_start().unwrap_or(0.0), st.t());
        let g1 = self.scene.gaps(st.y()).map_err(|e| fail(t1, e))?;
        let y1 = st.y().clone();
        let dense = st.dense().map_err(|e| self.ode_err(e))?;
        let found = self.scene.next_contact_event(
            dense,
            (t0, &self.geo),
            (t1, &g1),
            &y1,
            &self.contacts.borrow(),
            self.tau_min,
        );
        self.geo = g1;
        found.map_err(|e| fail(t1, e))
    }

    /// The samples in (t0, t_end] of the step just taken, from its dense output (exactly y at
    /// the step end).
    fn samples_until<F: Rhs, J: Jac>(&mut self, st: &mut Steps<F, J>, t_end: f64) -> Result<(), SceneError> {
        let t1 = st.t();
        while self.next_sample <= self.scene.spec().samples && self.sample_time(self.next_sample) <= t_end {
            let ts = self.sample_time(self.next_sample);
            let y = if ts == t1 { st.y().clone() } else { st.dense().map_err(|e| self.ode_err(e))?.eval(ts) };
            self.record(ts, &y)?;
            self.next_sample += 1;
        }
        Ok(())
    }

    /// After a step: an impact (restart after it), a lift-off (restart), resting contacts put
    /// back on their planes, or the drift projection onto the constraints.
    fn after<F: Rhs, J: Jac>(
        &mut self,
        st: &mut Steps<F, J>,
        event: Option<NextContact>,
    ) -> Result<(), SceneError> {
        let scene = self.scene;
        let (t0, t1) = (st.step_start().unwrap_or(0.0), st.t());
        match event {
            Some(NextContact::Touch(te)) => {
                let mut y = st.dense().map_err(|e| self.ode_err(e))?.eval(te);
                let mut c = self.contacts.borrow_mut();
                if scene.impact_at(te, &mut y, &mut c, &mut self.run.work).map_err(|e| fail(te, e))? == 0 {
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
                scene.settle(te, &mut y, &mut c, self.tau_min).map_err(|e| fail(te, e))?;
                drop(c);
                self.run.work.restarts += 1;
                if scene.has_constraints() {
                    let (before, after) =
                        scene.project(&mut y, &mut self.projection).map_err(|e| fail(te, e))?;
                    self.run.note_projection(before, after);
                }
                self.geo = scene.gaps(&y).map_err(|e| fail(te, e))?;
                st.restart(te, y).map_err(|e| self.ode_err(e))?;
            }
            Some(NextContact::LiftOff(te, k)) => {
                let y = st.dense().map_err(|e| self.ode_err(e))?.eval(te);
                let mut c = self.contacts.borrow_mut();
                c.resting[k] = false;
                let (effect, kind) = (scene.contacts[k], ContactEventKind::LiftOff);
                c.record(ContactEvent { t: te, effect, kind, closing_speed: 0.0, opening_speed: 0.0 });
                drop(c);
                self.run.work.restarts += 1;
                self.geo = scene.gaps(&y).map_err(|e| fail(te, e))?;
                st.restart(te, y).map_err(|e| self.ode_err(e))?;
            }
            None if self.contacts.borrow().resting.contains(&true) => {
                // resting spheres that drifted off their planes are put back
                let mut y = st.y().clone();
                let moved =
                    scene.hold_resting(t1, &mut y, &self.contacts.borrow()).map_err(|e| fail(t1, e))?;
                if moved {
                    self.geo = scene.gaps(&y).map_err(|e| fail(t1, e))?;
                    st.restart(t1, y).map_err(|e| self.ode_err(e))?;
                    self.run.work.projections += 1;
                }
            }
            None if scene.has_constraints() => {
                // drift control: back onto φ(q) = 0 and G v = 0, and restart from there
                let mut y = st.y().clone();
                let (before, after) = scene.project(&mut y, &mut self.projection).map_err(|e| fail(t1, e))?;
                self.run.note_projection(before, after);
                if before != after {
                    st.restart(t1, y).map_err(|e| self.ode_err(e))?;
                    self.run.work.projections += 1;
                }
            }
            None => {}
        }
        Ok(())
    }

    /// The run with its invariants' drift and final state.
    fn finish(self, y: Vec<f64>, start: Instant) -> Run {
        self.scene.finish(self.run, self.sampler.trackers, y, start, self.sampler.peak)
    }
}

impl Scene {
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
        let contacts =
            RefCell::new(Contacts { resting: vec![false; self.contacts.len()], events: Vec::new() });
        let failure = RefCell::new(None::<String>);
        let mut pass = Pass::new(self, &contacts, &failure);
        let y0 = pass.start()?;
        if self.built.model.nv() == 0 {
            // nothing moves (every joint a weld): the state is constant
            while pass.next_sample <= self.spec().samples {
                pass.record(pass.sample_time(pass.next_sample), &y0)?;
                pass.next_sample += 1;
            }
            (ctl.progress)(1.0);
            return Ok(pass.finish(y0, start));
        }
        let stops = pass.stops();
        // the piece between two corners of the load profiles the stepper is on
        let piece = Cell::new((0.0, stops[0].0));
        let f = RunRhs {
            scene: self,
            scratch: RhsScratch::new(self),
            piece: &piece,
            contacts: &contacts,
            failure: &failure,
        };
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
        let mut st =
            AnyStepper::with_rhs(&self.solver, f, jac, 0.0, y0, stops[0].0).map_err(|e| pass.ode_err(e))?;
        pass.geo = if self.needs.impacts { self.gaps(st.y()).map_err(|e| fail(0.0, e))? } else { Vec::new() };
        let (mut stop_at, mut last_check) = (0, 0);
        loop {
            if st.done() {
                if stop_at + 1 == stops.len() {
                    break;
                }
                stop_at += 1;
                pass.next_piece(&mut st, (stops[stop_at - 1], stops[stop_at].0), &piece)?;
            }
            match st.step() {
                Ok(()) => {}
                Err(OdeError::TooManySteps { t, max_steps }) => {
                    let duration = self.spec().duration;
                    pass.run.stop = Some(Stop {
                        reason: StopReason::MaxSteps,
                        t,
                        message: format!(
                            "max_steps = {max_steps} reached at t = {t:.6e} s of duration = {duration} s; valid: \
                             raise max_steps, loosen accuracy or shorten duration"
                        ),
                    });
                    break;
                }
                Err(e) => return Err(pass.ode_err(e)),
            }
            let event = pass.contact_event(&mut st)?;
            let t_end = event.map_or(st.t(), |e: NextContact| e.t());
            pass.samples_until(&mut st, t_end)?;
            pass.after(&mut st, event)?;
            (ctl.progress)(st.t() / self.spec().duration);
            // budgets: cancellation every step, wall time and the pace every 64 steps
            let steps = st.work().accepted + st.work().rejected;
            if let Some(stop) = self.budget(&ctl, (steps, &mut last_check), st.t(), start) {
                pass.run.stop = Some(stop);
                break;
            }
        }
        let work = st.work();
        pass.run.work.fevals = work.fevals;
        pass.run.work.accepted = work.accepted;
        pass.run.work.rejected = work.rejected;
        let y = st.y().clone();
        drop(st);
        pass.run.contacts = std::mem::take(&mut contacts.borrow_mut().events);
        Ok(pass.finish(y, start))
    }

    /// The budgets after `steps` steps at t: cancellation every step, wall time and the pace
    /// every 64 steps (from `last_check`, updated).
    fn budget(
        &self,
        ctl: &RunControl<'_>,
        (steps, last_check): (usize, &mut usize),
        t: f64,
        start: Instant,
    ) -> Option<Stop> {
        let duration = self.spec().duration;
        let stop = if ctl.cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
            Some((StopReason::Interrupted, format!("interrupted at t = {t} s of {duration} s")))
        } else if steps >= *last_check + 64 || steps + 1 >= self.solver.max_steps() {
            *last_check = steps;
            self.over_budget(steps, t, start.elapsed().as_secs_f64())
        } else {
            None
        };
        stop.map(|(reason, message)| Stop { reason, t, message })
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
}
