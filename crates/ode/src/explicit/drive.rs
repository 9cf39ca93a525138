//! Running a stepper to its end: the accepted steps, the events located on each step's
//! interpolant, and the dense output, collected into a [`Solution`]. Shared by the explicit
//! and the stiff integrators.
//!
//! Book: §4.11; HNW §II.6 (dense output).

use std::time::Instant;

use super::dense::DenseStep;
use super::events::{Event, EventHit, crosses, locate};
use crate::progress::Progress;
use crate::state::State;
use crate::{OdeError, Work};

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
fn find_events<S: State>(
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
