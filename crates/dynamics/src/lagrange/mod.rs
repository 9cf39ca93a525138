//! Lagrange's and Hamilton's equations without symbolic algebra (book ch. 9).
//!
//! The user writes T(q, q̇, t), U(q, t), the Rayleigh function R(q, q̇) and generalized
//! forces as methods of a [`Lagrangian`], generic over the scalar; vectrix differentiates
//! them exactly with num-dual dual numbers (no finite differences, no symbols):
//!
//! * M = ∂²T/∂q̇² (one hyper-dual evaluation per entry of the upper triangle);
//! * the velocity terms Cq̇ + b = Σ_j ∂²T/∂q̇∂q_j q̇_j + ∂²T/∂q̇∂t, one hyper-dual evaluation
//!   per coordinate along the flow direction (q̇, 1) in (q, t);
//! * ∂T/∂q, ∂U/∂q, ∂R/∂q̇ by first-order duals;
//!
//! then solves M q̈ = Q − ∂R/∂q̇ − ∂U/∂q + ∂T/∂q − Cq̇ − b (9.9.7) by Cholesky, with a clear
//! error when M is singular (Euler angles at gimbal lock). Rust closures cannot be generic,
//! so the "closures" are the generic methods of a trait that the user implements.

mod ad;
mod hamilton;
mod map;

pub use ad::{
    LagrangeTerms, accelerations, energy, energy_rate, generalized_momentum, lagrange_terms, mass_matrix,
};
pub use hamilton::{hamilton_rhs, hamiltonian, velocities_from_momenta};
pub use map::{
    KinematicMap, MapMasses, map_accelerations, map_equations, map_kinetic_energy, map_mass_matrix,
};

use nalgebra::{DMatrix, DVector};
use vectrix_tensor::Scalar;

use crate::DynamicsError;

/// A mechanical system given by its energies, generic over the scalar so that vectrix can
/// differentiate it with dual numbers.
///
/// Book: §9.3 (T), §9.8 (U, L = T − U), §9.9 (Rayleigh R), §9.4–9.5 (generalized forces).
///
/// # Conventions
/// Write constants with `T::lit(x)`. T must be quadratic in q̇ (9.3.11), as every mechanical
/// kinetic energy is; Hamilton's equations rely on it.
pub trait Lagrangian {
    /// Number of generalized coordinates r.
    fn dof(&self) -> usize;
    /// Kinetic energy T(q, q̇, t) (9.3.11).
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], t: T) -> T;
    /// Potential energy U(q, t) (9.8.2); zero by default.
    fn potential<T: Scalar>(&self, q: &[T], t: T) -> T {
        let _ = (q, t);
        T::zero()
    }
    /// Rayleigh dissipation function R(q, q̇) (9.9.2); zero by default.
    fn rayleigh<T: Scalar>(&self, q: &[T], qd: &[T]) -> T {
        let _ = (q, qd);
        T::zero()
    }
    /// Remaining generalized forces Q_npnR(q, q̇, t) (9.9.1), added into `out` (zeros on
    /// entry); none by default.
    fn generalized_force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let _ = (q, qd, t, out);
    }
}

/// Relative pivot below which a mass matrix counts as singular: 64 r ε.
pub const SINGULAR_PIVOT_REL_TOL: f64 = 64.0 * f64::EPSILON;

/// Solves M x = b by Cholesky; `Err(SingularMassMatrix)` when M is not positive definite or
/// a pivot L_kk² falls below [`SINGULAR_PIVOT_REL_TOL`]·r·max M_ii.
pub(crate) fn cholesky_solve(m: DMatrix<f64>, b: DVector<f64>) -> Result<DVector<f64>, DynamicsError> {
    if !m.iter().chain(b.iter()).all(|x| x.is_finite()) {
        return Err(DynamicsError::NonFinite { what: "mass matrix or right-hand side" });
    }
    let x = checked_cholesky(m)?.solve(&b);
    // finite M and b whose solution exceeds f64::MAX (b ≈ 1e308 over a small pivot)
    if !x.iter().all(|v| v.is_finite()) {
        return Err(DynamicsError::Overflow { what: "the solution of M x = b" });
    }
    Ok(x)
}

/// The Cholesky factor of M, `Err(SingularMassMatrix)` when M is not positive definite or a
/// pivot L_kk² falls below [`SINGULAR_PIVOT_REL_TOL`]·r·max M_ii.
pub(crate) fn checked_cholesky(
    m: DMatrix<f64>,
) -> Result<nalgebra::Cholesky<f64, nalgebra::Dyn>, DynamicsError> {
    let r = m.nrows();
    let scale = (0..r).map(|i| m[(i, i)].abs()).fold(0.0, f64::max);
    let chol = nalgebra::Cholesky::new(m).ok_or_else(|| DynamicsError::SingularMassMatrix {
        detail: "Cholesky found a non-positive pivot".into(),
    })?;
    let l = chol.l_dirty();
    for k in 0..r {
        let pivot = l[(k, k)] * l[(k, k)];
        if pivot <= SINGULAR_PIVOT_REL_TOL * r as f64 * scale {
            return Err(DynamicsError::SingularMassMatrix {
                detail: format!(
                    "pivot {k} is {pivot:e}, below {:e} × max Mᵢᵢ = {scale:e}",
                    SINGULAR_PIVOT_REL_TOL * r as f64
                ),
            });
        }
    }
    Ok(chol)
}
