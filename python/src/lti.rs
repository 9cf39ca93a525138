//! Linear systems for Python: transfer functions (descending coefficients, optional delay),
//! state space, zeros–poles–gain; margins, Bode, step responses and root loci on vectrix's
//! exact routines. The Python classes in `vectrix/lti.py` hold the coefficients and call these.
//!
//! Book: ch. 15 (transfer functions, responses, root locus §15.18), ch. 16 (margins §16.3).

use nalgebra::DMatrix;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use vectrix_lti::{Complex64, InputKind, LtiError, StateSpace, TransferFunction, Zpk, response, root_locus};

use crate::util::{nogil, real, vector};

fn lti_err(what: &str, e: LtiError) -> PyErr {
    PyValueError::new_err(format!("{what}: {e}"))
}

fn tf(
    py: Python<'_>,
    num: &Bound<'_, PyAny>,
    den: &Bound<'_, PyAny>,
    delay: f64,
) -> PyResult<TransferFunction> {
    let n = vector(py, num, "num", None)?;
    let d = vector(py, den, "den", None)?;
    if !(delay.is_finite() && delay >= 0.0) {
        return Err(PyValueError::new_err(format!("delay = {delay}; valid: a finite number ≥ 0 [s]")));
    }
    let g = TransferFunction::new(&n, &d).map_err(|e| lti_err("tf", e))?;
    if delay > 0.0 { g.with_delay(delay).map_err(|e| lti_err("delay", e)) } else { Ok(g) }
}

fn matrix(py: Python<'_>, obj: &Bound<'_, PyAny>, name: &str) -> PyResult<DMatrix<f64>> {
    let r = real(py, obj, name)?;
    match r.shape.as_slice() {
        [n, m] => Ok(DMatrix::from_row_slice(*n, *m, r.data()?)),
        s => Err(PyValueError::new_err(format!(
            "{name}: shape {}; valid: a 2-D matrix",
            crate::util::shape_str(s)
        ))),
    }
}

fn ss(
    py: Python<'_>,
    a: &Bound<'_, PyAny>,
    b: &Bound<'_, PyAny>,
    c: &Bound<'_, PyAny>,
    d: &Bound<'_, PyAny>,
) -> PyResult<StateSpace> {
    StateSpace::new(matrix(py, a, "A")?, matrix(py, b, "B")?, matrix(py, c, "C")?, matrix(py, d, "D")?)
        .map_err(|e| lti_err("ss", e))
}

fn complex_parts(v: &[Complex64]) -> (Vec<f64>, Vec<f64>) {
    (v.iter().map(|z| z.re).collect(), v.iter().map(|z| z.im).collect())
}

/// Margins of the loop L = num/den·e^{−sτ}: every crossover and the margins python-control
/// reports (gm, pm, wpc, wgc, sm, wsm; gm = inf and w = nan when absent). Book: §16.3.
#[pyfunction]
#[pyo3(signature = (num, den, delay = 0.0))]
fn _tf_margins<'py>(
    py: Python<'py>,
    num: &Bound<'_, PyAny>,
    den: &Bound<'_, PyAny>,
    delay: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let g = tf(py, num, den, delay)?;
    let m = nogil(py, "margins", || g.margins().map_err(|e| lti_err("margins", e)))?;
    let d = PyDict::new(py);
    d.set_item("gm", m.gain_margin().map_or(f64::INFINITY, |p| p.gain_margin))?;
    d.set_item("gm_db", m.gain_margin_db().unwrap_or(f64::INFINITY))?;
    d.set_item("pm", m.phase_margin_deg().unwrap_or(f64::INFINITY))?;
    d.set_item("sm", m.stability_margin_distance().unwrap_or(f64::INFINITY))?;
    d.set_item("wpc", m.phase_crossover_omega().unwrap_or(f64::NAN))?;
    d.set_item("wgc", m.gain_crossover_omega().unwrap_or(f64::NAN))?;
    d.set_item("wsm", m.stability_margin().map_or(f64::NAN, |s| s.omega))?;
    let pcs: Vec<(f64, f64)> = m.phase_crossovers.iter().map(|p| (p.omega, p.gain_margin)).collect();
    let gcs: Vec<(f64, f64)> = m.gain_crossovers.iter().map(|g| (g.omega, g.phase_margin_deg)).collect();
    d.set_item("phase_crossovers", pcs)?;
    d.set_item("gain_crossovers", gcs)?;
    Ok(d)
}

