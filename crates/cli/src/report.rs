//! What a run writes into its output folder: `trajectory.csv` (every column with its unit),
//! one SVG per requested output (y label with quantity and unit, drawing that output's columns
//! only) and, for every position output, the path of that body in the plane of its largest
//! motion; last `summary.json` (what was asked, what was done, what it cost, how the invariants
//! drifted, and which files a Ctrl-C or the byte budget left unwritten).
//!
//! Book: §8.3 (invariants), §4.11 (the work of an integration).

use serde::Serialize;
use vectrix_plot::{Chart, Curve, LineChart};
use vectrix_scene::{ConstraintViolation, Drift, Invariant, Run, RunWork, Scene, Stop, TrimReport};

use crate::output::{BoxError, file_stem};
use crate::sink::{Halt, Sink};

/// One CSV column and its SI unit.
#[derive(Debug, Serialize)]
pub(crate) struct Column<'a> {
    pub name: &'a str,
    pub unit: &'a str,
}

/// Contents of summary.json.
#[derive(Debug, Serialize)]
struct Summary<'a> {
    scene: &'a str,
    /// `false` when the run stopped early (see `stop`); the rows hold what was computed.
    complete: bool,
    stop: &'a Option<Stop>,
    /// Requested end time [s].
    duration: f64,
    /// Requested sample intervals.
    samples: usize,
    /// Rows written to trajectory.csv (t = 0 included).
    rows: usize,
    /// Last time written [s].
    t_end: f64,
    columns: Vec<Column<'a>>,
    outputs: &'a [String],
    /// The unit system of the columns and drift values (`si` or `imperial`); each column's unit
    /// is in `columns`.
    units: &'static str,
    invariants: &'a [Invariant],
    drift: &'a [Drift],
    /// Scenes with loops or rolling contacts: the largest |φ|∞ and |G v|∞ of the written rows
    /// after projection (§9.11), and the largest drift projected away at a step end.
    #[serde(skip_serializing_if = "Option::is_none")]
    max_constraint_violation: Option<ConstraintViolation>,
    #[serde(skip_serializing_if = "Option::is_none")]
    max_constraint_drift: Option<ConstraintViolation>,
    work: RunWork,
    /// What `[trim]` found: its unknowns, their change from the file's values, the residual.
    #[serde(skip_serializing_if = "Option::is_none")]
    trim: Option<&'a TrimReport>,
    /// The byte budget of the command's output (`--max-output-bytes`).
    max_output_bytes: u64,
    /// Set when writing stopped before every file was written: then `complete` is false.
    #[serde(skip_serializing_if = "Option::is_none")]
    output_stop: Option<OutputStop<'a>>,
}

/// Why files are missing from an output folder: Ctrl-C (or SIGTERM) while writing, or the
/// byte budget.
#[derive(Debug, Serialize)]
pub(crate) struct OutputStop<'a> {
    /// `interrupted` or `max_output_bytes`.
    reason: &'static str,
    /// The files not written.
    not_written: &'a [String],
    /// What happened and what would be valid.
    message: String,
}

impl<'a> OutputStop<'a> {
    /// The stop of a sink that halted with `not_written` files left.
    pub(crate) fn new(halt: Halt, not_written: &'a [String], max_bytes: u64) -> Self {
        let message = match halt {
            Halt::Interrupted => {
                "interrupted while writing the outputs: the files written are whole, the others are missing"
                    .to_string()
            }
            Halt::Budget => format!(
                "writing stopped at max_output_bytes = {max_bytes}: the files written are whole, the others are \
                 missing; valid: a larger --max-output-bytes, or fewer samples or outputs"
            ),
        };
        Self { reason: halt.name(), not_written, message }
    }
}

/// Whether CSV column `c` belongs to output `o` (`q` → q0, q1, …; `position:b` →
/// position:b.x, …). Exact: outputs are unique in a scene, and body and loop names hold no `.`.
pub(crate) fn belongs(c: &str, o: &str) -> bool {
    c == o
        || c.strip_prefix(o).is_some_and(|r| {
            r.starts_with('.')
                || (matches!(o, "q" | "v") && !r.is_empty() && r.chars().all(|x| x.is_ascii_digit()))
        })
}

