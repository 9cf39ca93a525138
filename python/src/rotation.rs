//! `vectrix.Rotation`: a batch of rotations with the commonly used subset of
//! `scipy.spatial.transform.Rotation`, on vectrix's Euler parameters (book §2.15–2.17).
//!
//! Stored as unit quaternions q = (η, ε) (scalar first, the book's order); `as_quat` returns
//! scipy's scalar-last order unless `scalar_first=True`. Deliberate differences from scipy are
//! listed in docs/python.md and on each method.
//!
//! Book: §2.9–2.17 (rotation matrices, Euler angles, angle vector, Euler parameters, Gibbs).

use nalgebra::Vector3;
use numpy::{IntoPyArray, PyArrayDyn, PyArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use vectrix_rotation::{EulerAngles, EulerKind, EulerSequence, Quaternion};

use crate::rotation_kernels::{EULER_BLOCK, euler_block, matrix_quat, quat_error};
use crate::util::{CHEAP, build, fill_out, nogil, real_unchecked, rows, rows_unchecked};

pyo3::create_exception!(
    _vectrix,
    GimbalLockError,
    pyo3::exceptions::PyValueError,
    "Euler angles asked at gimbal lock (book F2.13.5, F2.13.8): only a combination of the \
     first and last angle is determined. `.indices` lists the elements."
);
pyo3::create_exception!(
    _vectrix,
    GimbalLockWarning,
    pyo3::exceptions::PyUserWarning,
    "Euler angles returned at gimbal lock with the representative (combination, beta, 0)."
);

/// One or many rotations (book §2.9–2.17) as unit Euler parameters.
#[pyclass(module = "vectrix._vectrix", frozen)]
#[derive(Clone)]
pub struct Rotation {
    pub(crate) q: Vec<Quaternion<f64>>,
    pub(crate) single: bool,
}

/// A (N, …) or (…) numpy array from flat values.
pub(crate) fn out<'py>(
    py: Python<'py>,
    v: Vec<f64>,
    n: usize,
    single: bool,
    tail: &[usize],
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let mut shape: Vec<usize> = if single { vec![] } else { vec![n] };
    shape.extend_from_slice(tail);
    Ok(v.into_pyarray(py).reshape(shape)?.into_any().downcast_into::<PyArrayDyn<f64>>()?)
}

/// The Euler sequence of a scipy-style string: upper case intrinsic, lower case extrinsic.
pub(crate) fn sequence(seq: &str) -> PyResult<EulerSequence> {
    let bad = || {
        PyValueError::new_err(format!(
            "seq = {seq:?}; valid: three of x, y, z with unequal neighbours, all upper case (intrinsic, \
             'XYZ') or all lower case (extrinsic, 'xyz')"
        ))
    };
    let b = seq.as_bytes();
    if b.len() != 3 {
        return Err(bad());
    }
    let upper = b.iter().all(u8::is_ascii_uppercase);
    let lower = b.iter().all(u8::is_ascii_lowercase);
    if !(upper || lower) {
        return Err(bad());
    }
    let mut idx = [0usize; 3];
    for (k, c) in b.iter().enumerate() {
        idx[k] = match c.to_ascii_lowercase() {
            b'x' => 1,
            b'y' => 2,
            b'z' => 3,
            _ => return Err(bad()),
        };
    }
    let kind = if upper { EulerKind::Intrinsic } else { EulerKind::Extrinsic };
    EulerSequence::from_indices(idx, kind).map_err(|_| bad())
}

fn quat_from(v: &[f64]) -> Quaternion<f64> {
    Quaternion::new(v[0], v[1], v[2], v[3])
}

impl Rotation {
    pub(crate) fn new(q: Vec<Quaternion<f64>>, single: bool) -> Self {
        Self { q, single }
    }

