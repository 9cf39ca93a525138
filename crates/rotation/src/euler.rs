//! Euler angles in all 12 sequences, intrinsic (the book's) and extrinsic (book §2.12–2.13).
//!
//! An intrinsic sequence i-j-k with angles (α, β, γ) in the order applied turns F_A about its
//! axis i by α, the new frame about its axis j by β, and that frame about its axis k by γ:
//!
//! 𝓞_{D/A} = 𝓞_k(γ) 𝓞_j(β) 𝓞_i(α),  𝓡_{D/A} = 𝓡_i(α) 𝓡_j(β) 𝓡_k(γ)   (2.12.32–40).
//!
//! The extrinsic sequence i-j-k turns about the fixed axes of A in that order, so
//! 𝓡_{D/A} = 𝓡_k(γ) 𝓡_j(β) 𝓡_i(α) (Prob 2.26.10 ii, Prob 2.27.1).
//!
//! ```
//! use vectrix_rotation::prelude::*;
//! // Prob 2.27.1: intrinsic 3-2-1 (Ψ, Θ, Φ) is extrinsic 1-2-3 (Φ, Θ, Ψ).
//! let (psi, theta, phi) = (0.3, -0.2, 1.1);
//! let intrinsic = EulerAngles::new(EulerSequence::S321, [psi, theta, phi]).rotation_matrix();
//! let extrinsic = EulerAngles::new(EulerSequence::S123.extrinsic(), [phi, theta, psi]).rotation_matrix();
//! assert!((intrinsic - extrinsic).amax() < 1e-15);
//! ```

use nalgebra::Matrix3;
use vectrix_tensor::Scalar;

use crate::axis::{quaternion_about_sin_cos, rotation_about_sin_cos, times_rotation_about};
use crate::{Axis, Quaternion, RotationError};

/// Intrinsic (about the new, moving axes: the book's definition) or extrinsic (about the
/// fixed axes of the first frame).
///
/// Book: §2.12; Prob 2.26.10, Prob 2.27.1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EulerKind {
    /// About the axes of each new frame: 𝓡 = 𝓡_i(α)𝓡_j(β)𝓡_k(γ) (2.12.33).
    Intrinsic,
    /// About the fixed axes of the first frame: 𝓡 = 𝓡_k(γ)𝓡_j(β)𝓡_i(α).
    Extrinsic,
}

/// An Euler sequence i-j-k: three axes with unequal neighbours, and its kind.
///
/// Book: §2.12 (L1836): 6 asymmetric (Tait–Bryan, like 3-2-1) and 6 symmetric (i = k, like
/// 3-1-3) sequences.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct EulerSequence {
    axes: [Axis; 3],
    kind: EulerKind,
}

macro_rules! seq {
    ($name:ident, $a:ident, $b:ident, $c:ident, $doc:literal) => {
        #[doc = $doc]
        pub const $name: EulerSequence =
            EulerSequence { axes: [Axis::$a, Axis::$b, Axis::$c], kind: EulerKind::Intrinsic };
    };
}

impl EulerSequence {
    seq!(S123, X, Y, Z, "Intrinsic 1-2-3.");
    seq!(S132, X, Z, Y, "Intrinsic 1-3-2.");
    seq!(S213, Y, X, Z, "Intrinsic 2-1-3.");
    seq!(S231, Y, Z, X, "Intrinsic 2-3-1.");
    seq!(S312, Z, X, Y, "Intrinsic 3-1-2.");
    seq!(S321, Z, Y, X, "Intrinsic 3-2-1: (yaw Ψ, pitch Θ, roll Φ), (2.12.32).");
    seq!(S121, X, Y, X, "Intrinsic 1-2-1, (2.13.27).");
    seq!(S131, X, Z, X, "Intrinsic 1-3-1.");
    seq!(S212, Y, X, Y, "Intrinsic 2-1-2.");
    seq!(S232, Y, Z, Y, "Intrinsic 2-3-2.");
    seq!(S313, Z, X, Z, "Intrinsic 3-1-3: (precession Φ, nutation Θ, spin Ψ), (2.12.39).");
    seq!(S323, Z, Y, Z, "Intrinsic 3-2-3 (Ex 2.25.1).");

    /// All 12 intrinsic sequences.
    pub const ALL: [EulerSequence; 12] = [
        Self::S123,
        Self::S132,
        Self::S213,
        Self::S231,
        Self::S312,
        Self::S321,
        Self::S121,
        Self::S131,
        Self::S212,
        Self::S232,
        Self::S313,
        Self::S323,
    ];

    /// The sequence i-j-k of the given kind.
    ///
    /// # Errors
    /// [`RotationError::EqualAdjacentAxes`] when i = j or j = k.
    pub fn new(axes: [Axis; 3], kind: EulerKind) -> Result<Self, RotationError> {
        if axes[0] == axes[1] || axes[1] == axes[2] {
            return Err(RotationError::EqualAdjacentAxes { axes: axes.map(|a| a.index() as u8) });
        }
        Ok(Self { axes, kind })
    }

