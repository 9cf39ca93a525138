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
    ///
    /// Book: §2.6.
    #[inline]
    pub fn zero() -> Self {
        Self { m: Matrix3::zeros() }
    }

    /// The identity I⃗ = F_A 𝓕′_A, the same for every frame A (2.8.1, Fact 2.8.1).
    ///
    /// Book: (2.8.1), Fact 2.8.1.
    #[inline]
    pub fn identity() -> Self {
        Self { m: Matrix3::identity() }
    }

    /// M⃗ x⃗.
    ///
    /// Book: Fact 2.6.2, (2.6.17).
    #[inline]
    pub fn apply(&self, x: &Vector<T>) -> Vector<T> {
        Vector { c: self.m * x.c }
    }

    /// Coform M⃗′, the transpose analogue: (x⃗y⃗′)′ = y⃗x⃗′ (2.6.9).
    ///
    /// Book: (2.6.9–12), Fact 2.6.5.
    #[inline]
    pub fn coform(&self) -> Dyadic<T> {
        Dyadic { m: self.m.transpose() }
    }

    /// Trace tr M⃗, independent of the frame it is resolved in (Fact 2.6.x).
    ///
    /// Book: (2.10.50–51), (2.10.54).
    #[inline]
    pub fn trace(&self) -> T {
        self.m.trace()
    }

    /// Determinant det M⃗, independent of the frame (book §2.6).
    ///
    /// Book: (2.10.52–53), (2.10.57).
    #[inline]
    pub fn determinant(&self) -> T {
        self.m.determinant()
    }

    /// Inverse M⃗⁻¹, by the adjugate of M⃗/‖M⃗‖ (exact for 3 × 3 and differentiable for dual
    /// numbers); (M⃗⁻¹)|_A = (M⃗|_A)⁻¹ (Fact 2.6.5).
    ///
    /// Book: §2.6, Fact 2.6.5.
    ///
    /// # Errors
    /// [`TensorError::NonFinite`] for NaN/∞; [`TensorError::Singular`] when
    /// |det(M⃗/s)| ≤ `rel_tol` with s the largest |entry| of M⃗ resolved in any frame of the
    /// hidden basis (scale-free, so the test does not depend on units and does not overflow
    /// for huge or tiny entries). The reported `det` is that of the scaled dyadic.
    pub fn inverse(&self, rel_tol: f64) -> Result<Dyadic<T>, TensorError> {
        crate::check_tolerance(rel_tol, "rel_tol")?;
        if !self.is_finite() {
            return Err(TensorError::NonFinite { what: "dyadic" });
        }
        let scale = self.max_abs();
        if scale == T::zero() {
            return Err(TensorError::Singular { det: 0.0, tol: rel_tol });
        }
        // Work with M/s, s = max|M_ij|, so that det neither over- nor underflows: M⁻¹ = (M/s)⁻¹/s.
        let m = self.m / scale;
        let det = m.determinant();
        if det.re().abs() <= rel_tol {
            return Err(TensorError::Singular { det: det.re(), tol: rel_tol });
        }
        let adj = adjugate(&m);
        // (adj/det)/s: det·s underflows for a tiny s while the quotient is representable
        let inv = Dyadic { m: adj / det / scale };
        if !inv.is_finite() {
            // a nonsingular M whose inverse exceeds f64::MAX (det·s subnormal)
            return Err(TensorError::Overflow { what: "inverse dyadic" });
        }
        Ok(inv)
    }

    /// Symmetric part ½(M⃗ + M⃗′).
    ///
    /// Book: §2.6 (symmetric M⃗′ = M⃗).
    #[inline]
    pub fn symmetric_part(&self) -> Dyadic<T> {
        // ½M + ½Mᵀ: no overflow of M + Mᵀ for entries near f64::MAX
        let h = self.m * T::lit(0.5);
        Dyadic { m: h + h.transpose() }
    }

    /// Skew-symmetric part ½(M⃗ − M⃗′).
    ///
    /// Book: §2.6 (skew M⃗′ = −M⃗), Fact 2.6.1.
    #[inline]
    pub fn skew_part(&self) -> Dyadic<T> {
        let h = self.m * T::lit(0.5);
        Dyadic { m: h - h.transpose() }
    }

    /// Vee: the vector x⃗ with x⃗^× equal to the skew part of M⃗ (inverse of
    /// [`Vector::cross_dyad`] on skew dyadics, book §2.9).
    ///
    /// Book: Fact 2.9.3.
    #[inline]
    pub fn vee(&self) -> Vector<T> {
        let m = &self.m;
        let h = T::lit(0.5);
        Vector {
            c: nalgebra::Vector3::new(
                (m[(2, 1)] - m[(1, 2)]) * h,
                (m[(0, 2)] - m[(2, 0)]) * h,
                (m[(1, 0)] - m[(0, 1)]) * h,
            ),
        }
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

    /// `true` when M⃗′ = M⃗ within `tol`·‖M⃗‖_F (entrywise on the skew part).
    ///
    /// Book: §2.6 (symmetric: M⃗′ = M⃗).
    pub fn is_symmetric(&self, tol: f64) -> bool {
        self.skew_part().m.amax().re() <= tol * self.norm().re()
    }

    /// `true` when M⃗′ = −M⃗ within `tol`·‖M⃗‖_F.
    ///
    /// Book: §2.6 (skew symmetric: M⃗′ = −M⃗).
    pub fn is_skew(&self, tol: f64) -> bool {
        self.symmetric_part().m.amax().re() <= tol * self.norm().re()
    }

    /// The principal invariants (I₁, I₂, I₃) = (tr M⃗, ½[(tr M⃗)² − tr M⃗²], det M⃗), the
    /// coefficients of Cayley–Hamilton (2.10.56): M⃗³ − I₁M⃗² + I₂M⃗ − I₃I⃗ = 0. All three are
    /// frame invariant (2.10.50–53).
    ///
    /// Book: (2.10.50–53), (2.10.56).
    pub fn invariants(&self) -> [T; 3] {
        let t = self.trace();
        let t2 = (self.m * self.m).trace();
        [t, (t * t - t2) * T::lit(0.5), self.determinant()]
    }

    /// Cayley–Hamilton residual M⃗³ − I₁M⃗² + I₂M⃗ − I₃I⃗, which is the zero dyadic up to rounding
    /// (2.10.56). Useful as an oracle.
    ///
    /// Book: (2.10.56).
    pub fn cayley_hamilton_residual(&self) -> Dyadic<T> {
        let [i1, i2, i3] = self.invariants();
        let m2 = self.m * self.m;
        Dyadic { m: m2 * self.m - m2 * i1 + self.m * i2 - Matrix3::identity() * i3 }
    }

    /// det M⃗ from traces alone: ⅓ tr M⃗³ − ½ tr M⃗ tr M⃗² + ⅙ (tr M⃗)³ (2.10.57).
    ///
    /// Book: (2.10.57).
    pub fn determinant_from_traces(&self) -> T {
        let t = self.trace();
        let m2 = self.m * self.m;
        let (t2, t3) = (m2.trace(), (m2 * self.m).trace());
        t3 / T::lit(3.0) - t * t2 * T::lit(0.5) + t * t * t / T::lit(6.0)
    }

    /// tr M⃗⁻¹ = [(tr M⃗)² − tr M⃗²]/(2 det M⃗) = I₂/I₃ (2.10.58), without forming M⃗⁻¹.
    ///
    /// Book: (2.10.58).
    ///
    /// # Errors
    /// As [`Dyadic::inverse`]: [`TensorError::Singular`] when M⃗ is singular within `rel_tol`.
    pub fn trace_of_inverse(&self, rel_tol: f64) -> Result<T, TensorError> {
        // Reuse the scaled singularity test of `inverse`.
        self.inverse(rel_tol)?;
        let [_, i2, i3] = self.invariants();
        Ok(i2 / i3)
    }

    /// (I⃗ + α x⃗^× + β x⃗^×²)⁻¹ = I⃗ − (α/D) x⃗^× + ((α² + β²|x|² − β)/D) x⃗^×², with
    /// D = α²|x|² + (β|x|² − 1)² (2.9.16–17). With α = 1, β = 0 this is (I⃗ + x⃗^×)⁻¹ (2.9.8–9).
    ///
    /// Book: (2.9.8–9), (2.9.16–17).
    ///
    /// # Degenerate inputs
    /// D = 0 exactly when α = 0 and β|x|² = 1 (or the matrix is otherwise singular): returns
    /// [`TensorError::Singular`] when D ≤ `rel_tol`·(1 + α²|x|² + β²|x|⁴).
    pub fn cross_polynomial_inverse(
        x: &Vector<T>,
        alpha: T,
        beta: T,
        rel_tol: f64,
    ) -> Result<Dyadic<T>, TensorError> {
        crate::check_tolerance(rel_tol, "rel_tol")?;
        if !(x.is_finite() && alpha.re().is_finite() && beta.re().is_finite()) {
            return Err(TensorError::NonFinite { what: "cross-polynomial input" });
        }
        let n2 = x.norm_squared();
        let d = alpha * alpha * n2 + (beta * n2 - T::one()) * (beta * n2 - T::one());
        let scale = 1.0 + (alpha * alpha * n2).re() + (beta * beta * n2 * n2).re();
        if d.re() <= rel_tol * scale {
            return Err(TensorError::Singular { det: d.re(), tol: rel_tol * scale });
        }
        let xx = x.cross_dyad();
        let xx2 = xx * xx;
        // (2.9.17)
        let inv = Self::identity() - xx * (alpha / d) + xx2 * ((alpha * alpha + beta * beta * n2 - beta) / d);
        if !inv.is_finite() {
            // the formula needs |x⃗|⁴ (β²|x⃗|⁴ in d): beyond f64::MAX it is refused, not NaN
            return Err(TensorError::Overflow { what: "cross-polynomial inverse (|x|⁴ beyond f64::MAX)" });
        }
        Ok(inv)
    }

    /// Frobenius norm ‖M⃗‖_F = √tr(M⃗′M⃗), frame independent for standard frames; scaled by the
    /// largest entry so that huge or tiny entries neither overflow nor underflow.
    ///
    /// Book: §2.6, (2.10.50) (trace invariance).
    #[inline]
    pub fn norm(&self) -> T {
        let s = self.max_abs();
        if s == T::zero() || !s.re().is_finite() {
            return s;
        }
        let r = s.re();
        if r > 1e-150 && r < 1e150 {
            return self.m.norm();
        }
        (self.m / s).norm() * s
    }

    /// Largest |entry| in the hidden basis (a scale, not an invariant).
    fn max_abs(&self) -> T {
        self.m.iter().fold(T::zero(), |s, x| if x.abs() > s { x.abs() } else { s })
    }

    /// `true` when every component is finite.
    ///
    /// Book: DESIGN §5 (bad input).
    #[inline]
    pub fn is_finite(&self) -> bool {
        crate::scalar::all_finite(self.m.as_slice())
    }
}

