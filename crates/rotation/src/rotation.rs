//! The physical rotation R⃗_{B/A} (book §2.8, §2.11), frame-free.
//!
//! # Representation (measured)
//! A [`Rotation`] holds a unit rotor R = q₀ − 𝒥q⃗ (book §3.9), not an orthonormal dyad:
//! four numbers instead of nine, composition by one Hamilton product (16 multiplications
//! against 27 for a dyad product), no orthonormality drift to repair (a rotor renormalises
//! with one square root), and exact angle and axis by atan2. Applying to one vector costs two
//! cross products, exactly nalgebra's `UnitQuaternion * Vector3`; for many vectors, take
//! [`Rotation::to_dyadic`] once. Figures: `docs/performance.md` (bench `rotation`,
//! groups `compose` and `apply`, rotor beside dyad beside nalgebra).

use core::ops::Mul;

use nalgebra::Vector3;
use vectrix_frames::Frame;
use vectrix_tensor::{Bivector, Dyadic, Rotor, Scalar, Vector};

use crate::series::all_finite;
use crate::{AxisAngle, Quaternion, RotationError};

/// A physical rotation R⃗ (book §2.8): frame-free, acting on vectors, dyads and frames.
/// `Rotation::between(&b, &a)` is R⃗_{B/A}, with F_B = R⃗_{B/A} F_A (2.8.7–9).
///
/// Products read like the book: `r_cb * r_ba` is R⃗_{C/A} = R⃗_{C/B} R⃗_{B/A} (apply the right
/// factor first); `r * x` is R⃗x⃗.
///
/// Book: §2.8, (2.8.6–14); §2.11; rotor form §3.9.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotation<T: Scalar = f64> {
    pub(crate) rotor: Rotor<T>,
}

impl<T: Scalar> Default for Rotation<T> {
    fn default() -> Self {
        Self::identity()
    }
}

impl<T: Scalar> Rotation<T> {
    /// The identity I⃗ (2.8.1).
    #[inline]
    pub fn identity() -> Self {
        Self { rotor: Rotor::identity() }
    }

    /// From a rotor, normalised.
    ///
    /// # Errors
    /// [`RotationError::Zero`] for the zero element, [`RotationError::NonFinite`].
    pub fn from_rotor(r: &Rotor<T>) -> Result<Self, RotationError> {
        let b = r.bivector().undual();
        if !(r.scalar().re().is_finite() && b.is_finite()) {
            return Err(RotationError::NonFinite { what: "rotor" });
        }
        r.normalize().map(|rotor| Self { rotor }).ok_or(RotationError::Zero { what: "rotor" })
    }

    /// The unit rotor R with R x⃗ R̄ = R⃗x⃗ (book §3.9).
    #[inline]
    pub fn rotor(&self) -> Rotor<T> {
        self.rotor
    }

    /// R⃗_{B/A} = F_B 𝓕′_A (2.8.7): the rotation taking the axes of `a` to those of `b`.
    ///
    /// Book: (2.8.7–9).
    #[inline]
    pub fn between(b: &Frame<T>, a: &Frame<T>) -> Self {
        // R⃗_{B/A}|_A = 𝓡_{B/A} (Fact 2.10.1); frames are orthonormal by construction.
        Self::from_rotation_matrix_in_unchecked(a, &b.rotation_rel(a))
    }

    /// R⃗_{n̂}(θ): θ about `axis` by the right-hand rule (Rodrigues (2.11.1)), any real θ.
    ///
    /// # Errors
    /// [`RotationError::Zero`] for a zero axis, [`RotationError::NonFinite`].
    pub fn from_axis_angle(axis: &Vector<T>, theta: T) -> Result<Self, RotationError> {
        if !(axis.is_finite() && theta.re().is_finite()) {
            return Err(RotationError::NonFinite { what: "axis or angle" });
        }
        Rotor::from_axis_angle(axis, theta)
            .map(|rotor| Self { rotor })
            .ok_or(RotationError::Zero { what: "rotation axis" })
    }

    /// exp(Θ⃗^×): the rotation of the angle vector Θ⃗ = θn̂ (2.14.5, F2.14.2), with the sinc
    /// series near θ = 0.
    ///
    /// Book: §2.14, (2.14.12–15), Prob 2.26.22.
    ///
    /// # Errors
    /// [`RotationError::NonFinite`].
    pub fn exp(theta: &Vector<T>) -> Result<Self, RotationError> {
        if !theta.is_finite() {
            return Err(RotationError::NonFinite { what: "angle vector" });
        }
        let a = Frame::<T>::identity();
        let q = Quaternion::from_angle_vector(&vectrix_frames::Resolve::resolve(theta, &a));
        Ok(Self::from_quaternion_parts(&a, &q))
    }

