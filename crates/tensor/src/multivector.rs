//! Multivectors of Cl(3,0) (book §3.8).
//!
//! A multivector is S = s + x⃗ + B + t𝒥 on the basis [1, î, ĵ, k̂, î∧ĵ, ĵ∧k̂, k̂∧î, 𝒥] (3.8.1).
//! vectrix stores the bivector by its dual vector β⃗ (B = 𝒥β⃗, (3.8.30)), so a multivector is
//! a pair of "complex" parts with 𝒥 as the imaginary unit, which commutes with everything
//! and squares to −1 (3.8.27): S = (s + t𝒥) + (x⃗ + 𝒥β⃗). The geometric product of vectors
//! x⃗y⃗ = x⃗·y⃗ + x⃗∧y⃗ = x⃗·y⃗ + 𝒥(x⃗×y⃗) (3.8.3, 3.8.32) then extends bilinearly:
//! (z₁ + u⃗)(z₂ + w⃗) = z₁z₂ + u⃗·w⃗ + z₁w⃗ + z₂u⃗ + 𝒥(u⃗×w⃗).

use core::ops::{Add, Mul, Neg, Sub};

use nalgebra::Vector3;

use crate::{Bivector, Scalar, Tensor, TensorError, Trivector, Vector};

/// A multivector s + x⃗ + B + t𝒥 of Cl(3,0) (book §3.8): grades 0–3 with 1, 3, 3, 1
/// components, frame-free like every kernel object.
///
/// Book: §3.8, (3.8.1), (3.8.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Multivector<T: Scalar = f64> {
    pub(crate) s: T,
    pub(crate) v: Vector3<T>,
    /// Dual vector of the bivector part: B = 𝒥β⃗.
    pub(crate) b: Vector3<T>,
    pub(crate) t: T,
}

impl<T: Scalar> Multivector<T> {
    /// The multivector s + x⃗ + B + T from its grade parts.
    pub fn new(s: T, x: &Vector<T>, b: &Bivector<T>, t: &Trivector<T>) -> Self {
        Self { s, v: x.c, b: b.c, t: t.t }
    }

    /// The zero multivector.
    pub fn zero() -> Self {
        Self { s: T::zero(), v: Vector3::zeros(), b: Vector3::zeros(), t: T::zero() }
    }

    /// The scalar s as a multivector (grade 0).
    pub fn scalar(s: T) -> Self {
        Self { s, ..Self::zero() }
    }

    /// The pseudoscalar 𝒥 = î∧ĵ∧k̂ (Fact 3.7.5).
    pub fn pseudoscalar() -> Self {
        Self { t: T::one(), ..Self::zero() }
    }

    /// Grade-0 part ⟨S⟩₀.
    pub fn scalar_part(&self) -> T {
        self.s
    }

    /// Grade-1 part ⟨S⟩₁.
    pub fn vector_part(&self) -> Vector<T> {
        Vector { c: self.v }
    }

    /// Grade-2 part ⟨S⟩₂.
    pub fn bivector_part(&self) -> Bivector<T> {
        Bivector { c: self.b }
    }

    /// Grade-3 part ⟨S⟩₃.
    pub fn trivector_part(&self) -> Trivector<T> {
        Trivector { t: self.t }
    }

    /// Grade projection ⟨S⟩_k, k ∈ 0..=3 (zero for k > 3, (3.8.28)).
    ///
    /// Book: (3.8.1), (3.8.28).
    pub fn grade(&self, k: usize) -> Self {
        let z = Self::zero();
        match k {
            0 => Self { s: self.s, ..z },
            1 => Self { v: self.v, ..z },
            2 => Self { b: self.b, ..z },
            3 => Self { t: self.t, ..z },
            _ => z,
        }
    }

