//! `vectrix sweep SCENE --param PATH=v1,v2,…`: the Cartesian product of parameter values,
//! each a full scene run, in parallel on all cores (rayon). Everything goes into one output
//! folder `<out>/<name>-sweep/` written like any other (see [`crate::output`]): `sweep.csv`
//! (one row per run: parameters, completion, work, drift), one overlay SVG per requested
//! output with every run's curves, and `run-000/`, `run-001/`, … with each run's own files.
//! Runs are numbered, so their folders never collide whatever the parameter values; errors of
//! a run point into the user's scene file. A parameter given twice is refused (the table would
//! name values that were not used), and the whole output is bounded before any run starts.
//!
//! Book: — (parameter studies of the scenes of §7.11, ch. 6).

use std::io::Write;
use std::path::Path;
use std::sync::Mutex;

use rayon::prelude::*;
use vectrix_plot::LineChart;
use vectrix_scene::{
    ItemPath, Node, PathSeg, Run, RunControl, Scene, SceneSource, SceneSpec, StopReason, body_schema,
};
use vectrix_units::UnitSystem;

use crate::interrupt::interrupted;
use crate::output::{BoxError, file_stem, not_inside, preflight, write_dir};
use crate::report::{columns_of, y_label};
use crate::run::{Progress, located, outcome, print_written};

/// Most runs one sweep may ask for (the product of the value counts).
pub const MAX_SWEEP_RUNS: usize = 10_000;

/// The item of a parameter path: `effects[0].k`, or dotted with indices as numbers
/// (`effects.0.k`, so `effects.00.k` is the same parameter).
///
/// # Errors
/// A message when the path is not an item path.
fn item_of(path: &str) -> Result<ItemPath, String> {
    let p = ItemPath::parse(path).map_err(|e| format!("--param: {e}"))?;
    let steps = p.segments().iter().map(|s| match s.key().map(str::parse::<usize>) {
        Some(Ok(i)) => PathSeg::Index(i),
        _ => s.clone(),
    });
    Ok(ItemPath::from(steps.collect::<Vec<_>>()))
}

/// One parameter: its path (as given, and as an item) and values; a value may be a quantity
/// string (`2 lbf/ft`), converted by the scene schema's dimension for that key.
fn parse_param(p: &str, doc: &Node) -> Result<(String, ItemPath, Vec<f64>), String> {
    let (path, values) = p.split_once('=').ok_or_else(|| format!("`{p}`: expected PATH=v1,v2,…"))?;
    if path.is_empty() {
        return Err(format!("`{p}`: expected PATH=v1,v2,…"));
    }
    let item = item_of(path)?;
    let expect = body_schema(&item, doc);
    let vals = values
        .split(',')
        .map(|v| match (v.trim().parse::<f64>(), expect) {
            (Ok(x), _) if x.is_finite() => Ok(x),
            (Ok(_), _) => Err(format!("`{v}` in `{p}` is not a finite number")),
            (Err(_), Some(e)) => vectrix_units::Quantity::parse(v.trim())
                .and_then(|q| {
                    let d = e.dims.iter().copied().find(|d| *d == q.dimension()).unwrap_or(e.dims[0]);
                    q.to_si(d)
                })
                .map_err(|err| format!("`{v}` in --param `{p}`: {}", vectrix_scene::unit_message(&err))),
            (Err(_), None) => Err(format!("`{v}` in `{p}` is not a finite number")),
        })
        .collect::<Result<Vec<_>, _>>()?;
    if vals.is_empty() {
        return Err(format!("`{p}`: expected PATH=v1,v2,…"));
    }
    Ok((path.to_string(), item, vals))
}

/// One finished run of the sweep.
struct Done {
    index: usize,
    label: Vec<(String, f64)>,
    scene: Scene,
    run: Run,
    /// Whether every file of the run was written (a Ctrl-C or the byte budget may stop them).
    written: bool,
}

