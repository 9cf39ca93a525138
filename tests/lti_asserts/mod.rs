//! Tolerance helpers of the chapter 15–16 tests, named by what they mean.

/// Machine epsilon.
pub const EPS: f64 = f64::EPSILON;

/// |got − printed| ≤ ½·10^(−decimals): the printed value is `got` rounded (plus a hair, 10⁻⁹
/// relative, for the binary representation of the printed decimal).
#[track_caller]
pub fn assert_printed(got: f64, printed: f64, decimals: i32) {
    let tol = 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9);
    assert!((got - printed).abs() <= tol, "got {got}, printed {printed} (±{tol:e})");
}

/// |got − want| ≤ tol (absolute).
#[track_caller]
pub fn assert_abs(got: f64, want: f64, tol: f64) {
    let err = (got - want).abs();
    assert!(err <= tol, "got {got:e}, want {want:e}, |error| = {err:e} > {tol:e} (absolute)");
}

/// |got − want| ≤ tol·|want| (relative).
#[track_caller]
pub fn assert_rel(got: f64, want: f64, tol: f64) {
    let err = (got - want).abs();
    assert!(
        err <= tol * want.abs(),
        "got {got:e}, want {want:e}, |error| = {err:e} > {tol:e}·|want| (relative)"
    );
}
