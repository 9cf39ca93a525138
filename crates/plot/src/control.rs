//! Figures of linear systems (book ch. 15–16): Bode with margin markers, Nyquist with both
//! branches, the −1 point and direction arrows, step/impulse responses with final values,
//! root loci with ζ lines, pole–zero maps and phase portraits.

use crate::chart::{Arrow, Chart, Curve, Figure, Marker, RefLine, Shape, Stroke};
use crate::error::PlotError;
use crate::line::LineChart;
use vectrix_lti::{Complex64, FrequencyResponse, Margins, Nyquist, RootLocus, TimeResponse};

fn fmt_num(x: f64) -> String {
    if x.is_infinite() { if x > 0.0 { "∞".into() } else { "−∞".into() } } else { format!("{x:.4}") }
}

/// A Bode plot: magnitude in dB over phase in degrees, both against log ω, one curve per
/// system, with optional margin markers (0 dB and −180° lines, ω_mc and ω_pc, PM and GM).
///
/// Book: §16.3, Fig. 18.0.12 (Matlab `margin`); 16.8.4 (a ζ family).
///
/// # Errors
/// [`PlotError::Empty`] without systems.
pub fn bode(
    title: &str,
    systems: &[(&str, &FrequencyResponse)],
    margins: Option<&Margins>,
) -> Result<Figure, PlotError> {
    if systems.is_empty() {
        return Err(PlotError::Empty { figure: title.to_string() });
    }
    let mut mag = Chart {
        title: "Magnitude".into(),
        x_label: "ω [rad/s]".into(),
        y_label: "|G(jω)| [dB]".into(),
        log_x: true,
        ..Chart::default()
    };
    let mut phase = Chart {
        title: "Phase".into(),
        x_label: "ω [rad/s]".into(),
        y_label: "∠G(jω) [deg]".into(),
        log_x: true,
        ..Chart::default()
    };
    for (i, (name, r)) in systems.iter().enumerate() {
        mag.curves.push(Curve::new(
            *name,
            r.omega.iter().copied().zip(r.magnitude_db.iter().copied()).collect(),
            i,
        ));
        phase.curves.push(Curve::new(
            *name,
            r.omega.iter().copied().zip(r.phase_deg.iter().copied()).collect(),
            i,
        ));
    }
    if let Some(m) = margins {
        mag.hlines.push(RefLine { value: 0.0, label: Some("0 dB".into()) });
        // The −180° line on the branch the phase curve is on.
        let mid = systems[0].1.phase_deg.iter().copied().filter(|p| p.is_finite()).fold(0.0, f64::min);
        let line = -180.0 + 360.0 * ((mid + 180.0) / 360.0).ceil().min(0.0);
        phase.hlines.push(RefLine { value: line, label: Some(format!("{line:.0}°")) });
        if let Some(c) = m.phase_margin() {
            let w = c.omega;
            let label = format!("PM = {}° at {} rad/s", fmt_num(c.phase_margin_deg), fmt_num(w));
            mag.vlines.push(RefLine { value: w, label: None });
            phase.vlines.push(RefLine { value: w, label: Some(label) });
        }
        // no finite gain margin: GM = ∞ (16.8.10, 16.8.11i)
        let gm = m.gain_margin_db().unwrap_or(f64::INFINITY);
        match m.phase_crossover_omega() {
            Some(w) if w > 0.0 => {
                mag.vlines.push(RefLine {
                    value: w,
                    label: Some(format!("GM = {} dB at {} rad/s", fmt_num(gm), fmt_num(w))),
                });
                phase.vlines.push(RefLine { value: w, label: None });
            }
            _ => mag.title = format!("Magnitude (GM = {} dB)", fmt_num(gm)),
        }
    }
    Ok(Figure { title: title.to_string(), panels: vec![mag, phase] })
}

