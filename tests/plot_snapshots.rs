//! Snapshot tests of the SVG figures (book ch. 15–16). Each figure is rendered and compared
//! byte for byte with `tests/snapshots/<name>.svg`. These are regression guards of the plot
//! output, not book coverage: the textbook index lists them apart, and the problems they draw
//! are checked numerically (margins, crossovers, peaks) in the chapter files. A missing or
//! different snapshot fails; after checking a figure by eye, regenerate with
//! `VECTRIX_BLESS=1 cargo test --test plot_snapshots`.

use vectrix::lti::*;
use vectrix::plot::control;
use vectrix::plot::{LineChart, PlotError, Series};

fn check(name: &str, svg: &str) {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots").join(format!("{name}.svg"));
    if std::env::var_os("VECTRIX_BLESS").is_some() {
        std::fs::write(&path, svg).expect("write snapshot");
        return;
    }
    let want = std::fs::read_to_string(&path).unwrap_or_else(|_| {
        panic!("missing snapshot {}: run with VECTRIX_BLESS=1 to create it", path.display())
    });
    assert!(want == svg, "snapshot {name} differs; inspect and re-bless with VECTRIX_BLESS=1");
}

fn tf(n: &[f64], d: &[f64]) -> TransferFunction {
    TransferFunction::new(n, d).unwrap()
}

#[test]
fn snapshot_bode_16_8_11() {
    // 16.8.11 ii (Fig. 18.0.12): L = 1/(s(s+1)) and with the lead (s+2)/(s+20); PM markers.
    let l = tf(&[1.0], &[1.0, 1.0, 0.0]);
    let led = l.series(&tf(&[1.0, 2.0], &[1.0, 20.0])).unwrap();
    let w = logspace(-2.0, 2.0, 200).unwrap();
    let (a, b) = (l.bode(&w).unwrap(), led.bode(&w).unwrap());
    let fig = control::bode(
        "16.8.11: lead compensation",
        &[("1/(s(s+1))", &a), ("with lead", &b)],
        Some(&l.margins().unwrap()),
    )
    .unwrap();
    check("bode_16_8_11", &fig.to_svg().unwrap());
}

#[test]
fn snapshot_bode_16_8_13() {
    // 16.8.13: L = 1/(s(s+1)²): GM 6.02 dB at ω = 1, PM 21.39° at 0.6823.
    let l = tf(&[1.0], &[1.0, 2.0, 1.0, 0.0]);
    let w = logspace(-2.0, 2.0, 200).unwrap();
    let fig = control::bode("16.8.13", &[("L", &l.bode(&w).unwrap())], Some(&l.margins().unwrap())).unwrap();
    check("bode_16_8_13", &fig.to_svg().unwrap());
}

#[test]
fn snapshot_bode_16_8_4() {
    // 16.8.4: 1/(s² + 2ζs + 1) for ζ = 0.1, 0.3, 0.5, 0.7, 0.9.
    let w = logspace(-2.0, 2.0, 300).unwrap();
    let data: Vec<(String, FrequencyResponse)> = [0.1, 0.3, 0.5, 0.7, 0.9]
        .iter()
        .map(|z| (format!("ζ = {z}"), tf(&[1.0], &[1.0, 2.0 * z, 1.0]).bode(&w).unwrap()))
        .collect();
    let refs: Vec<(&str, &FrequencyResponse)> = data.iter().map(|(n, r)| (n.as_str(), r)).collect();
    check("bode_16_8_4", &control::bode("16.8.4: resonance", &refs, None).unwrap().to_svg().unwrap());
}

#[test]
fn snapshot_nyquist_16_8_14() {
    // 16.8.14: L = 4(s+10)/((s−1)(s−2)): two counter-clockwise encirclements, N = −2, P = 2, Z = 0.
    let ny = tf(&[4.0, 40.0], &[1.0, -3.0, 2.0]).nyquist(300).unwrap();
    check("nyquist_16_8_14", &control::nyquist("16.8.14", &ny, 30.0).unwrap().to_svg().unwrap());
}

#[test]
fn snapshot_nyquist_16_8_13() {
    // 16.8.13: L = 1/(s(s+1)²), indented at s = 0; clipped at |L| = 4.
    let ny = tf(&[1.0], &[1.0, 2.0, 1.0, 0.0]).nyquist(300).unwrap();
    check("nyquist_16_8_13", &control::nyquist("16.8.13", &ny, 4.0).unwrap().to_svg().unwrap());
}

