//! §15.4, §15.15, §15.16: single-degree-of-freedom systems, modes and stability classes;
//! problems 15.20.11–12, 15.20.33–34 and 15.20.51.

use super::*;
use nalgebra::dmatrix;
use std::f64::consts::LN_2;

#[test]
fn sec_15_4_sdof_kinds_and_stability_classes() {
    // §15.4 and §15.16: URB is unstable, UO Lyapunov stable, DRB semistable, DO AS.
    let cases = [
        (0.0, 0.0, SdofKind::UndampedRigidBody, StabilityClass::Unstable),
        (0.0, 2.0, SdofKind::UndampedOscillator, StabilityClass::LyapunovStable),
        (1.5, 0.0, SdofKind::DampedRigidBody, StabilityClass::Semistable),
        (1.5, 2.0, SdofKind::DampedOscillator, StabilityClass::AsymptoticallyStable),
    ];
    for (c, k, kind, class) in cases {
        let s = Sdof::new(2.0, c, k).unwrap();
        assert_eq!(s.kind(), kind);
        let a = s.to_state_space(SdofOutput::Position).unwrap().a().clone();
        assert_eq!(stability_of_matrix(&a, AXIS_RTOL).unwrap(), class, "{kind:?}");
    }
}

#[test]
fn fact_15_16_1_semisimple_zero_matrix_is_semistable() {
    // Notes §2: A = 0₂ has the repeated eigenvalue 0 but is semisimple, so it is Lyapunov
    // stable (indeed semistable); the Jordan block [[0,1],[0,0]] (URB) is unstable.
    assert_eq!(stability_of_matrix(&DMatrix::zeros(2, 2), AXIS_RTOL).unwrap(), StabilityClass::Semistable);
    // A repeated imaginary pair that is semisimple: two uncoupled undamped oscillators.
    let a = dmatrix![0.0, 1.0, 0.0, 0.0; -4.0, 0.0, 0.0, 0.0; 0.0, 0.0, 0.0, 1.0; 0.0, 0.0, -4.0, 0.0];
    assert_eq!(stability_of_matrix(&a, AXIS_RTOL).unwrap(), StabilityClass::LyapunovStable);
    // Coupled (a Jordan block at ±2j): resonance, unstable.
    let mut b = a.clone();
    b[(1, 2)] = 1.0;
    assert_eq!(stability_of_matrix(&b, AXIS_RTOL).unwrap(), StabilityClass::Unstable);
    // For poles (a transfer function) a repeated jω pole is unstable and not BIBO (15.16.1).
    let res = poly(&[1.0, 0.0, 2.0, 0.0, 1.0]); // (s² + 1)²
    assert_eq!(stability_of_polynomial(&res, AXIS_RTOL).unwrap(), StabilityClass::Unstable);
    assert!(!StabilityClass::LyapunovStable.is_bibo());
}

#[test]
fn eq_15_15_3_modes_of_underdamped_pair() {
    // (15.15.3)–(15.15.6): λ = −ζωn ± jωd, |λ| = ωn, ζ = −Re λ/|λ|, t½ = ln 2/(ζωn).
    let (wn, zeta) = (3.0, 0.2);
    let s = Sdof::new(1.0, 2.0 * zeta * wn, wn * wn).unwrap();
    assert_rel(s.natural_frequency(), wn, 4.0 * EPS);
    assert_rel(s.damping_ratio().unwrap(), zeta, 4.0 * EPS);
    let modes = modes(s.to_state_space(SdofOutput::Position).unwrap().a()).unwrap();
    for m in &modes {
        assert_rel(m.natural_frequency, wn, 16.0 * EPS);
        assert_rel(m.damping_ratio.unwrap(), zeta, 16.0 * EPS);
        assert_rel(m.damped_frequency, wn * (1.0 - zeta * zeta).sqrt(), 16.0 * EPS);
        assert_rel(m.time_to_half.unwrap(), LN_2 / (zeta * wn), 16.0 * EPS);
    }
}

#[test]
fn problem_15_20_11_underdamped_pair_formulas() {
    // 15.20.11: for λ, λ̄ = −ζωn ± jωn√(1 − ζ²): ωn = |λ|, ζ = −(λ + λ̄)/(2|λ|),
    // ωd = (λ − λ̄)/(2j). The eigenvalues of the oscillator's A give them back.
    for (wn, zeta) in [(0.7, 0.05), (3.0, 0.5), (12.0, 0.95)] {
        let s = Sdof::new(2.0, 2.0 * 2.0 * zeta * wn, 2.0 * wn * wn).unwrap();
        let ev = sorted(linalg::eigenvalues(s.to_state_space(SdofOutput::Position).unwrap().a()).unwrap());
        let (l, lb) = (ev[1], ev[0]);
        assert_eq!(lb, l.conj());
        assert_rel(l.norm(), wn, 16.0 * EPS);
        assert_rel(-(l + lb).re / (2.0 * l.norm()), zeta, 64.0 * EPS);
        assert_rel(((l - lb) / Complex64::new(0.0, 2.0)).re, wn * (1.0 - zeta * zeta).sqrt(), 16.0 * EPS);
        let m = Mode::of(l);
        assert_rel(m.natural_frequency, wn, 16.0 * EPS);
        assert_rel(m.damping_ratio.unwrap(), zeta, 64.0 * EPS);
    }
}

