//! Shared test support: assertions whose tolerances say what they mean, and proptest
//! strategies biased toward the hard sets (DESIGN §6). Included by each chapter file with
//! `mod support;`.
//!
//! # Choosing a tolerance
//!
//! Every assertion states its semantics in its name; none scales a tolerance by the value.
//!
//! - **A printed number of the book**: `assert_printed(got, "0.0985")` checks half a unit of
//!   the last printed digit (±0.00005 here; `"985"` is checked to ±0.5). Pass the digits exactly
//!   as printed. Where the book chops digits instead of rounding them (the notes say which),
//!   `assert_truncated(got, "6.29")` checks that chopping `got` gives the printed digits.
//! - **A closed form evaluated in floating point**: `assert_rel(got, want, k * EPS)` with k a
//!   small count of the roundings on the path (a few for a product or a square root, tens for a
//!   3 × 3 matrix product chain), so the test still fails on a wrong sign, factor or term.
//! - **Entries of an object with a natural scale** (rotation and unit-vector components, whose
//!   scale is 1; a vector or matrix whose largest entry sets the scale): `assert_abs` or
//!   `assert_abs_slice` at k·ε times that scale, or `assert_rel_slice`, which is relative to
//!   the largest |want_i| (so entries that should be 0 are checked at the scale of the object,
//!   where their rounding error lives).
//! - **A value that is zero in exact arithmetic**: `assert_abs(got, 0.0, k * EPS * scale)`,
//!   the scale being the size of the terms that cancel.
//! - **An iterative, integrated or truncated-series result**: the accuracy the method promises
//!   (the tolerance of the root finder, the step-size error of the integrator), with a comment
//!   that names it.
//!
//! Loosen only with a comment that says why the mathematics needs it (conditioning,
//! cancellation, an iteration's stopping rule); a printed-digit tolerance is never multiplied
//! by the value.
#![allow(dead_code)]

use proptest::prelude::*;
use vectrix::nalgebra::{Dim, Matrix, RawStorage};
use vectrix::prelude::*;

/// Machine epsilon of f64.
pub const EPS: f64 = f64::EPSILON;

/// Hard eigenangles (DESIGN §6): 0, tiny, near π, π.
pub const HARD_ANGLES: [f64; 9] = [
    0.0,
    1e-300,
    1e-16,
    1e-8,
    1e-4,
    std::f64::consts::PI - 1e-4,
    std::f64::consts::PI - 1e-8,
    std::f64::consts::PI - 1e-12,
    std::f64::consts::PI,
];

/// Asserts the absolute error |got − want| ≤ tol.
#[track_caller]
pub fn assert_abs(got: f64, want: f64, tol: f64) {
    let err = (got - want).abs();
    assert!(err <= tol, "got {got:e}, want {want:e}: |err| = {err:e} > abs tol {tol:e}");
}

/// Asserts the relative error |got − want| ≤ tol·|want| (so `want = 0` demands `got = 0`).
#[track_caller]
pub fn assert_rel(got: f64, want: f64, tol: f64) {
    let err = (got - want).abs();
    let bound = tol * want.abs();
    assert!(
        err <= bound,
        "got {got:e}, want {want:e}: |err| = {err:e} > rel tol {tol:e} · |want| = {bound:e}"
    );
}

/// Asserts |got_i − want_i| ≤ tol for every entry of two slices of equal length.
#[track_caller]
pub fn assert_abs_slice(got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "length mismatch");
    let err = max_abs_diff(got, want);
    assert!(err <= tol, "got {got:?}, want {want:?}: max |err| = {err:e} > abs tol {tol:e}");
}

/// Asserts max_i |got_i − want_i| ≤ tol·max_i |want_i|: relative to the largest entry (the
/// ∞-norm of `want`), so entries that should vanish are checked at the scale of the object.
#[track_caller]
pub fn assert_rel_slice(got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "length mismatch");
    let err = max_abs_diff(got, want);
    let scale = want.iter().fold(0.0, |m, w| nan_max(m, w.abs()));
    assert!(
        err <= tol * scale,
        "got {got:?}, want {want:?}: max |err| = {err:e} > rel tol {tol:e} · max|want| = {scale:e}"
    );
}

/// Asserts `got` rounds to the digits the book prints: |got − printed| ≤ ½ unit of the last
/// printed digit (`"6.29"` → ±0.005, `"985"` → ±0.5, `"1.5e-3"` → ±0.00005), plus 4 ε·|printed|
/// for the binary representation of the printed decimal.
#[track_caller]
pub fn assert_printed(got: f64, printed: &str) {
    let (want, unit) = parse_printed(printed);
    let tol = 0.5 * unit + 4.0 * EPS * want.abs();
    let err = (got - want).abs();
    assert!(err <= tol, "got {got}, printed {printed} (±{tol:e}): |err| = {err:e}");
}

