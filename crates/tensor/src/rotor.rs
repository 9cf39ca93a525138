//! Rotors (book §3.9): R = cos(θ/2) − sin(θ/2) 𝒥n̂, acting by the sandwich R x⃗ R̄.

use nalgebra::Vector3;

use crate::{Bivector, Dyadic, Scalar, Vector};

/// A rotor R = s + B, the even-grade element of Cl(3,0) with R R̄ = 1 (book §3.9).
///
/// From eigenaxis n̂ and eigenangle θ: R = cos(θ/2) − sin(θ/2)𝒥n̂ (3.9.1). The sandwich
/// R x⃗ R̄ rotates x⃗ by θ about n̂ with the right-hand rule, the same as Rodrigues's formula
/// (2.11.1). The Euler parameters are q₀ = s, q⃗ = −(bivector part undualized), so R = q₀ − 𝒥q⃗.
///
/// Book: §3.9, (3.9.1), (3.9.17).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotor<T: Scalar = f64> {
    pub(crate) s: T,
    pub(crate) b: Bivector<T>,
}

impl<T: Scalar> Rotor<T> {
    /// The identity rotor R = 1.
    #[inline]
    pub fn identity() -> Self {
        Self { s: T::one(), b: Bivector::zero() }
    }

    /// R = cos(θ/2) − sin(θ/2)𝒥n̂ for the axis `axis` (normalised here) and angle θ (3.9.1).
    /// `None` when the axis is zero.
    ///
    /// Book: (3.9.1).
    #[inline]
    pub fn from_axis_angle(axis: &Vector<T>, theta: T) -> Option<Self> {
        let n = axis.unit()?;
        let h = theta * T::lit(0.5);
        Some(Self { s: h.cos(), b: Bivector::dual_of(&n) * (-h.sin()) })
    }

    /// Scalar part cos(θ/2) (the Euler parameter η = q₀).
    #[inline]
    pub fn scalar(&self) -> T {
        self.s
    }

    /// Bivector part −sin(θ/2)𝒥n̂.
    #[inline]
    pub fn bivector(&self) -> Bivector<T> {
        self.b
    }

    /// Builds a rotor from its scalar and bivector parts without normalising; for hot paths
    /// that already hold a unit rotor. The caller guarantees s² + |B|² = 1.
    #[inline]
    pub fn from_parts_unchecked(s: T, b: Bivector<T>) -> Self {
        Self { s, b }
    }

    /// Reverse R̄ (the inverse of a unit rotor): the bivector part changes sign.
    #[inline]
    pub fn reverse(&self) -> Self {
        Self { s: self.s, b: -self.b }
    }

    /// The quaternion vector part q⃗ = −undual(B), as hidden components.
    #[inline(always)]
    fn qv(&self) -> Vector3<T> {
        -self.b.c
    }

    /// Sandwich R x⃗ R̄: rotates x⃗ (equal to Rodrigues's formula (2.11.1)).
    ///
    /// Book: §3.9; evaluated as x + 2q₀(q⃗×x) + 2q⃗×(q⃗×x), two cross products.
    #[inline]
    pub fn rotate(&self, x: &Vector<T>) -> Vector<T> {
        let q = self.qv();
        let t = q.cross(&x.c) * T::lit(2.0);
        Vector { c: x.c + t * self.s + q.cross(&t) }
    }

    /// Composition: `a.then(&b)` applies `a` first, then `b`; the result is the geometric
    /// product b a (book §3.9).
    #[inline]
    pub fn then(&self, second: &Rotor<T>) -> Rotor<T> {
        second.gp(self)
    }

    /// Geometric product `self` · `r` of two rotors (applying `r` first when used as a
    /// sandwich). In quaternion terms this is the Hamilton product of (s, q⃗).
    #[inline]
    pub fn gp(&self, r: &Rotor<T>) -> Rotor<T> {
        let (a0, a) = (self.s, self.qv());
        let (b0, b) = (r.s, r.qv());
        let s = a0 * b0 - a.dot(&b);
        let v = b * a0 + a * b0 + a.cross(&b);
        Rotor { s, b: Bivector { c: -v } }
    }

    /// The rotation dyad of the sandwich: (R x⃗ R̄) = D⃗ x⃗ (book §3.9, (2.11.x)).
    #[inline]
    pub fn to_dyadic(&self) -> Dyadic<T> {
        let q = self.qv();
        let s = self.s;
        let two = T::lit(2.0);
        let qq = q * q.transpose();
        let m = nalgebra::Matrix3::identity() * (s * s - q.dot(&q)) + qq * two + q.cross_matrix() * (two * s);
        Dyadic { m }
    }

    /// Normalises to R R̄ = 1; `None` for the zero element.
    #[inline]
    pub fn normalize(&self) -> Option<Rotor<T>> {
        let n = (self.s * self.s + self.b.c.norm_squared()).sqrt();
        if n == T::zero() || !n.re().is_finite() {
            return None;
        }
        Some(Rotor { s: self.s / n, b: self.b * (T::one() / n) })
    }
}

impl<T: Scalar> Default for Rotor<T> {
    fn default() -> Self {
        Self::identity()
    }
}