#[test]
fn snapshot_step_15_20_32() {
    // 15.20.32: step of (4s − 3)/(s² + 0.8s + 4): undershoot, y∞ = −0.75.
    let g = tf(&[4.0, -3.0], &[1.0, 0.8, 4.0]);
    let r = g.step(&time_grid(15.0, 301).unwrap()).unwrap();
    let fig = control::response("15.20.32: step response", &r, 0, Some(-0.75)).unwrap();
    check("step_15_20_32", &fig.to_svg().unwrap());
}

#[test]
fn snapshot_impulse_15_20_14() {
    // 15.20.14: DO acceleration output: impulse response plus (1/m)δ(t) shown in the title.
    let sys = Sdof::new(2.0, 0.6, 5.0).unwrap().to_state_space(SdofOutput::Acceleration).unwrap();
    let r = response(&sys, InputKind::Impulse, 0, 1.0, 0.0, &time_grid(20.0, 201).unwrap()).unwrap();
    let fig = control::response("15.20.14: impulse, acceleration output", &r, 0, Some(0.0)).unwrap();
    check("impulse_15_20_14", &fig.to_svg().unwrap());
}

#[test]
fn snapshot_rlocus_16_8_11() {
    // 16.8.11 iii (Fig. 18.0.13): k(s+2)/(s(s+1)(s+20)) with the ζ = 0.707 line.
    let g = tf(&[1.0, 2.0], &[1.0, 21.0, 20.0, 0.0]);
    let rl = root_locus(&g, 300.0, 0.02).unwrap();
    let fig = control::root_locus("16.8.11: root locus", &rl, &[std::f64::consts::FRAC_1_SQRT_2]).unwrap();
    check("rlocus_16_8_11", &fig.to_svg().unwrap());
}

#[test]
fn snapshot_pzmap_15_20_52() {
    // 15.20.52: poles and zeros of the 747 channel r/δa.
    let g = tf(&[0.00775, 0.0, 0.0, 0.0], &[1.0, 0.6358, 0.9389, 0.5116, 0.00367]);
    let fig = control::pole_zero_map(
        "pole–zero map",
        &g.poles().unwrap(),
        &[Complex64::new(0.2509, 1.1307), Complex64::new(0.2509, -1.1307), Complex64::new(-0.4357, 0.0)],
    )
    .unwrap();
    check("pzmap_15_20_52", &fig.to_svg().unwrap());
}

#[test]
fn snapshot_phase_portrait_15_20_10() {
    // 15.20.10: eigensolution Re(e^{λt}v), v = [3, 1] + j[1, 4], λ = σ + j: spiral in, ellipse,
    // spiral out for σ = −1/4, 0, 1/4 (the book's ±1 spirals too fast to read).
    let traj = |sigma: f64| -> Vec<(f64, f64)> {
        (0..=400)
            .map(|k| {
                let t = 12.0 * k as f64 / 400.0;
                let e = (sigma * t).exp();
                let (c, s) = (t.cos(), t.sin());
                // (15.6.2): x = e^{σt}(y cos ωt − z sin ωt), y = [3, 1], z = [1, 4].
                (e * (3.0 * c - s), e * (c - 4.0 * s))
            })
            .collect()
    };
    let fig = control::phase_portrait(
        "15.20.10: phase portrait",
        &[("σ = −1/4", traj(-0.25)), ("σ = 0", traj(0.0)), ("σ = 1/4", traj(0.25))],
    )
    .unwrap();
    check("phase_portrait_15_20_10", &fig.to_svg().unwrap());
}

#[test]
fn snapshot_time_series_15_20_9() {
    // 15.20.9: x = e^{−2t}(x₀ − 4) + 4 for x₀ = 5 and x₀ = −4.
    let t = time_grid(3.0, 61).unwrap();
    let a: Vec<f64> = t.iter().map(|t| (-2.0 * t).exp() + 4.0).collect();
    let b: Vec<f64> = t.iter().map(|t| -8.0 * (-2.0 * t).exp() + 4.0).collect();
    let c = control::time_series("15.20.9", &t, &[("x₀ = 5", &a), ("x₀ = −4", &b)]);
    check("time_series_15_20_9", &c.to_svg().unwrap());
}

