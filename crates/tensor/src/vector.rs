//! Physical vectors (book §1.3, §2.1–2.3).
//!
//! A [`Vector`] has no components: it holds them in one hidden reference basis that no user
//! ever sees. Numbers come out only through `x.resolve(&frame)` and go in only through
//! `frame.vector([..])` (crate `vectrix-frames`, book (2.4.14–16)).

use core::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

use nalgebra::Vector3;

use crate::angle::wrap_angle;
use crate::{Covector, Dyadic, Scalar};

/// A physical vector x⃗ (book §1.3): a directed magnitude with no components and no location.
///
/// Book: §1.3, §2.1–2.3.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vector<T: Scalar = f64> {
    pub(crate) c: Vector3<T>,
}

impl<T: Scalar> Vector<T> {
    /// The zero vector 0⃗.
    ///
    /// Book: §1.3 (the zero vector 0⃗).
    #[inline]
    pub fn zero() -> Self {
        Self { c: Vector3::zeros() }
    }

    /// Dot product x⃗·y⃗ = |x||y|cos θ (2.1.1).
    ///
    /// Book: (2.1.1), (2.4.25).
    #[inline]
    pub fn dot(&self, y: &Vector<T>) -> T {
        self.c.dot(&y.c)
    }

    /// Cross product x⃗×y⃗ = |x||y| sin θ θ̂_{y/x} (2.2.4).
    ///
    /// Book: (2.2.4), (2.4.29–32).
    #[inline]
    pub fn cross(&self, y: &Vector<T>) -> Vector<T> {
        Vector { c: self.c.cross(&y.c) }
    }

    /// Magnitude |x⃗| (2.1.2), computed without overflow or underflow for huge or tiny
    /// components (scaled by the largest component).
    ///
    /// Book: (2.1.2), Fact 2.4.2.
    #[inline]
    pub fn norm(&self) -> T {
        let m = self.c.x.abs().max(self.c.y.abs()).max(self.c.z.abs());
        if m == T::zero() {
            // |x⃗| is not differentiable at 0⃗: the plain √(x·x) gives 0 for f64 and a NaN
            // derivative for dual numbers (instead of the derivative of max|xᵢ|, which would
            // make `gradient(|r| r.norm(), 0⃗)` return a made-up direction).
            return self.c.norm();
        }
        if !m.re().is_finite() {
            return m;
        }
        // Within the comfortable range the plain formula is exact enough and faster.
        let r = m.re();
        if r > 1e-150 && r < 1e150 {
            return self.c.norm();
        }
        (self.c / m).norm() * m
    }

    /// |x⃗|².
    ///
    /// Book: Fact 2.4.2 (x⃗′x⃗ = |x⃗|²).
    #[inline]
    pub fn norm_squared(&self) -> T {
        self.c.norm_squared()
    }

    /// Unit vector x̂ = x⃗/|x⃗|; `None` for the zero vector, where the book leaves it undefined.
    ///
    /// Book: §2.1.
    #[inline]
    pub fn unit(&self) -> Option<Vector<T>> {
        let n = self.norm();
        let r = n.re();
        if r > 1e-150 && r < 1e150 {
            return Some(*self / n);
        }
        // Outside the comfortable range divide by the largest component first: |x⃗| may
        // overflow (components near f64::MAX) or lose bits (subnormal components) although x̂
        // exists for every nonzero finite x⃗.
        let m = self.c.x.abs().max(self.c.y.abs()).max(self.c.z.abs());
        if m == T::zero() || !self.is_finite() {
            return None;
        }
        let s = *self / m;
        Some(s / s.c.norm())
    }

    /// Coform x⃗′, the covector with x⃗′y⃗ = x⃗·y⃗ (2.1.6).
    ///
    /// Book: (2.1.6), Fact 2.1.2.
    #[inline]
    pub fn coform(&self) -> Covector<T> {
        Covector { c: self.c }
    }

    /// Outer product x⃗ y⃗′, the dyad of (2.6.1).
    ///
    /// Book: (2.6.1), (2.6.15).
    #[inline]
    pub fn outer(&self, y: &Vector<T>) -> Dyadic<T> {
        Dyadic { m: self.c * y.c.transpose() }
    }

    /// Cross-product dyad x⃗^×, with x⃗^× y⃗ = x⃗ × y⃗ (2.9.1).
    ///
    /// Book: (2.9.1), Fact 2.9.1.
    #[inline]
    pub fn cross_dyad(&self) -> Dyadic<T> {
        Dyadic { m: self.c.cross_matrix() }
    }

