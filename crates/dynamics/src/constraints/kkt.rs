//! The numeric core on plain matrices: the index-1 system
//! [[M, Gᵀ], [G, 0]] [x; λ] = [f; γ] by Cholesky of M and a QR of L⁻¹Gᵀ taken row by row,
//! which names the first constraint row that depends on the rows before it.
//!
//! With M = LLᵀ and Y = L⁻¹Gᵀ = QR (thin QR, columns in constraint order):
//! x = M⁻¹(f − Gᵀλ) and Gx = γ give GM⁻¹Gᵀλ = YᵀL⁻¹f − γ, that is RᵀRλ = RᵀQᵀz − γ with
//! z = L⁻¹f, so λ = R⁻¹(Qᵀz − R⁻ᵀγ) and x = L⁻ᵀ(z − Yλ). Householder QR without pivoting
//! treats the columns in order, so |R_kk| is the part of row k of G (in the M⁻¹ metric)
//! that no earlier row spans: a small |R_kk| names row k as dependent on rows 0..k.

use nalgebra::{Cholesky, DMatrix, DVector, Dyn, QR};

use crate::DynamicsError;
use crate::error::check_finite;
use crate::lagrange::checked_cholesky;

/// Default relative rank tolerance for constraint rows: row k counts as dependent when
/// |R_kk| ≤ tol·‖L⁻¹gₖ‖, and as singular when ‖L⁻¹gₖ‖ ≤ tol·maxⱼ‖L⁻¹gⱼ‖.
/// 1024 ε: rows that are dependent in exact arithmetic leave a residual of a few ε·√n.
pub const DEPENDENT_ROW_REL_TOL: f64 = 1024.0 * f64::EPSILON;

/// The solution of the index-1 system: x (q̈, or a correction) and the multipliers λ.
///
/// Book: §9.11 (Lagrange multipliers).
#[derive(Debug, Clone, PartialEq)]
pub struct KktSolution {
    /// x with M x + Gᵀλ = f and G x = γ (for the equations of motion, q̈).
    pub x: DVector<f64>,
    /// λ, one per constraint row. The generalized constraint force is −Gᵀλ.
    pub lambda: DVector<f64>,
}

/// M and a constraint Jacobian G factored once, for several right-hand sides (the equations
/// of motion, a position correction, a velocity projection).
///
/// Book: §9.11.
///
/// # Conventions
/// M is n×n symmetric positive definite (only its lower triangle is read); G is m×n with
/// one row per scalar constraint; the generalized constraint force is −Gᵀλ.
#[derive(Debug, Clone)]
pub struct KktFactor {
    l: Cholesky<f64, Dyn>,
    y: DMatrix<f64>,
    // None when there are no constraint rows
    qr: Option<QR<f64, Dyn, Dyn>>,
}

impl KktFactor {
    /// Factors M (Cholesky) and L⁻¹Gᵀ (QR in row order), checking rank row by row.
    ///
    /// Book: §9.11.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`] (G's columns ≠ n), [`DynamicsError::NonFinite`],
    /// [`DynamicsError::SingularMassMatrix`] (M not positive definite to
    /// [`crate::lagrange::SINGULAR_PIVOT_REL_TOL`]); [`DynamicsError::SingularConstraint`] for a row whose
    /// gradient vanishes; [`DynamicsError::DependentConstraint`] for the first row that
    /// depends on earlier rows (with m > n, row n at the latest).
    pub fn new(mass: &DMatrix<f64>, jacobian: &DMatrix<f64>, rank_tol: f64) -> Result<Self, DynamicsError> {
        let n = mass.nrows();
        crate::error::check_len(mass.ncols(), n, "mass matrix columns")?;
        crate::error::check_len(jacobian.ncols(), n, "constraint Jacobian columns")?;
        check_finite(mass.as_slice(), "mass matrix")?;
        check_finite(jacobian.as_slice(), "constraint Jacobian")?;
        if !(rank_tol.is_finite() && rank_tol > 0.0 && rank_tol < 1.0) {
            return Err(DynamicsError::OutOfRange {
                what: "rank tolerance",
                value: rank_tol,
                valid: "0 < tol < 1",
            });
        }
        let l = checked_cholesky(mass.clone())?;
        // Y = L⁻¹Gᵀ: row k of G in the M⁻¹ metric (|yₖ|² = gₖ M⁻¹ gₖᵀ)
        let mut y = jacobian.transpose();
        l.l_dirty().solve_lower_triangular_mut(&mut y);
        if y.ncols() == 0 {
            return Ok(Self { l, y, qr: None });
        }
        let qr = y.clone().qr();
        check_rank(&y, &qr, rank_tol)?;
        Ok(Self { l, y, qr: Some(qr) })
    }

