//! Shared test support: tolerances, closeness assertions and proptest strategies biased toward
//! the hard sets (DESIGN §6). Included by each chapter file with `mod support;`.
#![allow(dead_code)]

use proptest::prelude::*;
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

/// Asserts |got − want| ≤ tol·max(1, |want|).
#[track_caller]
pub fn assert_close(got: f64, want: f64, tol: f64) {
    let err = (got - want).abs();
    assert!(err <= tol * want.abs().max(1.0), "got {got:e}, want {want:e}, |err| = {err:e} > {tol:e}");
}

/// Asserts max |got_i − want_i| ≤ tol·max(1, max|want_i|) for slices of equal length.
#[track_caller]
pub fn assert_close_slice(got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "length mismatch");
    let scale = want.iter().fold(1.0f64, |m, w| m.max(w.abs()));
    let err = got.iter().zip(want).fold(0.0f64, |m, (g, w)| m.max((g - w).abs()));
    assert!(err <= tol * scale, "got {got:?}, want {want:?}, max |err| = {err:e} > {tol:e}·{scale}");
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
