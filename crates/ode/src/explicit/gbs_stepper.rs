//! Gragg–Bulirsch–Stoer extrapolation one accepted step at a time: the [`Stepper`] interface
//! (t, y, the work, `set_end`, `restart`) for [`Extrapolation`], so that a caller that drives
//! its own integration (a scene run) can use the method at tight tolerances. Like Hairer's
//! ODEX on the harmonic step sequence, it has no interpolant: a caller lands on the times it
//! needs with `set_end`, as Boost.Odeint's `integrate_times` does with its `bulirsch_stoer`.
//!
//! Book: §4.11; HNW §II.9.
//!
//! [`Stepper`]: super::Stepper

use super::dense::DenseStep;
use super::drive::Steps;
use super::extrapolation::{Extrapolation, Run};
use crate::progress::Progress;
use crate::state::{State, eval_into};
use crate::{InPlace, OdeError, Rhs};

/// An extrapolation run in progress: [`GbsStepper::step`] takes one accepted step (the last
/// one lands exactly on the end, which [`set_end`](Progress::set_end) moves),
/// [`GbsStepper::restart`] continues from a new state. The steps and bits are those of
/// [`Extrapolation::solve`] over the same interval.
///
/// ```
/// use vectrix_ode::{Extrapolation, explicit::GbsStepper};
/// // y′ = −y on [0, 1], landing on t = 0.5 on the way
/// let cfg = Extrapolation::gbs().rtol(1e-12).atol(1e-12);
/// let mut st = GbsStepper::new(&cfg, |_t: f64, y: &f64| -y, 0.0, 1.0, 0.5)?;
/// while !st.done() {
///     st.step()?;
/// }
/// assert!((st.y() - (-0.5f64).exp()).abs() < 1e-12);
/// st.set_end(1.0)?;
/// while !st.done() {
///     st.step()?;
/// }
/// assert!((st.y() - (-1f64).exp()).abs() < 1e-12);
/// # Ok::<(), vectrix_ode::OdeError>(())
/// ```
///
/// Book: §4.11; HNW §II.9.
pub struct GbsStepper<S: State, F: Rhs<S>> {
    f: F,
    /// t, y, the last step, h, the end time and the work (the accessors, by `Deref`).
    p: Progress<S>,
    run: Run<S>,
    /// f(t, y) at the current point (the next step's first evaluation), when `fresh`.
    f_now: S,
    fresh: bool,
}

impl<S: State, F: Rhs<S>> core::ops::Deref for GbsStepper<S, F> {
    type Target = Progress<S>;
    fn deref(&self) -> &Progress<S> {
        &self.p
    }
}

impl<S: State, F: Rhs<S>> core::ops::DerefMut for GbsStepper<S, F> {
    fn deref_mut(&mut self) -> &mut Progress<S> {
        &mut self.p
    }
}

impl<S: State, F: Rhs<S>> Steps<S> for GbsStepper<S, F> {
    fn step(&mut self) -> Result<(), OdeError> {
        GbsStepper::step(self)
    }
    fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        GbsStepper::dense(self)
    }
}

impl<S: State, F: Rhs<S>> core::fmt::Debug for GbsStepper<S, F> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("GbsStepper")
            .field("t", &self.p.t)
            .field("h", &self.p.h)
            .field("work", &self.p.work)
            .finish()
    }
}

impl<S: State, F: FnMut(f64, &S) -> S> GbsStepper<S, F> {
    /// Starts integrating y′ = f(t, y), y(t0) = y0 toward `t_end` with the settings of `cfg`
    /// (its `dense` flag is ignored: there is no interpolant).
    ///
    /// # Errors
    /// As [`Extrapolation::solve`]'s bad input, and [`OdeError::RhsNotFinite`] or
    /// [`OdeError::DimensionMismatch`] from the first evaluations.
    pub fn new(cfg: &Extrapolation, f: F, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        Self::start(cfg, f, t0, y0, t_end)
    }
}

impl<S: State, G: FnMut(f64, &S, &mut S)> GbsStepper<S, InPlace<G>> {
    /// [`GbsStepper::new`] with f written in place, `g(t, y, out)` ([`InPlace`]): the same
    /// steps and bits.
    ///
    /// # Errors
    /// As [`GbsStepper::new`].
    pub fn new_in_place(cfg: &Extrapolation, g: G, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        Self::start(cfg, InPlace(g), t0, y0, t_end)
    }
}

impl<S: State, F: Rhs<S>> GbsStepper<S, F> {
    /// [`GbsStepper::new`] for any [`Rhs`].
    pub(crate) fn start(cfg: &Extrapolation, mut f: F, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        let h_max = cfg.check_gbs(t0, t_end)?;
        let (run, f_now) = Run::start(cfg, &mut f, t0, &y0, h_max)?;
        let mut p = Progress::new(t0, y0, t_end, h_max, cfg.h_max, run.work);
        p.h = run.proposed();
        Ok(Self { f, p, run, f_now, fresh: true })
    }

    /// Takes one accepted step (rejected attempts and rows are retried inside); the last step
    /// lands exactly on the end time. Does nothing when [`done`](Progress::done).
    ///
    /// # Errors
    /// [`OdeError::TooManySteps`] (accepted + rejected reached `max_steps`),
    /// [`OdeError::StepSizeUnderflow`], [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`].
    pub fn step(&mut self) -> Result<(), OdeError> {
        if self.done() {
            return Ok(());
        }
        let t = self.p.t;
        if !self.fresh {
            eval_into(&mut self.f, t, &self.p.y, &mut self.f_now, (t, 1), &mut self.run.work.fevals)?;
            self.fresh = true;
        }
        // the end or the caller's bound caps the steps (`set_end` moves both)
        self.run.set_h_max(self.p.h_max);
        let (t_new, y1) = self.run.step(&mut self.f, t, &self.p.y, &self.f_now, self.p.t_end)?;
        let y1 = y1.clone();
        self.p.advance(t_new, y1);
        self.p.work = self.run.work;
        self.p.h = self.run.proposed();
        self.fresh = false;
        Ok(())
    }

    /// Extrapolation on the harmonic sequence keeps no interpolant: always
    /// [`OdeError::NoInterpolant`] (land on the times you need with
    /// [`set_end`](Progress::set_end)).
    ///
    /// # Errors
    /// Always [`OdeError::NoInterpolant`].
    pub fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        Err(OdeError::NoInterpolant { method: "gbs" })
    }

    /// Continues from (t, y) after a jump of the state or of the right-hand side: f is
    /// evaluated afresh; the step size and order proposals are kept.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteState`], [`OdeError::InvalidInterval`] if t is past the end,
    /// [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`].
    pub fn restart(&mut self, t: f64, y: S) -> Result<(), OdeError> {
        self.p.check_restart(t, &y)?;
        eval_into(&mut self.f, t, &y, &mut self.f_now, (t, 1), &mut self.run.work.fevals)?;
        self.p.work = self.run.work;
        self.p.t = t;
        self.p.y = y;
        self.fresh = true;
        Ok(())
    }
}
