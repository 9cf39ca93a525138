//! §15.16–15.18: the Routh test, stable gain intervals and servo loops; problems 15.20.39–41,
//! 15.20.43, 15.20.46–49.

use super::*;

#[test]
fn eq_15_17_1_and_15_17_2_low_order_conditions() {
    // (15.17.1): n = 3 Hurwitz ⇔ aᵢ > 0 and a₀ < a₁a₂; (15.17.2): n = 4 ⇔ aᵢ > 0 and
    // a₀a₃² + a₁² < a₁a₂a₃. The general Routh array agrees on a grid of coefficients.
    for a2 in [0.5, 1.0, 3.0] {
        for a1 in [0.2, 1.0, 4.0] {
            for a0 in [0.1, 1.0, 5.0] {
                let cubic = routh(&poly(&[1.0, a2, a1, a0])).unwrap().is_hurwitz();
                assert_eq!(cubic, a0 < a1 * a2, "a = {a2}, {a1}, {a0}");
                for a3 in [0.7, 2.0] {
                    let quartic = routh(&poly(&[1.0, a3, a2, a1, a0])).unwrap().is_hurwitz();
                    assert_eq!(quartic, a0 * a3 * a3 + a1 * a1 < a1 * a2 * a3);
                }
            }
        }
    }
}

#[test]
fn sec_15_17_routh_special_case_zero_in_first_column() {
    // s⁴ + s³ + 2s² + 2s + 3: the s² row starts with 0 (ε-substitution); 2 roots in the ORHP.
    let ra = routh(&poly(&[1.0, 1.0, 2.0, 2.0, 3.0])).unwrap();
    assert!(ra.epsilon_used);
    assert_eq!((ra.rhp, ra.imaginary, ra.lhp()), (2, 0, 2));
}

#[test]
fn sec_15_17_routh_special_case_row_of_zeros() {
    // s⁵ + 2s⁴ + 24s³ + 48s² − 25s − 50 = (s+2)(s²−1)(s²+25): the s³ row vanishes; the auxiliary
    // polynomial 2s⁴ + 48s² − 50 has roots ±1, ±5j: one ORHP root, two on the axis.
    let ra = routh(&poly(&[1.0, 2.0, 24.0, 48.0, -25.0, -50.0])).unwrap();
    assert_eq!(ra.auxiliary.as_ref().unwrap().coeffs(), &[2.0, 0.0, 48.0, 0.0, -50.0]);
    assert_eq!((ra.rhp, ra.imaginary, ra.lhp()), (1, 2, 2));
    // s⁴ + 5s² + 4 = (s²+1)(s²+4): all four roots on the axis.
    let ra = routh(&poly(&[1.0, 0.0, 5.0, 0.0, 4.0])).unwrap();
    assert_eq!((ra.rhp, ra.imaginary), (0, 4));
}

fn intervals(n: &[f64], d: &Polynomial) -> Vec<(f64, f64)> {
    stable_gain_intervals(&poly(n), d).unwrap()
}

#[test]
fn problem_15_20_39_proportional_gain_bound() {
    // 15.20.39: S = (s+0.5)/(s + 0.5 + 0.0203Kp): AS iff Kp > −24.6 (C: −24.631 = −0.5/0.0203).
    let iv = intervals(&[0.0203], &poly(&[1.0, 0.5]));
    assert_eq!(iv.len(), 1);
    assert_printed(iv[0].0, -24.631, 3);
    assert_eq!(iv[0].1, f64::INFINITY);
}

