//! Chapter 16: frequency response, Bode, Nyquist, margins and root locus (solutions ch. 18),
//! as executable tests.
//!
//! Printed values are checked to the digits printed (`assert_printed(got, 16.23, 2)` means
//! |got − 16.23| ≤ ½·10⁻²). The notes' computed values (C) are used where the book is
//! inconsistent or wrong; each such test says so.
mod support;

use support::{EPS, assert_abs, assert_rel};
use vectrix::lti::*;

#[track_caller]
fn assert_printed(got: f64, printed: f64, decimals: i32) {
    let tol = 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9);
    assert!((got - printed).abs() <= tol, "got {got}, printed {printed} (±{tol:e})");
}

fn tf(n: &[f64], d: &[f64]) -> TransferFunction {
    TransferFunction::new(n, d).unwrap()
}

fn poly(c: &[f64]) -> Polynomial {
    Polynomial::new(c).unwrap()
}

fn at(g: &TransferFunction, w: f64) -> FrequencyResponse {
    g.bode(&[w]).unwrap()
}

// ---------------------------------------------------------------- frequency response (16.2–16.6)

#[test]
fn problem_16_8_1_sensor_at_60_hz() {
    // 16.8.1: 9.2/(0.031s + 1): DC gain 42.32 for 4.6 V (0°); at 60 Hz |G| = 0.7844 and the
    // 3.3 mV ripple comes out with amplitude 2.588e-3 (C; printed 2.6e-3) and phase −85.11°
    // (C; the book prints −85.16°/−85.15°, a rounding of an approximate computation).
    let g = tf(&[9.2], &[0.031, 1.0]);
    assert_rel(g.dc_gain().unwrap() * 4.6, 42.32, 1e-12);
    let r = at(&g, 120.0 * std::f64::consts::PI);
    let mag = 10f64.powf(r.magnitude_db[0] / 20.0);
    assert_printed(mag, 0.7844, 4);
    assert_printed(mag * 3.3e-3, 2.588e-3, 6);
    assert_printed(r.phase_deg[0], -85.11, 2);
}

#[test]
fn problem_16_8_3_lead_at_omega_4() {
    // 16.8.3: (10/3)(s+6)/(s+2) at ω = 4: 14.6 dB, −29.75° (C: 14.607 dB, −29.745°).
    let g = tf(&[10.0 / 3.0, 20.0], &[1.0, 2.0]);
    let r = at(&g, 4.0);
    assert_printed(r.magnitude_db[0], 14.607, 3);
    assert_printed(r.phase_deg[0], -29.745, 3);
}

#[test]
#[allow(clippy::approx_constant)] // 0.7071 is the printed ωr, not a stand-in for 1/√2
fn problem_16_8_4_resonance_peaks() {
    // 16.8.4–5: 1/(s² + 2ζs + 1): ωr = √(1 − 2ζ²) and peak 1/(2ζ√(1 − ζ²)) for ζ < 1/√2;
    // (C) ζ = .1, .3, .5, .7 → ωr = 0.9899, 0.9055, 0.7071, 0.1414; peak 5.025, 1.747, 1.155,
    // 1.0002. (ERR: the printed "ωr = 0.9592–0.5292" and swapped case labels.)
    let want = [(0.1, 0.9899, 5.025), (0.3, 0.9055, 1.747), (0.5, 0.7071, 1.155), (0.7, 0.1414, 1.0002)];
    for (zeta, wr, peak) in want {
        let g = tf(&[1.0], &[1.0, 2.0 * zeta, 1.0]);
        // Golden-section search of |G(jω)| on [0.01, 1].
        let mag = |w: f64| -at(&g, w).magnitude_db[0];
        let (mut a, mut b) = (0.01, 1.0);
        let phi = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..80 {
            let (c, d) = (b - phi * (b - a), a + phi * (b - a));
            if mag(c) < mag(d) { b = d } else { a = c }
        }
        let w = 0.5 * (a + b);
        assert_printed(w, wr, 4);
        assert_printed(10f64.powf(-mag(w) / 20.0), peak, if peak > 1.01 { 3 } else { 4 });
        assert_abs(w, (1.0 - 2.0 * zeta * zeta).sqrt(), 1e-6); // golden search converges to √ε
    }
}

