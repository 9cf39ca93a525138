//! The stiff work–precision figures: one log–log panel per problem (end error against the
//! median wall time of a run, one line per method), drawn by vectrix-plot from the sitting's
//! JSON files (`{"tool": …, "points": [{"problem", "tool", "err", "secs", …}]}`), written as
//! `<svg dir>/stiff-<problem>.svg`.

use std::path::Path;

use vectrix_plot::{Chart, Curve, Marker, Shape, Stroke};

/// Problem id, panel title and the error's meaning.
const PANELS: [(&str, &str, &str); 5] = [
    (
        "chain",
        "Damped spring chain (6 masses, k = 1e6, c = 1e5, t = 0.2)",
        "max |x − x*| / max |x(0)| (modal closed form)",
    ),
    (
        "pendulum",
        "Pendulum on a stiff spring (k/m = 9.81e4, g/l = 9.81, t = 2)",
        "max |r − r*| / l₀ (scipy Radau at 1e-13)",
    ),
    ("damper", "Hinge with a stiff damper (λ ≈ −0.1, −1e4 /s, t = 10)", "|θ − θ*| / θ₀ (closed form)"),
    ("robertson", "Robertson's kinetics (t = 1e5)", "max relative error (scipy Radau at 1e-13)"),
    ("vdp", "Van der Pol μ = 1000 (VDPOL, t = 2)", "max relative error (Test Set end state)"),
];

/// Legend order: vectrix first, then the peers.
const ORDER: [&str; 11] = [
    "vectrix RADAU5",
    "vectrix BDF",
    "vectrix DOP853",
    "scipy Radau",
    "scipy BDF",
    "scipy LSODA",
    "diffsol bdf",
    "diffsol esdirk34",
    "diffsol tr_bdf2",
    "MuJoCo implicitfast",
    "MuJoCo RK4",
];

/// Errors above this are not drawn (a run that blew up or barely started to converge).
const MAX_DRAWN_ERROR: f64 = 1.0;

/// Marker, stroke and legend glyph per tool, as the frontier figures: vectrix's stiff methods
/// solid with dots, the wrong method dotted, scipy dotted with +, diffsol dashed with ○,
/// MuJoCo dashed with ×.
fn style(series: &str) -> (Shape, Stroke, &'static str) {
    match series.split(' ').next() {
        _ if series == "vectrix DOP853" => (Shape::Dot, Stroke::Dotted, "●"),
        Some("vectrix") => (Shape::Dot, Stroke::Solid, "●"),
        Some("scipy") => (Shape::Plus, Stroke::Dotted, "+"),
        Some("diffsol") => (Shape::Circle, Stroke::Dashed, "○"),
        Some("MuJoCo") => (Shape::Cross, Stroke::Dashed, "×"),
        _ => (Shape::Plus, Stroke::Dashed, "✚"),
    }
}

/// One palette index per method on every panel. vectrix-plot has seven colours and moves a
/// curve's dash one step along solid → dashed → dotted → dash-dot each time the index wraps;
/// indices 14–16 give the dashed peers the dash-dot style, unused by any other series, so no
/// two series of a panel share both colour and dash (diffsol and MuJoCo never share a panel).
fn colour(series: &str) -> Option<usize> {
    Some(match series {
        "vectrix RADAU5" => 0,
        "vectrix BDF" => 1,
        "vectrix DOP853" => 2,
        "scipy Radau" => 3,
        "scipy BDF" => 4,
        "scipy LSODA" => 5,
        "diffsol bdf" | "MuJoCo implicitfast" => 6,
        "MuJoCo RK4" => 14,
        "diffsol esdirk34" => 15,
        "diffsol tr_bdf2" => 16,
        _ => return None,
    })
}

/// (problem, series, error, seconds) of every point with a finite, positive error.
fn points(data: &Path) -> Vec<(String, String, f64, f64)> {
    let mut out = Vec::new();
    let mut files: Vec<_> =
        std::fs::read_dir(data).expect("data dir").filter_map(|e| e.ok().map(|e| e.path())).collect();
    files.sort();
    for file in files.iter().filter(|f| f.extension().is_some_and(|e| e == "json")) {
        // the peers' Python json writes failed runs as Infinity, which serde_json refuses
        let text = std::fs::read_to_string(file).expect("read").replace("Infinity", "null");
        let v: serde_json::Value =
            serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        for p in v["points"].as_array().into_iter().flatten() {
            let (Some(problem), Some(tool), Some(err), Some(secs)) =
                (p["problem"].as_str(), p["tool"].as_str(), p["err"].as_f64(), p["secs"].as_f64())
            else {
                continue; // a failed run: no error to draw
            };
            if err > 0.0 && err <= MAX_DRAWN_ERROR && secs > 0.0 {
                out.push((problem.to_string(), tool.to_string(), err, secs));
            }
        }
    }
    out
}

/// Writes `stiff-<problem>.svg` for every problem with points.
pub fn plot(data: &str, svg_dir: &str) {
    let pts = points(Path::new(data));
    for (id, title, x_label) in PANELS {
        let mut series: Vec<&str> =
            ORDER.iter().copied().filter(|s| pts.iter().any(|p| p.0 == id && p.1 == *s)).collect();
        // any series not in ORDER still gets drawn, after the known ones
        for p in pts.iter().filter(|p| p.0 == id) {
            if !series.contains(&p.1.as_str()) {
                series.push(&p.1);
            }
        }
        if series.is_empty() {
            continue;
        }
        let mut chart = Chart {
            title: title.into(),
            x_label: format!("end error: {x_label}"),
            y_label: "median wall time of a run [s]".into(),
            log_x: true,
            log_y: true,
            ..Chart::default()
        };
        for (i, name) in series.iter().enumerate() {
            let color = colour(name).unwrap_or(21 + i);
            let mut line: Vec<(f64, f64)> =
                pts.iter().filter(|p| p.0 == id && p.1 == *name).map(|p| (p.2, p.3)).collect();
            line.sort_by(|a, b| b.0.total_cmp(&a.0));
            let (shape, stroke, glyph) = style(name);
            for &at in &line {
                chart.markers.push(Marker { at, shape, color, label: None });
            }
            chart.curves.push(Curve {
                name: Some(format!("{glyph} {name}")),
                points: line,
                color,
                stroke,
                markers: false,
            });
        }
        let svg = chart.to_svg().expect("figure");
        let path = Path::new(svg_dir).join(format!("stiff-{id}.svg"));
        std::fs::write(&path, svg).expect("write svg");
        eprintln!("wrote {}", path.display());
    }
}
