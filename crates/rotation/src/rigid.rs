//! Rigid displacements, Chasles's theorem made constructive, chains and homogeneous
//! transforms (book §2.20–2.22, P2.26.19–20).

use nalgebra::{Matrix3, Matrix4, Vector3};
use vectrix_frames::{Frame, Resolve};
use vectrix_tensor::{Scalar, Vector};

use crate::{AxisAngle, Rotation, RotationError};

/// A rigid displacement about the reference point x: r⃗_{y′/x} = R⃗ r⃗_{y/x} + r⃗ (F2.21.1).
///
/// Book: §2.21, F2.21.1–3.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidDisplacement<T: Scalar = f64> {
    /// The rotation R⃗ about x.
    pub rotation: Rotation<T>,
    /// The translation r⃗ that follows it.
    pub translation: Vector<T>,
}

/// Chasles's theorem as a value (F2.21.4): every rigid displacement is a screw.
///
/// Book: F2.21.4 (proved geometrically in the book; constructed here, notes ch2b §2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Screw<T: Scalar = f64> {
    /// θ ≈ 0: a pure translation (the screw axis is at infinity).
    Translation(Vector<T>),
    /// r⃗_{y′/z} = R⃗_{n̂}(θ) r⃗_{y/z} + α n̂ for every point y.
    General {
        /// A point z of the screw axis, as r⃗_{z/x} (the point nearest to x).
        point: Vector<T>,
        /// The axis n̂ (unit).
        axis: Vector<T>,
        /// The angle θ ∈ (0, π].
        angle: T,
        /// The slide α along n̂.
        slide: T,
    },
}

impl<T: Scalar> RigidDisplacement<T> {
    /// r⃗_{y′/x} = R⃗ r⃗_{y/x} + r⃗ (F2.21.1).
    pub fn new(rotation: Rotation<T>, translation: Vector<T>) -> Self {
        Self { rotation, translation }
    }

    /// r⃗_{y′/x} of a point y given by r⃗_{y/x} (F2.21.1).
    #[inline]
    pub fn apply(&self, r_y_x: &Vector<T>) -> Vector<T> {
        self.rotation.apply(r_y_x) + self.translation
    }

    /// `second.compose(&first)`: first, then second: R⃗₂R⃗₁, R⃗₂r⃗₁ + r⃗₂.
    #[inline]
    pub fn compose(&self, first: &RigidDisplacement<T>) -> RigidDisplacement<T> {
        Self::new(self.rotation * first.rotation, self.rotation.apply(&first.translation) + self.translation)
    }

    /// The inverse displacement: R⃗⁻¹, −R⃗⁻¹r⃗ (P2.26.19–20).
    #[inline]
    pub fn inverse(&self) -> RigidDisplacement<T> {
        let r_inv = self.rotation.inverse();
        Self::new(r_inv, -r_inv.apply(&self.translation))
    }

    /// Chasles: axis n̂ and angle θ of R⃗, slide α = n̂·r⃗, and the axis point
    /// c⃗ = ½[r⃗⊥ + cot(θ/2) n̂×r⃗⊥] with r⃗⊥ = r⃗ − αn̂. `Screw::Translation` when θ ≤ `tol`,
    /// where cot(θ/2) blows up. At θ = π, cot = 0 and the point is well defined whatever the
    /// axis sign.
    ///
    /// Book: F2.21.4; notes ch2b §3.10.
    pub fn screw(&self, tol: f64) -> Screw<T> {
        let (axis, angle) = match self.rotation.axis_angle() {
            AxisAngle::Identity => return Screw::Translation(self.translation),
            AxisAngle::HalfTurn(n) => (n, T::pi()),
            AxisAngle::General { axis, angle } => (axis, angle),
        };
        if angle.re() <= tol {
            return Screw::Translation(self.translation);
        }
        let slide = axis.dot(&self.translation);
        let t_perp = self.translation - axis * slide;
        let half = angle * T::lit(0.5);
        let cot = half.cos() / half.sin();
        let point = (t_perp + axis.cross(&t_perp) * cot) * T::lit(0.5);
        Screw::General { point, axis, angle, slide }
    }

