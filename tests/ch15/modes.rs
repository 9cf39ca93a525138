//! §15.4, §15.15, §15.16: single-degree-of-freedom systems, modes and stability classes;
//! problems 15.20.11–13, 15.20.33–36 and 15.20.51, 15.20.53.

use super::*;
use crate::support::nan_min;
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

/// Smallest damping ratio over the eigenvalues of the 747 lateral model with the yaw-rate
/// feedback u_input = −k·r (15.20.53): A − k·b·C_r, C_r = [0, 1, 0, 0].
fn yaw_damper_min_zeta(input: usize, k: f64) -> (f64, Vec<Complex64>) {
    let sys = b747();
    let b = sys.b().column(input).clone_owned();
    let c_r = nalgebra::dmatrix![0.0, 1.0, 0.0, 0.0];
    let a_cl = sys.a() - k * &b * &c_r;
    let ev = sorted(linalg::eigenvalues(&a_cl).unwrap());
    let z = ev.iter().map(|l| -l.re / l.norm()).fold(f64::INFINITY, nan_min);
    (z, ev)
}

/// The gain in [lo, hi] that maximises `f` by a grid and a golden-section refinement.
fn argmax(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let n = 2000;
    let h = (hi - lo) / n as f64;
    let k0 = (0..=n).map(|i| lo + i as f64 * h).max_by(|a, b| f(*a).total_cmp(&f(*b))).unwrap();
    let (mut a, mut b) = (k0 - h, k0 + h);
    let phi = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..100 {
        let (c, d) = (b - phi * (b - a), a + phi * (b - a));
        if f(c) > f(d) { b = d } else { a = c }
    }
    0.5 * (a + b)
}

#[test]
fn problem_15_20_53_yaw_rate_damper() {
    // 15.20.53 (ERR: the problem cites the aircraft of 15.20.49; it means the 747 of 15.20.51).
    // No solution is printed; the notes compute (C), with u = −k·r: the rudder gain k = −2.79
    // maximises the smallest closed-loop damping ratio, ζ ≈ 0.44 with poles −0.30 ± 0.61j, −0.34,
    // −1.02; the ailerons reach only ζ ≈ 0.036, so the rudder is the better yaw damper.
    let k = argmax(|k| yaw_damper_min_zeta(0, k).0, -10.0, 10.0);
    let (zeta, ev) = yaw_damper_min_zeta(0, k);
    assert_printed(k, -2.79, 2);
    assert_printed(zeta, 0.44, 2);
    assert_printed(ev[0].re, -1.02, 2);
    assert_printed(ev[1].re, -0.34, 2);
    assert_printed(ev[2].re, -0.30, 2);
    assert_printed(ev[3].im, 0.61, 2);
    // open loop the Dutch roll has ζ = 0.0348 (15.20.51): the damper multiplies it by ~13
    assert_printed(yaw_damper_min_zeta(0, 0.0).0, 0.0348, 4);
    let ka = argmax(|k| yaw_damper_min_zeta(1, k).0, -10.0, 10.0);
    let (zeta_a, _) = yaw_damper_min_zeta(1, ka);
    assert_printed(zeta_a, 0.036, 3);
    assert!(zeta > 10.0 * zeta_a);
}

#[test]
fn example_15_16_3_rigid_body_velocity_is_not_bibo() {
    // Ex 15.16.3: v̂ = f̂/(ms) under the bounded input f = f₀·1(t) gives v = f₀t/m, unbounded:
    // G = 1/(ms) is not BIBO stable (its pole 0 is on the imaginary axis: Lyapunov, indeed
    // semi-, stable, but not asymptotically stable, Fact 15.16.5).
    let (m, f0) = (4.0, 2.0);
    let g = tf(&[1.0], &[m, 0.0]);
    let class = stability_of_polynomial(g.den(), AXIS_RTOL).unwrap();
    assert_eq!(class, StabilityClass::Semistable);
    assert!(!class.is_bibo());
    let t = time_grid(100.0, 11).unwrap();
    let r = response(&StateSpace::from_tf(&g).unwrap(), InputKind::Step, 0, f0, 0.0, &t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        assert_abs(r.y[0][k], f0 * tk / m, 64.0 * EPS * f0 * tk / m);
    }
    // the final-value theorem agrees: v̂ = f₀/(ms²) → +∞ (a double pole at 0)
    assert_eq!(tf(&[f0], &[m, 0.0, 0.0]).final_value(AXIS_RTOL).unwrap(), FinalValue::Infinite(1.0));
}