#[test]
fn problem_15_20_40_harmonic_command_internal_model() {
    // 15.20.40: the pitch loop G = 0.0203/(s + 0.5) (15.20.38) tracking r = sin t, r̂ = 1/(s² + 1):
    // with Ki/s (Ki = 30) and with 2K/(s² + 4) (K = −40) the error ê = S r̂ keeps the poles ±j, so
    // the final-value theorem does not apply and the error persists; with the internal model
    // K/(s² + 1) the closed loop s³ + 0.5s² + s + 0.5 + 0.0203K is AS iff −24.63 < K < 0 and the
    // error tends to 0 (K = −20 in the book's M-file).
    let g = tf(&[0.0203], &[1.0, 0.5]);
    let r = tf(&[1.0], &[1.0, 0.0, 1.0]);
    let error = |k: &TransferFunction| g.series(k).unwrap().sensitivity().unwrap().series(&r).unwrap();
    let illegal = |e: TransferFunction| {
        matches!(e.final_value(AXIS_RTOL).unwrap(), FinalValue::Illegal(Illegal::ImaginaryAxisPole(_)))
    };
    assert!(illegal(error(&tf(&[30.0], &[1.0, 0.0]))));
    assert!(illegal(error(&tf(&[-80.0], &[1.0, 0.0, 4.0]))));
    let iv =
        stable_gain_intervals(&poly(&[0.0203]), &poly(&[1.0, 0.5]).mul(&poly(&[1.0, 0.0, 1.0])).unwrap())
            .unwrap();
    assert_eq!(iv.len(), 1);
    assert_printed(iv[0].0, -24.63, 2);
    assert_abs(iv[0].1, 0.0, 1e-12);
    let e = error(&tf(&[-20.0], &[1.0, 0.0, 1.0])).minreal(1e-9).unwrap();
    assert_eq!(e.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(0.0));
}

#[test]
fn problem_15_20_41_same_conclusions_for_another_plant() {
    // 15.20.41: G = (4s² + 4s + 1)/(s³ + s² + πs + 0.777) with the M-file's gains: P control
    // (Kp = 20) leaves the step error r₀/(1 + Kp G(0)) = 3°·0.777/20.777; integral control
    // (Ki = 0.2) removes it; for r = sin t, Ki/s (Ki = 4) and 2K/(s² + 4) (K = −0.15) leave the FVT
    // inapplicable while the internal model K/(s² + 1) (K = 0.2) drives the error to 0 — the
    // conclusions of 15.20.39–40. Every one of these closed loops is asymptotically stable.
    let g = tf(&[4.0, 4.0, 1.0], &[1.0, 1.0, std::f64::consts::PI, 0.777]);
    let step = tf(&[3.0], &[1.0, 0.0]);
    let sine = tf(&[1.0], &[1.0, 0.0, 1.0]);
    let loop_of = |k: TransferFunction| g.series(&k).unwrap();
    let stable = |l: &TransferFunction| routh(l.sensitivity().unwrap().den()).unwrap().is_hurwitz();
    let p = loop_of(tf(&[20.0], &[1.0]));
    assert!(stable(&p));
    let FinalValue::Finite(e) =
        p.sensitivity().unwrap().series(&step).unwrap().final_value(AXIS_RTOL).unwrap()
    else {
        panic!("legal")
    };
    assert_rel(e, 3.0 * 0.777 / 20.777, 16.0 * EPS);
    let i = loop_of(tf(&[0.2], &[1.0, 0.0]));
    assert!(stable(&i));
    let e = i.sensitivity().unwrap().series(&step).unwrap().minreal(1e-9).unwrap();
    assert_eq!(e.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(0.0));
    for k in [tf(&[4.0], &[1.0, 0.0]), tf(&[-0.3], &[1.0, 0.0, 4.0])] {
        let l = loop_of(k);
        assert!(stable(&l));
        let e = l.sensitivity().unwrap().series(&sine).unwrap();
        assert!(matches!(
            e.final_value(AXIS_RTOL).unwrap(),
            FinalValue::Illegal(Illegal::ImaginaryAxisPole(_))
        ));
    }
    let im = loop_of(tf(&[0.2], &[1.0, 0.0, 1.0]));
    assert!(stable(&im));
    let e = im.sensitivity().unwrap().series(&sine).unwrap().minreal(1e-9).unwrap();
    assert_eq!(e.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(0.0));
}

#[test]
fn problem_15_20_43_quartic_gain_interval() {
    // 15.20.43 (C): G = 1/(s²+2s+1), Gc = k/(s²+2s): s⁴ + 4s³ + 5s² + 2s + k, AS iff 0 < k < 2.25
    // (exact: the Routh condition 2·20 − 16k > 4 ⇔ k < 9/4).
    let iv = intervals(&[1.0], &poly(&[1.0, 2.0, 1.0]).mul(&poly(&[1.0, 2.0, 0.0])).unwrap());
    assert_eq!(iv.len(), 1);
    assert_abs(iv[0].0, 0.0, 1e-12);
    assert_rel(iv[0].1, 2.25, 1e-10);
}

