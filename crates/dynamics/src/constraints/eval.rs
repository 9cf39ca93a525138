//! The constraint terms by dual numbers, and the constrained equations of motion.

use nalgebra::{DMatrix, DVector};
use num_dual::{Dual64, HyperDual64};

use super::{
    ConstrainedSystem, Constraints, DEPENDENT_ROW_REL_TOL, KinematicMap, LagrangeForm, Lagrangian, MapForm,
    solve_kkt,
};
use crate::DynamicsError;
use crate::error::{check_finite, check_len};

/// The constraint terms at one state, exact to round-off.
///
/// Book: §9.11, §9.12.
///
/// # Conventions
/// Rows: the m holonomic constraints first, then the k velocity constraints.
#[derive(Debug, Clone, PartialEq)]
pub struct ConstraintTerms {
    /// G = [Φ_q; A], (m + k) × n.
    pub jacobian: DMatrix<f64>,
    /// γ in the acceleration constraint G q̈ = γ: −[(Φ_q q̇)_q q̇ + 2Φ_qt q̇ + Φ_tt] for the
    /// holonomic rows, −(ψ_q q̇ + ψ_t) for the velocity rows.
    pub gamma: DVector<f64>,
    /// φ(q, t), length m.
    pub position: DVector<f64>,
    /// The velocity residuals [Φ_q q̇ + Φ_t; A q̇ + b], length m + k.
    pub velocity: DVector<f64>,
}

/// The constrained accelerations, the multipliers and the constraint terms they came from.
///
/// Book: §9.11.
#[derive(Debug, Clone, PartialEq)]
pub struct ConstrainedSolution {
    /// q̈.
    pub qdd: DVector<f64>,
    /// λ, one per constraint row; the generalized constraint force is −Gᵀλ.
    pub lambda: DVector<f64>,
    /// G, γ and the residuals at this state.
    pub terms: ConstraintTerms,
}

/// (m, k), with m + k ≤ n checked before anything is allocated.
pub(crate) fn counts<C: Constraints>(sys: &C, n: usize) -> Result<(usize, usize), DynamicsError> {
    let (m, k) = (sys.constraint_count(), sys.velocity_constraint_count());
    let count = m.saturating_add(k);
    if count > n {
        return Err(DynamicsError::TooManyConstraints { count, dof: n });
    }
    Ok((m, k))
}

fn check_state(n: usize, q: &[f64], qd: &[f64], t: f64) -> Result<(), DynamicsError> {
    check_len(q.len(), n, "q")?;
    check_len(qd.len(), n, "q̇")?;
    check_finite(q, "q")?;
    check_finite(qd, "q̇")?;
    check_finite(&[t], "t")
}

pub(crate) fn duals(x: &[f64]) -> Vec<Dual64> {
    x.iter().map(|&v| Dual64::from(v)).collect()
}

/// Values f(x) (length m) and the Jacobian ∂f/∂x (m × n) of `eval(x, out)`: one dual
/// evaluation per column, ε on x_j giving column j.
pub(crate) fn dual_jacobian(
    x: &[f64],
    m: usize,
    mut eval: impl FnMut(&[Dual64], &mut [Dual64]),
) -> (DVector<f64>, DMatrix<f64>) {
    let n = x.len();
    let (mut value, mut jac) = (DVector::zeros(m), DMatrix::zeros(m, n));
    if m == 0 {
        return (value, jac);
    }
    let mut xj = duals(x);
    let mut out = vec![Dual64::from(0.0); m];
    for j in 0..n {
        xj[j].eps = 1.0;
        out.fill(Dual64::from(0.0));
        eval(&xj, &mut out);
        xj[j].eps = 0.0;
        for (i, v) in out.iter().enumerate() {
            jac[(i, j)] = v.eps;
            value[i] = v.re;
        }
    }
    (value, jac)
}