#[test]
fn problem_16_8_6_phase_branches() {
    // 16.8.6–7 and (16.6.2): the low-frequency phase is 0° or −180° by the sign of the DC
    // gain, ±90° per zero/pole at 0; the phase is continuous in ω (factor by factor).
    let w = logspace(-3.0, 4.0, 701).unwrap();
    let cases: [(&str, TransferFunction, f64, f64); 5] = [
        ("lead", tf(&[1.0, 2.0], &[1.0, 10.0]), 0.0, 0.0),
        ("nonminimum phase", tf(&[1.0, -2.0], &[1.0, 10.0]), -180.0, -360.0),
        ("allpass", tf(&[1.0, -2.0], &[1.0, 2.0]), -180.0, -360.0),
        ("washout", tf(&[1.0, 0.0], &[1.0, 2.0]), 90.0, 0.0),
        (
            "rooftop",
            tf(&[1.0, 0.0, 0.0], poly(&[1.0, 2.0, 1.0]).mul(&poly(&[1.0, 20.0, 100.0])).coeffs()),
            180.0,
            -180.0,
        ),
    ];
    for (name, g, lo, hi) in cases {
        let b = g.bode(&w).unwrap();
        assert!((b.phase_deg[0] - lo).abs() < 1.0, "{name}: low-frequency phase {}", b.phase_deg[0]);
        assert!((b.phase_deg[700] - hi).abs() < 1.0, "{name}: high-frequency phase {}", b.phase_deg[700]);
        for (k, p) in b.phase_deg.windows(2).enumerate() {
            assert!((p[1] - p[0]).abs() < 20.0, "{name}: phase jump at ω = {}", w[k + 1]);
        }
    }
}

#[test]
fn bode_lightly_damped_and_high_frequency() {
    // Notes §3.4–3.5: a coarse grid across a ζ = 0.001 resonance keeps the phase on one branch
    // (0 → −180°, no ±360° jumps), and 1/(s+1)¹⁰ at ω = 10⁴ is −800 dB without overflow.
    let g = tf(&[1.0], &[1.0, 0.002, 1.0]);
    let b = g.bode(&[0.5, 0.999, 1.001, 2.0]).unwrap();
    assert!(b.phase_deg.windows(2).all(|p| p[1] < p[0]) && b.phase_deg[3] > -180.0);
    let z = Zpk::new(vec![], vec![Complex64::new(-1.0, 0.0); 10], 1.0).unwrap();
    let b = z.bode(&[1e4]).unwrap();
    assert_rel(b.magnitude_db[0], -10.0 * 10.0 * (1.0f64 + 1e8).log10(), 1e3 * EPS);
    assert_rel(b.phase_deg[0], -10.0 * 1e4f64.atan().to_degrees(), 1e3 * EPS);
    // From the expanded polynomial the tenfold root splits by ~ε^{1/10} ≈ 0.03 (notes §3.2),
    // yet the magnitude far away is still right to ~1e-11 relative (tolerance 1e-10).
    let den = [1.0, 10.0, 45.0, 120.0, 210.0, 252.0, 210.0, 120.0, 45.0, 10.0, 1.0];
    let b = tf(&[1.0], &den).bode(&[1e4]).unwrap();
    assert_rel(b.magnitude_db[0], -10.0 * 10.0 * (1.0f64 + 1e8).log10(), 1e-10);
}

#[test]
fn eq_16_5_7_real_pole_minus_3_db() {
    // (16.5.3), (16.5.7): α/(s − p): |G| = |α|/√(ω² + p²), −3 dB at ω = |p|.
    let g = tf(&[5.0], &[1.0, 4.0]);
    let r = at(&g, 4.0);
    assert_rel(r.magnitude_db[0] - 20.0 * (5.0f64 / 4.0).log10(), -10.0 * 2f64.log10(), 64.0 * EPS);
    assert_rel(r.phase_deg[0], -45.0, 64.0 * EPS);
}

#[test]
fn state_space_bode_matches_transfer_function() {
    // DO with position output: the ss path equals 1/(ms² + cs + k).
    let s = Sdof::new(2.0, 0.4, 8.0).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let w = logspace(-1.0, 1.0, 9).unwrap();
    let a = s.bode(0, 0, &w).unwrap();
    let b = tf(&[1.0], &[2.0, 0.4, 8.0]).bode(&w).unwrap();
    for k in 0..w.len() {
        assert_rel(a.magnitude_db[k], b.magnitude_db[k], 1e3 * EPS);
        // phases in (−180°, 180°]: absolute at that scale
        assert_abs(a.phase_deg[k], b.phase_deg[k], 64.0 * EPS * 180.0);
    }
}