/// The columns belonging to output `o`, with their indices.
pub(crate) fn columns_of<'a>(run: &'a Run, o: &str) -> Vec<(usize, &'a str)> {
    run.columns.iter().enumerate().filter(|(_, c)| belongs(c, o)).map(|(k, c)| (k, c.as_str())).collect()
}

/// `kg m^2/s` → `kg m²/s`.
fn pretty_unit(u: &str) -> String {
    u.replace("^2", "²").replace("^3", "³")
}

/// The y label of an output: its quantity and unit(s), e.g. `ω of racket [rad/s]`, `E [J]`.
pub(crate) fn y_label(run: &Run, o: &str) -> String {
    let (kind, body) = o.split_once(':').map_or((o, None), |(k, b)| (k, Some(b)));
    let symbol = match kind {
        "energy" => "E = T + U".to_string(),
        "momentum" => "p".to_string(),
        "angular_momentum" => "H".to_string(),
        "q" => "q".to_string(),
        "v" => "v".to_string(),
        "position" => "r".to_string(),
        "velocity" => "v".to_string(),
        "omega" => "ω".to_string(),
        "omega_body" => "ω (body axes)".to_string(),
        "coordinates" => "q".to_string(),
        "speeds" => "q̇".to_string(),
        "reaction" => "F (and couple M) on the first body".to_string(),
        k => k.to_string(),
    };
    let mut units: Vec<String> = Vec::new();
    for (k, _) in columns_of(run, o) {
        let u = pretty_unit(&run.units[k]);
        if !units.contains(&u) {
            units.push(u);
        }
    }
    let of = body.map(|b| format!(" of {b}")).unwrap_or_default();
    format!("{symbol}{of} [{}]", units.join(", "))
}

/// Writes the files of a body-scene run into the sink, below `prefix` (`""` or `run-003/`):
/// trajectory.csv, contacts.csv, the figures, and last summary.json. Returns whether every
/// file was written (a Ctrl-C or the byte budget may stop the data files; the summary then
/// lists what is missing and says the run is not complete).
///
/// # Errors
/// I/O and plot errors.
pub(crate) fn write_scene(
    sink: &Sink,
    prefix: &str,
    scene: &Scene,
    run: &Run,
    view: Option<&str>,
) -> Result<bool, BoxError> {
    let mut skipped: Vec<String> = Vec::new();
    // renders a data file only while the sink is still writing
    let mut put =
        |file: String, render: &dyn Fn() -> Result<Option<String>, BoxError>| -> Result<(), BoxError> {
            if sink.halt().is_none() {
                match render()? {
                    None => return Ok(()),
                    Some(text) if sink.data(&format!("{prefix}{file}"), text.as_bytes())? => return Ok(()),
                    Some(_) => {}
                }
            }
            skipped.push(file);
            Ok(())
        };
    put("trajectory.csv".into(), &|| Ok(Some(run.to_csv())))?;
    let mut taken = vec!["trajectory".to_string(), "summary".to_string(), "contacts".to_string()];
    if !run.contacts.is_empty() {
        put("contacts.csv".into(), &|| Ok(Some(run.contacts_csv())))?;
    }
    for o in &scene.spec().outputs {
        // each figure draws its own output's columns
        put(format!("{}.svg", file_stem(o, &mut taken)), &|| {
            let mut chart = LineChart::new(format!("{}: {o}", run.scene), "t [s]", y_label(run, o));
            for (k, c) in columns_of(run, o) {
                chart = chart.with_series(c, run.t.iter().zip(&run.rows).map(|(t, r)| (*t, r[k])).collect());
            }
            Ok(Some(chart.to_svg()?))
        })?;
        if let Some(body) = o.strip_prefix("position:") {
            put(format!("{}.svg", file_stem(&format!("path:{body}"), &mut taken)), &|| {
                path_svg(run, o, body)
            })?;
        }
    }
    if let Some(page) = view {
        put("view.html".into(), &|| Ok(Some(page.to_string())))?;
    }
    let stop =
        sink.halt().filter(|_| !skipped.is_empty()).map(|h| OutputStop::new(h, &skipped, sink.max_bytes()));
    let complete = stop.is_none();
    sink.last(
        &format!("{prefix}summary.json"),
        summary_json(scene, run, sink.max_bytes(), stop)?.as_bytes(),
    )?;
    Ok(complete)
}

