//! Chapter 15: linear dynamical systems (solutions ch. 17), as executable tests.
//!
//! Printed values are checked to the digits printed: `assert_printed(got, 9.8467, 4)` means
//! |got − 9.8467| ≤ ½·10⁻⁴ (plus a hair for binary round-off). Where the book errs (notes
//! ch15-18 §4, "ERR"), the corrected value is tested and the comment says so.
mod support;

use nalgebra::{DMatrix, dmatrix};
use support::{EPS, assert_abs, assert_rel, assert_rel_slice};
use vectrix::lti::*;

/// |got − printed| ≤ ½·10^(−decimals): the printed value is `got` rounded.
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

/// Sorted real parts and |imaginary parts| for comparing root sets.
fn sorted(mut v: Vec<Complex64>) -> Vec<Complex64> {
    v.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
    v
}

// ---------------------------------------------------------------- eigenvalues and roots (15.3)

#[test]
fn example_15_3_3_diagonal_eigenvalues() {
    // Ex 15.3.3: diag(1, 2) has eigenvalues 1 and 2.
    let ev = sorted(linalg::eigenvalues(&dmatrix![1.0, 0.0; 0.0, 2.0]).unwrap());
    assert_eq!(ev, vec![Complex64::new(1.0, 0.0), Complex64::new(2.0, 0.0)]);
}

#[test]
fn example_15_3_4_rotation_generator_eigenvalues() {
    // Ex 15.3.4: [[0, −1], [1, 0]] has eigenvalues ±j, an exact conjugate pair.
    let ev = linalg::eigenvalues(&dmatrix![0.0, -1.0; 1.0, 0.0]).unwrap();
    assert_eq!(ev.len(), 2);
    assert_eq!(ev[0], ev[1].conj());
    assert_abs(ev[0].re, 0.0, 4.0 * EPS);
    assert_abs(ev[0].im.abs(), 1.0, 4.0 * EPS);
}

#[test]
fn problem_15_20_2_eigenvalues_trace_determinant() {
    // 15.20.2: A = [[3,0,2],[4,3,5],[7,2,6]]: eig 9.8467, 2.2438, −0.0905; Σλ = tr A = 12,
    // ∏λ = det A = −2 (15.3.7–8); eig(A²) = λ² and eig(A⁻¹) = 1/λ (Facts 15.3.11–12).
    // ERR: the book's second listing {10.6031, 0.1515, 1.2454} is wrong and "A.^2" should be A².
    let a = dmatrix![3.0, 0.0, 2.0; 4.0, 3.0, 5.0; 7.0, 2.0, 6.0];
    let ev = sorted(linalg::eigenvalues(&a).unwrap());
    for (got, want) in ev.iter().zip([-0.0905, 2.2438, 9.8467]) {
        assert_printed(got.re, want, 4);
        assert_eq!(got.im, 0.0);
    }
    let sum: f64 = ev.iter().map(|z| z.re).sum();
    let prod: f64 = ev.iter().map(|z| z.re).product();
    assert_rel(sum, 12.0, 32.0 * EPS);
    assert_rel(prod, -2.0, 1e3 * EPS); // λ₃ ≈ −0.09 amplifies the relative error ~100×
    let ev2 = sorted(linalg::eigenvalues(&(&a * &a)).unwrap());
    for (got, want) in ev2.iter().zip([0.0082, 5.0349, 96.9570]) {
        assert_printed(got.re, want, 4);
    }
    let inv = a.clone().try_inverse().unwrap();
    let evi = sorted(linalg::eigenvalues(&inv).unwrap());
    for (got, want) in evi.iter().zip([-11.0472, 0.1016, 0.4457]) {
        assert_printed(got.re, want, 4);
    }
}

#[test]
fn eq_15_3_5_eigenvalues_of_matrices_that_stall_plain_qr() {
    // The cyclic permutation matrices are fixed points of the unshifted and of the plain
    // Francis double-shift QR step: only the exceptional shifts move them. Their eigenvalues are
    // the n-th roots of unity.
    for n in [3usize, 4, 5, 8, 13] {
        let a = DMatrix::from_fn(n, n, |i, j| if i == (j + 1) % n { 1.0 } else { 0.0 });
        let ev = linalg::eigenvalues(&a).unwrap();
        assert_eq!(ev.len(), n);
        for z in &ev {
            assert_abs(z.norm(), 1.0, 64.0 * EPS);
            // z is an n-th root of unity: zⁿ = 1
            assert!((z.powu(n as u32) - Complex64::new(1.0, 0.0)).norm() <= 1e3 * EPS, "n = {n}: {z}");
        }
    }
    // a Jordan block with a tiny corner: eigenvalues on a circle of radius δ^{1/n} (δ = 1e-12,
    // n = 6: radius 1e-2) — the textbook example of eigenvalue sensitivity.
    let n = 6;
    let a = DMatrix::from_fn(n, n, |i, j| {
        if j == i + 1 {
            1.0
        } else if i == n - 1 && j == 0 {
            1e-12
        } else {
            0.0
        }
    });
    for z in linalg::eigenvalues(&a).unwrap() {
        assert_abs(z.norm(), 1e-2, 1e-12);
    }
    // zero, identity and a 1×1 matrix
    assert!(linalg::eigenvalues(&DMatrix::zeros(4, 4)).unwrap().iter().all(|z| z.norm() == 0.0));
    assert!(
        linalg::eigenvalues(&DMatrix::identity(5, 5)).unwrap().iter().all(|z| *z == Complex64::new(1.0, 0.0))
    );
    assert_eq!(linalg::eigenvalues(&dmatrix![-3.5]).unwrap(), vec![Complex64::new(-3.5, 0.0)]);
}

#[test]
fn problem_15_20_5_roots_equal_companion_eigenvalues() {
    // 15.20.5: p = s³ + 3s² + 5s − 2 has roots −1.6641 ± 1.8230j and 0.3283.
    let r = sorted(poly(&[1.0, 3.0, 5.0, -2.0]).roots().unwrap());
    assert_printed(r[0].re, -1.6641, 4);
    assert_printed(r[0].im, -1.8230, 4);
    assert_eq!(r[0], r[1].conj());
    assert_printed(r[2].re, 0.3283, 4);
    // p(A) = 0 for its companion matrix (Cayley–Hamilton, 15.20.4).
    let sys = StateSpace::companion(&[-2.0, 5.0, 3.0], 1.0).unwrap();
    let a = sys.a();
    let pa = a * a * a + 3.0 * a * a + 5.0 * a - 2.0 * DMatrix::<f64>::identity(3, 3);
    assert!(pa.amax() <= 64.0 * EPS, "p(A) = {pa}");
}