#[test]
fn problem_15_20_12_overdamped_pair_formulas() {
    // 15.20.12: for λ₁, λ₂ = −ζωn ± ωn√(ζ² − 1): ωn = √(λ₁λ₂) and ζ = −(λ₁ + λ₂)/(2√(λ₁λ₂));
    // the real eigenvalues of an overdamped oscillator give back the ωn and ζ of §15.4.
    for (wn, zeta) in [(1.0, 1.5), (4.0, 3.0), (0.2, 10.0)] {
        let s = Sdof::new(1.0, 2.0 * zeta * wn, wn * wn).unwrap();
        let ev = sorted(linalg::eigenvalues(s.to_state_space(SdofOutput::Position).unwrap().a()).unwrap());
        assert!(ev.iter().all(|z| z.im == 0.0));
        let (l1, l2) = (ev[0].re, ev[1].re);
        let root = (l1 * l2).sqrt();
        // the slow eigenvalue ≈ −ωn/(2ζ) is found to relative ~4ζ²ε (its sensitivity)
        let tol = 16.0 * EPS * 4.0 * zeta * zeta;
        assert_rel(root, s.natural_frequency(), tol);
        assert_rel(-(l1 + l2) / (2.0 * root), s.damping_ratio().unwrap(), tol);
    }
}

#[test]
fn problem_15_20_33_damping_from_time_to_half_amplitude() {
    // 15.20.33: an underdamped pair whose amplitude halves in T seconds with damped frequency ωd
    // has ζ = 1/√(1 + (ωd T/ln 2)²) (and 0 < ζ < 1). Building λ from that ζ gives back
    // t½ = ln 2/(ζωn) = T and Im λ = ωd.
    for (wd, t_half) in [(0.9467, 21.0), (2.0, 0.5), (10.0, 3.0)] {
        let zeta = 1.0 / (1.0 + (wd * t_half / LN_2).powi(2)).sqrt();
        assert!(zeta > 0.0 && zeta < 1.0);
        let wn = wd / (1.0 - zeta * zeta).sqrt();
        let m = Mode::of(Complex64::new(-zeta * wn, wd));
        assert_rel(m.time_to_half.unwrap(), t_half, 16.0 * EPS);
        assert_rel(m.damped_frequency, wd, 4.0 * EPS);
        assert_rel(m.damping_ratio.unwrap(), zeta, 16.0 * EPS);
    }
}

#[test]
fn problem_15_20_34_overdamped_damping_from_time_to_half() {
    // 15.20.34: an overdamped oscillator whose slow mode halves in T seconds has
    // ζ = (b + 1/b)/2 with b = ln 2/(ωn T), and ζ ≥ 1. The slow eigenvalue of the oscillator with
    // that ζ has t½ = T.
    for (wn, t_half) in [(1.0, 3.0), (0.5, 10.0), (5.0, 0.2)] {
        let b = LN_2 / (wn * t_half);
        let zeta = 0.5 * (b + 1.0 / b);
        assert!(zeta >= 1.0);
        let s = Sdof::new(1.0, 2.0 * zeta * wn, wn * wn).unwrap();
        let ev = modes(s.to_state_space(SdofOutput::Position).unwrap().a()).unwrap();
        let slow = ev.iter().max_by(|a, b| a.eigenvalue.re.total_cmp(&b.eigenvalue.re)).unwrap();
        assert_rel(slow.time_to_half.unwrap(), t_half, 1e3 * EPS);
    }
}

#[test]
fn problem_15_20_51_boeing_747_dutch_roll() {
    // 15.20.51: λ = −0.0329 ± 0.9467j (Dutch roll, ζ = 0.0348, ωn = 0.947), −0.5627, −0.0073;
    // asymptotically stable.
    let a = b747().a().clone();
    let ev = sorted(linalg::eigenvalues(&a).unwrap());
    assert_printed(ev[0].re, -0.5627, 4);
    assert_printed(ev[1].re, -0.0329, 4);
    assert_printed(ev[2].im, 0.9467, 4);
    assert_printed(ev[3].re, -0.0073, 4);
    let dutch = Mode::of(ev[2]);
    assert_printed(dutch.damping_ratio.unwrap(), 0.0348, 4);
    assert_printed(dutch.natural_frequency, 0.947, 3);
    assert_eq!(stability_of_matrix(&a, AXIS_RTOL).unwrap(), StabilityClass::AsymptoticallyStable);
}