/// φ(q, t) and Φ_q (m × n): one dual evaluation per coordinate.
pub(crate) fn holonomic_rows<C: Constraints>(
    sys: &C,
    q: &[f64],
    t: f64,
    m: usize,
) -> Result<(DVector<f64>, DMatrix<f64>), DynamicsError> {
    let td = Dual64::from(t);
    let (phi, jac) = dual_jacobian(q, m, |qj, out| sys.constraints(qj, td, out));
    check_finite(phi.as_slice(), "constraint φ(q, t)")?;
    check_finite(jac.as_slice(), "constraint Jacobian Φ_q")?;
    Ok((phi, jac))
}

/// ψ(q, q̇, t) and A = ∂ψ/∂q̇ (k × n): one dual evaluation per velocity.
fn velocity_rows<C: Constraints>(
    sys: &C,
    q: &[f64],
    qd: &[f64],
    t: f64,
    k: usize,
) -> Result<(DVector<f64>, DMatrix<f64>), DynamicsError> {
    let (qv, td) = (duals(q), Dual64::from(t));
    let (psi, a) = dual_jacobian(qd, k, |qdj, out| sys.velocity_constraints(&qv, qdj, td, out));
    check_finite(psi.as_slice(), "velocity constraint ψ(q, q̇, t)")?;
    check_finite(a.as_slice(), "velocity constraint matrix A")?;
    Ok((psi, a))
}

/// G = [Φ_q; A] and the velocity residuals [Φ_q q̇ + Φ_t; A q̇ + b]: what a velocity
/// projection needs (no second derivatives).
pub(crate) fn velocity_system<C: Constraints>(
    sys: &C,
    q: &[f64],
    qd: &[f64],
    t: f64,
    (m, k): (usize, usize),
) -> Result<(DMatrix<f64>, DVector<f64>), DynamicsError> {
    let n = q.len();
    let (_, phi_q) = holonomic_rows(sys, q, t, m)?;
    let (psi, a) = velocity_rows(sys, q, qd, t, k)?;
    let mut g = DMatrix::zeros(m + k, n);
    g.rows_mut(0, m).copy_from(&phi_q);
    g.rows_mut(m, k).copy_from(&a);
    let mut r = DVector::zeros(m + k);
    if m > 0 {
        // φ̇ = Φ_q q̇ + Φ_t: ε part along the flow (q̇, 1)
        let qf: Vec<Dual64> = q.iter().zip(qd).map(|(&x, &v)| Dual64::new(x, v)).collect();
        let mut out = vec![Dual64::from(0.0); m];
        sys.constraints(&qf, Dual64::new(t, 1.0), &mut out);
        for (i, v) in out.iter().enumerate() {
            r[i] = v.eps;
        }
    }
    r.rows_mut(m, k).copy_from(&psi);
    check_finite(r.as_slice(), "velocity constraint residual")?;
    Ok((g, r))
}

