//! Interop with nalgebra and mint (DESIGN §2).
//!
//! - nalgebra `UnitQuaternion` / `Quaternion` is Hamilton with `q * v * q⁻¹` active: the same
//!   as [`Quaternion`] resolved in a frame A, i.e. q_{B/A} with `to_rotation_matrix()` =
//!   𝓡_{B/A} (columns = B's axes in A). Its storage is scalar-last `[i, j, k, w]`; vectrix's
//!   is scalar-first; the conversions below map the parts, never the raw storage.
//! - nalgebra `Rotation3` stores 𝓡_{B/A} (active). Its transpose is the book's 𝓞_{B/A}.
//! - mint `Quaternion { v, s }` carries the same Hamilton parts.

use nalgebra::{Rotation3, Unit, UnitQuaternion, Vector3};
use vectrix_frames::Frame;
use vectrix_tensor::Scalar;

use crate::{Quaternion, Rotation};

impl<T: Scalar> From<nalgebra::Quaternion<T>> for Quaternion<T> {
    fn from(q: nalgebra::Quaternion<T>) -> Self {
        Quaternion::new(q.w, q.i, q.j, q.k)
    }
}

impl<T: Scalar> From<Quaternion<T>> for nalgebra::Quaternion<T> {
    fn from(q: Quaternion<T>) -> Self {
        nalgebra::Quaternion::new(q.a, q.b, q.c, q.d)
    }
}

/// Euler parameters of nalgebra's unit quaternion (same rotation 𝓡; sign made canonical).
impl<T: Scalar> From<UnitQuaternion<T>> for Quaternion<T> {
    fn from(q: UnitQuaternion<T>) -> Self {
        Quaternion::from(q.into_inner()).canonical()
    }
}

impl<T: Scalar> From<Quaternion<T>> for mint::Quaternion<T> {
    fn from(q: Quaternion<T>) -> Self {
        mint::Quaternion { v: mint::Vector3 { x: q.b, y: q.c, z: q.d }, s: q.a }
    }
}

impl<T: Scalar> From<mint::Quaternion<T>> for Quaternion<T> {
    fn from(q: mint::Quaternion<T>) -> Self {
        Quaternion::new(q.s, q.v.x, q.v.y, q.v.z)
    }
}

impl<T: Scalar> Quaternion<T> {
    /// nalgebra's `UnitQuaternion` of the same rotation 𝓡 (normalised by nalgebra).
    pub fn to_unit_quaternion(&self) -> UnitQuaternion<T> {
        Unit::new_normalize(nalgebra::Quaternion::from(*self))
    }
}

impl<T: Scalar> Rotation<T> {
    /// nalgebra `UnitQuaternion` of R⃗ resolved in `a`: for R⃗_{B/A} it is q_{B/A}, whose
    /// `to_rotation_matrix()` is 𝓡_{B/A} (not 𝓞).
    ///
    /// Book: (2.15.20), Prob 2.26.23.
    pub fn to_unit_quaternion_in(&self, a: &Frame<T>) -> UnitQuaternion<T> {
        Unit::new_unchecked(self.quaternion_in(a).into())
    }

    /// From nalgebra's `UnitQuaternion` resolved in `a` (read as q_{B/A}).
    pub fn from_unit_quaternion_in(a: &Frame<T>, q: &UnitQuaternion<T>) -> Self {
        Self::from_quaternion_parts(a, &Quaternion::from(*q))
    }

    /// nalgebra `Rotation3` holding 𝓡_{B/A} = R⃗_{B/A}|_A (active; its transpose is 𝓞_{B/A}).
    ///
    /// Book: (2.10.2).
    pub fn to_rotation3_in(&self, a: &Frame<T>) -> Rotation3<T> {
        Rotation3::from_matrix_unchecked(self.rotation_matrix_in(a))
    }

    /// From nalgebra `Rotation3` read as 𝓡_{B/A} in `a` (Shepperd/Markley; nalgebra guarantees
    /// nothing about orthonormality, so use [`Rotation::from_rotation_matrix_in`] for
    /// untrusted input).
    pub fn from_rotation3_in(a: &Frame<T>, r: &Rotation3<T>) -> Self {
        Self::from_rotation_matrix_in_unchecked(a, r.matrix())
    }

    /// mint quaternion of R⃗ resolved in `a` (q_{B/A}, Hamilton, active).
    pub fn to_mint_in(&self, a: &Frame<T>) -> mint::Quaternion<T> {
        self.quaternion_in(a).into()
    }

    /// 𝓡_{B/A} as a mint row-major matrix (rows of 𝓡, i.e. the *columns* of 𝓞_{B/A}).
    pub fn to_mint_matrix_in(&self, a: &Frame<T>) -> mint::RowMatrix3<T> {
        let m = self.rotation_matrix_in(a);
        let row = |r: usize| mint::Vector3 { x: m[(r, 0)], y: m[(r, 1)], z: m[(r, 2)] };
        mint::RowMatrix3 { x: row(0), y: row(1), z: row(2) }
    }
}

/// nalgebra's `Vector3` from the angle vector of a quaternion (scipy `as_rotvec`,
/// nalgebra `scaled_axis`): the same numbers as [`Quaternion::angle_vector`].
pub fn scaled_axis<T: Scalar>(q: &Quaternion<T>) -> Vector3<T> {
    q.angle_vector()
}
