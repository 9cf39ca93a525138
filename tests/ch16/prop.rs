//! Property tests of chapter 16: phase branches, factored and coefficient frequency responses,
//! margins under time scaling.

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

    /// The transfer function's G(jω) from its coefficients agrees with the factored form on
    /// random systems; the gap is the roots' own rounding and the coefficients' conditioning
    /// (well-separated roots here: ≤ 1e-10 relative).
    #[test]
    fn tf_freqresp_agrees_with_factored_form(
        zeros in proptest::collection::vec(root(), 0..3),
        poles in proptest::collection::vec(root(), 1..5),
        k in prop_oneof![-3.0..-0.1f64, 0.1..3.0f64],
    ) {
        let zeros: Vec<Complex64> = zeros.into_iter().flatten().collect();
        let poles: Vec<Complex64> = poles.into_iter().flatten().collect();
        let g = Zpk::new(zeros, poles.clone(), k).unwrap().to_tf().unwrap();
        let w = logspace(-3.0, 3.0, 301).unwrap();
        let fast = g.freqresp(&w).unwrap();
        let slow = g.to_zpk().unwrap().freqresp(&w).unwrap();
        for ((a, b), &wi) in fast.iter().zip(&slow).zip(&w) {
            // within 10⁻⁶|p| of a pole on the axis (p = ±0.1j against the grid's ω ≈ 0.1) the
            // roots' own rounding δ moves G by δ/|jω − p| relative: no longer a test of the two
            // evaluations
            let near_pole = poles.iter().any(|p| (Complex64::new(0.0, wi) - p).norm() <= 1e-6 * p.norm());
            if !b.norm().is_finite() || near_pole {
                continue;
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
        let mut den = poly(&[1.0, p[0]]).mul(&poly(&[1.0, p[1]])).unwrap().mul(&poly(&[1.0, p[2]])).unwrap();
        if integrator {
            den = den.mul(&Polynomial::s()).unwrap();
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
