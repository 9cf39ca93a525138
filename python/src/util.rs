//! Input checking shared by every binding: numpy arrays of real numbers in, typed Python
//! errors out, and the panic guard.
//!
//! Book: — (the binding layer; DESIGN §5, errors name what was wrong and what is valid).

use std::panic::{AssertUnwindSafe, catch_unwind};

use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;

pyo3::create_exception!(
    _vectrix,
    Interrupted,
    pyo3::exceptions::PyKeyboardInterrupt,
    "Ctrl-C stopped a long computation; `.partial` holds what was computed."
);

/// Most elements one input array may have (2³¹): beyond it the call is refused before any
/// allocation (docs/robustness.md: every size is bounded).
pub const MAX_ELEMENTS: usize = 1 << 31;

/// A real array read from Python: its shape and its values in C order.
pub struct Real {
    pub shape: Vec<usize>,
    pub data: Vec<f64>,
}

impl Real {
    /// Number of elements.
    pub fn len(&self) -> usize {
        self.data.len()
    }
}

/// Reads `obj` (any array-like of real numbers: float or integer dtype) as f64 in C order.
/// `name` names the argument in every error. NaN and infinities are refused unless
/// `allow_nonfinite`.
///
/// # Errors
/// `TypeError` for a non-real dtype (complex, bool, object, strings), `ValueError` for NaN/∞,
/// or more than [`MAX_ELEMENTS`] elements.
pub fn real(py: Python<'_>, obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Real> {
    // fast path: a C-contiguous float64 array is read without any call into Python
    if let Ok(a) = obj.downcast::<PyArrayDyn<f64>>()
        && a.is_c_contiguous()
        && a.len() <= MAX_ELEMENTS
    {
        let ro = a.readonly();
        return finite(Real { shape: a.shape().to_vec(), data: ro.as_slice()?.to_vec() }, name);
    }
    let np = py.import("numpy")?;
    let arr = np.call_method1("asarray", (obj,)).map_err(|e| {
        PyTypeError::new_err(format!("{name}: not an array of numbers ({e}); valid: real numbers"))
    })?;
    let kind: String = arr.getattr("dtype")?.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "f" | "i" | "u") {
        let dt = arr.getattr("dtype")?.str()?.to_string();
        return Err(PyTypeError::new_err(format!(
            "{name}: dtype {dt}; valid: real numbers (a float or integer dtype)"
        )));
    }
    let size: usize = arr.getattr("size")?.extract()?;
    if size > MAX_ELEMENTS {
        return Err(PyValueError::new_err(format!("{name}: {size} elements; valid: at most {MAX_ELEMENTS}")));
    }
    let f = np.getattr("float64")?;
    let arr = np.call_method1("ascontiguousarray", (arr, f))?;
    let arr = arr.downcast::<PyArrayDyn<f64>>()?;
    let shape = arr.shape().to_vec();
    let ro = arr.readonly();
    finite(Real { shape, data: ro.as_slice()?.to_vec() }, name)
}

/// `r`, or a ValueError naming the first non-finite element.
fn finite(r: Real, name: &str) -> PyResult<Real> {
    if let Some(k) = r.data.iter().position(|x| !x.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "{name}: element {k} (flat index) is {}; valid: finite numbers",
            r.data[k]
        )));
    }
    Ok(r)
}

/// The number of cores, asked once (`available_parallelism` reads cgroup files on Linux).
pub fn cores() -> usize {
    static CORES: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |c| c.get()))
}

/// `f(k)` for k in 0..n, on all cores when n ≥ 16384.
pub fn par_map<T: Send>(n: usize, f: impl Fn(usize) -> T + Sync) -> Vec<T> {
    let c = cores();
    if n < 16_384 || c == 1 {
        return (0..n).map(f).collect();
    }
    let per = n.div_ceil(c);
    std::thread::scope(|s| {
        let hs: Vec<_> = (0..c)
            .map(|k| {
                let f = &f;
                s.spawn(move || (k * per..((k + 1) * per).min(n)).map(f).collect::<Vec<T>>())
            })
            .collect();
        hs.into_iter().flat_map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p))).collect()
    })
}

/// A shape as numpy prints it: `(5,)`, `(2, 3)`.
pub fn shape_str(s: &[usize]) -> String {
    match s {
        [n] => format!("({n},)"),
        _ => format!("({})", s.iter().map(|n| n.to_string()).collect::<Vec<_>>().join(", ")),
    }
}

/// `real` for a 1-D vector of length `n` (or any length when `n` is `None`).
pub fn vector(py: Python<'_>, obj: &Bound<'_, PyAny>, name: &str, n: Option<usize>) -> PyResult<Vec<f64>> {
    let r = real(py, obj, name)?;
    if r.shape.len() != 1 || n.is_some_and(|n| r.shape[0] != n) {
        let want = n.map_or("(k,)".to_string(), |n| format!("({n},)"));
        return Err(PyValueError::new_err(format!("{name}: shape {}; valid: {want}", shape_str(&r.shape))));
    }
    Ok(r.data)
}

/// Rows of length `width`: a single (width,) row or a (k, width) batch; returns the rows and
/// whether the input was a single row.
pub fn rows(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    name: &str,
    width: usize,
) -> PyResult<(Vec<f64>, usize, bool)> {
    let r = real(py, obj, name)?;
    match r.shape.as_slice() {
        [w] if *w == width => Ok((r.data, 1, true)),
        [n, w] if *w == width => Ok((r.data, *n, false)),
        s => Err(PyValueError::new_err(format!(
            "{name}: shape {}; valid: ({width},) or (N, {width})",
            shape_str(s)
        ))),
    }
}

/// Runs `f`, turning a Rust panic into a `RuntimeError` that says it is a vectrix bug: no panic
/// unwinds into Python.
pub fn guard<T>(what: &str, f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(p) => {
            let msg = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            Err(PyRuntimeError::new_err(format!("vectrix internal error in {what}: {msg} (please report)")))
        }
    }
}

/// [`guard`] around a computation that runs without the GIL.
pub fn nogil<T: Send>(py: Python<'_>, what: &str, f: impl FnOnce() -> PyResult<T> + Send) -> PyResult<T> {
    let r = py.allow_threads(|| catch_unwind(AssertUnwindSafe(f)));
    guard(what, || match r {
        Ok(r) => r,
        Err(p) => std::panic::resume_unwind(p),
    })
}

/// Splits `n` items into chunks for the available cores (one chunk below 16384 items) and
/// runs `f(start, end, chunk_out)` on each, in scoped threads; `out` has `width` values per item.
pub fn par_fill(n: usize, width: usize, out: &mut [f64], f: impl Fn(usize, usize, &mut [f64]) + Sync) {
    if n < 16_384 || cores() == 1 {
        f(0, n, out);
        return;
    }
    let per = n.div_ceil(cores());
    std::thread::scope(|s| {
        for (k, chunk) in out.chunks_mut(per * width).enumerate() {
            let f = &f;
            s.spawn(move || f(k * per, (k * per + chunk.len() / width).min(n), chunk));
        }
    });
}
