//! `vectrix.Model`: a kinematic tree (book §7.11) with RNEA, ABA, CRBA and their exact
//! derivatives, one state or a batch (N, …) computed on all cores without the GIL.
//!
//! Book: §7.11, (7.11.13)–(7.11.22); RBDA Tables 5.1, 6.2, 7.1 (the algorithms' layout).

use nalgebra::{DMatrix, Matrix3, Vector3};
use numpy::{IntoPyArray, PyArrayDyn};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use vectrix_dynamics::{DynamicsError, Joint, Link, Model as RsModel};

use crate::util::{fill_out, rows};

/// A multibody model (book §7.11) in reduced coordinates q (nq), v (nv).
#[pyclass(module = "vectrix._vectrix", frozen)]
pub struct Model {
    pub(crate) m: RsModel,
}

fn dyn_err(what: &str, k: Option<usize>, e: DynamicsError) -> PyErr {
    let at = k.map_or(String::new(), |k| format!(" (state {k})"));
    PyValueError::new_err(format!("{what}{at}: {e}"))
}

fn vec3(d: &Bound<'_, PyDict>, key: &str, k: usize) -> PyResult<Vector3<f64>> {
    let v: Vec<f64> = item(d, key, k)?
        .extract()
        .map_err(|_| PyTypeError::new_err(format!("links[{k}].{key}: valid: 3 numbers")))?;
    if v.len() != 3 || !v.iter().all(|x| x.is_finite()) {
        return Err(PyValueError::new_err(format!("links[{k}].{key} = {v:?}; valid: 3 finite numbers")));
    }
    Ok(Vector3::new(v[0], v[1], v[2]))
}

fn item<'py>(d: &Bound<'py, PyDict>, key: &str, k: usize) -> PyResult<Bound<'py, PyAny>> {
    d.get_item(key)?.ok_or_else(|| PyValueError::new_err(format!("links[{k}]: no `{key}`")))
}

fn mat3(d: &Bound<'_, PyDict>, key: &str, k: usize) -> PyResult<Matrix3<f64>> {
    let rows: Vec<Vec<f64>> = item(d, key, k)?
        .extract()
        .map_err(|_| PyTypeError::new_err(format!("links[{k}].{key}: valid: a 3×3 nested list")))?;
    if rows.len() != 3 || rows.iter().any(|r| r.len() != 3 || !r.iter().all(|x| x.is_finite())) {
        return Err(PyValueError::new_err(format!("links[{k}].{key}: valid: 3×3 finite numbers")));
    }
    Ok(Matrix3::from_fn(|r, c| rows[r][c]))
}

fn link(d: &Bound<'_, PyDict>, k: usize) -> PyResult<Link> {
    let kind: String = item(d, "joint", k)?.extract()?;
    let joint = match kind.as_str() {
        "pin" => Joint::Pin { axis: vec3(d, "axis", k)? },
        "sleeve" => Joint::Sleeve { axis: vec3(d, "axis", k)? },
        "collar" => Joint::Collar { axis: vec3(d, "axis", k)? },
        "slot" => Joint::Slot { axis: vec3(d, "axis", k)?, direction: vec3(d, "direction", k)? },
        "ball" => Joint::Ball,
        "weld" => Joint::Weld,
        "free" => Joint::Free,
        other => {
            return Err(PyValueError::new_err(format!(
                "links[{k}].joint = {other:?}; valid: pin, sleeve, collar, slot, ball, weld, free (book Table 1.3)"
            )));
        }
    };
    let parent: Option<usize> = match d.get_item("parent")? {
        Some(p) if !p.is_none() => Some(p.extract().map_err(|_| {
            PyValueError::new_err(format!("links[{k}].parent: valid: None or an earlier link index"))
        })?),
        _ => None,
    };
    let mass: f64 = item(d, "mass", k)?.extract()?;
    let mut l =
        Link::new(parent, joint, vec3(d, "offset", k)?, mass, vec3(d, "com", k)?, mat3(d, "inertia", k)?);
    if d.get_item("orientation")?.is_some() {
        l.orientation = mat3(d, "orientation", k)?;
    }
    Ok(l)
}

/// Broadcast count of several batches (1 broadcasts).
fn count(ns: &[(usize, &str)]) -> PyResult<usize> {
    let n = ns.iter().map(|x| x.0).max().unwrap_or(1);
    if let Some((m, name)) = ns.iter().find(|(m, _)| *m != 1 && *m != n) {
        return Err(PyValueError::new_err(format!(
            "{name}: {m} states against {n}; valid: equal batch sizes, or one state"
        )));
    }
    Ok(n)
}