    /// Values of every rotation, `width` each, written into a new numpy array in parallel
    /// without the GIL.
    fn map<'py>(
        &self,
        py: Python<'py>,
        what: &str,
        tail: &[usize],
        f: impl Fn(&Quaternion<f64>, &mut [f64]) + Sync,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let width: usize = tail.iter().product::<usize>().max(1);
        let q = &self.q;
        fill_out(py, what, q.len(), self.single, tail, CHEAP, |s, e, chunk| {
            for (k, o) in (s..e).zip(chunk.chunks_exact_mut(width)) {
                f(&q[k], o);
            }
        })
    }

    /// Pairs rotations of `self` and `other` with broadcasting of a single one.
    fn pair(&self, other: &Rotation) -> PyResult<(usize, bool)> {
        let (n, m) = (self.q.len(), other.q.len());
        if n != m && n != 1 && m != 1 {
            return Err(PyValueError::new_err(format!(
                "other: {m} rotations against {n}; valid: equal numbers, or one of them single"
            )));
        }
        Ok((n.max(m), self.single && other.single))
    }
}

#[pymethods]
impl Rotation {
    /// From quaternions (4,) or (N, 4), scalar last like scipy (`scalar_first=True` for the
    /// book's (η, ε)); normalised. A zero quaternion is a ValueError. Book: §2.15, (2.15.20).
    #[staticmethod]
    #[pyo3(signature = (quat, *, scalar_first = false))]
    fn from_quat(py: Python<'_>, quat: &Bound<'_, PyAny>, scalar_first: bool) -> PyResult<Self> {
        let (r, n, single) = rows_unchecked(py, quat, "quat", 4)?;
        let d = r.data()?;
        // one pass: normalise, and stop at the first quaternion that is zero or not finite
        let q = nogil(py, "from_quat", || {
            build(n, |k| {
                let v = &d[4 * k..4 * k + 4];
                let x = if scalar_first { quat_from(v) } else { Quaternion::new(v[3], v[0], v[1], v[2]) };
                x.normalize().ok_or(k)
            })
            .map_err(|k| quat_error(d, k))
        })?;
        Ok(Self::new(q, single))
    }

