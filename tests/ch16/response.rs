//! §16.1–16.7: phase and time shift, the frequency-response law, Bode data of poles at zero,
//! real and complex poles, the RC filter; problems 16.8.1–16.8.7.

use super::*;
use std::f64::consts::PI;

#[test]
fn sec_16_1_phase_shift_is_a_time_shift() {
    // (16.1.1)–(16.1.5): g(t) = sin(ωt + φ) = f(t − Δt) with Δt = −φ/ω; φ > 0 advances g,
    // φ < 0 delays it. After (16.1.7): g leads f when 0 < φ̂ − φ ≤ 180° (mod 360°).
    let w = 2.5;
    for phi in [-2.0, -0.3, 0.0, 0.7, PI] {
        let dt = time_shift(phi, w).unwrap();
        assert_eq!(dt, -phi / w);
        for t in [0.0, 0.4, 3.1] {
            // absolute: sines of size 1, arguments of size ≤ 10
            assert_abs((w * t + phi).sin(), (w * (t - dt)).sin(), 16.0 * EPS);
        }
    }
    assert!(leads(30.0, 0.0).unwrap());
    assert!(leads(180.0, 0.0).unwrap());
    assert!(!leads(190.0, 0.0).unwrap()); // leading by 190° is lagging by 170°
    assert!(!leads(0.0, 0.0).unwrap());
    assert!(leads(-170.0, 170.0).unwrap()); // −170° − 170° ≡ 20°
    assert!(matches!(time_shift(1.0, 0.0), Err(LtiError::InvalidArgument { .. })));
    // The frequency-response law (16.2.1)–(16.2.5): a pure delay e^{−τs} has ∠G = −ωτ, so the
    // output lags the input by Δt = τ exactly, and its gain is 1.
    let delay = tf(&[1.0], &[1.0]).with_delay(0.4).unwrap();
    let b = delay.bode(&[w]).unwrap();
    assert_abs(b.magnitude_db[0], 0.0, 4.0 * EPS);
    assert_rel(time_shift(b.phase_deg[0].to_radians(), w).unwrap(), 0.4, 8.0 * EPS);
}

#[test]
fn eq_16_2_4_harmonic_steady_state_of_a_lag() {
    // (16.2.1)–(16.2.5): the input sin ωt into the AS system 1/(s + 1) settles to
    // |G(jω)| sin(ωt + ∠G(jω)), |G| = 1/√(1 + ω²), ∠G = −atan ω; in the time domain the response
    // crosses zero Δt = atan(ω)/ω after the input (16.1.4). The forced response is the impulse
    // response of G·ω/(s² + ω²), exact; by t = 40 the transient e^{−t} is below 1e-17.
    let w = 2.0;
    let g = tf(&[1.0], &[1.0, 1.0]);
    let b = at(&g, w);
    assert_rel(10f64.powf(b.magnitude_db[0] / 20.0), 1.0 / (1.0 + w * w).sqrt(), 8.0 * EPS);
    assert_rel(b.phase_deg[0], -w.atan().to_degrees(), 8.0 * EPS);
    let y = g.series(&tf(&[w], &[1.0, 0.0, w * w])).unwrap();
    let t = time_grid(40.0, 4001).unwrap();
    let r = y.impulse(&t).unwrap();
    let amp = 1.0 / (1.0 + w * w).sqrt();
    let dt = time_shift(b.phase_deg[0].to_radians(), w).unwrap();
    assert_rel(dt, w.atan() / w, 8.0 * EPS);
    for k in (3000..4001).step_by(97) {
        let want = amp * (w * (t[k] - dt)).sin();
        assert_abs(r.y[0][k], want, 1e3 * EPS);
    }
}

