//! Step-by-step adaptive integration: one accepted step at a time, the interpolant of that
//! step on demand, and restarts after a jump of the state. A caller that samples outputs,
//! handles impacts, shows progress or enforces a budget drives the integration itself, so
//! that sampling never restarts the integrator (a restart costs a new first stage and
//! forgets the step size history).
//!
//! Book: §4.11; HNW §II.4 (step-size control), §II.6 (dense output).

use super::dense::DenseStep;
use super::drive::Steps;
use super::pair::{Adaptive, Pair, initial_step, order};
use super::{dop853, dopri5, vern9};
use crate::progress::Progress;
use crate::state::{State, check_state, eval, eval_into};
use crate::{InPlace, Rhs};
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
pub struct Stepper<S: State, F: Rhs<S>> {
    cfg: Adaptive,
    f: F,
    /// t, y, the last step, h, the end time and the work (the accessors, by `Deref`).
    p: Progress<S>,
    /// Stages of the last accepted step (k₁ = f at its start).
    k: Vec<S>,
    /// f(t, y) at the current point: the next step's first stage.
    f_now: S,
    /// ln of the previous accepted step's error (at least 1e-4): the PI controller's memory.
    ln_fac_old: f64,
    last_rejected: bool,
}

impl<S: State, F: Rhs<S>> core::ops::Deref for Stepper<S, F> {
    type Target = Progress<S>;
    fn deref(&self) -> &Progress<S> {
        &self.p
    }
}

impl<S: State, F: Rhs<S>> core::ops::DerefMut for Stepper<S, F> {
    fn deref_mut(&mut self) -> &mut Progress<S> {
        &mut self.p
    }
}

impl<S: State, F: Rhs<S>> Steps<S> for Stepper<S, F> {
    fn step(&mut self) -> Result<(), OdeError> {
        Stepper::step(self)
    }
    fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        Stepper::dense(self)
    }
}

impl<S: State, F: Rhs<S>> core::fmt::Debug for Stepper<S, F> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Stepper")
            .field("t", &self.p.t)
            .field("h", &self.p.h)
            .field("work", &self.p.work)
            .finish()
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
    pub fn new(cfg: &Adaptive, f: F, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        Self::start(cfg, f, t0, y0, t_end)
    }
}

impl<S: State, G: FnMut(f64, &S, &mut S)> Stepper<S, InPlace<G>> {
    /// [`Stepper::new`] with f written in place, `g(t, y, out)` ([`InPlace`]): the same steps
    /// and bits, without an allocation per evaluation for a heap state.
    ///
    /// # Errors
    /// As [`Stepper::new`].
    pub fn new_in_place(cfg: &Adaptive, g: G, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        Self::start(cfg, InPlace(g), t0, y0, t_end)
    }
}

