//! Adaptive explicit Runge–Kutta: DOPRI5, DOP853 and Vern9 with error control (dense output
//! and events for the two with an interpolant), solved in one call by driving a [`Stepper`]
//! to the end.
//!
//! Book: §4.11; HNW §II.4–II.10.

use std::time::Instant;

use super::drive::{Solution, drive};
use super::events::Event;
use super::pair::Pair;
use super::stepper::Stepper;
use crate::OdeError;
use crate::solver::Solver;
use crate::state::State;

impl Solver<Pair> {
    /// Solves y′ = f(t, y), y(t0) = y0 on [t0, t1].
    ///
    /// # Errors
    /// Bad input: [`OdeError::InvalidInterval`], [`OdeError::NonPositiveTolerance`],
    /// [`OdeError::NonPositiveStep`], [`OdeError::NonFiniteState`]; during the run:
    /// [`OdeError::RhsNotFinite`], [`OdeError::StepSizeUnderflow`], [`OdeError::TooManySteps`]
    /// (also up front when (t1 − t0)/h_max exceeds `max_steps`), [`OdeError::DimensionMismatch`]
    /// when f returns a state of another length than y; [`OdeError::NoInterpolant`] up front
    /// for Vern9 with `.dense(true)`.
    pub fn solve<S: State, F: FnMut(f64, &S) -> S>(
        &self,
        f: F,
        t0: f64,
        y0: &S,
        t1: f64,
    ) -> Result<Solution<S>, OdeError> {
        self.solve_with_events(f, t0, y0, t1, &mut [])
    }

    /// [`Adaptive::solve`](super::Adaptive::solve) with event location: each event's zeros are found on the dense
    /// output to |Δt| ≤ 4ε·max(1, |t|) (plus the interpolant's error, of the order of the
    /// tolerance).
    ///
    /// # Errors
    /// As [`Adaptive::solve`](super::Adaptive::solve); [`OdeError::NoInterpolant`] up front
    /// for Vern9 with events.
    pub fn solve_with_events<S: State, F: FnMut(f64, &S) -> S>(
        &self,
        f: F,
        t0: f64,
        y0: &S,
        t1: f64,
        events: &mut [Event<'_, S>],
    ) -> Result<Solution<S>, OdeError> {
        let start = Instant::now();
        if self.method == Pair::Vern9 && (self.dense || !events.is_empty()) {
            return Err(OdeError::NoInterpolant { method: "vern9" });
        }
        let st = Stepper::new(self, f, t0, y0.clone(), t1)?;
        drive(st, start, y0, events, self.dense)
    }
}
