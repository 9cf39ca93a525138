//! Equilibria of linear and affine systems: the states and constant inputs with ẋ = 0.
//!
//! Book: 15.20.8 (ẋ = ax + b tends to −b/a), 15.20.55 (all (x̄, ū) with Ax̄ + Bū = 0 for the
//! rigid bodies and the oscillator of §15.4).

use crate::error::{LtiError, check_finite};
use crate::linalg::{from_faer, to_faer};
use crate::ss::StateSpace;
use nalgebra::{DMatrix, DVector};

/// The equilibria of an affine system ẋ = Ax + b.
///
/// Book: 15.20.8.
#[derive(Debug, Clone, PartialEq)]
pub enum AffineEquilibria {
    /// Ax + b = 0 has no solution (b is not in the range of A): the state drifts forever
    /// (ẋ = b with A = 0).
    None,
    /// Exactly one equilibrium x̄ = −A⁻¹b.
    Unique(DVector<f64>),
    /// An affine family x̄ = x_p + N·c for every c: the particular solution of least norm and
    /// an orthonormal basis N of the null space of A.
    Family {
        /// The equilibrium of least norm, −A⁺b.
        particular: DVector<f64>,
        /// Orthonormal columns spanning the null space of A.
        directions: DMatrix<f64>,
    },
}

/// A full SVD M = UΣVᵀ with the numerical rank: singular values at or below `rtol·σ_max`
/// count as zero.
struct Split {
    u: DMatrix<f64>,
    v: DMatrix<f64>,
    s: Vec<f64>,
    rank: usize,
}

fn svd_split(m: &DMatrix<f64>, rtol: f64) -> Result<Split, LtiError> {
    let svd = to_faer(m).svd().map_err(|_| LtiError::NoConvergence { what: "SVD" })?;
    let s: Vec<f64> = (0..m.nrows().min(m.ncols())).map(|i| svd.S()[i]).collect();
    let top = s.first().copied().unwrap_or(0.0);
    let rank = s.iter().filter(|&&x| x > rtol * top && x > 0.0).count();
    Ok(Split { u: from_faer(svd.U()), v: from_faer(svd.V()), s, rank })
}

fn check_rtol(rtol: f64) -> Result<(), LtiError> {
    if !(rtol.is_finite() && (0.0..1.0).contains(&rtol)) {
        return Err(LtiError::InvalidArgument {
            what: "rank tolerance",
            reason: format!("rtol = {rtol}; need 0 ≤ rtol < 1 (relative to the largest singular value)"),
        });
    }
    Ok(())
}

/// The equilibria of ẋ = Ax + b: solutions of Ax = −b, by the SVD of A with singular values
/// at or below `rtol·σ_max` treated as zero (and b consistent when its component outside the
/// range of A is at most `rtol·(‖A‖‖x_p‖ + ‖b‖)`).
///
/// Book: 15.20.8 (a ≠ 0: x̄ = −b/a, the limit of x(t) when a < 0).
///
/// # Errors
/// [`LtiError::NotSquare`], [`LtiError::DimensionMismatch`], [`LtiError::NonFinite`],
/// [`LtiError::InvalidArgument`] for a tolerance outside [0, 1); [`LtiError::NoConvergence`].
pub fn affine_equilibria(a: &DMatrix<f64>, b: &[f64], rtol: f64) -> Result<AffineEquilibria, LtiError> {
    if a.nrows() != a.ncols() {
        return Err(LtiError::NotSquare { what: "A", rows: a.nrows(), cols: a.ncols() });
    }
    if b.len() != a.nrows() {
        return Err(LtiError::DimensionMismatch {
            what: "b",
            expected: format!("{} entries", a.nrows()),
            found: format!("{}", b.len()),
        });
    }
    check_finite("A", a.iter())?;
    check_finite("b", b)?;
    check_rtol(rtol)?;
    let n = a.nrows();
    let b = DVector::from_column_slice(b);
    if n == 0 {
        return Ok(AffineEquilibria::Unique(b));
    }
    let Split { u, v, s, rank } = svd_split(a, rtol)?;
    // x_p = −A⁺b = −V Σ⁺ Uᵀ b over the nonzero singular values
    let mut xp = DVector::zeros(n);
    for (i, si) in s.iter().enumerate().take(rank) {
        let c = u.column(i).dot(&b) / si;
        xp -= v.column(i) * c;
    }
    let residual = (a * &xp + &b).norm();
    let scale = s[0] * xp.norm() + b.norm();
    if residual > rtol.max(64.0 * f64::EPSILON * n as f64) * scale {
        return Ok(AffineEquilibria::None);
    }
    if rank == n {
        return Ok(AffineEquilibria::Unique(xp));
    }
    Ok(AffineEquilibria::Family { particular: xp, directions: v.columns(rank, n - rank).into_owned() })
}

impl StateSpace {
    /// All equilibria with constant input: an orthonormal basis of the (x̄, ū) with
    /// Ax̄ + Bū = 0, one column per independent equilibrium, the first n rows the state and the
    /// last m the input (the null space of [A B] by SVD, singular values at or below
    /// `rtol·σ_max` treated as zero). No columns: only the origin.
    ///
    /// Book: 15.20.55 (URB: constant position; DRB with velocity state: constant velocity held
    /// by a constant force ū = c v̄; DO: constant position held by ū = k q̄).
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] for a tolerance outside [0, 1); [`LtiError::NoConvergence`].
    pub fn equilibria(&self, rtol: f64) -> Result<DMatrix<f64>, LtiError> {
        check_rtol(rtol)?;
        let (n, m) = (self.n_states(), self.n_inputs());
        let mut ab = DMatrix::zeros(n, n + m);
        ab.view_mut((0, 0), (n, n)).copy_from(self.a());
        ab.view_mut((0, n), (n, m)).copy_from(self.b());
        if n == 0 {
            return Ok(DMatrix::identity(m, m));
        }
        let Split { v, rank, .. } = svd_split(&ab, rtol)?;
        Ok(v.columns(rank, n + m - rank).into_owned())
    }
}
