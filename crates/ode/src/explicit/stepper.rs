//! Step-by-step adaptive integration: one accepted step at a time, the interpolant of that
//! step on demand, and restarts after a jump of the state. A caller that samples outputs,
//! handles impacts, shows progress or enforces a budget drives the integration itself, so
//! that sampling never restarts the integrator (a restart costs a new first stage and
//! forgets the step size history).
//!
//! Book: §4.11; HNW §II.4 (step-size control), §II.6 (dense output).

use super::adaptive::{Adaptive, Pair, initial_step};
use super::dense::DenseStep;
use super::{dop853, dopri5};
use crate::error::{check_interval, check_step, check_tol};
use crate::state::{State, check_state, eval};
use crate::{OdeError, Work};

/// An adaptive integration in progress: [`Stepper::step`] takes one accepted step,
/// [`Stepper::dense`] gives that step's interpolant (computed only when asked: DOP853 pays
/// three more evaluations for it), [`Stepper::restart`] continues from a new state after a
/// discontinuity (an impact, a projection, a switch of a load profile).
///
/// ```
/// use vectrix_ode::explicit::{Adaptive, Stepper};
/// // y′ = −y on [0, 1], sampled at t = 0.25, 0.5, 0.75 from the interpolants
/// let mut st = Stepper::new(&Adaptive::dop853().rtol(1e-10).atol(1e-12), |_t: f64, y: &f64| -y, 0.0, 1.0, 1.0)
///     .unwrap();
/// let mut samples = vec![];
/// let mut next = 0.25;
/// while !st.done() {
///     st.step().unwrap();
///     while next < 1.0 && next <= st.t() {
///         samples.push(st.dense().unwrap().eval(next));
///         next += 0.25;
///     }
/// }
/// for (k, y) in samples.iter().enumerate() {
///     assert!((y - (-0.25 * (k + 1) as f64).exp()).abs() < 1e-10);
/// }
/// ```
///
/// Book: §4.11; HNW §II.4, §II.6.
pub struct Stepper<S: State, F: FnMut(f64, &S) -> S> {
    cfg: Adaptive,
    f: F,
    t: f64,
    y: S,
    t_end: f64,
    h: f64,
    h_max: f64,
    /// Stages of the last accepted step (k₁ = f at its start).
    k: Vec<S>,
    /// f(t, y) at the current point: the next step's first stage.
    f_now: S,
    /// Start (t, y) of the last accepted step, if one was taken since the last restart.
    prev: Option<(f64, S)>,
    dense: Option<DenseStep<S>>,
    work: Work,
    /// ln of the previous accepted step's error (at least 1e-4): the PI controller's memory.
    ln_fac_old: f64,
    last_rejected: bool,
}

impl<S: State, F: FnMut(f64, &S) -> S> core::fmt::Debug for Stepper<S, F> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Stepper").field("t", &self.t).field("h", &self.h).field("work", &self.work).finish()
    }
}

