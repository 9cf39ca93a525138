//! The rest of `vectrix.Rotation`: Davenport angles about any three axes, the mean rotation
//! and the best rotation between two sets of vectors (Wahba's problem).
//!
//! Book: §2.12 (rotations about given axes), F2.15.7 (composition); Markley et al. 2007
//! (quaternion averaging); Kabsch 1976 / Markley 1988 (SVD solution of Wahba's problem).

use nalgebra::{Matrix3, Matrix4, SymmetricEigen, Vector3};
use numpy::PyArrayDyn;
use pyo3::exceptions::{PyIndexError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PySlice;
use vectrix_rotation::{Quaternion, nearest_rotation};

use crate::rotation::{GimbalLockError, GimbalLockWarning, Rotation, about, out};
use crate::util::{nogil, real, rows, vector};

/// Three axes (3, 3) for Davenport angles: unit after normalisation, the middle one
/// perpendicular to both others (within 1e-7, scipy's tolerance).
fn davenport_axes(py: Python<'_>, axes: &Bound<'_, PyAny>) -> PyResult<[Vector3<f64>; 3]> {
    let r = real(py, axes, "axes")?;
    if r.shape != [3, 3] {
        return Err(PyValueError::new_err(format!(
            "axes: shape {}; valid: (3, 3), one axis per row",
            crate::util::shape_str(&r.shape)
        )));
    }
    let d = r.data()?;
    let mut n = [Vector3::zeros(); 3];
    for (k, a) in n.iter_mut().enumerate() {
        let v = Vector3::new(d[3 * k], d[3 * k + 1], d[3 * k + 2]);
        let len = v.norm();
        if !(len > 0.0 && len.is_finite()) {
            return Err(PyValueError::new_err(format!(
                "axes[{k}] has norm {len}; valid: a nonzero finite vector"
            )));
        }
        *a = v / len;
    }
    for (i, j) in [(0, 1), (1, 2)] {
        if n[i].dot(&n[j]).abs() > 1e-7 {
            return Err(PyValueError::new_err(format!(
                "axes[{i}]·axes[{j}] = {:e}; valid: the middle axis perpendicular to the first and the last",
                n[i].dot(&n[j])
            )));
        }
    }
    Ok(n)
}

fn extrinsic(order: &str) -> PyResult<bool> {
    match order {
        "e" | "extrinsic" => Ok(true),
        "i" | "intrinsic" => Ok(false),
        _ => Err(PyValueError::new_err(format!(
            "order = {order:?}; valid: 'e'/'extrinsic' or 'i'/'intrinsic'"
        ))),
    }
}

fn wrap(x: f64) -> f64 {
    use std::f64::consts::PI;
    if x < -PI {
        x + 2.0 * PI
    } else if x > PI {
        x - 2.0 * PI
    } else {
        x
    }
}

/// Angles about n1, n2, n3 of q, by the direct method of Bernardes & Viollet (2022, PLoS ONE
/// 17(11) e0276302), the one scipy uses; returns the angles in the order applied and whether
/// the element is at gimbal lock (β within 1e-7 of its limits).
fn davenport_angles(q: &Quaternion<f64>, n: &[Vector3<f64>; 3], extrinsic: bool) -> ([f64; 3], bool) {
    let (mut n1, mut n2, mut n3) = (n[0], n[1], n[2]);
    if !extrinsic {
        std::mem::swap(&mut n1, &mut n3);
    }
    let mut n_cross = n1.cross(&n2);
    let mut lamb = n3.dot(&n_cross).atan2(n3.dot(&n1));
    let flip = lamb < 0.0;
    if flip {
        n2 = -n2;
        lamb = -lamb;
        n_cross = -n_cross;
    }
    let t = about(&n2, lamb) * *q;
    let (a, b, c, d) = (t.a, t.epsilon().dot(&n1), t.epsilon().dot(&n2), t.epsilon().dot(&n_cross));
    let (first, third) = if extrinsic { (0, 2) } else { (2, 0) };
    let mut ang = [0.0; 3];
    ang[1] = 2.0 * c.hypot(d).atan2(a.hypot(b));
    let case1 = ang[1].abs() <= 1e-7;
    let case2 = (ang[1] - std::f64::consts::PI).abs() <= 1e-7;
    let (half_sum, half_diff) = (b.atan2(a), d.atan2(c));
    if !(case1 || case2) {
        ang[first] = half_sum - half_diff;
        ang[third] = half_sum + half_diff;
    } else if case1 {
        ang[first] = 2.0 * half_sum;
    } else {
        ang[first] = 2.0 * half_diff * if extrinsic { -1.0 } else { 1.0 };
    }
    ang[1] -= lamb;
    if flip {
        ang[1] = -ang[1];
    }
    (ang.map(wrap), case1 || case2)
}

#[pymethods]
impl Rotation {
    /// From Davenport angles about three axes (rows of `axes`, the middle one perpendicular to
    /// the others), `order` 'e'/'extrinsic' or 'i'/'intrinsic', `angles` (3,) or (N, 3) in the
    /// order applied. Book: §2.12 (composition of rotations about given axes), F2.15.7.
    #[staticmethod]
    #[pyo3(signature = (axes, order, angles, degrees = false))]
    fn from_davenport(
        py: Python<'_>,
        axes: &Bound<'_, PyAny>,
        order: &str,
        angles: &Bound<'_, PyAny>,
        degrees: bool,
    ) -> PyResult<Self> {
        let n = davenport_axes(py, axes)?;
        let ext = extrinsic(order)?;
        let (r, _, single) = rows(py, angles, "angles", 3)?;
        let d = r.data()?;
        let f = if degrees { std::f64::consts::PI / 180.0 } else { 1.0 };
        let q = nogil(py, "from_davenport", || {
            Ok(d.chunks(3)
                .map(|a| {
                    let [q1, q2, q3] = [0, 1, 2].map(|k| about(&n[k], a[k] * f));
                    if ext { q3 * q2 * q1 } else { q1 * q2 * q3 }.canonical()
                })
                .collect())
        })?;
        Ok(Self::new(q, single))
    }

    /// Davenport angles (N, 3) about `axes` (as `from_davenport`); at gimbal lock the third
    /// angle is set to 0 and `gimbal_lock` ('warn', 'raise', 'ignore') says what else happens,
    /// as for `as_euler`. Book: §2.13 (extraction), Bernardes & Viollet 2022.
    #[pyo3(signature = (axes, order, degrees = false, gimbal_lock = "warn"))]
    fn as_davenport<'py>(
        &self,
        py: Python<'py>,
        axes: &Bound<'_, PyAny>,
        order: &str,
        degrees: bool,
        gimbal_lock: &str,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let n = davenport_axes(py, axes)?;
        let ext = extrinsic(order)?;
        if !matches!(gimbal_lock, "warn" | "raise" | "ignore") {
            return Err(PyValueError::new_err(format!(
                "gimbal_lock = {gimbal_lock:?}; valid: 'warn', 'raise', 'ignore'"
            )));
        }
        let q = &self.q;
        let (v, locks) = nogil(py, "as_davenport", || {
            let f = if degrees { 180.0 / std::f64::consts::PI } else { 1.0 };
            let mut v = Vec::with_capacity(3 * q.len());
            let mut locks = Vec::new();
            for (k, q) in q.iter().enumerate() {
                let (a, lock) = davenport_angles(q, &n, ext);
                if lock {
                    locks.push(k);
                }
                v.extend(a.map(|x| x * f));
            }
            Ok((v, locks))
        })?;
        if !locks.is_empty() {
            let msg = format!(
                "gimbal lock at {} of {} rotations (first: {}); third angle set to 0",
                locks.len(),
                q.len(),
                locks[0]
            );
            match gimbal_lock {
                "raise" => {
                    let e = GimbalLockError::new_err(msg);
                    e.value(py).setattr("indices", locks)?;
                    return Err(e);
                }
                "warn" => {
                    PyErr::warn(py, &py.get_type::<GimbalLockWarning>(), &std::ffi::CString::new(msg)?, 1)?
                }
                _ => {}
            }
        }
        out(py, v, q.len(), self.single, &[3])
    }

    /// The mean rotation: the unit q maximising Σ wᵢ(q·qᵢ)², the eigenvector of the largest
    /// eigenvalue of Σ wᵢ qᵢqᵢᵀ (Markley et al. 2007, the chordal L2 mean scipy computes).
    /// `weights` (N,) non-negative, not all zero. Book: §2.15 (Euler parameters).
    #[pyo3(signature = (weights = None))]
    fn mean(&self, py: Python<'_>, weights: Option<Bound<'_, PyAny>>) -> PyResult<Self> {
        let n = self.q.len();
        let w = match weights {
            Some(w) => vector(py, &w, "weights", Some(n))?,
            None => vec![1.0; n],
        };
        if let Some(k) = w.iter().position(|x| *x < 0.0) {
            return Err(PyValueError::new_err(format!("weights[{k}] = {}; valid: weights ≥ 0", w[k])));
        }
        if w.iter().sum::<f64>() <= 0.0 || n == 0 {
            return Err(PyValueError::new_err(
                "weights: all zero (or no rotations); valid: a positive total weight",
            ));
        }
        let q = &self.q;
        let m = nogil(py, "mean", || {
            let mut k = Matrix4::zeros();
            for (q, w) in q.iter().zip(&w) {
                let v = q.to_vector4();
                k += v * v.transpose() * *w;
            }
            let e = SymmetricEigen::new(k);
            let i = e.eigenvalues.imax();
            let v = e.eigenvectors.column(i);
            Ok(Quaternion::new(v[0], v[1], v[2], v[3]).normalize().unwrap_or_default().canonical())
        })?;
        Ok(Self::new(vec![m], true))
    }

    /// The rotation C minimising Σ wᵢ|aᵢ − C bᵢ|² (Wahba's problem; scipy's `align_vectors`
    /// order: `a ≈ C.apply(b)`) and the root-sum-squared distance. One pair gives the smallest
    /// rotation taking b to a. Book: §2.10 (orthogonal matrices); Kabsch 1976, Markley 1988.
    #[staticmethod]
    #[pyo3(signature = (a, b, weights = None))]
    fn align_vectors(
        py: Python<'_>,
        a: &Bound<'_, PyAny>,
        b: &Bound<'_, PyAny>,
        weights: Option<Bound<'_, PyAny>>,
    ) -> PyResult<(Self, f64)> {
        let (ra, na, _) = rows(py, a, "a", 3)?;
        let (rb, nb, _) = rows(py, b, "b", 3)?;
        let (da, db) = (ra.data()?, rb.data()?);
        if na != nb {
            return Err(PyValueError::new_err(format!(
                "a has {na} vectors and b {nb}; valid: the same number"
            )));
        }
        let w = match weights {
            Some(w) => vector(py, &w, "weights", Some(na))?,
            None => vec![1.0; na],
        };
        if w.iter().any(|x| *x < 0.0) {
            return Err(PyValueError::new_err("weights: valid: all ≥ 0"));
        }
        let va: Vec<Vector3<f64>> = da.chunks(3).map(|v| Vector3::new(v[0], v[1], v[2])).collect();
        let vb: Vec<Vector3<f64>> = db.chunks(3).map(|v| Vector3::new(v[0], v[1], v[2])).collect();
        let c = if na == 1 {
            shortest(&va[0], &vb[0])?
        } else {
            let mut bm = Matrix3::zeros();
            for ((x, y), w) in va.iter().zip(&vb).zip(&w) {
                bm += x * y.transpose() * *w;
            }
            if bm.iter().all(|x| *x == 0.0) {
                return Err(PyValueError::new_err(
                    "a, b: no weighted pair of nonzero vectors; valid: at least one",
                ));
            }
            nearest_rotation(&bm).map_err(|e| PyValueError::new_err(format!("align_vectors: {e}")))?
        };
        let rssd =
            va.iter().zip(&vb).zip(&w).map(|((x, y), w)| w * (x - c * y).norm_squared()).sum::<f64>().sqrt();
        Ok((Self::new(vec![Quaternion::from_rotation_matrix_unchecked(&c).canonical()], true), rssd))
    }
}