#[test]
fn example_15_16_4_resonance_is_not_bibo() {
    // Ex 15.16.4, (15.16.1): G = 1/(s² + ωn²) driven by sin ωn t: ŷ = ωn/(s² + ωn²)² has
    // repeated poles ±jωn and y = (sin ωn t − ωn t cos ωn t)/(2ωn²), an oscillation with the
    // linear envelope t/(2ωn): G is Lyapunov stable but not BIBO stable.
    let wn = 1.7;
    let g = tf(&[1.0], &[1.0, 0.0, wn * wn]);
    let class = stability_of_polynomial(g.den(), AXIS_RTOL).unwrap();
    assert_eq!(class, StabilityClass::LyapunovStable);
    assert!(!class.is_bibo());
    let y_hat = g.series(&tf(&[wn], &[1.0, 0.0, wn * wn])).unwrap();
    assert_eq!(stability_of_polynomial(y_hat.den(), AXIS_RTOL).unwrap(), StabilityClass::Unstable);
    let want = |t: f64| ((wn * t).sin() - wn * t * (wn * t).cos()) / (2.0 * wn * wn);
    // exact simulation: the impulse response of ŷ is y (a 4-state model, amplitude ≤ t/(2ωn))
    let t = time_grid(60.0, 601).unwrap();
    let r = y_hat.impulse(&t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        assert_abs(r.y[0][k], want(tk), 1e4 * EPS * (1.0 + tk / (2.0 * wn)));
    }
    // the envelope grows linearly: the peaks near t = (2j + 1)π/ωn are ≈ t/(2ωn)
    for j in [5.0, 15.0, 25.0] {
        let tp = (2.0 * j + 1.0) * std::f64::consts::PI / wn;
        assert_rel(want(tp), tp / (2.0 * wn), 8.0 * EPS);
    }
}

#[test]
fn problem_15_20_13_critical_damping_as_the_limit_of_underdamping() {
    // 15.20.13: l'Hôpital on (15.15.8), (f₀/(mωd))e^{−ζωn t} sin ωd t with ωd = ωn√(1 − ζ²), as
    // ζ → 1 gives (15.15.9), (f₀/m)t e^{−ωn t}. Numerically: the underdamped formula at ζ = 1 − δ
    // converges to the critical one linearly in δ; to first order the relative gap is
    // δ(ωn t − ωn²t²/3) (from e^{δωn t} and sin x/x = 1 − x²/6 with ωd² ≈ 2δωn²).
    let (f0, m, wn) = (3.0, 2.0, 1.5);
    let critical = |t: f64| f0 / m * t * (-wn * t).exp();
    for t in [0.2f64, 1.0, 3.0] {
        for delta in [1e-2f64, 1e-4, 1e-6] {
            let zeta = 1.0 - delta;
            let wd = wn * (1.0 - zeta * zeta).sqrt();
            let under = f0 / (m * wd) * (-zeta * wn * t).exp() * (wd * t).sin();
            let first_order = delta * (wn * t - wn * wn * t * t / 3.0);
            // second-order remainder O(δ²(ωn t)⁴), plus ε/δ from the rounding of 1 − ζ²
            let tol = delta * delta * (1.0 + wn * t).powi(4) + 64.0 * EPS / delta;
            assert_abs(under / critical(t) - 1.0, first_order, tol);
        }
    }
    // and the library's exact impulse response of the critically damped oscillator is (15.15.9)
    let g = tf(&[1.0 / m], &[1.0, 2.0 * wn, wn * wn]);
    let ts = time_grid(4.0, 41).unwrap();
    let r = g.impulse(&ts).unwrap();
    for (k, &tk) in ts.iter().enumerate() {
        assert_abs(f0 * r.y[0][k], critical(tk), 256.0 * EPS * f0 / m);
    }
}