fn row(d: &[f64], n_of: usize, w: usize, k: usize) -> &[f64] {
    let k = if n_of == 1 { 0 } else { k };
    &d[k * w..(k + 1) * w]
}

/// States per batch below which one thread does all: a tree algorithm costs about a
/// microsecond per state, so 256 states (≈ 0.3 ms) pay for a thread's start.
const STATES_PER_THREAD: usize = 256;

impl Model {
    /// f(q_k, x_k, y_k) → `width` values, for every state of the batch, in parallel, each
    /// thread with its own work space from `scratch()`.
    #[allow(clippy::too_many_arguments)]
    fn batch3<'py, S>(
        &self,
        py: Python<'py>,
        what: &str,
        args: [(&Bound<'_, PyAny>, &str, usize); 3],
        tail: &[usize],
        scratch: impl Fn(&RsModel) -> S + Sync,
        f: impl Fn(&RsModel, &[f64], &[f64], &[f64], &mut [f64], &mut S) -> Result<(), DynamicsError> + Sync,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let [a, b, c] = args;
        let (ra, na, sa) = rows(py, a.0, a.1, a.2)?;
        let (rb, nb, sb) = rows(py, b.0, b.1, b.2)?;
        let (rc, nc, sc) = rows(py, c.0, c.1, c.2)?;
        let (da, db, dc) = (ra.data()?, rb.data()?, rc.data()?);
        let n = count(&[(na, a.1), (nb, b.1), (nc, c.1)])?;
        let width: usize = tail.iter().product::<usize>().max(1);
        let m = &self.m;
        let err = std::sync::Mutex::new(None::<(usize, DynamicsError)>);
        let arr = fill_out(py, what, n, sa && sb && sc, tail, STATES_PER_THREAD, |s, e, chunk| {
            let mut w = scratch(m);
            for (k, o) in (s..e).zip(chunk.chunks_exact_mut(width)) {
                if let Err(x) = f(m, row(da, na, a.2, k), row(db, nb, b.2, k), row(dc, nc, c.2, k), o, &mut w)
                {
                    // the first failing state of this thread; the smallest over the threads wins
                    if let Ok(mut g) = err.lock()
                        && g.as_ref().is_none_or(|(j, _)| k < *j)
                    {
                        *g = Some((k, x));
                    }
                    return;
                }
            }
        })?;
        if let Some((k, e)) = err.into_inner().ok().flatten() {
            return Err(dyn_err(what, (n > 1).then_some(k), e));
        }
        Ok(arr)
    }
}

fn put(o: &mut [f64], m: &DMatrix<f64>) {
    // row-major
    let (r, c) = m.shape();
    for i in 0..r {
        for j in 0..c {
            o[i * c + j] = m[(i, j)];
        }
    }
}

#[pymethods]
impl Model {
    /// A tree from a list of links, each a dict with `parent` (None = ground, else an earlier
    /// index), `joint` (pin, sleeve, collar, slot, ball, weld, free), `axis`/`direction` where
    /// the joint has them, `offset`, optional `orientation` (𝓞_{J/P}), `mass`, `com`,
    /// `inertia` (J about the centre, link frame): the layout of
    /// tests/data/multibody_reference.json. Book: §7.11, Table 1.3.
    #[staticmethod]
    #[pyo3(signature = (links, gravity = None))]
    fn from_links(
        py: Python<'_>,
        links: Vec<Bound<'_, PyDict>>,
        gravity: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let links: Vec<Link> = links.iter().enumerate().map(|(k, d)| link(d, k)).collect::<PyResult<_>>()?;
        let mut m = RsModel::new(&links).map_err(|e| dyn_err("links", None, e))?;
        if let Some(g) = gravity {
            let g = crate::util::vector(py, &g, "gravity", Some(3))?;
            m.gravity = Vector3::new(g[0], g[1], g[2]);
        }
        Ok(Self { m })
    }

    /// The benchmark chain: n pins about ẑ, rods of mass m and length l along x̂, zero
    /// gravity (`Model::revolute_chain`). Book: §7.11.
    #[staticmethod]
    fn revolute_chain(n: usize, m: f64, l: f64) -> PyResult<Self> {
        if !(m.is_finite() && m > 0.0 && l.is_finite() && l > 0.0) {
            return Err(PyValueError::new_err(format!("m = {m}, l = {l}; valid: finite numbers > 0")));
        }
        Ok(Self { m: RsModel::revolute_chain(n, m, l).map_err(|e| dyn_err("revolute_chain", None, e))? })
    }

    /// Number of configuration coordinates.
    #[getter]
    fn nq(&self) -> usize {
        self.m.nq()
    }