// ---------------------------------------------------------------- margins (16.3, 16.8.10–14)

#[test]
fn problem_16_8_10_infinite_gain_margin() {
    // 16.8.10: L = 2.5(s+100)/(s+1)²: GM = ∞; PM = 16.2° at ω_mc = 15.9 rad/s (printed);
    // computed (C): 16.23° at 15.879.
    let m = tf(&[2.5, 250.0], &[1.0, 2.0, 1.0]).margins().unwrap();
    assert_eq!(m.gain_margin_db(), f64::INFINITY);
    assert!(m.phase_crossovers.is_empty());
    assert_printed(m.phase_margin_deg(), 16.23, 2);
    assert_printed(m.gain_crossover_omega().unwrap(), 15.879, 3);
}

#[test]
fn problem_16_8_11_lead_raises_phase_margin() {
    // 16.8.11 i) L = 1/(s(s+1)): GM = ∞, PM = 51.8° at 0.786 (C: 51.83° at 0.7862);
    // ii) with the lead (s+2)/(s+20) (k = 1): PM 86.88° at ω_mc = 0.0996 (C).
    let l = tf(&[1.0], &[1.0, 1.0, 0.0]);
    let m = l.margins().unwrap();
    assert_eq!(m.gain_margin_db(), f64::INFINITY);
    assert_printed(m.phase_margin_deg(), 51.83, 2);
    assert_printed(m.gain_crossover_omega().unwrap(), 0.7862, 4);
    let led = l.series(&tf(&[1.0, 2.0], &[1.0, 20.0]));
    let m = led.margins().unwrap();
    assert_printed(m.phase_margin_deg(), 86.88, 2);
    assert_printed(m.gain_crossover_omega().unwrap(), 0.0996, 4);
}

#[test]
fn problem_16_8_11_root_locus_damping_gains() {
    // 16.8.11 iv): k(s+2)/(s(s+1)(s+20)) with closed-loop ζ = 1/√2: √2ωn³ − 23ωn² + 42√2ωn − 40 = 0
    // gives k = {197.9617, 31.7973, 12.7410} and poles −9.3734 ± 9.3734j, −1.3157 ± 1.3157j,
    // −0.8109 ± 0.8109j; AS for all k > 0; v) ramp error e∞ = 10/k = {0.0505, 0.3145, 0.7849}.
    let g = tf(&[1.0, 2.0], &[1.0, 21.0, 20.0, 0.0]);
    let rl = root_locus(&g, 400.0, 0.02).unwrap();
    assert_eq!(rl.asymptote_center, Some(-9.5));
    assert_eq!(rl.asymptote_angles_deg, vec![90.0, 270.0]);
    let hits = rl.zeta_crossings(&g, std::f64::consts::FRAC_1_SQRT_2);
    let ks: Vec<f64> = hits.iter().map(|h| h.0).collect();
    assert_eq!(ks.len(), 3, "crossings {hits:?}");
    for ((k, s), (kw, pw)) in hits.iter().zip([(12.7410, 0.8109), (31.7973, 1.3157), (197.9617, 9.3734)]) {
        assert_printed(*k, kw, 4);
        assert_printed(s.re, -pw, 4);
        assert_printed(s.im, pw, 4);
    }
    let iv = stable_gain_intervals(g.num(), g.den()).unwrap();
    assert_eq!(iv, vec![(0.0, f64::INFINITY)]);
    for (k, e) in [(197.9617, 0.0505), (31.7973, 0.3145), (12.7410, 0.7849)] {
        let l = g.scale(k);
        let err = l.sensitivity().unwrap().series(&tf(&[1.0], &[1.0, 0.0, 0.0]));
        let FinalValue::Finite(v) = err.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
        assert_printed(v, e, 4);
    }
}

#[test]
fn problem_16_8_12_integral_control_of_first_order_lag() {
    // 16.8.12: 1/(τs+1) with K_I/s: AS ⇔ K_I > 0; ramp error 1/K_I < 0.025 ⇔ K_I > 40.
    let tau = 0.3;
    let g = tf(&[1.0], &[tau, 1.0, 0.0]);
    assert_eq!(stable_gain_intervals(g.num(), g.den()).unwrap(), vec![(0.0, f64::INFINITY)]);
    let ki = 40.0;
    let e = g.scale(ki).sensitivity().unwrap().series(&tf(&[1.0], &[1.0, 0.0, 0.0]));
    assert_eq!(e.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(1.0 / ki));
}

