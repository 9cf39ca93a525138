//! Physical matrices (dyadics), book §2.6–2.9.

use core::ops::{Add, Mul, Neg, Sub};

use nalgebra::Matrix3;

use crate::{Scalar, TensorError, Vector};

/// A physical matrix M⃗ = Σ x⃗_i y⃗_i′ (book (2.6.1)): a second-order tensor of type (1, 1)
/// with no components.
///
/// Book: §2.6; identity (2.8.1), cross-product dyad (2.9.1), projectors (2.7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dyadic<T: Scalar = f64> {
    pub(crate) m: Matrix3<T>,
}

impl<T: Scalar> Dyadic<T> {
    /// The zero dyadic.
    #[inline]
    pub fn zero() -> Self {
        Self { m: Matrix3::zeros() }
    }

    /// The identity I⃗ = F_A 𝓕′_A, the same for every frame A (2.8.1, Fact 2.8.1).
    #[inline]
    pub fn identity() -> Self {
        Self { m: Matrix3::identity() }
    }

    /// Reserved for `vectrix-frames` (see [`Vector::from_hidden`]).
    #[doc(hidden)]
    #[inline(always)]
    pub fn from_hidden(m: Matrix3<T>) -> Self {
        Self { m }
    }

    /// Reserved for `vectrix-frames` (see [`Vector::hidden`]).
    #[doc(hidden)]
    #[inline(always)]
    pub fn hidden(&self) -> &Matrix3<T> {
        &self.m
    }

    /// M⃗ x⃗.
    #[inline]
    pub fn apply(&self, x: &Vector<T>) -> Vector<T> {
        Vector { c: self.m * x.c }
    }

    /// Coform M⃗′, the transpose analogue: (x⃗y⃗′)′ = y⃗x⃗′ (2.6.9).
    #[inline]
    pub fn coform(&self) -> Dyadic<T> {
        Dyadic { m: self.m.transpose() }
    }

    /// Trace tr M⃗, independent of the frame it is resolved in (Fact 2.6.x).
    #[inline]
    pub fn trace(&self) -> T {
        self.m.trace()
    }

    /// Determinant det M⃗, independent of the frame (book §2.6).
    #[inline]
    pub fn determinant(&self) -> T {
        self.m.determinant()
    }

    /// Inverse M⃗⁻¹.
    ///
    /// # Errors
    /// [`TensorError::Singular`] when |det M| ≤ `rel_tol`·‖M‖³ (relative to the Frobenius
    /// norm, so the test does not depend on units); [`TensorError::NonFinite`] for NaN/∞.
    pub fn inverse(&self, rel_tol: f64) -> Result<Dyadic<T>, TensorError> {
        if !self.is_finite() {
            return Err(TensorError::NonFinite { what: "dyadic" });
        }
        let det = self.determinant().re();
        let scale = self.m.norm().re();
        let tol = rel_tol * scale * scale * scale;
        if det.abs() <= tol || scale == 0.0 {
            return Err(TensorError::Singular { det, tol });
        }
        // Adjugate / det: exact for 3×3 and differentiable for dual numbers.
        let m = &self.m;
        let cof = |r1: usize, c1: usize, r2: usize, c2: usize| {
            m[(r1, c1)] * m[(r2, c2)] - m[(r1, c2)] * m[(r2, c1)]
        };
        let adj = Matrix3::new(
            cof(1, 1, 2, 2),
            -cof(0, 1, 2, 2),
            cof(0, 1, 1, 2),
            -cof(1, 0, 2, 2),
            cof(0, 0, 2, 2),
            -cof(0, 0, 1, 2),
            cof(1, 0, 2, 1),
            -cof(0, 0, 2, 1),
            cof(0, 0, 1, 1),
        );
        Ok(Dyadic { m: adj / self.determinant() })
    }

    /// Symmetric part ½(M⃗ + M⃗′).
    #[inline]
    pub fn symmetric_part(&self) -> Dyadic<T> {
        Dyadic { m: (self.m + self.m.transpose()) * T::lit(0.5) }
    }

