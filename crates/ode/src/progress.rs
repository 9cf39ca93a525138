//! Where a step-by-step run stands — time, state, the last accepted step, the step size
//! proposed, the end time and the work — shared by every stepper ([`Stepper`],
//! [`RadauStepper`], [`BdfStepper`]), which dereference to it for these accessors.
//!
//! [`Stepper`]: crate::explicit::Stepper
//! [`RadauStepper`]: crate::RadauStepper
//! [`BdfStepper`]: crate::BdfStepper

use crate::OdeError;
use crate::error::check_interval;
use crate::explicit::DenseStep;
use crate::state::{State, check_state};
use crate::work::Work;

/// The progress of a run: t, y, the start of the last accepted step and its interpolant, the
/// step size the controller proposes next, the end time and the work so far.
///
/// Book: §4.11; HNW §II.4.
#[derive(Debug, Clone)]
pub struct Progress<S> {
    pub(crate) t: f64,
    pub(crate) y: S,
    pub(crate) t_end: f64,
    pub(crate) h: f64,
    pub(crate) h_max: f64,
    /// The caller's step bound (`None`: the interval still to go).
    pub(crate) h_max_user: Option<f64>,
    /// Start (t, y) of the last accepted step, if one was taken since the last restart.
    pub(crate) prev: Option<(f64, S)>,
    pub(crate) dense: Option<DenseStep<S>>,
    pub(crate) work: Work,
}

impl<S: State> Progress<S> {
    pub(crate) fn new(t0: f64, y0: S, t_end: f64, h_max: f64, h_max_user: Option<f64>, work: Work) -> Self {
        Self { t: t0, y: y0, t_end, h: h_max, h_max, h_max_user, prev: None, dense: None, work }
    }

    /// The current time (the end of the last accepted step).
    pub fn t(&self) -> f64 {
        self.t
    }
    /// The current state.
    pub fn y(&self) -> &S {
        &self.y
    }
    /// The start of the last accepted step (`None` right after the stepper's `new` or a restart).
    pub fn step_start(&self) -> Option<f64> {
        self.prev.as_ref().map(|p| p.0)
    }
    /// `true` once the end time has been reached.
    pub fn done(&self) -> bool {
        self.t >= self.t_end
    }
    /// The work so far (wall time is not measured here).
    pub fn work(&self) -> Work {
        self.work
    }
    /// The step size the controller proposes next.
    pub fn proposed_step(&self) -> f64 {
        self.h
    }
    /// The end time.
    pub fn end(&self) -> f64 {
        self.t_end
    }

    /// Moves the end time (e.g. to stop exactly at a known discontinuity of the right-hand
    /// side, then restart there).
    ///
    /// # Errors
    /// [`OdeError::InvalidInterval`] unless t_end > [`Progress::t`] and finite.
    pub fn set_end(&mut self, t_end: f64) -> Result<(), OdeError> {
        check_interval(self.t, t_end)?;
        self.t_end = t_end;
        // without a cap of the user's, the cap is the interval still to go (not the first
        // interval's length: a first piece of 1e-13 s must not cap every later step)
        if self.h_max_user.is_none() {
            self.h_max = t_end - self.t;
        }
        Ok(())
    }

    /// The checks of a restart at (t, y): t not past the end, y finite and of the same
    /// dimension. On success forgets the last step (its interpolant no longer applies).
    pub(crate) fn check_restart(&mut self, t: f64, y: &S) -> Result<(), OdeError> {
        check_interval(t, self.t_end).or_else(|e| if t == self.t_end { Ok(()) } else { Err(e) })?;
        check_state(t, y)?;
        if y.dim() != self.y.dim() {
            return Err(OdeError::DimensionMismatch {
                what: "restarted state",
                got: y.dim(),
                expected: self.y.dim(),
            });
        }
        self.prev = None;
        self.dense = None;
        Ok(())
    }

    /// Moves to an accepted step's end (t_new, y1), keeping its start for the interpolant.
    pub(crate) fn advance(&mut self, t_new: f64, y1: S) {
        let y0 = std::mem::replace(&mut self.y, y1);
        self.prev = Some((self.t, y0));
        self.t = t_new;
        self.dense = None;
        self.work.accepted += 1;
    }
}