/// Asserts `got` chopped toward zero after the last printed digit gives the printed digits
/// (for the places where the book truncates rather than rounds: 6.297 printed as `"6.29"`).
#[track_caller]
pub fn assert_truncated(got: f64, printed: &str) {
    let (want, unit) = parse_printed(printed);
    let slack = 4.0 * EPS * want.abs();
    // Chopping toward zero: printed ≤ got < printed + unit for a positive value, mirrored for
    // a negative one.
    let ok = if want > 0.0 || (want == 0.0 && !printed.trim_start().starts_with('-')) {
        got >= want - slack && got < want + unit + slack
    } else {
        got <= want + slack && got > want - unit - slack
    };
    assert!(ok, "got {got}, which does not truncate to the printed {printed} (unit {unit:e})");
}

/// [`assert_printed`] entry by entry.
#[track_caller]
pub fn assert_printed_slice(got: &[f64], printed: &[&str]) {
    assert_eq!(got.len(), printed.len(), "length mismatch");
    for (g, p) in got.iter().zip(printed) {
        assert_printed(*g, p);
    }
}

/// The value of a printed decimal and the unit of its last digit: `"6.29"` → (6.29, 0.01),
/// `"985"` → (985, 1), `"-1.25e-3"` → (−0.00125, 0.00001).
pub fn parse_printed(printed: &str) -> (f64, f64) {
    let s = printed.trim();
    let value: f64 = s.parse().unwrap_or_else(|_| panic!("{printed:?} is not a decimal number"));
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], s[i + 1..].parse::<i32>().expect("decimal exponent")),
        None => (s, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, frac)| frac.len() as i32);
    (value, 10f64.powi(exponent - decimals))
}

fn max_abs_diff(got: &[f64], want: &[f64]) -> f64 {
    // NaN must fail: fold with a comparison that propagates it.
    got.iter().zip(want).fold(0.0, |m, (g, w)| nan_max(m, (g - w).abs()))
}

// # Worst-error folds that fail on NaN
//
// `f64::max(NaN, x)` is x, and nalgebra's `amax` keeps a NaN entry only when it is the last
// one, so a worst error folded with either passes `worst <= tol` although an entry is NaN.
// The folds below return NaN when any entry is NaN, so every comparison with them fails.
// `nan_blind_folds_are_refused` in `tests/textbook_index/nan_folds.rs` rejects the NaN-blind
// forms by pattern.

/// max(a, b), NaN when either is NaN: the drop-in for `f64::max` in a worst-error fold
/// (`.fold(0.0, nan_max)`, `worst = nan_max(worst, err)`).
pub fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() { f64::NAN } else { a.max(b) }
}

/// min(a, b), NaN when either is NaN: the drop-in for `f64::min` in a fold.
pub fn nan_min(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() { f64::NAN } else { a.min(b) }
}

/// The largest |entry| of a matrix or vector, NaN when any entry is NaN (0 when empty, as
/// `amax`): the drop-in for nalgebra's `amax` in a check `m.nan_amax() <= tol`.
pub trait NanAmax {
    /// max |mᵢⱼ|, NaN when any entry is NaN.
    fn nan_amax(&self) -> f64;
}

impl<R: Dim, C: Dim, S: RawStorage<f64, R, C>> NanAmax for Matrix<f64, R, C, S> {
    fn nan_amax(&self) -> f64 {
        self.iter().fold(0.0, |m, x| nan_max(m, x.abs()))
    }
}

/// Finite components in a range that includes tiny and huge magnitudes.
pub fn component() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -10.0..10.0f64,
        1 => (-1.0..1.0f64).prop_map(|x| x * 1e-150),
        1 => (-1.0..1.0f64).prop_map(|x| x * 1e150),
    ]
}

/// Three components, moderate magnitude.
pub fn triple() -> impl Strategy<Value = [f64; 3]> {
    [-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64]
}

/// A nonzero direction (not normalised).
pub fn direction() -> impl Strategy<Value = [f64; 3]> {
    triple().prop_filter("nonzero", |v| v.iter().map(|x| x * x).sum::<f64>() > 1e-6)
}

/// An angle in (−π, π] biased toward the hard set.
pub fn angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => -std::f64::consts::PI..std::f64::consts::PI,
        1 => prop::sample::select(HARD_ANGLES.to_vec()),
        1 => prop::sample::select(HARD_ANGLES.to_vec()).prop_map(|a| -a),
    ]
}

/// A random frame: the first frame rotated about a random axis by a random angle.
pub fn frame() -> impl Strategy<Value = Frame> {
    (direction(), angle()).prop_map(|(n, th)| {
        let a = Frame::new();
        let r = Rotor::from_axis_angle(&a.vector(n), th).expect("nonzero axis");
        a.rotated_by_rotor(&r)
    })
}

/// Every file below `dir` with its contents, to compare a tree before and after.
pub fn snapshot(dir: &std::path::Path) -> Vec<(std::path::PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                out.push((p.clone(), std::fs::read(&p).unwrap()));
            }
        }
    }
    out.sort();
    out
}
