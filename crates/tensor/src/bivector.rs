//! Bivectors of Cl(3,0) (book §3.8).

use core::ops::{Add, Mul, Neg, Sub};

use nalgebra::Vector3;

use crate::{Scalar, Vector};

/// A bivector B = b₂₃ e₂e₃ + b₃₁ e₃e₁ + b₁₂ e₁e₂ of Cl(3,0) (book §3.8): an oriented plane
/// element. It is frame-free; its hidden components are in the same hidden basis as
/// [`Vector`]. The dual of a vector, 𝒥n⃗, has the components of n⃗ (book (3.8.x)).
///
/// Book: §3.7–3.8.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bivector<T: Scalar = f64> {
    pub(crate) c: Vector3<T>,
}

impl<T: Scalar> Bivector<T> {
    /// The zero bivector.
    #[inline]
    pub fn zero() -> Self {
        Self { c: Vector3::zeros() }
    }

    /// Reserved for `vectrix-frames` (see [`Vector::from_hidden`]).
    #[doc(hidden)]
    #[inline(always)]
    pub fn from_hidden(c: Vector3<T>) -> Self {
        Self { c }
    }

    /// Reserved for `vectrix-frames` (see [`Vector::hidden`]).
    #[doc(hidden)]
    #[inline(always)]
    pub fn hidden(&self) -> &Vector3<T> {
        &self.c
    }

    /// The dual 𝒥n⃗ of a vector: the plane perpendicular to n⃗, oriented by the right-hand rule
    /// (book (3.8.x), duality by the pseudoscalar 𝒥).
    #[inline]
    pub fn dual_of(n: &Vector<T>) -> Self {
        Self { c: n.c }
    }

    /// The vector n⃗ with 𝒥n⃗ = self (inverse of [`Bivector::dual_of`]).
    #[inline]
    pub fn undual(&self) -> Vector<T> {
        Vector { c: self.c }
    }

    /// Magnitude (area of the oriented plane element).
    #[inline]
    pub fn norm(&self) -> T {
        self.undual().norm()
    }
}

impl<T: Scalar> Add for Bivector<T> {
    type Output = Bivector<T>;
    #[inline(always)]
    fn add(self, b: Bivector<T>) -> Bivector<T> {
        Bivector { c: self.c + b.c }
    }
}

impl<T: Scalar> Sub for Bivector<T> {
    type Output = Bivector<T>;
    #[inline(always)]
    fn sub(self, b: Bivector<T>) -> Bivector<T> {
        Bivector { c: self.c - b.c }
    }
}

impl<T: Scalar> Neg for Bivector<T> {
    type Output = Bivector<T>;
    #[inline(always)]
    fn neg(self) -> Bivector<T> {
        Bivector { c: -self.c }
    }
}

impl<T: Scalar> Mul<T> for Bivector<T> {
    type Output = Bivector<T>;
    #[inline(always)]
    fn mul(self, s: T) -> Bivector<T> {
        Bivector { c: self.c * s }
    }
}