impl<S: State, F: Rhs<S>> Stepper<S, F> {
    /// [`Stepper::new`] for any [`Rhs`].
    pub(crate) fn start(cfg: &Adaptive, mut f: F, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        let h_max = cfg.check(t0, t_end)?;
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
                order(cfg.method),
                h_max,
                (cfg.rtol, cfg.atol),
                &mut work,
            )?,
        };
        let mut p = Progress::new(t0, y0, t_end, h_max, cfg.h_max, work);
        p.h = h;
        Ok(Self {
            cfg: *cfg,
            f,
            p,
            k: Vec::with_capacity(16),
            f_now,
            ln_fac_old: 1e-4f64.ln(),
            last_rejected: false,
        })
    }

    /// Takes one accepted step (rejected attempts are retried inside, smaller); the last step
    /// lands exactly on the end time. Does nothing when [`done`](Progress::done).
    ///
    /// # Errors
    /// [`OdeError::TooManySteps`] (accepted + rejected reached `max_steps`),
    /// [`OdeError::StepSizeUnderflow`], [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`].
    pub fn step(&mut self) -> Result<(), OdeError> {
        if self.done() {
            return Ok(());
        }
        let tol = (self.cfg.rtol, self.cfg.atol);
        // order, β, clamps of the factor, safety factor (see [`Adaptive`](super::Adaptive))
        let (ord, beta, fac_min, fac_max, safe) = match self.cfg.method {
            Pair::Dopri5 => (5.0, 0.04, 0.2, 10.0, 0.9),
            Pair::Dop853 => (8.0, 0.0, 0.333, 6.0, 0.8),
            Pair::Vern9 => (9.0, 0.0, 0.333, 6.0, 0.8),
        };
        let expo1 = 1.0 / ord - beta * 0.75;
        let (t, t1) = (self.p.t, self.p.t_end);
        let mut h = self.p.h;
        loop {
            if self.p.work.accepted + self.p.work.rejected >= self.cfg.max_steps {
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
            // k₁ = f(t, y). In place: into the last step's first stage, the other stages'
            // slots kept for the step to write into (a heap state keeps its buffers).
            match self.k.first_mut() {
                Some(k1) if F::IN_PLACE => k1.clone_from(&self.f_now),
                _ => {
                    self.k.clear();
                    self.k.push(self.f_now.clone());
                }
            }
            let (y1, err) = match self.cfg.method {
                Pair::Dopri5 => {
                    dopri5::step(&mut self.f, t, &self.p.y, h, &mut self.k, tol, &mut self.p.work)?
                }
                Pair::Dop853 => {
                    dop853::step(&mut self.f, t, &self.p.y, h, &mut self.k, tol, &mut self.p.work)?
                }
                Pair::Vern9 => vern9::step(&mut self.f, t, &self.p.y, h, &mut self.k, tol, &mut self.p.work)?,
            };
            // step-size factor: fac = err^{expo1} / fac_old^β / safe, clamped. DOP853 (β = 0,
            // expo1 = 1/8): err^{1/8} as three square roots (correctly rounded; an exp of a log
            // cost about 6 % of a step on a cheap right-hand side). Vern9 (β = 0, expo1 = 1/9):
            // `root::ninth_root`, to 1.3e-5 (two `cbrt` cost about 300 instructions a step, 15 %
            // of Kepler's time). DOPRI5: one exp of logarithms, ln(fac_old) kept from the last
            // accepted step.
            let method = self.cfg.method;
            let err_pow = |err: f64| match method {
                Pair::Dop853 => err.sqrt().sqrt().sqrt(),
                Pair::Vern9 => super::root::ninth_root(err),
                Pair::Dopri5 => (expo1 * err.ln()).exp(),
            };
            if err <= 1.0 {
                let fac = if method != Pair::Dopri5 {
                    err_pow(err) / safe
                } else {
                    let ln_err = err.ln();
                    let fac = (expo1 * ln_err - beta * self.ln_fac_old).exp() / safe;
                    self.ln_fac_old = ln_err.max(1e-4f64.ln());
                    fac
                }
                .clamp(1.0 / fac_max, 1.0 / fac_min);
                let mut h_new = (h / fac).min(self.p.h_max);
                if self.last_rejected {
                    h_new = h_new.min(h);
                }
                self.last_rejected = false;
                let t_new = if last { t1 } else { t + h };
                // f(t + h, y₁): FSAL stage of DOPRI5, the next k₁ (and k₁₃) for DOP853
                match self.cfg.method {
                    Pair::Dopri5 => self.f_now.clone_from(&self.k[6]),
                    Pair::Dop853 | Pair::Vern9 if !F::IN_PLACE => {
                        let stage = if method == Pair::Vern9 { 17 } else { 13 };
                        self.f_now = eval(&mut self.f, t_new, &y1, t, stage, &mut self.p.work.fevals)?;
                    }
                    Pair::Dop853 | Pair::Vern9 => {
                        let at = (t, if method == Pair::Vern9 { 17 } else { 13 });
                        if let Err(e) =
                            eval_into(&mut self.f, t_new, &y1, &mut self.f_now, at, &mut self.p.work.fevals)
                        {
                            // f at the current point again (k₁ of the refused step is a copy)
                            self.f_now.clone_from(&self.k[0]);
                            return Err(e);
                        }
                    }
                }
                self.p.advance(t_new, y1);
                // a step cut short to land on t1 keeps the controller's proposal
                self.p.h = if last { h_new.max(self.p.h) } else { h_new };
                return Ok(());
            }
            h /= (err_pow(err) / safe).min(1.0 / fac_min);
            self.p.work.rejected += 1;
            self.last_rejected = true;
        }
    }

    /// The interpolant of the last accepted step, valid on [`step_start`](Progress::step_start) ..
    /// [`t`](Progress::t) (order 4 for DOPRI5, 7 for DOP853; DOP853 spends three evaluations
    /// the first time it is asked for a step).
    ///
    /// # Errors
    /// [`OdeError::NoDenseOutput`] before the first step or right after a restart;
    /// [`OdeError::RhsNotFinite`] from DOP853's extra stages; [`OdeError::NoInterpolant`]
    /// for Vern9, which keeps none (land on the times you need with `set_end`).
    pub fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        if self.p.dense.is_none() {
            let Some((t0, y0)) = &self.p.prev else { return Err(OdeError::NoDenseOutput) };
            let h = self.p.t - t0;
            let d = match self.cfg.method {
                Pair::Dopri5 => dopri5::dense(*t0, y0, &self.p.y, h, &self.k),
                Pair::Vern9 => return Err(OdeError::NoInterpolant { method: "vern9" }),
                Pair::Dop853 => dop853::dense(
                    &mut self.f,
                    *t0,
                    y0,
                    &self.p.y,
                    h,
                    &mut self.k,
                    &self.f_now,
                    &mut self.p.work,
                )?,
            };
            self.p.dense = Some(d);
        }
        self.p.dense.as_ref().ok_or(OdeError::NoDenseOutput)
    }

    /// Continues from (t, y) after a jump of the state or of the right-hand side (an impact,
    /// a projection onto a constraint manifold, a switching load): f is evaluated afresh and
    /// the step size proposal is kept (bounded by the new remaining interval).
    ///
    /// # Errors
    /// [`OdeError::NonFiniteState`], [`OdeError::InvalidInterval`] if t is past the end,
    /// [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`].
    pub fn restart(&mut self, t: f64, y: S) -> Result<(), OdeError> {
        self.p.check_restart(t, &y)?;
        self.f_now = eval(&mut self.f, t, &y, t, 1, &mut self.p.work.fevals)?;
        self.p.t = t;
        self.p.y = y;
        self.last_rejected = false;
        Ok(())
    }
}