#[test]
fn sec_16_4_pole_at_zero_is_infinite_not_nan() {
    // §16.4: 1/(ms) has −20 dB/decade and −90° for every ω > 0, and at ω = 0 the magnitude is
    // +∞ (16.4.1–4). Issue 19, item 2: at a pole on the imaginary axis freqresp, bode and eval
    // give |G| = +∞ (dB +∞) and the phase of the limit ω → ω₀⁺ — never NaN. At a zero on the
    // axis the magnitude is 0 (−∞ dB), the phase again the limit from above.
    let m = 2.0;
    let g = tf(&[1.0], &[m, 0.0]);
    let w = [0.0, 0.1, 1.0, 10.0];
    let b = g.bode(&w).unwrap();
    assert_eq!(b.magnitude_db[0], f64::INFINITY);
    assert_eq!(b.phase_deg[0], -90.0);
    for (k, wk) in w.iter().enumerate().skip(1) {
        assert_abs(b.magnitude_db[k], -20.0 * (m * wk).log10(), 64.0 * EPS);
        assert_abs(b.phase_deg[k], -90.0, 64.0 * EPS);
    }
    // G(j0⁺) = −j/(mω) → the point at infinity along −j
    let f = g.freqresp(&w).unwrap();
    assert_eq!(f[0], Complex64::new(0.0, f64::NEG_INFINITY));
    assert!(g.eval(Complex64::new(0.0, 0.0)).norm().is_infinite());
    assert!(!g.eval(Complex64::new(0.0, 0.0)).re.is_nan());
    // an integrator with a lag, 1/(s(s + 1)): −90° at 0⁺; the resonance 1/(s² + 1) at ω = 1:
    // +∞ and −180° (from above: the pole pair's factors j(ω − 1)·j(ω + 1) → −1·(ω − 1)(ω + 1))
    let b = tf(&[1.0], &[1.0, 1.0, 0.0]).bode(&[0.0]).unwrap();
    assert_eq!((b.magnitude_db[0], b.phase_deg[0]), (f64::INFINITY, -90.0));
    let res = tf(&[1.0], &[1.0, 0.0, 1.0]);
    let b = res.bode(&[0.5, 1.0, 2.0]).unwrap();
    assert_eq!(b.magnitude_db[1], f64::INFINITY);
    assert_abs(b.phase_deg[0], 0.0, 64.0 * EPS);
    assert_abs(b.phase_deg[1], -180.0, 64.0 * EPS);
    assert_abs(b.phase_deg[2], -180.0, 64.0 * EPS);
    let f = res.freqresp(&[1.0]).unwrap()[0];
    assert!(f.norm().is_infinite() && !f.re.is_nan() && !f.im.is_nan(), "{f}");
    let z = res.to_zpk().unwrap();
    assert!(z.bode(&[1.0]).unwrap().magnitude_db[0] == f64::INFINITY);
    assert!(!z.eval(Complex64::new(0.0, 1.0)).re.is_nan());
    // a washout s/(s + 2) at ω = 0: |G| = 0, −∞ dB, phase +90° (the book's low-frequency rule)
    let b = tf(&[1.0, 0.0], &[1.0, 2.0]).bode(&[0.0]).unwrap();
    assert_eq!((b.magnitude_db[0], b.phase_deg[0]), (f64::NEG_INFINITY, 90.0));
    // a common factor cancels in the limit: s/(s(s + 1)) at 0 is 1
    assert_eq!(tf(&[1.0, 0.0], &[1.0, 1.0, 0.0]).freqresp(&[0.0]).unwrap()[0], Complex64::new(1.0, 0.0));
    // a delayed integrator stays infinite (rotated), never NaN
    let gd = g.clone().with_delay(0.3).unwrap();
    let f = gd.freqresp(&[0.0]).unwrap()[0];
    assert!(f.norm().is_infinite() && !f.re.is_nan() && !f.im.is_nan());
    // the Nyquist image of 1/(s(s + 1)²) is finite on its indented contour
    let ny = tf(&[1.0], &[1.0, 2.0, 1.0, 0.0]).nyquist(100).unwrap();
    assert!(ny.positive.iter().all(|z| z.re.is_finite() && z.im.is_finite()));
}

