//! Adaptive explicit Runge–Kutta: DOPRI5 and DOP853 with error control, dense output and
//! events.

use std::time::Instant;

use super::dense::DenseStep;
use super::events::{Event, EventHit, crosses, locate};
use super::{dop853, dopri5};
use crate::error::{check_interval, check_step, check_tol};
use crate::state::{State, check_state, eval};
use crate::{OdeError, Work};

/// The embedded pair of an adaptive explicit method.
///
/// Book: §4.11; HNW §II.4–II.10.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Pair {
    /// Dormand–Prince 5(4), dense output of order 4, 6 evaluations per step (FSAL).
    Dopri5,
    /// Dormand–Prince 8(5,3), dense output of order 7, 12 evaluations per step (+3 for
    /// dense output).
    Dop853,
}

/// An adaptive solver: the pair, tolerances and limits. Built with [`Adaptive::dopri5`] or
/// [`Adaptive::dop853`] and the setters; defaults rtol = 1e-6, atol = 1e-9.
///
/// The local error is kept at ‖err/sk‖ ≤ 1 with sk = atol + rtol·max(|y|, |y₁|) per component
/// (HNW (4.10)); the step size follows Hairer's controller (PI with β = 0.04 for DOPRI5,
/// I-controller for DOP853).
///
/// Book: §4.11; HNW §II.4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Adaptive {
    /// The embedded pair.
    pub pair: Pair,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
    /// Initial step (chosen by Hairer's `hinit` when `None`).
    pub h0: Option<f64>,
    /// Largest step (the whole interval when `None`).
    pub h_max: Option<f64>,
    /// Maximum number of steps.
    pub max_steps: usize,
    /// Record dense output for [`Solution::sample`].
    pub dense: bool,
}

/// The result of an adaptive run: the accepted steps, events, work and (optionally) dense
/// output.
///
/// Book: §4.11.
#[derive(Debug, Clone)]
pub struct Solution<S> {
    /// Times of the accepted step ends, starting with t₀.
    pub t: Vec<f64>,
    /// States at those times.
    pub y: Vec<S>,
    /// Located events, in time order.
    pub events: Vec<EventHit<S>>,
    /// `true` when a terminal event stopped the run (the last entry of `t` is that event).
    pub terminated: bool,
    /// What the run cost.
    pub work: Work,
    pub(crate) dense: Vec<DenseStep<S>>,
}

impl<S: State> Solution<S> {
    /// Final state.
    pub fn last(&self) -> &S {
        &self.y[self.y.len() - 1]
    }

    /// The dense output at time `t`.
    ///
    /// # Errors
    /// [`OdeError::NoDenseOutput`] unless built with `.dense(true)`; [`OdeError::OutOfRange`].
    pub fn sample(&self, t: f64) -> Result<S, OdeError> {
        if self.dense.is_empty() {
            return Err(OdeError::NoDenseOutput);
        }
        let (t0, t1) = (self.t[0], self.t[self.t.len() - 1]);
        if !(t >= t0 && t <= t1) {
            return Err(OdeError::OutOfRange { t, t0, t1 });
        }
        let i = self.dense.partition_point(|d| d.t + d.h < t).min(self.dense.len() - 1);
        Ok(self.dense[i].eval(t))
    }
}

