//! vectrix-lti under hostile input, against today's API (docs/robustness.md). The LTI crate's
//! own fixes (eigen/balance bounds, time_grid allocation limit, expm overflow,
//! TransferFunction::scale(NaN)) are being made on another branch: this file covers the
//! functions that already satisfy the contract, and the coverage table lists the rest as
//! pending (`Enforce::Off`) until those fixes are merged.

use nalgebra::DMatrix;
use vectrix::lti::{Polynomial, Sdof, StateSpace, TransferFunction, Zpk, logspace};

use crate::harness::{err_or, hostile, refused};

type Complex64 = nalgebra::Complex<f64>;

cases! {
    // Polynomials: coefficients must be finite; the roots of a polynomial evaluate to ~0
    // relative to the size of its terms.
    polynomials ["Polynomial::new", "Polynomial::constant", "Polynomial::s", "Polynomial::coeffs", "Polynomial::degree",
        "Polynomial::is_zero", "Polynomial::leading", "Polynomial::coeff", "Polynomial::norm_inf", "Polynomial::eval",
        "Polynomial::derivative", "Polynomial::add", "Polynomial::sub", "Polynomial::mul", "Polynomial::from_roots"] {
        for x in hostile() {
            err_or(Polynomial::new(&[1.0, x, 1.0]), "Polynomial::new", |p| p.coeffs().iter().all(|c| c.is_finite()));
        }
        // The empty coefficient list is the zero polynomial (documented), not an error.
        assert!(Polynomial::new(&[]).is_ok_and(|p| p.is_zero()));
        let p = Polynomial::new(&[1.0, -3.0, 2.0]).unwrap();
        assert_eq!((p.degree(), p.leading(), p.coeff(0)), (2, 1.0, 2.0));
        assert!(!p.is_zero() && Polynomial::constant(0.0).is_zero() && Polynomial::s().degree() == 1);
        assert_eq!(p.norm_inf(), 3.0);
        assert_eq!(p.eval(1.0), 0.0);
        assert_eq!(p.derivative().unwrap().coeffs(), &[2.0, -3.0]);
        assert!(p.add(&p).and_then(|q| q.sub(&p)).and_then(|q| q.mul(&Polynomial::s())).unwrap().degree() == 3);
        err_or(Polynomial::from_roots(&[Complex64::new(1.0, 0.0), Complex64::new(2.0, 0.0)]), "from_roots", |q| q.coeffs() == p.coeffs());
        refused(Polynomial::from_roots(&[Complex64::new(f64::NAN, 0.0)]), "from_roots(NaN)");
    }

    // Transfer functions, zero–pole–gain and state-space constructors validate their input
    // (NaN, zero denominators, mismatched dimensions, negative delays).
    constructors ["TransferFunction::new", "TransferFunction::gain", "TransferFunction::with_delay", "TransferFunction::num",
        "TransferFunction::den", "TransferFunction::delay", "TransferFunction::relative_degree", "TransferFunction::is_proper",
        "TransferFunction::is_strictly_proper", "Zpk::new", "Zpk::with_delay", "Zpk::zeros", "Zpk::poles", "Zpk::gain",
        "Zpk::delay", "StateSpace::new", "StateSpace::from_rows", "StateSpace::a", "StateSpace::b", "StateSpace::c",
        "StateSpace::d", "StateSpace::n_states", "StateSpace::n_inputs", "StateSpace::n_outputs", "Sdof::new",
        "Sdof::natural_frequency", "Sdof::damping_ratio", "logspace"] {
        for x in hostile() {
            err_or(TransferFunction::new(&[1.0], &[1.0, x]), "TransferFunction::new", |g| g.den().coeffs().iter().all(|c| c.is_finite()));
            err_or(TransferFunction::gain(x), "TransferFunction::gain", |g| g.num().coeffs()[0].is_finite());
            err_or(TransferFunction::new(&[1.0], &[1.0, 1.0]).unwrap().with_delay(x), "with_delay", |g| g.delay().is_finite() && g.delay() >= 0.0);
            err_or(Zpk::new(vec![], vec![Complex64::new(x, 0.0)], 1.0), "Zpk::new", |z| z.poles().iter().all(|p| p.is_finite()));
            err_or(Zpk::new(vec![], vec![], x), "Zpk::new(gain)", |z| z.gain().is_finite() && z.zeros().is_empty());
            err_or(Zpk::new(vec![], vec![], 1.0).unwrap().with_delay(x), "Zpk::with_delay", |z| z.delay().is_finite() && z.delay() >= 0.0);
            err_or(Sdof::new(1.0, x, 4.0), "Sdof::new", |s| s.natural_frequency().is_finite() && s.damping_ratio().is_none_or(|z| z.is_finite()));
            err_or(StateSpace::from_rows(&[&[x]], &[&[1.0]], &[&[1.0]], &[&[0.0]]), "StateSpace::from_rows", |s| s.a()[(0, 0)].is_finite());
            // 10^x underflows to 0 for x ≤ −324: the correctly rounded value, so ≥ 0.
            err_or(logspace(x, 1.0, 10), "logspace", |w| w.iter().all(|c| c.is_finite() && *c >= 0.0));
        }
        refused(TransferFunction::new(&[1.0], &[0.0]), "TransferFunction::new(zero denominator)");
        let g = TransferFunction::new(&[1.0, 0.0], &[1.0, 2.0, 1.0]).unwrap();
        assert!(g.is_proper() && g.is_strictly_proper() && g.relative_degree() == 1);
        refused(StateSpace::new(DMatrix::zeros(2, 2), DMatrix::zeros(3, 1), DMatrix::zeros(1, 2), DMatrix::zeros(1, 1)), "StateSpace::new(mismatched)");
        let s = StateSpace::from_rows(&[&[0.0, 1.0], &[-1.0, 0.0]], &[&[0.0], &[1.0]], &[&[1.0, 0.0]], &[&[0.0]]).unwrap();
        assert_eq!((s.n_states(), s.n_inputs(), s.n_outputs()), (2, 1, 1));
        assert!(s.b().iter().chain(s.c().iter()).chain(s.d().iter()).all(|c| c.is_finite()));
        refused(logspace(0.0, 1.0, 0), "logspace(n = 0)");
    }
}
