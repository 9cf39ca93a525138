//! The physical inertia matrix J⃗_{B/z} (book §6.2): particle sums, shifts between points,
//! components in a frame with the book's sign convention, and validation.
//!
//! # The sign trap
//! The book's *product of inertia* J_xy ≜ Σ m x̄ȳ is a positive sum (6.2.5–6.2.8), while the
//! entry of the resolved matrix J_{B/z|B} in row x, column y is **−J_xy**. Here
//! [`product_of_inertia`] and [`InertiaComponents::products`] return the book's J_xy;
//! `j.resolve(&frame)` returns the matrix, whose off-diagonal entries are −J_xy.

use nalgebra::Matrix3;
use vectrix_frames::{Frame, Resolve};
use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::StaticsError;
use crate::basis::mat_re;

/// Default relative tolerance for inertia checks and clustering of principal moments:
/// 1024·ε, scaled by the largest principal moment (or the trace).
///
/// Book: §6.2, (6.2.4)–(6.2.8), Facts 6.2.7–6.2.8.
pub const INERTIA_REL_TOL: f64 = 1024.0 * f64::EPSILON;

/// Inertia of a particle of mass m at y about z: m(|r⃗|²I⃗ − r⃗r⃗′) = −m r⃗^× r⃗^×, r⃗ = r⃗_{y/z}.
///
/// Book: §6.2, (6.2.1)–(6.2.3).
pub fn particle_inertia<T: Scalar>(m: T, r_y_z: &Vector<T>) -> Dyadic<T> {
    // (6.2.3): J = m(|r|² I − r r′)
    (Dyadic::identity() * r_y_z.norm_squared() - r_y_z.outer(r_y_z)) * m
}

/// Parallel-axis theorem: J⃗_{B/z} = J⃗_{B/c} + m_B(|r⃗|²I⃗ − r⃗r⃗′), r⃗ = r⃗_{z/c}.
///
/// Book: Fact 6.2.12, (6.2.26); hence J⃗_{B/z} ⪰ J⃗_{B/c} (6.2.27).
pub fn parallel_axis<T: Scalar>(j_c: &Dyadic<T>, m: T, r_z_c: &Vector<T>) -> Dyadic<T> {
    *j_c + particle_inertia(m, r_z_c)
}

/// General shift between two arbitrary points z₁, z₂ (neither need be the centre of mass):
/// J⃗_{B/z₂} = J⃗_{B/z₁} + m_B[a⃗^× b⃗^× + b⃗^× a⃗^× − a⃗^× a⃗^×], a⃗ = r⃗_{z₂/z₁}, b⃗ = r⃗_{c/z₁}.
///
/// Book: Fact 6.2.13, (6.2.29).
pub fn shift_inertia<T: Scalar>(
    j_z1: &Dyadic<T>,
    m: T,
    r_z2_z1: &Vector<T>,
    r_c_z1: &Vector<T>,
) -> Dyadic<T> {
    let a = r_z2_z1.cross_dyad();
    let b = r_c_z1.cross_dyad();
    // (6.2.29)
    *j_z1 + (a * b + b * a - a * a) * m
}

/// Moment of inertia about the axis n̂ through z: n̂′J⃗_{B/z}n̂ (the axis is normalised here).
/// `None` for a zero axis.
///
/// Book: §6.2, Problem 6.14.6.
pub fn moment_of_inertia<T: Scalar>(j: &Dyadic<T>, axis: &Vector<T>) -> Option<T> {
    let n = axis.unit()?;
    Some(n.dot(&j.apply(&n)))
}

/// The book's product of inertia J_ab ≜ Σ m (â·r⃗)(b̂·r⃗) for perpendicular axes â, b̂ (normalised
/// here): the **positive** sum, equal to **minus** the matrix entry −â′J⃗b̂ (6.2.5–6.2.8).
/// `None` for a zero axis.
///
/// Book: §6.2, (6.2.5)–(6.2.8).
#[doc(alias = "product_of_inertia_xy")]
pub fn product_of_inertia<T: Scalar>(j: &Dyadic<T>, a: &Vector<T>, b: &Vector<T>) -> Option<T> {
    let a = a.unit()?;
    let b = b.unit()?;
    Some(-a.dot(&j.apply(&b)))
}

/// Moments and products of inertia of J⃗_{B/z} determined by a frame F_B (book (6.2.4)–(6.2.8)).
///
/// Book: §6.2, (6.2.4)–(6.2.8), Facts 6.2.7–6.2.8.
///
/// # Conventions
/// `products` = [J_xy, J_xz, J_yz] are the book's **positive sums** Σ m x̄ȳ; the matrix
/// J_{B/z|B} has −J_xy in row 1, column 2. Use [`InertiaComponents::matrix`] for the matrix.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InertiaComponents<T: Scalar = f64> {
    /// [J_xx, J_yy, J_zz]: diagonal entries of J_{B/z|B}.
    pub moments: [T; 3],
    /// [J_xy, J_xz, J_yz]: the book's products of inertia (positive sums), = −(matrix entries).
    pub products: [T; 3],
}

impl<T: Scalar> InertiaComponents<T> {
    /// Components of `j` in the frame `b`.
    ///
    /// Book: (6.2.4)–(6.2.8).
    pub fn of(j: &Dyadic<T>, b: &Frame<T>) -> Self {
        let m = j.resolve(b);
        Self {
            moments: [m[(0, 0)], m[(1, 1)], m[(2, 2)]],
            // The sign trap: matrix entry (x, y) is −J_xy.
            products: [-m[(0, 1)], -m[(0, 2)], -m[(1, 2)]],
        }
    }