    /// Geometric product S₁S₂ (3.8.3), associative, with ê_i² = 1 (Cl(3,0)), (î∧ĵ)² = 𝒥² = −1.
    ///
    /// Book: (3.8.3), (3.8.27), (3.8.38), Fig. 3.8.4 (with the fixes of the ch. 3 notes).
    #[inline]
    pub fn gp(&self, o: &Multivector<T>) -> Multivector<T> {
        let (v1, b1, v2, b2) = (&self.v, &self.b, &o.v, &o.b);
        // z₁z₂ + u⃗·w⃗, with u⃗·w⃗ = v₁·v₂ − β₁·β₂ + 𝒥(v₁·β₂ + β₁·v₂)
        let s = self.s * o.s - self.t * o.t + v1.dot(v2) - b1.dot(b2);
        let t = self.s * o.t + self.t * o.s + v1.dot(b2) + b1.dot(v2);
        // z₁w⃗ + z₂u⃗ + 𝒥(u⃗×w⃗), with 𝒥(u⃗×w⃗) = 𝒥(v₁×v₂ − β₁×β₂) − (v₁×β₂ + β₁×v₂)
        let v = v2 * self.s - b2 * self.t + v1 * o.s - b1 * o.t - v1.cross(b2) - b1.cross(v2);
        let b = b2 * self.s + v2 * self.t + b1 * o.s + v1 * o.t + v1.cross(v2) - b1.cross(b2);
        Multivector { s, v, b, t }
    }

    /// Outer (wedge) product S₁∧S₂ = Σ_{r,s} ⟨⟨S₁⟩_r⟨S₂⟩_s⟩_{r+s}, the determinant-convention
    /// wedge (3.7.17) extended to multivectors.
    ///
    /// Book: (3.7.17), (3.8.3).
    pub fn wedge(&self, o: &Multivector<T>) -> Multivector<T> {
        let mut out = Self::zero();
        for r in 0..=3 {
            for s in 0..=(3 - r) {
                out = out + self.grade(r).gp(&o.grade(s)).grade(r + s);
            }
        }
        out
    }

    /// Reverse S̃: grades 2 and 3 change sign ((x⃗y⃗)~ = y⃗x⃗).
    pub fn reverse(&self) -> Self {
        Self { s: self.s, v: self.v, b: -self.b, t: -self.t }
    }

    /// Grade involution Ŝ: grades 1 and 3 change sign.
    pub fn grade_involution(&self) -> Self {
        Self { s: self.s, v: -self.v, b: self.b, t: -self.t }
    }

    /// Clifford conjugate S̄ = (Ŝ)~: grades 1 and 2 change sign; an anti-automorphism.
    pub fn clifford_conjugate(&self) -> Self {
        Self { s: self.s, v: -self.v, b: -self.b, t: self.t }
    }

    /// The book's conjugate (3.8.41): every non-scalar component changes sign, 𝒥 included.
    /// On even elements (rotors) it equals the reverse and the Clifford conjugate; on general
    /// multivectors it is neither an automorphism nor an anti-automorphism, and for a vector
    /// S S̄ = −|x⃗|² (ch. 3 notes).
    ///
    /// Book: (3.8.41).
    pub fn book_conjugate(&self) -> Self {
        Self { s: self.s, v: -self.v, b: -self.b, t: -self.t }
    }

    /// Duality by the pseudoscalar: 𝒥S (= S𝒥, 𝒥 is central). 𝒥î = ĵ∧k̂, 𝒥ĵ = k̂∧î,
    /// 𝒥k̂ = î∧ĵ (3.8.30), 𝒥(î∧ĵ) = −k̂.
    ///
    /// Book: (3.8.27), (3.8.30)–(3.8.32).
    pub fn dual(&self) -> Self {
        // 𝒥(s + t𝒥) = −t + s𝒥; 𝒥(x⃗ + 𝒥β⃗) = −β⃗ + 𝒥x⃗
        Self { s: -self.t, v: -self.b, b: self.v, t: self.s }
    }

    /// Inverse of [`Multivector::dual`]: −𝒥S.
    pub fn undual(&self) -> Self {
        -self.dual()
    }

    /// Euclidean norm of the 8 components (the magnitudes of the grade parts in the area and
    /// volume convention, combined): √(⟨S S̃⟩₀).
    pub fn norm(&self) -> T {
        (self.s * self.s + self.v.norm_squared() + self.b.norm_squared() + self.t * self.t).sqrt()
    }

    /// The grade-k part expanded to its dense alternating (k, 0) tensor (determinant
    /// convention: x⃗∧y⃗ = x⃗⊗y⃗ − y⃗⊗x⃗, entries ±coefficient, never 1/k!); `None` for k > 3.
    ///
    /// Book: (3.7.1), (3.7.11), (3.8.1); ch. 3 notes §3 "Alternating sparsity".
    pub fn grade_tensor(&self, k: usize) -> Option<Tensor<T>> {
        match k {
            0 => Some(Tensor::scalar(self.s)),
            1 => Some(Tensor::from_vector(&self.vector_part())),
            2 => Some(self.bivector_part().to_tensor()),
            3 => Some(self.trivector_part().to_tensor()),
            _ => None,
        }
    }

