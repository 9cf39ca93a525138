//! The terms of Lagrange's equations by forward-mode automatic differentiation.

use nalgebra::{DMatrix, DVector};
use num_dual::{Dual64, HyperDual64};

use super::{Lagrangian, cholesky_solve};
use crate::DynamicsError;
use crate::error::{check_finite, check_len};

/// Every term of Lagrange's equations at one state, exact to round-off.
///
/// Book: (9.6.2), (9.6.4), (9.9.7).
#[derive(Debug, Clone, PartialEq)]
pub struct LagrangeTerms {
    /// M = ∂²T/∂q̇² (9.3.12).
    pub mass: DMatrix<f64>,
    /// p = ∂T/∂q̇ᵀ, the generalized momenta (9.13.6).
    pub momentum: DVector<f64>,
    /// Cq̇ + b = Σ_j ∂²T/∂q̇∂q_j q̇_j + ∂²T/∂q̇∂t: the part of d/dt ∂T/∂q̇ not proportional to q̈.
    pub velocity_terms: DVector<f64>,
    /// ∂T/∂qᵀ.
    pub dt_dq: DVector<f64>,
    /// ∂U/∂qᵀ (so Q_p = −∂U/∂qᵀ, (9.8.2)).
    pub du_dq: DVector<f64>,
    /// ∂R/∂q̇ᵀ (so Q_R = −∂R/∂q̇ᵀ, (9.9.2)).
    pub dr_dqd: DVector<f64>,
    /// Q_npnR, the user's remaining generalized forces.
    pub force: DVector<f64>,
}

impl LagrangeTerms {
    /// The right-hand side of M q̈ = Q_npnR − ∂R/∂q̇ − ∂U/∂q + ∂T/∂q − (Cq̇ + b) (9.9.7).
    pub fn rhs(&self) -> DVector<f64> {
        &self.force - &self.dr_dqd - &self.du_dq + &self.dt_dq - &self.velocity_terms
    }
}

fn check_state(r: usize, q: &[f64], qd: &[f64], t: f64) -> Result<(), DynamicsError> {
    check_len(q.len(), r, "q")?;
    check_len(qd.len(), r, "q̇")?;
    check_finite(q, "q")?;
    check_finite(qd, "q̇")?;
    check_finite(&[t], "t")
}

fn check_out(values: &[f64], what: &'static str) -> Result<(), DynamicsError> {
    check_finite(values, what)
}

/// q and q̇ as hyper-duals with ε₁-parts `d1` (on (q, q̇)) and ε₂-parts `d2`.
fn hyper(x: &[f64], d1: impl Fn(usize) -> f64, d2: impl Fn(usize) -> f64) -> Vec<HyperDual64> {
    x.iter().enumerate().map(|(k, &v)| HyperDual64::new(v, d1(k), d2(k), 0.0)).collect()
}