    /// The resolved inertia matrix J_{B/z|B}, with −J_xy off the diagonal (6.2.4).
    ///
    /// Book: §6.2, (6.2.4)–(6.2.8), Facts 6.2.7–6.2.8.
    pub fn matrix(&self) -> Matrix3<T> {
        let [jxx, jyy, jzz] = self.moments;
        let [jxy, jxz, jyz] = self.products;
        Matrix3::new(jxx, -jxy, -jxz, -jxy, jyy, -jyz, -jxz, -jyz, jzz)
    }

    /// The physical inertia dyadic whose components in `b` are these (book (2.10.22), (6.2.4)).
    ///
    /// Book: §6.2, (6.2.4)–(6.2.8), Facts 6.2.7–6.2.8.
    pub fn to_dyadic(&self, b: &Frame<T>) -> Dyadic<T> {
        b.dyadic(&self.matrix())
    }
}

/// Result of validating an inertia dyadic: principal moments and rank.
///
/// Book: §6.2, (6.2.4)–(6.2.8), Facts 6.2.7–6.2.8.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InertiaCheck {
    /// Principal moments λ1 ≥ λ2 ≥ λ3 (clamped at 0 when within tolerance of it).
    pub moments: [f64; 3],
    /// Rank: 0 (single particle at z), 2 (collinear with z), or 3 (Fact 6.2.7).
    pub rank: usize,
}

/// Eigenvalues of a symmetric 3×3 matrix, sorted λ1 ≥ λ2 ≥ λ3.
pub(crate) fn sorted_eigen(m: &Matrix3<f64>) -> ([f64; 3], Matrix3<f64>) {
    let eig = nalgebra::SymmetricEigen::new(*m);
    let mut idx = [0usize, 1, 2];
    idx.sort_by(|&a, &b| eig.eigenvalues[b].total_cmp(&eig.eigenvalues[a]));
    let lam = [eig.eigenvalues[idx[0]], eig.eigenvalues[idx[1]], eig.eigenvalues[idx[2]]];
    let vecs = Matrix3::from_columns(&[
        eig.eigenvectors.column(idx[0]).into_owned(),
        eig.eigenvectors.column(idx[1]).into_owned(),
        eig.eigenvectors.column(idx[2]).into_owned(),
    ]);
    (lam, vecs)
}

/// Validates a physical inertia dyadic: finite, symmetric, positive semidefinite
/// (Fact 6.2.7 i), rank ≠ 1 (Fact 6.2.7 iii) and λ1 ≤ λ2 + λ3 (6.2.19).
///
/// Book: Fact 6.2.7, Fact 6.2.8, (6.2.19).
///
/// # Conventions
/// `rel_tol` (use [`INERTIA_REL_TOL`]) is relative to the largest principal moment: moments
/// within rel_tol·λ1 of zero count as zero for the rank and are returned as 0.
///
/// # Errors
/// [`StaticsError::NonFinite`], [`StaticsError::NotSymmetric`],
/// [`StaticsError::NotPositiveSemidefinite`], [`StaticsError::RankOne`],
/// [`StaticsError::TriangleInequality`].
pub fn check_inertia<T: Scalar>(j: &Dyadic<T>, rel_tol: f64) -> Result<InertiaCheck, StaticsError> {
    analyse(j, rel_tol).map(|(check, _)| check)
}

/// [`check_inertia`] that also returns the eigenvectors (columns, working frame, sorted as the
/// moments), so that principal axes need one eigen-decomposition.
pub(crate) fn analyse<T: Scalar>(
    j: &Dyadic<T>,
    rel_tol: f64,
) -> Result<(InertiaCheck, Matrix3<f64>), StaticsError> {
    if !j.is_finite() {
        return Err(StaticsError::NonFinite { what: "inertia" });
    }
    vectrix_tensor::check_tolerance(rel_tol, "rel_tol")?;
    // Work on J/max|J_ij| (entries in [−1, 1]): the norms, the symmetric part and the
    // eigenvalues then neither overflow (J near f64::MAX) nor lose digits (subnormal J); the
    // moments are scaled back at the end. Every test below is relative, so unchanged.
    let m0 = mat_re(j);
    let unit = m0.amax();
    let unit = if unit == 0.0 { 1.0 } else { unit };
    let m = m0 / unit;
    let scale = m.norm();
    let asymmetry = (m - m.transpose()).norm();
    let sym_tol = rel_tol * scale;
    if asymmetry > sym_tol {
        return Err(StaticsError::NotSymmetric { asymmetry: asymmetry * unit, tol: sym_tol * unit });
    }
    let (mut lam, vecs) = sorted_eigen(&((m + m.transpose()) * 0.5));
    let tol = rel_tol * lam[0].abs().max(scale);
    if lam[2] < -tol {
        return Err(StaticsError::NotPositiveSemidefinite { min_moment: lam[2] * unit, tol: tol * unit });
    }
    // Moments within tolerance of zero are zero (e.g. the axial moment of a thin rod).
    for l in &mut lam {
        if l.abs() <= tol {
            *l = 0.0;
        }
    }
    let rank = lam.iter().filter(|&&l| l > 0.0).count();
    let moments = lam.map(|l| l * unit);
    if rank == 1 {
        return Err(StaticsError::RankOne { moments });
    }
    let excess = lam[0] - lam[1] - lam[2];
    if excess > tol {
        return Err(StaticsError::TriangleInequality { moments, excess: excess * unit });
    }
    if !moments.iter().all(|l| l.is_finite()) {
        return Err(StaticsError::Overflow { what: "principal moments of inertia" });
    }
    Ok((InertiaCheck { moments, rank }, vecs))
}