impl<S: State, F: FnMut(f64, &S) -> S> Stepper<S, F> {
    /// Starts integrating y′ = f(t, y), y(t0) = y0 toward `t_end` with the method,
    /// tolerances and limits of `cfg` (its `dense` flag is ignored: ask [`Stepper::dense`]).
    ///
    /// # Errors
    /// [`OdeError::InvalidInterval`], [`OdeError::NonPositiveTolerance`],
    /// [`OdeError::NonPositiveStep`], [`OdeError::NonFiniteState`], and
    /// [`OdeError::RhsNotFinite`] or [`OdeError::DimensionMismatch`] from the first evaluations.
    pub fn new(cfg: &Adaptive, mut f: F, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        check_interval(t0, t_end)?;
        check_tol("rtol", cfg.rtol)?;
        check_tol("atol", cfg.atol)?;
        let h_max = cfg.h_max.unwrap_or(t_end - t0);
        check_step(h_max)?;
        // A step cap that cannot cover [t0, t_end] within max_steps fails now, not after
        // max_steps evaluations (h_max = 1e-300 would otherwise spin through them).
        if (t_end - t0) / h_max > cfg.max_steps as f64 {
            return Err(OdeError::TooManySteps { t: t0, max_steps: cfg.max_steps });
        }
        if let Some(h0) = cfg.h0 {
            check_step(h0)?;
        }
        check_state(t0, &y0)?;
        let mut work = Work::default();
        let f_now = eval(&mut f, t0, &y0, t0, 1, &mut work.fevals)?;
        let h = match cfg.h0 {
            Some(h0) => h0.min(h_max),
            None => initial_step(
                &mut f,
                t0,
                &y0,
                &f_now,
                order(cfg.pair),
                h_max,
                (cfg.rtol, cfg.atol),
                &mut work,
            )?,
        };
        Ok(Self {
            cfg: *cfg,
            f,
            t: t0,
            y: y0,
            t_end,
            h,
            h_max,
            k: Vec::with_capacity(16),
            f_now,
            prev: None,
            dense: None,
            work,
            ln_fac_old: 1e-4f64.ln(),
            last_rejected: false,
        })
    }

    /// The current time (the end of the last accepted step).
    pub fn t(&self) -> f64 {
        self.t
    }

    /// The current state.
    pub fn y(&self) -> &S {
        &self.y
    }

    /// The start of the last accepted step (`None` right after [`Stepper::new`] or a restart).
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

    /// Takes one accepted step (rejected attempts are retried inside, smaller); the last step
    /// lands exactly on the end time. Does nothing when [`Stepper::done`].
    ///
    /// # Errors
    /// [`OdeError::TooManySteps`] (accepted + rejected reached `max_steps`),
    /// [`OdeError::StepSizeUnderflow`], [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`].
    pub fn step(&mut self) -> Result<(), OdeError> {
        if self.done() {
            return Ok(());
        }
        let tol = (self.cfg.rtol, self.cfg.atol);
        let (ord, beta, fac_min, fac_max) = match self.cfg.pair {
            Pair::Dopri5 => (5.0, 0.04, 0.2, 10.0),
            Pair::Dop853 => (8.0, 0.0, 0.333, 6.0),
        };
        let expo1 = 1.0 / ord - beta * 0.75;
        let safe = 0.9;
        let (t, t1) = (self.t, self.t_end);
        let mut h = self.h;
        loop {
            if self.work.accepted + self.work.rejected >= self.cfg.max_steps {
                return Err(OdeError::TooManySteps { t, max_steps: self.cfg.max_steps });
            }
            if 0.1 * h.abs() <= t.abs() * f64::EPSILON {
                return Err(OdeError::StepSizeUnderflow { t, h });
            }
            // last step lands exactly on t1 (Hairer: if t + 1.01h ≥ t1, h = t1 − t)
            let last = t + 1.01 * h >= t1;
            if last {
                h = t1 - t;
            }
            self.k.clear();
            self.k.push(self.f_now.clone());
            let (y1, err) = match self.cfg.pair {
                Pair::Dopri5 => dopri5::step(&mut self.f, t, &self.y, h, &mut self.k, tol, &mut self.work)?,
                Pair::Dop853 => dop853::step(&mut self.f, t, &self.y, h, &mut self.k, tol, &mut self.work)?,
            };
            // step-size factor: fac = err^{expo1} / fac_old^β / safe, clamped; as one exp of
            // logarithms (one ln and one exp a step instead of two powf, the controller's whole
            // cost on a cheap right-hand side), ln(fac_old) kept from the last accepted step
            let ln_err = err.ln();
            if err <= 1.0 {
                let fac = ((expo1 * ln_err - beta * self.ln_fac_old).exp() / safe)
                    .clamp(1.0 / fac_max, 1.0 / fac_min);
                let mut h_new = (h / fac).min(self.h_max);
                if self.last_rejected {
                    h_new = h_new.min(h);
                }
                self.ln_fac_old = ln_err.max(1e-4f64.ln());
                self.work.accepted += 1;
                self.last_rejected = false;
                let t_new = if last { t1 } else { t + h };
                // f(t + h, y₁): FSAL stage of DOPRI5, the next k₁ (and k₁₃) for DOP853
                let f1 = match self.cfg.pair {
                    Pair::Dopri5 => self.k[6].clone(),
                    Pair::Dop853 => eval(&mut self.f, t_new, &y1, t, 13, &mut self.work.fevals)?,
                };
                let y0 = std::mem::replace(&mut self.y, y1);
                self.prev = Some((t, y0));
                self.f_now = f1;
                self.dense = None;
                self.t = t_new;
                // a step cut short to land on t1 keeps the controller's proposal
                self.h = if last { h_new.max(self.h) } else { h_new };
                return Ok(());
            }
            h /= ((expo1 * ln_err).exp() / safe).min(1.0 / fac_min);
            self.work.rejected += 1;
            self.last_rejected = true;
        }
    }