/// Bode data at `omega` [rad/s]: (magnitude |G|, phase [deg] on the continuous branch, the
/// real and imaginary parts of G(jω)). Book: §15.14, §16.2.
#[pyfunction]
#[pyo3(signature = (num, den, omega, delay = 0.0))]
#[allow(clippy::type_complexity)]
fn _tf_bode<'py>(
    py: Python<'py>,
    num: &Bound<'_, PyAny>,
    den: &Bound<'_, PyAny>,
    omega: &Bound<'_, PyAny>,
    delay: f64,
) -> PyResult<(
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
)> {
    let g = tf(py, num, den, delay)?;
    let w = vector(py, omega, "omega", None)?;
    let r = nogil(py, "bode", || g.bode(&w).map_err(|e| lti_err("bode (omega: valid 0 ≤ ω < ∞)", e)))?;
    let mag: Vec<f64> = r.response.iter().map(|z| z.norm()).collect();
    let (re, im) = complex_parts(&r.response);
    Ok((mag.into_pyarray(py), r.phase_deg.into_pyarray(py), re.into_pyarray(py), im.into_pyarray(py)))
}

/// Step response y(t) of num/den·e^{−sτ} on a uniform grid `t` starting at 0. Book: §15.9.
#[pyfunction]
#[pyo3(signature = (num, den, t, delay = 0.0))]
fn _tf_step<'py>(
    py: Python<'py>,
    num: &Bound<'_, PyAny>,
    den: &Bound<'_, PyAny>,
    t: &Bound<'_, PyAny>,
    delay: f64,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let g = tf(py, num, den, delay)?;
    let t = vector(py, t, "t", None)?;
    let r = nogil(py, "step", || g.step(&t).map_err(|e| lti_err("step (t: a uniform grid from 0)", e)))?;
    Ok(r.y.into_iter().next().unwrap_or_default().into_pyarray(py))
}

/// Step response of input `input` of a state-space system: y (outputs, len t). Book: §15.8–15.9.
#[pyfunction]
#[pyo3(signature = (a, b, c, d, t, input = 0))]
#[allow(clippy::too_many_arguments)]
fn _ss_step<'py>(
    py: Python<'py>,
    a: &Bound<'_, PyAny>,
    b: &Bound<'_, PyAny>,
    c: &Bound<'_, PyAny>,
    d: &Bound<'_, PyAny>,
    t: &Bound<'_, PyAny>,
    input: usize,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let s = ss(py, a, b, c, d)?;
    let t = vector(py, t, "t", None)?;
    let r = nogil(py, "step", || {
        response(&s, InputKind::Step, input, 1.0, 0.0, &t).map_err(|e| lti_err("step", e))
    })?;
    PyArray2::from_vec2(py, &r.y).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// Poles and zeros of num/den as (re, im) arrays. Book: §15.18.
#[pyfunction]
#[allow(clippy::type_complexity)]
fn _tf_roots<'py>(
    py: Python<'py>,
    num: &Bound<'_, PyAny>,
    den: &Bound<'_, PyAny>,
) -> PyResult<((Vec<f64>, Vec<f64>), (Vec<f64>, Vec<f64>))> {
    let g = tf(py, num, den, 0.0)?;
    let (p, z) = nogil(py, "roots", || {
        Ok((g.poles().map_err(|e| lti_err("poles", e))?, g.zeros().map_err(|e| lti_err("zeros", e))?))
    })?;
    Ok((complex_parts(&p), complex_parts(&z)))
}

