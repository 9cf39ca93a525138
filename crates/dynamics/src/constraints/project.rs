//! Projection onto the constraint manifold, on plain f64 callbacks (usable by any model,
//! including scenes whose configuration lives on a manifold).
//!
//! * Positions: Gauss–Newton in the M-metric, Δ = argmin ½ΔᵀMΔ subject to
//!   φ(q) + Φ_q Δ = 0, that is [[M, Φ_qᵀ], [Φ_q, 0]] [Δ; μ] = [0; −φ], with backtracking and a
//!   bounded number of iterations (HNW §VII.2, HLW §IV.4).
//! * Velocities: the M-orthogonal projection v ← v − M⁻¹Gᵀ(GM⁻¹Gᵀ)⁻¹(Gv + c) onto
//!   {v : Gv + c = 0}, the kinetic-energy-nearest admissible velocity.

use nalgebra::{DMatrix, DVector};

use super::{DEPENDENT_ROW_REL_TOL, KktFactor};
use crate::DynamicsError;

/// Halvings of a Gauss–Newton step before the projection gives up.
const MAX_HALVINGS: usize = 8;

/// Largest number of Gauss–Newton iterations a projection may be given.
pub const MAX_PROJECTION_ITERATIONS: usize = 100;

/// Options of a projection onto the constraints.
///
/// Book: §9.11.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProjectionOptions {
    /// Stop when |φ|∞ ≤ tol (absolute, in the units of φ). Default 1e-12.
    pub tol: f64,
    /// At most this many Gauss–Newton iterations (1..=[`MAX_PROJECTION_ITERATIONS`]).
    /// Default 10.
    pub max_iterations: usize,
    /// Relative rank tolerance of the constraint rows. Default [`DEPENDENT_ROW_REL_TOL`].
    pub rank_tol: f64,
}

impl Default for ProjectionOptions {
    fn default() -> Self {
        Self { tol: 1e-12, max_iterations: 10, rank_tol: DEPENDENT_ROW_REL_TOL }
    }
}

impl ProjectionOptions {
    /// `Err(OutOfRange)` unless tol > 0, 1 ≤ max_iterations ≤
    /// [`MAX_PROJECTION_ITERATIONS`] and 0 < rank_tol < 1.
    pub(crate) fn check(&self) -> Result<(), DynamicsError> {
        let bad = |what, value, valid| Err(DynamicsError::OutOfRange { what, value, valid });
        if !(self.tol.is_finite() && self.tol > 0.0) {
            return bad("projection tolerance", self.tol, "finite and > 0");
        }
        if !(1..=MAX_PROJECTION_ITERATIONS).contains(&self.max_iterations) {
            return bad("projection iterations", self.max_iterations as f64, "1 ≤ iterations ≤ 100");
        }
        if !(self.rank_tol.is_finite() && self.rank_tol > 0.0 && self.rank_tol < 1.0) {
            return bad("rank tolerance", self.rank_tol, "0 < tol < 1");
        }
        Ok(())
    }
}

/// The result of [`project_positions`].
///
/// Book: §9.11.
#[derive(Debug, Clone, PartialEq)]
pub struct PositionProjection {
    /// The projected configuration.
    pub q: Vec<f64>,
    /// Gauss–Newton iterations taken (0 when q was already on the manifold).
    pub iterations: usize,
    /// |φ|∞ before.
    pub initial: f64,
    /// |φ|∞ after (≤ tol).
    pub violation: f64,
}

fn inf_norm(x: &DVector<f64>) -> f64 {
    x.amax()
}

/// Projects q onto {q : φ(q) = 0} by Gauss–Newton in the metric of `mass`.
///
/// `constraints(q)` returns (φ(q), Φ_q(q)) with Φ_q of size m × n, n the size of `mass`;
/// `retract(q, Δ)` returns q ⊕ Δ (q + Δ for plain coordinates; the exponential map for a
/// quaternion, so that q may have more entries than n). Each iteration solves
/// [[M, Φ_qᵀ], [Φ_q, 0]] [Δ; μ] = [0; −φ] and halves Δ (at most 8 times) until |φ|∞
/// decreases.
///
/// Book: §9.11; HNW §VII.2.
///
/// # Errors
/// [`DynamicsError::OutOfRange`] (options), the callbacks' errors, the factorization's
/// errors ([`KktFactor::new`]), and [`DynamicsError::ProjectionFailed`] when |φ|∞ does not
/// reach `tol` within `max_iterations` or stops decreasing.
pub fn project_positions<F, R>(
    q: &[f64],
    mass: &DMatrix<f64>,
    mut constraints: F,
    mut retract: R,
    opts: &ProjectionOptions,
) -> Result<PositionProjection, DynamicsError>
where
    F: FnMut(&[f64]) -> Result<(DVector<f64>, DMatrix<f64>), DynamicsError>,
    R: FnMut(&[f64], &DVector<f64>) -> Result<Vec<f64>, DynamicsError>,
{
    opts.check()?;
    let (mut phi, mut jac) = constraints(q)?;
    let initial = inf_norm(&phi);
    let (mut q, mut violation) = (q.to_vec(), initial);
    let zero = DVector::zeros(mass.nrows());
    for iterations in 0..opts.max_iterations {
        if violation <= opts.tol {
            return Ok(PositionProjection { q, iterations, initial, violation });
        }
        // [[M, Φ_qᵀ], [Φ_q, 0]] [Δ; μ] = [0; −φ]
        let step = KktFactor::new(mass, &jac, opts.rank_tol)?.solve(&zero, &(-&phi))?.x;
        let mut scale = 1.0;
        let mut halvings = 0;
        loop {
            let q_try = retract(&q, &(&step * scale))?;
            let (phi_try, jac_try) = constraints(&q_try)?;
            let v = inf_norm(&phi_try);
            if v < violation {
                (q, phi, jac, violation) = (q_try, phi_try, jac_try, v);
                break;
            }
            // no decrease: the linearization overshoots (far from the manifold)
            halvings += 1;
            if halvings > MAX_HALVINGS {
                return Err(DynamicsError::ProjectionFailed {
                    iterations: iterations + 1,
                    violation,
                    tol: opts.tol,
                });
            }
            scale *= 0.5;
        }
    }
    if violation <= opts.tol {
        Ok(PositionProjection { q, iterations: opts.max_iterations, initial, violation })
    } else {
        Err(DynamicsError::ProjectionFailed { iterations: opts.max_iterations, violation, tol: opts.tol })
    }
}

/// The M-orthogonal projection of v onto {v : Gv + c = 0}: v − M⁻¹Gᵀ(GM⁻¹Gᵀ)⁻¹r with the
/// residual r = Gv + c, solved as [[M, Gᵀ], [G, 0]] [δ; μ] = [0; −r], v + δ.
///
/// Book: §9.11, §9.12.
///
/// # Errors
/// As [`KktFactor::new`]; [`DynamicsError::DimensionMismatch`] for sizes that disagree.
pub fn project_velocities(
    v: &DVector<f64>,
    mass: &DMatrix<f64>,
    jacobian: &DMatrix<f64>,
    residual: &DVector<f64>,
    rank_tol: f64,
) -> Result<DVector<f64>, DynamicsError> {
    crate::error::check_len(v.len(), mass.nrows(), "v")?;
    let delta = KktFactor::new(mass, jacobian, rank_tol)?.solve(&DVector::zeros(v.len()), &(-residual))?.x;
    Ok(v + delta)
}
