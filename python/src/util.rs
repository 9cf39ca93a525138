//! Input checking shared by every binding: numpy arrays of real numbers in, typed Python
//! errors out, and the panic guard.
//!
//! Book: — (the binding layer; DESIGN §5, errors name what was wrong and what is valid).

use std::panic::{AssertUnwindSafe, catch_unwind};

use numpy::{PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
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

/// A real array read from Python: its shape and a read-only borrow of its values in C order.
///
/// The values are numpy's own buffer when the argument is already a C-contiguous float64
/// array (no copy), otherwise one contiguous float64 copy made by numpy. The borrow may be
/// read without the GIL (as numpy's own loops do): the binding never writes to it.
pub struct Real<'py> {
    pub shape: Vec<usize>,
    ro: PyReadonlyArrayDyn<'py, f64>,
}

impl Real<'_> {
    /// The values in C order.
    ///
    /// # Errors
    /// Never for an array made by [`real`] (it is C-contiguous); a `ValueError` otherwise.
    pub fn data(&self) -> PyResult<&[f64]> {
        Ok(self.ro.as_slice()?)
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.shape.iter().product()
    }
}

/// Reads `obj` (any array-like of real numbers: float or integer dtype) as f64 in C order,
/// borrowing a C-contiguous float64 array in place and copying anything else once. `name`
/// names the argument in every error. NaN and infinities are refused.
///
/// # Errors
/// `TypeError` for a non-real dtype (complex, bool, object, strings), `ValueError` for NaN/∞,
/// or more than [`MAX_ELEMENTS`] elements.
pub fn real<'py>(py: Python<'_>, obj: &Bound<'py, PyAny>, name: &str) -> PyResult<Real<'py>> {
    let r = real_unchecked(py, obj, name)?;
    finite(r.data()?, name)?;
    Ok(r)
}

/// [`real`] without the finiteness scan, for kernels that check every element themselves in
/// their own pass (reporting with [`nonfinite`]): one pass over the input instead of two.
///
/// # Errors
/// As [`real`], except NaN/∞.
pub fn real_unchecked<'py>(_py: Python<'_>, obj: &Bound<'py, PyAny>, name: &str) -> PyResult<Real<'py>> {
    let py = obj.py();
    // fast path: a C-contiguous float64 array is borrowed without any call into Python
    if let Ok(a) = obj.downcast::<PyArrayDyn<f64>>()
        && a.is_c_contiguous()
    {
        return borrow(a, name);
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
    borrow(arr.downcast::<PyArrayDyn<f64>>()?, name)
}

/// A read-only borrow of a C-contiguous float64 array, refused beyond [`MAX_ELEMENTS`].
fn borrow<'py>(a: &Bound<'py, PyArrayDyn<f64>>, name: &str) -> PyResult<Real<'py>> {
    if a.len() > MAX_ELEMENTS {
        return Err(PyValueError::new_err(format!(
            "{name}: {} elements; valid: at most {MAX_ELEMENTS}",
            a.len()
        )));
    }
    let ro = a.try_readonly().map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
    Ok(Real { shape: a.shape().to_vec(), ro })
}

/// `Ok`, or a ValueError naming the first non-finite element of `data`.
fn finite(data: &[f64], name: &str) -> PyResult<()> {
    match data.iter().position(|x| !x.is_finite()) {
        Some(k) => Err(nonfinite(name, k, data[k])),
        None => Ok(()),
    }
}

/// The ValueError for the non-finite element `x` at flat index `k` of argument `name`.
pub fn nonfinite(name: &str, k: usize, x: f64) -> PyErr {
    PyValueError::new_err(format!("{name}: element {k} (flat index) is {x}; valid: finite numbers"))
}

