//! §16.3: gain, phase and stability margins as python-control 0.10 defines them; Nyquist;
//! problems 16.8.10–16.8.14.
//!
//! Values labelled "python-control" come from `control.stability_margins(L)` (python-control
//! 0.10.2, double precision, run once by hand): an independent implementation, agreeing here
//! to 1e-9 relative (its `numpy.roots` polynomials carry ~1e-12 relative errors).

use super::*;

/// |got − want| ≤ 1e-9·|want|: agreement with python-control's double-precision margins.
#[track_caller]
fn assert_python(got: f64, want: f64) {
    assert_rel(got, want, 1e-9);
}

#[test]
fn problem_16_8_10_infinite_gain_margin() {
    // 16.8.10: L = 2.5(s+100)/(s+1)²: GM = ∞; PM = 16.2° at ω_mc = 15.9 rad/s (printed);
    // computed (C): 16.23° at 15.879. python-control: PM 16.229661236461396° at
    // 15.878665912195705, stability margin 0.28008742084817795 at 16.169883001403246.
    let m = tf(&[2.5, 250.0], &[1.0, 2.0, 1.0]).margins().unwrap();
    assert_eq!(m.gain_margin_db(), None);
    assert!(m.phase_crossovers.is_empty());
    assert_printed(m.phase_margin_deg().unwrap(), 16.23, 2);
    assert_printed(m.gain_crossover_omega().unwrap(), 15.879, 3);
    assert_python(m.phase_margin_deg().unwrap(), 16.229661236461396);
    assert_python(m.gain_crossover_omega().unwrap(), 15.878665912195705);
    let sm = m.stability_margin().unwrap();
    assert_python(sm.distance, 0.28008742084817795);
    assert_python(sm.omega, 16.169883001403246);
}

#[test]
fn problem_16_8_11_lead_raises_phase_margin() {
    // 16.8.11 i) L = 1/(s(s+1)): GM = ∞, PM = 51.8° at 0.786 (C: 51.83° at 0.7862);
    // ii) with the lead (s+2)/(s+20) (k = 1): PM 86.88° at ω_mc = 0.0996 (C). python-control
    // for i): PM 51.82729237°, stability margin 0.6812500386332132 at 1.1687708944803679.
    let l = tf(&[1.0], &[1.0, 1.0, 0.0]);
    let m = l.margins().unwrap();
    assert_eq!(m.gain_margin_db(), None);
    assert_printed(m.phase_margin_deg().unwrap(), 51.83, 2);
    assert_printed(m.gain_crossover_omega().unwrap(), 0.7862, 4);
    assert_python(m.gain_crossover_omega().unwrap(), 0.786151377757423);
    assert_python(m.stability_margin_distance().unwrap(), 0.6812500386332132);
    assert_python(m.stability_margin().unwrap().omega, 1.1687708944803679);
    let led = l.series(&tf(&[1.0, 2.0], &[1.0, 20.0])).unwrap();
    let m = led.margins().unwrap();
    assert_printed(m.phase_margin_deg().unwrap(), 86.88, 2);
    assert_printed(m.gain_crossover_omega().unwrap(), 0.0996, 4);
}