#[test]
fn problem_15_20_35_eigenvalue_loci_of_the_oscillator() {
    // 15.20.35: eigenvalues of [[0, 1], [−k/m, −c/m]], k = 2.5, m = 7, c ∈ [0, 12] (the M-file's
    // grid 0:0.1:12): ±j√(k/m) at c = 0; (−c ± j√(4mk − c²))/(2m) below c_crit = 2√(mk) = 8.3666
    // (C); a double −c/(2m) at c_crit; (−c ± √(c² − 4mk))/(2m) above it. ERR: the printed
    // overdamped case carries a spurious j, and the plot title says k = 3, m = 6.
    let (k, m) = (2.5f64, 7.0f64);
    let c_crit = 2.0 * (m * k).sqrt();
    assert_printed(c_crit, 8.3666, 4);
    for i in 0..=120 {
        let c = 0.1 * i as f64;
        let a = dmatrix![0.0, 1.0; -k / m, -c / m];
        let ev = sorted(linalg::eigenvalues(&a).unwrap());
        let disc = c * c - 4.0 * m * k;
        let want = if disc < 0.0 {
            let w = (-disc).sqrt() / (2.0 * m);
            [Complex64::new(-c / (2.0 * m), -w), Complex64::new(-c / (2.0 * m), w)]
        } else {
            let r = disc.sqrt() / (2.0 * m);
            [Complex64::new(-c / (2.0 * m) - r, 0.0), Complex64::new(-c / (2.0 * m) + r, 0.0)]
        };
        // near c_crit the eigenvalues of the nearly defective A move like √|disc|: allow √ε
        let tol = if disc.abs() < 0.5 { 1e-7 } else { 64.0 * EPS };
        for (g, w) in ev.iter().zip(&want) {
            assert!((g - w).norm() <= tol * (k / m).sqrt().max(w.norm()), "c = {c}: {g} vs {w}");
        }
        // complex below c_crit (on the imaginary axis at c = 0), real above it
        if disc < -0.5 {
            assert!(ev.iter().all(|l| l.im != 0.0), "c = {c}");
        } else if disc > 0.5 {
            assert!(ev.iter().all(|l| l.im == 0.0 && l.re < 0.0), "c = {c}");
        }
    }
}

#[test]
fn problem_15_20_36_poles_on_the_circle_or_with_product_wn_squared() {
    // 15.20.36: for 0 ≤ ζ ≤ 1 the poles −ζωn ± jωn√(1 − ζ²) have |λ₁| = |λ₂| = ωn (the loci of
    // 15.20.35 run on the circle of radius ωn = √(k/m)); for ζ > 1, λ₁λ₂ = ωn² (they leave the
    // circle at −ωn as a pair inverse to each other about it).
    for wn in [0.3f64, 1.0, 4.0] {
        for i in 0..=40 {
            let zeta = 0.05 * i as f64; // 0 to 2
            let a = dmatrix![0.0, 1.0; -wn * wn, -2.0 * zeta * wn];
            let ev = linalg::eigenvalues(&a).unwrap();
            if zeta < 0.99 {
                for l in &ev {
                    assert_rel(l.norm(), wn, 64.0 * EPS);
                }
            } else if zeta > 1.01 {
                let prod = ev[0] * ev[1];
                // the fast root is ~4ζ² times the slow one: the product carries that many ε
                assert_rel(prod.re, wn * wn, 64.0 * EPS * 4.0 * zeta * zeta);
                assert_eq!(prod.im, 0.0);
                assert!(ev.iter().all(|l| l.im == 0.0 && l.re < 0.0));
            }
            // the product is ωn² in every case (det A = ωn²), the sum −2ζωn (tr A)
            assert_rel((ev[0] * ev[1]).re, wn * wn, 64.0 * EPS * (1.0 + 4.0 * zeta * zeta));
            assert_abs((ev[0] + ev[1]).re, -2.0 * zeta * wn, 64.0 * EPS * wn * (1.0 + zeta));
        }
    }
}
