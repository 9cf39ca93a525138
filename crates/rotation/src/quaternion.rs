//! Hamilton quaternions 𝐪 = a + b𝐢 + c𝐣 + d𝐤 and their algebra (book §2.16).
//!
//! 𝐢² = 𝐣² = 𝐤² = −1, 𝐢𝐣 = 𝐤 = −𝐣𝐢, 𝐣𝐤 = 𝐢, 𝐤𝐢 = 𝐣 (2.16.1): **Hamilton, scalar first**,
//! the same algebra as nalgebra's `Quaternion` (whose storage is scalar-last, `[i, j, k, w]`).
//! Rotation-specific methods (Euler parameters) are in `euler_parameters.rs`.

use core::ops::{Add, Mul, Neg, Sub};

use nalgebra::{Matrix4, Vector3, Vector4};
use vectrix_tensor::Scalar;

use crate::series::{norm3, sinc};

/// A Hamilton quaternion 𝐪 = a + b𝐢 + c𝐣 + d𝐤 (2.16.3), scalar first.
///
/// As Euler parameters of a rotation (§2.15) a = η = cos(θ/2) and (b, c, d) = ε = sin(θ/2) n̂,
/// with the canonical sign η ≥ 0; see [`Quaternion::from_rotation_matrix`].
///
/// Book: §2.15–2.16, (2.15.20), (2.16.3).
#[derive(Debug, Clone, Copy, PartialEq)]
#[doc(alias = "EulerParameters")]
#[doc(alias = "quat")]
pub struct Quaternion<T: Scalar = f64> {
    /// Scalar part a (= η).
    pub a: T,
    /// 𝐢 part b (= ε₁).
    pub b: T,
    /// 𝐣 part c (= ε₂).
    pub c: T,
    /// 𝐤 part d (= ε₃).
    pub d: T,
}

impl<T: Scalar> Quaternion<T> {
    /// 𝐪 = a + b𝐢 + c𝐣 + d𝐤 (2.16.3).
    #[inline]
    pub fn new(a: T, b: T, c: T, d: T) -> Self {
        Self { a, b, c, d }
    }

    /// 1, the identity rotation's Euler parameters [1, 0, 0, 0] (book §2.15).
    #[inline]
    pub fn identity() -> Self {
        Self::new(T::one(), T::zero(), T::zero(), T::zero())
    }

    /// From the scalar part η and the vector part ε: 𝐪 = [η; ε] (2.15.20).
    #[inline]
    pub fn from_parts(eta: T, epsilon: Vector3<T>) -> Self {
        Self::new(eta, epsilon.x, epsilon.y, epsilon.z)
    }

    /// A pure quaternion [0; v] (book §2.16, Prob 2.26.23).
    #[inline]
    pub fn pure(v: Vector3<T>) -> Self {
        Self::from_parts(T::zero(), v)
    }

    /// Scalar part η = a.
    #[inline]
    pub fn eta(&self) -> T {
        self.a
    }

    /// Vector part ε = (b, c, d).
    #[inline]
    pub fn epsilon(&self) -> Vector3<T> {
        Vector3::new(self.b, self.c, self.d)
    }

    /// [a, b, c, d] as a column (the book's q ∈ ℝ⁴, scalar first).
    #[inline]
    pub fn to_vector4(&self) -> Vector4<T> {
        Vector4::new(self.a, self.b, self.c, self.d)
    }

    /// Conjugate 𝐪̄ = a − b𝐢 − c𝐣 − d𝐤 (book §2.16). Note conj(𝐪₂𝐪₁) = 𝐪̄₁𝐪̄₂: the printed
    /// (2.16.8) has the order wrong (notes ch2b, erratum).
    #[inline]
    pub fn conjugate(&self) -> Self {
        Self::new(self.a, -self.b, -self.c, -self.d)
    }

    /// Squared norm 𝐪𝐪̄ = a² + b² + c² + d².
    #[inline]
    pub fn norm_squared(&self) -> T {
        self.a * self.a + self.b * self.b + self.c * self.c + self.d * self.d
    }

