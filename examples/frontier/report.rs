//! Reading the frontier points of every tool, the time to reach an error along each tool's
//! frontier, the figures and the table.

use serde_json::Value;
use vectrix::plot::{Chart, Curve, Marker, Shape, Stroke};

/// One point as read back from any tool's JSON.
#[derive(Debug, Clone, PartialEq)]
pub struct Pt {
    pub problem: String,
    pub series: String,
    pub tool: String,
    pub route: String,
    /// Error (`None`: the run failed or blew up).
    pub error: Option<f64>,
    /// Wall time of the run plus the tool's one-off setup (sympy's derivation).
    pub seconds: f64,
}

impl Pt {
    /// A point from one entry of a tool's `points` array.
    pub fn from_json(v: &Value) -> Option<Self> {
        let s = |k: &str| v.get(k).and_then(Value::as_str).map(str::to_string);
        let seconds =
            v.get("seconds")?.as_f64()? + v.get("setup_seconds").and_then(Value::as_f64).unwrap_or(0.0);
        Some(Self {
            problem: s("problem")?,
            series: s("series")?,
            tool: s("tool")?,
            route: s("route").unwrap_or_default(),
            error: v.get("error").and_then(Value::as_f64).filter(|e| e.is_finite()),
            seconds,
        })
    }

    /// The family a point belongs to in the table: vectrix's library and scene routes apart.
    pub fn family(&self) -> String {
        match (self.tool.as_str(), self.route.as_str()) {
            ("vectrix", "scene") => "vectrix scene".into(),
            ("vectrix", _) => "vectrix library".into(),
            (t, _) => t.into(),
        }
    }
}

/// The time one series needs to reach `target`: along the series' Pareto front (its points
/// sorted by time, keeping each point that lowers the error of every cheaper one), the time
/// is interpolated linearly in log error – log time between the last front point above the
/// target and the first at or below it. `None` when no point reaches the target; `Some((t,
/// true))` when even the cheapest point is below it (then t is an upper bound).
pub fn time_to_reach(points: &[(f64, f64)], target: f64) -> Option<(f64, bool)> {
    let mut pts: Vec<(f64, f64)> =
        points.iter().copied().filter(|(e, t)| *e > 0.0 && e.is_finite() && *t > 0.0).collect();
    pts.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.total_cmp(&b.0)));
    let mut front: Vec<(f64, f64)> = Vec::new();
    for p in pts {
        if front.last().is_none_or(|l| p.0 < l.0) {
            front.push(p);
        }
    }
    let k = front.iter().position(|(e, _)| *e <= target)?;
    if k == 0 {
        return Some((front[0].1, true));
    }
    let ((e0, t0), (e1, t1)) = (front[k - 1], front[k]);
    let s = (target.ln() - e0.ln()) / (e1.ln() - e0.ln());
    Some(((t0.ln() + s * (t1.ln() - t0.ln())).exp(), false))
}

/// The fastest series of `family` at `target`: (time, upper bound?, series).
pub fn family_time(pts: &[Pt], problem: &str, family: &str, target: f64) -> Option<(f64, bool, String)> {
    let mut names: Vec<&str> = pts
        .iter()
        .filter(|p| p.problem == problem && p.family() == family)
        .map(|p| p.series.as_str())
        .collect();
    names.dedup();
    names.sort_unstable();
    names.dedup();
    names
        .into_iter()
        .filter_map(|s| {
            let line: Vec<(f64, f64)> = pts
                .iter()
                .filter(|p| p.problem == problem && p.series == s)
                .filter_map(|p| p.error.map(|e| (e, p.seconds)))
                .collect();
            time_to_reach(&line, target).map(|(t, ub)| (t, ub, s.to_string()))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
}

/// Marker shape, stroke and legend glyph of a family.
fn style(family: &str) -> (Shape, Stroke, &'static str) {
    match family {
        "vectrix library" => (Shape::Dot, Stroke::Solid, "●"),
        "vectrix scene" => (Shape::Circle, Stroke::Solid, "○"),
        "mujoco" => (Shape::Cross, Stroke::Dashed, "×"),
        "mujoco-c" => (Shape::Cross, Stroke::Solid, "×"),
        "odeint" => (Shape::Plus, Stroke::Solid, "+"),
        "scipy" => (Shape::Plus, Stroke::Dotted, "+"),
        "sympy" => (Shape::Circle, Stroke::Dashed, "◌"),
        _ => (Shape::Plus, Stroke::Dashed, "✚"),
    }
}

/// Errors above this are not drawn (a run that blew up or barely started to converge).
pub const MAX_DRAWN_ERROR: f64 = 1.0;

/// One figure: every series of `problem`, error against time on log–log axes, the colour
/// per series, the stroke and marker per family (legend entries start with the marker).
pub fn figure(pts: &[Pt], problem: &str, title: &str, x_label: &str) -> Chart {
    let mut series: Vec<(String, String)> = Vec::new();
    for p in pts.iter().filter(|p| p.problem == problem) {
        if !series.iter().any(|(s, _)| *s == p.series) {
            series.push((p.series.clone(), p.family()));
        }
    }
    let mut chart = Chart {
        title: title.into(),
        x_label: x_label.into(),
        y_label: "wall time of a run [s]".into(),
        log_x: true,
        log_y: true,
        ..Chart::default()
    };
    for (color, (name, family)) in series.iter().enumerate() {
        let (shape, stroke, glyph) = style(family);
        let mut line: Vec<(f64, f64)> = pts
            .iter()
            .filter(|p| p.problem == problem && p.series == *name)
            .filter_map(|p| p.error.filter(|e| *e > 0.0 && *e <= MAX_DRAWN_ERROR).map(|e| (e, p.seconds)))
            .collect();
        line.sort_by(|a, b| a.1.total_cmp(&b.1));
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
    chart
}

/// Formats a time with a unit and three significant digits.
pub fn fmt_time(t: f64) -> String {
    let (v, unit) = if t >= 1.0 {
        (t, "s")
    } else if t >= 1e-3 {
        (t * 1e3, "ms")
    } else {
        (t * 1e6, "µs")
    };
    let decimals = if v >= 100.0 {
        0
    } else if v >= 10.0 {
        1
    } else {
        2
    };
    format!("{v:.decimals$} {unit}")
}