impl Dyadic<f64> {
    /// The same dyadic over another scalar type (see [`Vector::cast`]).
    ///
    /// Book: §2.24.
    #[inline]
    pub fn cast<U: Scalar>(&self) -> Dyadic<U> {
        Dyadic { m: self.m.map(U::lit) }
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

/// The adjugate adj(M) of a resolved 3×3 matrix, with M adj(M) = det(M) I: exact, division-free
/// and differentiable for dual numbers, so M⁻¹ = adj(M)/det(M) wherever det(M) ≠ 0.
///
/// Book: §2.6 (inverse of a physical matrix), Cramer's rule.
pub fn adjugate<T: Scalar>(m: &Matrix3<T>) -> Matrix3<T> {
    let cof =
        |r1: usize, c1: usize, r2: usize, c2: usize| m[(r1, c1)] * m[(r2, c2)] - m[(r1, c2)] * m[(r2, c1)];
    Matrix3::new(
        cof(1, 1, 2, 2),
        -cof(0, 1, 2, 2),
        cof(0, 1, 1, 2),
        -cof(1, 0, 2, 2),
        cof(0, 0, 2, 2),
        -cof(0, 0, 1, 2),
        cof(1, 0, 2, 1),
        -cof(0, 0, 2, 1),
        cof(0, 0, 1, 1),
    )
}
