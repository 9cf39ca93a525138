//! Helpers shared by the chapter 6 tests.
#![allow(dead_code)]

use vectrix::nalgebra::Matrix3;
use vectrix::prelude::*;
use vectrix::statics::Point;

use crate::support::{assert_abs_slice, assert_rel_slice};

/// Asserts two 3×3 matrices agree entrywise: max |got − want| ≤ tol.
#[track_caller]
pub fn assert_mat_abs(got: &Matrix3<f64>, want: &Matrix3<f64>, tol: f64) {
    assert_abs_slice(got.as_slice(), want.as_slice(), tol);
}

/// Asserts max |got − want| ≤ tol·max|want| over the entries (relative to the largest entry).
#[track_caller]
pub fn assert_mat_rel(got: &Matrix3<f64>, want: &Matrix3<f64>, tol: f64) {
    assert_rel_slice(got.as_slice(), want.as_slice(), tol);
}

/// Asserts two vectors agree componentwise in the first frame: max |got − want| ≤ tol.
#[track_caller]
pub fn assert_vec_abs(got: &Vector, want: &Vector, tol: f64) {
    let a = Frame::new();
    assert_abs_slice(got.resolve(&a).as_slice(), want.resolve(&a).as_slice(), tol);
}

/// Asserts max |got − want| ≤ tol·max|want| over the components in the first frame.
#[track_caller]
pub fn assert_vec_rel(got: &Vector, want: &Vector, tol: f64) {
    let a = Frame::new();
    assert_rel_slice(got.resolve(&a).as_slice(), want.resolve(&a).as_slice(), tol);
}

/// Asserts two dyadics agree entrywise in the first frame: max |got − want| ≤ tol.
#[track_caller]
pub fn assert_dyadic_abs(got: &Dyadic, want: &Dyadic, tol: f64) {
    let a = Frame::new();
    assert_mat_abs(&got.resolve(&a), &want.resolve(&a), tol);
}

/// Asserts max |got − want| ≤ tol·max|want| over the entries in the first frame.
#[track_caller]
pub fn assert_dyadic_rel(got: &Dyadic, want: &Dyadic, tol: f64) {
    let a = Frame::new();
    assert_mat_rel(&got.resolve(&a), &want.resolve(&a), tol);
}

/// The point with r⃗_{y/o} = a.vector(x).
pub fn pt(a: &Frame, x: [f64; 3]) -> Point {
    Point::at(a.vector(x))
}

/// Diagonal matrix.
pub fn diag(d: [f64; 3]) -> Matrix3<f64> {
    Matrix3::from_diagonal(&vectrix::nalgebra::Vector3::from(d))
}
