//! `vectrix run [SCENE]`: run a scene (the embedded default when none is given), show a
//! progress bar on long runs, write the outputs and print a short summary.
//!
//! Book: §7.8 (the default scene: torque-free body, tennis-racket flip), §8.3 (invariants).

use std::io::Write;
use std::path::Path;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use vectrix_dynamics::scene::{DEFAULT_SCENE, Run, Scene};
use vectrix_flight::scene::FlightScene;

/// Runs a loaded scene with a progress bar that appears only after half a second.
pub(crate) fn simulate(scene: &Scene, quiet: bool) -> Result<Run, Box<dyn std::error::Error>> {
    let start = Instant::now();
    let mut bar: Option<ProgressBar> = None;
    let mut progress = |f: f64| {
        if quiet {
            return;
        }
        if bar.is_none() && start.elapsed() > Duration::from_millis(500) && f < 0.9 {
            let b = ProgressBar::new(1000);
            if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:40}] {percent}% eta {eta}") {
                b.set_style(style);
            }
            b.set_message(scene.spec().name.clone());
            bar = Some(b);
        }
        if let Some(b) = &bar {
            b.set_position((f * 1000.0) as u64);
        }
    };
    let run = scene.run(&mut progress)?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    Ok(run)
}

/// Prints the short summary of a run.
pub(crate) fn print_summary(out: &mut impl Write, scene: &Scene, run: &Run) -> std::io::Result<()> {
    let w = run.work;
    writeln!(
        out,
        "scene `{}`: t = 0 … {} s, {} samples, {} f-evals, {} steps ({} rejected), {} impacts, {:.3} s wall",
        run.scene,
        scene.spec().duration,
        run.t.len(),
        w.fevals,
        w.accepted,
        w.rejected,
        w.impacts,
        w.wall_seconds
    )?;
    if run.invariants.is_empty() {
        writeln!(out, "no invariants follow from the declared effects")?;
    }
    for d in &run.drift {
        writeln!(
            out,
            "  {:<18} initial {:.6e}  max drift {:.2e} (relative {:.2e})",
            d.invariant.name(),
            d.initial,
            d.max_abs,
            d.max_rel
        )?;
    }
    Ok(())
}

/// `vectrix run`.
pub fn run(
    out: &mut impl Write,
    path: Option<&Path>,
    dir: &Path,
    quiet: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let scene = match path {
        Some(p) => match crate::check::load_any(p)? {
            crate::check::Loaded::Bodies(s) => *s,
            crate::check::Loaded::Flight(f) => return run_flight(out, &f, dir),
        },
        None => Scene::from_toml(DEFAULT_SCENE, "<default scene>")?,
    };
    let run = simulate(&scene, quiet)?;
    let dest = crate::output::write(dir, &scene, &run)?;
    print_summary(out, &scene, &run)?;
    writeln!(out, "wrote {}", dest.display())?;
    Ok(())
}

/// `vectrix run` on a flight scene: trim, nonlinear and linear responses, modes.
fn run_flight(
    out: &mut impl Write,
    scene: &FlightScene,
    dir: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let start = Instant::now();
    let run = scene.run()?;
    let dest = crate::output::write_flight(dir, &run)?;
    writeln!(
        out,
        "flight scene `{}`: t = 0 … {} s, {} samples, {} f-evals, {} steps, {:.3} s wall",
        run.scene,
        scene.spec().duration,
        run.t.len(),
        run.fevals,
        run.steps,
        start.elapsed().as_secs_f64()
    )?;
    for m in &run.modes {
        writeln!(
            out,
            "  {:<13} λ = {:+.5} ± {:.5}j  ωn = {:.4} rad/s  ζ = {:.4}",
            m.name, m.re, m.im, m.natural_frequency, m.damping_ratio
        )?;
    }
    for (k, o) in run.outputs.iter().enumerate() {
        match run.max_linear_error(k) {
            Some(e) => writeln!(
                out,
                "  {o:<9} max excursion {:.3e}, linear model off by ≤ {e:.2e}",
                run.max_excursion(k)
            )?,
            None => writeln!(out, "  {o:<9} max excursion {:.3e}", run.max_excursion(k))?,
        }
    }
    writeln!(out, "wrote {}", dest.display())?;
    Ok(())
}
