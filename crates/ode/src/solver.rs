//! The settings every adaptive method shares — tolerances, step bounds, a step cap, dense
//! output — written once, with the method-specific part as a type parameter:
//! [`Adaptive`](crate::Adaptive) = `Solver<Pair>`, [`Radau5`](crate::Radau5) =
//! `Solver<RadauIIA>`, [`Bdf`](crate::Bdf) = `Solver<BdfFormula>`.

/// An adaptive solver: the method `M` with the tolerances and limits of a run. The local
/// error is kept at ‖err/sk‖ ≤ 1 with sk = atol + rtol·|y| per component (each method says
/// which |y| and how its estimate is scaled); defaults rtol = 1e-6, atol = 1e-9, at most 10⁶
/// steps (accepted + rejected).
///
/// Book: §4.11; HNW §II.4 (step-size control), HW §IV.8.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solver<M> {
    /// The method and its own settings.
    pub method: M,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
    /// Initial step (each method's own starting rule when `None`).
    pub h0: Option<f64>,
    /// Largest step (the whole interval when `None`).
    pub h_max: Option<f64>,
    /// Maximum number of steps (accepted + rejected).
    pub max_steps: usize,
    /// Record dense output for [`Solution::sample`](crate::Solution::sample).
    pub dense: bool,
}

impl<M> Solver<M> {
    /// `method` with the defaults: rtol = 1e-6, atol = 1e-9, 10⁶ steps, no dense output.
    pub const fn with_method(method: M) -> Self {
        Self { method, rtol: 1e-6, atol: 1e-9, h0: None, h_max: None, max_steps: 1_000_000, dense: false }
    }
    /// Relative tolerance.
    pub fn rtol(mut self, rtol: f64) -> Self {
        self.rtol = rtol;
        self
    }
    /// Absolute tolerance.
    pub fn atol(mut self, atol: f64) -> Self {
        self.atol = atol;
        self
    }
    /// Initial step size.
    pub fn h0(mut self, h0: f64) -> Self {
        self.h0 = Some(h0);
        self
    }
    /// Maximum step size.
    pub fn h_max(mut self, h_max: f64) -> Self {
        self.h_max = Some(h_max);
        self
    }
    /// Maximum number of steps.
    pub fn max_steps(mut self, n: usize) -> Self {
        self.max_steps = n;
        self
    }
    /// Record dense output.
    pub fn dense(mut self, dense: bool) -> Self {
        self.dense = dense;
        self
    }

    /// The checks every stepper makes before its first evaluation: a forward finite interval,
    /// positive finite tolerances and steps, and a step cap that can cover the interval.
    /// Returns the step bound h_max.
    ///
    /// # Errors
    /// [`OdeError::InvalidInterval`](crate::OdeError::InvalidInterval),
    /// [`OdeError::NonPositiveTolerance`](crate::OdeError::NonPositiveTolerance),
    /// [`OdeError::NonPositiveStep`](crate::OdeError::NonPositiveStep),
    /// [`OdeError::TooManySteps`](crate::OdeError::TooManySteps).
    pub(crate) fn check(&self, t0: f64, t_end: f64) -> Result<f64, crate::OdeError> {
        use crate::error::{check_interval, check_step, check_tol};
        check_interval(t0, t_end)?;
        check_tol("rtol", self.rtol)?;
        check_tol("atol", self.atol)?;
        let h_max = self.h_max.unwrap_or(t_end - t0);
        check_step(h_max)?;
        // A step cap that cannot cover [t0, t_end] within max_steps fails now, not after
        // max_steps evaluations (h_max = 1e-300 would otherwise spin through them).
        if (t_end - t0) / h_max > self.max_steps as f64 {
            return Err(crate::OdeError::TooManySteps { t: t0, max_steps: self.max_steps });
        }
        if let Some(h0) = self.h0 {
            check_step(h0)?;
        }
        Ok(h_max)
    }
}
