//! Property tests of chapter 15: eigenvalues, Routh counts, ss ↔ tf, the matrix exponential.

use super::*;
use crate::support::NanAmax;
use proptest::prelude::*;

/// Monic polynomials from roots kept off the imaginary axis by at least 0.05, biased to
/// repeated and nearly repeated roots.
fn roots_strategy() -> impl Strategy<Value = Vec<Complex64>> {
    let re = prop_oneof![-5.0..-0.05f64, 0.05..5.0f64];
    let one = (re.clone(), 0.0..4.0f64, proptest::bool::ANY).prop_map(|(r, i, complex)| {
        if complex { vec![Complex64::new(r, i), Complex64::new(r, -i)] } else { vec![Complex64::new(r, 0.0)] }
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
        prop_assert!((&lhs - &rhs).nan_amax() <= 1e-12 * lhs.nan_amax().max(1.0) * 1e3);
    }
}
