//! vectrix-plot under hostile input (docs/robustness.md): a figure is valid SVG with finite
//! coordinates (never `NaN` or `inf` in an attribute) or a typed error (empty, non-finite,
//! non-positive on a log axis, invalid range).

use vectrix::lti::{Complex64, FrequencyResponse, Margins, Nyquist, RootLocus, TimeResponse};
use vectrix::plot::{Curve, Figure, LineChart, Series, control};

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

    // The control-theory figures (§15–16): Bode, Nyquist, responses, root loci, pole–zero
    // maps, phase portraits, time series and work–precision charts over hostile data
    // (±1e308, subnormal, ±∞, NaN, empty, mismatched lengths): valid SVG with finite
    // coordinates or a typed error, never a panic.
    control_figures ["control::bode", "control::nyquist", "control::response", "control::root_locus",
        "control::pole_zero_map", "control::phase_portrait", "control::time_series", "control::work_precision"] {
        let c = |re: f64, im: f64| Complex64::new(re, im);
        let fig_ok = |f: Result<Figure, vectrix::plot::PlotError>, what: &str| err_or(f.and_then(|f| f.to_svg()), what, |s| finite_svg(s));
        let no_margins = Margins { phase_crossovers: vec![], gain_crossovers: vec![], stability_points: vec![] };
        for a in hostile() {
            let fr = FrequencyResponse {
                omega: vec![0.1, 1.0, a.abs()],
                response: vec![c(1.0, 0.0), c(a, -a), c(0.0, 1.0)],
                magnitude_db: vec![0.0, a, -20.0],
                phase_deg: vec![0.0, -90.0, a],
            };
            fig_ok(control::bode("bode", &[("G", &fr)], None), "bode");
            fig_ok(control::bode("bode", &[("G", &fr), ("H", &fr)], Some(&no_margins)), "bode(margins)");
            let ny = Nyquist { contour: vec![], positive: vec![c(1.0, 0.0), c(a, a), c(-0.5, -0.1), c(0.0, 0.0)], encirclements: 0, open_loop_rhp: 0, closed_loop_rhp: 0 };
            for clip in [a, 10.0] {
                fig_ok(control::nyquist("nyquist", &ny, clip), "nyquist");
            }
            let tr = TimeResponse { t: vec![0.0, 1.0, 2.0], y: vec![vec![0.0, a, 1.0]], x: vec![], impulse_weight: vec![a] };
            for out in [0, 1, usize::MAX] {
                fig_ok(control::response("step", &tr, out, Some(a)), "response");
            }
            let rl = RootLocus {
                gains: vec![0.0, 1.0],
                branches: vec![vec![c(-1.0, 0.0), c(a, a)]],
                poles: vec![c(-1.0, 0.0)],
                zeros: vec![c(a, 0.0)],
                asymptote_center: Some(a),
                asymptote_angles_deg: vec![a, 180.0],
                breakaway: vec![(c(a, 0.0), a)],
                jw_crossings: vec![(a, a)],
                departure_deg: vec![(c(-1.0, 0.0), a)],
            };
            // a NaN ζ or asymptote centre is named in its legend text ("ζ = NaN"); the
            // coordinates stay finite
            err_or(control::root_locus("rl", &rl, &[a, 0.5]).and_then(|f| f.to_svg()), "root_locus", |s| {
                s.starts_with("<svg") && !s.contains("=\"NaN") && !s.contains("=\"inf") && !s.contains("=\"-inf")
            });
            fig_ok(control::pole_zero_map("pz", &[c(a, 1.0)], &[c(-1.0, a)]), "pole_zero_map");
            fig_ok(control::phase_portrait("pp", &[("x", vec![(0.0, 0.0), (a, 1.0), (1.0, a)]), ("y", vec![])]), "phase_portrait");
            err_or(control::time_series("ts", &[0.0, 1.0, a], &[("y", &[1.0, a, 2.0]), ("z", &[1.0])]).to_svg(), "time_series", |s| finite_svg(s));
            err_or(control::work_precision("wp", &[("m", vec![(1e-3, 0.1), (a, a)])]).to_svg(), "work_precision", |s| finite_svg(s));
        }
        refused(control::bode("empty", &[], None), "bode(no systems)");
        let ny = Nyquist { contour: vec![], positive: vec![], encirclements: 0, open_loop_rhp: 0, closed_loop_rhp: 0 };
        refused(control::nyquist("empty", &ny, 10.0), "nyquist(empty)");
        let tr = TimeResponse { t: vec![], y: vec![], x: vec![], impulse_weight: vec![] };
        refused(control::response("empty", &tr, 0, None), "response(no outputs)");
        // y longer than t: the extra samples have no time and are dropped, never indexed
        let tr = TimeResponse { t: vec![0.0], y: vec![vec![0.0, 5.0, 9.0]], x: vec![], impulse_weight: vec![] };
        err_or(control::response("mismatched", &tr, 0, None).and_then(|f| f.to_svg()), "response(mismatched)", |s| finite_svg(s));
        let rl = RootLocus { gains: vec![], branches: vec![], poles: vec![], zeros: vec![], asymptote_center: None, asymptote_angles_deg: vec![], breakaway: vec![], jw_crossings: vec![], departure_deg: vec![] };
        refused(control::root_locus("empty", &rl, &[]), "root_locus(empty)");
        refused(control::pole_zero_map("empty", &[], &[]), "pole_zero_map(empty)");
        refused(control::phase_portrait("empty", &[]), "phase_portrait(empty)");
        refused(control::time_series("empty", &[], &[]).to_svg(), "time_series(empty)");
        refused(control::work_precision("empty", &[]).to_svg(), "work_precision(empty)");
    }
}
