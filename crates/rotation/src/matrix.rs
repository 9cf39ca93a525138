//! Checks and projections for resolved rotation matrices 𝓡 (book §2.10, notes §3.10).

use nalgebra::Matrix3;
use vectrix_tensor::Scalar;

use crate::RotationError;
use crate::series::all_finite;

/// Default orthonormality tolerance for checked constructors: 128·ε on ‖MᵀM − I‖_max, as Drake
/// uses (DESIGN §5). Same value as `vectrix_frames::ORTHONORMAL_TOL`.
pub const ROTATION_TOL: f64 = 128.0 * f64::EPSILON;

/// Checks that `m` is a proper rotation matrix: finite, ‖MᵀM − I‖_max ≤ `tol`, det > 0.
///
/// Book: (2.10.5–9), Fact 2.10.9 (det 𝓞 = 1).
///
/// # Errors
/// [`RotationError::NonFinite`], [`RotationError::NotOrthonormal`] (with the defect found),
/// [`RotationError::Reflection`] for det < 0.
pub fn check_rotation_matrix<T: Scalar>(m: &Matrix3<T>, tol: f64) -> Result<(), RotationError> {
    vectrix_tensor::check_tolerance(tol, "tol")?;
    // ‖MᵀM − I‖_max; a NaN or ∞ entry makes it non-finite, reported as such.
    let g = m.tr_mul(m) - Matrix3::identity();
    let defect = g.iter().fold(0.0f64, |d, x| d.max(x.re().abs()));
    if !defect.is_finite() || g.iter().any(|x| x.re().is_nan()) {
        return Err(RotationError::NonFinite { what: "rotation matrix" });
    }
    if defect > tol {
        return Err(RotationError::NotOrthonormal { defect, tol });
    }
    let det = m.determinant().re();
    if det < 0.0 {
        return Err(RotationError::Reflection { det });
    }
    Ok(())
}

/// The rotation nearest to `m` in the Frobenius norm: the orthogonal polar factor U Vᵀ of
/// the SVD M = U Σ Vᵀ, with the last singular direction flipped when det(U Vᵀ) < 0 so the
/// result is proper. This is the explicit projection for noisy input; no checked constructor
/// ever applies it silently.
///
/// Book: §2.10 (orthogonality), notes ch1-2a §3.10 (renormalisation by polar decomposition).
///
/// # Errors
/// [`RotationError::NonFinite`]; [`RotationError::Zero`] for the zero matrix.
#[doc(alias = "polar_decomposition")]
#[doc(alias = "orthonormalize")]
pub fn nearest_rotation<T: Scalar>(m: &Matrix3<T>) -> Result<Matrix3<T>, RotationError> {
    if !all_finite(m.iter().copied()) {
        return Err(RotationError::NonFinite { what: "matrix" });
    }
    if m.iter().all(|x| *x == T::zero()) {
        return Err(RotationError::Zero { what: "matrix" });
    }
    // The polar factor of M is that of M/max|M_ij|: scaling first keeps the SVD finite for
    // entries near f64::MAX or subnormal.
    let scale = m.iter().fold(T::zero(), |a, x| a.max(x.abs()));
    let svd = (m / scale).svd(true, true);
    let (Some(u), Some(v_t)) = (svd.u, svd.v_t) else {
        return Err(RotationError::NonFinite { what: "SVD of the matrix" });
    };
    let mut u = u;
    // det(U Vᵀ) = −1: flip the column of U belonging to the smallest singular value.
    if (u * v_t).determinant() < T::zero() {
        let (k, _) = svd
            .singular_values
            .iter()
            .enumerate()
            .fold((0, svd.singular_values[0]), |acc, (i, s)| if *s < acc.1 { (i, *s) } else { acc });
        let col = -u.column(k);
        u.set_column(k, &col);
    }
    let r = u * v_t;
    if !all_finite(r.iter().copied()) {
        return Err(RotationError::NonFinite { what: "SVD of the matrix" });
    }
    Ok(r)
}
