//! The small Lie-group interface the Lie-group integrators need.

use nalgebra::SVector;
use vectrix_tensor::{Bivector, Rotor, Vector};

/// A Lie group G with its algebra 𝔤: the exponential map, the group product, the bracket
/// and linear combinations in 𝔤. The integrators solve y′ = y·ξ(t, y) (ξ ∈ 𝔤, the
/// right-trivialized or "body" form), whose exact flow for constant ξ is y(t + h) = y·exp(hξ).
///
/// Book: §4.11 (attitude rate equations), §3.9 (rotors); HLW §IV.8 (Lie-group methods).
pub trait LieGroup: Clone {
    /// Elements ξ of the Lie algebra 𝔤.
    type Algebra: Clone;
    /// The exponential map exp: 𝔤 → G.
    fn exp(xi: &Self::Algebra) -> Self;
    /// The group product `self`·`rhs`.
    fn compose(&self, rhs: &Self) -> Self;
    /// The Lie bracket [a, b].
    fn bracket(a: &Self::Algebra, b: &Self::Algebra) -> Self::Algebra;
    /// a + c·b in 𝔤.
    fn axpy(a: &Self::Algebra, c: f64, b: &Self::Algebra) -> Self::Algebra;
    /// c·ξ in 𝔤.
    fn scale(c: f64, xi: &Self::Algebra) -> Self::Algebra;
    /// Largest |component| of a state, for non-finite checks (`f64::NAN` when not finite).
    fn magnitude(&self) -> f64;
    /// Largest |component| of an algebra element (`f64::NAN` when not finite).
    fn algebra_magnitude(xi: &Self::Algebra) -> f64;
}

/// Rotors with body angular velocity: 𝔤 = physical vectors ϕ⃗ (rotation vectors),
/// exp(ϕ⃗) = exp(−½𝒥ϕ⃗) = cos(|ϕ|/2) − sin(|ϕ|/2)𝒥ϕ̂ (3.9.1, 3.9.3; [`Rotor::exp`]), product = geometric product, bracket =
/// cross product. y′ = y·ξ is the body form Ṙ = R(−½𝒥ω⃗_b) with ω⃗_b = R̄ω⃗R, the angular
/// velocity pulled back to the reference frame: ω⃗_b resolved in A has the components of
/// ω⃗_{B/A} resolved in B (the book's ω_B in (4.11.13)).
///
/// The product of two unit rotors is renormalised: this removes the O(ε) round-off drift
/// of |R| per step and nothing else (the truncation error of a Lie-group method never
/// leaves the group).
///
/// Book: §3.9, (3.9.1); §4.11, (4.11.13), (4.11.17).
impl LieGroup for Rotor<f64> {
    type Algebra = Vector<f64>;

    #[inline]
    fn exp(phi: &Vector<f64>) -> Self {
        // exp(ϕ⃗) = exp(−½𝒥ϕ⃗) = cos(|ϕ|/2) − sin(|ϕ|/2)𝒥ϕ̂ (3.9.3), the kernel's rotor exponential
        Rotor::exp(&(Bivector::dual_of(phi) * -0.5))
    }

    #[inline]
    fn compose(&self, rhs: &Self) -> Self {
        let r = self.gp(rhs);
        r.normalize().unwrap_or(r)
    }

    #[inline]
    fn bracket(a: &Vector<f64>, b: &Vector<f64>) -> Vector<f64> {
        // [a, b] of so(3) ≅ (ℝ³, ×)
        a.cross(b)
    }

    #[inline]
    fn axpy(a: &Vector<f64>, c: f64, b: &Vector<f64>) -> Vector<f64> {
        *a + *b * c
    }
    #[inline]
    fn scale(c: f64, xi: &Vector<f64>) -> Vector<f64> {
        *xi * c
    }

    fn magnitude(&self) -> f64 {
        let s = self.scalar();
        let b = self.bivector().norm();
        if s.is_finite() && b.is_finite() { s.abs().max(b) } else { f64::NAN }
    }