#[test]
fn problem_16_8_13_margins_of_type_one_third_order() {
    // 16.8.13: L = 1/(s(s+1)²): ω_pc = 1, L(j) = −0.5, GM = 6.02 dB; ω_gc = 0.6823 (the root of
    // ω³ + ω − 1), PM = 21.39° (C; the book prints 21.5° and 21.9°, inconsistent). ERR: "GM =
    // 20 log(1 − |L|)" should be −20 log|L|.
    let l = tf(&[1.0], &[1.0, 2.0, 1.0, 0.0]);
    let m = l.margins().unwrap();
    assert_abs(m.phase_crossover_omega().unwrap(), 1.0, 64.0 * EPS);
    assert_printed(m.gain_margin_db(), 6.02, 2);
    assert_rel(m.gain_margin_db(), -20.0 * 0.5f64.log10(), 1e3 * EPS);
    let w = m.gain_crossover_omega().unwrap();
    assert_abs(w * w * w + w - 1.0, 0.0, 64.0 * EPS);
    assert_printed(w, 0.6823, 4);
    assert_printed(m.phase_margin_deg(), 21.39, 2);
    // Nyquist: starts at −2 − j∞ after the indentation at s = 0; N = 0, P = 0, Z = 0.
    let ny = l.nyquist(200).unwrap();
    let first_on_axis = ny.contour.iter().position(|s| s.re == 0.0).unwrap();
    assert!((ny.positive[first_on_axis].re + 2.0).abs() < 1e-3);
    assert_eq!((ny.encirclements, ny.open_loop_rhp, ny.closed_loop_rhp), (0, 0, 0));
    assert_eq!(winding(&ny), 0);
}

/// Clockwise encirclements of −1 counted from the sampled image (lower branch = mirror).
fn winding(ny: &Nyquist) -> isize {
    let mut pts: Vec<Complex64> = ny.positive.iter().rev().map(|z| z.conj()).collect();
    pts.extend(&ny.positive);
    pts.push(pts[0]);
    let mut total = 0.0;
    for p in pts.windows(2) {
        let (a, b) = (p[0] + 1.0, p[1] + 1.0);
        total += (b / a).arg();
    }
    -(total / std::f64::consts::TAU).round() as isize
}

#[test]
fn problem_16_8_14_unstable_open_loop() {
    // 16.8.14: L = 4(s+10)/((s−1)(s−2)): real-axis crossing −1.33 at ω = 4√2, exactly −4/3
    // (the notes' "−1.3334" is a rounding slip);
    // N = −2, P = 2, Z = 0 ⇒ AS; L(0) = 20; closed-loop poles −0.5 ± 6.461j; stable iff the
    // gain factor exceeds 0.75, so GM = −2.50 dB (negative: a lower gain margin); PM = 9.2° at
    // ω_mc = 6.770, reached on the continuous branch (+189.2° wraps to 9.2°, notes §3.5).
    let l = tf(&[4.0, 40.0], &[1.0, -3.0, 2.0]);
    assert_eq!(l.dc_gain(), Some(20.0));
    let ny = l.nyquist(400).unwrap();
    assert_eq!((ny.encirclements, ny.open_loop_rhp, ny.closed_loop_rhp), (-2, 2, 0));
    assert_eq!(winding(&ny), -2);
    let m = l.margins().unwrap();
    assert_rel(m.phase_crossover_omega().unwrap(), 4.0 * 2f64.sqrt(), 1e3 * EPS);
    let cross = l.bode(&[4.0 * 2f64.sqrt()]).unwrap().response[0];
    assert_printed(cross.re, -1.33, 2);
    assert_rel(cross.re, -4.0 / 3.0, 1e3 * EPS);
    assert_printed(m.gain_margin_db(), -2.50, 2);
    assert_printed(m.phase_margin_deg(), 9.2, 1);
    assert_printed(m.gain_crossover_omega().unwrap(), 6.770, 3);
    let cl = l.feedback(&TransferFunction::gain(1.0).unwrap()).unwrap().poles().unwrap();
    assert_printed(cl[0].re, -0.5, 4);
    assert_printed(cl[0].im.abs(), 6.461, 3);
    let iv = stable_gain_intervals(l.num(), l.den()).unwrap();
    assert_eq!(iv.len(), 1);
    assert_abs(iv[0].0, 0.75, 1e-12);
}

