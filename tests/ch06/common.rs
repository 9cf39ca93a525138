//! Helpers shared by the chapter 6 tests.
#![allow(dead_code)]

use vectrix::nalgebra::Matrix3;
use vectrix::prelude::*;
use vectrix::statics::Point;

use crate::support::assert_close_slice;

/// Asserts two 3×3 matrices agree entrywise within tol·max(1, max|want|).
#[track_caller]
pub fn assert_mat_close(got: &Matrix3<f64>, want: &Matrix3<f64>, tol: f64) {
    assert_close_slice(got.as_slice(), want.as_slice(), tol);
}

/// Asserts two vectors agree, resolved in `a`.
#[track_caller]
pub fn assert_vec_close(got: &Vector, want: &Vector, tol: f64) {
    let a = Frame::new();
    assert_close_slice(got.resolve(&a).as_slice(), want.resolve(&a).as_slice(), tol);
}

/// Asserts two dyadics agree, resolved in the first frame.
#[track_caller]
pub fn assert_dyadic_close(got: &Dyadic, want: &Dyadic, tol: f64) {
    let a = Frame::new();
    assert_mat_close(&got.resolve(&a), &want.resolve(&a), tol);
}

/// The point with r⃗_{y/o} = a.vector(x).
pub fn pt(a: &Frame, x: [f64; 3]) -> Point {
    Point::at(a.vector(x))
}

/// Diagonal matrix.
pub fn diag(d: [f64; 3]) -> Matrix3<f64> {
    Matrix3::from_diagonal(&vectrix::nalgebra::Vector3::from(d))
}
