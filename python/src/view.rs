//! A scene run's 3-D view from Python (issue 36 item 5): the same self-contained page that
//! `vectrix run` writes as `view.html` (vectrix-cli's [`vectrix_cli::scene_page`]: three.js
//! vendored and inlined, no network, at most 1001 instants and 40 000 poses), shown in Jupyter
//! through IPython's HTML display as a sandboxed `<iframe srcdoc=…>` ([`vectrix_cli::View`]).
//!
//! Book: §2.12 (attitudes as quaternions), §7.11 (poses of a tree of bodies).

use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use vectrix_cli::{DEFAULT_MAX_OUTPUT_BYTES, View, scene_page, scene_page_bound};
use vectrix_scene::{Run, Scene as RsScene};
use vectrix_units::UnitSystem;

use crate::scene::{Cancel, scene_err};
use crate::util::nogil;

/// What a run's view needs: the scene's text as run (overrides applied), its file name, and
/// the run without its rows (the page's poses come from a second pass at the view's instants;
/// only the run's end time, completion and column count are read).
#[pyclass(module = "vectrix._vectrix", frozen)]
pub struct ViewSource {
    text: String,
    file: String,
    run: Run,
}

impl ViewSource {
    /// The source of `run`'s view; `run`'s rows are dropped here (the Python `RunResult` holds
    /// the outputs), its times kept to the last.
    pub(crate) fn new(text: String, file: String, mut run: Run) -> Self {
        run.rows = Vec::new();
        let last = run.t.last().copied();
        run.t = last.into_iter().collect();
        Self { text, file, run }
    }
}

#[pymethods]
impl ViewSource {
    /// The page (`view.html` of `vectrix run`), and its size bound. Book: §7.11.
    ///
    /// Errors: `SceneError` when the scene no longer loads; `ValueError` when the page would
    /// exceed the command line's default output limit (the same bound `vectrix run` checks).
    #[pyo3(signature = (cancel = None))]
    fn page(&self, py: Python<'_>, cancel: Option<Cancel>) -> PyResult<(String, u64)> {
        let (text, file, run) = (&self.text, &self.file, &self.run);
        let flag = cancel.map_or_else(|| Arc::new(AtomicBool::new(false)), |c| c.0.clone());
        let scene =
            nogil(py, "view", || Ok(RsScene::from_toml(text, file)))?.map_err(|e| scene_err(py, &e))?;
        let bound = scene_page_bound(&scene);
        if bound > DEFAULT_MAX_OUTPUT_BYTES {
            return Err(PyValueError::new_err(format!(
                "view of {:?}: up to {bound} bytes; valid: at most {DEFAULT_MAX_OUTPUT_BYTES} (vectrix run's default \
                 --max-output-bytes)",
                scene.spec().name
            )));
        }
        let page =
            nogil(py, "view", || Ok(scene_page(&scene, (text, file), run, UnitSystem::Si, Some(&flag))))?;
        Ok((page, bound))
    }
}

/// The page in a sandboxed iframe whose `srcdoc` holds it HTML-escaped (scripts allowed,
/// nothing else): what `_repr_html_` shows in a notebook.
#[pyfunction]
pub fn view_iframe(page: String) -> String {
    View::from_page(page).iframe()
}