#[test]
fn issue_33_transfer_function_at_a_pole_is_the_point_at_infinity() {
    // docs/robustness.md, "Where ∞ is the answer": G at a pole is ∞, the exact value of a
    // rational function there (python-control and Matlab give ∞ too), in the direction of the
    // limit G(s + h), h → 0⁺ real: 1/(s + 1) at −1 is 1/h → +∞; 1/(s² + 2s + 2) at −1 + j is
    // 1/(D′(s)h) = 1/(2jh) → −j∞. A value beyond the f64 range is ∞ in its direction
    // (1e300/(s + 1e-300) at 0 is 1e600: +∞, where it used to come out as −∞ − j∞); a
    // cancelled factor gives the limit; elsewhere the value is finite.
    let inf = f64::INFINITY;
    let c = Complex64::new;
    assert_eq!(tf(&[1.0], &[1.0, 1.0]).eval(c(-1.0, 0.0)), c(inf, 0.0));
    assert_eq!(tf(&[1.0], &[1.0, 2.0, 2.0]).eval(c(-1.0, 1.0)), c(0.0, -inf));
    assert_eq!(tf(&[1e300], &[1.0, 1e-300]).eval(c(0.0, 0.0)), c(inf, 0.0));
    assert_eq!(tf(&[1.0, 1.0], &[1.0, 3.0, 2.0]).eval(c(-1.0, 0.0)), c(1.0, 0.0));
    assert_eq!(tf(&[1.0], &[1.0, 1.0]).eval(c(-1.0, 1.0)), c(0.0, -1.0));
}

#[test]
fn issue_33_freqresp_at_an_axis_pole_is_infinite_inside_ok() {
    // docs/robustness.md, "Where ∞ is the answer": a grid point jω₀ that is a pole gives the
    // point at infinity in the direction of the limit ω → ω₀⁺ and leaves the other points
    // alone: 1/(s² + 1) = 1/(1 − ω²) → −∞ from above ω₀ = 1. Where |G(jω)| only exceeds the
    // range (1e300/(s + 1e-300) at ω = 1e-300, |G| ≈ 7e599) the value is ∞ in its direction
    // (−45°: both components).
    let inf = f64::INFINITY;
    let w = [0.5, 1.0, 2.0];
    let f = tf(&[1.0], &[1.0, 0.0, 1.0]).freqresp(&w).unwrap();
    assert_eq!(f[1], Complex64::new(-inf, 0.0));
    for k in [0, 2] {
        assert_eq!(f[k].im, 0.0);
        assert_rel(f[k].re, 1.0 / (1.0 - w[k] * w[k]), 4.0 * EPS);
    }
    let f = tf(&[1e300], &[1.0, 1e-300]).freqresp(&[1e-300]).unwrap();
    assert_eq!(f[0], Complex64::new(inf, -inf));
}

#[test]
fn issue_33_bode_at_an_axis_pole_is_infinite_db_with_a_finite_phase() {
    // docs/robustness.md, "Where ∞ is the answer": at a pole on the grid the magnitude is
    // +∞ dB (§16.4: |G(j0)| = +∞ for 1/(ms)), the phase the finite limit ω → ω₀⁺ on the
    // branch of the factors; the other points are the ordinary values. 1/(s(s² + 1)): −90° on
    // (0, 1), −270° above 1 (the pair's factors turn by −180° there).
    let w = [0.0, 0.5, 1.0, 2.0];
    let b = tf(&[1.0], &[1.0, 0.0, 1.0, 0.0]).bode(&w).unwrap();
    assert_eq!((b.magnitude_db[0], b.magnitude_db[2]), (f64::INFINITY, f64::INFINITY));
    for (k, want) in [(0, -90.0), (1, -90.0), (2, -270.0), (3, -270.0)] {
        assert_abs(b.phase_deg[k], want, 64.0 * EPS * 270.0);
    }
    for k in [1, 3] {
        assert_abs(b.magnitude_db[k], -20.0 * (w[k] * (1.0 - w[k] * w[k])).abs().log10(), 64.0 * EPS * 20.0);
    }
    // |G| beyond the f64 range is not a pole: the response is ∞, the dB value finite
    // (20 log₁₀(1e600/√2) = 12000 − 10 log₁₀ 2)
    let b = tf(&[1e300], &[1.0, 1e-300]).bode(&[1e-300]).unwrap();
    assert!(b.response[0].norm().is_infinite());
    assert_rel(b.magnitude_db[0], 12000.0 - 10.0 * 2f64.log10(), 64.0 * EPS);
    assert_abs(b.phase_deg[0], -45.0, 64.0 * EPS * 45.0);
}

