//! Rotors (book §3.9): R = cos(θ/2) − sin(θ/2) 𝒥n̂, acting by the sandwich R x⃗ R̄.

use nalgebra::Vector3;

use crate::{Bivector, Dyadic, Multivector, Scalar, TensorError, Vector};

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
    /// `None` when the axis is zero or an input is not finite.
    ///
    /// Book: (3.9.1).
    #[inline]
    pub fn from_axis_angle(axis: &Vector<T>, theta: T) -> Option<Self> {
        if !theta.re().is_finite() || !axis.is_finite() {
            return None;
        }
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
        // With q⃗ = −β⃗ (B = 𝒥β⃗): t = 2q⃗×x = −2β⃗×x, x + q₀t + q⃗×t = x + q₀t − β⃗×t.
        let beta = &self.b.c;
        let t = beta.cross(&x.c) * T::lit(-2.0);
        Vector { c: x.c + t * self.s - beta.cross(&t) }
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
        // Fast path (the usual case, one branch): s² + |B|² neither underflows nor overflows.
        let n2 = self.s * self.s + self.b.c.norm_squared();
        if n2.re() > 1e-290 && n2.re() < 1e290 {
            let n = n2.sqrt();
            return Some(Rotor { s: self.s / n, b: self.b * (T::one() / n) });
        }
        // Scaled by the largest component first (as `Vector::unit`), so that components of
        // 1e±200 neither overflow nor underflow s² + |B|².
        let m = self.s.abs().max(self.b.c.x.abs()).max(self.b.c.y.abs()).max(self.b.c.z.abs());
        // (f64::max ignores NaN, so check every component)
        if m == T::zero() || !(self.s.re().is_finite() && self.b.is_finite()) {
            return None;
        }
        let (s, b) = (self.s / m, self.b.c / m);
        let n = (s * s + b.norm_squared()).sqrt();
        Some(Rotor { s: s / n, b: Bivector { c: b / n } })
    }
}

impl<T: Scalar> Rotor<T> {
    /// R_{v∧w}(θ) = cos(θ/2) − sin(θ/2) B̂ for the plane B̂ = (v⃗∧w⃗)/|v⃗∧w⃗| (3.9.1): the
    /// rotation by θ in that plane, turning v⃗ toward w⃗, about n̂ = v̂×ŵ (Fact 3.9.1). The
    /// vectors need not be orthonormal. `None` when they are parallel or zero (no plane).
    ///
    /// Book: (3.9.1)–(3.9.3), Fact 3.9.1.
    pub fn from_plane_angle(v: &Vector<T>, w: &Vector<T>, theta: T) -> Option<Self> {
        if !theta.re().is_finite() {
            return None;
        }
        let b_hat = v.wedge(w).unit()?;
        let h = theta * T::lit(0.5);
        Some(Self { s: h.cos(), b: b_hat * (-h.sin()) })
    }

    /// The product of two reflections ŵv̂ = ŵ·v̂ + ŵ∧v̂ (3.9.20–22): the rotor of the rotation
    /// by **twice** the angle from v̂ to ŵ about v̂×ŵ. Defined for every pair of nonzero vectors:
    /// parallel input gives 1 and anti-parallel input gives −1 (a full turn, the identity
    /// rotation). `None` when either vector is zero.
    ///
    /// Book: (3.9.20)–(3.9.22), Fact 3.9.4.
    pub fn from_two_vectors(v: &Vector<T>, w: &Vector<T>) -> Option<Self> {
        let (v, w) = (v.unit()?, w.unit()?);
        // ŵv̂ = ŵ·v̂ + ŵ∧v̂
        Some(Self { s: w.dot(&v), b: w.wedge(&v) })
    }

    /// The rotor of the smallest rotation taking the direction of v⃗ to that of w⃗: R = m̂v̂ with
    /// the halfway direction m̂ = (v̂+ŵ)/|v̂+ŵ| (half of (3.9.20)), so R v̂ R̄ = ŵ.
    ///
    /// Book: (3.9.20)–(3.9.22).
    ///
    /// # Degenerate inputs
    /// `None` when either vector is zero or they are anti-parallel: every half turn about an
    /// axis perpendicular to v⃗ qualifies; [`Rotor::between_or_half_turn`] picks one.
    pub fn between(v: &Vector<T>, w: &Vector<T>) -> Option<Self> {
        let (v, w) = (v.unit()?, w.unit()?);
        let m = (v + w).unit()?;
        // m̂v̂ = m̂·v̂ + m̂∧v̂
        Some(Self { s: m.dot(&v), b: m.wedge(&v) })
    }

