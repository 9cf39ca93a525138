//! `vectrix accuracy`: runs the work–precision harness of vectrix-ode, writes one SVG
//! work–precision diagram per reference problem (error against wall time, log–log, one line
//! per method) and prints the tables of docs/accuracy.md.
//!
//! Book: §4.11; HNW §II.10 (work–precision diagrams).

use std::io::Write;
use std::path::Path;

use vectrix_ode::ACCURACY_TABLE;
use vectrix_ode::harness::{Budget, FILE_STEMS, PROBLEMS, Point, cheapest, derive_accuracy, run_all};
use vectrix_plot::LineChart;

use crate::output::{BoxError, write_dir};
use crate::sink::Limits;

/// Target errors of the "cheapest method" table.
const TARGETS: [f64; 4] = [1e-3, 1e-6, 1e-9, 1e-12];

/// Runs the harness, writes `<dir>/<problem>.svg` (the folder `dir` written like a scene's
/// output folder, see [`crate::output`]) and prints the tables as markdown. `all` also prints
/// every measured point.
///
/// # Errors
/// A `dir` that is not a folder name vectrix may write, I/O errors writing the SVGs or the
/// output, plot errors.
pub fn run(
    out: &mut impl Write,
    dir: &Path,
    quick: bool,
    all: bool,
    max_bytes: u64,
) -> Result<crate::run::Outcome, BoxError> {
    let (parent, name) = split_dir(dir)?;
    crate::output::preflight(parent, name)?;
    let budget = if quick { Budget::Quick } else { Budget::Full };
    let points = run_all(budget);
    let figures = PROBLEMS
        .iter()
        .zip(FILE_STEMS)
        .map(|(problem, stem)| Ok((format!("{stem}.svg"), diagram(&points, problem)?)))
        .collect::<Result<Vec<_>, BoxError>>()?;
    let limits = Limits { max_bytes, reserve: 4096 };
    let w = write_dir(parent, name, limits, |sink| {
        for (file, svg) in &figures {
            sink.data(file, svg.as_bytes())?;
        }
        Ok(())
    })?;
    for f in &w.files {
        writeln!(out, "wrote {}", w.dest.join(f).display())?;
    }
    if w.halt.is_some() {
        writeln!(out, "INCOMPLETE output: writing stopped before every figure was written")?;
    }
    writeln!(out)?;
    cheapest_table(out, &points)?;
    effort_table(out, &points)?;
    drift_table(out, &points)?;
    derived_table(out, &points)?;
    if all {
        writeln!(out, "\n### Every point\n")?;
        writeln!(
            out,
            "| problem | method | rtol or steps | error | time [s] | f-evals | accepted | rejected | Jacobians |"
        )?;
        writeln!(out, "|---|---|---|---|---|---|---|---|---|")?;
        for p in &points {
            writeln!(
                out,
                "| {} | {} | {:.0e} | {:.2e} | {:.2e} | {} | {} | {} | {} |",
                p.problem,
                p.method,
                p.param,
                p.error,
                p.seconds,
                p.work.fevals,
                p.work.accepted,
                p.work.rejected,
                p.work.jacobians
            )?;
        }
    }
    Ok(crate::run::outcome(None, w.halt))
}

/// `docs/accuracy/integrators` → (`docs/accuracy`, `integrators`): the parent folder and the
/// folder's name, which must be a plain name vectrix may write.
fn split_dir(dir: &Path) -> Result<(&Path, &str), BoxError> {
    let name = dir.file_name().and_then(|n| n.to_str()).ok_or_else(|| {
        format!(
            "--out {}: not a folder name; valid: a path ending in a folder name, e.g. out/accuracy",
            dir.display()
        )
    })?;
    let parent = dir.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    Ok((parent, name))
}

/// Methods in the order they appear in `points` for `problem`.
fn methods<'a>(points: &'a [Point], problem: &str) -> Vec<&'a str> {
    let mut m: Vec<&str> = Vec::new();
    for p in points.iter().filter(|p| p.problem == problem) {
        if !m.contains(&p.method) {
            m.push(p.method);
        }
    }
    m
}

/// The diagram of one problem: error against time, log–log, one line per method (points
/// with error above 10 or not finite are left out: the run blew up).
fn diagram(points: &[Point], problem: &str) -> Result<String, BoxError> {
    let mut chart = LineChart::new(
        format!("Work–precision: {problem}"),
        "wall time of one run [s]",
        "max-norm error at the end time",
    )
    .log_log();
    for m in methods(points, problem) {
        let pts: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.problem == problem && p.method == m)
            .filter(|p| p.error.is_finite() && p.error > 0.0 && p.error <= 10.0 && p.seconds > 0.0)
            .map(|p| (p.seconds, p.error.max(1e-16)))
            .collect();
        if !pts.is_empty() {
            chart = chart.with_series(m, pts);
        }
    }
    Ok(chart.to_svg()?)
}