#[test]
fn eq_16_3_1_phase_margin_sign_corrected() {
    // (16.3.1) prints PM = 180° − ∠G(jω_mc); the correct margin is 180° + ∠L(jω_mc): for
    // L = 1/(s(s+1)), ∠L(jω_mc) = −128.17°, so PM = 51.83°, not 308.17°.
    let l = tf(&[1.0], &[1.0, 1.0, 0.0]);
    let m = l.margins().unwrap();
    let w = m.gain_crossover_omega().unwrap();
    let phase = l.bode(&[w]).unwrap().phase_deg[0];
    assert_rel(m.phase_margin_deg(), 180.0 + phase, 64.0 * EPS);
    assert_printed(180.0 - phase, 308.17, 2);
}

#[test]
fn margins_with_delay() {
    // A delay τ lowers the phase at ω_mc by ωτ and leaves |L| unchanged (15.10.2):
    // 1/(s(s+1)) with τ = 0.2 loses 0.7862·0.2 rad = 9.01°.
    let l = tf(&[1.0], &[1.0, 1.0, 0.0]);
    let m0 = l.margins().unwrap();
    let md = l.clone().with_delay(0.2).unwrap().margins().unwrap();
    let w = m0.gain_crossover_omega().unwrap();
    assert_abs(md.gain_crossover_omega().unwrap(), w, 1e-9);
    assert_rel(md.phase_margin_deg(), m0.phase_margin_deg() - (0.2 * w).to_degrees(), 1e-9);
    // The delayed loop now has phase crossovers (finite GM).
    assert!(md.gain_margin_db().is_finite() && md.gain_margin_db() > 0.0);
}

// ---------------------------------------------------------------- root locus (15.18.3)

#[test]
fn problem_15_20_49_root_locus_rules() {
    // 15.20.49: α = −2.7733, asymptote angles 60°, 180°, 300°; jω crossings at the ends of
    // 4.2221 < k < 417.77.
    let d = poly(&[1.0, -0.08, 0.016]).mul(&poly(&[1.0, 8.6, 50.98]));
    let g = TransferFunction::from_polynomials(poly(&[1.0, 0.2]), d).unwrap();
    let rl = root_locus(&g, 600.0, 0.02).unwrap();
    assert_printed(rl.asymptote_center.unwrap(), -2.7733, 4);
    assert_eq!(rl.asymptote_angles_deg, vec![60.0, 180.0, 300.0]);
    let ks: Vec<f64> = rl.jw_crossings.iter().map(|c| c.1).collect();
    assert_eq!(ks.len(), 2, "{:?}", rl.jw_crossings);
    assert_printed(ks.iter().copied().fold(f64::INFINITY, f64::min), 4.2221, 4);
    assert_printed(ks.iter().copied().fold(0.0, f64::max), 417.77, 2);
    // Every sampled branch point satisfies D₀ + kN₀ = 0.
    for (b, _) in rl.branches.iter().zip(0..) {
        for (j, s) in b.iter().enumerate().step_by(25) {
            let r = g.den().eval_c(*s) + rl.gains[j] * g.num().eval_c(*s);
            assert!(r.norm() <= 1e-6 * (1.0 + rl.gains[j]) * s.norm().max(1.0).powi(4));
        }
    }
}

#[test]
fn problem_15_20_50_three_zeros() {
    // 15.20.50: same poles, zeros −0.3, −1.7, −8.4: K ≈ 2.9 gives s = −0.301 ± 0.299j with
    // ζ = 0.709, ωn = 0.424; (C) AS for k > 0.2456. The gain is read from a plot ("≈ 2.9"), so at
    // exactly 2.9 the pole agrees to two decimals (−0.3003 ± 0.2995j).
    let d = poly(&[1.0, -0.08, 0.016]).mul(&poly(&[1.0, 8.6, 50.98]));
    let n = poly(&[1.0, 0.3]).mul(&poly(&[1.0, 1.7])).mul(&poly(&[1.0, 8.4]));
    let cl = d.add(&n.scale(2.9)).roots().unwrap();
    let slow = cl.iter().find(|s| s.im > 0.0 && s.norm() < 1.0).unwrap();
    assert_printed(slow.re, -0.30, 2);
    assert_printed(slow.im, 0.30, 2);
    let mode = Mode::of(*slow);
    assert_printed(mode.damping_ratio.unwrap(), 0.71, 2);
    assert_printed(mode.natural_frequency, 0.42, 2);
    let iv = stable_gain_intervals(&n, &d).unwrap();
    assert_printed(iv[0].0, 0.2456, 4);
    assert_eq!(iv[0].1, f64::INFINITY);
}

