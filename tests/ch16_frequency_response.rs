//! Chapter 16: frequency response, Bode, Nyquist, margins and root locus (solutions in the
//! book's chapter 18), as executable tests, split by topic into `tests/ch16/*.rs`.
//!
//! Tolerances say what they mean: `assert_printed(got, printed, d)` is |got − printed| ≤
//! ½·10⁻ᵈ (half a unit of the last printed digit); `assert_abs` and `assert_rel` are absolute
//! and relative. The notes' computed values (C) are used where the book is inconsistent or
//! wrong; each such test says so.

mod support;

use vectrix::lti::*;

#[path = "lti_asserts/mod.rs"]
mod lti_asserts;
use lti_asserts::*;

#[path = "ch16/locus.rs"]
mod locus;
#[path = "ch16/margins.rs"]
mod margins;
#[path = "ch16/prop.rs"]
mod prop;
#[path = "ch16/response.rs"]
mod response;
#[path = "ch16/sensitivity.rs"]
mod sensitivity;

fn tf(n: &[f64], d: &[f64]) -> TransferFunction {
    TransferFunction::new(n, d).unwrap()
}

fn poly(c: &[f64]) -> Polynomial {
    Polynomial::new(c).unwrap()
}

/// Bode data at one frequency.
fn at(g: &TransferFunction, w: f64) -> FrequencyResponse {
    g.bode(&[w]).unwrap()
}
