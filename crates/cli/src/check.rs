//! `vectrix check SCENE`: parse and validate a scene without running it.
//!
//! Book: — (file format).

use std::io::Write;
use std::path::Path;

use crate::output::BoxError;

/// Validates and prints what the scene declares and which invariants it implies.
pub fn check(out: &mut impl Write, path: &Path) -> Result<(), BoxError> {
    let scene = crate::input::load(path)?.scene;
    let spec = scene.spec();
    writeln!(
        out,
        "{}: ok — scene `{}`, {} bodies, {} effects, {} coordinates, duration {} s",
        path.display(),
        spec.name,
        spec.bodies.len(),
        spec.effects.len(),
        scene.model().nq(),
        spec.duration
    )?;
    if let Some(t) = scene.trim_report() {
        writeln!(out, "{}", trim_line(t))?;
    }
    let inv: Vec<&str> = scene.invariants().iter().map(|i| i.name()).collect();
    writeln!(
        out,
        "invariants implied by the declared effects: {}",
        if inv.is_empty() { "none".into() } else { inv.join(", ") }
    )?;
    Ok(())
}

/// One line that says what `[trim]` found: each unknown's change from the file's value (SI),
/// the residual |v̇|∞ and the Newton iterations.
pub(crate) fn trim_line(t: &vectrix_scene::TrimReport) -> String {
    let found: Vec<String> = t.free.iter().zip(&t.change).map(|(f, c)| format!("{f} {c:+.6e}")).collect();
    format!(
        "trimmed ({} Newton iterations, residual |v̇|∞ = {:.1e}): {}",
        t.iterations,
        t.residual,
        found.join(", ")
    )
}
