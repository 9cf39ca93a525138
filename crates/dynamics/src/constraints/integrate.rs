//! Integration of a constrained system with drift control: the index-1 equations
//! ([`super::solve_constrained`]) integrated by an adaptive Runge–Kutta pair, and every
//! accepted state projected back onto the constraint manifold (positions by Gauss–Newton in
//! the M-metric, then velocities by the M-orthogonal projection), with the violation
//! reported.
//!
//! Without projection the index-1 formulation keeps φ̈ = 0 only, so φ and φ̇ drift like the
//! integration error integrated once and twice (HNW §VII.2); the projection removes it at
//! every step, at the cost of one extra f-eval per step it changes (the integrator restarts
//! from the projected state, [`Stepper::restart`], keeping its step size).

use std::cell::RefCell;

use nalgebra::DVector;
use vectrix_ode::explicit::{DenseStep, Stepper};
use vectrix_ode::{Adaptive, OdeError, Work};

use super::eval::{counts, holonomic_rows, velocity_system};
use super::{
    ConstrainedSystem, Constraints, ProjectionOptions, project_positions, project_velocities,
    solve_constrained,
};
use crate::DynamicsError;
use crate::error::{check_finite, check_len};

/// The constraint violation of a state: |φ(q, t)|∞ and the largest velocity residual
/// |[Φ_q q̇ + Φ_t; A q̇ + b]|∞ (each in the units of its constraint).
///
/// Book: §9.11, §9.12.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Violation {
    /// |φ(q, t)|∞.
    pub position: f64,
    /// |[Φ_q q̇ + Φ_t; A q̇ + b]|∞.
    pub velocity: f64,
}

impl Violation {
    fn max(self, other: Self) -> Self {
        Self { position: self.position.max(other.position), velocity: self.velocity.max(other.velocity) }
    }
}

/// The [`Violation`] of (q, q̇) at t.
///
/// Book: §9.11, §9.12.
///
/// # Errors
/// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`],
/// [`DynamicsError::TooManyConstraints`].
pub fn constraint_violation<C: Constraints>(
    sys: &C,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<Violation, DynamicsError> {
    check_len(qd.len(), q.len(), "q̇")?;
    check_finite(q, "q")?;
    check_finite(qd, "q̇")?;
    check_finite(&[t], "t")?;
    let (m, k) = counts(sys, q.len())?;
    let (phi, _) = holonomic_rows(sys, q, t, m)?;
    let (_, r) = velocity_system(sys, q, qd, t, (m, k))?;
    Ok(Violation { position: phi.amax(), velocity: r.amax() })
}

/// An adaptive integrator for a [`ConstrainedSystem`] with projection after each accepted
/// step. Built with [`ConstrainedIntegrator::new`] and public fields.
///
/// Book: §9.11, §9.12.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConstrainedIntegrator {
    /// The Runge–Kutta pair and its tolerances (on y = (q, q̇)).
    pub solver: Adaptive,
    /// Tolerances of the projection; a state is projected when its position or velocity
    /// violation exceeds `projection.tol`.
    pub projection: ProjectionOptions,
    /// Project every accepted state (default `true`); `false` integrates the index-1
    /// equations as they are, to measure the drift.
    pub project_steps: bool,
    /// Project an initial state that violates the constraints by more than `initial_tol`
    /// (default `false`: such a state is an error).
    pub project_initial: bool,
    /// Largest initial violation accepted as consistent. Default 1e-10 (absolute).
    pub initial_tol: f64,
    /// Keep the dense output of every step for [`ConstrainedRun::sample`] (default `false`).
    pub dense: bool,
}