/// A Nyquist plot: L(jω) for ω > 0 (solid) and its mirror for ω < 0 (dashed), direction
/// arrows on both, the critical point −1 and the unit circle; points farther than `clip`
/// from the origin are left out (an integrator sends the plot to infinity).
///
/// Book: 16.8.6, 16.8.13–16.8.14, Figs. 18.0.11 and 18.0.14.
///
/// # Errors
/// [`PlotError::Empty`] when no point is within `clip`.
pub fn nyquist(title: &str, ny: &Nyquist, clip: f64) -> Result<Figure, PlotError> {
    let keep = |z: &Complex64| if z.norm() <= clip { (z.re, z.im) } else { (f64::NAN, f64::NAN) };
    let pos: Vec<(f64, f64)> = ny.positive.iter().map(keep).collect();
    let neg: Vec<(f64, f64)> = ny.positive.iter().map(|z| keep(&z.conj())).collect();
    if pos.iter().all(|p| p.0.is_nan()) {
        return Err(PlotError::Empty { figure: title.to_string() });
    }
    let circle: Vec<(f64, f64)> = (0..=96)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 96.0;
            (t.cos(), t.sin())
        })
        .collect();
    let mut chart = Chart {
        title: format!(
            "{title}  (N = {}, P = {}, Z = {})",
            ny.encirclements, ny.open_loop_rhp, ny.closed_loop_rhp
        ),
        x_label: "Re L(jω)".into(),
        y_label: "Im L(jω)".into(),
        equal_aspect: true,
        ..Chart::default()
    };
    chart.curves.push(Curve::new("ω > 0", pos.clone(), 0));
    chart.curves.push(Curve {
        name: Some("ω < 0".into()),
        points: neg.clone(),
        color: 0,
        stroke: Stroke::Dashed,
        markers: false,
    });
    chart.curves.push(Curve {
        name: Some("unit circle".into()),
        points: circle,
        color: 6, // black: a reference curve, not a system
        stroke: Stroke::Dotted,
        markers: false,
    });
    // Arrows at a quarter and three quarters of the visible points, in the direction of
    // increasing ω (reversed on the mirror branch).
    let visible: Vec<usize> =
        (1..pos.len()).filter(|&k| !pos[k].0.is_nan() && !pos[k - 1].0.is_nan()).collect();
    for f in [0.25, 0.6] {
        if let Some(&k) = visible.get((visible.len() as f64 * f) as usize) {
            chart.arrows.push(Arrow { from: pos[k - 1], to: pos[k], color: 0 });
            chart.arrows.push(Arrow { from: neg[k], to: neg[k - 1], color: 0 });
        }
    }
    chart.markers.push(Marker { at: (-1.0, 0.0), shape: Shape::Plus, color: 2, label: Some("−1".into()) });
    Ok(Figure { title: String::new(), panels: vec![chart] })
}

/// A step or impulse response of output `output` with a dashed final-value line and the peak
/// marked.
///
/// Book: §15.9, 15.20.32, 15.20.39.
///
/// # Errors
/// [`PlotError::Empty`] for a missing output or an empty response; [`PlotError::NonFinite`]
/// for a non-finite impulse weight.
pub fn response(
    title: &str,
    r: &TimeResponse,
    output: usize,
    final_value: Option<f64>,
) -> Result<Figure, PlotError> {
    let Some(y) = r.y.get(output).filter(|y| !y.is_empty()) else {
        return Err(PlotError::Empty { figure: title.to_string() });
    };
    let mut chart =
        Chart { title: title.into(), x_label: "t [s]".into(), y_label: "y(t)".into(), ..Chart::default() };
    chart.curves.push(Curve::new(
        format!("y{}", output + 1),
        r.t.iter().copied().zip(y.iter().copied()).collect(),
        0,
    ));
    if let Some(v) = final_value {
        chart.hlines.push(RefLine { value: v, label: Some(format!("y∞ = {}", fmt_num(v))) });
    }
    // samples of y beyond the last time have no abscissa (a y longer than t): not searched
    if let Some((k, &peak)) =
        y.iter().take(r.t.len()).enumerate().filter(|(_, v)| v.is_finite()).max_by(|a, b| a.1.total_cmp(b.1))
    {
        chart.markers.push(Marker {
            at: (r.t[k], peak),
            shape: Shape::Dot,
            color: 2,
            label: Some(format!("peak {peak:.4} at {:.3} s", r.t[k])),
        });
    }
    if let Some(&w) = r.impulse_weight.get(output).filter(|w| **w != 0.0) {
        // a non-finite weight cannot be drawn, and "inf"/"NaN" never reach the SVG
        if !w.is_finite() {
            return Err(PlotError::NonFinite {
                series: format!("y{} impulse weight", output + 1),
                index: 0,
                x: 0.0,
                y: w,
            });
        }
        chart.title = format!("{title}  (+ {w:.4}·δ(t))");
    }
    Ok(Figure { title: String::new(), panels: vec![chart] })
}