#[test]
fn problem_16_8_13_margins_of_type_one_third_order() {
    // 16.8.13: L = 1/(s(s+1)²): ω_pc = 1, L(j) = −0.5, GM = 6.02 dB (ratio 2); ω_gc = 0.6823
    // (the root of ω³ + ω − 1), PM = 21.39° (C; the book prints 21.5° and 21.9°, inconsistent).
    // ERR: "GM = 20 log(1 − |L|)" should be −20 log|L|. python-control: PM 21.386389751875043°
    // at 0.6823278038280193, stability margin 0.2969887933385196 at 0.7666128519921597; ω = 0
    // is no phase crossover (L(0) is infinite).
    let l = tf(&[1.0], &[1.0, 2.0, 1.0, 0.0]);
    let m = l.margins().unwrap();
    assert_eq!(m.phase_crossovers.len(), 1);
    assert_rel(m.phase_crossover_omega().unwrap(), 1.0, 8.0 * EPS);
    assert_printed(m.gain_margin_db().unwrap(), 6.02, 2);
    assert_rel(m.gain_margin_db().unwrap(), -20.0 * 0.5f64.log10(), 8.0 * EPS);
    assert_rel(m.gain_margin_ratio().unwrap(), 2.0, 8.0 * EPS);
    let w = m.gain_crossover_omega().unwrap();
    // ω³ + ω − 1 = 0 to the rounding of its terms (each ≤ 1)
    assert_abs(w * w * w + w - 1.0, 0.0, 8.0 * EPS);
    assert_printed(w, 0.6823, 4);
    assert_printed(m.phase_margin_deg().unwrap(), 21.39, 2);
    assert_python(m.phase_margin_deg().unwrap(), 21.386389751875043);
    assert_python(m.stability_margin_distance().unwrap(), 0.2969887933385196);
    assert_python(m.stability_margin().unwrap().omega, 0.7666128519921597);
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
    // (the notes' "−1.3334" is a rounding slip); N = −2, P = 2, Z = 0 ⇒ AS; L(0) = 20;
    // closed-loop poles −0.5 ± 6.461j; stable iff the gain factor exceeds 0.75, so GM = −2.50 dB
    // (ratio 0.75: a lower gain margin); PM = 9.2° at ω_mc = 6.770 (+189.2° wraps to 9.2°,
    // notes §3.5). python-control: GM 0.75 at 5.656854249492381, PM 9.233961742025286° at
    // 6.769548737017737, stability margin 0.14537324883137637 at 6.515362178777454.
    let l = tf(&[4.0, 40.0], &[1.0, -3.0, 2.0]);
    assert_eq!(l.dc_gain(), Some(20.0));
    let ny = l.nyquist(400).unwrap();
    assert_eq!((ny.encirclements, ny.open_loop_rhp, ny.closed_loop_rhp), (-2, 2, 0));
    assert_eq!(winding(&ny), -2);
    let m = l.margins().unwrap();
    assert_rel(m.phase_crossover_omega().unwrap(), 4.0 * 2f64.sqrt(), 8.0 * EPS);
    let cross = l.freqresp(&[4.0 * 2f64.sqrt()]).unwrap()[0];
    assert_printed(cross.re, -1.33, 2);
    assert_rel(cross.re, -4.0 / 3.0, 16.0 * EPS);
    assert_printed(m.gain_margin_db().unwrap(), -2.50, 2);
    assert_rel(m.gain_margin_ratio().unwrap(), 0.75, 16.0 * EPS);
    assert_printed(m.phase_margin_deg().unwrap(), 9.2, 1);
    assert_printed(m.gain_crossover_omega().unwrap(), 6.770, 3);
    assert_python(m.phase_margin_deg().unwrap(), 9.233961742025286);
    assert_python(m.gain_crossover_omega().unwrap(), 6.769548737017737);
    assert_python(m.stability_margin_distance().unwrap(), 0.14537324883137637);
    assert_python(m.stability_margin().unwrap().omega, 6.515362178777454);
    let cl = l.feedback(&TransferFunction::gain(1.0).unwrap()).unwrap().poles().unwrap();
    assert_printed(cl[0].re, -0.5, 4);
    assert_printed(cl[0].im.abs(), 6.461, 3);
    let iv = stable_gain_intervals(l.num(), l.den()).unwrap();
    assert_eq!(iv.len(), 1);
    assert_rel(iv[0].0, 0.75, 1e-12);
}

