//! `vectrix run [SCENE]`: run a scene (the embedded default when none is given), show a
//! progress bar with an estimated time to completion on long runs, stop cleanly on Ctrl-C or
//! SIGTERM (writing what was computed, marked incomplete), write the outputs within the byte
//! budget (refused before the run when its bound exceeds it) and print a summary.
//!
//! Book: §7.8 (the default scene: torque-free body, tennis-racket flip), §8.3 (invariants).

use std::io::Write;
use std::path::Path;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use vectrix_scene::{DEFAULT_SCENE, InvariantValue, Run, RunControl, Scene, SceneSource, StopReason};
use vectrix_units::UnitSystem;

use crate::input::load;
use crate::interrupt::interrupted;
use crate::output::{BoxError, Written, not_inside, preflight, write_dir};
use crate::sink::Halt;

/// A progress bar that appears after half a second, with an ETA from the elapsed time and
/// the fraction done (elapsed·(1 − f)/f), not from the rate of the last updates.
pub(crate) struct Progress {
    start: Instant,
    name: String,
    quiet: bool,
    bar: Option<ProgressBar>,
}

impl Progress {
    pub fn new(name: &str, quiet: bool) -> Self {
        Self { start: Instant::now(), name: name.to_string(), quiet, bar: None }
    }

    /// Reports fraction `f` ∈ [0, 1] done.
    pub fn update(&mut self, f: f64) {
        if self.quiet || !f.is_finite() {
            return;
        }
        let elapsed = self.start.elapsed();
        if self.bar.is_none() && elapsed > Duration::from_millis(500) && f < 0.9 {
            let b = ProgressBar::new(1000);
            if let Ok(style) = ProgressStyle::with_template("{prefix} [{bar:40}] {percent:>3}% {msg}") {
                b.set_style(style.progress_chars("=> "));
            }
            b.set_prefix(self.name.clone());
            self.bar = Some(b);
        }
        if let Some(b) = &self.bar {
            let pos = (f.clamp(0.0, 1.0) * 1000.0) as u64;
            if pos != b.position() {
                b.set_position(pos);
                let e = elapsed.as_secs_f64();
                let eta = if f > 0.0 { e * (1.0 - f) / f } else { f64::INFINITY };
                b.set_message(format!("{e:.0} s elapsed, ETA {}", human(eta)));
            }
        }
    }

    pub fn finish(self) {
        if let Some(b) = self.bar {
            b.finish_and_clear();
        }
    }
}

/// `75 s`, `3 min 10 s`, `2 h 5 min`.
fn human(s: f64) -> String {
    if !s.is_finite() {
        return "—".into();
    }
    let s = s.round() as u64;
    match s {
        0..60 => format!("{s} s"),
        60..3600 => format!("{} min {} s", s / 60, s % 60),
        _ => format!("{} h {} min", s / 3600, (s % 3600) / 60),
    }
}

/// Runs a loaded scene with a progress bar and Ctrl-C handling.
pub(crate) fn simulate(scene: &Scene, quiet: bool) -> Result<Run, BoxError> {
    let mut bar = Progress::new(&scene.spec().name, quiet);
    let run = scene.run_with(RunControl { progress: &mut |f| bar.update(f), cancel: Some(interrupted()) })?;
    bar.finish();
    Ok(run)
}

fn value(v: &InvariantValue) -> String {
    match v {
        InvariantValue::Scalar(x) => format!("{x:+.9e}"),
        InvariantValue::Vector(x) => format!("[{:+.6e}, {:+.6e}, {:+.6e}]", x[0], x[1], x[2]),
    }
}

/// Prints the short summary of a run.
pub(crate) fn print_summary(out: &mut impl Write, scene: &Scene, run: &Run) -> std::io::Result<()> {
    let w = run.work;
    writeln!(
        out,
        "scene `{}`: t = 0 … {} s, {} rows, {} f-evals, {} steps ({} rejected), {} impacts, {} restarts, {:.3} s wall",
        run.scene,
        run.t.last().copied().unwrap_or(0.0),
        run.t.len(),
        w.fevals,
        w.accepted,
        w.rejected,
        w.impacts,
        w.restarts,
        w.wall_seconds
    )?;
    writeln!(out, "  method             {}", run.method)?;
    if let Some(t) = scene.trim_report() {
        writeln!(out, "  {}", crate::check::trim_line(t))?;
    }
    if let Some(s) = &run.stop {
        writeln!(out, "INCOMPLETE (requested t = 0 … {} s): {}", scene.spec().duration, s.message)?;
    }
    if let (Some(v), Some(d)) = (run.max_constraint_violation, run.max_constraint_drift) {
        writeln!(
            out,
            "  constraints        max violation |φ| {:.2e}, |G v| {:.2e} after projection ({} projections; \
             largest drift corrected |φ| {:.2e}, |G v| {:.2e})",
            v.position, v.velocity, w.projections, d.position, d.velocity
        )?;
    }
    if run.invariants.is_empty() {
        writeln!(out, "no invariants follow from the declared effects")?;
    }
    for d in &run.drift {
        writeln!(
            out,
            "  {:<18} initial {}  max drift {:.2e} (relative {:.2e})",
            d.invariant.name(),
            value(&d.initial),
            d.max_abs,
            d.max_rel
        )?;
    }
    Ok(())
}

