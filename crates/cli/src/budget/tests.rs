//! The bounds hold: what the writers produce never exceeds the estimate.

use super::*;
use crate::sink::Sink;
use vectrix_plot::LineChart;

/// A zigzag that thinning cannot shorten (every point far from the last), with values near
/// the largest f64 and long names: the worst case of the figure bound.
#[test]
fn the_figure_bound_holds_for_the_worst_series() {
    let n = 5000;
    let zig = |k: usize, s: f64| (k as f64, if k.is_multiple_of(2) { s * 1e300 } else { -s * 1e300 });
    let names: Vec<String> = (0..9).map(|i| format!("{}{i}", "&<".repeat(20))).collect();
    let mut chart = LineChart::new("&".repeat(100), "<".repeat(50), ">".repeat(50));
    for (i, name) in names.iter().enumerate() {
        chart = chart.with_series(name, (0..n).map(|k| zig(k, 1.0 + i as f64)).collect());
    }
    let svg = chart.to_svg().unwrap();
    let bound = figure(200, names.iter().map(|m| (m.len(), n)));
    assert!((svg.len() as u64) <= bound, "{} > {bound}", svg.len());
    // few points: markers at each
    let small = LineChart::new("t", "x", "y").with_series("a", (0..40).map(|k| zig(k, 1.0)).collect());
    assert!((small.to_svg().unwrap().len() as u64) <= figure(3, [(1, 40)]));
}

/// A real run's files against the estimate of its scene, file by file.
#[test]
fn a_runs_files_fit_its_estimate() {
    let text = vectrix_scene::DEFAULT_SCENE.replace("samples = 800", "samples = 50");
    let scene = Scene::from_toml(&text, "t.toml").unwrap();
    let e = scene_estimate(&scene);
    let run = scene.run(&mut |_| {}).unwrap();
    let d = tempfile::tempdir().unwrap();
    let sink = Sink::with_cancel(d.path(), e.limits(1 << 30).unwrap(), None);
    assert!(crate::report::write_scene(&sink, "", &scene, &run, None).unwrap());
    let size = |f: &str| std::fs::metadata(d.path().join(f)).unwrap().len();
    let part = |n: &str| e.parts.iter().find(|(m, _)| m == n).unwrap().1;
    assert!(size("trajectory.csv") <= part("trajectory.csv"));
    let svgs: u64 = sink.files().iter().filter(|f| f.ends_with(".svg")).map(|f| size(f)).sum();
    assert!(svgs <= part("figures"), "{svgs} > {}", part("figures"));
    assert!(size("summary.json") <= e.summaries);
    assert!(sink.bytes() <= e.total());
}

fn scene_estimate(s: &Scene) -> Estimate {
    scene(s)
}

#[test]
fn an_estimate_over_the_budget_says_what_and_what_is_valid() {
    let mut e = Estimate::default();
    e.data("trajectory.csv", 2_000_000_000);
    e.data("figures", 300_000_000);
    e.summary(10_000);
    let m = e.limits(1 << 30).unwrap_err();
    assert!(m.contains("up to 2.3 GB (trajectory.csv 2.0 GB, figures 300.0 MB)"), "{m}");
    assert!(m.contains("max_output_bytes = 1073741824"), "{m}");
    let l = e.limits(3_000_000_000).unwrap();
    assert_eq!((l.max_bytes, l.reserve), (3_000_000_000, 10_000));
}
