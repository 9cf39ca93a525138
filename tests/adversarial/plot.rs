//! vectrix-plot under hostile input (docs/robustness.md): a figure is valid SVG with finite
//! coordinates (never `NaN` or `inf` in an attribute) or a typed error (empty, non-finite,
//! non-positive on a log axis, invalid range).

use vectrix::plot::{Curve, Figure, LineChart, Series};

use crate::harness::{err_or, hostile, refused};

/// Every number in the SVG is finite: no `NaN`, `inf` in any attribute.
fn finite_svg(svg: &str) -> bool {
    svg.starts_with("<svg") && !svg.contains("NaN") && !svg.contains("inf")
}

cases! {
    // Line charts over data from ±1e308 to subnormal: the axes are laid out with half-spans
    // (the named bug wrote y1="NaN" for ±1e308); NaN/∞ data and log axes with values ≤ 0 are
    // refused; an empty chart is refused.
    line_charts ["LineChart::new", "LineChart::log_log", "LineChart::with_series", "LineChart::to_chart",
        "LineChart::to_svg", "Series::new"] {
        let extremes = [(0.0, -1e308), (1.0, 1e308)];
        let c = LineChart::new("extremes", "x", "y").with_series("s", extremes.to_vec());
        let svg = c.to_svg().expect("finite data over ±1e308 is plottable");
        assert!(finite_svg(&svg), "{svg}");
        for a in hostile() {
            for b in hostile() {
                let c = LineChart::new("t", "x", "y").with_series("s", vec![(0.0, a), (1.0, b)]);
                if let Ok(svg) = c.to_svg() {
                    let bad = svg.find("NaN").or_else(|| svg.find("inf"));
                    if let Some(i) = bad {
                        let line = svg[..i].rsplit('\n').next().unwrap_or("").to_string() + svg[i..].split('\n').next().unwrap_or("");
                        panic!("LineChart over ({a:e}, {b:e}): {line}");
                    }
                }
                err_or(c.to_chart(), "LineChart::to_chart", |ch| ch.curves.iter().all(|cv| cv.points.iter().all(|p| p.0.is_finite() && p.1.is_finite())));
                let l = LineChart::new("t", "x", "y").log_log().with_series("s", vec![(a.abs(), 1.0), (1.0, b.abs())]);
                err_or(l.to_svg(), "log-log", |s| finite_svg(s));
            }
        }
        refused(LineChart::new("empty", "x", "y").to_svg(), "empty chart");
        refused(LineChart::new("empty series", "x", "y").with_series("s", vec![]).to_svg(), "empty series");
        let s = Series::new("s", vec![(0.0, 1.0)]);
        assert_eq!(s.points.len(), 1);
        // Hostile names are escaped, never break the SVG.
        let hostile_name = LineChart::new("<script>&\"'", "</svg>", "y").with_series("\u{202e}<b>", vec![(0.0, 1.0), (1.0, 2.0)]);
        let svg = hostile_name.to_svg().unwrap();
        assert!(!svg.contains("<script>") && !svg.contains("<b>") && finite_svg(&svg));
    }

    // Charts and figures with fixed ranges, equal aspect and markers: ranges must be finite
    // with lo < hi; an equal-aspect chart whose widened range would overflow is refused.
    charts_and_figures ["Chart::to_svg", "Figure::to_svg", "Curve::new"] {
        let base = LineChart::new("t", "x", "y").with_series("s", vec![(0.0, 0.0), (1.0, 1.0)]).to_chart().unwrap();
        for a in hostile() {
            let mut c = base.clone();
            c.x_range = Some((a, 1.0));
            err_or(c.to_svg(), "Chart(x_range)", |s| finite_svg(s));
            let mut c = base.clone();
            c.y_range = Some((0.0, a));
            c.equal_aspect = true;
            err_or(c.to_svg(), "Chart(equal aspect)", |s| finite_svg(s));
            let mut c = base.clone();
            c.curves.push(Curve::new("c", vec![(a, -a), (-a, a)], 3));
            c.equal_aspect = true;
            err_or(c.to_svg(), "Chart(curve, equal aspect)", |s| finite_svg(s));
        }
        let fig = Figure { title: "f".into(), panels: vec![base.clone(), base.clone()] };
        err_or(fig.to_svg(), "Figure", |s| finite_svg(s));
        refused(Figure { title: "empty".into(), panels: vec![] }.to_svg(), "Figure(no panels)");
        let c = Curve::new("c", vec![(0.0, 0.0)], usize::MAX);
        let mut ch = base;
        ch.curves.push(c);
        err_or(ch.to_svg(), "palette index usize::MAX", |s| finite_svg(s));
    }
}