/// For each problem and target error: the cheapest method that reached it.
fn cheapest_table(out: &mut impl Write, points: &[Point]) -> Result<(), BoxError> {
    writeln!(out, "### Cheapest method per target error (wall time of one run, f-evals)\n")?;
    write!(out, "| problem |")?;
    for t in TARGETS {
        write!(out, " error ≤ {t:.0e} |")?;
    }
    writeln!(out, "\n|---|{}", "---|".repeat(TARGETS.len()))?;
    for problem in PROBLEMS {
        write!(out, "| {problem} |")?;
        for t in TARGETS {
            match cheapest(points, problem, t) {
                Some(p) => write!(out, " {} ({:.1e} s, {}) |", p.method, p.seconds, p.work.fevals)?,
                None => write!(out, " — |")?,
            }
        }
        writeln!(out)?;
    }
    Ok(())
}

/// For each problem and method: time to reach 10⁻⁶ and 10⁻⁹ (or the best error reached).
fn effort_table(out: &mut impl Write, points: &[Point]) -> Result<(), BoxError> {
    writeln!(out, "\n### Time to reach an error, per method (best error reached if never)\n")?;
    for problem in PROBLEMS {
        writeln!(out, "**{problem}**\n")?;
        writeln!(out, "| method | error ≤ 1e-6 | error ≤ 1e-9 | best error (time) |")?;
        writeln!(out, "|---|---|---|---|")?;
        for m in methods(points, problem) {
            let runs: Vec<&Point> = points.iter().filter(|p| p.problem == problem && p.method == m).collect();
            let reach = |t: f64| {
                runs.iter()
                    .filter(|p| p.error <= t)
                    .min_by(|a, b| a.seconds.total_cmp(&b.seconds))
                    .map_or("—".to_string(), |p| format!("{:.1e} s", p.seconds))
            };
            let best = runs.iter().min_by(|a, b| a.error.total_cmp(&b.error));
            let best = best.map_or("—".to_string(), |p| format!("{:.1e} ({:.1e} s)", p.error, p.seconds));
            writeln!(out, "| {m} | {} | {} | {best} |", reach(1e-6), reach(1e-9))?;
        }
        writeln!(out)?;
    }
    Ok(())
}

/// Rigid body: drift off SO(3) (|q| − 1 or |RR̄| − 1), of T and of |H| at the finest run.
fn drift_table(out: &mut impl Write, points: &[Point]) -> Result<(), BoxError> {
    writeln!(out, "### Rigid body: drift at the most accurate run of each method (t = 20)\n")?;
    writeln!(out, "| method | error of ω | steps or rtol | off SO(3) | ΔT/T | Δ\\|H\\|/\\|H\\| |")?;
    writeln!(out, "|---|---|---|---|---|---|")?;
    for m in methods(points, "rigid body") {
        let best = points
            .iter()
            .filter(|p| p.problem == "rigid body" && p.method == m)
            .min_by(|a, b| a.error.total_cmp(&b.error));
        if let Some(p) = best
            && let Some([so3, t, h]) = p.drift
        {
            writeln!(out, "| {m} | {:.1e} | {:.0e} | {so3:.1e} | {t:.1e} | {h:.1e} |", p.error, p.param)?;
        }
    }
    Ok(())
}

/// The accuracy table as derived now, next to the one compiled into `Accuracy`.
fn derived_table(out: &mut impl Write, points: &[Point]) -> Result<(), BoxError> {
    writeln!(out, "\n### Accuracy::RelTol table (derived now | compiled in)\n")?;
    writeln!(
        out,
        "| target | derived method | derived rtol | summed time [s] | compiled method | compiled rtol |"
    )?;
    writeln!(out, "|---|---|---|---|---|---|")?;
    for d in derive_accuracy(points) {
        let compiled = ACCURACY_TABLE.iter().find(|r| r.target == d.target);
        let (cm, cr) = compiled.map_or(("—".to_string(), "—".to_string()), |r| {
            (format!("{:?}", r.pair), format!("{:.0e}", r.rtol))
        });
        writeln!(
            out,
            "| {:.0e} | {} | {:.0e} | {:.1e} | {cm} | {cr} |",
            d.target, d.method, d.rtol, d.seconds
        )?;
    }
    Ok(())
}