    /// Number of velocity coordinates.
    #[getter]
    fn nv(&self) -> usize {
        self.m.nv()
    }

    /// Gravity g resolved in the ground frame.
    #[getter]
    fn gravity(&self) -> [f64; 3] {
        [self.m.gravity.x, self.m.gravity.y, self.m.gravity.z]
    }

    /// The neutral configuration (zero angles, unit quaternions).
    fn neutral<'py>(&self, py: Python<'py>) -> Bound<'py, numpy::PyArray1<f64>> {
        self.m.neutral().into_pyarray(py)
    }

    /// Inverse dynamics τ = RNEA(q, v, v̇): (nv,) or (N, nv) for batches. Book: §7.11,
    /// (7.11.13)–(7.11.22).
    fn rnea<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'_, PyAny>,
        v: &Bound<'_, PyAny>,
        a: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (nq, nv) = (self.m.nq(), self.m.nv());
        self.batch3(
            py,
            "rnea",
            [(q, "q", nq), (v, "v", nv), (a, "a", nv)],
            &[nv],
            |_| (),
            |m, q, v, a, o, _| {
                o.copy_from_slice(&m.rnea(q, v, a, None)?.tau);
                Ok(())
            },
        )
    }

    /// Forward dynamics v̇ = ABA(q, v, τ): (nv,) or (N, nv). Book: §7.11; RBDA Table 7.1.
    fn aba<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'_, PyAny>,
        v: &Bound<'_, PyAny>,
        tau: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (nq, nv) = (self.m.nq(), self.m.nv());
        self.batch3(
            py,
            "aba",
            [(q, "q", nq), (v, "v", nv), (tau, "tau", nv)],
            &[nv],
            RsModel::aba_scratch,
            |m, q, v, t, o, w| m.aba_checked(q, v, t, None, o, w),
        )
    }

    /// Mass matrix M(q) = CRBA(q): (nv, nv) or (N, nv, nv). Book: §7.11; RBDA Table 6.2.
    fn crba<'py>(&self, py: Python<'py>, q: &Bound<'_, PyAny>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (nq, nv) = (self.m.nq(), self.m.nv());
        self.batch3(
            py,
            "crba",
            [(q, "q", nq), (q, "q", nq), (q, "q", nq)],
            &[nv, nv],
            |_| (),
            |m, q, _, _, o, _| {
                put(o, &m.crba(q)?);
                Ok(())
            },
        )
    }

    /// Internal: RNEA derivatives packed per state as [τ, ∂τ/∂q, ∂τ/∂v, M] (row-major).
    fn _rnea_derivatives<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'_, PyAny>,
        v: &Bound<'_, PyAny>,
        a: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (nq, nv) = (self.m.nq(), self.m.nv());
        self.batch3(
            py,
            "rnea_derivatives",
            [(q, "q", nq), (v, "v", nv), (a, "a", nv)],
            &[nv * (1 + 3 * nv)],
            |_| (),
            |m, q, v, a, o, _| {
                let d = m.rnea_derivatives(q, v, a, None)?;
                o[..nv].copy_from_slice(&d.tau);
                let s = nv * nv;
                put(&mut o[nv..nv + s], &d.dtau_dq);
                put(&mut o[nv + s..nv + 2 * s], &d.dtau_dv);
                put(&mut o[nv + 2 * s..], &d.mass_matrix);
                Ok(())
            },
        )
    }

    /// Internal: ABA derivatives packed per state as [v̇, ∂v̇/∂q, ∂v̇/∂v, ∂v̇/∂τ].
    fn _aba_derivatives<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'_, PyAny>,
        v: &Bound<'_, PyAny>,
        tau: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (nq, nv) = (self.m.nq(), self.m.nv());
        self.batch3(
            py,
            "aba_derivatives",
            [(q, "q", nq), (v, "v", nv), (tau, "tau", nv)],
            &[nv * (1 + 3 * nv)],
            |_| (),
            |m, q, v, t, o, _| {
                let d = m.aba_derivatives(q, v, t, None)?;
                o[..nv].copy_from_slice(&d.vdot);
                let s = nv * nv;
                put(&mut o[nv..nv + s], &d.dvdot_dq);
                put(&mut o[nv + s..nv + 2 * s], &d.dvdot_dv);
                put(&mut o[nv + 2 * s..], &d.dvdot_dtau);
                Ok(())
            },
        )
    }

    fn __repr__(&self) -> String {
        format!("<vectrix.Model: {} links, nq = {}, nv = {}>", self.m.links(), self.m.nq(), self.m.nv())
    }
}