    /// The sequence from the book's indices, e.g. `[3, 2, 1]`.
    ///
    /// # Errors
    /// [`RotationError::InvalidAxis`] or [`RotationError::EqualAdjacentAxes`].
    pub fn from_indices(indices: [usize; 3], kind: EulerKind) -> Result<Self, RotationError> {
        Self::new(
            [Axis::from_index(indices[0])?, Axis::from_index(indices[1])?, Axis::from_index(indices[2])?],
            kind,
        )
    }

    /// The same axes, extrinsic.
    pub const fn extrinsic(self) -> Self {
        Self { axes: self.axes, kind: EulerKind::Extrinsic }
    }

    /// The same axes, intrinsic.
    pub const fn intrinsic(self) -> Self {
        Self { axes: self.axes, kind: EulerKind::Intrinsic }
    }

    /// The axes in the order applied.
    #[inline]
    pub fn axes(&self) -> [Axis; 3] {
        self.axes
    }

    /// Intrinsic or extrinsic.
    pub fn kind(&self) -> EulerKind {
        self.kind
    }

    /// `true` for i = k (3-1-3 type), `false` for Tait–Bryan (3-2-1 type).
    #[inline]
    pub fn is_symmetric(&self) -> bool {
        self.axes[0] == self.axes[2]
    }

    /// The intrinsic sequence whose 𝓡-product equals this one with the angles reversed:
    /// extrinsic i-j-k (α, β, γ) = intrinsic k-j-i (γ, β, α).
    #[inline]
    pub(crate) fn as_intrinsic_reversed(&self) -> (Self, bool) {
        match self.kind {
            EulerKind::Intrinsic => (*self, false),
            EulerKind::Extrinsic => {
                let [i, j, k] = self.axes;
                (Self { axes: [k, j, i], kind: EulerKind::Intrinsic }, true)
            }
        }
    }
}

/// Euler angles (α, β, γ) in the order applied, with their sequence (always explicit).
///
/// Book: §2.12, (2.12.32–42).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerAngles<T: Scalar = f64> {
    /// The sequence.
    pub sequence: EulerSequence,
    /// (α, β, γ) in the order applied (3-2-1: (Ψ, Θ, Φ); 3-1-3: (Φ, Θ, Ψ)).
    pub angles: [T; 3],
}

impl<T: Scalar> EulerAngles<T> {
    /// Angles (α, β, γ) in the order applied about the axes of `sequence`.
    pub fn new(sequence: EulerSequence, angles: [T; 3]) -> Self {
        Self { sequence, angles }
    }

    /// 𝓡_{D/A}: 𝓡_i(α)𝓡_j(β)𝓡_k(γ) intrinsic (2.12.33), 𝓡_k(γ)𝓡_j(β)𝓡_i(α) extrinsic.
    ///
    /// Book: (2.12.33), (2.12.40).
    #[inline]
    pub fn rotation_matrix(&self) -> Matrix3<T> {
        // The product of elementary matrices, not the quaternion route: near gimbal lock the
        // entries that carry the factor cos β (or sin β) stay relatively accurate here, while
        // 𝓡(q) forms them by cancellation, which makes the extraction lose ε/cos β.
        let [i, j, k] = self.sequence.axes;
        let [(sa, ca), (sb, cb), (sc, cc)] = T::fast_sin_cos3(self.angles);
        match self.sequence.kind {
            EulerKind::Intrinsic => {
                let m = times_rotation_about(&rotation_about_sin_cos(i, sa, ca), j, sb, cb);
                times_rotation_about(&m, k, sc, cc)
            }
            EulerKind::Extrinsic => {
                let m = times_rotation_about(&rotation_about_sin_cos(k, sc, cc), j, sb, cb);
                times_rotation_about(&m, i, sa, ca)
            }
        }
    }

    /// 𝓞_{D/A} = 𝓞_k(γ)𝓞_j(β)𝓞_i(α) (intrinsic, (2.12.32)); the transpose of
    /// [`EulerAngles::rotation_matrix`].
    ///
    /// Book: (2.12.32), (2.12.39).
    #[doc(alias = "dcm")]
    pub fn orientation_matrix(&self) -> Matrix3<T> {
        self.rotation_matrix().transpose()
    }

    /// Euler parameters q_{D/A} = q_i(α) ⊗ q_j(β) ⊗ q_k(γ) (intrinsic; reversed for extrinsic),
    /// canonical η ≥ 0.
    ///
    /// Book: §2.15, F2.15.7 (corrected order, see [`crate::compose_quaternion`]).
    #[inline]
    pub fn quaternion(&self) -> Quaternion<T> {
        self.quaternion_raw().canonical()
    }

    /// The product of the three elementary factors, not canonicalised.
    #[inline]
    fn quaternion_raw(&self) -> Quaternion<T> {
        let [i, j, k] = self.sequence.axes;
        let half = T::lit(0.5);
        let [a, b, c] = self.angles;
        let [(sa, ca), (sb, cb), (sc, cc)] = T::fast_sin_cos3([a * half, b * half, c * half]);
        match self.sequence.kind {
            EulerKind::Intrinsic => quaternion_about_sin_cos(i, sa, ca)
                .times_elementary_sin_cos(j, sb, cb)
                .times_elementary_sin_cos(k, sc, cc),
            EulerKind::Extrinsic => quaternion_about_sin_cos(k, sc, cc)
                .times_elementary_sin_cos(j, sb, cb)
                .times_elementary_sin_cos(i, sa, ca),
        }
    }
}