    /// The multivector Σ of dense alternating (k, 0) tensors, k ∈ 0..=3, compressed
    /// (inverse of [`Multivector::grade_tensor`]); each must be alternating within `tol`
    /// relative to its largest component.
    ///
    /// # Errors
    /// [`TensorError::Shape`] for a tensor of mixed type, of order above 3, or not alternating.
    pub fn from_grade_tensors(parts: &[Tensor<T>], tol: f64) -> Result<Self, TensorError> {
        crate::check_tolerance(tol, "tol")?;
        let mut m = Self::zero();
        for t in parts {
            match (t.p, t.q) {
                (0, 0) => m.s += t.data[0],
                (1, 0) => m.v += nalgebra::Vector3::from_column_slice(&t.data),
                (2, 0) => m.b += Bivector::from_tensor(t, tol)?.c,
                (3, 0) => m.t += Trivector::from_tensor(t, tol)?.t,
                (p, q) => {
                    return Err(TensorError::Shape {
                        detail: format!(
                            "a multivector part is an alternating (k, 0) tensor with k ≤ 3, got ({p}, {q})"
                        ),
                    });
                }
            }
        }
        if !m.is_finite() {
            return Err(TensorError::NonFinite { what: "grade tensors" });
        }
        Ok(m)
    }

    /// `true` when every component is finite.
    pub fn is_finite(&self) -> bool {
        crate::scalar::all_finite(&[
            self.s, self.v.x, self.v.y, self.v.z, self.b.x, self.b.y, self.b.z, self.t,
        ])
    }
}

impl<T: Scalar> From<Vector<T>> for Multivector<T> {
    fn from(x: Vector<T>) -> Self {
        Self { v: x.c, ..Self::zero() }
    }
}

impl<T: Scalar> From<Bivector<T>> for Multivector<T> {
    fn from(b: Bivector<T>) -> Self {
        Self { b: b.c, ..Self::zero() }
    }
}

impl<T: Scalar> From<Trivector<T>> for Multivector<T> {
    fn from(t: Trivector<T>) -> Self {
        Self { t: t.t, ..Self::zero() }
    }
}

impl<T: Scalar> Vector<T> {
    /// Geometric product x⃗y⃗ = x⃗·y⃗ + x⃗∧y⃗ (3.8.3).
    ///
    /// Book: (3.8.3).
    #[inline]
    pub fn gp(&self, y: &Vector<T>) -> Multivector<T> {
        Multivector { s: self.dot(y), v: Vector3::zeros(), b: self.wedge(y).c, t: T::zero() }
    }
}

impl<T: Scalar> Default for Multivector<T> {
    fn default() -> Self {
        Self::zero()
    }
}

impl<T: Scalar> Add for Multivector<T> {
    type Output = Multivector<T>;
    fn add(self, o: Multivector<T>) -> Multivector<T> {
        Multivector { s: self.s + o.s, v: self.v + o.v, b: self.b + o.b, t: self.t + o.t }
    }
}

impl<T: Scalar> Sub for Multivector<T> {
    type Output = Multivector<T>;
    fn sub(self, o: Multivector<T>) -> Multivector<T> {
        Multivector { s: self.s - o.s, v: self.v - o.v, b: self.b - o.b, t: self.t - o.t }
    }
}

impl<T: Scalar> Neg for Multivector<T> {
    type Output = Multivector<T>;
    fn neg(self) -> Multivector<T> {
        Multivector { s: -self.s, v: -self.v, b: -self.b, t: -self.t }
    }
}

/// Scaling by a real number.
impl<T: Scalar> Mul<T> for Multivector<T> {
    type Output = Multivector<T>;
    fn mul(self, k: T) -> Multivector<T> {
        Multivector { s: self.s * k, v: self.v * k, b: self.b * k, t: self.t * k }
    }
}

/// The geometric product S₁ * S₂ = [`Multivector::gp`] (left factor first, as printed).
impl<T: Scalar> Mul for Multivector<T> {
    type Output = Multivector<T>;
    fn mul(self, o: Multivector<T>) -> Multivector<T> {
        self.gp(&o)
    }
}
