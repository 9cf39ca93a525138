//! Relative motion of two frames: 𝓞_{B/A}, ω⃗_{B/A}, α⃗_{B/A} (book §4.2–4.6).
//!
//! A [`FrameMotion`] is the state of frame F_B relative to frame F_A at one instant: the two
//! frames' axes (hence 𝓞_{B/A}), the angular velocity ω⃗_{B/A} and the angular acceleration
//! α⃗_{B/A} = ω⃗_{B/A}^{A•} = ω⃗_{B/A}^{B•} (4.4.3). Both vectors are physical (frame-free);
//! resolve them with `x.resolve(&frame)`.

use nalgebra::Matrix3;
use vectrix_frames::Frame;
use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::label::check_label;
use crate::{FrameLabel, KinematicsError, LabeledFrame};

/// The motion of frame F_B relative to frame F_A at one instant.
///
/// Book: §4.2–4.6; Def 4.2.3 (Ω⃗_{B/A}), Fact 4.3.1 (ω⃗_{B/A}), (4.4.3) (α⃗_{B/A}).
///
/// # Conventions
/// `omega()` is ω⃗_{B/A} (B's rotation seen from A); `inverse()` gives ω⃗_{A/B} = −ω⃗_{B/A}.
/// 𝓞_{B/A} is passive: x|_B = 𝓞_{B/A} x|_A.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameMotion<T: Scalar = f64> {
    b: LabeledFrame<T>,
    a: LabeledFrame<T>,
    omega: Vector<T>,
    alpha: Vector<T>,
}

pub(crate) fn finite_vector<T: Scalar>(x: &Vector<T>, what: &'static str) -> Result<(), KinematicsError> {
    if x.is_finite() { Ok(()) } else { Err(KinematicsError::NonFinite { what }) }
}

impl<T: Scalar> FrameMotion<T> {
    /// The motion of `b` = F_B relative to `a` = F_A with ω⃗_{B/A} = `omega_b_a` and
    /// α⃗_{B/A} = `alpha_b_a` (argument order is subscript order).
    ///
    /// Book: §4.2–4.4.
    ///
    /// # Errors
    /// [`KinematicsError::SameFrame`] when both labels are equal; [`KinematicsError::NonFinite`].
    pub fn new(
        b: LabeledFrame<T>,
        a: LabeledFrame<T>,
        omega_b_a: Vector<T>,
        alpha_b_a: Vector<T>,
    ) -> Result<Self, KinematicsError> {
        if b.label == a.label {
            return Err(KinematicsError::SameFrame { label: a.label });
        }
        finite_vector(&omega_b_a, "ω_{B/A}")?;
        finite_vector(&alpha_b_a, "α_{B/A}")?;
        Ok(Self { b, a, omega: omega_b_a, alpha: alpha_b_a })
    }

    /// The motion from resolved data: 𝓞_{B/A}, ω_{B/A}|_B and α_{B/A}|_B (the body form of
    /// most sensors and of (4.3.17–20)). F_B is built from F_A and 𝓞_{B/A}.
    ///
    /// Book: (2.10.16), (4.4.6).
    ///
    /// # Errors
    /// As [`FrameMotion::new`], and `Frame` errors when 𝓞_{B/A} is not a rotation (within
    /// `vectrix_frames::ORTHONORMAL_TOL`).
    pub fn from_body_rates(
        b: FrameLabel,
        a: &LabeledFrame<T>,
        o_b_a: &Matrix3<T>,
        omega_b_a_in_b: [T; 3],
        alpha_b_a_in_b: [T; 3],
    ) -> Result<Self, KinematicsError> {
        let frame_b = Frame::from_orientation_rel(&a.frame, o_b_a, vectrix_frames::ORTHONORMAL_TOL)?;
        let omega = frame_b.vector(omega_b_a_in_b);
        let alpha = frame_b.vector(alpha_b_a_in_b);
        Self::new(LabeledFrame::with_label(b, frame_b), *a, omega, alpha)
    }

    /// The moving frame F_B.
    ///
    /// Book: §4.2.
    pub fn body(&self) -> &LabeledFrame<T> {
        &self.b
    }

    /// The reference frame F_A.
    ///
    /// Book: §4.2.
    pub fn reference(&self) -> &LabeledFrame<T> {
        &self.a
    }

    /// ω⃗_{B/A}.
    ///
    /// Book: Fact 4.3.1.
    pub fn omega(&self) -> Vector<T> {
        self.omega
    }

