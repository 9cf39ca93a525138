//! `vectrix.Scene`: scene files (docs/scenes.md) loaded, checked, run and linearized from
//! Python; outputs as numpy columns, summaries as dicts, errors as `vectrix.SceneError`
//! carrying file, line and column.
//!
//! Book: §4.11 (integration), §7.11 (multibody), §8.3 (invariants), §12 (linearization).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use numpy::IntoPyArray;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use vectrix_scene::{MAX_SCENE_BYTES, Run, RunControl, Scene as RsScene, SceneError as RsError};

use crate::util::{guard, nogil};

pyo3::create_exception!(
    _vectrix,
    SceneError,
    pyo3::exceptions::PyValueError,
    "A scene that cannot be loaded, built or run; `.file`, `.line`, `.col`, `.path` locate it in \
     the scene file (None for a run failure, which has `.t`)."
);

/// The Python `SceneError` of a scene error, with its location as attributes.
pub(crate) fn scene_err(py: Python<'_>, e: &RsError) -> PyErr {
    let err = SceneError::new_err(e.to_string());
    let v = err.value(py);
    #[allow(clippy::type_complexity)]
    let (file, line, col, path, t): (
        Option<&str>,
        Option<usize>,
        Option<usize>,
        Option<&str>,
        Option<f64>,
    ) = match e {
        RsError::Parse { file, line, column, .. } => (Some(file), Some(*line), Some(*column), None, None),
        RsError::Invalid { file, line, column, path, .. } => {
            (Some(file), Some(*line), Some(*column), Some(path), None)
        }
        RsError::Run { t, .. } => (None, None, None, None, Some(*t)),
        _ => (None, None, None, None, None),
    };
    let _ = v.setattr("file", file);
    let _ = v.setattr("line", line);
    let _ = v.setattr("col", col);
    let _ = v.setattr("path", path);
    let _ = v.setattr("t", t);
    err
}

/// A cancellation flag shared with running scenes (set by Ctrl-C in `vectrix.sweep`, or by
/// the caller): a run stops after its current step and returns the rows computed.
#[pyclass(module = "vectrix._vectrix", frozen)]
#[derive(Clone, Default)]
pub struct Cancel(pub(crate) Arc<AtomicBool>);

#[pymethods]
impl Cancel {
    #[new]
    fn new() -> Self {
        Self::default()
    }
    /// Asks every run holding this flag to stop.
    fn set(&self) {
        self.0.store(true, Ordering::SeqCst);
    }
    /// Whether it was set.
    fn is_set(&self) -> bool {
        self.0.load(Ordering::SeqCst)
    }
}

/// A validated scene (docs/scenes.md), ready to run or linearize.
#[pyclass(module = "vectrix._vectrix", frozen)]
pub struct Scene {
    pub(crate) scene: RsScene,
    text: String,
    file: String,
}

/// Sets the value at a dotted path (`effects.0.k`) of a TOML document to a number or a
/// quantity string (converted by the scene itself, docs/scenes.md "Units").
fn set(doc: &mut toml::Value, path: &str, x: &Bound<'_, PyAny>) -> Result<(), String> {
    let mut cur = doc;
    for seg in path.split('.') {
        cur = match cur {
            toml::Value::Table(t) => {
                t.get_mut(seg).ok_or_else(|| format!("`{path}`: no key `{seg}` in the scene"))?
            }
            toml::Value::Array(a) => {
                let i: usize = seg.parse().map_err(|_| format!("`{path}`: `{seg}` must be an index"))?;
                let n = a.len();
                a.get_mut(i).ok_or_else(|| format!("`{path}`: index {i}; valid: 0..{n}"))?
            }
            _ => return Err(format!("`{path}`: `{seg}` is below a value")),
        };
    }
    let new = if let Ok(s) = x.extract::<String>() {
        toml::Value::String(s)
    } else if let (Ok(i), toml::Value::Integer(_)) = (x.extract::<i64>(), &*cur) {
        toml::Value::Integer(i)
    } else if let Ok(f) = x.extract::<f64>() {
        if !f.is_finite() {
            return Err(format!("`{path}` = {f}; valid: a finite number or a quantity string (\"2 lbf\")"));
        }
        match cur {
            toml::Value::Integer(_) if f.fract() == 0.0 && f.abs() < 9.0e15 => toml::Value::Integer(f as i64),
            toml::Value::Integer(_) => return Err(format!("`{path}` is an integer; {f} is not")),
            _ => toml::Value::Float(f),
        }
    } else {
        let t = x.get_type().name().map(|n| n.to_string()).unwrap_or_default();
        return Err(format!("`{path}`: a {t}; valid: a number or a quantity string (\"2 lbf\")"));
    };
    if matches!(cur, toml::Value::Table(_) | toml::Value::Array(_)) {
        return Err(format!("`{path}` is a table or array; valid: the path of a number"));
    }
    *cur = new;
    Ok(())
}

