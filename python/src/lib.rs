//! Python bindings of vectrix (issue 37): the `vectrix._vectrix` extension module that the
//! pure-Python package `vectrix` wraps. Numpy in and out, the GIL released around every loop,
//! bad input a `ValueError`/`TypeError` naming the argument and the valid range, and no Rust
//! panic ever crossing into Python ([`util::guard`]).
//!
//! Book: the modules cite the sections they expose (rotations §2.9–2.16, multibody §7.11,
//! linear systems ch. 15–16, scenes §4.11).

use pyo3::prelude::*;

mod lti;
mod model;
mod rotation;
mod rotation_kernels;
mod rotation_more;
mod scene;
mod util;
mod view;

/// The extension module `vectrix._vectrix`.
#[pymodule]
fn _vectrix(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("SceneError", py.get_type::<scene::SceneError>())?;
    m.add("GimbalLockError", py.get_type::<rotation::GimbalLockError>())?;
    m.add("GimbalLockWarning", py.get_type::<rotation::GimbalLockWarning>())?;
    m.add("Interrupted", py.get_type::<util::Interrupted>())?;
    m.add_class::<rotation::Rotation>()?;
    m.add_class::<scene::Scene>()?;
    m.add_class::<scene::Cancel>()?;
    m.add_class::<model::Model>()?;
    m.add_class::<view::ViewSource>()?;
    m.add_function(wrap_pyfunction!(view::view_iframe, m)?)?;
    lti::register(m)?;
    m.add("MAX_ELEMENTS", util::MAX_ELEMENTS)?;
    Ok(())
}