    /// Norm |𝐪| = √(𝐪𝐪̄) (book §2.16).
    #[inline]
    pub fn norm(&self) -> T {
        let n2 = self.norm_squared();
        let r = n2.re();
        // Fast path: |q|² neither underflows nor overflows.
        if r > 1e-290 && r < 1e290 {
            return n2.sqrt();
        }
        // Scaled by the largest component (as `Vector::norm`): exact for 1e±300 components.
        let m = self.max_abs();
        if m == T::zero() || !m.re().is_finite() {
            return n2.sqrt();
        }
        self.div_by(m).norm_squared().sqrt() * m
    }

    /// The largest |component|.
    #[inline]
    fn max_abs(&self) -> T {
        self.a.abs().max(self.b.abs()).max(self.c.abs()).max(self.d.abs())
    }

    /// Every component divided by `m` (a division, not a multiplication by 1/m, which
    /// overflows for subnormal m).
    #[inline]
    fn div_by(&self, m: T) -> Self {
        Self::new(self.a / m, self.b / m, self.c / m, self.d / m)
    }

    /// Inverse 𝐪⁻¹ = 𝐪̄/|𝐪|²; `None` for 𝐪 = 0.
    #[inline]
    pub fn inverse(&self) -> Option<Self> {
        // 𝐪⁻¹ = 𝐪̄/|𝐪|²; fast path when |𝐪|² is in range (the usual case, one branch)
        let n2 = self.norm_squared();
        let r = n2.re();
        if r > 1e-290 && r < 1e290 {
            return Some(self.conjugate() * (T::one() / n2));
        }
        // otherwise scaled so that |𝐪|² never leaves the range
        let n = self.norm();
        if n == T::zero() || !n.re().is_finite() {
            return None;
        }
        // u = 𝐪/m has |u| ∈ [1, 2]: 𝐪⁻¹ = ū/(|u|² m)
        let m = self.max_abs();
        let u = self.div_by(m);
        let inv = u.conjugate().div_by(u.norm_squared()).div_by(m);
        inv.to_vector4().iter().all(|x| x.re().is_finite()).then_some(inv)
    }

    /// 𝐪/|𝐪|; `None` for 𝐪 = 0 or non-finite components.
    #[inline]
    pub fn normalize(&self) -> Option<Self> {
        // Fast path (the usual case, one branch): |𝐪|² neither underflows nor overflows.
        let n2 = self.norm_squared();
        let r = n2.re();
        if r > 1e-290 && r < 1e290 {
            return Some(*self * (T::one() / n2.sqrt()));
        }
        // Scale by the largest component first (as `Vector::unit`): (1e200, 1e200, 0, 0) and
        // (1e-200, …) normalise exactly instead of overflowing or underflowing |𝐪|².
        let m = self.max_abs();
        // (f64::max ignores NaN, so check every component)
        if m == T::zero() || !self.to_vector4().iter().all(|x| x.re().is_finite()) {
            return None;
        }
        let s = self.div_by(m);
        Some(s.div_by(s.norm_squared().sqrt()))
    }

    /// Euclidean inner product a₁a₂ + b₁b₂ + c₁c₂ + d₁d₂ (cos of half the angle between two
    /// unit quaternions).
    #[inline]
    pub fn dot(&self, p: &Quaternion<T>) -> T {
        self.a * p.a + self.b * p.b + self.c * p.c + self.d * p.d
    }

    /// Left-multiplication matrix Q(𝐪): Q(𝐪) p = 𝐪𝐩 (2.15.33, 2.16.6), with Q(𝐪₂𝐪₁) =
    /// Q(𝐪₂)Q(𝐪₁) and det Q = |𝐪|⁴.
    ///
    /// Book: (2.15.33), (2.16.6).
    #[inline]
    pub fn left_matrix(&self) -> Matrix4<T> {
        let (a, b, c, d) = (self.a, self.b, self.c, self.d);
        #[rustfmt::skip]
        let q = Matrix4::new(
            a, -b, -c, -d,
            b,  a, -d,  c,
            c,  d,  a, -b,
            d, -c,  b,  a,
        );
        q
    }

