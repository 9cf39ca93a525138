//! The per-element kernels of `vectrix.Rotation`'s batch conversions that report errors or
//! gimbal locks: quaternions and matrices checked in the same pass that converts them, and
//! Euler angles written block by block with scipy's representative at gimbal lock.
//!
//! Book: §2.10 (rotation matrices), §2.13 (Facts 2.13.5, 2.13.8: gimbal lock), §2.15
//! (Euler parameters, (2.15.20)).

use nalgebra::Matrix3;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use vectrix_rotation::{
    EulerBatch, EulerSolution, Quaternion, ROTATION_TOL, check_rotation_matrix, nearest_rotation,
};

use crate::util::nonfinite;

/// The error for quaternion `k` of `d` (4 values each) that `normalize` refused: a non-finite
/// element, or a zero (or overflowing) norm.
pub(crate) fn quat_error(d: &[f64], k: usize) -> PyErr {
    match (4 * k..4 * k + 4).find(|&i| !d[i].is_finite()) {
        Some(i) => nonfinite("quat", i, d[i]),
        None => PyValueError::new_err(format!(
            "quat[{k}] has norm 0 (or overflows); valid: a nonzero finite quaternion"
        )),
    }
}

/// The canonical quaternion of matrix `k` (9 values `v`, row-major): a rotation matrix to
/// round-off is used as it is, others are projected to the nearest rotation (polar
/// decomposition, notes ch1-2a §3.10), as scipy does.
///
/// # Errors
/// A non-finite element (named by its flat index), a determinant ≤ 0 (no rotation).
#[inline]
pub(crate) fn matrix_quat(v: &[f64], k: usize) -> PyResult<Quaternion<f64>> {
    if let Some(i) = v.iter().position(|x| !x.is_finite()) {
        return Err(nonfinite("matrix", 9 * k + i, v[i]));
    }
    let m = Matrix3::from_row_slice(v);
    let det = m.determinant();
    if det.is_nan() || det <= 0.0 {
        return Err(PyValueError::new_err(format!(
            "matrix[{k}] has determinant {det:e}; valid: a rotation matrix (determinant > 0)"
        )));
    }
    let m = if check_rotation_matrix(&m, ROTATION_TOL).is_ok() {
        m
    } else {
        nearest_rotation(&m).map_err(|e| PyValueError::new_err(format!("matrix[{k}]: {e}")))?
    };
    Ok(Quaternion::from_rotation_matrix_unchecked(&m).canonical())
}

/// Rotations per block of [`Rotation::as_euler`]: the batch's angle buffer (24 bytes each)
/// stays in the L2 cache.
pub(crate) const EULER_BLOCK: usize = 2048;

/// Writes the angles of `batch` (rotations `first`, …) times `f` into `out` (3 per rotation),
/// with scipy's representative at gimbal lock, and appends the locked indices to `locks`.
pub(crate) fn euler_block(batch: &EulerBatch, first: usize, f: f64, out: &mut [f64], locks: &mut Vec<usize>) {
    for (o, a) in out.chunks_exact_mut(3).zip(batch.angles()) {
        o.copy_from_slice(&[a[0] * f, a[1] * f, a[2] * f]);
    }
    for (k, sol) in batch.gimbal_locks() {
        // scipy's choice for both kinds: the angle applied last is 0, so the first is the
        // determined combination α + sign·γ (F2.13.5, F2.13.8)
        if let EulerSolution::GimbalLock { middle, combination, .. } = sol {
            out[3 * k..3 * k + 3].copy_from_slice(&[combination * f, middle * f, 0.0]);
        }
        locks.push(first + k);
    }
}