impl Adaptive {
    fn with(pair: Pair) -> Self {
        Self { pair, rtol: 1e-6, atol: 1e-9, h0: None, h_max: None, max_steps: 1_000_000, dense: false }
    }
    /// Dormand–Prince 5(4).
    pub fn dopri5() -> Self {
        Self::with(Pair::Dopri5)
    }
    /// DOP853.
    pub fn dop853() -> Self {
        Self::with(Pair::Dop853)
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

    /// Solves y′ = f(t, y), y(t0) = y0 on [t0, t1].
    ///
    /// # Errors
    /// Bad input: [`OdeError::InvalidInterval`], [`OdeError::NonPositiveTolerance`],
    /// [`OdeError::NonPositiveStep`], [`OdeError::NonFiniteState`]; during the run:
    /// [`OdeError::RhsNotFinite`], [`OdeError::StepSizeUnderflow`], [`OdeError::TooManySteps`].
    pub fn solve<S: State, F: FnMut(f64, &S) -> S>(
        &self,
        f: F,
        t0: f64,
        y0: &S,
        t1: f64,
    ) -> Result<Solution<S>, OdeError> {
        self.solve_with_events(f, t0, y0, t1, &mut [])
    }

    /// [`Adaptive::solve`] with event location: each event's zeros are found on the dense
    /// output to |Δt| ≤ 4ε·max(1, |t|) (plus the interpolant's error, of the order of the
    /// tolerance).
    ///
    /// # Errors
    /// As [`Adaptive::solve`].
    pub fn solve_with_events<S: State, F: FnMut(f64, &S) -> S>(
        &self,
        f: F,
        t0: f64,
        y0: &S,
        t1: f64,
        events: &mut [Event<'_, S>],
    ) -> Result<Solution<S>, OdeError> {
        self.solve_with_hook(f, t0, y0, t1, events, |_, _| Ok(false))
    }

    /// [`Adaptive::solve_with_events`] with a hook called on the state at the end of every
    /// accepted step (and on the state of a terminal event), before it is recorded and before
    /// the next step starts from it. The hook may change the state in place: a projection
    /// onto an invariant manifold (constraint drift control, HNW §VII.2; HLW §IV.4) or a
    /// renormalization. It returns `Ok(true)` when it changed the state, so that the first
    /// stage of the next step is evaluated again at the new state (one extra f-eval: the
    /// first-same-as-last stage no longer applies), `Ok(false)` when it left it alone, and
    /// `Err(e)` to stop the run with the caller's error.
    ///
    /// The error control sees the step as taken; the dense output of a step interpolates
    /// from its (hooked) start to its unhooked end, so samples inside a step differ from the
    /// hooked states by at most the change the hook made at the step's end.
    ///
    /// # Errors
    /// As [`Adaptive::solve`] (converted with `E::from`), and the hook's own errors.
    pub fn solve_with_hook<S, F, E, H>(
        &self,
        mut f: F,
        t0: f64,
        y0: &S,
        t1: f64,
        events: &mut [Event<'_, S>],
        mut hook: H,
    ) -> Result<Solution<S>, E>
    where
        S: State,
        F: FnMut(f64, &S) -> S,
        E: From<OdeError>,
        H: FnMut(f64, &mut S) -> Result<bool, E>,
    {
        let start = Instant::now();
        check_interval(t0, t1)?;
        check_tol("rtol", self.rtol)?;
        check_tol("atol", self.atol)?;
        let h_max = self.h_max.unwrap_or(t1 - t0);
        check_step(h_max)?;
        if let Some(h0) = self.h0 {
            check_step(h0)?;
        }
        check_state(t0, y0)?;
        let tol = (self.rtol, self.atol);
        let (order, beta, fac_min, fac_max) = match self.pair {
            Pair::Dopri5 => (5.0, 0.04, 0.2, 10.0),
            Pair::Dop853 => (8.0, 0.0, 0.333, 6.0),
        };
        let expo1 = 1.0 / order - beta * 0.75;
        let safe = 0.9;

        let mut work = Work::default();
        // room for a typical run's accepted steps up front (no early reallocations)
        let (mut ts, mut ys) = (Vec::with_capacity(256), Vec::with_capacity(256));
        ts.push(t0);
        ys.push(y0.clone());
        let mut sol =
            Solution { t: ts, y: ys, events: Vec::new(), terminated: false, work, dense: Vec::new() };
        let mut t = t0;
        let mut y = y0.clone();
        let mut k: Vec<S> = Vec::with_capacity(16);
        k.push(eval(&mut f, t, &y, t, 1, &mut work.fevals)?);
        let mut h = match self.h0 {
            Some(h0) => h0.min(h_max),
            None => initial_step(&mut f, t, &y, &k[0], order, h_max, tol, &mut work)?,
        };
        let mut g_prev: Vec<f64> = events.iter_mut().map(|e| (e.g)(t, &y)).collect();
        let mut fac_old = 1e-4_f64;
        let mut last_rejected = false;
        let want_dense = self.dense || !events.is_empty();

        loop {
            if work.accepted + work.rejected >= self.max_steps {
                return Err(OdeError::TooManySteps { t, max_steps: self.max_steps }.into());
            }
            if 0.1 * h.abs() <= t.abs() * f64::EPSILON {
                return Err(OdeError::StepSizeUnderflow { t, h }.into());
            }
            // last step lands exactly on t1 (Hairer: if t + 1.01h ≥ t1, h = t1 − t)
            let last = t + 1.01 * h >= t1;
            if last {
                h = t1 - t;
            }
            let (y1, err) = match self.pair {
                Pair::Dopri5 => dopri5::step(&mut f, t, &y, h, &mut k, tol, &mut work)?,
                Pair::Dop853 => dop853::step(&mut f, t, &y, h, &mut k, tol, &mut work)?,
            };
            // step-size factor: fac = err^{expo1} / fac_old^β / safe, clamped
            let fac11 = err.powf(expo1);
            if err <= 1.0 {
                let stab = if beta == 0.0 { 1.0 } else { fac_old.powf(beta) };
                let fac = (fac11 / stab / safe).clamp(1.0 / fac_max, 1.0 / fac_min);
                let mut h_new = (h / fac).min(h_max);
                if last_rejected {
                    h_new = h_new.min(h);
                }
                fac_old = err.max(1e-4);
                work.accepted += 1;
                last_rejected = false;
                let t_new = if last { t1 } else { t + h };
                // f(t + h, y₁): FSAL stage of DOPRI5, the next k₁ (and k₁₃) for DOP853
                let f1 = match self.pair {
                    Pair::Dopri5 => k[6].clone(),
                    Pair::Dop853 => eval(&mut f, t_new, &y1, t, 13, &mut work.fevals)?,
                };
                let dense = if want_dense {
                    Some(match self.pair {
                        Pair::Dopri5 => dopri5::dense(t, &y, &y1, h, &k),
                        Pair::Dop853 => dop853::dense(&mut f, t, &y, &y1, h, &mut k, &f1, &mut work)?,
                    })
                } else {
                    None
                };
                // events: sign changes of g over [t, t_new], located on the dense output
                if let Some(d) = &dense
                    && !events.is_empty()
                    && let Some(t_stop) = self.find_events(events, &mut g_prev, d, t, t_new, &y1, &mut sol)
                {
                    let mut y_stop = d.eval(t_stop);
                    hook(t_stop, &mut y_stop)?;
                    sol.t.push(t_stop);
                    sol.y.push(y_stop);
                    sol.terminated = true;
                    if self.dense {
                        sol.dense.push(d.clone());
                    }
                    break;
                }
                if self.dense
                    && let Some(d) = dense
                {
                    sol.dense.push(d);
                }
                t = t_new;
                y = y1;
                k.clear();
                if hook(t, &mut y)? {
                    // the hook moved the state: f₁ of the next step is f at the new state
                    k.push(eval(&mut f, t, &y, t, 1, &mut work.fevals)?);
                    for (e, g) in events.iter_mut().zip(g_prev.iter_mut()) {
                        *g = (e.g)(t, &y);
                    }
                } else {
                    k.push(f1);
                }
                sol.t.push(t);
                sol.y.push(y.clone());
                if last {
                    break;
                }
                h = h_new;
            } else {
                h /= (fac11 / safe).min(1.0 / fac_min);
                work.rejected += 1;
                last_rejected = true;
            }
        }
        work.wall = start.elapsed();
        sol.work = work;
        Ok(sol)
    }

    /// Records the events of one accepted step; returns the time of the first terminal one.
    #[allow(clippy::too_many_arguments)]
    fn find_events<S: State>(
        &self,
        events: &mut [Event<'_, S>],
        g_prev: &mut [f64],
        d: &DenseStep<S>,
        t: f64,
        t_new: f64,
        y1: &S,
        sol: &mut Solution<S>,
    ) -> Option<f64> {
        let mut hits = Vec::new();
        for (i, e) in events.iter_mut().enumerate() {
            let g1 = (e.g)(t_new, y1);
            if let Some(rising) = crosses(e.direction, g_prev[i], g1) {
                let tz = locate(&mut *e.g, d, (t, g_prev[i]), (t_new, g1));
                hits.push((tz, i, rising, e.terminal));
            }
            g_prev[i] = g1;
        }
        hits.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut stop = None;
        for (tz, index, rising, terminal) in hits {
            sol.events.push(EventHit { index, t: tz, y: d.eval(tz), rising });
            if terminal {
                stop = Some(tz);
                break;
            }
        }
        stop
    }
}

/// Hairer's starting step `hinit`: h with ‖h f₀‖ ≈ 0.01‖y₀‖, refined by an estimate of
/// the second derivative so that the first local error is near the tolerance.
#[allow(clippy::too_many_arguments)]
fn initial_step<S: State, F: FnMut(f64, &S) -> S>(
    f: &mut F,
    t: f64,
    y: &S,
    f0: &S,
    order: f64,
    h_max: f64,
    (rtol, atol): (f64, f64),
    work: &mut Work,
) -> Result<f64, OdeError> {
    let n = y.dim() as f64;
    let sk = |i: usize| atol + rtol * y.as_slice()[i].abs();
    let (mut dnf, mut dny) = (0.0, 0.0);
    for i in 0..y.dim() {
        dnf += (f0.as_slice()[i] / sk(i)).powi(2);
        dny += (y.as_slice()[i] / sk(i)).powi(2);
    }
    let (dnf, dny) = ((dnf / n).sqrt(), (dny / n).sqrt());
    let mut h = if dnf <= 1e-5 || dny <= 1e-5 { 1e-6 } else { 0.01 * dny / dnf };
    h = h.min(h_max);
    // explicit Euler step y + h f₀ and the derivative there
    let mut y1 = y.clone();
    for (a, b) in y1.as_mut_slice().iter_mut().zip(f0.as_slice()) {
        *a += h * b;
    }
    let f1 = eval(f, t + h, &y1, t, 1, &mut work.fevals)?;
    let mut der2 = 0.0;
    for i in 0..y.dim() {
        der2 += ((f1.as_slice()[i] - f0.as_slice()[i]) / sk(i)).powi(2);
    }
    let der2 = (der2 / n).sqrt() / h;
    let der12 = der2.abs().max(dnf);
    let h1 = if der12 <= 1e-15 { (h * 1e-3).max(1e-6) } else { (0.01 / der12).powf(1.0 / order) };
    Ok((100.0 * h).min(h1).min(h_max))
}

#[cfg(test)]
mod tests {
    use nalgebra::Vector2;

    use super::Adaptive;
    use crate::OdeError;

    /// ẏ = (y₂, −y₁) keeps |y| = 1; the hook puts each accepted state back on the circle, so
    /// |y| − 1 stays at rounding level, and each change costs one extra f-eval.
    #[test]
    fn hook_projects_every_accepted_step() {
        let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], -y[0]);
        let mut calls = 0;
        let sol = Adaptive::dopri5()
            .rtol(1e-4)
            .atol(1e-4)
            .solve_with_hook(f, 0.0, &Vector2::new(1.0, 0.0), 200.0, &mut [], |_, y: &mut Vector2<f64>| {
                calls += 1;
                *y /= y.norm();
                Ok::<bool, OdeError>(true)
            })
            .unwrap();
        let accepted = sol.work.accepted;
        assert_eq!(calls, accepted);
        // DOPRI5 is FSAL: 6 f-evals per step, 1 initial, 1 from hinit, plus one per hooked step
        assert_eq!(sol.work.fevals, 2 + 6 * (accepted + sol.work.rejected) + accepted);
        for y in &sol.y {
            // one normalization leaves |y| within a few ulps of 1
            assert!((y.norm() - 1.0).abs() <= 4.0 * f64::EPSILON, "|y| = {}", y.norm());
        }
    }

    /// The hook's error stops the run and is returned as it is.
    #[test]
    fn hook_error_stops_the_run() {
        #[derive(Debug, PartialEq)]
        enum Stop {
            At(f64),
            Ode(OdeError),
        }
        impl From<OdeError> for Stop {
            fn from(e: OdeError) -> Self {
                Stop::Ode(e)
            }
        }
        let f = |_: f64, y: &f64| -*y;
        let r = Adaptive::dop853().solve_with_hook(f, 0.0, &1.0, 10.0, &mut [], |t, _: &mut f64| {
            if t > 1.0 { Err(Stop::At(t)) } else { Ok(false) }
        });
        assert!(matches!(r, Err(Stop::At(t)) if t > 1.0));
        // solver errors come through E::from
        let r: Result<_, Stop> =
            Adaptive::dop853().rtol(-1.0).solve_with_hook(f, 0.0, &1.0, 1.0, &mut [], |_, _| Ok(false));
        assert!(matches!(r, Err(Stop::Ode(OdeError::NonPositiveTolerance { .. }))));
    }
}
