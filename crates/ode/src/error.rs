//! The one error type of vectrix-ode.

use thiserror::Error;

/// Everything that can go wrong in an integration, with where it happened.
///
/// Book: §4.11 (integration of the kinematic equations); DESIGN §5 (typed errors).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum OdeError {
    /// The initial state has a NaN or infinite component.
    #[error("initial state component {index} is {value} at t = {t}; every component must be finite")]
    NonFiniteState {
        /// Time of the state.
        t: f64,
        /// Index of the offending component.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// The right-hand side returned a NaN or infinite component.
    #[error(
        "right-hand side returned {value} in component {index} at t = {t} (stage {stage} of the step from t = {step_start}); it must be finite"
    )]
    RhsNotFinite {
        /// Time at which f was evaluated.
        t: f64,
        /// Start of the step being taken.
        step_start: f64,
        /// Stage of the method (1-based).
        stage: usize,
        /// Index of the offending component.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A step size or step count that is not positive and finite.
    #[error("step size h = {h} is invalid; it must be finite and > 0")]
    NonPositiveStep {
        /// The offending step size.
        h: f64,
    },
    /// A tolerance that is not positive and finite.
    #[error("tolerance {name} = {value} is invalid; it must be finite and > 0")]
    NonPositiveTolerance {
        /// `"rtol"` or `"atol"`.
        name: &'static str,
        /// The offending value.
        value: f64,
    },
    /// The time interval is empty, reversed or not finite.
    #[error("time interval [{t0}, {t1}] is invalid; it needs finite t0 < t1")]
    InvalidInterval {
        /// Start.
        t0: f64,
        /// End.
        t1: f64,
    },
    /// The step size fell below what floating point can resolve.
    #[error("step size {h:e} at t = {t} is below the round-off limit; the problem may be stiff or singular")]
    StepSizeUnderflow {
        /// Time of the failure.
        t: f64,
        /// The last step size tried.
        h: f64,
    },
    /// The maximum number of steps was reached.
    #[error("maximum of {max_steps} steps reached at t = {t} before the end of the interval")]
    TooManySteps {
        /// Time reached.
        t: f64,
        /// The limit.
        max_steps: usize,
    },
    /// Newton's method for the implicit stages did not converge.
    #[error(
        "Newton iteration did not converge in {iterations} iterations in the step from t = {t} (h = {h}); reduce h"
    )]
    NewtonFailed {
        /// Start of the step.
        t: f64,
        /// Step size.
        h: f64,
        /// Iterations done.
        iterations: usize,
    },
    /// The Newton matrix I − h(A⊗J) is singular.
    #[error("Newton matrix is singular in the step from t = {t} (h = {h})")]
    SingularNewtonMatrix {
        /// Start of the step.
        t: f64,
        /// Step size.
        h: f64,
    },
    /// A dense-output query outside the integrated interval.
    #[error("time {t} is outside the integrated interval [{t0}, {t1}]")]
    OutOfRange {
        /// Requested time.
        t: f64,
        /// Start of the solution.
        t0: f64,
        /// End of the solution.
        t1: f64,
    },
    /// Dense output was not recorded for this solution.
    #[error("dense output was not recorded; enable it with `.dense(true)`")]
    NoDenseOutput,
    /// A method without an interpolant was asked for the state between its steps.
    #[error(
        "{method} keeps no interpolant between its steps; land on the times you need (set_end), or use dopri5, dop853, radau5 or bdf for dense output and events"
    )]
    NoInterpolant {
        /// The method's name.
        method: &'static str,
    },
    /// An [`Accuracy`](crate::Accuracy) stricter than the harness could reach.
    #[error(
        "requested accuracy {requested:e} is below the strictest measured target {best:e}; ask for ≥ {best:e} or choose a method yourself"
    )]
    UnreachableAccuracy {
        /// The requested tolerance.
        requested: f64,
        /// The strictest target in the table.
        best: f64,
    },
    /// Vectors of different lengths where equal lengths are needed.
    #[error("dimension mismatch: {what} has length {got}, expected {expected}")]
    DimensionMismatch {
        /// Which argument.
        what: &'static str,
        /// Its length.
        got: usize,
        /// The required length.
        expected: usize,
    },
    /// The iteration matrices of an implicit Runge–Kutta step (RADAU5's (γ/h)I − J and
    /// ((α + iβ)/h)I − J) are singular at this step size.
    #[error(
        "iteration matrix of the implicit step from t = {t} (h = {h:e}) is singular at the state {}; the Jacobian has an eigenvalue at γ/h: change the step size bounds or check the model",
        show_state(.state)
    )]
    SingularIterationMatrix {
        /// Start of the step.
        t: f64,
        /// Step size.
        h: f64,
        /// State at the start of the step.
        state: Vec<f64>,
    },
    /// Newton's method for the implicit stages kept failing (diverging, stalling or meeting
    /// a non-finite right-hand side) until the step reached the floor of round-off or
    /// ten consecutive failures.
    #[error(
        "Newton iteration of the implicit step from t = {t} did not converge even at h = {h:e} ({failures} consecutive failures) at the state {}; the right-hand side may be discontinuous or its Jacobian wrong",
        show_state(.state)
    )]
    NewtonStalled {
        /// Start of the step.
        t: f64,
        /// The last step size tried.
        h: f64,
        /// Consecutive failed Newton iterations.
        failures: usize,
        /// State at the start of the step.
        state: Vec<f64>,
    },
    /// A method setting outside its valid range (BDF's `max_order`, a Newton cap of 0).
    #[error("{name} = {value} is invalid; valid: {valid}")]
    InvalidSetting {
        /// The setting.
        name: &'static str,
        /// The offending value.
        value: usize,
        /// The valid range.
        valid: &'static str,
    },
    /// The Jacobian ∂f/∂y has a NaN or infinite entry.
    #[error(
        "Jacobian ∂f/∂y has {value} at row {row}, column {col} at t = {t}, state {}; every entry must be finite",
        show_state(.state)
    )]
    JacobianNotFinite {
        /// Time of the evaluation.
        t: f64,
        /// Row (component of f).
        row: usize,
        /// Column (component of y).
        col: usize,
        /// The offending value.
        value: f64,
        /// The state at which it was evaluated.
        state: Vec<f64>,
    },
}

/// The first components of a state, for messages (at most 8, then the count of the rest).
fn show_state(y: &[f64]) -> String {
    let head: Vec<String> = y.iter().take(8).map(|v| format!("{v}")).collect();
    if y.len() > 8 {
        format!("[{}, … {} more]", head.join(", "), y.len() - 8)
    } else {
        format!("[{}]", head.join(", "))
    }
}

/// Checks that `h` is positive and finite.
pub(crate) fn check_step(h: f64) -> Result<(), OdeError> {
    if h.is_finite() && h > 0.0 { Ok(()) } else { Err(OdeError::NonPositiveStep { h }) }
}

/// Checks a tolerance.
pub(crate) fn check_tol(name: &'static str, value: f64) -> Result<(), OdeError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(OdeError::NonPositiveTolerance { name, value })
    }
}

/// Checks `t0 < t1`, both finite.
pub(crate) fn check_interval(t0: f64, t1: f64) -> Result<(), OdeError> {
    if t0.is_finite() && t1.is_finite() && t0 < t1 {
        Ok(())
    } else {
        Err(OdeError::InvalidInterval { t0, t1 })
    }
}