    /// [`Rotor::between`], with a defined answer for anti-parallel input: the half turn about
    /// the part of `axis` perpendicular to v⃗, R = −𝒥n̂. `None` only for zero vectors or an
    /// `axis` parallel to v⃗ in the anti-parallel case.
    ///
    /// Book: (3.9.1) with θ = π.
    pub fn between_or_half_turn(v: &Vector<T>, w: &Vector<T>, axis: &Vector<T>) -> Option<Self> {
        if let Some(r) = Self::between(v, w) {
            return Some(r);
        }
        let v_hat = v.unit()?;
        w.unit()?;
        // Anti-parallel: half turn about n̂ ⟂ v⃗, R = cos(π/2) − sin(π/2)𝒥n̂.
        let n = (*axis - v_hat * v_hat.dot(axis)).unit()?;
        Some(Self { s: T::zero(), b: -Bivector::dual_of(&n) })
    }

    /// Exponential exp(B) = cos|B| + sin|B| B/|B| of a bivector (B² = −|B|²), so
    /// exp(−𝒥n̂θ/2) = R_n̂(θ) (3.9.3). Series for |B| < 10⁻⁴ (exact derivatives at 0).
    ///
    /// Book: (3.9.3), (3.9.22).
    pub fn exp(b: &Bivector<T>) -> Self {
        // φ² decides the branch (the series keeps exact derivatives at 0); when it overflows
        // (|B| ≥ 1e154) φ comes from the scaled norm, so exp(1e300 𝒥k̂) is finite.
        let phi2 = b.c.norm_squared();
        let (c, sinc) = if phi2.re() < 1e-8 {
            // cos φ ≈ 1 − φ²/2 + φ⁴/24, sin φ/φ ≈ 1 − φ²/6 + φ⁴/120 (error < 1e-27)
            let one = T::one();
            (
                one - phi2 * T::lit(0.5) + phi2 * phi2 / T::lit(24.0),
                one - phi2 / T::lit(6.0) + phi2 * phi2 / T::lit(120.0),
            )
        } else {
            let phi = if phi2.re().is_finite() { phi2.sqrt() } else { b.norm() };
            (phi.cos(), phi.sin() / phi)
        };
        Self { s: c, b: *b * sinc }
    }

    /// Logarithm of the rotation: the bivector B = −𝒥n̂θ/2 with eigenangle θ ∈ [0, π] and
    /// exp(B) = ±R (R and −R are the same rotation; the representative with scalar part ≥ 0 is
    /// used). θ/2 = atan2(|B_R|, |s|), never acos; series near 0.
    ///
    /// Book: (3.9.3), §3.9; DESIGN §4 for the canonical choice.
    ///
    /// # Degenerate inputs
    /// At θ = π (scalar part 0, or below 4ε|B| so that θ = π to rounding) n̂ and −n̂ give the
    /// same rotation; the axis returned has its first nonzero component positive in the
    /// reference basis (the frame `Frame::new()`).
    pub fn log(&self) -> Bivector<T> {
        let (s, mut b) = if self.s.re() < 0.0 { (-self.s, -self.b) } else { (self.s, self.b) };
        if s.re() <= 4.0 * T::eps() * b.c.norm().re() {
            // θ = π to rounding (|s| ≤ 4ε|B|, θ within ~1e-15 of π): canonical axis n̂ = −β⃗/|β⃗| with its first nonzero component positive.
            let n = -b.c;
            let first = [n.x, n.y, n.z].into_iter().find(|x| *x != T::zero());
            if first.is_some_and(|x| x.re() < 0.0) {
                b = -b;
            }
        }
        let n2 = b.c.norm_squared();
        // φ/|b| with φ = atan2(|b|, s); series (1/s)(1 − n²/(3s²)) for small |b|/s.
        let ratio = if n2.re() < 1e-10 * (s * s).re() {
            (T::one() - n2 / (T::lit(3.0) * s * s)) / s
        } else {
            let n = n2.sqrt();
            n.atan2(s) / n
        };
        b * ratio
    }