/// Python protocol and internal helpers (len, indexing, repr, stacking).
#[pymethods]
impl Rotation {
    /// Number of rotations (a single rotation has none, like scipy: TypeError).
    fn __len__(&self) -> PyResult<usize> {
        if self.single {
            return Err(PyTypeError::new_err("a single rotation has no len(); valid: a stack of rotations"));
        }
        Ok(self.q.len())
    }

    /// Element or slice (numpy-style integer, slice, or integer array).
    fn __getitem__(&self, py: Python<'_>, key: &Bound<'_, PyAny>) -> PyResult<Self> {
        if self.single {
            return Err(PyTypeError::new_err("a single rotation is not subscriptable"));
        }
        let n = self.q.len() as isize;
        if let Ok(k) = key.extract::<isize>() {
            let i = if k < 0 { k + n } else { k };
            if !(0..n).contains(&i) {
                return Err(PyIndexError::new_err(format!("index {k}; valid: -{n} ≤ k < {n}")));
            }
            return Ok(Self::new(vec![self.q[i as usize]], true));
        }
        if let Ok(s) = key.downcast::<PySlice>() {
            let ind = s.indices(n)?;
            let mut v = Vec::new();
            let mut i = ind.start;
            while (ind.step > 0 && i < ind.stop) || (ind.step < 0 && i > ind.stop) {
                v.push(self.q[i as usize]);
                i += ind.step;
            }
            return Ok(Self::new(v, false));
        }
        let idx = real(py, key, "index")?;
        let mut v = Vec::with_capacity(idx.len());
        for &x in idx.data()? {
            let i = if x < 0.0 { x + n as f64 } else { x };
            if i.fract() != 0.0 || !(0.0..n as f64).contains(&i) {
                return Err(PyIndexError::new_err(format!("index {x}; valid: integers -{n} ≤ k < {n}")));
            }
            v.push(self.q[i as usize]);
        }
        Ok(Self::new(v, false))
    }