impl Done {
    /// Complete: the run reached its duration with trustworthy numbers, and its files are all
    /// written.
    fn complete(&self) -> bool {
        self.run.is_complete() && self.written
    }
}

/// Where and how a sweep writes.
pub(crate) struct Options<'a> {
    /// Parent directory of the output folder.
    pub dir: &'a Path,
    /// No progress bar.
    pub quiet: bool,
    /// Unit system of the outputs.
    pub units: UnitSystem,
    /// The byte budget.
    pub max_output_bytes: u64,
    /// `Some((k, n))`: run only the k-th of n slices (1 ≤ k ≤ n), see [`parse_shard`].
    pub shard: Option<(usize, usize)>,
}

/// `K/N` of `--shard`: the runs whose number i (0-based, in the order of the unsharded sweep)
/// has i mod N = K − 1, so that the slices of a grid take about equal work; 1 ≤ K ≤ N ≤
/// [`MAX_SWEEP_RUNS`]. Slurm: `--array=1-N` and `--shard $SLURM_ARRAY_TASK_ID/N`.
pub(crate) fn parse_shard(s: &str) -> Result<(usize, usize), String> {
    let bad = || format!("--shard `{s}`; valid: K/N with 1 ≤ K ≤ N ≤ {MAX_SWEEP_RUNS} (e.g. 3/8)");
    let (k, n) = s.split_once('/').ok_or_else(bad)?;
    let (k, n): (usize, usize) = (k.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
    if !(1 <= k && k <= n && n <= MAX_SWEEP_RUNS) {
        return Err(bad());
    }
    Ok((k, n))
}

/// Refuses a parameter given twice (`--param duration=1,2 --param duration=3`): every run
/// would use the last value while the table named the others.
fn unique(params: &[String]) -> Result<(), String> {
    let paths: Vec<(&str, ItemPath)> = params
        .iter()
        .map(|p| Ok((p.as_str(), item_of(p.split_once('=').map_or(p.as_str(), |(a, _)| a))?)))
        .collect::<Result<_, String>>()?;
    for (k, (p, s)) in paths.iter().enumerate() {
        if let Some((q, _)) = paths[..k].iter().find(|(_, t)| t == s) {
            return Err(format!(
                "--param `{p}` repeats the parameter of --param `{q}`; valid: each parameter once, with all its \
                 values in one list (`PATH=v1,v2,…`)"
            ));
        }
    }
    Ok(())
}

/// The runs of a sweep, in the order of the unsharded sweep: each run's global number, its
/// parameter values and its scene, every one validated before any is run (errors point into
/// the user's file).
type Planned = Vec<(usize, Vec<(String, f64)>, Scene)>;

/// `vectrix sweep`.
pub(crate) fn sweep(
    out: &mut impl Write,
    path: &Path,
    params: &[String],
    opts: &Options<'_>,
) -> Result<crate::run::Outcome, BoxError> {
    unique(params)?;
    let loaded = crate::input::load(path)?;
    let base_scene = loaded.scene;
    let (text, file) = (&loaded.text, &loaded.file);
    let src = SceneSource::new(text, file)?;
    // quantity strings ("675.124 ft/s") become SI numbers first, as when the scene loaded: the
    // swept values are SI numbers too
    let doc = src.document(&body_schema)?;
    let params = params.iter().map(|p| parse_param(p, &doc)).collect::<Result<Vec<_>, _>>()?;
    let planned = plan(&params, &doc, &src, opts.shard)?;
    let total = planned.len();
    let name = match opts.shard {
        Some((k, n)) => format!("{}-sweep-shard-{k}-of-{n}", base_scene.spec().name),
        None => format!("{}-sweep", base_scene.spec().name),
    };
    let dir = opts.dir;
    not_inside(path, dir, &name)?;
    preflight(dir, &name)?;
    let scenes: Vec<&Scene> = planned.iter().map(|(_, _, s)| s).collect();
    let labels: Vec<usize> = planned.iter().map(|(_, c, _)| describe(c).len()).collect();
    let limits = crate::budget::sweep(&scenes, &labels, params.len())
        .limits(opts.max_output_bytes)
        .map_err(|m| located(text, file, format!("{total} runs: {m}")))?;
    let mut done = run_all(planned, &name, opts)?;
    let w = write_dir(dir, &name, limits, |sink| {
        // each run's folder (CSV, summary, figures) on all cores too: serial, the writing was
        // a tenth of a two-core sweep's wall time
        let written = done
            .par_iter()
            .map(|d| -> Result<bool, String> {
                let sub = format!("run-{:03}", d.index);
                sink.dir(&sub).map_err(|e| e.to_string())?;
                crate::report::write_scene(sink, &format!("{sub}/"), &d.scene, &d.run, None)
                    .map_err(|e| e.to_string())
            })
            .collect::<Result<Vec<bool>, String>>()?;
        for (d, w) in done.iter_mut().zip(written) {
            d.written = w;
        }
        let mut taken = vec!["sweep".to_string()];
        let stems: Vec<(String, &_)> =
            base_scene.spec().outputs.iter().map(|o| (file_stem(o, &mut taken), o)).collect();
        for (stem, o) in stems {
            if sink.halt().is_none() {
                sink.data(&format!("{stem}.svg"), overlay(&name, o, &done)?.as_bytes())?;
            }
        }
        sink.last("sweep.csv", sweep_csv(&params, &done).as_bytes())?;
        Ok(())
    })?;
    print_table(out, &done)?;
    print_written(out, &w, opts.max_output_bytes)?;
    // an interrupted run first, else the first run that stopped, says how the sweep ended
    let reasons = || done.iter().filter_map(|d| d.run.stop.as_ref().map(|s| s.reason));
    let stop = reasons().find(|r| *r == StopReason::Interrupted).or_else(|| reasons().next());
    Ok(outcome(stop, w.halt))
}

/// The Cartesian product of the parameters' values, the shard's slice of it (keeping the
/// global run numbers) and each run's scene: the document with the run's numbers set.
fn plan(
    params: &[(String, ItemPath, Vec<f64>)],
    doc: &Node,
    src: &SceneSource<'_>,
    shard: Option<(usize, usize)>,
) -> Result<Planned, BoxError> {
    let total = params.iter().try_fold(1usize, |n, (_, _, v)| n.checked_mul(v.len())).unwrap_or(usize::MAX);
    if total > MAX_SWEEP_RUNS {
        return Err(format!("the sweep asks for {total} runs; valid: at most {MAX_SWEEP_RUNS}").into());
    }
    let mut combos: Vec<Vec<(String, f64)>> = vec![vec![]];
    for (p, _, vals) in params {
        combos = combos
            .into_iter()
            .flat_map(|c| vals.iter().map(move |v| [c.clone(), vec![(p.clone(), *v)]].concat()))
            .collect();
    }
    combos
        .into_iter()
        .enumerate()
        .filter(|(i, _)| shard.is_none_or(|(k, n)| i % n == k - 1))
        .map(|(index, combo)| -> Result<_, BoxError> {
            let mut d = doc.clone();
            for (p, v) in &combo {
                let item = params.iter().find(|(q, _, _)| q == p).map(|(_, item, _)| item);
                let item = item.ok_or_else(|| format!("--param `{p}` has no item path"))?;
                d.set_number(item, *v).map_err(|m| src.invalid(item, m))?;
            }
            let spec: SceneSpec = src.read_document(&d)?;
            let scene = Scene::from_spec_in(spec, src)?;
            Ok((index, combo, scene))
        })
        .collect()
}

/// Every planned run on all cores, with a progress line; an error when any run failed
/// (nothing is written then), naming how many and the first.
fn run_all(planned: Planned, name: &str, opts: &Options<'_>) -> Result<Vec<Done>, BoxError> {
    let total = planned.len();
    let progress = Mutex::new((Progress::new(name, opts.quiet), 0usize));
    let results: Vec<Result<Done, String>> = planned
        .into_par_iter()
        .map(|(index, label, scene)| {
            let run = scene
                .run_with(RunControl { progress: &mut |_| {}, cancel: Some(interrupted()) })
                .and_then(|r| r.in_units(opts.units))
                .map_err(|e| format!("run {index} ({}): {e}", describe(&label)))?;
            if let Ok(mut p) = progress.lock() {
                p.1 += 1;
                let f = p.1 as f64 / total as f64;
                p.0.update(f);
            }
            Ok(Done { index, label, scene, run, written: true })
        })
        .collect();
    if let Ok(p) = progress.into_inner() {
        p.0.finish();
    }
    let (mut done, mut failed) = (Vec::new(), Vec::new());
    for r in results {
        match r {
            Ok(d) => done.push(d),
            Err(e) => failed.push(e),
        }
    }
    if let Some(first) = failed.first() {
        return Err(format!(
            "{} of {total} sweep runs failed (nothing written); first: {first}",
            failed.len()
        )
        .into());
    }
    Ok(done)
}

/// The table of runs on standard output.
fn print_table(out: &mut impl Write, done: &[Done]) -> std::io::Result<()> {
    writeln!(out, "| run | parameters | complete | wall [s] | f-evals | drift |\n|---|---|---|---|---|---|")?;
    for d in done {
        let drift: Vec<String> =
            d.run.drift.iter().map(|x| format!("{} {:.1e}", x.invariant.name(), x.max_rel)).collect();
        writeln!(
            out,
            "| {:03} | {} | {} | {:.3} | {} | {} |",
            d.index,
            describe(&d.label),
            d.complete(),
            d.run.work.wall_seconds,
            d.run.work.fevals,
            drift.join("; ")
        )?;
    }
    Ok(())
}

fn describe(label: &[(String, f64)]) -> String {
    label.iter().map(|(p, v)| format!("{p}={v}")).collect::<Vec<_>>().join(", ")
}

/// sweep.csv: one row per run.
fn sweep_csv(params: &[(String, ItemPath, Vec<f64>)], done: &[Done]) -> String {
    let checks: Vec<&str> =
        done.first().map(|d| d.run.drift.iter().map(|x| x.invariant.name()).collect()).unwrap_or_default();
    let mut s = String::from("run");
    for (p, _, _) in params {
        s.push_str(&format!(",{p}"));
    }
    s.push_str(",complete,rows,fevals,accepted,rejected,wall_seconds");
    for c in &checks {
        s.push_str(&format!(",{c}_max_rel_drift"));
    }
    s.push('\n');
    for d in done {
        s.push_str(&format!("{:03}", d.index));
        for (_, v) in &d.label {
            s.push_str(&format!(",{v:e}"));
        }
        let w = d.run.work;
        s.push_str(&format!(
            ",{},{},{},{},{},{:e}",
            d.complete(),
            d.run.t.len(),
            w.fevals,
            w.accepted,
            w.rejected,
            w.wall_seconds
        ));
        for x in &d.run.drift {
            s.push_str(&format!(",{:e}", x.max_rel));
        }
        s.push('\n');
    }
    s
}

/// All runs' curves of one output on one chart.
fn overlay(name: &str, o: &str, done: &[Done]) -> Result<String, BoxError> {
    let Some(first) = done.first() else { return Err("no runs".into()) };
    let mut chart = LineChart::new(format!("{name}: {o}"), "t [s]", y_label(&first.run, o));
    for d in done {
        for (k, c) in columns_of(&d.run, o) {
            let pts = d.run.t.iter().zip(&d.run.rows).map(|(t, r)| (*t, r[k])).collect();
            chart = chart.with_series(format!("{c} ({})", describe(&d.label)), pts);
        }
    }
    Ok(chart.to_svg()?)
}