/// The mass matrix M = ∂²T/∂q̇² (9.3.12), r(r+1)/2 hyper-dual evaluations of T.
///
/// Book: (9.3.11)–(9.3.12), Fact 9.3.1 (M ≻ 0 except at singular coordinates).
///
/// # Errors
/// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`] (input or T).
pub fn mass_matrix<L: Lagrangian>(
    sys: &L,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<DMatrix<f64>, DynamicsError> {
    let r = sys.dof();
    check_state(r, q, qd, t)?;
    let qh = hyper(q, |_| 0.0, |_| 0.0);
    let th = HyperDual64::from(t);
    let mut m = DMatrix::zeros(r, r);
    for i in 0..r {
        for j in i..r {
            // ε₁ on q̇_i, ε₂ on q̇_j: the ε₁ε₂ part is ∂²T/∂q̇_i∂q̇_j
            let qdh = hyper(qd, |k| f64::from(k == i), |k| f64::from(k == j));
            let v = sys.kinetic(&qh, &qdh, th).eps1eps2;
            m[(i, j)] = v;
            m[(j, i)] = v;
        }
    }
    check_out(m.as_slice(), "mass matrix ∂²T/∂q̇²")?;
    Ok(m)
}

/// Every term of Lagrange's equations at (q, q̇, t): r(r+1)/2 + r hyper-dual and 3r dual
/// evaluations.
///
/// Book: (9.6.2), (9.6.4), (9.8.13), (9.9.7).
///
/// # Errors
/// As [`mass_matrix`].
pub fn lagrange_terms<L: Lagrangian>(
    sys: &L,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<LagrangeTerms, DynamicsError> {
    let r = sys.dof();
    let mass = mass_matrix(sys, q, qd, t)?;
    let mut momentum = DVector::zeros(r);
    let mut velocity_terms = DVector::zeros(r);
    for i in 0..r {
        // ε₁ on q̇_i; ε₂ along the flow (q̇ on q, 1 on t): ε₁ε₂ = Σ_j ∂²T/∂q̇_i∂q_j q̇_j + ∂²T/∂q̇_i∂t
        let qh = hyper(q, |_| 0.0, |k| qd[k]);
        let qdh = hyper(qd, |k| f64::from(k == i), |_| 0.0);
        let v = sys.kinetic(&qh, &qdh, HyperDual64::new(t, 0.0, 1.0, 0.0));
        momentum[i] = v.eps1;
        velocity_terms[i] = v.eps1eps2;
    }
    let qd_d: Vec<Dual64> = qd.iter().map(|&x| Dual64::from(x)).collect();
    let q_d: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
    let td = Dual64::from(t);
    let mut dt_dq = DVector::zeros(r);
    let mut du_dq = DVector::zeros(r);
    let mut dr_dqd = DVector::zeros(r);
    for i in 0..r {
        let qi: Vec<Dual64> = q.iter().enumerate().map(|(k, &x)| Dual64::new(x, f64::from(k == i))).collect();
        let qdi: Vec<Dual64> =
            qd.iter().enumerate().map(|(k, &x)| Dual64::new(x, f64::from(k == i))).collect();
        dt_dq[i] = sys.kinetic(&qi, &qd_d, td).eps;
        du_dq[i] = sys.potential(&qi, td).eps;
        dr_dqd[i] = sys.rayleigh(&q_d, &qdi).eps;
    }
    let mut force = DVector::zeros(r);
    sys.generalized_force(q, qd, t, force.as_mut_slice());
    for (v, what) in [
        (&momentum, "∂T/∂q̇"),
        (&velocity_terms, "∂²T/∂q̇∂q q̇"),
        (&dt_dq, "∂T/∂q"),
        (&du_dq, "∂U/∂q"),
        (&dr_dqd, "∂R/∂q̇"),
        (&force, "generalized force"),
    ] {
        check_out(v.as_slice(), what)?;
    }
    Ok(LagrangeTerms { mass, momentum, velocity_terms, dt_dq, du_dq, dr_dqd, force })
}

/// The generalized accelerations q̈ from Lagrange's equations (9.9.7), M solved by Cholesky.
///
/// Book: §9.6, §9.8, §9.9, (9.9.7).
///
/// # Errors
/// As [`mass_matrix`]; [`DynamicsError::SingularMassMatrix`] when M is not positive definite
/// to working precision (Euler angles at gimbal lock, cos Θ = 0 in (9.3.25)).
pub fn accelerations<L: Lagrangian>(
    sys: &L,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<DVector<f64>, DynamicsError> {
    let terms = lagrange_terms(sys, q, qd, t)?;
    let rhs = terms.rhs();
    cholesky_solve(terms.mass, rhs)
}

/// The generalized momenta p = ∂T/∂q̇ᵀ (9.13.6): constants of motion for ignorable
/// coordinates (Fact 9.6.4: Q_j = 0 and ∂L/∂q_j = 0 ⇒ p_j constant).
///
/// Book: Fact 9.6.4, (9.13.6).
///
/// # Errors
/// As [`mass_matrix`].
pub fn generalized_momentum<L: Lagrangian>(
    sys: &L,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<DVector<f64>, DynamicsError> {
    let r = sys.dof();
    check_state(r, q, qd, t)?;
    let qv: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
    let mut p = DVector::zeros(r);
    for i in 0..r {
        let qdi: Vec<Dual64> =
            qd.iter().enumerate().map(|(k, &x)| Dual64::new(x, f64::from(k == i))).collect();
        p[i] = sys.kinetic(&qv, &qdi, Dual64::from(t)).eps;
    }
    check_out(p.as_slice(), "∂T/∂q̇")?;
    Ok(p)
}

/// Total energy E = T + U (Fact 9.8.4: constant when every force is potential and T, U do
/// not depend on t).
///
/// Book: Fact 8.4.1, Fact 9.8.4.
///
/// # Errors
/// As [`mass_matrix`].
pub fn energy<L: Lagrangian>(sys: &L, q: &[f64], qd: &[f64], t: f64) -> Result<f64, DynamicsError> {
    check_state(sys.dof(), q, qd, t)?;
    let e = sys.kinetic(q, qd, t) + sys.potential(q, t);
    check_out(&[e], "energy")?;
    Ok(e)
}

/// The dissipation law Ė = −(∂R/∂q̇) q̇ + Q_npnRᵀ q̇ (Fact 9.9.3, with the remaining forces'
/// power added), for T and U without explicit time dependence. For R = ½q̇ᵀCq̇ this is
/// −q̇ᵀCq̇ = −2R.
///
/// Book: Fact 9.9.3, (9.13.16).
///
/// # Errors
/// As [`lagrange_terms`]; [`DynamicsError::Overflow`] when the power exceeds f64::MAX.
pub fn energy_rate<L: Lagrangian>(sys: &L, q: &[f64], qd: &[f64], t: f64) -> Result<f64, DynamicsError> {
    let terms = lagrange_terms(sys, q, qd, t)?;
    let qd = DVector::from_column_slice(qd);
    let rate = (&terms.force - &terms.dr_dqd).dot(&qd);
    // finite forces and speeds whose power exceeds f64::MAX
    if !rate.is_finite() {
        return Err(DynamicsError::Overflow { what: "energy rate" });
    }
    Ok(rate)
}
