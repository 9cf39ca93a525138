//! The solve functions every stiff integrator offers (RADAU5, BDF), written once over the
//! [`Implicit`] methods: finite-difference or supplied Jacobian, with or without events.
//!
//! Book: §4.11; HW §IV.8 (RADAU5), §III.5 and Shampine & Reichelt 1997 (BDF).

use super::radau_core::NoJacobian;
use crate::OdeError;
use std::time::Instant;

use crate::AnyStepper;
use crate::explicit::{Event, Solution, drive};
use crate::solver::Solver;
use crate::state::State;

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::super::RadauIIA {}
    impl Sealed for super::super::BdfFormula {}
}

/// A stiff method of vectrix ([`RadauIIA`](crate::RadauIIA), [`BdfFormula`](crate::BdfFormula)):
/// the methods of [`Solver`] below are those of both [`Radau5`](crate::Radau5) and
/// [`Bdf`](crate::Bdf). Sealed: implemented in this crate only.
///
/// Book: §4.11; HW §IV.8, §III.5.
pub trait Implicit: Copy + sealed::Sealed {
    /// The method as a [`Method`](crate::Method) (what the solve functions run).
    #[doc(hidden)]
    fn method(cfg: &Solver<Self>) -> crate::Method;
}

/// The body of every solve function: the method's stepper driven to t1 by `drive`.
fn run<M: Implicit, S: State, F: FnMut(f64, &S) -> S, J: FnMut(f64, &S, &mut [f64])>(
    cfg: &Solver<M>,
    f: F,
    jac: Option<J>,
    (t0, y0, t1): (f64, &S, f64),
    events: &mut [Event<'_, S>],
) -> Result<Solution<S>, OdeError> {
    let start = Instant::now();
    let st = AnyStepper::new(&M::method(cfg), f, jac, t0, y0.clone(), t1)?;
    drive(st, start, y0, events, cfg.dense)
}

impl<M: Implicit> Solver<M> {
    /// Solves y′ = f(t, y), y(t0) = y0 on [t0, t1] with a finite-difference Jacobian (n
    /// f-evaluations each, reported in [`Work::fd_jacobian_fevals`](crate::Work::fd_jacobian_fevals)).
    ///
    /// # Errors
    /// As [`Solver::solve_with_jacobian_and_events`].
    pub fn solve<S: State, F: FnMut(f64, &S) -> S>(
        &self,
        f: F,
        t0: f64,
        y0: &S,
        t1: f64,
    ) -> Result<Solution<S>, OdeError> {
        run(self, f, None::<NoJacobian<S>>, (t0, y0, t1), &mut [])
    }

    /// Solves with the Jacobian `jac(t, y, out)` writing ∂f/∂y row-major (out[i·n + j] =
    /// ∂fᵢ/∂yⱼ).
    ///
    /// # Errors
    /// As [`Solver::solve_with_jacobian_and_events`].
    pub fn solve_with_jacobian<S: State, F: FnMut(f64, &S) -> S, J: FnMut(f64, &S, &mut [f64])>(
        &self,
        f: F,
        jac: J,
        t0: f64,
        y0: &S,
        t1: f64,
    ) -> Result<Solution<S>, OdeError> {
        run(self, f, Some(jac), (t0, y0, t1), &mut [])
    }

    /// [`Solver::solve`] with events located on the method's dense output.
    ///
    /// # Errors
    /// As [`Solver::solve_with_jacobian_and_events`].
    pub fn solve_with_events<S: State, F: FnMut(f64, &S) -> S>(
        &self,
        f: F,
        t0: f64,
        y0: &S,
        t1: f64,
        events: &mut [Event<'_, S>],
    ) -> Result<Solution<S>, OdeError> {
        run(self, f, None::<NoJacobian<S>>, (t0, y0, t1), events)
    }

    /// The general form: Jacobian supplied, events located on the dense output (RADAU5's
    /// collocation polynomial, BDF's interpolating polynomial) to |Δt| ≤ 4ε·max(1, |t|) plus
    /// the interpolant's error (of the order of the tolerance).
    ///
    /// # Errors
    /// Bad input: [`OdeError::InvalidInterval`], [`OdeError::NonPositiveTolerance`],
    /// [`OdeError::NonPositiveStep`], [`OdeError::NonFiniteState`],
    /// [`OdeError::InvalidSetting`]; during the run: [`OdeError::RhsNotFinite`],
    /// [`OdeError::JacobianNotFinite`], [`OdeError::SingularIterationMatrix`],
    /// [`OdeError::NewtonStalled`], [`OdeError::StepSizeUnderflow`],
    /// [`OdeError::TooManySteps`], [`OdeError::DimensionMismatch`]. Each of the stiff ones
    /// names t and the state.
    pub fn solve_with_jacobian_and_events<S: State, F: FnMut(f64, &S) -> S, J: FnMut(f64, &S, &mut [f64])>(
        &self,
        f: F,
        jac: J,
        t0: f64,
        y0: &S,
        t1: f64,
        events: &mut [Event<'_, S>],
    ) -> Result<Solution<S>, OdeError> {
        run(self, f, Some(jac), (t0, y0, t1), events)
    }
}
