//! Chapter 15: linear dynamical systems (solutions in the book's chapter 17), as executable
//! tests, split by topic into `tests/ch15/*.rs`.
//!
//! Tolerances say what they mean: `assert_printed(got, printed, d)` is |got − printed| ≤
//! ½·10⁻ᵈ (half a unit of the last printed digit, the book's rounding); `assert_abs(got, want,
//! tol)` is |got − want| ≤ tol; `assert_rel(got, want, tol)` is |got − want| ≤ tol·|want|.
//! Where the book errs (notes ch15-18 §4, "ERR"), the corrected value is tested and the comment
//! says so.

mod support;

use nalgebra::DMatrix;
use vectrix::lti::*;

#[path = "lti_asserts/mod.rs"]
mod lti_asserts;
use lti_asserts::*;

#[path = "ch15/algebra.rs"]
mod algebra;
#[path = "ch15/errors.rs"]
mod errors;
#[path = "ch15/exponential.rs"]
mod exponential;
#[path = "ch15/laplace.rs"]
mod laplace;
#[path = "ch15/modes.rs"]
mod modes;
#[path = "ch15/prop.rs"]
mod prop;
#[path = "ch15/realisation.rs"]
mod realisation;
#[path = "ch15/responses.rs"]
mod responses;
#[path = "ch15/routh.rs"]
mod routh;

fn tf(n: &[f64], d: &[f64]) -> TransferFunction {
    TransferFunction::new(n, d).unwrap()
}

fn poly(c: &[f64]) -> Polynomial {
    Polynomial::new(c).unwrap()
}

/// Roots sorted by real part, then imaginary part.
fn sorted(mut v: Vec<Complex64>) -> Vec<Complex64> {
    v.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
    v
}

/// The Boeing 747 lateral model of 15.20.51–52: states (β, r, p, φ), inputs (δr, δa), outputs
/// r and φ.
fn b747() -> StateSpace {
    let a = nalgebra::dmatrix![-0.0558, -0.9968, 0.0802, 0.0415;
                     0.598, -0.115, -0.0318, 0.0;
                     -3.05, 0.388, -0.4650, 0.0;
                     0.0, 0.0805, 1.0, 0.0];
    let b = nalgebra::dmatrix![0.00729, 0.0; -0.475, 0.00775; 0.153, 0.143; 0.0, 0.0];
    let c = nalgebra::dmatrix![0.0, 1.0, 0.0, 0.0; 0.0, 0.0, 0.0, 1.0];
    StateSpace::new(a, b, c, DMatrix::zeros(2, 2)).unwrap()
}