    /// The angle vector Θ⃗ = θn̂, θ ∈ [0, π] (log map, §2.14). At θ = π both ±πn̂ are logs; the
    /// frame-free choice is the canonical sign in the first frame `Frame::new()`; use
    /// [`Rotation::angle_vector_in`] for the canonical sign in a frame of your choice.
    ///
    /// Book: §2.14 (L2477), (2.14.17); notes ch2b §3.5.
    pub fn log(&self) -> Vector<T> {
        let a = Frame::<T>::identity();
        a.vector(self.quaternion_in(&a).angle_vector().into())
    }

    /// Eigenaxis and eigenangle, frame-free (the half-turn sign as in [`Rotation::log`]).
    ///
    /// Book: §2.11, Facts 2.11.4–5.
    pub fn axis_angle(&self) -> AxisAngle<T> {
        let a = Frame::<T>::identity();
        match self.quaternion_in(&a).axis_angle() {
            AxisAngle::Identity => AxisAngle::Identity,
            AxisAngle::HalfTurn(n) => AxisAngle::HalfTurn(a.vector(n.into())),
            AxisAngle::General { axis, angle } => AxisAngle::General { axis: a.vector(axis.into()), angle },
        }
    }

    /// The eigenangle θ = 2 atan2(|q⃗|, |q₀|) ∈ [0, π] (2.11.49, by atan2).
    #[inline]
    pub fn angle(&self) -> T {
        let s = self.rotor.bivector().undual().norm();
        T::lit(2.0) * s.atan2(self.rotor.scalar().abs())
    }

    /// R⃗x⃗ (Rodrigues (2.11.1), evaluated as the rotor sandwich: two cross products).
    #[inline]
    pub fn apply(&self, x: &Vector<T>) -> Vector<T> {
        self.rotor.rotate(x)
    }

    /// R⃗ M⃗ R⃗′: a physical matrix carried by the rotation (book §2.10, (2.10.38) frame-free).
    #[inline]
    pub fn apply_dyadic(&self, m: &Dyadic<T>) -> Dyadic<T> {
        let r = self.to_dyadic();
        r * *m * r.coform()
    }

    /// F_B = R⃗ F_A: the frame with rotated axes (2.8.9).
    #[inline]
    pub fn apply_frame(&self, a: &Frame<T>) -> Frame<T> {
        a.rotated_by_rotor(&self.rotor)
    }

    /// The rotation dyad R⃗ (a physical matrix, book §2.8).
    #[inline]
    pub fn to_dyadic(&self) -> Dyadic<T> {
        self.rotor.to_dyadic()
    }

    /// R⃗_{C/A} = R⃗_{C/B} R⃗_{B/A} (2.10.44): `r_cb.compose(&r_ba)` applies `r_ba` first.
    ///
    /// Book: (2.10.44), F2.11.11.
    #[inline]
    pub fn compose(&self, first: &Rotation<T>) -> Rotation<T> {
        Rotation { rotor: self.rotor.gp(&first.rotor) }
    }

    /// R⃗⁻¹ = R⃗′: R⃗_{A/B} = R⃗_{B/A}⁻¹ (2.8.12–14).
    #[inline]
    pub fn inverse(&self) -> Rotation<T> {
        Rotation { rotor: self.rotor.reverse() }
    }

    /// R⃗ᵗ = exp(t log R⃗), about the same axis by t·θ (θ ∈ [0, π] the principal angle).
    ///
    /// Book: §2.14 (exp/log).
    ///
    /// # Errors
    /// [`RotationError::NonFinite`] for a NaN or infinite `t`; [`RotationError::Overflow`]
    /// when t·θ exceeds the largest finite number.
    pub fn powf(&self, t: T) -> Result<Rotation<T>, RotationError> {
        if !t.re().is_finite() {
            return Err(RotationError::NonFinite { what: "exponent t" });
        }
        let a = Frame::<T>::identity();
        let th = self.quaternion_in(&a).angle_vector() * t;
        if !th.iter().all(|x| x.re().is_finite()) {
            return Err(RotationError::Overflow { what: "angle vector t·θ" });
        }
        Ok(Self::from_quaternion_parts(&a, &Quaternion::from_angle_vector(&th)))
    }

    /// Geodesic interpolation: `self` at t = 0, `other` at t = 1, the shorter arc.
    ///
    /// Book: §2.14.
    ///
    /// # Errors
    /// [`RotationError::NonFinite`] for a NaN or infinite `t`; [`RotationError::Overflow`]
    /// when t times the angle between the two exceeds the largest finite number.
    pub fn slerp(&self, other: &Rotation<T>, t: T) -> Result<Rotation<T>, RotationError> {
        if !t.re().is_finite() {
            return Err(RotationError::NonFinite { what: "interpolation parameter t" });
        }
        let a = Frame::<T>::identity();
        let q = self.quaternion_in(&a).slerp(&other.quaternion_in(&a), t);
        if !q.to_vector4().iter().all(|x| x.re().is_finite()) {
            return Err(RotationError::Overflow { what: "angle t·θ of the interpolation" });
        }
        Ok(Self::from_quaternion_parts(&a, &q))
    }

