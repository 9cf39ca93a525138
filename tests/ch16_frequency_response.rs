//! Chapter 16: frequency response, Bode, Nyquist, margins and root locus (solutions in the
//! book's chapter 18), as executable tests, split by topic into `tests/ch16/*.rs`.
//!
//! Tolerances say what they mean: `assert_printed(got, printed, d)` is |got − printed| ≤
//! ½·10⁻ᵈ (half a unit of the last printed digit); `assert_abs` and `assert_rel` are absolute
//! and relative. The notes' computed values (C) are used where the book is inconsistent or
//! wrong; each such test says so.

use vectrix::lti::*;

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

/// Machine epsilon.
const EPS: f64 = f64::EPSILON;

/// |got − printed| ≤ ½·10^(−decimals), plus 10⁻⁹ relative for the binary representation.
#[track_caller]
fn assert_printed(got: f64, printed: f64, decimals: i32) {
    let tol = 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9);
    assert!((got - printed).abs() <= tol, "got {got}, printed {printed} (±{tol:e})");
}

/// |got − want| ≤ tol (absolute).
#[track_caller]
fn assert_abs(got: f64, want: f64, tol: f64) {
    let err = (got - want).abs();
    assert!(err <= tol, "got {got:e}, want {want:e}, |error| = {err:e} > {tol:e} (absolute)");
}

/// |got − want| ≤ tol·|want| (relative).
#[track_caller]
fn assert_rel(got: f64, want: f64, tol: f64) {
    let err = (got - want).abs();
    assert!(
        err <= tol * want.abs(),
        "got {got:e}, want {want:e}, |error| = {err:e} > {tol:e}·|want| (relative)"
    );
}

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
