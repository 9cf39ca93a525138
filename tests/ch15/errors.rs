//! Typed errors for bad input (DESIGN §5; issue 19 item 6, issue 22): never a panic, NaN,
//! hang, abort or silent fallback.

use super::*;
use nalgebra::dmatrix;

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

#[test]
fn issue_19_unpaired_complex_roots_are_errors() {
    // A real polynomial cannot have 1 + j without 1 − j: `from_roots(&[1+1j])` used to give
    // s − 1, and a zpk with the pole −1 + j alone used to become 1/(s + 1).
    let r = Complex64::new(1.0, 1.0);
    assert!(matches!(
        Polynomial::from_roots(&[r]),
        Err(LtiError::UnpairedComplexRoot { re, im, .. }) if re == 1.0 && im == 1.0
    ));
    assert!(matches!(
        Zpk::new(vec![], vec![Complex64::new(-1.0, 1.0)], 1.0),
        Err(LtiError::UnpairedComplexRoot { what: "poles", .. })
    ));
    // with the conjugate the product is exactly the real quadratic s² − 2s + 2
    assert_eq!(Polynomial::from_roots(&[r, r.conj()]).unwrap().coeffs(), &[1.0, -2.0, 2.0]);
    let z = Zpk::new(vec![], vec![Complex64::new(-1.0, 1.0), Complex64::new(-1.0, -1.0)], 1.0).unwrap();
    assert_eq!(z.to_tf().unwrap().den().coeffs(), &[1.0, 2.0, 2.0]);
}

#[test]
fn issue_19_zero_polynomial_is_an_error() {
    // The zero polynomial has every number as a root: it is neither stable nor anything else
    // (`stability_of_polynomial(0)` used to say asymptotically stable).
    let zero = poly(&[0.0, 0.0]);
    assert!(matches!(stability_of_polynomial(&zero, AXIS_RTOL), Err(LtiError::ZeroPolynomial { .. })));
    assert!(matches!(zero.roots(), Err(LtiError::ZeroPolynomial { .. })));
    assert!(matches!(zero.monic(), Err(LtiError::ZeroPolynomial { .. })));
    assert!(matches!(routh(&zero), Err(LtiError::InvalidArgument { .. })));
}

#[test]
fn issue_22_grids_are_bounded() {
    // `time_grid(1.0, 1e12)` aborted on allocation; grids and simulations are bounded by
    // MAX_VALUES with a typed error, before anything is allocated.
    assert!(matches!(
        time_grid(1.0, 1_000_000_000_000),
        Err(LtiError::TooLarge { requested: 1_000_000_000_000, limit: MAX_VALUES, .. })
    ));
    assert!(matches!(logspace(0.0, 1.0, usize::MAX), Err(LtiError::TooLarge { .. })));
    assert_eq!(time_grid(1.0, 11).unwrap().len(), 11);
}

#[test]
fn issue_22_nan_never_inside_ok() {
    // TransferFunction::scale(NaN) returned NaN coefficients without an error; interconnections
    // whose coefficients overflow are errors too.
    let g = tf(&[1.0], &[1.0, 1.0]);
    assert!(matches!(g.scale(f64::NAN), Err(LtiError::NonFinite { .. })));
    assert!(matches!(g.scale(f64::INFINITY), Err(LtiError::NonFinite { .. })));
    let huge = tf(&[1e200], &[1.0, 1.0]);
    assert!(matches!(huge.series(&huge), Err(LtiError::Overflow { .. })));
    assert!(matches!(huge.scale(1e200), Err(LtiError::Overflow { .. })));
    assert!(matches!(poly(&[1e200, 1.0]).mul(&poly(&[1e200, 1.0])), Err(LtiError::Overflow { .. })));
    // an unstable response whose true value overflows: e^{t} to t = 1000 (e^{1000} > 1.8e308)
    let unstable = tf(&[1.0], &[1.0, -1.0]);
    assert!(matches!(unstable.step(&time_grid(1000.0, 11).unwrap()), Err(LtiError::Overflow { .. })));
    // a balanced matrix of huge entries: Ok and finite, or Overflow — never ∞ inside Ok
    match linalg::balance(&dmatrix![1e308, 1e308; 1e-308, 1e308]) {
        Ok(b) => assert!(b.iter().all(|x| x.is_finite())),
        Err(e) => assert!(matches!(e, LtiError::Overflow { .. })),
    }
}

#[test]
fn issue_33_polynomial_at_infinity_is_the_limit() {
    // docs/robustness.md, "Where ∞ is the answer": p(±∞) = lim p(x) = c₀·(±∞)ⁿ, as numpy's
    // polyval; a finite x whose |p(x)| exceeds f64::MAX gives ±∞ by the sign of p(x); NaN
    // gives NaN (it used to come out as ±∞).
    let inf = f64::INFINITY;
    let q = poly(&[1.0, 0.0, -1.0]); // s² − 1
    assert_eq!((q.eval(inf), q.eval(-inf)), (inf, inf));
    let cubic = poly(&[-2.0, 5.0, 0.0, 7.0]); // −2s³ + 5s² + 7
    assert_eq!((cubic.eval(inf), cubic.eval(-inf)), (-inf, inf));
    assert_eq!(poly(&[3.0]).eval(inf), 3.0);
    assert_eq!(poly(&[0.0]).eval(-inf), 0.0);
    // overflow at a finite point: s² at 1e200 and −s³ at 1e110 (true values 1e400, −1e330)
    assert_eq!(poly(&[1.0, 0.0, 0.0]).eval(1e200), inf);
    assert_eq!(poly(&[-1.0, 0.0, 0.0, 0.0]).eval(1e110), -inf);
    for p in [&q, &cubic, &poly(&[3.0]), &poly(&[0.0])] {
        assert!(p.eval(f64::NAN).is_nan(), "{p:?} at NaN");
    }
}

#[test]
fn issue_33_logspace_past_f64_max_is_an_error() {
    // 10^b beyond f64::MAX ≈ 1.8e308 (b ≥ log₁₀ f64::MAX ≈ 308.2547) used to put ∞ inside Ok;
    // it is an InvalidArgument naming the valid range. Up to that edge every point is finite,
    // the last is exactly 10^b (Matlab's and numpy's endpoint), and a = −f64::MAX no longer
    // overflows the exponent sum (b − a)·k.
    for b in [400.0, f64::MAX.log10(), 1e300] {
        match logspace(0.0, b, 5) {
            Err(LtiError::InvalidArgument { what: "logspace", reason }) => {
                assert!(reason.contains("308.2547"), "b = {b}: {reason}")
            }
            other => panic!("logspace(0, {b}, 5): {other:?}"),
        }
    }
    let w = logspace(300.0, 308.25, 7).unwrap();
    assert!(w.iter().all(|x| x.is_finite()) && w.windows(2).all(|p| p[0] < p[1]), "{w:?}");
    assert_eq!(*w.last().unwrap(), 10f64.powf(308.25));
    let w = logspace(-f64::MAX, 2.0, 10).unwrap();
    assert!(w.iter().all(|x| x.is_finite() && *x >= 0.0) && w[9] == 100.0, "{w:?}");
    // an ordinary grid keeps its values: 10⁻², 10⁻¹, …, 10²
    assert_eq!(logspace(-2.0, 2.0, 5).unwrap(), [0.01, 0.1, 1.0, 10.0, 100.0]);
}