/// The number of cores, asked once (`available_parallelism` reads cgroup files on Linux),
/// or `VECTRIX_NUM_THREADS` when set to a positive integer (as `OMP_NUM_THREADS` for numpy's
/// BLAS: single-threaded measurements, or a share of a cluster node).
pub fn cores() -> usize {
    static CORES: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *CORES.get_or_init(|| {
        let env = std::env::var("VECTRIX_NUM_THREADS").ok().and_then(|s| s.trim().parse::<usize>().ok());
        match env {
            Some(n) if n > 0 => n,
            _ => std::thread::available_parallelism().map_or(1, |c| c.get()),
        }
    })
}

/// Items below which a cheap per-item kernel (a rotation conversion, tens of nanoseconds)
/// runs on one thread: spawning threads costs tens of microseconds.
pub const CHEAP: usize = 16_384;

/// `f(k)` for k in 0..n into a new vector, on all cores from [`CHEAP`] items on; the first
/// error by index wins. The vector's memory is hinted for huge pages (as numpy does for its
/// large arrays), so that a 10⁶-element result costs a few page faults, not thousands.
///
/// # Errors
/// The error of the smallest k whose `f(k)` failed.
pub fn build<T: Copy + Send, E: Send>(
    n: usize,
    f: impl Fn(usize) -> Result<T, E> + Sync,
) -> Result<Vec<T>, E> {
    let mut v = huge_vec::<T>(n);
    // each chunk writes every one of its slots or returns an error
    let res = par_items(&mut v.spare_capacity_mut()[..n], CHEAP, |s, chunk| {
        for (k, o) in chunk.iter_mut().enumerate() {
            o.write(f(s + k)?);
        }
        Ok(())
    });
    res.into_iter().collect::<Result<(), E>>()?;
    // SAFETY: every chunk returned Ok, so all n slots 0..n were written above (`T: Copy` has
    // no destructor to run on an early error, when the length stays 0)
    unsafe { v.set_len(n) };
    Ok(v)
}

/// An empty vector with room for `n` values, its memory advised for transparent huge pages
/// when it spans at least one 2 MiB page (Linux; elsewhere a plain vector).
fn huge_vec<T>(n: usize) -> Vec<T> {
    let mut v: Vec<T> = Vec::with_capacity(n);
    #[cfg(target_os = "linux")]
    {
        const HUGE: usize = 2 << 20;
        let (start, len) = (v.as_mut_ptr() as usize, n * std::mem::size_of::<T>());
        let first = start.next_multiple_of(HUGE);
        let last = (start + len) / HUGE * HUGE;
        if last > first {
            // SAFETY: [first, last) lies inside the allocation that `v` owns; MADV_HUGEPAGE
            // only advises the kernel how to back it (no memory is read, written or freed),
            // and a refusal (an error return) changes nothing.
            unsafe {
                libc::madvise(first as *mut libc::c_void, last - first, libc::MADV_HUGEPAGE);
            }
        }
    }
    v
}

/// A shape as numpy prints it: `(5,)`, `(2, 3)`.
pub fn shape_str(s: &[usize]) -> String {
    match s {
        [n] => format!("({n},)"),
        _ => format!("({})", s.iter().map(|n| n.to_string()).collect::<Vec<_>>().join(", ")),
    }
}

/// `real` for a 1-D vector of length `n` (or any length when `n` is `None`), copied (for
/// short vectors: polynomials, weights, time grids).
pub fn vector(py: Python<'_>, obj: &Bound<'_, PyAny>, name: &str, n: Option<usize>) -> PyResult<Vec<f64>> {
    let r = real(py, obj, name)?;
    if r.shape.len() != 1 || n.is_some_and(|n| r.shape[0] != n) {
        let want = n.map_or("(k,)".to_string(), |n| format!("({n},)"));
        return Err(PyValueError::new_err(format!("{name}: shape {}; valid: {want}", shape_str(&r.shape))));
    }
    Ok(r.data()?.to_vec())
}

/// Rows of length `width`: a single (width,) row or a (k, width) batch; returns the borrowed
/// array, the number of rows and whether the input was a single row.
pub fn rows<'py>(
    py: Python<'_>,
    obj: &Bound<'py, PyAny>,
    name: &str,
    width: usize,
) -> PyResult<(Real<'py>, usize, bool)> {
    shaped(real(py, obj, name)?, name, width)
}