    /// Undirected angle θ between x⃗ and y⃗ in [0, π], by atan2(|x×y|, x·y); 0 when either
    /// vector is zero (book L497).
    ///
    /// Book: (2.1.4), computed stably instead of by cos⁻¹ (accurate near 0 and π).
    ///
    /// # Degenerate inputs
    /// Tiny and huge magnitudes are safe: both vectors are first scaled by their largest
    /// component (the angle does not depend on length), so x·y and |x×y| never under- or
    /// overflow.
    #[inline]
    pub fn angle(&self, y: &Vector<T>) -> T {
        let (x, y) = (self.scaled_for_angle(), y.scaled_for_angle());
        // + 0 turns a signed zero −0 into +0: atan2(0, −0) would be π, the book wants 0 (L497).
        x.cross(&y).norm().atan2(x.dot(&y) + T::zero())
    }

    /// x⃗/max|x_i| (x⃗ itself when zero or non-finite): same direction, magnitude in [1, √3].
    #[inline]
    fn scaled_for_angle(&self) -> Vector<T> {
        let m = self.c.x.abs().max(self.c.y.abs()).max(self.c.z.abs());
        if m == T::zero() || !m.re().is_finite() { *self } else { *self / m }
    }

    /// Parallel or anti-parallel within `tol`: |x̂ × ŷ| ≤ tol (book (2.1.5): |x·y| = |x||y|).
    /// A zero vector is parallel to every vector.
    ///
    /// Book: (2.1.5).
    #[inline]
    pub fn is_parallel(&self, y: &Vector<T>, tol: f64) -> bool {
        match (self.unit(), y.unit()) {
            (Some(x), Some(y)) => x.cross(&y).norm().re() <= tol,
            _ => true,
        }
    }

    /// Perpendicular within `tol`: |x̂·ŷ| ≤ tol. A zero vector is perpendicular to every vector.
    ///
    /// Book: §2.1 (x·y = 0).
    #[inline]
    pub fn is_perpendicular(&self, y: &Vector<T>, tol: f64) -> bool {
        match (self.unit(), y.unit()) {
            (Some(x), Some(y)) => x.dot(&y).re().abs() <= tol,
            _ => true,
        }
    }

    /// Unit angle vector θ̂_{self/x} = x⃗×y⃗/|x⃗×y⃗| for y⃗ = `self` (2.2.7): aligned with x×y,
    /// curling x toward y. `None` when the vectors are parallel, anti-parallel or zero.
    ///
    /// Book: §2.2, (2.2.7); θ̂_{x/y} = −θ̂_{y/x} (2.2.2).
    #[inline]
    pub fn unit_angle_vector_rel(&self, x: &Vector<T>) -> Option<Vector<T>> {
        // Scaling first keeps x × y finite and nonzero for huge or tiny inputs.
        x.scaled_for_angle().cross(&self.scaled_for_angle()).unit()
    }

    /// Angle vector θ⃗_{self/x} = θ θ̂_{self/x} (2.2.1, 2.2.10). `None` where θ̂ is undefined.
    ///
    /// Book: (2.2.1), (2.2.10).
    #[inline]
    pub fn angle_vector_rel(&self, x: &Vector<T>) -> Option<Vector<T>> {
        self.unit_angle_vector_rel(x).map(|n| n * x.angle(self))
    }

    /// Directed angle θ_{self/x/n̂} in (−π, π] (2.3.1) about the normal `n` (perpendicular to
    /// both vectors, as the book requires; its length does not matter. For an `n` that is not
    /// perpendicular the result is the angle of the projections onto the plane ⊥ n̂): 0 for aligned vectors, +θ when n̂ = θ̂_{y/x},
    /// −θ when n̂ = −θ̂_{y/x}, and **π for anti-parallel vectors whatever n̂** (never −π).
    /// 0 when either vector is zero (atan2(0, 0) = 0, (2.3.9)). `None` when `n` is zero.
    ///
    /// Book: (2.3.1), (2.3.8–9).
    #[inline]
    pub fn directed_angle_rel(&self, x: &Vector<T>, n: &Vector<T>) -> Option<T> {
        if !(self.is_finite() && x.is_finite()) {
            return None;
        }
        let n_hat = n.unit()?;
        let (x, y) = (x.scaled_for_angle(), self.scaled_for_angle());
        // (2.3.8): θ = atan2(n̂·(x×y), x·y); + 0 maps −0 to +0 so that a zero vector gives 0
        // (2.3.9), not ±π from IEEE atan2(±0, −0).
        let theta = (n_hat.dot(&x.cross(&y)) + T::zero()).atan2(x.dot(&y) + T::zero());
        // Anti-parallel: atan2(−0, −1) = −π; the book's rule (2.3.1) gives +π.
        Some(wrap_angle(theta))
    }