/// What [`ConstrainedIntegrator::integrate`] returns.
///
/// Book: §9.11.
#[derive(Debug, Clone)]
pub struct ConstrainedRun {
    /// Times of the accepted steps, starting with t₀.
    pub t: Vec<f64>,
    /// States y = (q, q̇) at those times, projected.
    pub y: Vec<DVector<f64>>,
    /// The interpolant of each step (when asked for), from its projected start to its end
    /// before projection.
    pub dense: Vec<DenseStep<DVector<f64>>>,
    /// The largest violation over the recorded states, after projection.
    pub max_constraint_violation: Violation,
    /// The largest violation found at a step's end before projection: the drift one step
    /// makes.
    pub max_drift: Violation,
    /// How many states were projected (initial state included).
    pub projections: usize,
    /// f-evaluations and steps.
    pub work: Work,
    n: usize,
}

impl ConstrainedRun {
    /// q at the i-th recorded time `t[i]`.
    pub fn q(&self, i: usize) -> &[f64] {
        &self.y[i].as_slice()[..self.n]
    }
    /// q̇ at the i-th recorded time.
    pub fn qd(&self, i: usize) -> &[f64] {
        &self.y[i].as_slice()[self.n..]
    }
    /// y = (q, q̇) at time t from the dense output. Inside a step the interpolant runs to the
    /// step's unprojected end, so it may differ from the constraint manifold by up to
    /// [`ConstrainedRun::max_drift`].
    ///
    /// # Errors
    /// [`OdeError::NoDenseOutput`] unless the integrator had `dense = true`;
    /// [`OdeError::OutOfRange`] outside the run.
    pub fn sample(&self, t: f64) -> Result<DVector<f64>, DynamicsError> {
        if self.dense.is_empty() {
            return Err(OdeError::NoDenseOutput.into());
        }
        let (t0, t1) = (self.t[0], self.t[self.t.len() - 1]);
        if !(t >= t0 && t <= t1) {
            return Err(OdeError::OutOfRange { t, t0, t1 }.into());
        }
        let i = self.dense.partition_point(|d| d.t + d.h < t).min(self.dense.len() - 1);
        Ok(self.dense[i].eval(t))
    }
}

impl ConstrainedIntegrator {
    /// The given solver with projection after every accepted step, the initial state
    /// checked (not projected) and the default [`ProjectionOptions`].
    pub fn new(solver: Adaptive) -> Self {
        Self {
            solver,
            projection: ProjectionOptions::default(),
            project_steps: true,
            project_initial: false,
            initial_tol: 1e-10,
            dense: false,
        }
    }

    /// Projects y = (q, q̇) at t: positions (Gauss–Newton, holonomic rows), then velocities
    /// (all rows).
    fn project<S: ConstrainedSystem>(
        &self,
        sys: &S,
        t: f64,
        y: &mut DVector<f64>,
    ) -> Result<(), DynamicsError> {
        let n = sys.dof();
        let (m, k) = counts(sys, n)?;
        let (q, qd) = (y.as_slice()[..n].to_vec(), y.as_slice()[n..].to_vec());
        let q = if m > 0 {
            let mass = sys.mass(&q, t)?;
            let retract =
                |q: &[f64], d: &DVector<f64>| Ok(q.iter().zip(d.iter()).map(|(a, b)| a + b).collect());
            project_positions(&q, &mass, |q| holonomic_rows(sys, q, t, m), retract, &self.projection)?.q
        } else {
            q
        };
        let mass = sys.mass(&q, t)?;
        let (g, r) = velocity_system(sys, &q, &qd, t, (m, k))?;
        let qd =
            project_velocities(&DVector::from_column_slice(&qd), &mass, &g, &r, self.projection.rank_tol)?;
        y.as_mut_slice()[..n].copy_from_slice(&q);
        y.as_mut_slice()[n..].copy_from_slice(qd.as_slice());
        Ok(())
    }