#[test]
fn roots_exact_zeros_and_trimming() {
    // Exact roots at 0 stay exact (integrators, DRB), and ss → tf round-off in the leading
    // coefficient is trimmed (notes §3.3: 1.1e-16 gave a spurious zero at −1.04e16).
    let p = poly(&[1.0, 1.0, 0.0, 0.0]);
    let r = sorted(p.roots().unwrap());
    assert_eq!(r[1], Complex64::new(0.0, 0.0));
    assert_eq!(r[2], Complex64::new(0.0, 0.0));
    let noisy = poly(&[1.1e-16, 1.151, 0.1774]);
    assert_eq!(noisy.trim(TRIM_RTOL).degree(), 1);
}

// ---------------------------------------------------------------- matrix exponential (15.5)

#[test]
fn example_15_5_1_expm_of_diagonal() {
    // Ex 15.5.1: e^{diag(1,2)t} = diag(eᵗ, e²ᵗ).
    let t = 0.7;
    let e = expm(&dmatrix![t, 0.0; 0.0, 2.0 * t]).unwrap();
    assert_rel(e[(0, 0)], t.exp(), 4.0 * EPS);
    assert_rel(e[(1, 1)], (2.0 * t).exp(), 4.0 * EPS);
    assert_eq!(e[(0, 1)], 0.0);
}

#[test]
fn example_15_5_2_expm_of_rotation_generator() {
    // Ex 15.5.2: e^{[[0, ω], [−ω, 0]]t} = [[cos ωt, sin ωt], [−sin ωt, cos ωt]].
    // ERR: the book cites Ex 15.3.3 for the eigenvalues; it means Ex 15.3.4.
    for wt in [0.1f64, 1.0, 3.0, 25.0] {
        let e = expm(&dmatrix![0.0, wt; -wt, 0.0]).unwrap();
        let want = dmatrix![wt.cos(), wt.sin(); -wt.sin(), wt.cos()];
        assert!((e - want).amax() <= 64.0 * EPS * wt.max(1.0), "ωt = {wt}");
    }
}

#[test]
fn expm_defective_critical_damping() {
    // Notes §3.1: e^{[[0,1],[−1,−2]]t} = e^{−t}[[1+t, t], [−t, 1−t]] (a Jordan block, where an
    // eigendecomposition fails); at t = 1.3: [[0.62682, 0.35429], [−0.35429, −0.08176]].
    let t = 1.3;
    let e = expm(&dmatrix![0.0, t; -t, -2.0 * t]).unwrap();
    let f = (-t).exp();
    let want = dmatrix![f * (1.0 + t), f * t; -f * t, f * (1.0 - t)];
    assert!((&e - want).amax() <= 16.0 * EPS);
    assert_printed(e[(0, 0)], 0.62682, 5);
    assert_printed(e[(1, 1)], -0.08176, 5);
}

#[test]
fn problem_15_20_27_damped_rigid_body_expm() {
    // 15.20.27: DRB e^{At} = [[1, (m/c)(1 − e^{−ct/m})], [0, e^{−ct/m}]] → [[1, m/c], [0, 0]].
    let (m, c) = (3.0, 4.0);
    let a = Sdof::new(m, c, 0.0).unwrap().to_state_space(SdofOutput::Position).unwrap().a().clone();
    for t in [0.5f64, 2.0, 40.0] {
        let e = expm(&(&a * t)).unwrap();
        assert_abs(e[(0, 1)], m / c * (1.0 - (-c * t / m).exp()), 16.0 * EPS);
        assert_abs(e[(1, 1)], (-c * t / m).exp(), 16.0 * EPS);
        assert_abs(e[(0, 0)], 1.0, 16.0 * EPS);
    }
}

#[test]
fn expm_large_norm_uses_scaling_and_squaring() {
    // e^{[[σ, ω], [−ω, σ]]t} = e^{σt}[[cos ωt, sin ωt], [−sin ωt, cos ωt]] with ‖A‖ ~ 80: the
    // Padé-13 branch with squarings. Squaring s times amplifies round-off by ~2ˢ.
    let (sigma, w, t) = (-0.5f64, 40.0f64, 2.0f64);
    let e = expm(&dmatrix![sigma * t, w * t; -w * t, sigma * t]).unwrap();
    let f = (sigma * t).exp();
    let want = dmatrix![f * (w * t).cos(), f * (w * t).sin(); -f * (w * t).sin(), f * (w * t).cos()];
    assert!((e - want).amax() <= 1e3 * EPS, "expm with scaling");
}

// ---------------------------------------------------------------- SDOF and modes (15.4, 15.15)