    /// `true` when every component is finite.
    ///
    /// Book: DESIGN §5 (bad input).
    #[inline]
    pub fn is_finite(&self) -> bool {
        crate::scalar::all_finite(self.c.as_slice())
    }

    /// Projection along y⃗: P_y x⃗ = (x⃗·y⃗/|y⃗|²) y⃗ (2.7.7), computed as (x⃗·ŷ) ŷ. `None` for
    /// y⃗ = 0⃗ (P_y is undefined).
    ///
    /// Book: §2.7, (2.7.1), (2.7.7).
    #[inline]
    pub fn projection_along(&self, y: &Vector<T>) -> Option<Vector<T>> {
        let u = y.unit()?;
        // ŷ(ŷ·x⃗) with the dot product of x⃗/m scaled back, so that x⃗ near f64::MAX does not
        // overflow; `None` when x⃗ is not finite or the projection itself overflows.
        let p = u * u.dot(self);
        (self.is_finite() && p.is_finite()).then_some(p)
    }

    /// Projection perpendicular to y⃗: P_{y⊥} x⃗ = x⃗ − P_y x⃗ (2.7.2). `None` for y⃗ = 0⃗.
    ///
    /// Book: §2.7, (2.7.2).
    #[inline]
    pub fn projection_perp(&self, y: &Vector<T>) -> Option<Vector<T>> {
        self.projection_along(y).map(|p| *self - p)
    }

    /// Scalar triple product [x, y, z] = x·(y×z) (2.2.13).
    ///
    /// Book: (2.4.36–37), Fact 2.9.7.
    #[inline]
    pub fn triple(&self, y: &Vector<T>, z: &Vector<T>) -> T {
        self.dot(&y.cross(z))
    }
}

impl Vector<f64> {
    /// The same vector over another scalar type: `x.cast::<Dual64>()` lifts an f64 vector into
    /// dual numbers (derivative part zero), so frame-free inputs can enter a differentiated
    /// function (book §2.24).
    ///
    /// Book: §2.24.
    #[inline]
    pub fn cast<U: Scalar>(&self) -> Vector<U> {
        Vector { c: self.c.map(U::lit) }
    }
}

impl<T: Scalar> Default for Vector<T> {
    fn default() -> Self {
        Self::zero()
    }
}

impl<T: Scalar> Add for Vector<T> {
    type Output = Vector<T>;
    #[inline(always)]
    fn add(self, y: Vector<T>) -> Vector<T> {
        Vector { c: self.c + y.c }
    }
}

impl<T: Scalar> AddAssign for Vector<T> {
    #[inline(always)]
    fn add_assign(&mut self, y: Vector<T>) {
        self.c += y.c;
    }
}

impl<T: Scalar> Sub for Vector<T> {
    type Output = Vector<T>;
    #[inline(always)]
    fn sub(self, y: Vector<T>) -> Vector<T> {
        Vector { c: self.c - y.c }
    }
}

impl<T: Scalar> SubAssign for Vector<T> {
    #[inline(always)]
    fn sub_assign(&mut self, y: Vector<T>) {
        self.c -= y.c;
    }
}

impl<T: Scalar> Neg for Vector<T> {
    type Output = Vector<T>;
    #[inline(always)]
    fn neg(self) -> Vector<T> {
        Vector { c: -self.c }
    }
}

/// Scaling a⃗ s by a scalar on the right.
impl<T: Scalar> Mul<T> for Vector<T> {
    type Output = Vector<T>;
    #[inline(always)]
    fn mul(self, s: T) -> Vector<T> {
        Vector { c: self.c * s }
    }
}

/// Scaling s a⃗ by an `f64` on the left.
impl Mul<Vector<f64>> for f64 {
    type Output = Vector<f64>;
    #[inline(always)]
    fn mul(self, x: Vector<f64>) -> Vector<f64> {
        x * self
    }
}

impl<T: Scalar> Div<T> for Vector<T> {
    type Output = Vector<T>;
    #[inline(always)]
    fn div(self, s: T) -> Vector<T> {
        Vector { c: self.c / s }
    }
}