    fn algebra_magnitude(xi: &Vector<f64>) -> f64 {
        let n = xi.norm();
        if n.is_finite() { n } else { f64::NAN }
    }
}

/// ℝⁿ under addition: exp(ξ) = ξ, product = sum, bracket = 0. Makes a vector-space part of
/// a state (angular velocity, position) a factor of a product group.
///
/// Book: HLW §IV.8 (vector spaces are abelian Lie groups).
impl<const N: usize> LieGroup for SVector<f64, N> {
    type Algebra = SVector<f64, N>;

    #[inline]
    fn exp(xi: &Self) -> Self {
        *xi
    }
    #[inline]
    fn compose(&self, rhs: &Self) -> Self {
        self + rhs
    }
    #[inline]
    fn bracket(_: &Self, _: &Self) -> Self {
        Self::zeros()
    }
    #[inline]
    fn axpy(a: &Self, c: f64, b: &Self) -> Self {
        a + b * c
    }
    #[inline]
    fn scale(c: f64, xi: &Self) -> Self {
        xi * c
    }
    fn magnitude(&self) -> f64 {
        if self.iter().all(|v| v.is_finite()) { self.amax() } else { f64::NAN }
    }
    fn algebra_magnitude(xi: &Self) -> f64 {
        xi.magnitude()
    }
}

/// ℝ³ physical vectors under addition (as for [`SVector`]).
///
/// Book: HLW §IV.8.
impl LieGroup for Vector<f64> {
    type Algebra = Vector<f64>;

    #[inline]
    fn exp(xi: &Self) -> Self {
        *xi
    }
    #[inline]
    fn compose(&self, rhs: &Self) -> Self {
        *self + *rhs
    }
    #[inline]
    fn bracket(_: &Self, _: &Self) -> Self {
        Vector::zero()
    }
    #[inline]
    fn axpy(a: &Self, c: f64, b: &Self) -> Self {
        *a + *b * c
    }
    #[inline]
    fn scale(c: f64, xi: &Self) -> Self {
        *xi * c
    }
    fn magnitude(&self) -> f64 {
        let n = self.norm();
        if n.is_finite() { n } else { f64::NAN }
    }
    fn algebra_magnitude(xi: &Self) -> f64 {
        xi.magnitude()
    }
}

/// The direct product G × H (attitude × angular velocity): componentwise everything.
///
/// Book: HLW §IV.8.
impl<G: LieGroup, H: LieGroup> LieGroup for (G, H) {
    type Algebra = (G::Algebra, H::Algebra);

    #[inline]
    fn exp(xi: &Self::Algebra) -> Self {
        (G::exp(&xi.0), H::exp(&xi.1))
    }
    #[inline]
    fn compose(&self, rhs: &Self) -> Self {
        (self.0.compose(&rhs.0), self.1.compose(&rhs.1))
    }
    #[inline]
    fn bracket(a: &Self::Algebra, b: &Self::Algebra) -> Self::Algebra {
        (G::bracket(&a.0, &b.0), H::bracket(&a.1, &b.1))
    }
    #[inline]
    fn axpy(a: &Self::Algebra, c: f64, b: &Self::Algebra) -> Self::Algebra {
        (G::axpy(&a.0, c, &b.0), H::axpy(&a.1, c, &b.1))
    }
    #[inline]
    fn scale(c: f64, xi: &Self::Algebra) -> Self::Algebra {
        (G::scale(c, &xi.0), H::scale(c, &xi.1))
    }
    fn magnitude(&self) -> f64 {
        nan_max(self.0.magnitude(), self.1.magnitude())
    }
    fn algebra_magnitude(xi: &Self::Algebra) -> f64 {
        nan_max(G::algebra_magnitude(&xi.0), H::algebra_magnitude(&xi.1))
    }
}

/// max that propagates NaN (f64::max drops it).
fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() { f64::NAN } else { a.max(b) }
}