#[test]
fn work_precision_line_chart() {
    // A work–precision diagram (error against time, log–log), the LineChart other crates use.
    let rk4: Vec<(f64, f64)> =
        (1..=6).map(|k| (10f64.powi(-2 * k), 1e-5 * 10f64.powf(k as f64 / 2.0))).collect();
    let dop: Vec<(f64, f64)> =
        (1..=6).map(|k| (10f64.powi(-2 * k), 3e-5 * 10f64.powf(k as f64 / 8.0))).collect();
    let c = control::work_precision("work–precision", &[("RK4", rk4), ("DOP853", dop)]);
    check("work_precision", &c.to_svg().unwrap());
}

#[test]
fn line_chart_is_deterministic_and_rejects_bad_points() {
    let c = LineChart {
        title: "t".into(),
        x_label: "x".into(),
        y_label: "y".into(),
        log_x: true,
        log_y: true,
        series: vec![Series { name: "a".into(), points: vec![(1.0, 2.0), (10.0, 0.5)] }],
    };
    assert_eq!(c.to_svg().unwrap(), c.to_svg().unwrap());
    let mut bad = c.clone();
    bad.series[0].points.push((0.0, 1.0));
    assert!(matches!(bad.to_svg(), Err(PlotError::NonPositiveOnLogAxis { axis: "x", .. })));
    let mut nan = c.clone();
    nan.series[0].points.push((2.0, f64::NAN));
    assert!(matches!(nan.to_svg(), Err(PlotError::NonFinite { index: 2, .. })));
    assert!(matches!(LineChart::new("e", "x", "y").to_svg(), Err(PlotError::Empty { .. })));
}

/// The (stroke, stroke-dasharray) of every legend line of a chart, in legend order. Legend
/// lines are the `<line …/>` elements 22 px long right of the plot area.
fn legend_styles(svg: &str) -> Vec<(String, String)> {
    let attr = |el: &str, name: &str| {
        el.split(&format!(r#" {name}=""#)).nth(1).and_then(|r| r.split('"').next()).unwrap_or("").to_string()
    };
    svg.lines()
        .filter(|l| {
            l.starts_with("<line") && {
                let x1: f64 = attr(l, "x1").parse().unwrap_or(0.0);
                let x2: f64 = attr(l, "x2").parse().unwrap_or(0.0);
                x1 > 468.0 && (x2 - x1 - 22.0).abs() < 1e-9
            }
        })
        .map(|l| (attr(l, "stroke"), attr(l, "stroke-dasharray")))
        .collect()
}

#[test]
fn work_precision_eleven_methods_differ_in_colour_or_style() {
    // Issue 23: the rigid-body work–precision figure has 11 methods; two of them shared a
    // colour. Every series must now differ from every other in colour or line style, and the
    // colours must come from Okabe and Ito's colour-universal-design palette (the published
    // hex codes, yellow excluded as too faint on white).
    let okabe_ito = ["#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000"];
    let methods: Vec<(String, Vec<(f64, f64)>)> = (0..11)
        .map(|i| {
            (format!("method {i}"), vec![(1e-3, 1e-4 * f64::from(i + 1)), (1e-9, 1e-2 * f64::from(i + 1))])
        })
        .collect();
    let named: Vec<(&str, Vec<(f64, f64)>)> = methods.iter().map(|(n, p)| (n.as_str(), p.clone())).collect();
    let svg = control::work_precision("11 methods", &named).to_svg().unwrap();
    let styles = legend_styles(&svg);
    assert_eq!(styles.len(), 11, "one legend line per method: {styles:?}");
    for (i, a) in styles.iter().enumerate() {
        assert!(okabe_ito.contains(&a.0.as_str()), "series {i}: colour {} is not Okabe–Ito", a.0);
        for b in &styles[i + 1..] {
            assert_ne!(a, b, "two series share colour and style");
        }
    }
    // The first seven are solid in seven colours; the next ones repeat a colour dashed.
    assert!(styles[..7].iter().all(|s| s.1.is_empty()));
    assert_eq!(styles[7], (okabe_ito[0].to_string(), "8 5".to_string()));
}