impl Scene {
    fn load(py: Python<'_>, text: String, file: String) -> PyResult<Self> {
        let (t, f) = (&text, &file);
        let scene = nogil(py, "Scene", || Ok(RsScene::from_toml(t, f)))?.map_err(|e| scene_err(py, &e))?;
        Ok(Self { scene, text, file })
    }

    /// The scene with `overrides` applied (none: `None`, use `self.scene`).
    pub(crate) fn with(
        &self,
        py: Python<'_>,
        overrides: &[(String, Bound<'_, PyAny>)],
    ) -> PyResult<Option<RsScene>> {
        Ok(self.with_text(py, overrides)?.map(|(s, _, _)| s))
    }

    /// [`Scene::with`] with the scene's TOML text and file label as run.
    pub(crate) fn with_text(
        &self,
        py: Python<'_>,
        overrides: &[(String, Bound<'_, PyAny>)],
    ) -> PyResult<Option<(RsScene, String, String)>> {
        if overrides.is_empty() {
            return Ok(None);
        }
        let mut doc: toml::Value =
            toml::from_str(&self.text).map_err(|e| PyValueError::new_err(format!("{}: {e}", self.file)))?;
        for (p, v) in overrides {
            set(&mut doc, p, v).map_err(|m| SceneError::new_err(format!("{}: override {m}", self.file)))?;
        }
        let text = toml::to_string(&doc).map_err(|e| PyValueError::new_err(format!("overrides: {e}")))?;
        let label = format!("{} (with overrides)", self.file);
        let scene = nogil(py, "Scene overrides", || Ok(RsScene::from_toml(&text, &label)))?
            .map_err(|e| scene_err(py, &e))?;
        Ok(Some((scene, text, label)))
    }
}

/// Runs `scene` without the GIL; Ctrl-C (checked every 0.1 s on the main thread) or `cancel`
/// stop it after the current step with the rows computed (`stop.reason = "interrupted"`).
/// Returns the run and the KeyboardInterrupt when Ctrl-C stopped it.
pub(crate) fn run_scene(
    py: Python<'_>,
    scene: &RsScene,
    cancel: Option<&Cancel>,
) -> PyResult<(Run, Option<PyErr>)> {
    let flag = cancel.map_or_else(|| Arc::new(AtomicBool::new(false)), |c| c.0.clone());
    let signal: Mutex<Option<PyErr>> = Mutex::new(None);
    let threading = py.import("threading")?;
    let main = threading.call_method0("current_thread")?.is(&threading.call_method0("main_thread")?);
    let r = nogil(py, "Scene.run", || {
        let mut last = Instant::now();
        let mut progress = |_f: f64| {
            if main && last.elapsed() > Duration::from_millis(100) {
                last = Instant::now();
                if let Err(e) = Python::with_gil(|py| py.check_signals()) {
                    flag.store(true, Ordering::SeqCst);
                    if let Ok(mut s) = signal.lock() {
                        *s = Some(e);
                    }
                }
            }
        };
        Ok(scene.run_with(RunControl { progress: &mut progress, cancel: Some(&flag) }))
    })?;
    let sig = signal.into_inner().ok().flatten();
    let run = r.map_err(|e| scene_err(py, &e))?;
    Ok((run, sig))
}

/// t, the columns as numpy arrays, units, and the summary (everything but the rows) as JSON.
pub(crate) fn run_to_py<'py>(py: Python<'py>, run: &Run) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("t", run.t.clone().into_pyarray(py))?;
    let cols = PyDict::new(py);
    for (k, c) in run.columns.iter().enumerate() {
        let v: Vec<f64> = run.rows.iter().map(|r| r[k]).collect();
        cols.set_item(c, v.into_pyarray(py))?;
    }
    d.set_item("columns", cols)?;
    let units = PyDict::new(py);
    for (c, u) in run.columns.iter().zip(&run.units) {
        units.set_item(c, u)?;
    }
    d.set_item("units", units)?;
    let mut summary = serde_json::to_value(run).map_err(|e| PyValueError::new_err(e.to_string()))?;
    if let Some(m) = summary.as_object_mut() {
        m.remove("rows");
        m.remove("t");
        m.insert("complete".into(), serde_json::Value::Bool(run.is_complete()));
    }
    d.set_item("summary_json", summary.to_string())?;
    Ok(d)
}

#[pymethods]
impl Scene {
    /// Loads and validates a scene file (TOML, at most 4 MiB). Errors: `SceneError` with
    /// file, line, col. Book: §4.11, §7.11.
    #[staticmethod]
    fn from_file(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Self> {
        let meta = std::fs::metadata(&path)
            .map_err(|e| PyValueError::new_err(format!("path {}: {e}", path.display())))?;
        if !meta.is_file() || meta.len() > MAX_SCENE_BYTES as u64 {
            return Err(PyValueError::new_err(format!(
                "path {}: {} bytes or not a regular file; valid: a scene file of at most {MAX_SCENE_BYTES} bytes",
                path.display(),
                meta.len()
            )));
        }
        let text = std::fs::read_to_string(&path)
            .map_err(|e| PyValueError::new_err(format!("path {}: {e}", path.display())))?;
        Self::load(py, text, path.display().to_string())
    }

    /// Loads and validates a scene from its TOML text; `file` names it in errors.
    #[staticmethod]
    #[pyo3(signature = (text, file = "<scene>".to_string()))]
    fn from_toml(py: Python<'_>, text: String, file: String) -> PyResult<Self> {
        Self::load(py, text, file)
    }

    /// The scene's name.
    #[getter]
    fn name(&self) -> String {
        self.scene.spec().name.clone()
    }

    /// The TOML text it was loaded from.
    #[getter]
    fn text(&self) -> String {
        self.text.clone()
    }

    /// The file name used in errors.
    #[getter]
    fn file(&self) -> String {
        self.file.clone()
    }

    /// Validates `overrides` (a list of (dotted path, value)) against the scene without running.
    fn _check(&self, py: Python<'_>, overrides: Vec<(String, Bound<'_, PyAny>)>) -> PyResult<()> {
        self.with(py, &overrides).map(|_| ())
    }

    /// Internal: runs with overrides; a dict of t, columns, units, summary_json.
    #[pyo3(signature = (overrides, cancel = None))]
    fn _run<'py>(
        &self,
        py: Python<'py>,
        overrides: Vec<(String, Bound<'py, PyAny>)>,
        cancel: Option<Cancel>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let own = self.with_text(py, &overrides)?;
        let scene = own.as_ref().map_or(&self.scene, |o| &o.0);
        let (run, sig) = run_scene(py, scene, cancel.as_ref())?;
        let d = guard("Scene.run", || run_to_py(py, &run))?;
        // what `RunResult.view()` needs, the rows left out (they are in `d`)
        let (text, file) = own.map_or_else(|| (self.text.clone(), self.file.clone()), |o| (o.1, o.2));
        let t_last = run.t.last().copied().unwrap_or(0.0);
        d.set_item("view", crate::view::ViewSource::new(text, file, run))?;
        if let Some(sig) = sig {
            // Ctrl-C: `vectrix.Interrupted` (a KeyboardInterrupt) carrying what was computed
            let e = crate::util::Interrupted::new_err(format!("{sig}: run stopped at t = {t_last}"));
            e.value(py).setattr("partial", d)?;
            return Err(e);
        }
        Ok(d)
    }

    /// Internal: the linearization as JSON (A, B, C, D row-major, eigenvalues, modes).
    fn _linearize(&self, py: Python<'_>, overrides: Vec<(String, Bound<'_, PyAny>)>) -> PyResult<String> {
        let own = self.with(py, &overrides)?;
        let scene = own.as_ref().unwrap_or(&self.scene);
        let lin = nogil(py, "Scene.linearize", || Ok(scene.linearize()))?.map_err(|e| scene_err(py, &e))?;
        serde_json::to_string(&lin).map_err(|e| PyTypeError::new_err(e.to_string()))
    }

    /// The multibody model of the scene's bodies (book §7.11).
    fn model(&self) -> crate::model::Model {
        crate::model::Model { m: self.scene.model().clone() }
    }

    /// The initial state y = (q, v).
    fn initial_state<'py>(&self, py: Python<'py>) -> Bound<'py, numpy::PyArray1<f64>> {
        self.scene.initial_state().into_pyarray(py)
    }

    fn __repr__(&self) -> String {
        format!("<vectrix.Scene {:?} from {}>", self.scene.spec().name, self.file)
    }
}
