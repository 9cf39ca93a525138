//! Bivectors of Cl(3,0) (book §3.8).

use core::ops::{Add, Mul, Neg, Sub};

use nalgebra::Vector3;

use crate::{Scalar, Tensor, TensorError, Vector};

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

    /// Area of the oriented plane element: |x⃗∧y⃗| = |x⃗||y⃗| sin θ = |x⃗×y⃗| (3.7.9–10). This is
    /// the book's magnitude, not the Frobenius norm of the dense array (√2 times larger).
    ///
    /// Book: (3.7.9), (3.7.10).
    #[inline]
    pub fn area(&self) -> T {
        self.norm()
    }

    /// The unit bivector B/|B| (the plane with unit area); `None` for the zero bivector.
    #[inline]
    pub fn unit(&self) -> Option<Bivector<T>> {
        self.undual().unit().map(|n| Bivector { c: n.c })
    }

    /// `true` when every component is finite.
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.undual().is_finite()
    }

    /// The dense alternating (2, 0) tensor of x⃗∧y⃗ = x⃗⊗y⃗ − y⃗⊗x⃗ (3.7.1): six nonzero
    /// entries ±b, determinant convention.
    ///
    /// Book: (3.7.1), (3.7.7).
    pub fn to_tensor(&self) -> Tensor<T> {
        let (x, y, z) = (self.c.x, self.c.y, self.c.z);
        let o = T::zero();
        // (x∧y)[a][b] = ε_abc (x×y)_c
        Tensor { p: 2, q: 0, data: vec![o, z, -y, -z, o, x, y, -x, o], limit: crate::DEFAULT_MAX_COMPONENTS }
    }

    /// The compressed bivector of a dense (2, 0) tensor, which must be alternating within
    /// `tol` relative to its largest component.
    ///
    /// # Errors
    /// [`TensorError::Shape`] for another type or a tensor that is not alternating.
    pub fn from_tensor(t: &Tensor<T>, tol: f64) -> Result<Bivector<T>, TensorError> {
        crate::check_tolerance(tol, "tol")?;
        if (t.p, t.q) != (2, 0) {
            return Err(TensorError::Shape {
                detail: format!("a bivector is a (2, 0) tensor, got ({}, {})", t.p, t.q),
            });
        }
        let b = Bivector { c: Vector3::new(t.data[5], t.data[6], t.data[1]) };
        crate::wedge::check_alternating(t, &b.to_tensor(), tol)?;
        Ok(b)
    }
}

impl<T: Scalar> Default for Bivector<T> {
    fn default() -> Self {
        Self::zero()
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