#[test]
fn eq_16_5_7_real_pole_minus_3_db() {
    // (16.5.3), (16.5.7): α/(s − p): |G| = |α|/√(ω² + p²), −3 dB (exactly −10 log₁₀ 2) at ω = |p|.
    let g = tf(&[5.0], &[1.0, 4.0]);
    let r = at(&g, 4.0);
    assert_abs(r.magnitude_db[0] - 20.0 * (5.0f64 / 4.0).log10(), -10.0 * 2f64.log10(), 64.0 * EPS);
    assert_rel(r.phase_deg[0], -45.0, 8.0 * EPS);
}

#[test]
fn sec_16_7_rc_low_pass_filter() {
    // §16.7, Ex 16.7.1: V_out = 1/(RCs + 1)·V_in (−3 dB and −45° at ω = 1/RC) and
    // I = Cs/(RCs + 1)·V_in → V_in/R at high frequency (|I/V_in| → 1/R, phase → 0).
    let (r, c) = (1.0e3, 2.0e-6); // 1 kΩ, 2 µF: 1/RC = 500 rad/s
    let vout = tf(&[1.0], &[r * c, 1.0]);
    let b = at(&vout, 1.0 / (r * c));
    assert_abs(b.magnitude_db[0], -10.0 * 2f64.log10(), 64.0 * EPS);
    assert_rel(b.phase_deg[0], -45.0, 16.0 * EPS);
    let current = tf(&[c, 0.0], &[r * c, 1.0]);
    let high = current.freqresp(&[1e9]).unwrap()[0];
    // |G − 1/R| = (1/R)/|1 + jωRC| ≈ 1/(R·ωRC) = 1e-9/(R·2e-3): relative 5e-7
    assert_rel(high.norm(), 1.0 / r, 1e-6);
    assert!(high.arg().abs() < 1e-6);
    assert_eq!(current.freqresp(&[0.0]).unwrap()[0], Complex64::new(0.0, 0.0));
}

#[test]
fn problem_16_8_1_sensor_at_60_hz() {
    // 16.8.1: 9.2/(0.031s + 1): DC gain 42.32 for 4.6 V (0°); at 60 Hz |G| = 0.7844 and the
    // 3.3 mV ripple comes out with amplitude 2.588e-3 (C; printed 2.6e-3) and phase −85.11°
    // (C; the book prints −85.16°/−85.15°, a rounding of an approximate computation).
    let g = tf(&[9.2], &[0.031, 1.0]);
    assert_rel(g.dc_gain().unwrap() * 4.6, 42.32, 4.0 * EPS);
    let r = at(&g, 120.0 * PI);
    let mag = 10f64.powf(r.magnitude_db[0] / 20.0);
    assert_printed(mag, 0.7844, 4);
    assert_printed(mag * 3.3e-3, 2.588e-3, 6);
    assert_printed(r.phase_deg[0], -85.11, 2);
}