    /// α⃗_{B/A} = ω⃗_{B/A}^{A•} = ω⃗_{B/A}^{B•} (equal because ω⃗ × ω⃗ = 0⃗).
    ///
    /// Book: (4.4.3).
    pub fn alpha(&self) -> Vector<T> {
        self.alpha
    }

    /// The angular-velocity dyad Ω⃗_{B/A} = R⃗_{A/B} R⃗_{B/A}^{B•} = ω⃗_{B/A}^× (skew).
    ///
    /// Book: Def 4.2.3, Fact 4.2.4, Fact 4.3.1.
    pub fn omega_dyad(&self) -> Dyadic<T> {
        self.omega.cross_dyad()
    }

    /// 𝓞_{B/A} (passive, x|_B = 𝓞_{B/A} x|_A).
    ///
    /// Book: (2.10.13).
    pub fn o_b_a(&self) -> Matrix3<T> {
        self.b.frame.orientation_rel(&self.a.frame)
    }

    /// The inverse motion of F_A relative to F_B: ω⃗_{A/B} = −ω⃗_{B/A} (4.3.8) and
    /// α⃗_{A/B} = −α⃗_{B/A}.
    ///
    /// # Caution (Fact 4.3.2)
    /// Resolved, ω_{A/B}|_A = −𝓞_{A/B} ω_{B/A}|_B, which differs from −ω_{B/A}|_B unless ω is
    /// along the eigenaxis. The physical vectors here avoid that classic bug.
    ///
    /// Book: (4.3.8), (4.2.19).
    pub fn inverse(&self) -> Self {
        Self { b: self.a, a: self.b, omega: -self.omega, alpha: -self.alpha }
    }

    /// Summation for two frames: `c_b.compose(&b_a)` is the motion of F_C relative to F_A,
    /// ω⃗_{C/A} = ω⃗_{C/B} + ω⃗_{B/A} (4.6.2) and
    /// α⃗_{C/A} = α⃗_{C/B} + α⃗_{B/A} − ω⃗_{C/B} × ω⃗_{B/A} (4.6.5).
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`] unless `self` is relative to the body of `inner`;
    /// [`KinematicsError::SameFrame`] when F_C is F_A.
    ///
    /// Book: (4.6.2), (4.6.5), Fact 4.6.1.
    pub fn compose(&self, inner: &FrameMotion<T>) -> Result<Self, KinematicsError> {
        check_label("FrameMotion::compose (C/B after B/A)", inner.b.label, self.a.label)?;
        // (4.6.2), (4.6.5)
        let omega = self.omega + inner.omega;
        let alpha = self.alpha + inner.alpha - self.omega.cross(&inner.omega);
        Self::new(self.b, inner.a, omega, alpha)
    }

    /// Summation along a chain `[B/A, C/B, D/C, …]` (base first): the motion of the last body
    /// relative to the first reference, by α⃗_{k/0} = α⃗_{k−1/0} + α⃗_{k/k−1} + ω⃗_{k−1/0} × ω⃗_{k/k−1}
    /// (the recursion form of (4.6.6–7)).
    ///
    /// Book: (4.6.2), (4.6.5–7).
    ///
    /// # Errors
    /// [`KinematicsError::EmptyChain`]; [`KinematicsError::FrameMismatch`] when a link is not
    /// relative to the previous link's body.
    pub fn chain(links: &[FrameMotion<T>]) -> Result<Self, KinematicsError> {
        let (first, rest) =
            links.split_first().ok_or(KinematicsError::EmptyChain { what: "FrameMotion::chain" })?;
        rest.iter().try_fold(*first, |acc, link| link.compose(&acc))
    }

    /// The mixed angular acceleration α⃗_{B/A/C} = ω⃗_{B/A}^{C•} = α⃗_{B/A} − ω⃗_{C/A} × ω⃗_{B/A}
    /// (transport theorem applied to ω⃗_{B/A}), where `c_a` is the motion of F_C relative to F_A.
    ///
    /// Book: (4.4.4), with (4.4.1).
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`] unless `c_a` is relative to this motion's F_A.
    pub fn mixed_alpha(&self, c_a: &FrameMotion<T>) -> Result<Vector<T>, KinematicsError> {
        check_label("FrameMotion::mixed_alpha", self.a.label, c_a.a.label)?;
        // ω^{C•} = ω^{A•} − ω_{C/A} × ω (4.4.1 with A and C)
        Ok(self.alpha - c_a.omega.cross(&self.omega))
    }
}