/// [`rows`] without the finiteness scan (the kernel checks, see [`real_unchecked`]).
pub fn rows_unchecked<'py>(
    py: Python<'_>,
    obj: &Bound<'py, PyAny>,
    name: &str,
    width: usize,
) -> PyResult<(Real<'py>, usize, bool)> {
    shaped(real_unchecked(py, obj, name)?, name, width)
}

fn shaped<'py>(r: Real<'py>, name: &str, width: usize) -> PyResult<(Real<'py>, usize, bool)> {
    match *r.shape.as_slice() {
        [w] if w == width => Ok((r, 1, true)),
        [n, w] if w == width => Ok((r, n, false)),
        ref s => Err(PyValueError::new_err(format!(
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

/// Splits the items of `out` (one slice element per item) into one chunk per core (one chunk
/// below `min_par` items) and runs `f(first_item, chunk)` on each in scoped threads; returns
/// the chunks' results in order.
pub fn par_items<T: Send, R: Send>(
    out: &mut [T],
    min_par: usize,
    f: impl Fn(usize, &mut [T]) -> R + Sync,
) -> Vec<R> {
    let n = out.len();
    if n < min_par.max(2) || cores() == 1 {
        return vec![f(0, out)];
    }
    let per = n.div_ceil(cores());
    std::thread::scope(|s| {
        let hs: Vec<_> = out
            .chunks_mut(per)
            .enumerate()
            .map(|(k, chunk)| {
                let f = &f;
                s.spawn(move || f(k * per, chunk))
            })
            .collect();
        hs.into_iter().map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p))).collect()
    })
}

/// Splits `n` items of `width` values each into chunks for the available cores (one chunk
/// below `min_par` items) and runs `f(start, end, chunk_out)` on each, in scoped threads.
pub fn par_fill(
    n: usize,
    width: usize,
    out: &mut [f64],
    min_par: usize,
    f: impl Fn(usize, usize, &mut [f64]) + Sync,
) {
    if width == 0 || n < min_par.max(2) || cores() == 1 {
        f(0, n, out);
        return;
    }
    let per = n.div_ceil(cores());
    std::thread::scope(|s| {
        for (k, chunk) in out.chunks_mut(per * width).enumerate() {
            let f = &f;
            s.spawn(move || f(k * per, k * per + chunk.len() / width, chunk));
        }
    });
}

/// Elements from which [`fill_out`] asks numpy for an uninitialised array (a call into
/// Python, a few microseconds) instead of a zeroed one.
const BIG: usize = 1 << 16;

/// A new float64 numpy array of shape (n, *tail) (or `tail` alone when `single`), allocated
/// by numpy (which asks the kernel for huge pages on large arrays: a fresh 10⁶-row output
/// costs a few page faults, not thousands) and filled in place by `f(start, end, chunk)`
/// without the GIL, on all cores from `min_par` items on.
pub fn fill_out<'py>(
    py: Python<'py>,
    what: &str,
    n: usize,
    single: bool,
    tail: &[usize],
    min_par: usize,
    f: impl Fn(usize, usize, &mut [f64]) + Sync,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let mut shape: Vec<usize> = if single { vec![] } else { vec![n] };
    shape.extend_from_slice(tail);
    let width: usize = tail.iter().product();
    let arr = if n * width < BIG {
        PyArrayDyn::<f64>::zeros(py, shape, false)
    } else {
        // numpy.empty: no zeroing pass over a buffer that is about to be overwritten whole
        // (every element is written by `f`, the contract of this function)
        let e = py.import("numpy")?.call_method1("empty", (shape,))?;
        e.downcast_into::<PyArrayDyn<f64>>()?
    };
    {
        let mut rw = arr.try_readwrite().map_err(|e| PyRuntimeError::new_err(format!("{what}: {e}")))?;
        let o = rw.as_slice_mut()?;
        nogil(py, what, || {
            par_fill(n, width, o, min_par, &f);
            Ok(())
        })?;
    }
    Ok(arr)
}