    /// Whether this is one rotation (not a stack).
    #[getter]
    fn single(&self) -> bool {
        self.single
    }

    fn __repr__(&self) -> String {
        if self.single {
            let q = self.q[0];
            format!("Rotation.from_quat([{}, {}, {}, {}])", q.b, q.c, q.d, q.a)
        } else {
            format!("<vectrix.Rotation: {} rotations>", self.q.len())
        }
    }

    /// Internal: the stack of rotations `rotations` joined (used by `Rotation.concatenate`).
    #[staticmethod]
    fn _concat(rotations: Vec<Rotation>) -> Self {
        Self::new(rotations.iter().flat_map(|r| r.q.iter().copied()).collect(), false)
    }

    /// Internal: the same rotations as a stack (single → N = 1) or, when `single`, unstacked.
    fn _as_single(&self, single: bool) -> PyResult<Self> {
        if single && self.q.len() != 1 {
            return Err(PyValueError::new_err("only a stack of one rotation can be single"));
        }
        Ok(Self::new(self.q.clone(), single))
    }
}

/// The smallest rotation taking the direction of b to that of a (a half turn about an axis
/// perpendicular to b when they are opposite).
fn shortest(a: &Vector3<f64>, b: &Vector3<f64>) -> PyResult<Matrix3<f64>> {
    let (na, nb) = (a.norm(), b.norm());
    if na == 0.0 || nb == 0.0 {
        return Err(PyValueError::new_err("a, b: a zero vector has no direction; valid: nonzero vectors"));
    }
    let (x, y) = (a / na, b / nb);
    let axis = y.cross(&x);
    let s = axis.norm();
    let c = y.dot(&x);
    let q = if s > 1e-300 {
        about(&(axis / s), s.atan2(c))
    } else if c > 0.0 {
        Quaternion::identity()
    } else {
        let k = y.iamin();
        let mut e = Vector3::zeros();
        e[k] = 1.0;
        let p = y.cross(&e).normalize();
        about(&p, std::f64::consts::PI)
    };
    Ok(q.rotation_matrix())
}
