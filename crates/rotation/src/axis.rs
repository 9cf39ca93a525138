//! Frame axes 1, 2, 3 and the elementary (Euler) matrices 𝓞_i(θ), 𝓡_i(θ) (book §2.12).

use nalgebra::Matrix3;
use vectrix_tensor::Scalar;

use crate::{Quaternion, RotationError};

/// An axis of a frame: 1 = î, 2 = ĵ, 3 = k̂ (x, y, z).
///
/// Book: §2.12, (2.12.1–3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Axis {
    /// Axis 1, î (x).
    X = 1,
    /// Axis 2, ĵ (y).
    Y = 2,
    /// Axis 3, k̂ (z).
    Z = 3,
}

impl Axis {
    /// Axis from the book's index 1, 2, 3.
    ///
    /// # Errors
    /// [`RotationError::InvalidAxis`] outside 1..=3.
    pub fn from_index(index: usize) -> Result<Self, RotationError> {
        match index {
            1 => Ok(Axis::X),
            2 => Ok(Axis::Y),
            3 => Ok(Axis::Z),
            _ => Err(RotationError::InvalidAxis { index }),
        }
    }

    /// The book's index 1, 2, 3.
    #[inline]
    pub fn index(self) -> usize {
        self as usize
    }

    /// Zero-based component index 0, 1, 2.
    #[inline]
    pub(crate) fn i0(self) -> usize {
        self as usize - 1
    }
}

/// Elementary orientation matrix 𝓞_i(θ) (2.12.14–16), passive: 𝓞_{B/A} when F_B = R⃗_{î_A}(θ)F_A
/// (and likewise for axes 2, 3). 𝓞₁(θ) = `[[1,0,0],[0,c,s],[0,−s,c]]`.
///
/// Book: (2.12.14–16), Fact 2.12.1, Fact 2.13.1.
#[doc(alias = "O1")]
#[doc(alias = "O2")]
#[doc(alias = "O3")]
#[inline]
pub fn orientation_about<T: Scalar>(axis: Axis, theta: T) -> Matrix3<T> {
    rotation_about(axis, -theta)
}

/// Elementary rotation matrix 𝓡_i(θ) = 𝓞_i(θ)ᵀ (active, right-hand rule).
/// 𝓡₃(θ) = `[[c,−s,0],[s,c,0],[0,0,1]]`.
///
/// Book: (2.12.17–19).
#[doc(alias = "R1")]
#[doc(alias = "R2")]
#[doc(alias = "R3")]
#[inline]
pub fn rotation_about<T: Scalar>(axis: Axis, theta: T) -> Matrix3<T> {
    let (s, c) = theta.sin_cos();
    let (o, z) = (T::one(), T::zero());
    match axis {
        Axis::X => Matrix3::new(o, z, z, z, c, -s, z, s, c),
        Axis::Y => Matrix3::new(c, z, s, z, o, z, -s, z, c),
        Axis::Z => Matrix3::new(c, -s, z, s, c, z, z, z, o),
    }
}

impl<T: Scalar> Quaternion<T> {
    /// 𝐪 ⊗ q_i(θ): the Hamilton product with an elementary factor (c, s e_i), using its
    /// sparsity (8 multiplications instead of 16).
    ///
    /// Book: (2.16.10) with v₁ = s e_i.
    #[inline]
    pub fn times_elementary(&self, axis: Axis, theta: T) -> Quaternion<T> {
        let (s, c) = (theta * T::lit(0.5)).sin_cos();
        let (a, b, cc, d) = (self.a, self.b, self.c, self.d);
        // (a c − s v·e_i, c v + a s e_i + s v × e_i)
        match axis {
            Axis::X => Quaternion::new(a * c - b * s, b * c + a * s, cc * c + d * s, d * c - cc * s),
            Axis::Y => Quaternion::new(a * c - cc * s, b * c - d * s, cc * c + a * s, d * c + b * s),
            Axis::Z => Quaternion::new(a * c - d * s, b * c + cc * s, cc * c - b * s, d * c + a * s),
        }
    }
}

/// Euler parameters of 𝓡_i(θ): (cos θ/2, sin θ/2 e_i), not canonicalised (so products of
/// elementary factors stay smooth in θ).
///
/// Book: (2.15.20) for n̂ = e_i.
#[inline]
pub fn quaternion_about<T: Scalar>(axis: Axis, theta: T) -> Quaternion<T> {
    let (s, c) = (theta * T::lit(0.5)).sin_cos();
    let z = T::zero();
    match axis {
        Axis::X => Quaternion::new(c, s, z, z),
        Axis::Y => Quaternion::new(c, z, s, z),
        Axis::Z => Quaternion::new(c, z, z, s),
    }
}
