//! One accepted BDF step, its interpolating polynomial and restarts (a child module of
//! `bdf_stepper`: it reads the stepper's private state).
//!
//! Book: §4.11; HW §III.5, §V.5; Shampine & Reichelt 1997 (scipy `BDF._step_impl`).

use super::{BdfStepper, Failure, MAX_FACTOR, MAX_ORDER, MIN_FACTOR, Scratch, error_const, gamma};
use crate::Rhs;

/// Consecutive failed Newton solves (or singular matrices) in one step before giving up.
const MAX_FAILURES: usize = 10;
use super::super::radau_core::rms_scaled;
use crate::OdeError;
use crate::explicit::{DenseStep, Form};
use crate::state::{State, eval};

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> BdfStepper<S, F, J> {
    /// Takes one accepted step (rejected attempts are retried inside, smaller); the last step
    /// lands exactly on the end time. Does nothing when done.
    ///
    /// # Errors
    /// [`OdeError::TooManySteps`] (accepted + rejected, Newton failures included),
    /// [`OdeError::StepSizeUnderflow`] (error test failing down to the round-off floor
    /// 10 ulp(t)), [`OdeError::NewtonStalled`] (Newton failing with a fresh Jacobian down to
    /// that floor), [`OdeError::SingularIterationMatrix`], [`OdeError::JacobianNotFinite`],
    /// [`OdeError::RhsNotFinite`] (when that is why Newton failed at the floor); each names t
    /// and the state.
    pub fn step(&mut self) -> Result<(), OdeError> {
        if self.p.done() {
            return Ok(());
        }
        // the step's buffers are lent out for its duration and returned on every exit
        let mut ws = core::mem::take(&mut self.ws);
        let result = self.step_with(&mut ws);
        self.ws = ws;
        result
    }

    /// The body of [`BdfStepper::step`], with the buffers `ws` (allocated once per run).
    fn step_with(&mut self, ws: &mut Scratch) -> Result<(), OdeError> {
        let t = self.p.t;
        // the floor: 10 units in the last place of t (scipy's `min_step`)
        let min_step = 10.0 * (t.abs() * f64::EPSILON).max(f64::MIN_POSITIVE);
        let mut h = self.p.h;
        if h > self.p.h_max {
            self.rescale(self.p.h_max / h);
            h = self.p.h_max;
            self.lu_c = None;
        }
        let mut failures: Option<(Failure, Option<OdeError>, usize)> = None;
        loop {
            if self.p.work.accepted + self.p.work.rejected >= self.cfg.max_steps {
                return Err(OdeError::TooManySteps { t, max_steps: self.cfg.max_steps });
            }
            if h < min_step || !h.is_finite() {
                return Err(self.give_up(t, h, failures));
            }
            // the last step lands on t_end (differences rescaled to the shorter step)
            let mut t_new = t + h;
            if t_new >= self.p.t_end {
                t_new = self.p.t_end;
                self.rescale((t_new - t) / h);
                self.lu_c = None;
            }
            h = t_new - t;
            let k = self.order;
            let n = self.d[0].len();
            // predictor y⁽⁰⁾ = Σⱼ₌₀ᵏ Dⱼ, ψ = Σⱼ₌₁ᵏ γⱼDⱼ/γₖ, c = h/γₖ
            let gk = gamma(k);
            for i in 0..n {
                ws.y_pred[i] = (0..=k).map(|j| self.d[j][i]).sum();
                ws.scale[i] = self.cfg.atol + self.cfg.rtol * ws.y_pred[i].abs();
                ws.psi[i] = (1..=k).map(|j| gamma(j) * self.d[j][i]).sum::<f64>() / gk;
            }
            let c = h / gk;
            let mut fresh_jac = false;
            let outcome = loop {
                if !self.factorize(c) {
                    break Err(Failure::Singular);
                }
                let nw = self.newton(t_new, c, ws);
                if nw.converged {
                    break Ok(nw);
                }
                if fresh_jac {
                    let cnt = failures.as_ref().map_or(0, |f| f.2) + 1;
                    failures = Some((Failure::Newton, nw.error, cnt));
                    break Err(Failure::Newton);
                }
                // Newton failed with an old J: refresh it at the predictor and retry once
                self.refresh_jacobian(t_new, &ws.y_pred)?;
                fresh_jac = true;
            };
            let nw = match outcome {
                Ok(nw) => nw,
                Err(kind) => {
                    if matches!(kind, Failure::Singular) {
                        let cnt = failures.as_ref().map_or(0, |f| f.2) + 1;
                        failures = Some((Failure::Singular, None, cnt));
                    }
                    // ten consecutive failures end the step (as RADAU5), whatever h is
                    if failures.as_ref().is_some_and(|f| f.2 >= MAX_FAILURES) {
                        return Err(self.give_up(t, h, failures));
                    }
                    h *= 0.5;
                    self.rescale(0.5);
                    self.lu_c = None;
                    self.p.work.rejected += 1;
                    continue;
                }
            };
            let cap = self.cfg.method.max_newton as f64;
            let safety = 0.9 * (2.0 * cap + 1.0) / (2.0 * cap + nw.iterations as f64);
            // local error (1/(k+1))·∇ᵏ⁺¹yₙ₊₁ (HW (III.5.9), κ = 0), scaled at the new y
            for i in 0..n {
                ws.scale[i] = self.cfg.atol + self.cfg.rtol * ws.y[i].abs();
                ws.err[i] = error_const(k) * ws.d[i];
            }
            let err_norm = rms_scaled(&ws.err, &ws.scale);
            // a NaN norm fails the test too
            if err_norm.is_nan() || err_norm > 1.0 {
                let factor = if err_norm.is_finite() {
                    MIN_FACTOR.max(safety * err_norm.powf(-1.0 / (k as f64 + 1.0)))
                } else {
                    MIN_FACTOR
                };
                h *= factor;
                self.rescale(factor);
                self.p.work.rejected += 1;
                // Newton converged: its factors are kept (scipy), refactorized only when it fails
                continue;
            }
            self.accept(t_new, h, ws, err_norm, safety);
            return Ok(());
        }
    }

    /// The error that ends a step at (t, h): the last failure's kind (a singular matrix, Newton's
    /// own error or its stalling), else the step-size floor; each names t and the state.
    fn give_up(&self, t: f64, h: f64, failures: Option<(Failure, Option<OdeError>, usize)>) -> OdeError {
        let state = self.p.y.as_slice().to_vec();
        match failures {
            Some((Failure::Singular, _, _)) => OdeError::SingularIterationMatrix { t, h, state },
            Some((Failure::Newton, Some(e), _)) => e,
            Some((Failure::Newton, None, n)) => OdeError::NewtonStalled { t, h, failures: n, state },
            None => OdeError::StepSizeUnderflow { t, h },
        }
    }

    /// Moves to the accepted step's end, updates the differences, and every k + 1 equal steps
    /// picks the order k − 1, k or k + 1 that allows the largest next step (HW §V.5).
    /// `ws` holds the new y, d = ∇ᵏ⁺¹yₙ₊₁ and the error scale at the new y.
    fn accept(&mut self, t_new: f64, h: f64, ws: &Scratch, err_norm: f64, safety: f64) {
        let (d, scale) = (&ws.d[..], &ws.scale[..]);
        let mut y1 = self.p.y.clone();
        y1.as_mut_slice().copy_from_slice(&ws.y);
        self.p.advance(t_new, y1);
        self.p.h = h;
        self.n_equal_steps += 1;
        let k = self.order;
        let n = d.len();
        // ∇ʲ⁺¹yₙ₊₁ = ∇ʲyₙ₊₁ − ∇ʲyₙ, with d = ∇ᵏ⁺¹yₙ₊₁: D_{k+2} = d − D_{k+1}, D_{k+1} = d,
        // then Dᵢ += Dᵢ₊₁ downwards
        let (low, high) = self.d.split_at_mut(k + 2);
        for ((hi, lo), di) in high[0].iter_mut().zip(low[k + 1].iter_mut()).zip(d) {
            *hi = di - *lo;
            *lo = *di;
        }
        for j in (0..=k).rev() {
            for i in 0..n {
                self.d[j][i] += self.d[j + 1][i];
            }
        }
        if self.n_equal_steps < k + 1 {
            return;
        }
        // error estimates at orders k − 1 and k + 1, and the step each allows
        let norm_at = |j: usize, row: &[f64]| {
            let e: Vec<f64> = row.iter().map(|x| error_const(j) * x).collect();
            rms_scaled(&e, scale)
        };
        let max_order = self.cfg.method.max_order.min(MAX_ORDER);
        let err_m = if k > 1 { norm_at(k - 1, &self.d[k]) } else { f64::INFINITY };
        let err_p = if k < max_order { norm_at(k + 1, &self.d[k + 2]) } else { f64::INFINITY };
        let factor_of = |e: f64, q: usize| if e > 0.0 { e.powf(-1.0 / q as f64) } else { f64::INFINITY };
        let factors = [factor_of(err_m, k), factor_of(err_norm, k + 1), factor_of(err_p, k + 2)];
        // the largest factor wins (NaN never does); ties keep the lower order, as argmax
        let mut best = 1;
        for (i, f) in factors.iter().enumerate() {
            if *f > factors[best] || (i < best && *f == factors[best]) {
                best = i;
            }
        }
        self.order = k + best - 1;
        let factor = MAX_FACTOR.min(safety * factors[best]);
        let factor = if factor.is_finite() && factor > 0.0 { factor } else { 1.0 };
        self.p.h = h * factor;
        self.rescale(factor);
        self.lu_c = None;
    }

    /// The polynomial interpolating the last k + 1 accepted points (the differences of the
    /// step the controller proposes next), valid on [`Progress::step_start`] ..
    /// [`Progress::t`]: y(t) = D₀ + Σⱼ₌₁ᵏ Dⱼ Πₘ₌₀ʲ⁻¹ (t − (tₙ − m h))/((m + 1) h). No f
    /// evaluations.
    ///
    /// [`Progress::step_start`]: crate::Progress::step_start
    /// [`Progress::t`]: crate::Progress::t
    ///
    /// # Errors
    /// [`OdeError::NoDenseOutput`] before the first step or right after a restart.
    pub fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        if self.p.dense.is_none() {
            let Some((t0, _)) = &self.p.prev else { return Err(OdeError::NoDenseOutput) };
            let c = (0..=self.order)
                .map(|j| {
                    let mut s = self.p.y.clone();
                    s.as_mut_slice().copy_from_slice(&self.d[j]);
                    s
                })
                .collect();
            self.p.dense = Some(DenseStep { t: *t0, h: self.p.t - t0, c, form: Form::Bdf(self.p.h) });
        }
        self.p.dense.as_ref().ok_or(OdeError::NoDenseOutput)
    }

    /// Continues from (t, y) after a jump of the state or of the right-hand side: order 1,
    /// differences from y and h f(t, y), the Jacobian afresh, the step size proposal kept.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteState`], [`OdeError::InvalidInterval`] if t is past the end,
    /// [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`],
    /// [`OdeError::JacobianNotFinite`].
    pub fn restart(&mut self, t: f64, y: S) -> Result<(), OdeError> {
        self.p.check_restart(t, &y)?;
        let f0 = eval(&mut self.f, t, &y, t, 1, &mut self.p.work.fevals)?;
        let h = self.p.h.min(self.p.h_max);
        for row in self.d.iter_mut() {
            row.fill(0.0);
        }
        self.d[0].copy_from_slice(y.as_slice());
        for (di, fi) in self.d[1].iter_mut().zip(f0.as_slice()) {
            *di = h * fi;
        }
        self.p.t = t;
        self.p.y = y;
        self.p.h = h;
        self.order = 1;
        self.n_equal_steps = 0;
        let y_now = self.p.y.as_slice().to_vec();
        self.refresh_jacobian(t, &y_now)
    }
}