/// summary.json of a body-scene run; `output_stop` when files are missing.
pub(crate) fn summary_json(
    scene: &Scene,
    run: &Run,
    max_output_bytes: u64,
    output_stop: Option<OutputStop<'_>>,
) -> Result<String, BoxError> {
    let summary = Summary {
        scene: &run.scene,
        complete: run.is_complete() && output_stop.is_none(),
        stop: &run.stop,
        duration: scene.spec().duration,
        samples: scene.spec().samples,
        rows: run.t.len(),
        t_end: run.t.last().copied().unwrap_or(0.0),
        columns: run.columns.iter().zip(&run.units).map(|(n, u)| Column { name: n, unit: u }).collect(),
        outputs: &scene.spec().outputs,
        units: run.unit_system,
        invariants: &run.invariants,
        drift: &run.drift,
        max_constraint_violation: run.max_constraint_violation,
        max_constraint_drift: run.max_constraint_drift,
        work: run.work,
        trim: scene.trim_report(),
        max_output_bytes,
        output_stop,
    };
    Ok(serde_json::to_string_pretty(&summary)?)
}

/// The path of a body in the plane of its two largest coordinate ranges (an orbit, a
/// pendulum bob), drawn with equal scales; `None` when the body does not move.
fn path_svg(run: &Run, o: &str, body: &str) -> Result<Option<String>, BoxError> {
    let cols = columns_of(run, o);
    if cols.len() != 3 {
        return Ok(None);
    }
    let range = |k: usize| {
        let (lo, hi) = run
            .rows
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| (lo.min(r[k]), hi.max(r[k])));
        hi - lo
    };
    let mut axes: Vec<(usize, &str, f64)> = cols.iter().map(|&(k, c)| (k, c, range(k))).collect();
    axes.sort_by(|a, b| b.2.total_cmp(&a.2));
    let ((kx, cx, rx), (ky, cy, _)) = (axes[0], axes[1]);
    if rx.is_nan() || rx <= 0.0 {
        return Ok(None);
    }
    let (kx, cx, ky, cy) = if kx < ky { (kx, cx, ky, cy) } else { (ky, cy, kx, cx) };
    let pts: Vec<(f64, f64)> = run.rows.iter().map(|r| (r[kx], r[ky])).collect();
    let start = pts[0];
    let chart = Chart {
        title: format!("{}: path of {body}", run.scene),
        x_label: format!("{cx} [{}]", run.units[kx]),
        y_label: format!("{cy} [{}]", run.units[ky]),
        equal_aspect: true,
        curves: vec![Curve::new(body, pts, 0)],
        markers: vec![vectrix_plot::Marker {
            at: start,
            shape: vectrix_plot::Shape::Dot,
            color: 1,
            label: Some("t = 0".into()),
        }],
        ..Chart::default()
    };
    Ok(Some(chart.to_svg()?))
}

#[cfg(test)]
mod tests {
    use std::sync::atomic::AtomicBool;

    use super::*;
    use crate::sink::Limits;

    /// Issue 33 item 2: Ctrl-C while the files are written stops at a whole file, and
    /// summary.json says the run is not complete and which files are missing (it used to say
    /// `complete: true` while the writing went on regardless).
    #[test]
    fn an_interrupt_while_writing_makes_the_summary_incomplete() {
        static FLAG: AtomicBool = AtomicBool::new(true);
        let text = vectrix_scene::DEFAULT_SCENE.replace("samples = 800", "samples = 10");
        let scene = Scene::from_toml(&text, "t.toml").unwrap();
        let run = scene.run(&mut |_| {}).unwrap();
        assert!(run.is_complete());
        let d = tempfile::tempdir().unwrap();
        let sink = Sink::with_cancel(d.path(), Limits { max_bytes: 1 << 30, reserve: 0 }, Some(&FLAG));
        assert!(!write_scene(&sink, "", &scene, &run, None).unwrap());
        assert_eq!(sink.files(), ["summary.json"]);
        let s: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(d.path().join("summary.json")).unwrap()).unwrap();
        assert_eq!(s["complete"], false);
        assert_eq!(s["output_stop"]["reason"], "interrupted");
        let missing = s["output_stop"]["not_written"].as_array().unwrap();
        assert_eq!(missing[0], "trajectory.csv");
        assert_eq!(missing.len(), 1 + scene.spec().outputs.len());
        assert_eq!(s["max_output_bytes"], 1u64 << 30);
    }
}