/// G, γ, φ and the velocity residuals at (q, q̇, t): n dual evaluations of φ and of ψ, one
/// hyper-dual evaluation of φ along the flow (q̇, 1) twice, one dual evaluation of ψ along
/// (q̇, 1) with q̇ held.
///
/// Book: §9.11, §9.12.
///
/// # Errors
/// [`DynamicsError::DimensionMismatch`] (q̇ of another length than q),
/// [`DynamicsError::NonFinite`] (input or constraint values),
/// [`DynamicsError::TooManyConstraints`] (m + k > n).
pub fn constraint_terms<C: Constraints>(
    sys: &C,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<ConstraintTerms, DynamicsError> {
    let n = q.len();
    check_state(n, q, qd, t)?;
    let (m, k) = counts(sys, n)?;
    let (position, phi_q) = holonomic_rows(sys, q, t, m)?;
    let (psi, a) = velocity_rows(sys, q, qd, t, k)?;
    let mut jacobian = DMatrix::zeros(m + k, n);
    jacobian.rows_mut(0, m).copy_from(&phi_q);
    jacobian.rows_mut(m, k).copy_from(&a);
    let (mut gamma, mut velocity) = (DVector::zeros(m + k), DVector::zeros(m + k));
    if m > 0 {
        // ε₁ = ε₂ = (q̇, 1) on (q, t): ε₁ part φ̇, ε₁ε₂ part (Φ_q q̇)_q q̇ + 2Φ_qt q̇ + Φ_tt
        let qh: Vec<HyperDual64> = q.iter().zip(qd).map(|(&x, &v)| HyperDual64::new(x, v, v, 0.0)).collect();
        let mut out = vec![HyperDual64::from(0.0); m];
        sys.constraints(&qh, HyperDual64::new(t, 1.0, 1.0, 0.0), &mut out);
        for (i, v) in out.iter().enumerate() {
            velocity[i] = v.eps1;
            gamma[i] = -v.eps1eps2;
        }
    }
    if k > 0 {
        // ψ̇ = A q̈ + ψ_q q̇ + ψ_t: the ε part along (q̇, 1) with q̇ held is ψ_q q̇ + ψ_t
        let qf: Vec<Dual64> = q.iter().zip(qd).map(|(&x, &v)| Dual64::new(x, v)).collect();
        let mut out = vec![Dual64::from(0.0); k];
        sys.velocity_constraints(&qf, &duals(qd), Dual64::new(t, 1.0), &mut out);
        for (i, v) in out.iter().enumerate() {
            gamma[m + i] = -v.eps;
        }
        velocity.rows_mut(m, k).copy_from(&psi);
    }
    check_finite(gamma.as_slice(), "constraint acceleration term γ")?;
    check_finite(velocity.as_slice(), "velocity constraint residual")?;
    Ok(ConstraintTerms { jacobian, gamma, position, velocity })
}

/// q̈ and λ of a [`ConstrainedSystem`]: [[M, Gᵀ], [G, 0]] [q̈; λ] = [f; γ], solved by
/// [`solve_kkt`] with [`DEPENDENT_ROW_REL_TOL`].
///
/// The state is taken as given: when it violates the constraints, q̈ still satisfies the
/// acceleration constraint (the violation does not grow quadratically, but it is not
/// corrected; use [`super::ConstrainedIntegrator`] for that).
///
/// Book: §9.11, §9.12.
///
/// # Errors
/// As [`constraint_terms`] and [`solve_kkt`]: a redundant or singular constraint set is a
/// [`DynamicsError::DependentConstraint`] or [`DynamicsError::SingularConstraint`] naming
/// the row.
pub fn solve_constrained<S: ConstrainedSystem>(
    sys: &S,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<ConstrainedSolution, DynamicsError> {
    check_state(sys.dof(), q, qd, t)?;
    let terms = constraint_terms(sys, q, qd, t)?;
    let (mass, forcing) = sys.equations(q, qd, t)?;
    let kkt = solve_kkt(&mass, &terms.jacobian, &forcing, &terms.gamma, DEPENDENT_ROW_REL_TOL)?;
    Ok(ConstrainedSolution { qdd: kkt.x, lambda: kkt.lambda, terms })
}

/// [`solve_constrained`] for a [`Lagrangian`] with [`Constraints`]: Lagrange's equations
/// with multipliers, M q̈ = Q − ∂R/∂q̇ − ∂U/∂q + ∂T/∂q − (Cq̇ + b) − Gᵀλ, G q̈ = γ.
///
/// Book: §9.9, (9.9.7); §9.11; §9.12.
///
/// # Errors
/// As [`solve_constrained`].
pub fn constrained_accelerations<L: Lagrangian + Constraints>(
    sys: &L,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<ConstrainedSolution, DynamicsError> {
    solve_constrained(&LagrangeForm(sys), q, qd, t)
}

/// [`solve_constrained`] for a [`KinematicMap`] with [`Constraints`]: rigid bodies and
/// particles given by where they are, joined by constraints (a closed loop).
///
/// Book: §9.3, §9.11.
///
/// # Errors
/// As [`solve_constrained`].
pub fn map_constrained_accelerations<K: KinematicMap + Constraints>(
    sys: &K,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<ConstrainedSolution, DynamicsError> {
    solve_constrained(&MapForm(sys), q, qd, t)
}
