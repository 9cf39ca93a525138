//! Components in an internal working frame.
//!
//! Mass properties and equilibrium need numbers (eigenvalues, least squares). They are taken
//! in one fixed working frame through the public `resolve`/`Frame::dyadic` API, never through
//! the kernel's hidden basis; results are mapped back to frame-free objects at once, so the
//! choice of working frame never shows.

use nalgebra::{Matrix3, Vector3};
use vectrix_frames::{Frame, Resolve};
use vectrix_tensor::{Dyadic, Scalar, Vector};

/// The working frame.
#[inline]
pub(crate) fn work<T: Scalar>() -> Frame<T> {
    Frame::identity()
}

/// Components of a dyadic in the working frame.
#[inline]
pub(crate) fn mat<T: Scalar>(d: &Dyadic<T>) -> Matrix3<T> {
    d.resolve(&work())
}

/// Components of a vector in the working frame.
#[inline]
pub(crate) fn vec3<T: Scalar>(x: &Vector<T>) -> Vector3<T> {
    x.resolve(&work())
}

/// The vector whose working-frame components are `x`.
#[inline]
pub(crate) fn vector<T: Scalar>(x: &Vector3<T>) -> Vector<T> {
    work().vector([x.x, x.y, x.z])
}

/// Real parts of a dyadic's components, for eigenvalues and tolerances.
#[inline]
pub(crate) fn mat_re<T: Scalar>(d: &Dyadic<T>) -> Matrix3<f64> {
    mat(d).map(|x| x.re())
}