    /// Number of constraint rows m.
    pub fn rows(&self) -> usize {
        self.y.ncols()
    }

    /// Solves [[M, Gᵀ], [G, 0]] [x; λ] = [f; γ].
    ///
    /// Book: §9.11.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`];
    /// [`DynamicsError::Overflow`] when finite f and γ give a non-finite x or λ (γ ≈ 1e308).
    pub fn solve(&self, forcing: &DVector<f64>, gamma: &DVector<f64>) -> Result<KktSolution, DynamicsError> {
        let (n, m) = self.y.shape();
        crate::error::check_len(forcing.len(), n, "forcing")?;
        crate::error::check_len(gamma.len(), m, "γ")?;
        check_finite(forcing.as_slice(), "forcing")?;
        check_finite(gamma.as_slice(), "γ")?;
        let low = self.l.l_dirty();
        // z = L⁻¹f
        let mut z = forcing.clone();
        low.solve_lower_triangular_mut(&mut z);
        // λ = R⁻¹(Qᵀz − R⁻ᵀγ)
        let lambda = match &self.qr {
            None => DVector::zeros(0),
            Some(qr) => {
                let r = qr.r();
                let mut qtz = z.clone();
                qr.q_tr_mul(&mut qtz);
                let mut w = gamma.clone();
                r.tr_solve_upper_triangular_mut(&mut w);
                let mut lambda = qtz.rows(0, m) - w;
                r.solve_upper_triangular_mut(&mut lambda);
                lambda
            }
        };
        // x = L⁻ᵀ(z − Yλ)
        let mut x = z - &self.y * &lambda;
        low.tr_solve_lower_triangular_mut(&mut x);
        if !(x.iter().chain(lambda.iter()).all(|v| v.is_finite())) {
            return Err(DynamicsError::Overflow { what: "KKT solution (x, λ)" });
        }
        Ok(KktSolution { x, lambda })
    }
}

/// Solves [[M, Gᵀ], [G, 0]] [x; λ] = [f; γ] in one call ([`KktFactor`] once).
///
/// For the equations of motion, f = Q − Cq̇ − … (the unconstrained right-hand side) and γ
/// the right side of the acceleration constraint G q̈ = γ; then x = q̈ and −Gᵀλ is the
/// generalized constraint force (for a pendulum written as a particle with
/// φ = |r| − l, λ is the tension).
///
/// Book: §9.11.
///
/// # Errors
/// As [`KktFactor::new`] and [`KktFactor::solve`].
pub fn solve_kkt(
    mass: &DMatrix<f64>,
    jacobian: &DMatrix<f64>,
    forcing: &DVector<f64>,
    gamma: &DVector<f64>,
    rank_tol: f64,
) -> Result<KktSolution, DynamicsError> {
    KktFactor::new(mass, jacobian, rank_tol)?.solve(forcing, gamma)
}

/// Row-by-row rank check of Y = L⁻¹Gᵀ from its QR: the first singular or dependent row is
/// an error.
fn check_rank(y: &DMatrix<f64>, qr: &QR<f64, Dyn, Dyn>, tol: f64) -> Result<(), DynamicsError> {
    let (n, m) = y.shape();
    let norms: Vec<f64> = (0..m).map(|k| y.column(k).norm()).collect();
    let scale = norms.iter().copied().fold(0.0, f64::max);
    let r = qr.r();
    for k in 0..m {
        // a row with no gradient at all (relative to the other rows, or exactly)
        if norms[k] == 0.0 || norms[k] <= tol * scale {
            return Err(DynamicsError::SingularConstraint { row: k, norm: norms[k], scale });
        }
        // beyond n rows nothing is left to span: the residual is zero
        let residual = if k < n { r[(k, k)].abs() / norms[k] } else { 0.0 };
        if residual <= tol {
            return Err(DynamicsError::DependentConstraint {
                row: k,
                depends_on: combination(&r, &norms, k.min(n), k),
                residual,
                tol,
            });
        }
    }
    Ok(())
}

/// The earlier rows that row k is made of: c = R[..p, ..p]⁻¹ R[..p, k] with p = min(k, n)
/// gives yₖ ≈ Σ cᵢ yᵢ; rows whose share |cᵢ|‖yᵢ‖ exceeds √ε‖yₖ‖ are listed.
fn combination(r: &DMatrix<f64>, norms: &[f64], p: usize, k: usize) -> Vec<usize> {
    let head = r.view((0, 0), (p, p)).into_owned();
    let mut c = r.view((0, k), (p, 1)).into_owned();
    if !head.solve_upper_triangular_mut(&mut c) {
        return (0..p).collect();
    }
    (0..p).filter(|&i| c[i].abs() * norms[i] > f64::EPSILON.sqrt() * norms[k]).collect()
}