    /// Eigenangle θ = 2 atan2(|B|, |s|) ∈ [0, π] of the rotation (2.11.x, DESIGN §4).
    pub fn angle(&self) -> T {
        T::lit(2.0) * self.b.c.norm().atan2(self.s.abs())
    }

    /// Sandwich R x⃗ R̄ (Fact 3.9.1), the same as [`Rotor::rotate`]: Rodrigues's formula (2.11.1).
    ///
    /// Book: Fact 3.9.1, (2.11.1).
    #[inline]
    pub fn sandwich(&self, x: &Vector<T>) -> Vector<T> {
        self.rotate(x)
    }

    /// R B R̄ for a bivector: R(x⃗∧y⃗)R̄ = (Rx⃗R̄)∧(Ry⃗R̄) (3.9.9); B = 𝒥β⃗ rotates with β⃗.
    ///
    /// Book: (3.9.9).
    #[inline]
    pub fn sandwich_bivector(&self, b: &Bivector<T>) -> Bivector<T> {
        Bivector { c: self.rotate(&b.undual()).c }
    }

    /// R S R̄ for a general multivector, by geometric products (Fact 3.9.1).
    pub fn sandwich_multivector(&self, m: &Multivector<T>) -> Multivector<T> {
        let r = self.to_multivector();
        r.gp(m).gp(&r.reverse())
    }

    /// The rotor as an even multivector s + B.
    pub fn to_multivector(&self) -> Multivector<T> {
        Multivector::new(self.s, &Vector::zero(), &self.b, &crate::Trivector::zero())
    }

    /// The rotor of an even multivector with S S̄ = 1 within `tol` (relative), normalised.
    ///
    /// # Errors
    /// [`TensorError::OutOfRange`] when a grade-1 or grade-3 part or the defect |S S̄ − 1|
    /// exceeds `tol`; [`TensorError::NonFinite`] for non-finite components.
    pub fn from_multivector(m: &Multivector<T>, tol: f64) -> Result<Self, TensorError> {
        crate::check_tolerance(tol, "tol")?;
        if !m.is_finite() {
            return Err(TensorError::NonFinite { what: "multivector" });
        }
        let odd = m.v.norm().re().max(m.t.abs().re());
        let defect = (m.s * m.s + m.b.norm_squared() - T::one()).abs().re();
        if odd > tol || defect > tol {
            return Err(TensorError::OutOfRange {
                what: "rotor defect max(|odd part|, |S S̄ − 1|)",
                value: odd.max(defect),
                valid: "an even multivector with S S̄ = 1 within the tolerance",
            });
        }
        Self::from_parts_unchecked(m.s, Bivector { c: m.b })
            .normalize()
            .ok_or(TensorError::Zero { what: "rotor" })
    }

    /// Magnitude √(R R̄) = √(s² + |B|²) (1 for a rotor).
    pub fn norm(&self) -> T {
        (self.s * self.s + self.b.c.norm_squared()).sqrt()
    }
}

/// Reflection of x⃗ in the plane perpendicular to n⃗: −n̂x⃗n̂ = x⃗ − 2(n̂·x⃗)n̂ (3.9.17–18).
/// `None` when n⃗ is zero.
///
/// Book: (3.9.17), (3.9.18).
pub fn reflect<T: Scalar>(x: &Vector<T>, n: &Vector<T>) -> Option<Vector<T>> {
    let n = n.unit()?;
    Some(*x - n * (T::lit(2.0) * n.dot(x)))
}

/// Geometric product R₁R₂ of rotors (apply R₂ first): `r1 * r2` = [`Rotor::gp`], so
/// R_{C/A} = R_{C/B} R_{B/A} (2.10.44).
impl<T: Scalar> core::ops::Mul for Rotor<T> {
    type Output = Rotor<T>;
    #[inline]
    fn mul(self, r: Rotor<T>) -> Rotor<T> {
        self.gp(&r)
    }
}

impl<T: Scalar> Default for Rotor<T> {
    fn default() -> Self {
        Self::identity()
    }
}
