//! The same bits before and after the issue-38 split of the Hessenberg QR (`hqr`: deflation
//! search, shift and QR sweep as their own functions): the split moved arithmetic between
//! functions without changing one operation, so its eigenvalues (and the polynomial roots that
//! go through it) are pinned to the bits the code gave before the split (`f64::to_bits`, in
//! hex), as well as checked against their closed forms. The QR uses only +, −, ×, ÷ and √
//! (correctly rounded, no fused multiply–add, no run-time dispatch), so these bits are the same
//! on every machine. The pinned values are what commit 307870e computed.
//!
//! The margins (split into search and selection) and `lsim` (split by step) are checked here
//! against closed forms; their results go through libm's transcendental functions and faer's
//! run-time-dispatched products, whose last bit is the platform's, so they are not pinned.

use nalgebra::DMatrix;
use vectrix_lti::{Complex64, Polynomial, TransferFunction, linalg};

/// The test matrices (row-major), shared by the generator and the test.
fn cases() -> Vec<(&'static str, usize, Vec<f64>)> {
    let mut v = Vec::new();
    // companion matrix (15.7.3) of (s − 1)(s − 2)(s − 3) = s³ − 6s² + 11s − 6
    v.push(("companion_123", 3, vec![6.0, -11.0, 6.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]));
    // the cyclic shift: eigenvalues the 4th roots of unity; Francis' shift stalls on it, so the
    // exceptional shifts of iterations 10 and 20 run
    let mut p = vec![0.0; 16];
    for i in 0..4 {
        p[((i + 1) % 4) * 4 + i] = 1.0;
    }
    v.push(("cyclic_4", 4, p));
    // tridiag(1, 2, 1), n = 8: λₖ = 2 + 2cos(kπ/9)
    let n = 8;
    let mut t = vec![0.0; n * n];
    for i in 0..n {
        t[i * n + i] = 2.0;
        if i + 1 < n {
            t[i * n + i + 1] = 1.0;
            t[(i + 1) * n + i] = 1.0;
        }
    }
    v.push(("tridiag_8", n, t));
    // Grcar matrix, n = 12 (non-normal, complex spectrum; trace 12)
    let n = 12;
    let mut g = vec![0.0; n * n];
    for i in 0..n {
        for j in i..(i + 4).min(n) {
            g[i * n + j] = 1.0;
        }
        if i + 1 < n {
            g[(i + 1) * n + i] = -1.0;
        }
    }
    v.push(("grcar_12", n, g));
    // a dense 30×30 matrix from a fixed linear congruential sequence in [−1, 1)
    let n = 30;
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut d = vec![0.0; n * n];
    for x in d.iter_mut() {
        state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        *x = (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
    }
    v.push(("lcg_30", n, d));
    v
}

/// The loops whose margins are pinned: name, numerator, denominator, delay.
fn loops() -> Vec<(&'static str, Vec<f64>, Vec<f64>, f64)> {
    vec![
        // 10/(s(s + 1)(s + 5)): phase crossover at ω = √5 with GM = 3
        ("type1_cubic", vec![10.0], vec![1.0, 6.0, 5.0, 0.0], 0.0),
        // 2e^{−0.1s}/(s + 1): gain crossover at ω = √3
        ("delayed_lag", vec![2.0], vec![1.0, 1.0], 0.1),
        // (s² + 1)(s + 3)/((s + 1)(s + 2)(s² + 0.2s + 4)): an axis zero and a resonance
        ("axis_zero", vec![1.0, 3.0, 1.0, 3.0], vec![1.0, 3.2, 6.6, 12.4, 8.0], 0.0),
    ]
}

/// ẋ = −x + u, y = x sampled at h = 0.1 on [0, 2] with the ramp u = t held first-order and
/// delayed by 0.25 s (two and a half steps: every step is split).
fn lsim_ramp() -> vectrix_lti::TimeResponse {
    use nalgebra::DMatrix;
    let sys = vectrix_lti::StateSpace::new(
        DMatrix::from_element(1, 1, -1.0),
        DMatrix::from_element(1, 1, 1.0),
        DMatrix::from_element(1, 1, 1.0),
        DMatrix::from_element(1, 1, 0.0),
    )
    .unwrap();
    let t: Vec<f64> = (0..=20).map(|k| k as f64 * 0.1).collect();
    vectrix_lti::lsim(&sys, 0, &t, &t, &[0.0], vectrix_lti::Hold::Foh, 0.25).unwrap()
}

const EPS: f64 = f64::EPSILON;

/// Exact bit patterns of (re, im) for each eigenvalue, in the order returned.
fn bits(z: &[Complex64]) -> Vec<[u64; 2]> {
    z.iter().map(|z| [z.re.to_bits(), z.im.to_bits()]).collect()
}

/// Every expected value has its own computed value within tol, in any order (fails on NaN:
/// a NaN is within no tolerance).
fn assert_close(name: &str, got: &[Complex64], want: &[Complex64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{name}: {got:?}");
    let mut left: Vec<Complex64> = got.to_vec();
    for w in want {
        let i = left.iter().position(|g| (g - w).norm() <= tol);
        assert!(i.is_some(), "{name}: nothing within {tol:e} of {w}\n{got:?}");
        left.remove(i.unwrap_or(0));
    }
}

fn eig(name: &str) -> Vec<Complex64> {
    let (_, n, a) = cases().into_iter().find(|c| c.0 == name).expect("case");
    linalg::eigenvalues(&DMatrix::from_row_slice(n, n, &a)).expect("eigenvalues")
}

/// Bits of the eigenvalues before the split, per case, in the order returned.
const EIG_BITS: [(&str, &[[u64; 2]]); 5] = [
    (
        "companion_123",
        &[
            [0x4007fffffffffffc, 0x0000000000000000],
            [0x4000000000000001, 0x0000000000000000],
            [0x3ff0000000000004, 0x0000000000000000],
        ],
    ),
    (
        "cyclic_4",
        &[
            [0x3fefffffffffffff, 0x0000000000000000],
            [0xbcb0000000000000, 0x3feffffffffffff8],
            [0xbcb0000000000000, 0xbfeffffffffffff8],
            [0xbff0000000000000, 0x0000000000000000],
        ],
    ),
    (
        "tridiag_8",
        &[
            [0x400f08fb2129168e, 0x0000000000000000],
            [0x400c41b7d167a820, 0x0000000000000000],
            [0x4007ffffffffffff, 0x0000000000000000],
            [0x4002c7434fc16e72, 0x0000000000000000],
            [0x3ffa7179607d231f, 0x0000000000000000],
            [0x3feffffffffffffe, 0x0000000000000000],
            [0x3fddf24174c2bf1c, 0x0000000000000000],
            [0x3fbee09bdadd2dc0, 0x0000000000000000],
        ],
    ),
    (
        "grcar_12",
        &[
            [0x3ff967b7b07c1eca, 0x3feec7b6746035f7],
            [0x3ff967b7b07c1eca, 0xbfeec7b6746035f7],
            [0x3ff8a24633a5740c, 0x3fd63f24e2c6555e],
            [0x3ff8a24633a5740c, 0xbfd63f24e2c6555e],
            [0x3ff687bcefe3761d, 0x3ff21cb6fbb64f2a],
            [0x3ff687bcefe3761d, 0xbff21cb6fbb64f2a],
            [0x3febae1530b85da4, 0x3ff7f6341d896d5a],
            [0x3febae1530b85da4, 0xbff7f6341d896d5a],
            [0x3fdbe064c61b9fb8, 0x3ffe4290a4eeccef],
            [0x3fdbe064c61b9fb8, 0xbffe4290a4eeccef],
            [0x3fc4f90b10bf0297, 0x40015439d6c9972d],
            [0x3fc4f90b10bf0297, 0xc0015439d6c9972d],
        ],
    ),
    (
        "lcg_30",
        &[
            [0x400cc01c4b4d2de4, 0x0000000000000000],
            [0x40030b7bccb9c141, 0x3ff5624d37923e65],
            [0x40030b7bccb9c141, 0xbff5624d37923e65],
            [0x4001209067f8c2b4, 0x3fdb7fe38fef1718],
            [0x4001209067f8c2b4, 0xbfdb7fe38fef1718],
            [0x3ff826f0d1002ee2, 0x40002b83b87f71a1],
            [0x3ff826f0d1002ee2, 0xc0002b83b87f71a1],
            [0x3ff7d5f27abf1678, 0x3fe651d482a34687],
            [0x3ff7d5f27abf1678, 0xbfe651d482a34687],
            [0x3ff20d04ad413b2a, 0x0000000000000000],
            [0x3ff17736f20a16a7, 0x3ffbc935c2dc7c15],
            [0x3ff17736f20a16a7, 0xbffbc935c2dc7c15],
            [0x3fdd8ce726aef9e3, 0x4002335d40ea0960],
            [0x3fdd8ce726aef9e3, 0xc002335d40ea0960],
            [0x3fcf79cf0e2702c4, 0x3feabf58f6e8d050],
            [0x3fcf79cf0e2702c4, 0xbfeabf58f6e8d050],
            [0xbfccfbb7ed717d04, 0x4006a27a00962318],
            [0xbfccfbb7ed717d04, 0xc006a27a00962318],
            [0xbfdfbb1e45fc1682, 0x0000000000000000],
            [0xbfed603d08a7ca21, 0x40001310e04daaaa],
            [0xbfed603d08a7ca21, 0xc0001310e04daaaa],
            [0xbff1319a571a0c74, 0x3fe357005ea88f77],
            [0xbff1319a571a0c74, 0xbfe357005ea88f77],
            [0xbff9afd8e19e748b, 0x3ff92ae6faae4e0f],
            [0xbff9afd8e19e748b, 0xbff92ae6faae4e0f],
            [0xc0000b46e99f18f8, 0x3fe0539767c0e4ad],
            [0xc0000b46e99f18f8, 0xbfe0539767c0e4ad],
            [0xc003ec75d97a49a4, 0x0000000000000000],
            [0xc00833683dff4de4, 0x3fe41b3f7c3ab022],
            [0xc00833683dff4de4, 0xbfe41b3f7c3ab022],
        ],
    ),
];

#[test]
fn hqr_eigenvalues_keep_their_bits() {
    for (name, want) in EIG_BITS {
        assert_eq!(bits(&eig(name)), want, "{name}: the eigenvalues changed bits");
    }
}

/// The closed forms of the pinned cases, to a few ε times the spectrum's scale.
#[test]
fn hqr_eigenvalues_match_closed_forms() {
    let c = |re: f64, im: f64| Complex64::new(re, im);
    assert_close(
        "companion_123",
        &eig("companion_123"),
        &[c(1.0, 0.0), c(2.0, 0.0), c(3.0, 0.0)],
        64.0 * EPS * 3.0,
    );
    let roots4 = [c(-1.0, 0.0), c(0.0, -1.0), c(0.0, 1.0), c(1.0, 0.0)];
    assert_close("cyclic_4", &eig("cyclic_4"), &roots4, 64.0 * EPS);
    let tri: Vec<Complex64> =
        (1..=8).map(|k| c(2.0 + 2.0 * (k as f64 * std::f64::consts::PI / 9.0).cos(), 0.0)).collect();
    assert_close("tridiag_8", &eig("tridiag_8"), &tri, 64.0 * EPS * 4.0);
    // no closed form for the spectra of Grcar and the random matrix: their sum is the trace
    for (name, n, a) in cases().into_iter().filter(|c| c.0 == "grcar_12" || c.0 == "lcg_30") {
        let ev = eig(name);
        let trace: f64 = (0..n).map(|i| a[i * n + i]).sum();
        let sum: Complex64 = ev.iter().sum();
        let scale: f64 = ev.iter().map(|z| z.norm()).sum();
        assert_eq!(ev.len(), n, "{name}");
        assert!((sum - c(trace, 0.0)).norm() <= 64.0 * EPS * scale, "{name}: Σλ = {sum} vs trace {trace}");
    }
}

/// Polynomial roots go through the same QR (the companion matrix is already Hessenberg).
#[test]
fn polynomial_roots_keep_their_bits_and_closed_form() {
    let r = Polynomial::new(&[1.0, 3.0, 8.0, 8.0, 7.0, 5.0]).unwrap().roots().unwrap();
    assert_eq!(bits(&r), POLY5_BITS, "the roots changed bits");
    // (s² + 2s + 5)(s + 1)(s² + 1)
    let c = |re: f64, im: f64| Complex64::new(re, im);
    let want = [c(-1.0, -2.0), c(-1.0, 0.0), c(-1.0, 2.0), c(0.0, -1.0), c(0.0, 1.0)];
    assert_close("poly5", &r, &want, 64.0 * EPS * 5.0);
}

/// Root bits of s⁵ + 3s⁴ + 8s³ + 8s² + 7s + 5 before the split.
const POLY5_BITS: &[[u64; 2]] = &[
    [0xbc4af33333333d93, 0x3ff0000000000000],
    [0xbc4af33333333d93, 0xbff0000000000000],
    [0xbfeffffffffffffe, 0x0000000000000000],
    [0xbff0000000000001, 0x3fffffffffffffff],
    [0xbff0000000000001, 0xbfffffffffffffff],
];

fn margins(name: &str) -> vectrix_lti::Margins {
    let (_, n, d, tau) = loops().into_iter().find(|l| l.0 == name).expect("loop");
    TransferFunction::new(&n, &d).unwrap().with_delay(tau).unwrap().margins().unwrap()
}

/// The closed forms: GM = 3 at ω = √5 for 10/(s(s + 1)(s + 5)); for 2e^{−0.1s}/(s + 1) the
/// gain crossover ω = √3 with PM = 180° − 60° − 0.1√3 rad; the axis zero at ω = 1 of
/// (s² + 1)(s + 3)/… is a phase crossover with GM = ∞.
#[test]
fn margins_match_closed_forms() {
    let m = margins("type1_cubic");
    let gm = m.gain_margin().expect("a gain margin");
    assert!((gm.omega - 5f64.sqrt()).abs() <= 16.0 * EPS * 5f64.sqrt(), "{gm:?}");
    assert!((gm.gain_margin - 3.0).abs() <= 64.0 * EPS * 3.0, "{gm:?}");
    let m = margins("delayed_lag");
    let pm = m.phase_margin().expect("a phase margin");
    let w = 3f64.sqrt();
    assert!((pm.omega - w).abs() <= 16.0 * EPS * w, "{pm:?}");
    let want = 120.0 - (0.1 * w).to_degrees();
    assert!((pm.phase_margin_deg - want).abs() <= 1e3 * EPS * 180.0, "{pm:?} vs {want}");
    let m = margins("axis_zero");
    let zero = m.phase_crossovers.iter().find(|c| (c.omega - 1.0).abs() <= 1e3 * EPS).expect("ω = 1");
    assert_eq!(zero.gain_margin, f64::INFINITY, "{zero:?}");
}

#[test]
fn lsim_ramp_through_a_fractional_delay_matches_closed_form() {
    let r = lsim_ramp();
    // y(t) = (t − d) − 1 + e^{−(t − d)} for t ≥ d = 0.25, 0 before (the held ramp is exact)
    for (&t, &y) in r.t.iter().zip(&r.y[0]) {
        let s = t - 0.25;
        let want = if s <= 0.0 { 0.0 } else { s - 1.0 + (-s).exp() };
        // exact discretisation: a few ε of rounding per step taken
        let tol = 32.0 * EPS * r.t.len() as f64;
        assert!((y - want).abs() <= tol, "t = {t}: y = {y} vs {want}");
    }
}