    /// The interpolant of the last accepted step, valid on [`Stepper::step_start`] ..
    /// [`Stepper::t`] (order 4 for DOPRI5, 7 for DOP853; DOP853 spends three evaluations
    /// the first time it is asked for a step).
    ///
    /// # Errors
    /// [`OdeError::NoDenseOutput`] before the first step or right after a restart;
    /// [`OdeError::RhsNotFinite`] from DOP853's extra stages.
    pub fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        if self.dense.is_none() {
            let Some((t0, y0)) = &self.prev else { return Err(OdeError::NoDenseOutput) };
            let h = self.t - t0;
            let d = match self.cfg.pair {
                Pair::Dopri5 => dopri5::dense(*t0, y0, &self.y, h, &self.k),
                Pair::Dop853 => {
                    dop853::dense(&mut self.f, *t0, y0, &self.y, h, &mut self.k, &self.f_now, &mut self.work)?
                }
            };
            self.dense = Some(d);
        }
        self.dense.as_ref().ok_or(OdeError::NoDenseOutput)
    }

    /// Continues from (t, y) after a jump of the state or of the right-hand side (an impact,
    /// a projection onto a constraint manifold, a switching load): f is evaluated afresh and
    /// the step size proposal is kept (bounded by the new remaining interval).
    ///
    /// # Errors
    /// [`OdeError::NonFiniteState`], [`OdeError::InvalidInterval`] if t is past the end,
    /// [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`].
    pub fn restart(&mut self, t: f64, y: S) -> Result<(), OdeError> {
        check_interval(t, self.t_end).or_else(|e| if t == self.t_end { Ok(()) } else { Err(e) })?;
        check_state(t, &y)?;
        if y.dim() != self.y.dim() {
            return Err(OdeError::DimensionMismatch {
                what: "restarted state",
                got: y.dim(),
                expected: self.y.dim(),
            });
        }
        self.f_now = eval(&mut self.f, t, &y, t, 1, &mut self.work.fevals)?;
        self.t = t;
        self.y = y;
        self.prev = None;
        self.dense = None;
        self.last_rejected = false;
        Ok(())
    }

    /// Moves the end time (e.g. to stop exactly at a known discontinuity of the right-hand
    /// side, then [`Stepper::restart`] there).
    ///
    /// # Errors
    /// [`OdeError::InvalidInterval`] unless t_end > [`Stepper::t`] and finite.
    pub fn set_end(&mut self, t_end: f64) -> Result<(), OdeError> {
        check_interval(self.t, t_end)?;
        self.t_end = t_end;
        // without a cap of the user's, the cap is the interval still to go (not the first
        // interval's length: a first piece of 1e-13 s must not cap every later step)
        if self.cfg.h_max.is_none() {
            self.h_max = t_end - self.t;
        }
        Ok(())
    }

    /// The end time.
    pub fn end(&self) -> f64 {
        self.t_end
    }
}

/// Classical order of the propagated solution.
fn order(p: Pair) -> f64 {
    match p {
        Pair::Dopri5 => 5.0,
        Pair::Dop853 => 8.0,
    }
}
