//! Scene output: `trajectory.csv`, `summary.json` and one SVG per requested output (flight
//! scenes add `modes.svg`), written
//! to a temporary folder and renamed into place, so that a folder that exists is complete.
//!
//! Book: — (reporting).

use std::path::{Path, PathBuf};

use serde::Serialize;
use vectrix_dynamics::scene::{Drift, Invariant, Run, RunWork, Scene};
use vectrix_flight::scene::FlightRun;
use vectrix_plot::LineChart;

/// Contents of summary.json.
#[derive(Debug, Serialize)]
struct Summary<'a> {
    scene: &'a str,
    duration: f64,
    samples: usize,
    outputs: &'a [String],
    invariants: &'a [Invariant],
    drift: &'a [Drift],
    work: RunWork,
    wall_seconds: f64,
}

/// The columns belonging to output `o` (`q` → q0, q1, …; `position:b` → position:b.x, …).
fn columns_of<'a>(run: &'a Run, o: &str) -> Vec<(usize, &'a str)> {
    run.columns
        .iter()
        .enumerate()
        .filter(|(_, c)| {
            c.as_str() == o
                || c.strip_prefix(o).is_some_and(|r| {
                    r.starts_with('.')
                        || (matches!(o, "q" | "v") && !r.is_empty() && r.chars().all(|x| x.is_ascii_digit()))
                })
        })
        .map(|(k, c)| (k, c.as_str()))
        .collect()
}

/// File-name form of an output name.
fn file_stem(o: &str) -> String {
    o.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' || c == '-' { c } else { '_' }).collect()
}

/// Writes `<parent>/<scene>/` atomically (temp folder + rename); returns its path.
pub(crate) fn write(parent: &Path, scene: &Scene, run: &Run) -> Result<PathBuf, Box<dyn std::error::Error>> {
    write_dir(parent, &scene.spec().name, |tmp| {
        std::fs::write(tmp.join("trajectory.csv"), run.to_csv())?;
        let summary = Summary {
            scene: &run.scene,
            duration: scene.spec().duration,
            samples: scene.spec().samples,
            outputs: &scene.spec().outputs,
            invariants: &run.invariants,
            drift: &run.drift,
            work: run.work,
            wall_seconds: run.work.wall_seconds,
        };
        std::fs::write(tmp.join("summary.json"), serde_json::to_string_pretty(&summary)?)?;
        for o in &scene.spec().outputs {
            let cols = columns_of(run, o);
            let mut chart = LineChart::new(format!("{}: {o}", run.scene), "t [s]", o.as_str());
            for (k, c) in cols {
                chart = chart.with_series(c, run.t.iter().zip(&run.rows).map(|(t, r)| (*t, r[k])).collect());
            }
            std::fs::write(tmp.join(format!("{}.svg", file_stem(o))), chart.to_svg()?)?;
        }
        Ok(())
    })
}

/// Writes a flight scene's `<parent>/<scene>/`: trajectory.csv (nonlinear and linear columns),
/// summary.json (trim, modes, linear-model error), one SVG per output and modes.svg.
pub(crate) fn write_flight(parent: &Path, run: &FlightRun) -> Result<PathBuf, Box<dyn std::error::Error>> {
    write_dir(parent, &run.scene, |tmp| {
        std::fs::write(tmp.join("trajectory.csv"), run.to_csv())?;
        std::fs::write(tmp.join("summary.json"), run.summary_json())?;
        for (k, o) in run.outputs.iter().enumerate() {
            std::fs::write(tmp.join(format!("{}.svg", file_stem(o))), run.response_svg(k)?)?;
        }
        std::fs::write(tmp.join("modes.svg"), run.modes_svg()?)?;
        Ok(())
    })
}

/// Creates `<parent>/<name>/` atomically: `fill` writes into a temp folder that is renamed
/// into place only when it succeeds.
fn write_dir(
    parent: &Path,
    name: &str,
    fill: impl FnOnce(&Path) -> Result<(), Box<dyn std::error::Error>>,
) -> Result<PathBuf, Box<dyn std::error::Error>> {
    let name = file_stem(name);
    std::fs::create_dir_all(parent)?;
    let tmp =
        parent.join(format!(".{name}.partial-{}-{:?}", std::process::id(), std::thread::current().id()));
    let tmp = PathBuf::from(file_stem_path(&tmp));
    if tmp.exists() {
        std::fs::remove_dir_all(&tmp)?;
    }
    std::fs::create_dir_all(&tmp)?;
    if let Err(e) = fill(&tmp) {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    let dest = parent.join(&name);
    if dest.exists() {
        std::fs::remove_dir_all(&dest)?;
    }
    std::fs::rename(&tmp, &dest)?;
    Ok(dest)
}

/// The temp path with characters that are awkward in file names replaced.
fn file_stem_path(p: &Path) -> String {
    p.display().to_string().replace(['(', ')', ' '], "")
}
