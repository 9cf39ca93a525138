//! §15.7, §15.14: state-space form, transfer functions of state-space models, minimal
//! realisations, interconnections, pole placement and equilibria; problems 15.20.8, 15.20.14,
//! 15.20.37–38, 15.20.42, 15.20.52, 15.20.54–56, 15.20.58.

use super::*;
use crate::support::NanAmax;
use nalgebra::dmatrix;

#[test]
fn problem_15_20_52_boeing_747_channel_zeros() {
    // 15.20.52 (computed in the notes): common denominator s⁴ + 0.6358s³ + 0.9389s² + 0.5116s
    // + 0.00367; zeros r/δr: −0.4981, −0.0119 ± 0.4878j; r/δa: 0.2509 ± 1.1307j, −0.4357;
    // φ/δr: 4.4398, −2.6940; φ/δa: −0.0954 ± 0.8723j.
    let sys = b747();
    let g = sys.to_tf(0, 0).unwrap();
    let den = g.den().monic().unwrap();
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
    // the cancelled pair is accurate to ~√ε, so the survivors carry ~1e-13 relative error
    assert_rel(g.num().coeff(0) / g.den().coeff(1), 0.0203, 1e3 * EPS);
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
fn eq_15_7_3_companion_form() {
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
fn eq_15_18_4_interconnections_series_parallel_feedback() {
    // Series, parallel and unity feedback (15.18.4) agree between tf and state space.
    let g1 = tf(&[1.0, 2.0], &[1.0, 3.0, 5.0]);
    let g2 = tf(&[4.0], &[1.0, 1.0]);
    let (s1, s2) = (StateSpace::from_tf(&g1).unwrap(), StateSpace::from_tf(&g2).unwrap());
    let cases = [
        (g1.series(&g2).unwrap(), s1.series(&s2).unwrap()),
        (g1.parallel(&g2).unwrap(), s1.parallel(&s2).unwrap()),
        (g1.feedback(&TransferFunction::gain(1.0).unwrap()).unwrap(), s1.unity_feedback().unwrap()),
    ];
    for (g, s) in cases {
        let gs = s.to_tf(0, 0).unwrap();
        for w in [0.0, 0.3, 2.0, 30.0] {
            let z = Complex64::new(0.0, w);
            // relative for |G| ≥ 1, absolute below (the values are O(1))
            assert!((g.eval(z) - gs.eval(z)).norm() <= 1e3 * EPS * g.eval(z).norm().max(1.0));
        }
    }
}

#[test]
fn problem_15_20_54_pole_placement_by_ackermann() {
    // 15.20.54 (Matlab `place`, one input): K places the eigenvalues of A − bK. For the damped
    // oscillator in companion coordinates the gain is the closed form k₁ = mωn² − k,
    // k₂ = 2mζωn − c (from s² + (c + k₂)/m·s + (k + k₁)/m = s² + 2ζωn s + ωn²).
    let (m, c, k) = (2.0, 0.6, 5.0);
    let sys = Sdof::new(m, c, k).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let (wn, zeta) = (3.0f64, 0.7f64);
    let wd = wn * (1.0 - zeta * zeta).sqrt();
    let gain = sys.place(0, &[Complex64::new(-zeta * wn, wd), Complex64::new(-zeta * wn, -wd)]).unwrap();
    assert_rel(gain[(0, 0)], m * wn * wn - k, 16.0 * EPS);
    assert_rel(gain[(0, 1)], 2.0 * m * zeta * wn - c, 16.0 * EPS);
    // The 747 lateral model (15.20.51; the problem cites 15.20.49, the notes read 15.20.51 as in
    // 15.20.53) with the rudder alone: the closed-loop eigenvalues (by nalgebra's Schur form,
    // independent of the crate's QR) are the requested ones.
    let plane = b747();
    let want = [
        Complex64::new(-0.5, 0.9),
        Complex64::new(-0.5, -0.9),
        Complex64::new(-0.8, 0.0),
        Complex64::new(-1.2, 0.0),
    ];
    let kg = plane.place(0, &want).unwrap();
    let b0 = plane.b().column(0).into_owned();
    let closed = plane.a() - &b0 * &kg;
    let mut got: Vec<Complex64> = closed.complex_eigenvalues().iter().copied().collect();
    got = sorted(got);
    for (g, w) in got.iter().zip(sorted(want.to_vec())) {
        // 𝒞 of the 747 has condition ≈ 10³: the placed poles carry ~10³·ε·‖A‖ error
        assert!((g - w).norm() <= 1e-10, "{g} vs {w}");
    }
    // an uncontrollable pair is a typed error: the URB with B = [1, 0]ᵀ cannot move q̇
    let urb =
        StateSpace::from_rows(&[&[0.0, 1.0], &[0.0, 0.0]], &[&[1.0], &[0.0]], &[&[1.0, 0.0]], &[&[0.0]])
            .unwrap();
    assert!(matches!(
        urb.place(0, &want[2..]),
        Err(LtiError::InvalidArgument { what: "pole placement", .. })
    ));
    assert!(matches!(sys.place(0, &want[..1]), Err(LtiError::DimensionMismatch { .. })));
    assert!(matches!(sys.place(0, &[want[0], want[2]]), Err(LtiError::UnpairedComplexRoot { .. })));
}

#[test]
fn problem_15_20_55_equilibria_with_constant_input() {
    // 15.20.55: all (x̄, ū) with Ax̄ + Bū = 0. i) URB (q, q̇): constant position, zero velocity,
    // zero force; ii) URB (q̇ only): any constant velocity with zero force; iii) DRB (q, q̇):
    // constant position, zero force; iv) DRB (q̇ only): constant velocity v̄ held by ū = c v̄;
    // v) DO (q, q̇): constant position q̄ held by the force ū = k q̄. One independent equilibrium
    // each; the basis vector (x̄, ū) is checked up to its sign and scale.
    let (m, c, k) = (2.0, 0.6, 5.0);
    let one = |a: DMatrix<f64>, b: DMatrix<f64>| {
        let n = a.nrows();
        StateSpace::new(a, b, DMatrix::identity(n, n), DMatrix::zeros(n, 1)).unwrap()
    };
    let cases: [(StateSpace, Vec<f64>); 5] = [
        (one(dmatrix![0.0, 1.0; 0.0, 0.0], dmatrix![0.0; 1.0 / m]), vec![1.0, 0.0, 0.0]),
        (one(dmatrix![0.0], dmatrix![1.0 / m]), vec![1.0, 0.0]),
        (one(dmatrix![0.0, 1.0; 0.0, -c / m], dmatrix![0.0; 1.0 / m]), vec![1.0, 0.0, 0.0]),
        (one(dmatrix![-c / m], dmatrix![1.0 / m]), vec![1.0, c]),
        (one(dmatrix![0.0, 1.0; -k / m, -c / m], dmatrix![0.0; 1.0 / m]), vec![1.0, 0.0, k]),
    ];
    for (i, (sys, dir)) in cases.iter().enumerate() {
        let e = sys.equilibria(1e-12).unwrap();
        assert_eq!(e.ncols(), 1, "case {}", i + 1);
        let v = e.column(0);
        let want = nalgebra::DVector::from_column_slice(dir).normalize();
        // |cos| of the angle between the basis vector and the expected direction
        assert_abs(v.dot(&want).abs(), 1.0, 16.0 * EPS);
        // and it is an equilibrium: A x̄ + B ū = 0
        let n = sys.n_states();
        let r = sys.a() * v.rows(0, n) + sys.b() * v.rows(n, 1);
        assert!(r.nan_amax() <= 16.0 * EPS, "case {}: residual {r}", i + 1);
    }
}

#[test]
fn problem_15_20_8_affine_equilibria() {
    // 15.20.8: ẋ = ax + b settles at x̄ = −b/a when a < 0 (15.20.9: a = −2, b = 8 → 4). An
    // affine system ẋ = Ax + b has one equilibrium when A is nonsingular, none when b leaves the
    // range of A (a = 0, b ≠ 0: x drifts), and a family when b is in the range of a singular A.
    let AffineEquilibria::Unique(x) = affine_equilibria(&dmatrix![-2.0], &[8.0], 1e-12).unwrap() else {
        panic!("unique")
    };
    assert_rel(x[0], 4.0, 4.0 * EPS);
    assert_eq!(affine_equilibria(&dmatrix![0.0], &[1.0], 1e-12).unwrap(), AffineEquilibria::None);
    // the DRB with position in the state, pushed by a constant force f: v̇ = −(c/m)v + f/m
    // settles at v = f/c while q keeps growing — no equilibrium
    let (m, c, f) = (2.0, 0.5, 3.0);
    assert_eq!(
        affine_equilibria(&dmatrix![0.0, 1.0; 0.0, -c / m], &[0.0, f / m], 1e-12).unwrap(),
        AffineEquilibria::None
    );
    // b in the range of a singular A: A = [[1, 1], [2, 2]], b = [−2, −4]: x₁ + x₂ = 2
    let AffineEquilibria::Family { particular, directions } =
        affine_equilibria(&dmatrix![1.0, 1.0; 2.0, 2.0], &[-2.0, -4.0], 1e-12).unwrap()
    else {
        panic!("family")
    };
    assert_abs(particular[0] + particular[1], 2.0, 16.0 * EPS);
    assert_eq!(directions.ncols(), 1);
    assert_abs(directions[(0, 0)] + directions[(1, 0)], 0.0, 16.0 * EPS);
}

#[test]
fn example_15_7_1_damped_oscillator_state_space() {
    // Ex 15.7.1, (15.7.6): q̈ = −(c/m)q̇ − (k/m)q + f/m with x = (q, q̇) and position output:
    // A = [[0, 1], [−k/m, −c/m]], B = [0, 1/m]ᵀ, C = [1, 0], D = 0; its transfer function is
    // 1/(ms² + cs + k).
    let (m, c, k) = (7.0, 1.5, 2.5);
    let sys = Sdof::new(m, c, k).unwrap().to_state_space(SdofOutput::Position).unwrap();
    assert_eq!(sys.a(), &dmatrix![0.0, 1.0; -k / m, -c / m]);
    assert_eq!(sys.b(), &dmatrix![0.0; 1.0 / m]);
    assert_eq!(sys.c(), &dmatrix![1.0, 0.0]);
    assert_eq!(sys.d(), &dmatrix![0.0]);
    let g = sys.to_tf(0, 0).unwrap();
    let want = tf(&[1.0], &[m, c, k]);
    for w in [0.0, 0.2, 0.6, 5.0] {
        let s = Complex64::new(0.0, w);
        // relative to |G(jω)| ≤ 1/(c ωn) ~ 1: a 2 × 2 resolvent, tens of roundings
        assert!((g.eval(s) - want.eval(s)).norm() <= 64.0 * EPS * want.eval(s).norm(), "ω = {w}");
    }
}

#[test]
fn example_15_14_1_velocity_output_transfer_function() {
    // Ex 15.14.1: the damped oscillator with velocity output, C = [0, 1]:
    // G = C(sI − A)⁻¹B = s/(ms² + cs + k); every pole of G is an eigenvalue of A.
    let (m, c, k) = (2.0, 0.6, 5.0);
    let sys = Sdof::new(m, c, k).unwrap().to_state_space(SdofOutput::Velocity).unwrap();
    assert_eq!(sys.c(), &dmatrix![0.0, 1.0]);
    let g = sys.to_tf(0, 0).unwrap();
    // normalise by the leading denominator coefficient: want (s/m)/(s² + (c/m)s + k/m)
    let (n, d) = (g.num().coeffs(), g.den().coeffs());
    let lead = d[0];
    assert_eq!(g.num().degree(), 1);
    assert_rel(n[0] / lead, 1.0 / m, 16.0 * EPS);
    assert_abs(n[1] / lead, 0.0, 16.0 * EPS / m); // the zero at s = 0, exactly or to rounding
    assert_rel(d[1] / lead, c / m, 16.0 * EPS);
    assert_rel(d[2] / lead, k / m, 16.0 * EPS);
    let ev = sorted(linalg::eigenvalues(sys.a()).unwrap());
    for (p, e) in sorted(g.poles().unwrap()).iter().zip(&ev) {
        assert!((p - e).norm() <= 64.0 * EPS * e.norm(), "pole {p} vs eigenvalue {e}");
    }
}

#[test]
fn problem_15_20_56_controllability_and_observability_of_sdof_models() {
    // 15.20.56, state (q, q̇): [B AB] = [[0, 1/m], [1/m, −c/m²]] has rank 2 for URB, DRB, UO, DO
    // (i); position output, [C; CA] = [[1, 0], [0, 1]]: always observable (ii); velocity output,
    // [C; CA] = [[0, 1], [−k/m, −c/m]]: observable iff k ≠ 0, so not for URB and DRB (iii).
    let m = 2.0;
    for (name, c, k) in [("URB", 0.0, 0.0), ("DRB", 3.0, 0.0), ("UO", 0.0, 5.0), ("DO", 3.0, 5.0)] {
        let s = Sdof::new(m, c, k).unwrap();
        let pos = s.to_state_space(SdofOutput::Position).unwrap();
        let vel = s.to_state_space(SdofOutput::Velocity).unwrap();
        assert_eq!(pos.ctrb(), dmatrix![0.0, 1.0 / m; 1.0 / m, -c / (m * m)], "{name}");
        assert!(pos.is_controllable(1e-10).unwrap(), "{name} controllable");
        assert_eq!(pos.obsv(), dmatrix![1.0, 0.0; 0.0, 1.0], "{name}");
        assert!(pos.is_observable(1e-10).unwrap(), "{name} position-observable");
        assert_eq!(vel.obsv(), dmatrix![0.0, 1.0; -k / m, -c / m], "{name}");
        assert_eq!(vel.is_observable(1e-10).unwrap(), k != 0.0, "{name} velocity-observable");
    }
}

/// The cascade of 15.20.58 in state space, x = (x₁ of G₁ = 1/(s + p); x₂ of G₂ = (s + p)/(s + 2)²
/// in companion form). `g1_first`: G₁ forced by a·u, G₂ forced by y₁ + d·u; otherwise G₂ forced
/// by a·u and G₁ by y₂ + d·u. Outputs (y₁, y₂); u is a unit step.
fn cascade_15_20_58(p: f64, a: f64, d: f64, g1_first: bool) -> StateSpace {
    let (c2a, c2b) = (p, 1.0); // C₂ = [p, 1]: numerator s + p
    let (am, b) = if g1_first {
        (dmatrix![-p, 0.0, 0.0; 0.0, 0.0, 1.0; 1.0, -4.0, -4.0], dmatrix![a; 0.0; d])
    } else {
        (dmatrix![-p, c2a, c2b; 0.0, 0.0, 1.0; 0.0, -4.0, -4.0], dmatrix![d; 0.0; a])
    };
    let c = dmatrix![1.0, 0.0, 0.0; 0.0, c2a, c2b];
    StateSpace::new(am, b, c, DMatrix::zeros(2, 1)).unwrap()
}

#[test]
fn problem_15_20_58_pole_zero_cancellation_in_a_cascade() {
    // 15.20.58: G₁ = 1/(s + p) then G₂ = (s + p)/(s + 2)², p = 1, 0, −1 (stable, zero, unstable
    // cancellation), nonzero initial states, constant input a into G₁ and constant disturbance d
    // on y₁. By Laplace, with the free response of G₂ written F₂(s) = ((p(s + 4) − 4)x₂ₐ +
    // (s + p)x₂ᵦ)/(s + 2)²:
    //   ŷ₁ = (x₁₀ + a/s)/(s + p),
    //   ŷ₂ = F₂ + (x₁₀ + a/s)/(s + 2)² + d(s + p)/(s(s + 2)²),
    // so the mode e^{−pt} of G₁ never reaches y₂, and y₂ → (a + pd)/4 in every case, while y₁
    // diverges for p ≤ 0. Reversed (G₂ first, input a; d on y₂):
    //   ŷ₁ = (x₁₀ + F₂ + d/s)/(s + p) + a/(s(s + 2)²),
    // which diverges for p = −1 unless the residue x₁₀ + F₂(1) + d vanishes.
    let (a, d) = (1.5, -0.5);
    let (x10, x2a, x2b) = (0.4, -0.3, 0.8);
    let t = time_grid(10.0, 101).unwrap();
    for p in [1.0, 0.0, -1.0] {
        // G₁ first: the simulated y₂ against the inverse transform.
        let sys = cascade_15_20_58(p, a, d, true);
        let r = lsim(&sys, 0, &vec![1.0; t.len()], &t, &[x10, x2a, x2b], Hold::Zoh, 0.0).unwrap();
        let num = [p * x2a + x2b, (4.0 * p - 4.0) * x2a + p * x2b + x10 + d, a + d * p];
        let y2_hat = tf(&num, &[1.0, 4.0, 4.0, 0.0]);
        let y2 = y2_hat.inverse_laplace(CLUSTER_RTOL).unwrap();
        assert_eq!(y2_hat.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite((a + p * d) / 4.0));
        for (k, &tk) in t.iter().enumerate() {
            // The simulated cancellation is exact only to rounding: for p = −1 the state carries
            // e^{t} and y₂ = C₂x₂ cancels it, leaving an error ~ε·e^{t} (the point of 15.20.59).
            let growth = (-p * tk).exp().max(1.0);
            assert_abs(r.y[1][k], y2.eval(tk), 1e3 * EPS * growth);
        }
        let y1_end = r.y[0][t.len() - 1];
        // y₁ by hand: (x₁₀ − a)e^{−t} + a, x₁₀ + at, (x₁₀ + a)eᵗ − a
        if p == 1.0 {
            assert_abs(y1_end, a + (x10 - a) * (-10.0f64).exp(), 1e3 * EPS);
        } else if p == 0.0 {
            assert_rel(y1_end, x10 + a * 10.0, 1e3 * EPS);
        } else {
            assert_rel(y1_end, (x10 + a) * 10f64.exp() - a, 1e3 * EPS);
        }
        // Reversed: the residue of ŷ₁ at the cancelled pole −p is x₁₀ + F₂(−p) + d/(−p) (p ≠ 0).
        let sys = cascade_15_20_58(p, a, d, false);
        let r = lsim(&sys, 0, &vec![1.0; t.len()], &t, &[x10, x2a, x2b], Hold::Zoh, 0.0).unwrap();
        if p == -1.0 {
            let f2 = ((p * (1.0 + 4.0) - 4.0) * x2a + (1.0 + p) * x2b) / 9.0;
            let residue = x10 + f2 + d;
            // y₁(t)e^{−t} → residue; at t = 10 the bounded rest of y₁ (size ~1) contributes
            // O(e^{−10}) ≈ 5e-5
            assert_abs(r.y[0][t.len() - 1] * (-10.0f64).exp(), residue, 1e-3);
            assert!(residue.abs() > 0.1, "generic initial states excite the unstable mode");
        }
        if p == 1.0 {
            // everything stable: y₁ → a/4 + d, up to transients O(t e^{−t}) ≈ 5e-4 at t = 10
            assert_abs(r.y[0][t.len() - 1], a / 4.0 + d, 1e-3);
        }
    }
}