#[test]
fn eq_15_18_9_departure_and_breakaway() {
    // (15.18.9): (s+2)/(s² + 2s + 2): φ(−1 + j) = ∠(p − z) − ∠(p − p̄) + 180° = 45° − 90° + 180°
    // = 135°. Breakaway of 1/(s(s+2)) at s = −1 with k = 1.
    let g = tf(&[1.0, 2.0], &[1.0, 2.0, 2.0]);
    let rl = root_locus(&g, 10.0, 0.05).unwrap();
    let up = rl.departure_deg.iter().find(|(p, _)| p.im > 0.0).unwrap();
    assert_rel(up.1, 135.0, 1e3 * EPS);
    let rl = root_locus(&tf(&[1.0], &[1.0, 2.0, 0.0]), 5.0, 0.05).unwrap();
    assert_eq!(rl.breakaway.len(), 1);
    assert_abs(rl.breakaway[0].0.re, -1.0, 16.0 * EPS);
    assert_abs(rl.breakaway[0].1, 1.0, 16.0 * EPS);
}

// ---------------------------------------------------------------- Bode's sensitivity integral

#[test]
fn problem_16_8_8_and_16_8_9_sensitivity_integral() {
    // (16.8.8)–(16.8.9): ∫₀^∞ ln|S(jω)| dω = π Σ Re pᵢ over ORHP poles of L. 16.8.8 solves
    // L = −1/(s² + 2s + 3) (ERR: the statement says 10/(s² + 2s + 1)); the book's Riemann sum
    // gives 0.0021, the exact value is 0 for both loops. 16.8.9: L = 4/((s−1)(s+2)), pole at 1:
    // π (book 3.1412).
    for l in [tf(&[-1.0], &[1.0, 2.0, 3.0]), tf(&[10.0], &[1.0, 2.0, 1.0])] {
        assert!(sensitivity_integral(&l).unwrap().abs() <= 1e-9);
    }
    let v = sensitivity_integral(&tf(&[4.0], &[1.0, 1.0, -2.0])).unwrap();
    assert_rel(v, std::f64::consts::PI, 1e-9);
    // S = (s² + s − 2)/(s² + s + 2), poles (−1 ± j√7)/2 (printed without the j).
    let s = tf(&[4.0], &[1.0, 1.0, -2.0]).sensitivity().unwrap();
    let p = s.poles().unwrap();
    assert_abs(p[0].re, -0.5, 64.0 * EPS);
    assert_rel(p[0].im.abs(), 7f64.sqrt() / 2.0, 64.0 * EPS);
}

// ---------------------------------------------------------------- typed errors

#[test]
fn frequency_tools_reject_bad_input() {
    let g = tf(&[1.0, 0.0], &[1.0, 1.0]);
    assert!(matches!(sensitivity_integral(&g), Err(LtiError::InvalidArgument { .. })));
    assert!(matches!(tf(&[1.0, 0.0, 0.0], &[1.0, 1.0]).nyquist(50), Err(LtiError::Improper { .. })));
    assert!(matches!(g.bode(&[-1.0]), Err(LtiError::InvalidArgument { .. })));
    assert!(matches!(logspace(2.0, 1.0, 10), Err(LtiError::InvalidArgument { .. })));
    assert!(matches!(root_locus(&g, -1.0, 0.1), Err(LtiError::InvalidArgument { .. })));
    // −1 on the Nyquist plot: L = 1/(s² + 0s + 0) + … closed loop s² + 1 has poles ±j.
    assert!(matches!(tf(&[1.0], &[1.0, 0.0, 0.0]).nyquist(50), Err(LtiError::InvalidArgument { .. })));
}

// ---------------------------------------------------------------- properties