#[test]
fn section_15_4_sdof_kinds_and_stability_classes() {
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
fn fact_15_16_semisimple_zero_matrix_is_semistable() {
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
    assert_abs(s.damping_ratio().unwrap(), zeta, 4.0 * EPS);
    let modes = modes(s.to_state_space(SdofOutput::Position).unwrap().a()).unwrap();
    for m in &modes {
        assert_rel(m.natural_frequency, wn, 16.0 * EPS);
        assert_abs(m.damping_ratio.unwrap(), zeta, 16.0 * EPS);
        assert_rel(m.damped_frequency, wn * (1.0 - zeta * zeta).sqrt(), 16.0 * EPS);
        assert_rel(m.time_to_half.unwrap(), std::f64::consts::LN_2 / (zeta * wn), 16.0 * EPS);
    }
}

#[test]
fn problem_15_20_51_boeing_747_dutch_roll() {
    // 15.20.51: λ = −0.0329 ± 0.9467j (Dutch roll, ζ = 0.0348, ωn = 0.947), −0.5627, −0.0073;
    // asymptotically stable.
    let a = dmatrix![-0.0558, -0.9968, 0.0802, 0.0415;
                     0.598, -0.115, -0.0318, 0.0;
                     -3.05, 0.388, -0.4650, 0.0;
                     0.0, 0.0805, 1.0, 0.0];
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

// ---------------------------------------------------------------- state space ↔ tf (15.7, 15.14)

fn b747() -> StateSpace {
    let a = dmatrix![-0.0558, -0.9968, 0.0802, 0.0415;
                     0.598, -0.115, -0.0318, 0.0;
                     -3.05, 0.388, -0.4650, 0.0;
                     0.0, 0.0805, 1.0, 0.0];
    let b = dmatrix![0.00729, 0.0; -0.475, 0.00775; 0.153, 0.143; 0.0, 0.0];
    // Outputs r (state 2) and φ (state 4), 15.20.52.
    let c = dmatrix![0.0, 1.0, 0.0, 0.0; 0.0, 0.0, 0.0, 1.0];
    StateSpace::new(a, b, c, DMatrix::zeros(2, 2)).unwrap()
}

#[test]
fn problem_15_20_52_boeing_747_channel_zeros() {
    // 15.20.52 (computed in the notes): common denominator s⁴ + 0.6358s³ + 0.9389s² + 0.5116s
    // + 0.00367; zeros r/δr: −0.4981, −0.0119 ± 0.4878j; r/δa: 0.2509 ± 1.1307j, −0.4357;
    // φ/δr: 4.4398, −2.6940; φ/δa: −0.0954 ± 0.8723j.
    let sys = b747();
    let g = sys.to_tf(0, 0).unwrap();
    let den = g.den().monic();
    for (got, want) in den.coeffs().iter().zip([1.0, 0.6358, 0.9389, 0.5116, 0.00367]) {
        assert_printed(*got, want, if want < 0.01 { 5 } else { 4 });
    }
    let check = |out, inp, want: &[(f64, f64)]| {
        let z = sorted(sys.to_tf(out, inp).unwrap().zeros().unwrap());
        assert_eq!(z.len(), want.len(), "channel {out}/{inp}: zeros {z:?}");
        for (g, w) in z.iter().zip(want) {
            assert_printed(g.re, w.0, 4);
            assert_printed(g.im, w.1, 4);
        }
    };
    check(0, 0, &[(-0.4981, 0.0), (-0.0119, -0.4878), (-0.0119, 0.4878)]);
    check(0, 1, &[(-0.4357, 0.0), (0.2509, -1.1307), (0.2509, 1.1307)]);
    check(1, 0, &[(-2.6940, 0.0), (4.4398, 0.0)]);
    check(1, 1, &[(-0.0954, -0.8723), (-0.0954, 0.8723)]);
}

#[test]
fn problem_15_20_38_pitch_minreal() {
    // 15.20.38: θ depends only on θ and δe, so G = 0.0203/(s + 0.5); the plain ss → tf is the
    // non-minimal 3rd-order ratio (notes §3.3) and minreal recovers the first-order one.
    let a = dmatrix![-0.313, 56.7, 0.0; -0.0139, -0.426, 0.0; 0.0, 0.0, -0.5];
    let sys =
        StateSpace::new(a, dmatrix![0.232; 0.0; 0.0203], dmatrix![0.0, 0.0, 1.0], dmatrix![0.0]).unwrap();
    let full = sys.to_tf(0, 0).unwrap();
    assert_eq!(full.den().degree(), 3);
    let g = full.minreal(1e-6).unwrap();
    assert_eq!(g.den().degree(), 1);
    assert_abs(g.num().coeff(0) / g.den().coeff(1), 0.0203, 1e3 * EPS);
    assert_abs(g.den().coeff(0) / g.den().coeff(1), 0.5, 1e3 * EPS);
}

#[test]
fn problem_15_20_42_markov_trimmed_numerator() {
    // 15.20.42: G = 1.151(s + 0.1541)/(s(s² + 0.739s + 0.9215)); CB = 0 so the s² coefficient of
    // the numerator must come out exactly 0, not 1e-16 (notes §3.3, a spurious zero at −1e16).
    let a = dmatrix![-0.313, 56.7, 0.0; -0.0139, -0.426, 0.0; 0.0, 56.7, 0.0];
    let sys =
        StateSpace::new(a, dmatrix![0.232; 0.0203; 0.0], dmatrix![0.0, 0.0, 1.0], dmatrix![0.0]).unwrap();
    let g = sys.to_tf(0, 0).unwrap();
    assert_eq!(g.num().degree(), 1, "numerator {}", g.num());
    assert_printed(g.num().leading(), 1.151, 3);
    let z = g.zeros().unwrap();
    assert_printed(z[0].re, -0.1541, 4);
    let d = g.den().coeffs();
    assert_printed(d[1], 0.739, 3);
    assert_printed(d[2], 0.9215, 4);
    assert_eq!(d[3], 0.0); // the integrator θ̇ = 56.7q
}

#[test]
fn problem_15_20_37_cancellation_and_minimal_realisation() {
    // 15.20.37: A = [[0,1],[−2,−3]], B = [0,1]ᵀ, C = [1,1]: G = (s+1)/((s+1)(s+2)) = 1/(s+2);
    // minimal realisation (−2, 1, 1, 0).
    let sys =
        StateSpace::from_rows(&[&[0.0, 1.0], &[-2.0, -3.0]], &[&[0.0], &[1.0]], &[&[1.0, 1.0]], &[&[0.0]])
            .unwrap();
    let g = sys.to_tf(0, 0).unwrap();
    assert_eq!(g.num().coeffs(), &[1.0, 1.0]);
    assert_eq!(g.den().coeffs(), &[1.0, 3.0, 2.0]);
    assert!(!sys.is_observable(1e-10).unwrap()); // the cancelled mode is unobservable
    let m = sys.minreal(1e-8).unwrap();
    assert_eq!(m.n_states(), 1);
    assert_rel(m.a()[(0, 0)], -2.0, 16.0 * EPS);
    assert_abs(m.c()[(0, 0)] * m.b()[(0, 0)], 1.0, 16.0 * EPS);
}

#[test]
fn eq_15_14_15_drb_velocity_output_cancels() {
    // (15.14.15): DRB with velocity output: s/(s² + (c/m)s) = 1/(s + c/m); the position state
    // is unobservable (15.20.56: velocity output is unobservable for URB and DRB).
    let (m, c) = (2.0, 3.0);
    let sys = Sdof::new(m, c, 0.0).unwrap().to_state_space(SdofOutput::Velocity).unwrap();
    assert!(sys.is_controllable(1e-10).unwrap());
    assert!(!sys.is_observable(1e-10).unwrap());
    let g = sys.to_tf(0, 0).unwrap().minreal(1e-8).unwrap();
    assert_eq!(g.den().degree(), 1);
    assert_rel(g.den().coeff(0) / g.den().coeff(1), c / m, 16.0 * EPS);
    for kind in [(0.0, 0.0), (c, 0.0), (0.0, 5.0), (c, 5.0)] {
        let s = Sdof::new(m, kind.0, kind.1).unwrap();
        let pos = s.to_state_space(SdofOutput::Position).unwrap();
        assert_eq!(linalg::rank(&pos.ctrb(), 1e-10).unwrap(), 2, "15.20.56 ctrb rank 2");
        let vel = s.to_state_space(SdofOutput::Velocity).unwrap();
        assert_eq!(vel.is_observable(1e-10).unwrap(), kind.1 > 0.0);
    }
}

#[test]
fn problem_15_20_14_acceleration_output_feedthrough() {
    // 15.20.14: DO with acceleration output has D = 1/m and C = [−k/m, −c/m] (ERR: the book
    // prints C = [0, −c/m]). Check against G = s²/(ms² + cs + k).
    let (m, c, k) = (2.0, 0.6, 5.0);
    let sys = Sdof::new(m, c, k).unwrap().to_state_space(SdofOutput::Acceleration).unwrap();
    assert_eq!(sys.d()[(0, 0)], 1.0 / m);
    let g = sys.to_tf(0, 0).unwrap();
    let want = tf(&[1.0, 0.0, 0.0], &[m, c, k]);
    for w in [0.1, 1.0, 7.0] {
        let s = Complex64::new(0.0, w);
        assert!((g.eval(s) - want.eval(s)).norm() <= 1e3 * EPS);
    }
    // The impulse response reports the Dirac part Dδ(t) separately (15.8.5, notes §3.10).
    let r = response(&sys, InputKind::Impulse, 0, 2.0, 0.0, &time_grid(1.0, 11).unwrap()).unwrap();
    assert_eq!(r.impulse_weight, vec![2.0 / m]);
}

#[test]
fn companion_form_15_7_3() {
    // (15.7.3): q''' + a₂q'' + a₁q' + a₀q = b₀u in companion form has G = b₀/(s³ + a₂s² + a₁s + a₀).
    let sys = StateSpace::companion(&[6.0, 11.0, 6.0], 2.0).unwrap();
    assert_eq!(sys.a()[(2, 0)], -6.0);
    assert_eq!(sys.a()[(0, 1)], 1.0);
    let g = sys.to_tf(0, 0).unwrap();
    assert_rel(g.num().coeffs()[0], 2.0, 64.0 * EPS);
    for (got, want) in g.den().coeffs().iter().zip([1.0, 6.0, 11.0, 6.0]) {
        assert_rel(*got, want, 64.0 * EPS);
    }
}

#[test]
fn interconnections_series_parallel_feedback() {
    // Series, parallel and unity feedback agree between tf and state space (15.18.4).
    let g1 = tf(&[1.0, 2.0], &[1.0, 3.0, 5.0]);
    let g2 = tf(&[4.0], &[1.0, 1.0]);
    let (s1, s2) = (StateSpace::from_tf(&g1).unwrap(), StateSpace::from_tf(&g2).unwrap());
    let cases = [
        (g1.series(&g2), s1.series(&s2).unwrap()),
        (g1.parallel(&g2).unwrap(), s1.parallel(&s2).unwrap()),
        (g1.feedback(&TransferFunction::gain(1.0).unwrap()).unwrap(), s1.unity_feedback().unwrap()),
    ];
    for (g, s) in cases {
        let gs = s.to_tf(0, 0).unwrap();
        for w in [0.0, 0.3, 2.0, 30.0] {
            let z = Complex64::new(0.0, w);
            assert!((g.eval(z) - gs.eval(z)).norm() <= 1e3 * EPS * g.eval(z).norm().max(1.0));
        }
    }
}

// ---------------------------------------------------------------- Laplace (15.10–15.13)

#[test]
fn example_15_11_4_partial_fractions_and_inverse() {
    // Ex 15.11.4: (s+2)(s+4)/(s(s+1)(s+3)) → 8/3 − 1.5e^{−t} − (1/6)e^{−3t}.
    let g = tf(&[1.0, 6.0, 8.0], &[1.0, 4.0, 3.0, 0.0]);
    let pf = g.partial_fractions(CLUSTER_RTOL).unwrap();
    let res = |p: f64| pf.terms.iter().find(|t| (t.pole.re - p).abs() < 1e-9).unwrap().residue.re;
    assert_rel(res(0.0), 8.0 / 3.0, 64.0 * EPS);
    assert_rel(res(-1.0), -1.5, 64.0 * EPS);
    assert_abs(res(-3.0), -1.0 / 6.0, 64.0 * EPS);
    let y = g.inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.0f64, 0.4, 2.0, 9.0] {
        let want = 8.0 / 3.0 - 1.5 * (-t).exp() - (-3.0 * t).exp() / 6.0;
        // absolute at the scale of the largest term, 8/3
        assert_abs(y.eval(t), want, 64.0 * EPS * 8.0 / 3.0);
    }
}

#[test]
fn problem_15_20_19_inverse_laplace_real_form() {
    // 15.20.19: 1/(s(s²+s+1)) → 1 − e^{−t/2}cos(√3t/2) − (1/√3)e^{−t/2}sin(√3t/2); notes (C):
    // the step response of 1/(s²+s+1) peaks at 1.1630 at t = 3.628.
    let y = tf(&[1.0], &[1.0, 1.0, 1.0, 0.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    let w = 3f64.sqrt() / 2.0;
    for t in [0.3f64, 1.0, 5.0] {
        let want = 1.0 - (-t / 2.0).exp() * ((w * t).cos() + (w * t).sin() / 3f64.sqrt());
        // absolute at the scale of the terms (≤ 2)
        assert_abs(y.eval(t), want, 64.0 * EPS * 2.0);
    }
    // Peak: ẏ = 0 at ωd t = π, so t = 2π/√3 = 3.628 and y = 1 + e^{−π/√3} = 1.1630.
    let tp = std::f64::consts::PI / w;
    assert_printed(tp, 3.628, 3);
    assert_printed(y.eval(tp), 1.1630, 4);
    let step = tf(&[1.0], &[1.0, 1.0, 1.0]).step(&[0.0, tp]).unwrap();
    assert_rel(step.y[0][1], y.eval(tp), 1e3 * EPS);
}

#[test]
fn eq_15_15_9_repeated_pole_inverse() {
    // (15.15.9): critical damping, (1/m)/(s + ωn)² → (1/m) t e^{−ωn t}; and 2/(s+1)³ → t²e^{−t}.
    let y = tf(&[0.5], &[1.0, 4.0, 4.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.1f64, 1.0, 3.0] {
        assert_abs(y.eval(t), 0.5 * t * (-2.0 * t).exp(), 1e-7); // double root split by ~√ε
    }
    let y = tf(&[2.0], &[1.0, 3.0, 3.0, 1.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.1f64, 1.0, 3.0] {
        assert_abs(y.eval(t), t * t * (-t).exp(), 1e-6); // triple root split by ~ε^{1/3}
    }
}

#[test]
fn problem_15_20_17_harmonic_response() {
    // 15.20.17: v̇ + 2v = sin 5t (ERR: the statement says v̈ + 2v̇), v(0) = v₀:
    // v = (v₀ + 5/29)e^{−2t} − (5/29)cos 5t + (2/29)sin 5t.
    let v0 = 0.4;
    // V = (v₀(s²+25) + 5)/((s+2)(s²+25)).
    let v = tf(&[v0, 0.0, 25.0 * v0 + 5.0], &[1.0, 2.0, 25.0, 50.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.2f64, 1.0, 4.0] {
        let want = (v0 + 5.0 / 29.0) * (-2.0 * t).exp() - 5.0 / 29.0 * (5.0 * t).cos()
            + 2.0 / 29.0 * (5.0 * t).sin();
        assert_abs(v.eval(t), want, 256.0 * EPS);
    }
}

#[test]
fn problem_15_20_26_forced_undamped_oscillator() {
    // 15.20.26: 2q̈ + 17q = 5 sin 2t from rest: q = (5/9)sin 2t − (10/9)√(2/17) sin(√(17/2) t).
    let q = tf(&[10.0], Polynomial::new(&[2.0, 0.0, 17.0]).unwrap().mul(&poly(&[1.0, 0.0, 4.0])).coeffs())
        .inverse_laplace(CLUSTER_RTOL)
        .unwrap();
    let w = (17.0f64 / 2.0).sqrt();
    for t in [0.5f64, 3.0, 10.0] {
        let want = 5.0 / 9.0 * (2.0 * t).sin() - 10.0 / 9.0 * (2.0f64 / 17.0).sqrt() * (w * t).sin();
        assert_abs(q.eval(t), want, 256.0 * EPS);
    }
}

#[test]
fn example_15_13_2_final_value_theorem() {
    // Ex 15.13.2: 1 → 1; −t → −∞ (needs s → 0⁺); e^{−t} → 0; eᵗ → illegal (not 0).
    assert_eq!(final_value(&tf(&[1.0], &[1.0, 0.0]), AXIS_RTOL).unwrap(), FinalValue::Finite(1.0));
    assert_eq!(final_value(&tf(&[-1.0], &[1.0, 0.0, 0.0]), AXIS_RTOL).unwrap(), FinalValue::Infinite(-1.0));
    assert_eq!(final_value(&tf(&[1.0], &[1.0, 1.0]), AXIS_RTOL).unwrap(), FinalValue::Finite(0.0));
    assert!(matches!(
        final_value(&tf(&[1.0], &[1.0, -1.0]), AXIS_RTOL).unwrap(),
        FinalValue::Illegal(Illegal::RightHalfPlanePole(_))
    ));
    // sin t never settles: a pole on the imaginary axis.
    assert!(matches!(
        final_value(&tf(&[1.0], &[1.0, 0.0, 1.0]), AXIS_RTOL).unwrap(),
        FinalValue::Illegal(Illegal::ImaginaryAxisPole(_))
    ));
}

#[test]
fn problem_15_20_29_final_values() {
    // 15.20.29: i) −5/(s(s+7)²), u = 3e^{−2t}: y∞ = −15/98; ii) 5/(s−3): illegal (ORHP);
    // iii) −4/(s²+2.4s+0.3), u = 6t²: legal, −∞.
    let g = tf(&[-5.0], &[1.0, 14.0, 49.0, 0.0]).series(&tf(&[3.0], &[1.0, 2.0]));
    let FinalValue::Finite(v) = g.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
    assert_abs(v, -15.0 / 98.0, 16.0 * EPS);
    let g = tf(&[5.0], &[1.0, -3.0]).series(&tf(&[7.0, -3.0 * 0.0], &[1.0, 0.0]));
    assert!(matches!(g.final_value(AXIS_RTOL).unwrap(), FinalValue::Illegal(Illegal::RightHalfPlanePole(_))));
    let g = tf(&[-4.0], &[1.0, 2.4, 0.3]).series(&tf(&[12.0], &[1.0, 0.0, 0.0, 0.0]));
    assert_eq!(g.final_value(AXIS_RTOL).unwrap(), FinalValue::Infinite(-1.0));
}

#[test]
fn problem_15_20_30_routh_and_final_values() {
    // 15.20.30 i) (s²−1)/(s(3s³+2s²+4s+3)), u = 2δ: illegal, a₂a₁ − a₀ = −1/9 < 0 (ERR: "6/3"
    // should be 1); ii) 1/(s(s²+3s+1)), u = −2e^{−t}sin 2t: y∞ = −0.8.
    let cubic = poly(&[3.0, 2.0, 4.0, 3.0]);
    let ra = routh(&cubic).unwrap();
    assert_eq!(ra.rhp, 2);
    let m = cubic.monic();
    assert_abs(m.coeff(2) * m.coeff(1) - m.coeff(0), -1.0 / 9.0, 16.0 * EPS);
    let y = tf(&[2.0, 0.0, -2.0], cubic.mul(&Polynomial::s()).coeffs());
    assert!(matches!(y.final_value(AXIS_RTOL).unwrap(), FinalValue::Illegal(Illegal::RightHalfPlanePole(_))));
    // −2e^{−t}sin 2t ↦ −4/((s+1)² + 4).
    let y = tf(&[1.0], &[1.0, 3.0, 1.0, 0.0]).series(&tf(&[-4.0], &[1.0, 2.0, 5.0]));
    let FinalValue::Finite(v) = y.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
    assert_abs(v, -0.8, 16.0 * EPS);
}

#[test]
fn problem_15_20_31_final_values() {
    // 15.20.31 i) DRB free response, m = 3, c = 4, q₀ = 1, q̇₀ = −2: q∞ = (mq̇₀ + cq₀)/c = −0.5
    // (corrected in the notes); ii) (4s²−12s−16)/(2s⁵+2s⁴+4s³+2s²+s), u = 3δ(t−1): Routh
    // 1.5 < 2 holds and y∞ = −48 (the delay e^{−s} is ignored at s = 0).
    let (m, c) = (3.0, 4.0);
    let q = tf(&[m * 1.0, c * 1.0 + m * -2.0], &[m, c, 0.0]);
    let FinalValue::Finite(v) = q.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
    assert_abs(v, -0.5, 16.0 * EPS);
    let sys = Sdof::new(m, c, 0.0).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let r = initial(&sys, &[1.0, -2.0], &time_grid(60.0, 7).unwrap()).unwrap();
    assert_abs(r.y[0][6], -0.5, 1e-12);
    let y = tf(&[12.0, -36.0, -48.0], &[2.0, 2.0, 4.0, 2.0, 1.0, 0.0]).with_delay(1.0).unwrap();
    assert!(routh(&poly(&[2.0, 2.0, 4.0, 2.0, 1.0])).unwrap().is_hurwitz());
    let FinalValue::Finite(v) = y.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
    assert_rel(v, -48.0, 16.0 * EPS);
}

#[test]
fn problem_15_20_15_16_initial_values() {
    // 15.20.15–16: t, t+1, sin 2t, cos 2t: y(0⁺) = 0, 1, 0, 1; ẏ(0⁺) = 1, 1, 2, 0 (Facts
    // 15.12.1–2, the derivative form as corrected: lim s[sŷ − y(0⁺)]).
    let cases = [
        (tf(&[1.0], &[1.0, 0.0, 0.0]), [0.0, 1.0]),
        (tf(&[1.0, 1.0], &[1.0, 0.0, 0.0]), [1.0, 1.0]),
        (tf(&[2.0], &[1.0, 0.0, 4.0]), [0.0, 2.0]),
        (tf(&[1.0, 0.0], &[1.0, 0.0, 4.0]), [1.0, 0.0]),
    ];
    for (y, want) in cases {
        assert_eq!(y.initial_values(2).unwrap(), want.to_vec());
    }
    // 15.20.28: y = 2e^{−6t}: ÿ(0⁺) = 72.
    assert_eq!(tf(&[2.0], &[1.0, 6.0]).initial_values(3).unwrap(), vec![2.0, -12.0, 72.0]);
}

#[test]
fn example_15_13_3_nonminimum_phase_undershoot() {
    // Ex 15.13.3: step f₀ into (s − z)/(s² + 2ζωn s + ωn²): y∞ = −f₀z/ωn², y(0⁺) = 0,
    // ẏ(0⁺) = f₀; z > 0 gives an initial undershoot. 15.20.32: (4s − 3)/(s² + 0.8s + 4):
    // y(0⁺) = 0, ẏ(0⁺) = 4, y∞ = −0.75, poles −0.4 ± 1.96j; (C) max 1.0875 at 0.531 s,
    // min −1.7177 at 2.134 s.
    let g = tf(&[4.0, -3.0], &[1.0, 0.8, 4.0]);
    let y = g.series(&tf(&[1.0], &[1.0, 0.0]));
    assert_eq!(y.initial_values(2).unwrap(), vec![0.0, 4.0]);
    assert_eq!(y.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(-0.75));
    let p = g.poles().unwrap();
    assert_printed(p[0].re, -0.4, 2);
    assert_printed(p[0].im.abs(), 1.96, 2);
    let t = time_grid(4.0, 4001).unwrap();
    let r = g.step(&t).unwrap();
    let (kmax, ymax) = r.y[0].iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)).unwrap();
    let (kmin, ymin) = r.y[0].iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1)).unwrap();
    assert_printed(*ymax, 1.0875, 4);
    assert_printed(t[kmax], 0.531, 3);
    assert_printed(*ymin, -1.7177, 4);
    assert_printed(t[kmin], 2.134, 3);
    // The sampled step agrees with the inverse transform everywhere (exact discretisation).
    let exact = y.inverse_laplace(CLUSTER_RTOL).unwrap();
    for k in (0..t.len()).step_by(397) {
        // absolute at the response's scale (|y| ≤ 1.8), after 4000 exact steps
        assert_abs(r.y[0][k], exact.eval(t[k]), 1e3 * EPS);
    }
}

// ---------------------------------------------------------------- time responses (15.8–15.9)

#[test]
fn eq_15_15_8_underdamped_impulse_response() {
    // (15.15.8): f₀δ into (1/m)/(s² + 2ζωn s + ωn²) gives (f₀/(mωd))e^{−ζωn t} sin ωd t.
    let (m, wn, zeta, f0) = (2.0, 3.0, 0.1, 0.7);
    let s =
        Sdof::new(m, 2.0 * zeta * wn * m, wn * wn * m).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let t = time_grid(10.0, 501).unwrap();
    let r = response(&s, InputKind::Impulse, 0, f0, 0.0, &t).unwrap();
    let wd = wn * (1.0 - zeta * zeta).sqrt();
    for k in (0..t.len()).step_by(50) {
        let want = f0 / (m * wd) * (-zeta * wn * t[k]).exp() * (wd * t[k]).sin();
        assert_abs(r.y[0][k], want, 1e3 * EPS);
    }
    assert_eq!(r.impulse_weight, vec![0.0]);
}

#[test]
fn delayed_step_is_exact_off_grid() {
    // A step delayed by 0.35 (not a multiple of h = 0.1) into 1/(s+1): y = 1 − e^{−(t−0.35)}.
    let g = tf(&[1.0], &[1.0, 1.0]).with_delay(0.35).unwrap();
    let t = time_grid(5.0, 51).unwrap();
    let r = g.step(&t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        let want = if tk < 0.35 { 0.0 } else { 1.0 - (-(tk - 0.35)).exp() };
        assert_abs(r.y[0][k], want, 64.0 * EPS);
    }
}

#[test]
fn problem_15_20_23_drb_ramp_velocity() {
    // 15.20.23: DRB, ramp f₀t, velocity output: v = f₀(−m/c² + t/c + (m/c²)e^{−ct/m}).
    let (m, c, f0) = (2.0, 0.5, 3.0);
    let sys = Sdof::new(m, c, 0.0).unwrap().to_state_space(SdofOutput::Velocity).unwrap();
    let t = time_grid(20.0, 41).unwrap();
    let r = response(&sys, InputKind::Ramp, 0, f0, 0.0, &t).unwrap();
    let want: Vec<f64> =
        t.iter().map(|&tk| f0 * (-m / (c * c) + tk / c + m / (c * c) * (-c * tk / m).exp())).collect();
    // relative to the largest value of the run: the rounding accumulates at the state's scale
    assert_rel_slice(&r.y[0], &want, 64.0 * EPS);
    // lsim with first-order hold of the sampled ramp is exact too, also with an off-grid delay.
    let u: Vec<f64> = t.iter().map(|&tk| f0 * tk).collect();
    let l = lsim(&sys, 0, &u, &t, &[0.0, 0.0], Hold::Foh, 0.0).unwrap();
    assert_rel_slice(&l.y[0], &r.y[0], 64.0 * EPS);
    let d = 0.3; // h = 0.5
    let rd = response(&sys, InputKind::Ramp, 0, f0, d, &t).unwrap();
    let ld = lsim(&sys, 0, &u, &t, &[0.0, 0.0], Hold::Foh, d).unwrap();
    assert_rel_slice(&ld.y[0], &rd.y[0], 1e3 * EPS);
}

#[test]
fn problem_15_20_9_first_order_free_and_forced() {
    // 15.20.8–9: ẋ = −2x + 8: x = e^{−2t}(x₀ − 4) + 4; x₀ = 5 gives e^{−2t} + 4 (ERR: the M-file
    // uses exp(−3t)).
    let sys = StateSpace::from_rows(&[&[-2.0]], &[&[8.0]], &[&[1.0]], &[&[0.0]]).unwrap();
    let t = time_grid(3.0, 31).unwrap();
    let free = initial(&sys, &[5.0], &t).unwrap();
    let forced = response(&sys, InputKind::Step, 0, 1.0, 0.0, &t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        assert_rel(free.y[0][k] + forced.y[0][k], (-2.0 * tk).exp() + 4.0, 64.0 * EPS);
    }
    // lsim with ZOH of a constant input and x₀ gives the same.
    let l = lsim(&sys, 0, &vec![1.0; t.len()], &t, &[5.0], Hold::Zoh, 0.0).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        assert_rel(l.y[0][k], (-2.0 * tk).exp() + 4.0, 64.0 * EPS);
    }
}

// ---------------------------------------------------------------- Routh and gain intervals (15.17)

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
fn routh_special_case_zero_in_first_column() {
    // s⁴ + s³ + 2s² + 2s + 3: the s² row starts with 0 (ε-substitution); 2 roots in the ORHP.
    let ra = routh(&poly(&[1.0, 1.0, 2.0, 2.0, 3.0])).unwrap();
    assert!(ra.epsilon_used);
    assert_eq!((ra.rhp, ra.imaginary, ra.lhp()), (2, 0, 2));
}

#[test]
fn routh_special_case_row_of_zeros() {
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
    // 15.20.39: S = (s+0.5)/(s + 0.5 + 0.0203Kp): AS iff Kp > −24.6 (C: −24.631).
    let iv = intervals(&[0.0203], &poly(&[1.0, 0.5]));
    assert_eq!(iv.len(), 1);
    assert_printed(iv[0].0, -24.631, 3);
    assert_eq!(iv[0].1, f64::INFINITY);
}

#[test]
fn problem_15_20_43_quartic_gain_interval() {
    // 15.20.43 (C): G = 1/(s²+2s+1), Gc = k/(s²+2s): s⁴ + 4s³ + 5s² + 2s + k, AS iff 0 < k < 2.25.
    let iv = intervals(&[1.0], &poly(&[1.0, 2.0, 1.0]).mul(&poly(&[1.0, 2.0, 0.0])));
    assert_eq!(iv.len(), 1);
    assert_abs(iv[0].0, 0.0, 1e-12);
    assert_rel(iv[0].1, 2.25, 1e-10);
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
    let d = poly(&[1.0, -0.08, 0.016]).mul(&poly(&[1.0, 8.6, 50.98]));
    let iv = intervals(&[1.0, 0.2], &d);
    assert_eq!(iv.len(), 1);
    assert_printed(iv[0].0, 4.2221, 4);
    assert_printed(iv[0].1, 417.77, 2);
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

// ---------------------------------------------------------------- typed errors

#[test]
fn bad_input_is_a_typed_error() {
    assert_eq!(TransferFunction::new(&[1.0], &[0.0, 0.0]).unwrap_err(), LtiError::ZeroDenominator);
    assert!(matches!(TransferFunction::new(&[f64::NAN], &[1.0]), Err(LtiError::NonFinite { .. })));
    assert!(matches!(
        StateSpace::from_tf(&tf(&[1.0, 0.0, 0.0], &[1.0, 1.0])),
        Err(LtiError::Improper { num_degree: 2, den_degree: 1, .. })
    ));
    let a = DMatrix::zeros(2, 3);
    assert!(matches!(
        StateSpace::new(a, DMatrix::zeros(2, 1), DMatrix::zeros(1, 2), DMatrix::zeros(1, 1)),
        Err(LtiError::NotSquare { rows: 2, cols: 3, .. })
    ));
    assert!(matches!(
        StateSpace::new(
            DMatrix::zeros(2, 2),
            DMatrix::zeros(3, 1),
            DMatrix::zeros(1, 2),
            DMatrix::zeros(1, 1)
        ),
        Err(LtiError::DimensionMismatch { what: "B", .. })
    ));
    assert!(matches!(expm(&DMatrix::from_element(2, 2, f64::INFINITY)), Err(LtiError::NonFinite { .. })));
    assert!(matches!(Sdof::new(0.0, 1.0, 1.0), Err(LtiError::InvalidArgument { .. })));
    assert!(matches!(b747().to_tf(2, 0), Err(LtiError::IndexOutOfRange { what: "output", .. })));
    let g = tf(&[1.0], &[1.0, 1.0]).with_delay(0.5).unwrap();
    assert!(matches!(g.feedback(&g), Err(LtiError::Delay { .. })));
    assert!(matches!(g.step(&[0.0, 0.1, 0.3]), Err(LtiError::InvalidArgument { what: "time grid", .. })));
    assert!(matches!(tf(&[1.0, 2.0], &[1.0, 1.0]).initial_values(1), Err(LtiError::Improper { .. })));
}

// ---------------------------------------------------------------- properties

mod prop {
    use super::*;
    use proptest::prelude::*;

    /// Monic polynomials from roots kept off the imaginary axis by at least 0.05, biased to
    /// repeated and nearly repeated roots.
    fn roots_strategy() -> impl Strategy<Value = Vec<Complex64>> {
        let re = prop_oneof![-5.0..-0.05f64, 0.05..5.0f64];
        let one = (re.clone(), 0.0..4.0f64, proptest::bool::ANY).prop_map(|(r, i, complex)| {
            if complex {
                vec![Complex64::new(r, i), Complex64::new(r, -i)]
            } else {
                vec![Complex64::new(r, 0.0)]
            }
        });
        proptest::collection::vec(one, 1..5).prop_map(|v| v.into_iter().flatten().collect())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(96))]

        /// Eigenvalues (15.3.5) of random matrices, small and above the 64×64 switch to the
        /// library solver: they sum to the trace, and each is an eigenvalue to backward-stable
        /// accuracy (the smallest singular value of A − λI is tiny relative to ‖A‖).
        #[test]
        fn eigenvalues_sum_to_trace_and_are_eigenvalues(
            n in prop_oneof![1usize..12, Just(20usize), Just(70usize)],
            seed in any::<u64>(),
            scale in prop_oneof![Just(1.0f64), Just(1e-8), Just(1e8)],
        ) {
            let mut x = seed | 1;
            let mut next = || {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                (x >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
            };
            let a = DMatrix::from_fn(n, n, |_, _| next() * scale);
            let ev = linalg::eigenvalues(&a).unwrap();
            prop_assert_eq!(ev.len(), n);
            let norm = a.norm();
            let sum: Complex64 = ev.iter().sum();
            prop_assert!((sum.re - a.trace()).abs() <= 1e3 * EPS * norm * n as f64);
            prop_assert!(sum.im.abs() <= 1e3 * EPS * norm * n as f64);
            if n <= 20 {
                for l in &ev {
                    let m = a.map(|v| Complex64::new(v, 0.0)) - DMatrix::<Complex64>::identity(n, n) * *l;
                    let smin = m.singular_values().min();
                    prop_assert!(smin <= 1e4 * EPS * norm, "n = {}, λ = {}, σ_min = {:e}", n, l, smin);
                }
            }
        }

        /// The Routh count equals the number of ORHP roots (§15.17).
        #[test]
        fn routh_count_equals_rhp_roots(roots in roots_strategy()) {
            let p = Polynomial::from_roots(&roots).unwrap();
            let ra = routh(&p).unwrap();
            let rhp = roots.iter().filter(|r| r.re > 0.0).count();
            prop_assert_eq!(ra.rhp, rhp);
            prop_assert_eq!(ra.imaginary, 0);
        }

        /// ss → tf → ss keeps the frequency response (15.14.5).
        #[test]
        fn ss_to_tf_to_ss_keeps_frequency_response(
            a in proptest::collection::vec(-3.0..3.0f64, 16),
            b in proptest::collection::vec(-2.0..2.0f64, 4),
            c in proptest::collection::vec(-2.0..2.0f64, 4),
            d in -1.0..1.0f64,
        ) {
            let sys = StateSpace::new(
                DMatrix::from_row_slice(4, 4, &a),
                DMatrix::from_column_slice(4, 1, &b),
                DMatrix::from_row_slice(1, 4, &c),
                DMatrix::from_element(1, 1, d),
            ).unwrap();
            let g = sys.to_tf(0, 0).unwrap();
            let back = StateSpace::from_tf(&g).unwrap().to_tf(0, 0).unwrap();
            for w in [0.05, 0.7, 3.0, 40.0] {
                let s = Complex64::new(0.0, w);
                // Direct evaluation C(sI − A)⁻¹B + D as the reference.
                let m = DMatrix::from_fn(4, 4, |i, j| if i == j { s } else { Complex64::new(0.0, 0.0) })
                    - sys.a().map(|x| Complex64::new(x, 0.0));
                let Some(inv) = m.try_inverse() else { continue };
                let want = (sys.c().map(|x| Complex64::new(x, 0.0)) * inv * sys.b().map(|x| Complex64::new(x, 0.0)))[(0, 0)] + d;
                let cond = want.norm().max(1.0);
                prop_assert!((g.eval(s) - want).norm() <= 1e-8 * cond, "tf {} vs {}", g.eval(s), want);
                prop_assert!((back.eval(s) - want).norm() <= 1e-8 * cond);
            }
        }

        /// e^{A}e^{−A} = I and e^{A(t₁+t₂)} = e^{At₁}e^{At₂}.
        #[test]
        fn expm_group_property(a in proptest::collection::vec(-2.0..2.0f64, 9), t1 in 0.0..2.0f64, t2 in 0.0..2.0f64) {
            let a = DMatrix::from_row_slice(3, 3, &a);
            let lhs = expm(&(&a * (t1 + t2))).unwrap();
            let rhs = expm(&(&a * t1)).unwrap() * expm(&(&a * t2)).unwrap();
            prop_assert!((&lhs - &rhs).amax() <= 1e-12 * lhs.amax().max(1.0) * 1e3);
        }
    }
}
