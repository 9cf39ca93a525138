//! Hamilton's equations from a [`Lagrangian`] (book §9.13).

use nalgebra::DVector;
use num_dual::Dual64;

use super::{Lagrangian, cholesky_solve, lagrange_terms, mass_matrix};
use crate::DynamicsError;
use crate::error::{check_finite, check_len};

/// q̇ from the momenta: p = Mq̇ + Fᵀ (9.13.6) with Fᵀ = ∂T/∂q̇ at q̇ = 0, so
/// q̇ = M⁻¹(p − Fᵀ) (T quadratic in q̇, (9.3.11)).
///
/// Book: (9.13.6).
///
/// # Errors
/// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`],
/// [`DynamicsError::SingularMassMatrix`].
pub fn velocities_from_momenta<L: Lagrangian>(
    sys: &L,
    q: &[f64],
    p: &[f64],
    t: f64,
) -> Result<DVector<f64>, DynamicsError> {
    let r = sys.dof();
    check_len(p.len(), r, "p")?;
    check_finite(p, "p")?;
    let zero = vec![0.0; r];
    let m = mass_matrix(sys, q, &zero, t)?;
    // Fᵀ = ∂T/∂q̇ at q̇ = 0
    let qv: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
    let mut f = DVector::zeros(r);
    for i in 0..r {
        let e: Vec<Dual64> = (0..r).map(|k| Dual64::new(0.0, f64::from(k == i))).collect();
        f[i] = sys.kinetic(&qv, &e, Dual64::from(t)).eps;
    }
    cholesky_solve(m, DVector::from_column_slice(p) - f)
}

/// The Hamiltonian H = pᵀq̇ − L (9.13.7) at (q, p, t).
///
/// Book: (9.13.7)–(9.13.9) (with the corrected sign of ½FM⁻¹Fᵀ, notes ch9-14).
///
/// # Errors
/// As [`velocities_from_momenta`]; [`DynamicsError::Overflow`] when H exceeds f64::MAX.
pub fn hamiltonian<L: Lagrangian>(sys: &L, q: &[f64], p: &[f64], t: f64) -> Result<f64, DynamicsError> {
    let qd = velocities_from_momenta(sys, q, p, t)?;
    let l = sys.kinetic(q, qd.as_slice(), t) - sys.potential(q, t);
    let h = DVector::from_column_slice(p).dot(&qd) - l;
    // finite p and q whose pᵀq̇ or L exceeds f64::MAX (∞ − ∞ = NaN)
    if !h.is_finite() {
        return Err(DynamicsError::Overflow { what: "Hamiltonian" });
    }
    Ok(h)
}

/// Hamilton's equations q̇ = ∂H/∂pᵀ, ṗ = −∂H/∂qᵀ + Q_np (9.13.10–12), evaluated through the
/// Lagrangian: q̇ from [`velocities_from_momenta`], ṗ = ∂L/∂qᵀ − ∂R/∂q̇ᵀ + Q_npnR.
///
/// Book: §9.13, (9.13.10)–(9.13.16).
///
/// # Errors
/// As [`velocities_from_momenta`].
pub fn hamilton_rhs<L: Lagrangian>(
    sys: &L,
    q: &[f64],
    p: &[f64],
    t: f64,
) -> Result<(DVector<f64>, DVector<f64>), DynamicsError> {
    let qd = velocities_from_momenta(sys, q, p, t)?;
    let terms = lagrange_terms(sys, q, qd.as_slice(), t)?;
    let pd = &terms.dt_dq - &terms.du_dq - &terms.dr_dqd + &terms.force;
    Ok((qd, pd))
}
