//! Trivectors of Cl(3,0) (book §3.7–3.8): multiples t𝒥 of the pseudoscalar.

use core::ops::{Add, Mul, Neg, Sub};

use crate::{Scalar, Tensor, TensorError};

/// A trivector t𝒥 (book §3.7): an oriented volume element, a multiple of the pseudoscalar
/// 𝒥 = î∧ĵ∧k̂, which is the same for every right-handed frame (Fact 3.7.5).
///
/// Book: §3.7, (3.7.20)–(3.7.26), Fact 3.7.5.
///
/// # Conventions
/// Determinant convention (3.7.17): x⃗∧y⃗∧z⃗ = det[x y z] 𝒥 with coefficient 1, so
/// [`Trivector::volume`] is |det[x y z]|, not the Frobenius norm of the dense array (which is
/// √6 times larger, (3.7.26)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trivector<T: Scalar = f64> {
    pub(crate) t: T,
}

impl<T: Scalar> Trivector<T> {
    /// The pseudoscalar 𝒥 = î∧ĵ∧k̂ (Fact 3.7.5).
    ///
    /// Book: Fact 3.7.5, (3.8.27).
    #[doc(alias = "pseudoscalar")]
    pub fn j() -> Self {
        Self { t: T::one() }
    }

    /// The zero trivector.
    pub fn zero() -> Self {
        Self { t: T::zero() }
    }

    /// The trivector t𝒥.
    pub fn new(t: T) -> Self {
        Self { t }
    }

    /// The coefficient t of t𝒥 (frame-free: 𝒥 is the same in every right-handed frame).
    pub fn coefficient(&self) -> T {
        self.t
    }

    /// Volume |t| of the oriented volume element: |x⃗∧y⃗∧z⃗| = |det[x y z]| (3.7.23).
    ///
    /// Book: (3.7.23).
    pub fn volume(&self) -> T {
        self.t.abs()
    }

    /// The dense alternating (3, 0) tensor t Σ ε_abc ê_a⊗ê_b⊗ê_c, in the determinant
    /// convention (entries ±t, never t/6).
    ///
    /// Book: (3.7.11), (3.7.20).
    pub fn to_tensor(&self) -> Tensor<T> {
        let data = (0..27)
            .map(|k| T::lit(f64::from(crate::tensor::levi_civita_symbol(k / 9, (k / 3) % 3, k % 3))) * self.t)
            .collect();
        Tensor { p: 3, q: 0, data, limit: crate::DEFAULT_MAX_COMPONENTS }
    }

    /// The compressed trivector of a dense (3, 0) tensor, which must be alternating within
    /// `tol` (absolute, on each component, relative to the largest component).
    ///
    /// # Errors
    /// [`TensorError::Shape`] for another type or a tensor that is not alternating.
    pub fn from_tensor(t: &Tensor<T>, tol: f64) -> Result<Self, TensorError> {
        crate::check_tolerance(tol, "tol")?;
        if (t.p, t.q) != (3, 0) {
            return Err(TensorError::Shape {
                detail: format!("a trivector is a (3, 0) tensor, got ({}, {})", t.p, t.q),
            });
        }
        if !t.is_finite() {
            return Err(TensorError::NonFinite { what: "tensor components" });
        }
        let tri = Self { t: t.data[5] };
        crate::wedge::check_alternating(t, &tri.to_tensor(), tol)?;
        Ok(tri)
    }
}

impl<T: Scalar> Add for Trivector<T> {
    type Output = Trivector<T>;
    #[inline(always)]
    fn add(self, o: Trivector<T>) -> Trivector<T> {
        Trivector { t: self.t + o.t }
    }
}

impl<T: Scalar> Sub for Trivector<T> {
    type Output = Trivector<T>;
    #[inline(always)]
    fn sub(self, o: Trivector<T>) -> Trivector<T> {
        Trivector { t: self.t - o.t }
    }
}

impl<T: Scalar> Neg for Trivector<T> {
    type Output = Trivector<T>;
    #[inline(always)]
    fn neg(self) -> Trivector<T> {
        Trivector { t: -self.t }
    }
}

impl<T: Scalar> Mul<T> for Trivector<T> {
    type Output = Trivector<T>;
    #[inline(always)]
    fn mul(self, s: T) -> Trivector<T> {
        Trivector { t: self.t * s }
    }
}
