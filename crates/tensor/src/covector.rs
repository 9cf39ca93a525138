//! Covectors (book §2.1, (2.1.6)): linear functionals on physical vectors.

use core::ops::{Add, Mul, Neg, Sub};

use nalgebra::Vector3;

use crate::{Dyadic, Scalar, Vector};

/// A covector x⃗′ (book (2.1.6)): x⃗′y⃗ ≜ x⃗·y⃗. Resolved, it is a row: x⃗′|_A = x|_Aᵀ (2.4.20).
///
/// Book: §2.1, (2.1.6), Fact 2.1.2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Covector<T: Scalar = f64> {
    pub(crate) c: Vector3<T>,
}

impl<T: Scalar> Covector<T> {
    /// The zero covector.
    ///
    /// Book: §2.1 (covectors).
    #[inline]
    pub fn zero() -> Self {
        Self { c: Vector3::zeros() }
    }

    /// Coform back to the vector: (x⃗′)′ = x⃗ (Fact 2.1.2).
    ///
    /// Book: (2.1.6), Fact 2.1.2.
    #[inline]
    pub fn coform(&self) -> Vector<T> {
        Vector { c: self.c }
    }

    /// Evaluation x⃗′y⃗ = x⃗·y⃗ (2.1.6).
    ///
    /// Book: (2.1.6).
    #[inline]
    pub fn apply(&self, y: &Vector<T>) -> T {
        self.c.dot(&y.c)
    }

    /// Magnitude, equal to that of the coform.
    ///
    /// Book: (2.1.6), Fact 2.4.2.
    #[inline]
    pub fn norm(&self) -> T {
        self.coform().norm()
    }

    /// `true` when every component is finite.
    ///
    /// Book: DESIGN §5 (bad input).
    #[inline]
    pub fn is_finite(&self) -> bool {
        crate::scalar::all_finite(self.c.as_slice())
    }
}

impl Covector<f64> {
    /// The same covector over another scalar type (see [`Vector::cast`]).
    ///
    /// Book: §2.24.
    #[inline]
    pub fn cast<U: Scalar>(&self) -> Covector<U> {
        Covector { c: self.c.map(U::lit) }
    }
}

/// x⃗ y⃗′: a vector times a covector is the dyad of (2.6.1), the same as `x.outer(&y)`.
///
/// Book: (2.6.1).
impl<T: Scalar> Mul<Covector<T>> for Vector<T> {
    type Output = Dyadic<T>;
    #[inline(always)]
    fn mul(self, y: Covector<T>) -> Dyadic<T> {
        Dyadic { m: self.c * y.c.transpose() }
    }
}

/// x⃗′ y⃗: evaluation of the covector at a vector.
impl<T: Scalar> Mul<Vector<T>> for Covector<T> {
    type Output = T;
    #[inline(always)]
    fn mul(self, y: Vector<T>) -> T {
        self.apply(&y)
    }
}

/// x⃗′ M⃗: a covector times a dyadic is a covector ((x′M)y = x′(My)).
impl<T: Scalar> Mul<Dyadic<T>> for Covector<T> {
    type Output = Covector<T>;
    #[inline(always)]
    fn mul(self, m: Dyadic<T>) -> Covector<T> {
        Covector { c: m.m.tr_mul(&self.c) }
    }
}

impl<T: Scalar> Mul<T> for Covector<T> {
    type Output = Covector<T>;
    #[inline(always)]
    fn mul(self, s: T) -> Covector<T> {
        Covector { c: self.c * s }
    }
}

impl<T: Scalar> Add for Covector<T> {
    type Output = Covector<T>;
    #[inline(always)]
    fn add(self, y: Covector<T>) -> Covector<T> {
        Covector { c: self.c + y.c }
    }
}

impl<T: Scalar> Sub for Covector<T> {
    type Output = Covector<T>;
    #[inline(always)]
    fn sub(self, y: Covector<T>) -> Covector<T> {
        Covector { c: self.c - y.c }
    }
}

impl<T: Scalar> Neg for Covector<T> {
    type Output = Covector<T>;
    #[inline(always)]
    fn neg(self) -> Covector<T> {
        Covector { c: -self.c }
    }
}