/// The budget error of a scene, located at its `samples` key.
pub(crate) fn located(text: &str, file: &str, message: String) -> BoxError {
    match SceneSource::new(text, file) {
        Ok(src) => src.invalid("samples", message).into(),
        Err(e) => e.into(),
    }
}

/// Prints where the output went, its size against the budget, and what writing left out.
pub(crate) fn print_written(out: &mut impl Write, w: &Written, max_bytes: u64) -> std::io::Result<()> {
    if let Some(h) = w.halt {
        writeln!(
            out,
            "INCOMPLETE output: writing stopped ({}); the files written are whole, summary.json lists the others",
            match h {
                Halt::Interrupted => "interrupted",
                Halt::Budget => "max_output_bytes reached",
            }
        )?;
    }
    writeln!(
        out,
        "wrote {} ({}; max_output_bytes = {max_bytes})",
        w.dest.display(),
        crate::budget::human(w.bytes)
    )
}

/// How a run ended, for the process exit code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// The run reached its duration.
    Complete,
    /// A budget stopped it (output written, marked incomplete).
    Budget,
    /// Ctrl-C or SIGTERM stopped the run or its writing (output written, marked incomplete).
    Interrupted,
    /// The run reached its duration, but its numbers are outside the range where they mean
    /// anything (an invariant's drift, a state near the largest f64): output written, marked
    /// incomplete.
    Unreliable,
}

/// The outcome of a run whose run loop ended with `stop` and whose writing with `halt`.
pub(crate) fn outcome(stop: Option<StopReason>, halt: Option<Halt>) -> Outcome {
    match (stop, halt) {
        (Some(StopReason::Interrupted), _) | (_, Some(Halt::Interrupted)) => Outcome::Interrupted,
        (Some(StopReason::MaxSteps | StopReason::MaxWallSeconds), _) | (_, Some(Halt::Budget)) => {
            Outcome::Budget
        }
        (Some(StopReason::InvariantDrift | StopReason::StateOutOfRange), None) => Outcome::Unreliable,
        (None, None) => Outcome::Complete,
    }
}

/// Options of `vectrix run`.
pub(crate) struct Options<'a> {
    /// Parent of the output folder.
    pub dir: &'a Path,
    /// No progress bar.
    pub quiet: bool,
    /// Unit system of the outputs.
    pub units: UnitSystem,
    /// `--max-output-bytes`.
    pub max_bytes: u64,
    /// Write view.html (unless the scene says `view = false`).
    pub view: bool,
}

/// `vectrix run`.
pub(crate) fn run(
    out: &mut impl Write,
    path: Option<&Path>,
    opts: &Options<'_>,
) -> Result<Outcome, BoxError> {
    let &Options { dir, quiet, units, max_bytes, .. } = opts;
    let (text, file, scene) = match path {
        Some(p) => {
            let loaded = load(p)?;
            (loaded.text, loaded.file, loaded.scene)
        }
        None => {
            let file = "<default scene>".to_string();
            (DEFAULT_SCENE.to_string(), file.clone(), Scene::from_toml(DEFAULT_SCENE, &file)?)
        }
    };
    let name = &scene.spec().name;
    if let Some(p) = path {
        not_inside(p, dir, name)?;
    }
    preflight(dir, name)?;
    let view = opts.view && scene.spec().view;
    let mut estimate = crate::budget::scene(&scene);
    if view {
        estimate.data("view.html", crate::budget::scene_view(&scene));
    }
    let limits = estimate.limits(max_bytes).map_err(|m| located(&text, &file, m))?;
    let run = simulate(&scene, quiet)?.in_units(units)?;
    let page =
        view.then(|| crate::view::scene_page(&scene, (&text, &file), &run, units, Some(interrupted())));
    let w = write_dir(dir, name, limits, |sink| {
        crate::report::write_scene(sink, "", &scene, &run, page.as_deref()).map(|_| ())
    })?;
    print_summary(out, &scene, &run)?;
    print_written(out, &w, max_bytes)?;
    Ok(outcome(run.stop.as_ref().map(|s| s.reason), w.halt))
}