    /// The homogeneous transform in `a`: [[R⃗|_A, r⃗|_A], [0, 1]], acting on [r_{y/x}|_A; 1].
    ///
    /// Book: P2.26.19–20.
    pub fn homogeneous_in(&self, a: &Frame<T>) -> Matrix4<T> {
        homogeneous(&self.rotation.rotation_matrix_in(a), &self.translation.resolve(a))
    }

    /// From a homogeneous transform resolved in `a` (the rotation block checked within `tol`,
    /// the bottom row must be [0 0 0 1]).
    ///
    /// # Errors
    /// As [`crate::check_rotation_matrix`]; [`RotationError::NotOrthonormal`] when the bottom
    /// row is not [0 0 0 1] (reported as its defect).
    pub fn from_homogeneous_in(a: &Frame<T>, h: &Matrix4<T>, tol: f64) -> Result<Self, RotationError> {
        vectrix_tensor::check_tolerance(tol, "tol")?;
        let r: Matrix3<T> = h.fixed_view::<3, 3>(0, 0).into_owned();
        let t: Vector3<T> = h.fixed_view::<3, 1>(0, 3).into_owned();
        let row = [h[(3, 0)], h[(3, 1)], h[(3, 2)], h[(3, 3)] - T::one()];
        let defect = crate::series::max_abs(row);
        if defect.is_nan() || defect > tol {
            return Err(RotationError::NotOrthonormal { defect, tol });
        }
        Ok(Self::new(Rotation::from_rotation_matrix_in(a, &r, tol)?, a.vector(t.into())))
    }
}

/// [[M, r], [0, 1]].
///
/// Book: P2.26.19.
pub fn homogeneous<T: Scalar>(m: &Matrix3<T>, r: &Vector3<T>) -> Matrix4<T> {
    let mut h = Matrix4::identity();
    h.fixed_view_mut::<3, 3>(0, 0).copy_from(m);
    h.fixed_view_mut::<3, 1>(0, 3).copy_from(r);
    h
}

/// The exact inverse of a homogeneous transform with a rotation block:
/// [[𝓞, r], [0, 1]]⁻¹ = [[𝓞ᵀ, −𝓞ᵀr], [0, 1]] (P2.26.20), no general 4×4 inversion.
///
/// Book: P2.26.20.
pub fn homogeneous_inverse<T: Scalar>(h: &Matrix4<T>) -> Matrix4<T> {
    let o: Matrix3<T> = h.fixed_view::<3, 3>(0, 0).transpose();
    let r: Vector3<T> = h.fixed_view::<3, 1>(0, 3).into_owned();
    homogeneous(&o, &-(o * r))
}

/// One link of a chain of bodies (§2.22): the orientation 𝓞_{child/parent} and the position of
/// the child's point relative to the parent's, r_{child/parent} resolved in the child frame.
///
/// Book: §2.22, (2.22.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChainLink<T: Scalar = f64> {
    /// 𝓞_{child/parent} (passive).
    pub o_child_parent: Matrix3<T>,
    /// r_{child/parent}|_child.
    pub r_in_child: Vector3<T>,
}

/// Forward sum (2.22.2): r_{tip/base}|_base = Σ 𝓞_{base/k} r_{k/k−1}|_k with
/// 𝓞_{base/k} = 𝓞_{base/k−1}𝓞_{k−1/k} accumulated link by link.
///
/// Book: (2.22.2).
pub fn chain_forward<T: Scalar>(links: &[ChainLink<T>]) -> Vector3<T> {
    let mut o_base_k = Matrix3::identity();
    let mut r = Vector3::zeros();
    for l in links {
        // (2.22.2): 𝓞_{A/C} = 𝓞_{A/B} 𝓞_{B/C}, 𝓞_{B/C} = 𝓞_{C/B}ᵀ
        o_base_k *= l.o_child_parent.transpose();
        r += o_base_k * l.r_in_child;
    }
    r
}

/// Backward (Horner) form (2.22.3): r|_A = 𝓞_{A/B}[𝓞_{B/C}(𝓞_{C/D} r_{D/C}|_D + r_{C/B}|_C)
/// + r_{B/A}|_B], one matrix–vector product per link.
///
/// Book: (2.22.3).
pub fn chain_backward<T: Scalar>(links: &[ChainLink<T>]) -> Vector3<T> {
    links.iter().rev().fold(Vector3::zeros(), |v, l| l.o_child_parent.tr_mul(&(v + l.r_in_child)))
}
