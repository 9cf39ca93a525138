//! `vectrix check SCENE`: parse and validate a scene without running it.
//!
//! Book: — (file format).

use std::io::Write;
use std::path::Path;

use vectrix_scene::flight::AnyScene;

use crate::output::BoxError;

/// Validates and prints what the scene declares and which invariants it implies.
pub fn check(out: &mut impl Write, path: &Path) -> Result<(), BoxError> {
    let scene = match crate::input::load(path)?.scene {
        AnyScene::Bodies(s) => *s,
        AnyScene::Flight(f) => {
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