/// The transfer function (num, den) from `output` to `input` of a state-space system.
/// Book: (15.8.1), §15.20.
#[pyfunction]
#[pyo3(signature = (a, b, c, d, output = 0, input = 0))]
#[allow(clippy::too_many_arguments)]
fn _ss_to_tf(
    py: Python<'_>,
    a: &Bound<'_, PyAny>,
    b: &Bound<'_, PyAny>,
    c: &Bound<'_, PyAny>,
    d: &Bound<'_, PyAny>,
    output: usize,
    input: usize,
) -> PyResult<(Vec<f64>, Vec<f64>)> {
    let s = ss(py, a, b, c, d)?;
    let g = nogil(py, "ss.to_tf", || s.to_tf(output, input).map_err(|e| lti_err("to_tf", e)))?;
    Ok((g.num().coeffs().to_vec(), g.den().coeffs().to_vec()))
}

/// A controllable-canonical realization (A, B, C, D) of a proper num/den. Book: §15.20.
#[pyfunction]
#[allow(clippy::type_complexity)]
fn _tf_to_ss(
    py: Python<'_>,
    num: &Bound<'_, PyAny>,
    den: &Bound<'_, PyAny>,
) -> PyResult<(Vec<Vec<f64>>, Vec<Vec<f64>>, Vec<Vec<f64>>, Vec<Vec<f64>>)> {
    let g = tf(py, num, den, 0.0)?;
    let s = StateSpace::from_tf(&g).map_err(|e| lti_err("to_ss", e))?;
    let rows = |m: &DMatrix<f64>| (0..m.nrows()).map(|i| m.row(i).iter().copied().collect()).collect();
    Ok((rows(s.a()), rows(s.b()), rows(s.c()), rows(s.d())))
}

/// num/den of zeros, poles (complex, conjugate pairs exact) and gain k. Book: §15.18.
#[pyfunction]
fn _zpk_to_tf(zeros: Vec<Complex64>, poles: Vec<Complex64>, gain: f64) -> PyResult<(Vec<f64>, Vec<f64>)> {
    let z = Zpk::new(zeros, poles, gain).map_err(|e| lti_err("zpk", e))?;
    let g = z.to_tf().map_err(|e| lti_err("zpk.to_tf", e))?;
    Ok((g.num().coeffs().to_vec(), g.den().coeffs().to_vec()))
}

/// Root locus of 1 + k·num/den for 0 ≤ k ≤ k_max: gains (K,) and branches (n, K) complex.
/// Book: §15.18, Rules 1–7.
#[pyfunction]
#[pyo3(signature = (num, den, k_max, max_step = None))]
#[allow(clippy::type_complexity)]
fn _root_locus<'py>(
    py: Python<'py>,
    num: &Bound<'_, PyAny>,
    den: &Bound<'_, PyAny>,
    k_max: f64,
    max_step: Option<f64>,
) -> PyResult<(Bound<'py, PyArray1<f64>>, Vec<Vec<Complex64>>)> {
    let g = tf(py, num, den, 0.0)?;
    let step = max_step.unwrap_or(k_max / 200.0);
    let r = nogil(py, "root_locus", || {
        root_locus(&g, k_max, step).map_err(|e| lti_err("root_locus (valid: k_max > 0)", e))
    })?;
    Ok((r.gains.into_pyarray(py), r.branches))
}

/// Registers the functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_tf_margins, m)?)?;
    m.add_function(wrap_pyfunction!(_tf_bode, m)?)?;
    m.add_function(wrap_pyfunction!(_tf_step, m)?)?;
    m.add_function(wrap_pyfunction!(_ss_step, m)?)?;
    m.add_function(wrap_pyfunction!(_tf_roots, m)?)?;
    m.add_function(wrap_pyfunction!(_ss_to_tf, m)?)?;
    m.add_function(wrap_pyfunction!(_tf_to_ss, m)?)?;
    m.add_function(wrap_pyfunction!(_zpk_to_tf, m)?)?;
    m.add_function(wrap_pyfunction!(_root_locus, m)?)?;
    Ok(())
}
