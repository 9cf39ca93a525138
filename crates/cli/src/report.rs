//! What a run writes into its output folder: `trajectory.csv` (every column with its unit),
//! `summary.json` (what was asked, what was done, what it cost, how the invariants drifted),
//! one SVG per requested output (y label with quantity and unit) and, for every position
//! output, the path of that body in the plane of its largest motion. Flight scenes write their
//! own CSV and figures (`vectrix_scene::flight::FlightRun`).
//!
//! Book: §8.3 (invariants), §4.11 (the work of an integration).

use std::path::Path;

use serde::Serialize;
use vectrix_plot::{Chart, Curve, LineChart};
use vectrix_scene::flight::FlightRun;
use vectrix_scene::{ConstraintViolation, Drift, Invariant, Run, RunWork, Scene, Stop};

use crate::output::{BoxError, file_stem};

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
}

/// The columns belonging to output `o` (`q` → q0, q1, …; `position:b` → position:b.x, …).
pub(crate) fn columns_of<'a>(run: &'a Run, o: &str) -> Vec<(usize, &'a str)> {
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

/// Writes trajectory.csv, summary.json and the figures of a body-scene run into `dir`.
pub(crate) fn write_scene(dir: &Path, scene: &Scene, run: &Run) -> Result<(), BoxError> {
    std::fs::write(dir.join("trajectory.csv"), run.to_csv())?;
    std::fs::write(dir.join("summary.json"), summary_json(scene, run)?)?;
    let mut taken = vec!["trajectory".to_string(), "summary".to_string(), "contacts".to_string()];
    if !run.contacts.is_empty() {
        std::fs::write(dir.join("contacts.csv"), run.contacts_csv())?;
    }
    for o in &scene.spec().outputs {
        let mut chart = LineChart::new(format!("{}: {o}", run.scene), "t [s]", y_label(run, o));
        for (k, c) in columns_of(run, o) {
            chart = chart.with_series(c, run.t.iter().zip(&run.rows).map(|(t, r)| (*t, r[k])).collect());
        }
        std::fs::write(dir.join(format!("{}.svg", file_stem(o, &mut taken))), chart.to_svg()?)?;
        if let Some(body) = o.strip_prefix("position:")
            && let Some(svg) = path_svg(run, o, body)?
        {
            std::fs::write(dir.join(format!("{}.svg", file_stem(&format!("path:{body}"), &mut taken))), svg)?;
        }
    }
    Ok(())
}

/// summary.json of a body-scene run.
pub(crate) fn summary_json(scene: &Scene, run: &Run) -> Result<String, BoxError> {
    let summary = Summary {
        scene: &run.scene,
        complete: run.is_complete(),
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

/// Writes a flight-scene run: trajectory.csv (nonlinear and linear columns), summary.json
/// (trim, modes, linear-model error), one SVG per output and modes.svg.
pub(crate) fn write_flight(dir: &Path, run: &FlightRun) -> Result<(), BoxError> {
    std::fs::write(dir.join("trajectory.csv"), run.to_csv())?;
    std::fs::write(dir.join("summary.json"), run.summary_json())?;
    let mut taken = vec!["trajectory".to_string(), "summary".to_string(), "modes".to_string()];
    for (k, o) in run.outputs.iter().enumerate() {
        std::fs::write(dir.join(format!("{}.svg", file_stem(o, &mut taken))), run.response_svg(k)?)?;
    }
    std::fs::write(dir.join("modes.svg"), run.modes_svg()?)?;
    Ok(())
}