#[test]
fn problem_15_20_46_pi_region() {
    // 15.20.46: G = 1/(s² + 3s − 2) with PI: s³ + 3s² + (Kp − 2)s + Ki is AS ⇔ Kp > 2 and
    // 0 < Ki < 3(Kp − 2); (C) (5, 8) stable, (5, 10) not.
    let stable = |kp: f64, ki: f64| routh(&poly(&[1.0, 3.0, kp - 2.0, ki])).unwrap().is_hurwitz();
    assert!(stable(5.0, 8.0));
    assert!(!stable(5.0, 10.0));
    // The Ki interval at Kp = 5 from the one-parameter tool: (0, 9).
    let iv = intervals(&[1.0], &poly(&[1.0, 3.0, 3.0, 0.0]));
    assert_abs(iv[0].0, 0.0, 1e-12);
    assert_rel(iv[0].1, 9.0, 1e-10);
}

#[test]
fn problem_15_20_47_pi_control_of_a_type_one_plant() {
    // 15.20.47: G = 1/(s(s + 1)) with PI control Kp + Ki/s: the closed loop s³ + s² + Kp s + Ki
    // is AS ⇔ 0 < Ki < Kp (Routh), and the ramp error ê = S/s² = (s + 1)/(s³ + s² + Kp s + Ki)
    // tends to 0 (FVT); the M-file's (Kp, Ki) = (15, 1) and (5, 2) are stable, and the exact
    // ramp error at t = 60 is below 1e-7 for (5, 2) (notes: lsim gives −8e-9).
    for (kp, ki, ok) in [(15.0, 1.0, true), (5.0, 2.0, true), (2.0, 3.0, false)] {
        assert_eq!(routh(&poly(&[1.0, 1.0, kp, ki])).unwrap().is_hurwitz(), ok, "({kp}, {ki})");
    }
    let iv = intervals(&[1.0], &poly(&[1.0, 1.0, 5.0, 0.0]));
    assert_eq!(iv.len(), 1);
    assert_abs(iv[0].0, 0.0, 1e-12);
    assert_rel(iv[0].1, 5.0, 1e-10);
    let l = tf(&[5.0, 2.0], &[1.0, 1.0, 0.0, 0.0]);
    let s = l.sensitivity().unwrap();
    let e = s.series(&tf(&[1.0], &[1.0, 0.0, 0.0])).unwrap().minreal(1e-9).unwrap();
    assert_eq!(e.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(0.0));
    let r = s.ramp(&time_grid(60.0, 601).unwrap()).unwrap();
    assert!(r.y[0][600].abs() < 1e-7, "e(60) = {}", r.y[0][600]);
}

#[test]
fn problem_15_20_48_root_locus_stability() {
    // 15.20.48 (C): i) (s+1)(s+2)/((s−1)(s−2)(s−3)): AS iff k > (3 + √89)/2 = 6.2170;
    // ii) (s+2)²/((s+1)(s²+1)): AS for all k > 0.
    let iv = intervals(&[1.0, 3.0, 2.0], &poly(&[1.0, -6.0, 11.0, -6.0]));
    assert_eq!(iv.len(), 1);
    assert_rel(iv[0].0, (3.0 + 89f64.sqrt()) / 2.0, 1e-10);
    assert_eq!(iv[0].1, f64::INFINITY);
    let iv = intervals(&[1.0, 4.0, 4.0], &poly(&[1.0, 1.0, 1.0, 1.0]));
    assert!(iv.iter().any(|&(lo, hi)| lo <= 0.0 && hi == f64::INFINITY), "{iv:?}");
}

#[test]
fn problem_15_20_49_gain_interval() {
    // 15.20.49: poles 0.04 ± 0.12j, −4.3 ± 5.7j, zero −0.2:
    // G = (s+0.2)/((s² − 0.08s + 0.016)(s² + 8.6s + 50.98)), AS for ≈ 4.25 < k < 417 (printed);
    // computed (notes, C): 4.2221 < k < 417.77. The printed 4.25 is a reading from the plot.
    let d = poly(&[1.0, -0.08, 0.016]).mul(&poly(&[1.0, 8.6, 50.98])).unwrap();
    let iv = intervals(&[1.0, 0.2], &d);
    assert_eq!(iv.len(), 1);
    assert_printed(iv[0].0, 4.2221, 4);
    assert_printed(iv[0].1, 417.77, 2);
}