    /// Skew-symmetric part ½(M⃗ − M⃗′).
    #[inline]
    pub fn skew_part(&self) -> Dyadic<T> {
        Dyadic { m: (self.m - self.m.transpose()) * T::lit(0.5) }
    }

    /// Vee: the vector x⃗ with x⃗^× equal to the skew part of M⃗ (inverse of
    /// [`Vector::cross_dyad`] on skew dyadics, book §2.9).
    #[inline]
    pub fn vee(&self) -> Vector<T> {
        let m = &self.m;
        let h = T::lit(0.5);
        Vector::from_hidden(nalgebra::Vector3::new(
            (m[(2, 1)] - m[(1, 2)]) * h,
            (m[(0, 2)] - m[(2, 0)]) * h,
            (m[(1, 0)] - m[(0, 1)]) * h,
        ))
    }

    /// Projector along x⃗: P = x̂x̂′ (2.7). `None` for x⃗ = 0⃗.
    ///
    /// Book: §2.7.
    #[inline]
    pub fn projector_along(x: &Vector<T>) -> Option<Dyadic<T>> {
        let u = x.unit()?;
        Some(u.outer(&u))
    }

    /// Projector perpendicular to x⃗: I⃗ − x̂x̂′ (2.7). `None` for x⃗ = 0⃗.
    ///
    /// Book: §2.7.
    #[inline]
    pub fn projector_perp(x: &Vector<T>) -> Option<Dyadic<T>> {
        Self::projector_along(x).map(|p| Self::identity() - p)
    }

    /// Projector onto the plane spanned by x⃗ and y⃗: I⃗ − n̂n̂′ with n̂ ∥ x⃗×y⃗ (2.7). `None` when
    /// the vectors are parallel or zero (no plane).
    ///
    /// Book: §2.7.
    #[inline]
    pub fn projector_onto_plane(x: &Vector<T>, y: &Vector<T>) -> Option<Dyadic<T>> {
        Self::projector_perp(&x.cross(y))
    }

    /// Frobenius norm (frame independent for orthonormal frames).
    #[inline]
    pub fn norm(&self) -> T {
        self.m.norm()
    }

    /// `true` when every component is finite.
    #[inline]
    pub fn is_finite(&self) -> bool {
        crate::scalar::all_finite(self.m.as_slice())
    }
}

/// M⃗ x⃗: a dyadic applied to a vector.
impl<T: Scalar> Mul<Vector<T>> for Dyadic<T> {
    type Output = Vector<T>;
    #[inline(always)]
    fn mul(self, x: Vector<T>) -> Vector<T> {
        Vector { c: self.m * x.c }
    }
}

/// M⃗ N⃗: composition, (M N) x = M (N x).
impl<T: Scalar> Mul<Dyadic<T>> for Dyadic<T> {
    type Output = Dyadic<T>;
    #[inline(always)]
    fn mul(self, n: Dyadic<T>) -> Dyadic<T> {
        Dyadic { m: self.m * n.m }
    }
}

impl<T: Scalar> Mul<T> for Dyadic<T> {
    type Output = Dyadic<T>;
    #[inline(always)]
    fn mul(self, s: T) -> Dyadic<T> {
        Dyadic { m: self.m * s }
    }
}

impl<T: Scalar> Add for Dyadic<T> {
    type Output = Dyadic<T>;
    #[inline(always)]
    fn add(self, n: Dyadic<T>) -> Dyadic<T> {
        Dyadic { m: self.m + n.m }
    }
}

impl<T: Scalar> Sub for Dyadic<T> {
    type Output = Dyadic<T>;
    #[inline(always)]
    fn sub(self, n: Dyadic<T>) -> Dyadic<T> {
        Dyadic { m: self.m - n.m }
    }
}

impl<T: Scalar> Neg for Dyadic<T> {
    type Output = Dyadic<T>;
    #[inline(always)]
    fn neg(self) -> Dyadic<T> {
        Dyadic { m: -self.m }
    }
}
