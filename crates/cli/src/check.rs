//! `vectrix check SCENE`: parse and validate a scene without running it.
//!
//! Book: — (file format).

use std::io::Write;
use std::path::Path;

use vectrix_dynamics::scene::Scene;

/// Loads a scene file, reporting errors with line and column.
pub(crate) fn load(path: &Path) -> Result<Scene, Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(Scene::from_toml(&text, &path.display().to_string())?)
}

/// Validates and prints what the scene declares and which invariants it implies.
pub fn check(out: &mut impl Write, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let scene = load(path)?;
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
    let inv: Vec<&str> = scene.invariants().iter().map(|i| i.name()).collect();
    writeln!(
        out,
        "invariants implied by the declared effects: {}",
        if inv.is_empty() { "none".into() } else { inv.join(", ") }
    )?;
    Ok(())
}