/// A root locus: branches, × open-loop poles, ○ zeros, dotted asymptotes from α, and dashed
/// constant-ζ rays (ζ = sin θ, θ from the imaginary axis, (15.15.6)).
///
/// Book: §15.18.3, 15.20.49–15.20.50, Fig. 18.0.13.
///
/// # Errors
/// [`PlotError::Empty`] for a locus without branches.
pub fn root_locus(title: &str, rl: &RootLocus, zetas: &[f64]) -> Result<Figure, PlotError> {
    if rl.branches.is_empty() {
        return Err(PlotError::Empty { figure: title.to_string() });
    }
    let mut chart = Chart {
        title: title.into(),
        x_label: "Re s".into(),
        y_label: "Im s".into(),
        equal_aspect: true,
        ..Chart::default()
    };
    for (i, b) in rl.branches.iter().enumerate() {
        let name = (i == 0).then(|| "locus".to_string());
        chart.curves.push(Curve {
            name,
            points: b.iter().map(|s| (s.re, s.im)).collect(),
            color: 0,
            stroke: Stroke::Solid,
            markers: false,
        });
    }
    let extent =
        rl.branches.iter().flatten().chain(&rl.poles).chain(&rl.zeros).map(|s| s.norm()).fold(1.0, f64::max);
    if let Some(alpha) = rl.asymptote_center {
        for (i, a) in rl.asymptote_angles_deg.iter().enumerate() {
            let (s, c) = a.to_radians().sin_cos();
            chart.curves.push(Curve {
                name: (i == 0).then(|| format!("asymptotes (α = {alpha:.4})")),
                points: vec![(alpha, 0.0), (alpha + 2.0 * extent * c, 2.0 * extent * s)],
                color: 6, // black: reference lines, not a system
                stroke: Stroke::Dotted,
                markers: false,
            });
        }
    }
    for (i, &z) in zetas.iter().enumerate() {
        let th = z.clamp(-1.0, 1.0).asin();
        let (s, c) = (std::f64::consts::FRAC_PI_2 + th).sin_cos();
        let r = 2.0 * extent;
        chart.curves.push(Curve {
            name: Some(format!("ζ = {z:.3}")),
            points: vec![(r * c, -r * s), (0.0, 0.0), (r * c, r * s)],
            color: 3 + i,
            stroke: Stroke::Dashed,
            markers: false,
        });
    }
    push_poles_zeros(&mut chart, &rl.poles, &rl.zeros);
    // Frame the finite part of the locus: the open-loop pattern widened by the branch extent
    // reached at moderate gains.
    let pts: Vec<&Complex64> = rl.branches.iter().flatten().chain(&rl.poles).chain(&rl.zeros).collect();
    let (mut x0, mut x1, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64);
    for s in &pts {
        x0 = x0.min(s.re);
        x1 = x1.max(s.re);
        y1 = y1.max(s.im.abs());
    }
    let pad = 0.1 * (x1 - x0).max(2.0 * y1).max(1e-3);
    chart.x_range = Some((x0 - pad, x1 + pad));
    chart.y_range = Some((-y1 - pad, y1 + pad));
    Ok(Figure { title: String::new(), panels: vec![chart] })
}