#[test]
fn eq_16_2_4_paired_factor_response_matches_factor_by_factor() {
    // G(jω) with conjugate pole pairs as real quadratics a² − (ω − b)(ω + b) − 2jaω equals the
    // factor-by-factor product to a few ε at every ω: a lightly damped pole (ζ = 1e-7) at
    // resonance, a zero on the axis (G = 0 exactly), and ω so large that the products would
    // overflow (then the interleaved sweep takes over).
    let wn: f64 = 3.0;
    let zeta = 1e-7;
    let g = tf(&[1.0, 0.0, 4.0], &[1.0, 2.0 * zeta * wn, wn * wn, 0.5]);
    let z = g.to_zpk().unwrap();
    let w: Vec<f64> = [0.0, 0.5, 2.0, 2.9999, wn, 3.0001, 1e2, 1e40, 1e200].to_vec();
    let fast = g.freqresp(&w).unwrap();
    for (a, &wi) in fast.iter().zip(&w).take(7) {
        let b = z.eval(Complex64::new(0.0, wi));
        assert!((a - b).norm() <= 32.0 * EPS * b.norm(), "ω = {wi}: {a} vs {b}");
    }
    assert_eq!(fast[2], Complex64::new(0.0, 0.0)); // the zero at s = ±2j
    // far above every root G(jω) → 1/(jω) (the plain product overflows: inf/inf)
    for (a, &wi) in fast.iter().zip(&w).skip(7) {
        let want = Complex64::new(0.0, -1.0 / wi);
        assert!((a - want).norm() <= 1e-12 * want.norm(), "ω = {wi}: {a} vs {want}");
    }
    // the roots are computed once and cached: equal results on a second call, and a delay
    // (which the cache does not depend on) still applies
    assert_eq!(g.freqresp(&w).unwrap(), fast);
    let gd = g.clone().with_delay(0.3).unwrap();
    let wd = gd.freqresp(&[1.0]).unwrap()[0];
    let w1 = g.freqresp(&[1.0]).unwrap()[0];
    assert!((wd - w1 * Complex64::from_polar(1.0, -0.3)).norm() <= 8.0 * EPS * wd.norm());
    assert!(g.freqresp(&[-1.0]).is_err());
}

mod prop {
    use super::*;
    use proptest::prelude::*;