    /// Right-multiplication matrix: Q̃(𝐪) p = 𝐩𝐪.
    ///
    /// Book: §2.16 (the companion of (2.16.6)).
    #[inline]
    pub fn right_matrix(&self) -> Matrix4<T> {
        let (a, b, c, d) = (self.a, self.b, self.c, self.d);
        #[rustfmt::skip]
        let q = Matrix4::new(
            a, -b, -c, -d,
            b,  a,  d, -c,
            c, -d,  a,  b,
            d,  c, -b,  a,
        );
        q
    }

    /// Exponential e^𝐪 = eᵃ (cos|v| + (sin|v|/|v|) v) (Prob 2.26.22, series near |v| = 0).
    ///
    /// Book: Prob 2.26.22: e^{𝐪/2} of a pure quaternion is a unit quaternion.
    pub fn exp(&self) -> Self {
        let v = self.epsilon();
        let t = norm3(&v);
        let ea = self.a.exp();
        Self::from_parts(ea * t.cos(), v * (ea * sinc(t)))
    }

    /// Principal logarithm ln 𝐪 = ln|𝐪| + (atan2(|v|, a)/|v|) v; `None` for 𝐪 = 0. For a
    /// negative real 𝐪 (v = 0, a < 0) the vector part is π along +𝐢 (a documented choice: every
    /// unit direction is a logarithm there).
    ///
    /// Book: inverse of Prob 2.26.22; the angle by atan2, never acos (notes ch2b §3.5).
    pub fn ln(&self) -> Option<Self> {
        let n = self.norm();
        if n == T::zero() || !n.re().is_finite() {
            return None;
        }
        let v = self.epsilon();
        let s = norm3(&v);
        let phi = s.atan2(self.a);
        let v = if s == T::zero() {
            if self.a < T::zero() { Vector3::new(T::pi(), T::zero(), T::zero()) } else { v }
        } else {
            // v̂ φ: divide first, so that a subnormal |v| does not overflow φ/|v|
            (v / s) * phi
        };
        Some(Self::from_parts(n.ln(), v))
    }
}

impl<T: Scalar> Default for Quaternion<T> {
    fn default() -> Self {
        Self::identity()
    }
}

/// Hamilton product 𝐪₂𝐪₁ = (a₂a₁ − v₂·v₁, a₂v₁ + a₁v₂ + v₂×v₁) (2.16.10).
impl<T: Scalar> Mul for Quaternion<T> {
    type Output = Quaternion<T>;
    #[inline(always)]
    fn mul(self, q: Quaternion<T>) -> Quaternion<T> {
        let p = self;
        Quaternion {
            a: p.a * q.a - p.b * q.b - p.c * q.c - p.d * q.d,
            b: p.a * q.b + p.b * q.a + p.c * q.d - p.d * q.c,
            c: p.a * q.c - p.b * q.d + p.c * q.a + p.d * q.b,
            d: p.a * q.d + p.b * q.c - p.c * q.b + p.d * q.a,
        }
    }
}

/// Scaling by a real number.
impl<T: Scalar> Mul<T> for Quaternion<T> {
    type Output = Quaternion<T>;
    #[inline(always)]
    fn mul(self, s: T) -> Quaternion<T> {
        Quaternion::new(self.a * s, self.b * s, self.c * s, self.d * s)
    }
}

impl<T: Scalar> Add for Quaternion<T> {
    type Output = Quaternion<T>;
    #[inline(always)]
    fn add(self, q: Quaternion<T>) -> Quaternion<T> {
        Quaternion::new(self.a + q.a, self.b + q.b, self.c + q.c, self.d + q.d)
    }
}

impl<T: Scalar> Sub for Quaternion<T> {
    type Output = Quaternion<T>;
    #[inline(always)]
    fn sub(self, q: Quaternion<T>) -> Quaternion<T> {
        Quaternion::new(self.a - q.a, self.b - q.b, self.c - q.c, self.d - q.d)
    }
}

impl<T: Scalar> Neg for Quaternion<T> {
    type Output = Quaternion<T>;
    #[inline(always)]
    fn neg(self) -> Quaternion<T> {
        Quaternion::new(-self.a, -self.b, -self.c, -self.d)
    }
}