#[test]
fn problem_16_8_2_amplifier_input_frequency() {
    // 16.8.2: α/(Ts + 1) with α = 43.1, T = 0.037 turns 2.8 V into 76.2 V at
    // ω = √((2.8α/76.2)² − 1)/T = 33.19 rad/s: the gain crossover of (2.8/76.2)·G.
    let g = tf(&[43.1], &[0.037, 1.0]);
    let m = g.scale(2.8 / 76.2).unwrap().margins().unwrap();
    assert_eq!(m.gain_crossovers.len(), 1);
    let w = m.gain_crossovers[0].omega;
    assert_printed(w, 33.19, 2);
    assert_rel(w, ((2.8 * 43.1 / 76.2f64).powi(2) - 1.0).sqrt() / 0.037, 64.0 * EPS);
    assert_rel(10f64.powf(at(&g, w).magnitude_db[0] / 20.0), 76.2 / 2.8, 64.0 * EPS);
}

#[test]
fn problem_16_8_3_lead_at_omega_4() {
    // 16.8.3: the lag filter with pole −2, zero −6 and DC gain 10, (10/3)(s+6)/(s+2), at ω = 4:
    // 14.6 dB, −29.75° (C: 14.607 dB, −29.745°).
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
        // a golden search locates a maximum to ~√ε relative (the function is flat there)
        assert_abs(w, (1.0 - 2.0 * zeta * zeta).sqrt(), 1e-6);
    }
}