fn push_poles_zeros(chart: &mut Chart, poles: &[Complex64], zeros: &[Complex64]) {
    for p in poles {
        chart.markers.push(Marker { at: (p.re, p.im), shape: Shape::Cross, color: 2, label: None });
    }
    for z in zeros {
        chart.markers.push(Marker { at: (z.re, z.im), shape: Shape::Circle, color: 4, label: None });
    }
}

/// A pole–zero map: × poles, ○ zeros, with the imaginary axis dashed.
///
/// Book: 15.20.52 (zeros of the four 747 channels), Def 15.11.2.
///
/// # Errors
/// [`PlotError::Empty`] without poles or zeros.
pub fn pole_zero_map(title: &str, poles: &[Complex64], zeros: &[Complex64]) -> Result<Figure, PlotError> {
    if poles.is_empty() && zeros.is_empty() {
        return Err(PlotError::Empty { figure: title.to_string() });
    }
    let mut chart = Chart {
        title: title.into(),
        x_label: "Re s".into(),
        y_label: "Im s".into(),
        equal_aspect: true,
        ..Chart::default()
    };
    chart.vlines.push(RefLine { value: 0.0, label: None });
    chart.hlines.push(RefLine { value: 0.0, label: None });
    push_poles_zeros(&mut chart, poles, zeros);
    Ok(Figure { title: String::new(), panels: vec![chart] })
}

/// A phase portrait: trajectories (x₁(t), x₂(t)) with an arrow showing the direction of time
/// on each.
///
/// Book: 15.20.10 (spirals in, ellipse, spirals out).
///
/// # Errors
/// [`PlotError::Empty`] without trajectories.
pub fn phase_portrait(title: &str, trajectories: &[(&str, Vec<(f64, f64)>)]) -> Result<Figure, PlotError> {
    if trajectories.iter().all(|t| t.1.len() < 2) {
        return Err(PlotError::Empty { figure: title.to_string() });
    }
    let mut chart = Chart {
        title: title.into(),
        x_label: "x₁".into(),
        y_label: "x₂".into(),
        equal_aspect: true,
        ..Chart::default()
    };
    for (i, (name, pts)) in trajectories.iter().enumerate() {
        chart.curves.push(Curve::new(*name, pts.clone(), i));
        for f in [0.1, 0.5] {
            let k = ((pts.len() as f64 * f) as usize).clamp(1, pts.len().saturating_sub(1).max(1));
            if k < pts.len() {
                chart.arrows.push(Arrow { from: pts[k - 1], to: pts[k], color: i });
            }
        }
        if let Some(&start) = pts.first() {
            chart.markers.push(Marker { at: start, shape: Shape::Dot, color: i, label: None });
        }
    }
    Ok(Figure { title: String::new(), panels: vec![chart] })
}

/// Time series: several named signals against t on one chart.
///
/// Book: 15.20.39 (command and response overlaid), 15.20.9 (several initial conditions).
pub fn time_series(title: &str, t: &[f64], signals: &[(&str, &[f64])]) -> LineChart {
    let mut c = LineChart::new(title, "t [s]", "");
    for (name, y) in signals {
        c = c.with_series(*name, t.iter().copied().zip(y.iter().copied()).collect());
    }
    c
}

/// A work–precision diagram: error against time, log–log, one line per method.
pub fn work_precision(title: &str, methods: &[(&str, Vec<(f64, f64)>)]) -> LineChart {
    let mut c = LineChart::new(title, "error", "time [s]").log_log();
    for (name, pts) in methods {
        c = c.with_series(*name, pts.clone());
    }
    c
}