    /// Quaternions (N, 4), scalar last unless `scalar_first`; `canonical=True` gives the one
    /// with η ≥ 0 (book's canonical form). Book: §2.15.
    #[pyo3(signature = (canonical = false, *, scalar_first = false))]
    fn as_quat<'py>(
        &self,
        py: Python<'py>,
        canonical: bool,
        scalar_first: bool,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.map(py, "as_quat", &[4], |q, o| {
            let q = if canonical { q.canonical() } else { *q };
            let v = [q.a, q.b, q.c, q.d];
            if scalar_first {
                o.copy_from_slice(&v);
            } else {
                o.copy_from_slice(&[v[1], v[2], v[3], v[0]]);
            }
        })
    }

    /// From rotation matrices (3, 3) or (N, 3, 3). Matrices off orthogonality are projected to
    /// the nearest rotation (polar decomposition, notes ch1-2a §3.10), as scipy does; a
    /// determinant ≤ 0 is a ValueError (it is no rotation). Book: §2.10, F2.15.3.
    #[staticmethod]
    fn from_matrix(py: Python<'_>, matrix: &Bound<'_, PyAny>) -> PyResult<Self> {
        let r = real_unchecked(py, matrix, "matrix")?;
        let (n, single) = match r.shape.as_slice() {
            [3, 3] => (1, true),
            [n, 3, 3] => (*n, false),
            s => {
                return Err(PyValueError::new_err(format!(
                    "matrix: shape {}; valid: (3, 3) or (N, 3, 3)",
                    crate::util::shape_str(s)
                )));
            }
        };
        let d = r.data()?;
        // one pass over the input: check, project when needed, convert
        let q = nogil(py, "from_matrix", || build(n, |k| matrix_quat(&d[9 * k..9 * k + 9], k)))?;
        Ok(Self::new(q, single))
    }

    /// Rotation matrices 𝓡(q) (N, 3, 3) (active: x ↦ 𝓡x). Book: (2.15.14).
    fn as_matrix<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.map(py, "as_matrix", &[3, 3], |q, o| {
            // row-major out: nalgebra stores columns, so the transpose's storage is 𝓡's rows
            o.copy_from_slice(q.rotation_matrix().transpose().as_slice());
        })
    }

    /// From angle vectors Θ = θn̂ (3,) or (N, 3), radians unless `degrees`. Book: §2.14, (2.14.5).
    #[staticmethod]
    #[pyo3(signature = (rotvec, degrees = false))]
    fn from_rotvec(py: Python<'_>, rotvec: &Bound<'_, PyAny>, degrees: bool) -> PyResult<Self> {
        let (r, _, single) = rows(py, rotvec, "rotvec", 3)?;
        let d = r.data()?;
        let s = if degrees { std::f64::consts::PI / 180.0 } else { 1.0 };
        let q = nogil(py, "from_rotvec", || {
            build(d.len() / 3, |k| {
                Ok(Quaternion::from_angle_vector(&(Vector3::new(d[3 * k], d[3 * k + 1], d[3 * k + 2]) * s)))
            })
        })?;
        Ok(Self::new(q, single))
    }

    /// Angle vectors θn̂ with θ ∈ [0, π] (N, 3). Book: §2.14 (log map).
    #[pyo3(signature = (degrees = false))]
    fn as_rotvec<'py>(&self, py: Python<'py>, degrees: bool) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let s = if degrees { 180.0 / std::f64::consts::PI } else { 1.0 };
        self.map(py, "as_rotvec", &[3], |q, o| {
            let v = q.angle_vector() * s;
            o.copy_from_slice(v.as_slice());
        })
    }

    /// From modified Rodrigues parameters p = tan(θ/4) n̂ (3,) or (N, 3). Book: extends §2.17.
    #[staticmethod]
    fn from_mrp(py: Python<'_>, mrp: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (r, _, single) = rows(py, mrp, "mrp", 3)?;
        let d = r.data()?;
        let q = nogil(py, "from_mrp", || {
            Ok(d.chunks(3).map(|v| Quaternion::from_mrp(&Vector3::new(v[0], v[1], v[2]))).collect())
        })?;
        Ok(Self::new(q, single))
    }

    /// Modified Rodrigues parameters with |p| ≤ 1 (N, 3). Book: extends §2.17.
    fn as_mrp<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.map(py, "as_mrp", &[3], |q, o| o.copy_from_slice(q.mrp().as_slice()))
    }

    /// From Gibbs vectors g = tan(θ/2) n̂ (3,) or (N, 3) (vectrix extra). Book: §2.17, (2.17.1).
    #[staticmethod]
    fn from_gibbs(py: Python<'_>, gibbs: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (r, _, single) = rows(py, gibbs, "gibbs", 3)?;
        let d = r.data()?;
        let q = nogil(py, "from_gibbs", || {
            Ok(d.chunks(3).map(|v| Quaternion::from_gibbs(&Vector3::new(v[0], v[1], v[2]))).collect())
        })?;
        Ok(Self::new(q, single))
    }

    /// Gibbs vectors (N, 3) (vectrix extra); a half turn has none (|g| = ∞): ValueError naming
    /// the element. Book: §2.17.
    fn as_gibbs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        if let Some(k) = self.q.iter().position(|q| q.try_gibbs().is_err()) {
            return Err(PyValueError::new_err(format!(
                "rotation {k} is a half turn (η = 0): its Gibbs vector tan(θ/2)n̂ is infinite; valid: angles below π"
            )));
        }
        self.map(py, "as_gibbs", &[3], |q, o| o.copy_from_slice(q.try_gibbs().unwrap_or_default().as_slice()))
    }

    /// From Euler angles: `seq` upper case intrinsic ('ZYX'), lower case extrinsic ('xyz'), as
    /// scipy; `angles` (3,) or (N, 3) in the order applied. Book: §2.12, (2.12.32–40).
    #[staticmethod]
    #[pyo3(signature = (seq, angles, degrees = false))]
    fn from_euler(py: Python<'_>, seq: &str, angles: &Bound<'_, PyAny>, degrees: bool) -> PyResult<Self> {
        let s = sequence(seq)?;
        let (r, _, single) = rows(py, angles, "angles", 3)?;
        let d = r.data()?;
        let f = if degrees { std::f64::consts::PI / 180.0 } else { 1.0 };
        let q = nogil(py, "from_euler", || {
            build(d.len() / 3, |k| {
                Ok(EulerAngles::new(s, [d[3 * k] * f, d[3 * k + 1] * f, d[3 * k + 2] * f]).quaternion())
            })
        })?;
        Ok(Self::new(q, single))
    }

    /// Euler angles (N, 3) of `seq` (as `from_euler`). At gimbal lock (F2.13.5, F2.13.8) the
    /// representative (combination, β, 0) in the order applied; `gimbal_lock` says what else
    /// happens: "warn" (a `GimbalLockWarning` naming the elements, scipy's behaviour with a
    /// typed warning), "raise" (`GimbalLockError` with `.indices`), or "ignore".
    /// Book: §2.13, Facts 2.13.3–8.
    #[pyo3(signature = (seq, degrees = false, gimbal_lock = "warn"))]
    fn as_euler<'py>(
        &self,
        py: Python<'py>,
        seq: &str,
        degrees: bool,
        gimbal_lock: &str,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let s = sequence(seq)?;
        if !matches!(gimbal_lock, "warn" | "raise" | "ignore") {
            return Err(PyValueError::new_err(format!(
                "gimbal_lock = {gimbal_lock:?}; valid: 'warn', 'raise', 'ignore'"
            )));
        }
        let f = if degrees { 180.0 / std::f64::consts::PI } else { 1.0 };
        let q = &self.q;
        // (first error, gimbal-locked indices) gathered from the threads
        let found = std::sync::Mutex::new((None::<(usize, String)>, Vec::<usize>::new()));
        let arr = fill_out(py, "as_euler", q.len(), self.single, &[3], CHEAP, |s0, e0, chunk| {
            let mut locks = Vec::new();
            let mut err = None;
            // blocks small enough that the batch's own angle buffer stays in cache
            for (b, out) in (s0..e0).step_by(EULER_BLOCK).zip(chunk.chunks_mut(3 * EULER_BLOCK)) {
                let e = (b + EULER_BLOCK).min(e0);
                match EulerAngles::from_quaternions(&q[b..e], s) {
                    Ok(batch) => euler_block(&batch, b, f, out, &mut locks),
                    Err(x) => {
                        err = Some((b, x.to_string()));
                        break;
                    }
                }
            }
            if let Ok(mut g) = found.lock() {
                if let Some((b, x)) = err
                    && g.0.as_ref().is_none_or(|(j, _)| b < *j)
                {
                    g.0 = Some((b, x));
                }
                g.1.extend(locks);
            }
        })?;
        let (err, mut locks) = found.into_inner().unwrap_or_default();
        if let Some((_, e)) = err {
            return Err(PyValueError::new_err(format!("rotation: {e}")));
        }
        locks.sort_unstable();
        if !locks.is_empty() {
            let msg = format!(
                "gimbal lock at {} of {} rotations (first: {}) for {seq}: only a combination of the first and last \
                 angle is determined; returned (combination, beta, 0)",
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
        Ok(arr)
    }

    /// The gimbal-locked elements for `seq`: a list of (index, beta, combination, sign) where
    /// the first and last angle satisfy α + sign·γ = combination (vectrix extra). Book: F2.13.5.
    fn gimbal_locks(&self, py: Python<'_>, seq: &str) -> PyResult<Vec<(usize, f64, f64, i8)>> {
        let s = sequence(seq)?;
        let q = &self.q;
        let batch = nogil(py, "gimbal_locks", || {
            EulerAngles::from_quaternions(q, s).map_err(|e| PyValueError::new_err(format!("rotation: {e}")))
        })?;
        Ok(batch
            .gimbal_locks()
            .iter()
            .filter_map(|(k, sol)| match sol {
                vectrix_rotation::EulerSolution::GimbalLock { middle, combination, sign, .. } => {
                    Some((*k, *middle, *combination, *sign))
                }
                _ => None,
            })
            .collect())
    }

    /// Rotates vectors (3,) or (N, 3): 𝓡(q)x (or 𝓡ᵀx with `inverse`), one rotation against
    /// many vectors and many against one broadcast. Book: Prob 2.26.23.
    #[pyo3(signature = (vectors, inverse = false))]
    fn apply<'py>(
        &self,
        py: Python<'py>,
        vectors: &Bound<'_, PyAny>,
        inverse: bool,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (r, m, vsingle) = rows(py, vectors, "vectors", 3)?;
        let d = r.data()?;
        let n = self.q.len();
        if n != m && n != 1 && m != 1 {
            return Err(PyValueError::new_err(format!(
                "vectors: {m} vectors for {n} rotations; valid: equal numbers, or one of them single"
            )));
        }
        let count = n.max(m);
        let q = &self.q;
        fill_out(py, "apply", count, self.single && vsingle, &[3], CHEAP, |s, e, chunk| {
            for (k, o) in (s..e).zip(chunk.chunks_exact_mut(3)) {
                let r = q[if n == 1 { 0 } else { k }];
                let r = if inverse { r.conjugate() } else { r };
                let x = &d[3 * if m == 1 { 0 } else { k }..];
                let y = r.rotate(&Vector3::new(x[0], x[1], x[2]));
                o.copy_from_slice(y.as_slice());
            }
        })
    }

    /// Composition `self * other`: apply `other` first, then `self` (scipy's order), q₁ ⊗ q₂.
    /// Book: F2.15.7 (corrected order), §2.16.
    fn __mul__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Self> {
        let other = other
            .downcast::<Rotation>()
            .map_err(|_| PyTypeError::new_err("other: not a Rotation; valid: Rotation * Rotation"))?;
        let o = other.get();
        let (n, single) = self.pair(o)?;
        let (a, b) = (&self.q, &o.q);
        let q = nogil(py, "compose", || {
            build(n, |k| Ok(a[if a.len() == 1 { 0 } else { k }] * b[if b.len() == 1 { 0 } else { k }]))
        })?;
        Ok(Self::new(q, single))
    }

    /// The inverse rotations q̄. Book: Fact 2.15.6.
    fn inv(&self) -> Self {
        Self::new(self.q.iter().map(Quaternion::conjugate).collect(), self.single)
    }

    /// Rotation angles θ ∈ [0, π] (a float, or (N,)). Book: §2.14.
    fn magnitude<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.map(py, "magnitude", &[], |q, o| o[0] = 2.0 * q.epsilon().norm().atan2(q.a.abs()))
    }

    /// Spherical linear interpolation from `self` (t = 0) to `other` (t = 1) along the shorter
    /// arc, element by element (vectrix's `Quaternion::slerp`). Book: §2.14 (geodesic exp(tΘ)).
    fn slerp(&self, py: Python<'_>, other: &Rotation, t: f64) -> PyResult<Self> {
        if !t.is_finite() {
            return Err(PyValueError::new_err(format!("t = {t}; valid: a finite number")));
        }
        let (n, single) = self.pair(other)?;
        let (a, b) = (&self.q, &other.q);
        let q = nogil(py, "slerp", || {
            Ok((0..n)
                .map(|k| a[if a.len() == 1 { 0 } else { k }].slerp(&b[if b.len() == 1 { 0 } else { k }], t))
                .collect())
        })?;
        Ok(Self::new(q, single))
    }
}

/// The elementary quaternion about unit axis n by θ (book (2.15.4)).
pub(crate) fn about(n: &Vector3<f64>, theta: f64) -> Quaternion<f64> {
    let (s, c) = (0.5 * theta).sin_cos();
    Quaternion::from_parts(c, n * s)
}
