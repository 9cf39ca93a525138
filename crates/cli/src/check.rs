//! `vectrix check SCENE`: parse and validate a scene without running it.
//!
//! Book: — (file format).

use std::io::Write;
use std::path::Path;

use vectrix_dynamics::scene::Scene;
use vectrix_flight::scene::FlightScene;

/// A loaded scene file: a multibody scene or a flight scene (one with an `[aircraft]` table).
pub(crate) enum Loaded {
    /// Bodies, joints and effects (`vectrix_dynamics::scene`).
    Bodies(Box<Scene>),
    /// An aircraft, its trim and control inputs (`vectrix_flight::scene`).
    Flight(Box<FlightScene>),
}

/// Whether a scene text declares an aircraft (top-level `[aircraft]` table).
pub(crate) fn is_flight(text: &str) -> bool {
    text.parse::<toml::Table>().is_ok_and(|t| t.contains_key("aircraft"))
}

/// Loads a scene file of either kind, reporting errors with line and column.
pub(crate) fn load_any(path: &Path) -> Result<Loaded, Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let file = path.display().to_string();
    Ok(if is_flight(&text) {
        Loaded::Flight(Box::new(FlightScene::from_toml(&text, &file)?))
    } else {
        Loaded::Bodies(Box::new(Scene::from_toml(&text, &file)?))
    })
}

/// Loads a multibody scene file, reporting errors with line and column.
pub(crate) fn load(path: &Path) -> Result<Scene, Box<dyn std::error::Error>> {
    match load_any(path)? {
        Loaded::Bodies(s) => Ok(*s),
        Loaded::Flight(_) => Err(format!(
            "{}: a flight scene (it has an [aircraft] table); `vectrix run` and `vectrix check` take it, \
             sweeps take multibody scenes only",
            path.display()
        )
        .into()),
    }
}

/// Validates and prints what the scene declares and which invariants it implies.
pub fn check(out: &mut impl Write, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let scene = match load_any(path)? {
        Loaded::Bodies(s) => *s,
        Loaded::Flight(f) => {
            let t = &f.linearization().trim;
            writeln!(
                out,
                "{}: ok — flight scene `{}`, aircraft `{}`, trimmed at α = {:.4} rad, δe = {:.4} rad, thrust = {:.1} \
                 (residual {:.1e}), {} inputs, duration {} s",
                path.display(),
                f.spec().name,
                f.spec().aircraft.model,
                t.state.aero_angles().alpha,
                t.controls.elevator,
                t.controls.thrust,
                t.residual,
                f.spec().inputs.len(),
                f.spec().duration
            )?;
            return Ok(());
        }
    };
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
