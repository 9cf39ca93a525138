//! Adaptive explicit Runge–Kutta: DOPRI5 and DOP853 with error control, dense output and
//! events.

use std::time::Instant;

use super::dense::DenseStep;
use super::events::{Event, EventHit, crosses, locate};
use super::stepper::Stepper;
use crate::progress::Progress;
use crate::solver::Solver;
use crate::state::{State, eval};
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

/// An adaptive explicit solver: the pair with its tolerances and limits ([`Solver`]). Built
/// with [`Adaptive::dopri5`] or [`Adaptive::dop853`] and the setters; defaults rtol = 1e-6,
/// atol = 1e-9.
///
/// The local error is kept at ‖err/sk‖ ≤ 1 with sk = atol + rtol·max(|y|, |y₁|) per component
/// (HNW (4.10)); the step size follows Hairer's controller (PI with β = 0.04 for DOPRI5,
/// I-controller for DOP853).
///
/// Book: §4.11; HNW §II.4.
pub type Adaptive = Solver<Pair>;

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

impl Solver<Pair> {
    /// Dormand–Prince 5(4).
    pub const fn dopri5() -> Self {
        Self::with_method(Pair::Dopri5)
    }
    /// DOP853.
    pub const fn dop853() -> Self {
        Self::with_method(Pair::Dop853)
    }

    /// Solves y′ = f(t, y), y(t0) = y0 on [t0, t1].
    ///
    /// # Errors
    /// Bad input: [`OdeError::InvalidInterval`], [`OdeError::NonPositiveTolerance`],
    /// [`OdeError::NonPositiveStep`], [`OdeError::NonFiniteState`]; during the run:
    /// [`OdeError::RhsNotFinite`], [`OdeError::StepSizeUnderflow`], [`OdeError::TooManySteps`]
    /// (also up front when (t1 − t0)/h_max exceeds `max_steps`), [`OdeError::DimensionMismatch`]
    /// when f returns a state of another length than y.
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
        let start = Instant::now();
        let st = Stepper::new(self, f, t0, y0.clone(), t1)?;
        drive(st, start, y0, events, self.dense)
    }
}

/// A stepper [`drive`] can run: one accepted step at a time and that step's interpolant.
pub(crate) trait Steps<S: State>: core::ops::Deref<Target = Progress<S>> {
    /// One accepted step.
    fn step(&mut self) -> Result<(), OdeError>;
    /// The interpolant of the last accepted step.
    fn dense(&mut self) -> Result<&DenseStep<S>, OdeError>;
}

/// Runs a stepper to its end (or a terminal event): records the accepted steps, locates the
/// events on each step's interpolant and keeps the interpolants when `keep_dense`.
pub(crate) fn drive<S: State, St: Steps<S>>(
    mut st: St,
    start: Instant,
    y0: &S,
    events: &mut [Event<'_, S>],
    keep_dense: bool,
) -> Result<Solution<S>, OdeError> {
    let t0 = st.t();
    // room for a typical run's accepted steps up front (no early reallocations)
    let (mut ts, mut ys) = (Vec::with_capacity(256), Vec::with_capacity(256));
    ts.push(t0);
    ys.push(y0.clone());
    let mut sol = Solution {
        t: ts,
        y: ys,
        events: Vec::new(),
        terminated: false,
        work: Work::default(),
        dense: Vec::new(),
    };
    let mut g_prev: Vec<f64> = events.iter_mut().map(|e| (e.g)(t0, y0)).collect();
    let want_dense = keep_dense || !events.is_empty();
    while !st.done() {
        st.step()?;
        let (t, t_new) = (st.step_start().unwrap_or(t0), st.t());
        let dense = if want_dense { Some(st.dense()?.clone()) } else { None };
        // events: sign changes of g over [t, t_new], located on the dense output
        if let Some(d) = &dense
            && !events.is_empty()
            && let Some(t_stop) = find_events(events, &mut g_prev, d, t, t_new, st.y(), &mut sol)
        {
            sol.t.push(t_stop);
            sol.y.push(d.eval(t_stop));
            sol.terminated = true;
            if keep_dense {
                sol.dense.push(d.clone());
            }
            break;
        }
        if keep_dense && let Some(d) = dense {
            sol.dense.push(d);
        }
        sol.t.push(t_new);
        sol.y.push(st.y().clone());
    }
    sol.work = st.work();
    sol.work.wall = start.elapsed();
    Ok(sol)
}

/// Records the events of one accepted step [t, t_new] (zeros of g located on its dense
/// output `d`); returns the time of the first terminal one.
#[allow(clippy::too_many_arguments)]
pub(crate) fn find_events<S: State>(
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

/// √(Σ xᵢ²/n), the plain sum of squares when it is finite (the same bits as always), else
/// scaled by the largest |xᵢ| so that rates beyond 1e154 of their tolerance do not square to ∞
/// (which made the starting step 0).
fn rms(n: usize, x: impl Fn(usize) -> f64) -> f64 {
    let plain = (0..n).fold(0.0, |s, i| s + x(i).powi(2));
    if plain.is_finite() {
        return (plain / n as f64).sqrt();
    }
    let m =
        (0..n).fold(0.0_f64, |m, i| if x(i).is_nan() || m.is_nan() { f64::NAN } else { m.max(x(i).abs()) });
    if !(m.is_finite() && m > 0.0) {
        return m;
    }
    m * ((0..n).fold(0.0, |s, i| s + (x(i) / m).powi(2)) / n as f64).sqrt()
}

/// Hairer's starting step `hinit`: h with ‖h f₀‖ ≈ 0.01‖y₀‖, refined by an estimate of
/// the second derivative so that the first local error is near the tolerance.
#[allow(clippy::too_many_arguments)]
pub(crate) fn initial_step<S: State, F: FnMut(f64, &S) -> S>(
    f: &mut F,
    t: f64,
    y: &S,
    f0: &S,
    order: f64,
    h_max: f64,
    (rtol, atol): (f64, f64),
    work: &mut Work,
) -> Result<f64, OdeError> {
    let sk = |i: usize| atol + rtol * y.as_slice()[i].abs();
    let (dnf, dny) = (rms(y.dim(), |i| f0.as_slice()[i] / sk(i)), rms(y.dim(), |i| y.as_slice()[i] / sk(i)));
    let mut h = if dnf <= 1e-5 || dny <= 1e-5 { 1e-6 } else { 0.01 * dny / dnf };
    h = h.min(h_max);
    // explicit Euler step y + h f₀ and the derivative there
    let mut y1 = y.clone();
    for (a, b) in y1.as_mut_slice().iter_mut().zip(f0.as_slice()) {
        *a += h * b;
    }
    let f1 = eval(f, t + h, &y1, t, 1, &mut work.fevals)?;
    let der2 = rms(y.dim(), |i| (f1.as_slice()[i] - f0.as_slice()[i]) / sk(i)) / h;
    let der12 = der2.abs().max(dnf);
    let h1 = if der12 <= 1e-15 { (h * 1e-3).max(1e-6) } else { (0.01 / der12).powf(1.0 / order) };
    Ok((100.0 * h).min(h1).min(h_max))
}