#[test]
fn problem_16_8_6_phase_branches() {
    // 16.8.6–7 and (16.6.2): the low-frequency phase is 0° or −180° by the sign of the DC
    // gain, ±90° per zero/pole at 0; the phase is continuous in ω (factor by factor).
    let w = logspace(-3.0, 4.0, 701).unwrap();
    let rooftop_den = poly(&[1.0, 2.0, 1.0]).mul(&poly(&[1.0, 20.0, 100.0])).unwrap();
    let cases: [(&str, TransferFunction, f64, f64); 5] = [
        ("lead", tf(&[1.0, 2.0], &[1.0, 10.0]), 0.0, 0.0),
        ("nonminimum phase", tf(&[1.0, -2.0], &[1.0, 10.0]), -180.0, -360.0),
        ("allpass", tf(&[1.0, -2.0], &[1.0, 2.0]), -180.0, -360.0),
        ("washout", tf(&[1.0, 0.0], &[1.0, 2.0]), 90.0, 0.0),
        ("rooftop", tf(&[1.0, 0.0, 0.0], rooftop_den.coeffs()), 180.0, -180.0),
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
fn eq_16_6_3_lightly_damped_and_high_frequency() {
    // Notes §3.4–3.5: a coarse grid across a ζ = 0.001 resonance keeps the phase on one branch
    // (0 → −180°, no ±360° jumps), and 1/(s+1)¹⁰ at ω = 10⁴ is −800 dB without overflow.
    let g = tf(&[1.0], &[1.0, 0.002, 1.0]);
    let b = g.bode(&[0.5, 0.999, 1.001, 2.0]).unwrap();
    assert!(b.phase_deg.windows(2).all(|p| p[1] < p[0]) && b.phase_deg[3] > -180.0);
    let z = Zpk::new(vec![], vec![Complex64::new(-1.0, 0.0); 10], 1.0).unwrap();
    let b = z.bode(&[1e4]).unwrap();
    let want_db = -10.0 * 10.0 * (1.0f64 + 1e8).log10();
    assert_rel(b.magnitude_db[0], want_db, 64.0 * EPS);
    assert_rel(b.phase_deg[0], -10.0 * 1e4f64.atan().to_degrees(), 64.0 * EPS);
    // From the expanded polynomial (s + 1)¹⁰ — exact integer coefficients — the magnitude comes
    // from the coefficients now (issue 19: Bode no longer inherits the tenfold root's ε^{1/10}
    // splitting): ln|G| to a few ε times its condition number Σ|dₖ|ωᵏ/|D| ≈ 1.
    let den = [1.0, 10.0, 45.0, 120.0, 210.0, 252.0, 210.0, 120.0, 45.0, 10.0, 1.0];
    let b = tf(&[1.0], &den).bode(&[1e4]).unwrap();
    assert_rel(b.magnitude_db[0], want_db, 64.0 * EPS);
}

#[test]
fn eq_16_2_4_state_space_bode_matches_transfer_function() {
    // (16.2.4) for a state-space model: the DO with position output is 1/(ms² + cs + k).
    let s = Sdof::new(2.0, 0.4, 8.0).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let w = logspace(-1.0, 1.0, 9).unwrap();
    let a = s.bode(0, 0, &w).unwrap();
    let b = tf(&[1.0], &[2.0, 0.4, 8.0]).bode(&w).unwrap();
    for k in 0..w.len() {
        // absolute in dB and degrees: the ss → tf coefficients carry ~10ε relative each
        assert_abs(a.magnitude_db[k], b.magnitude_db[k], 1e3 * EPS);
        assert_abs(a.phase_deg[k], b.phase_deg[k], 1e3 * EPS);
    }
}

#[test]
fn eq_16_2_4_paired_factor_response_matches_factor_by_factor() {
    // G(jω) of a zero–pole–gain model with conjugate pairs multiplied as real quadratics
    // a² − (ω − b)(ω + b) − 2jaω equals the factor-by-factor product to a few ε at every ω, and
    // the coefficient form of the transfer function agrees: a lightly damped pole (ζ = 1e-7) at
    // resonance, a zero on the axis (G = 0 exactly), and ω so large that the products would
    // overflow.
    let wn: f64 = 3.0;
    let zeta = 1e-7;
    let g = tf(&[1.0, 0.0, 4.0], &[1.0, 2.0 * zeta * wn, wn * wn, 0.5]);
    let z = g.to_zpk().unwrap();
    let w: Vec<f64> = [0.0, 0.5, 2.0, 2.9999, wn, 3.0001, 1e2, 1e40, 1e200].to_vec();
    let fast = g.freqresp(&w).unwrap();
    let paired = z.freqresp(&w).unwrap();
    for ((a, p), &wi) in fast.iter().zip(&paired).zip(&w).take(7) {
        let b = z.eval(Complex64::new(0.0, wi));
        // the factored forms agree to a few ε; the coefficient form to its condition number,
        // which at the resonance (|D| ≈ 1.5e-6·ω³) is ≈ 10⁷: 1e-8 relative there
        assert!((p - b).norm() <= 32.0 * EPS * b.norm(), "ω = {wi}: {p} vs {b}");
        assert!((a - b).norm() <= 1e-8 * b.norm(), "ω = {wi}: {a} vs {b}");
    }
    assert_eq!(fast[2], Complex64::new(0.0, 0.0)); // the zero at s = ±2j
    // far above every root G(jω) → 1/(jω) (the plain product overflows: inf/inf)
    for (a, &wi) in fast.iter().zip(&w).skip(7) {
        let want = Complex64::new(0.0, -1.0 / wi);
        assert!((a - want).norm() <= 1e-12 * want.norm(), "ω = {wi}: {a} vs {want}");
    }
    // a delay multiplies by e^{−jωτ}
    let gd = g.clone().with_delay(0.3).unwrap();
    let wd = gd.freqresp(&[1.0]).unwrap()[0];
    let w1 = g.freqresp(&[1.0]).unwrap()[0];
    assert!((wd - w1 * Complex64::from_polar(1.0, -0.3)).norm() <= 8.0 * EPS * wd.norm());
    assert!(g.freqresp(&[-1.0]).is_err());
}

#[test]
fn example_16_7_1_rc_circuit_from_its_two_equations() {
    // Ex 16.7.1: V_in − V_out = RI and V_out = I/(Cs), i.e. (16.7.1) V_out = (V_in − V_out)/(RCs):
    // a unity-feedback loop around 1/(RCs), so V_out = V_in/(RCs + 1) = (1/RC)/(s + 1/RC)·V_in,
    // and I = Cs·V_out = Cs/(RCs + 1)·V_in, which tends to V_in/R at high frequency.
    let (r, c) = (4.7e3, 1.0e-6); // 4.7 kΩ, 1 µF
    let integrator = tf(&[1.0], &[r * c, 0.0]);
    let vout = integrator.feedback(&TransferFunction::gain(1.0).unwrap()).unwrap();
    let current = vout.series(&tf(&[c, 0.0], &[1.0])).unwrap();
    let want_vout = tf(&[1.0 / (r * c)], &[1.0, 1.0 / (r * c)]);
    let want_current = tf(&[c, 0.0], &[r * c, 1.0]);
    for w in [0.0, 10.0, 1.0 / (r * c), 1e4, 1e7] {
        let s = Complex64::new(0.0, w);
        let (g, h) = (vout.eval(s), want_vout.eval(s));
        assert!((g - h).norm() <= 16.0 * EPS * h.norm().max(EPS), "V_out at ω = {w}");
        let (g, h) = (current.eval(s), want_current.eval(s));
        assert!((g - h).norm() <= 16.0 * EPS * h.norm(), "I at ω = {w}");
    }
    // at high frequency the capacitor is a short: |I/V_in| → 1/R with |I/V_in − 1/R| ≈ 1/(R·ωRC)
    let w = 1e8;
    let hi = current.eval(Complex64::new(0.0, w));
    assert_abs(hi.norm() * r, 1.0, 1.0 / (w * r * c));
}

#[test]
fn problem_16_8_5_resonance_frequency_and_peak() {
    // 16.8.5: |G(jω)| = 1/√(ω⁴ + 2(2ζ² − 1)ωn²ω² + ωn⁴) for G = 1/(s² + 2ζωn s + ωn²). For
    // ζ < 1/√2 it peaks at ωr = ωn√(1 − 2ζ²) with |G(jωr)| = 1/(2ζωn²√(1 − ζ²)); for ζ ≥ 1/√2 it
    // never exceeds the DC gain 1/ωn² (resonance damping 1/√2). (ERR: the printed ωr range
    // "0.9592–0.5292" for ζ = 0.1–0.7 should be 0.9899–0.1414, problem_16_8_4_resonance_peaks.)
    let w = logspace(-2.0, 2.0, 801).unwrap();
    for wn in [0.5f64, 2.0, 30.0] {
        for zeta in [0.05f64, 0.2, 0.5, 0.7, 0.705, 0.72, 0.9] {
            let g = tf(&[1.0], &[1.0, 2.0 * zeta * wn, wn * wn]);
            let omega: Vec<f64> = w.iter().map(|x| x * wn).collect();
            let mag: Vec<f64> = g.bode(&omega).unwrap().response.iter().map(|z| z.norm()).collect();
            let formula = |x: f64| {
                1.0 / (x.powi(4) + 2.0 * (2.0 * zeta * zeta - 1.0) * wn * wn * x * x + wn.powi(4)).sqrt()
            };
            for (k, &x) in omega.iter().enumerate() {
                assert_rel(mag[k], formula(x), 64.0 * EPS);
            }
            let dc = 1.0 / (wn * wn);
            if zeta < std::f64::consts::FRAC_1_SQRT_2 {
                let wr = wn * (1.0 - 2.0 * zeta * zeta).sqrt();
                let peak = 1.0 / (2.0 * zeta * wn * wn * (1.0 - zeta * zeta).sqrt());
                assert_rel(at(&g, wr).response[0].norm(), peak, 64.0 * EPS);
                // ωr is the maximum: no sample exceeds the peak, the neighbours are lower
                assert!(mag.iter().all(|&m| m <= peak * (1.0 + 64.0 * EPS)));
                assert!(
                    at(&g, wr * 1.01).response[0].norm() < peak
                        && at(&g, wr * 0.99).response[0].norm() < peak
                );
                assert!(peak > dc);
            } else {
                assert!(mag.iter().all(|&m| m <= dc * (1.0 + 64.0 * EPS)), "ζ = {zeta}: above DC gain");
            }
        }
    }
}

#[test]
fn problem_16_8_7_rooftop_and_integrator_bode_asymptotes() {
    // 16.8.7 (plots only in the book): the hand-sketch rules, checked on the computed Bode data.
    // i) rooftop s²/((s + 1)²(s + 10)²): +40 dB/dec below ω = 1, flat between the corners at the
    // asymptote 20 log₁₀(1/100) = −40 dB, −40 dB/dec above ω = 10; phase 180° − 2 atan ω −
    // 2 atan(ω/10), from +180° to −180°.
    let den = poly(&[1.0, 2.0, 1.0]).mul(&poly(&[1.0, 20.0, 100.0])).unwrap();
    let g = tf(&[1.0, 0.0, 0.0], den.coeffs());
    let slope = |g: &TransferFunction, w: f64| {
        let b = g.bode(&[w, 10.0 * w]).unwrap();
        b.magnitude_db[1] - b.magnitude_db[0] // dB per decade
    };
    assert_abs(slope(&g, 1e-4), 40.0, 1e-3); // the corner's influence at 1e-4 is O(ω²) dB
    assert_abs(slope(&g, 1e4), -40.0, 1e-3);
    assert_abs(at(&g, 3.0).magnitude_db[0], -40.0, 3.0); // the flat top, within the ±3 dB corners
    for w in [1e-3f64, 0.5, 1.0, 3.0, 10.0, 100.0, 1e4] {
        let want = 180.0 - 2.0 * w.atan().to_degrees() - 2.0 * (w / 10.0).atan().to_degrees();
        assert_abs(at(&g, w).phase_deg[0], want, 1e3 * EPS * 180.0);
        // the exact magnitude, factor by factor
        let mag = w * w / ((1.0 + w * w) * (100.0 + w * w));
        assert_rel(at(&g, w).response[0].norm(), mag, 64.0 * EPS);
    }
    // ii) (s + 1)(s + 100)/(s(s + 5)(s + 10)): at low frequency 2/s (−20 dB/dec, −90°, 6.02 dB at
    // ω = 1 on the asymptote), at high frequency 1/s (−20 dB/dec, −90°); in between the phase
    // is −90° + atan ω + atan(ω/100) − atan(ω/5) − atan(ω/10).
    let num = poly(&[1.0, 1.0]).mul(&poly(&[1.0, 100.0])).unwrap();
    let den = poly(&[1.0, 0.0]).mul(&poly(&[1.0, 5.0])).unwrap().mul(&poly(&[1.0, 10.0])).unwrap();
    let g = TransferFunction::from_polynomials(num, den).unwrap();
    assert_abs(slope(&g, 1e-5), -20.0, 1e-3);
    assert_abs(slope(&g, 1e6), -20.0, 1e-3);
    assert_abs(at(&g, 1e-5).magnitude_db[0], 20.0 * (2.0f64 / 1e-5).log10(), 1e-3);
    assert_abs(at(&g, 1e7).magnitude_db[0], 20.0 * (1.0f64 / 1e7).log10(), 1e-3);
    for w in [1e-4f64, 1.0, 7.0, 30.0, 1e3, 1e6] {
        let want = -90.0 + w.atan().to_degrees() + (w / 100.0).atan().to_degrees()
            - (w / 5.0).atan().to_degrees()
            - (w / 10.0).atan().to_degrees();
        assert_abs(at(&g, w).phase_deg[0], want, 1e3 * EPS * 180.0);
    }
}
