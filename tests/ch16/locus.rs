//! §15.18.3 root-locus rules and the loop problems that use them: 15.20.49–50, 16.8.11–16.8.12.

use super::*;
use crate::support::{nan_max, nan_min};

#[test]
fn problem_15_20_49_root_locus_rules() {
    // 15.20.49: α = −2.7733, asymptote angles 60°, 180°, 300°; jω crossings at the ends of
    // 4.2221 < k < 417.77.
    let d = poly(&[1.0, -0.08, 0.016]).mul(&poly(&[1.0, 8.6, 50.98])).unwrap();
    let g = TransferFunction::from_polynomials(poly(&[1.0, 0.2]), d).unwrap();
    let rl = root_locus(&g, 600.0, 0.02).unwrap();
    assert_printed(rl.asymptote_center.unwrap(), -2.7733, 4);
    assert_eq!(rl.asymptote_angles_deg, vec![60.0, 180.0, 300.0]);
    let ks: Vec<f64> = rl.jw_crossings.iter().map(|c| c.1).collect();
    assert_eq!(ks.len(), 2, "{:?}", rl.jw_crossings);
    assert_printed(ks.iter().copied().fold(f64::INFINITY, nan_min), 4.2221, 4);
    assert_printed(ks.iter().copied().fold(0.0, nan_max), 417.77, 2);
    // Every sampled branch point satisfies D₀ + kN₀ = 0 to the roots' accuracy (~1e-10
    // relative for these well-separated branches), relative to the size of the terms.
    for b in &rl.branches {
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
    let d = poly(&[1.0, -0.08, 0.016]).mul(&poly(&[1.0, 8.6, 50.98])).unwrap();
    let n = poly(&[1.0, 0.3]).mul(&poly(&[1.0, 1.7])).unwrap().mul(&poly(&[1.0, 8.4])).unwrap();
    let cl = d.add(&n.scale(2.9).unwrap()).unwrap().roots().unwrap();
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
    assert_rel(up.1, 135.0, 8.0 * EPS);
    let rl = root_locus(&tf(&[1.0], &[1.0, 2.0, 0.0]), 5.0, 0.05).unwrap();
    assert_eq!(rl.breakaway.len(), 1);
    assert_rel(rl.breakaway[0].0.re, -1.0, 16.0 * EPS);
    assert_rel(rl.breakaway[0].1, 1.0, 16.0 * EPS);
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
    let ramp = tf(&[1.0], &[1.0, 0.0, 0.0]);
    for (k, e) in [(197.9617, 0.0505), (31.7973, 0.3145), (12.7410, 0.7849)] {
        let err = g.scale(k).unwrap().sensitivity().unwrap().series(&ramp).unwrap();
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
    let e = g.scale(ki).unwrap().sensitivity().unwrap().series(&tf(&[1.0], &[1.0, 0.0, 0.0])).unwrap();
    assert_eq!(e.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(1.0 / ki));
}