#[test]
fn eq_16_3_2_gain_margin_at_zero_frequency_from_the_exact_sign() {
    // (16.3.2) with python-control's crossover set: ω = 0 is a phase crossover exactly when
    // L(0) = N(0)/D(0) ≤ 0 with D(0) ≠ 0, decided from the signs of the two coefficients (issue 19:
    // a product over roots dropped it on round-off and reported GM = ∞ instead of the margin).
    // L = −1/(s + 1)²: L(0) = −1, GM = 1 (0 dB) at ω = 0; no gain crossover at ω > 0
    // (python-control: gm 1.0 at ω 0, pm ∞). L = (−2s + 1)/(s + 1)³ (a right-half-plane zero):
    // python-control GM 1.1428571428571428 at 0.8451542547285166, PM 45.795263773854714° at
    // 0.5502505227003374, stability margin 0.12142686230366634 at 0.8319335592870657.
    let m = tf(&[-1.0], &[1.0, 2.0, 1.0]).margins().unwrap();
    assert_eq!(m.phase_crossovers.len(), 1);
    assert_eq!(m.phase_crossovers[0].omega, 0.0);
    assert_eq!(m.gain_margin_ratio(), Some(1.0));
    assert_eq!(m.gain_margin_db(), Some(0.0));
    assert_eq!(m.phase_margin_deg(), None);
    let m = tf(&[-2.0, 1.0], &[1.0, 3.0, 3.0, 1.0]).margins().unwrap();
    assert_python(m.gain_margin_ratio().unwrap(), 1.1428571428571428);
    assert_python(m.phase_crossover_omega().unwrap(), 0.8451542547285166);
    assert_python(m.phase_margin_deg().unwrap(), 45.795263773854714);
    assert_python(m.gain_crossover_omega().unwrap(), 0.5502505227003374);
    assert_python(m.stability_margin_distance().unwrap(), 0.12142686230366634);
    assert_python(m.stability_margin().unwrap().omega, 0.8319335592870657);
    // a zero at the origin: L(0) = 0 ≤ 0, so ω = 0 is listed with GM = ∞, and there is no finite
    // gain margin (python-control: gm = ∞, wpc = NaN)
    let m = tf(&[1.0, 0.0], &[1.0, 2.0, 3.0]).margins().unwrap();
    assert_eq!(m.phase_crossovers.len(), 1);
    assert_eq!(m.phase_crossovers[0].gain_margin, f64::INFINITY);
    assert_eq!(m.gain_margin(), None);
    // a negative loop 1/(s + 1)·(−1) with a pole at 0 excludes ω = 0: −1/(s(s+1)) has PM −128.17°
    // (python-control: −128.17270762701224 at 0.786151377757423) and no phase crossover
    let m = tf(&[-1.0], &[1.0, 1.0, 0.0]).margins().unwrap();
    assert!(m.phase_crossovers.is_empty());
    assert_python(m.phase_margin_deg().unwrap(), -128.17270762701224);
    assert_eq!(m.stability_margin(), None);
}

#[test]
fn eq_16_3_1_phase_margin_sign_corrected() {
    // (16.3.1) prints PM = 180° − ∠G(jω_mc); the correct margin is 180° + ∠L(jω_mc) (python-control:
    // mod(∠L, 360°) − 180°): for L = 1/(s(s+1)), ∠L(jω_mc) = −128.17°, so PM = 51.83°, not
    // 308.17°. And 5/(s + 1): PM 101.5369590328155° at 4.898979485566356 = √24 (python-control).
    let l = tf(&[1.0], &[1.0, 1.0, 0.0]);
    let m = l.margins().unwrap();
    let w = m.gain_crossover_omega().unwrap();
    let phase = l.bode(&[w]).unwrap().phase_deg[0];
    assert_abs(m.phase_margin_deg().unwrap(), 180.0 + phase, 64.0 * EPS * 180.0);
    assert_printed(wrap_deg(180.0 - phase), wrap_deg(308.17), 2); // the printed 308.17°
    let m = tf(&[5.0], &[1.0, 1.0]).margins().unwrap();
    assert_rel(m.gain_crossover_omega().unwrap(), 24f64.sqrt(), 8.0 * EPS);
    assert_python(m.phase_margin_deg().unwrap(), 101.5369590328155);
}

#[test]
fn eq_15_10_2_margins_with_delay() {
    // A delay τ lowers the phase at ω_mc by ωτ and leaves |L| unchanged (15.10.2):
    // 1/(s(s+1)) with τ = 0.2 loses 0.7862·0.2 rad = 9.01°. (python-control has no delays; the
    // delayed phase crossovers are bracketed on a grid and bisected to ~1e-15 relative.)
    let l = tf(&[1.0], &[1.0, 1.0, 0.0]);
    let m0 = l.margins().unwrap();
    let md = l.clone().with_delay(0.2).unwrap().margins().unwrap();
    let w = m0.gain_crossover_omega().unwrap();
    assert_rel(md.gain_crossover_omega().unwrap(), w, 8.0 * EPS);
    assert_abs(
        md.phase_margin_deg().unwrap(),
        m0.phase_margin_deg().unwrap() - (0.2 * w).to_degrees(),
        1e-12,
    );
    // The delayed loop now has phase crossovers (finite GM), at arg L₀(jω) − ωτ = −180°.
    let c = md.gain_margin().unwrap();
    assert!(c.gain_margin_db > 0.0);
    let phase = l.bode(&[c.omega]).unwrap().phase_deg[0] - (0.2 * c.omega).to_degrees();
    assert_abs(wrap_deg(phase + 180.0), 0.0, 1e-9);
}
