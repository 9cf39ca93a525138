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
    let (s, c) = crate::series::sin_cos(theta);
    rotation_about_sin_cos(axis, s, c)
}

/// 𝓡_i(θ) from (sin θ, cos θ).
#[inline(always)]
pub(crate) fn rotation_about_sin_cos<T: Scalar>(axis: Axis, s: T, c: T) -> Matrix3<T> {
    let (o, z) = (T::one(), T::zero());
    match axis {
        Axis::X => Matrix3::new(o, z, z, z, c, -s, z, s, c),
        Axis::Y => Matrix3::new(c, z, s, z, o, z, -s, z, c),
        Axis::Z => Matrix3::new(c, -s, z, s, c, z, z, z, o),
    }
}

/// 𝓜 𝓡_k(θ) from (sin θ, cos θ), using the sparsity of 𝓡_k: column k of 𝓜 is kept and, with
/// (p, q) = (k + 1, k + 2) mod 3, the new columns are c·m_p + s·m_q and c·m_q − s·m_p. The
/// same sums as the dense product without its exact terms 0·m and 1·m.
///
/// Book: (2.12.17–19), (2.12.33).
#[inline(always)]
pub(crate) fn times_rotation_about<T: Scalar>(m: &Matrix3<T>, axis: Axis, s: T, c: T) -> Matrix3<T> {
    // One monomorphised body per axis: constant indices keep the matrix in registers.
    match axis {
        Axis::X => times_rotation_about_k::<T, 0>(m, s, c),
        Axis::Y => times_rotation_about_k::<T, 1>(m, s, c),
        Axis::Z => times_rotation_about_k::<T, 2>(m, s, c),
    }
}

/// [`times_rotation_about`] for the axis of index `K`.
#[inline(always)]
fn times_rotation_about_k<T: Scalar, const K: usize>(m: &Matrix3<T>, s: T, c: T) -> Matrix3<T> {
    let (p, q) = ((K + 1) % 3, (K + 2) % 3);
    let mut out = *m;
    for r in 0..3 {
        let (mp, mq) = (m[(r, p)], m[(r, q)]);
        out[(r, p)] = c * mp + s * mq;
        out[(r, q)] = c * mq - s * mp;
    }
    out
}

impl<T: Scalar> Quaternion<T> {
    /// 𝐪 ⊗ q_i(θ): the Hamilton product with an elementary factor (c, s e_i), using its
    /// sparsity (8 multiplications instead of 16).
    ///
    /// Book: (2.16.10) with v₁ = s e_i.
    #[inline]
    pub fn times_elementary(&self, axis: Axis, theta: T) -> Quaternion<T> {
        let (s, c) = crate::series::sin_cos(theta * T::lit(0.5));
        self.times_elementary_sin_cos(axis, s, c)
    }

    /// 𝐪 ⊗ (c, s e_i) with (s, c) = (sin θ/2, cos θ/2).
    #[inline(always)]
    pub(crate) fn times_elementary_sin_cos(&self, axis: Axis, s: T, c: T) -> Quaternion<T> {
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
    let (s, c) = crate::series::sin_cos(theta * T::lit(0.5));
    quaternion_about_sin_cos(axis, s, c)
}

/// (c, s e_i) with (s, c) = (sin θ/2, cos θ/2).
#[inline(always)]
pub(crate) fn quaternion_about_sin_cos<T: Scalar>(axis: Axis, s: T, c: T) -> Quaternion<T> {
    let z = T::zero();
    match axis {
        Axis::X => Quaternion::new(c, s, z, z),
        Axis::Y => Quaternion::new(c, z, s, z),
        Axis::Z => Quaternion::new(c, z, z, s),
    }
}