    /// Restores |R| = 1 after long products (notes ch1-2a §3.10); one square root.
    ///
    /// # Errors
    /// [`RotationError::Zero`] or [`RotationError::NonFinite`] for a corrupted rotor.
    pub fn renormalize(&self) -> Result<Rotation<T>, RotationError> {
        Self::from_rotor(&self.rotor)
    }

    /// The minimal rotation taking the direction of `x` to that of `y` (F2.11.9):
    /// R⃗_{θ̂_{y/x}}(θ_{y/x}), computed as the normalised quaternion (|x||y| + x·y, x×y). For
    /// anti-parallel vectors every axis ⊥ x⃗ works; the one chosen is x⃗ × (the axis of the
    /// first frame least aligned with x⃗), documented and deterministic. `None` when either
    /// vector is zero.
    ///
    /// Book: F2.11.9 (the "unique" wording over-claims: any R⃗ with R⃗x̂ = ŷ qualifies), (2.11.21).
    pub fn taking(x: &Vector<T>, y: &Vector<T>) -> Option<Rotation<T>> {
        let (xh, yh) = (x.unit()?, y.unit()?);
        let c = xh.dot(&yh);
        let w = xh.cross(&yh);
        // 1 + cos θ cancels near θ = π: there, use θ = atan2(|w|, c) and n̂ = w/|w|; an error
        // ε/sin θ in n̂ (ill-conditioned near anti-parallel) moves R⃗x̂ by only ε, since n̂ ⊥ x̂.
        let (s, v) = if c.re() > -0.5 {
            (T::one() + c, w)
        } else {
            let wn = w.norm();
            if wn == T::zero() {
                // 180° singularity: x̂ ≈ −ŷ, axis ⊥ x̂.
                let a = Frame::<T>::identity();
                let xc = vectrix_frames::Resolve::resolve(&xh, &a);
                let k = xc.iamin();
                let mut e = Vector3::zeros();
                e[k] = T::one();
                let n = xh.cross(&a.vector(e.into())).unit()?;
                return Some(Rotation {
                    rotor: Rotor::from_parts_unchecked(T::zero(), Bivector::dual_of(&-n)),
                });
            }
            let half = wn.atan2(c) * T::lit(0.5);
            (half.cos(), w * (half.sin() / wn))
        };
        let n = (s * s + v.norm_squared()).sqrt();
        Some(Rotation { rotor: Rotor::from_parts_unchecked(s / n, Bivector::dual_of(&-(v / n))) })
    }

    /// The commutator R⃗₁R⃗₂ − R⃗₂R⃗₁ (2.19.6): zero exactly when the axes are parallel, one is
    /// I⃗, or both are half-turns about perpendicular axes (F2.19.4).
    ///
    /// Book: F2.19.3–4, (2.19.6).
    pub fn commutator(&self, other: &Rotation<T>) -> Dyadic<T> {
        let (a, b) = (self.to_dyadic(), other.to_dyadic());
        a * b - b * a
    }

    /// `true` when the two rotations commute: ‖R⃗₁R⃗₂ − R⃗₂R⃗₁‖_F ≤ `tol` (F2.19.3–4).
    pub fn commutes_with(&self, other: &Rotation<T>, tol: f64) -> bool {
        self.commutator(other).norm().re() <= tol
    }

    /// Builds from Euler parameters resolved in `a` (assumed unit).
    #[inline]
    pub(crate) fn from_quaternion_parts(a: &Frame<T>, q: &Quaternion<T>) -> Self {
        // R = q₀ − 𝒥q⃗ with q⃗ = F_A ε|_A (book §3.9, (3.9.17)).
        let qv = a.vector([q.b, q.c, q.d]);
        Self { rotor: Rotor::from_parts_unchecked(q.a, Bivector::dual_of(&-qv)) }
    }

    /// `true` when every component is finite.
    pub fn is_finite(&self) -> bool {
        all_finite([self.rotor.scalar()]) && self.rotor.bivector().undual().is_finite()
    }
}

/// `r_cb * r_ba` = R⃗_{C/A} = R⃗_{C/B}R⃗_{B/A} (2.10.44): the right factor acts first.
impl<T: Scalar> Mul for Rotation<T> {
    type Output = Rotation<T>;
    #[inline(always)]
    fn mul(self, first: Rotation<T>) -> Rotation<T> {
        self.compose(&first)
    }
}

/// `r * x` = R⃗x⃗.
impl<T: Scalar> Mul<Vector<T>> for Rotation<T> {
    type Output = Vector<T>;
    #[inline(always)]
    fn mul(self, x: Vector<T>) -> Vector<T> {
        self.apply(&x)
    }
}