    fn root() -> impl Strategy<Value = Vec<Complex64>> {
        let re = prop_oneof![3 => -5.0..-0.01f64, 2 => 0.01..5.0f64, 1 => Just(0.0)];
        (re, prop_oneof![Just(0.0), 0.1..6.0f64], proptest::bool::ANY).prop_map(|(r, i, pair)| {
            if pair && i != 0.0 {
                vec![Complex64::new(r, i), Complex64::new(r, -i)]
            } else {
                vec![Complex64::new(r, 0.0)]
            }
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// The vectorised sweep (turn counting, one atan2 per ω) gives exactly the branch of
        /// the factor-by-factor phase (16.6.2), including right-half-plane roots, roots at 0
        /// and ω = 0.
        #[test]
        fn sweep_phase_equals_factorwise_phase(
            zeros in proptest::collection::vec(root(), 0..3),
            poles in proptest::collection::vec(root(), 1..4),
            k in prop_oneof![-3.0..-0.1f64, 0.1..3.0f64],
            tau in prop_oneof![Just(0.0), 0.0..0.5f64],
        ) {
            let zeros: Vec<Complex64> = zeros.into_iter().flatten().collect();
            let poles: Vec<Complex64> = poles.into_iter().flatten().collect();
            let z = Zpk::new(zeros, poles, k).unwrap().with_delay(tau).unwrap();
            let mut w = vec![0.0];
            w.extend(logspace(-2.0, 2.0, 60).unwrap());
            let b = z.bode(&w).unwrap();
            for (i, &wi) in w.iter().enumerate() {
                let want = z.phase_deg(wi);
                let g = z.eval(Complex64::new(0.0, wi));
                if !(g.norm().is_finite() && g.norm() > 0.0) {
                    continue; // at a root on the axis the phase is undefined
                }
                prop_assert!((b.phase_deg[i] - want).abs() <= 1e-9 * want.abs().max(1.0), "ω = {}: {} vs {}", wi, b.phase_deg[i], want);
                prop_assert!((b.response[i] - g).norm() <= 1e-12 * g.norm().max(1.0));
            }
        }

        /// The paired-factor G(jω) (16.2.4) agrees with the factor-by-factor product to a few
        /// ε on random systems, right-half-plane and axis roots and delays included.
        #[test]
        fn zpk_freqresp_agrees_with_factor_by_factor_product(
            zeros in proptest::collection::vec(root(), 0..3),
            poles in proptest::collection::vec(root(), 1..5),
            k in prop_oneof![-3.0..-0.1f64, 0.1..3.0f64],
            tau in prop_oneof![Just(0.0), 0.0..0.5f64],
        ) {
            let zeros: Vec<Complex64> = zeros.into_iter().flatten().collect();
            let poles: Vec<Complex64> = poles.into_iter().flatten().collect();
            let n = zeros.len() + poles.len();
            let z = Zpk::new(zeros, poles, k).unwrap().with_delay(tau).unwrap();
            let w = logspace(-3.0, 3.0, 301).unwrap();
            for (a, &wi) in z.freqresp(&w).unwrap().iter().zip(&w) {
                let b = z.eval(Complex64::new(0.0, wi));
                if !b.norm().is_finite() {
                    continue; // a pole on the axis at this ω
                }
                prop_assert!((a - b).norm() <= 8.0 * (n + 2) as f64 * EPS * b.norm(), "ω = {}: {} vs {}", wi, a, b);
            }
        }

        /// The transfer function's G(jω) from its coefficients (guaranteed to FREQRESP_RTOL,
        /// else from the factors) agrees with the factored form on random systems; the gap is
        /// the roots' own rounding (well-separated roots here: ≤ 1e-10 relative).
        #[test]
        fn tf_freqresp_agrees_with_factored_form(
            zeros in proptest::collection::vec(root(), 0..3),
            poles in proptest::collection::vec(root(), 1..5),
            k in prop_oneof![-3.0..-0.1f64, 0.1..3.0f64],
        ) {
            let zeros: Vec<Complex64> = zeros.into_iter().flatten().collect();
            let poles: Vec<Complex64> = poles.into_iter().flatten().collect();
            let g = Zpk::new(zeros, poles, k).unwrap().to_tf().unwrap();
            let w = logspace(-3.0, 3.0, 301).unwrap();
            let fast = g.freqresp(&w).unwrap();
            let slow = g.to_zpk().unwrap().freqresp(&w).unwrap();
            for (a, b) in fast.iter().zip(&slow) {
                if !b.norm().is_finite() {
                    continue; // a pole on the axis at this ω
                }
                prop_assert!((a - b).norm() <= 1e-10 * b.norm() + 1e-300, "{} vs {}", a, b);
            }
        }

        /// Margins are invariant under time scaling L(s) ↦ L(s/a); crossovers scale by a.
        #[test]
        fn margins_invariant_under_time_scaling(
            k in 0.5..50.0f64,
            p in proptest::collection::vec(0.05..20.0f64, 3),
            z in prop_oneof![Just(None), (0.1..30.0f64).prop_map(Some)],
            integrator in proptest::bool::ANY,
            a in prop_oneof![0.01..0.1f64, 0.1..10.0f64, 10.0..100.0f64],
        ) {
            let mut den = poly(&[1.0, p[0]]).mul(&poly(&[1.0, p[1]])).mul(&poly(&[1.0, p[2]]));
            if integrator {
                den = den.mul(&Polynomial::s());
            }
            let num = match z { Some(z) => poly(&[k, k * z]), None => poly(&[k]) };
            let l = TransferFunction::from_polynomials(num, den).unwrap();
            let m = l.margins().unwrap();
            let ms = l.time_scaled(a).unwrap().margins().unwrap();
            prop_assert_eq!(m.gain_crossovers.len(), ms.gain_crossovers.len());
            prop_assert_eq!(m.phase_crossovers.len(), ms.phase_crossovers.len());
            for (c, cs) in m.gain_crossovers.iter().zip(&ms.gain_crossovers) {
                prop_assert!((cs.omega - a * c.omega).abs() <= 1e-8 * a * c.omega);
                prop_assert!((cs.phase_margin_deg - c.phase_margin_deg).abs() <= 1e-7);
            }
            for (c, cs) in m.phase_crossovers.iter().zip(&ms.phase_crossovers) {
                prop_assert!((cs.omega - a * c.omega).abs() <= 1e-8 * a * c.omega.max(1e-300));
                prop_assert!((cs.gain_margin_db - c.gain_margin_db).abs() <= 1e-7);
            }
        }
    }
}