    /// Integrates the constrained equations of motion from (q₀, q̇₀) at t₀ to t₁.
    ///
    /// Book: §9.11, §9.12.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`],
    /// [`DynamicsError::OutOfRange`] (tolerances);
    /// [`DynamicsError::InconsistentInitialConditions`] when (q₀, q̇₀) violates the
    /// constraints by more than `initial_tol` and `project_initial` is off; the errors of
    /// [`solve_constrained`] (redundant or singular constraints, reached during the run) and
    /// of the projection ([`DynamicsError::ProjectionFailed`]); [`DynamicsError::Ode`] from
    /// the integrator.
    pub fn integrate<S: ConstrainedSystem>(
        &self,
        sys: &S,
        q0: &[f64],
        qd0: &[f64],
        t0: f64,
        t1: f64,
    ) -> Result<ConstrainedRun, DynamicsError> {
        let n = sys.dof();
        check_len(q0.len(), n, "q₀")?;
        check_len(qd0.len(), n, "q̇₀")?;
        self.projection.check()?;
        if !(self.initial_tol.is_finite() && self.initial_tol > 0.0) {
            return Err(DynamicsError::OutOfRange {
                what: "initial consistency tolerance",
                value: self.initial_tol,
                valid: "finite and > 0",
            });
        }
        let mut y0 = DVector::from_iterator(2 * n, q0.iter().chain(qd0).copied());
        let v0 = constraint_violation(sys, q0, qd0, t0)?;
        let mut projections = 0;
        if v0.position > self.initial_tol || v0.velocity > self.initial_tol {
            if !self.project_initial {
                return Err(DynamicsError::InconsistentInitialConditions {
                    position: v0.position,
                    velocity: v0.velocity,
                    tol: self.initial_tol,
                });
            }
            self.project(sys, t0, &mut y0)?;
            projections += 1;
        }
        let worst = constraint_violation(sys, &y0.as_slice()[..n], &y0.as_slice()[n..], t0)?;
        let mut run = ConstrainedRun {
            t: vec![t0],
            y: vec![y0.clone()],
            dense: Vec::new(),
            max_constraint_violation: worst,
            max_drift: Violation::default(),
            projections,
            work: Work::default(),
            n,
        };
        // the right-hand side cannot fail: a failure is kept here and NaN stops the solver
        let failure: RefCell<Option<DynamicsError>> = RefCell::new(None);
        let f = |t: f64, y: &DVector<f64>| {
            let (q, qd) = y.as_slice().split_at(n);
            match solve_constrained(sys, q, qd, t) {
                Ok(s) => DVector::from_iterator(2 * n, qd.iter().chain(s.qdd.iter()).copied()),
                Err(e) => {
                    failure.borrow_mut().get_or_insert(e);
                    DVector::from_element(2 * n, f64::NAN)
                }
            }
        };
        let ode = |e: OdeError| match e {
            OdeError::RhsNotFinite { .. } => failure.borrow_mut().take().unwrap_or(DynamicsError::Ode(e)),
            e => DynamicsError::Ode(e),
        };
        let tol = self.projection.tol;
        let mut st = Stepper::new(&self.solver, f, t0, y0, t1).map_err(ode)?;
        while !st.done() {
            st.step().map_err(ode)?;
            let t = st.t();
            if self.dense {
                run.dense.push(st.dense().map_err(ode)?.clone());
            }
            let mut y = st.y().clone();
            let (q, qd) = y.as_slice().split_at(n);
            let before = constraint_violation(sys, q, qd, t)?;
            run.max_drift = run.max_drift.max(before);
            if self.project_steps && (before.position > tol || before.velocity > tol) {
                self.project(sys, t, &mut y)?;
                run.projections += 1;
                let (q, qd) = y.as_slice().split_at(n);
                run.max_constraint_violation =
                    run.max_constraint_violation.max(constraint_violation(sys, q, qd, t)?);
                if !st.done() {
                    // continue from the projected state: a fresh first stage, the step size kept
                    st.restart(t, y.clone()).map_err(ode)?;
                }
            } else {
                run.max_constraint_violation = run.max_constraint_violation.max(before);
            }
            run.t.push(t);
            run.y.push(y);
        }
        run.work = st.work();
        Ok(run)
    }
}
