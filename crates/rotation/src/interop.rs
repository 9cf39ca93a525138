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

use crate::{AxisAngle, EulerAngles, Quaternion, Rotation};

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

// ---------------------------------------------------------------------------------------
// Every resolved representation into nalgebra's and mint's rotation types (issue 23).
// Angle vectors, Gibbs vectors, MRPs (nalgebra `Vector3`) and rotation/orientation matrices
// (nalgebra `Matrix3`) convert to mint through nalgebra's own `convert-mint` impls, enabled
// by this crate: `mint::Vector3::from(v)`, `mint::ColumnMatrix3::from(m)`, and mint turns a
// column matrix into a `RowMatrix3` with `From`.

/// nalgebra's `UnitQuaternion` from Euler parameters that are unit within [`crate::ROTATION_TOL`]
/// (the parts are kept as they are: same rotation 𝓡, same sign).
///
/// Book: (2.15.20).
///
/// # Errors
/// [`crate::RotationError::NonFinite`], [`crate::RotationError::NotUnit`] (normalise explicitly
/// with [`Quaternion::normalize`] first).
impl<T: Scalar> TryFrom<Quaternion<T>> for UnitQuaternion<T> {
    type Error = crate::RotationError;
    fn try_from(q: Quaternion<T>) -> Result<Self, Self::Error> {
        q.check_unit(crate::ROTATION_TOL)?;
        Ok(Unit::new_unchecked(q.into()))
    }
}

/// nalgebra's `Rotation3` holding 𝓡(q) (2.15.14), active: q_{B/A} gives 𝓡_{B/A}.
///
/// Book: (2.15.14).
///
/// # Errors
/// As `UnitQuaternion::try_from`: the quaternion must be unit within [`crate::ROTATION_TOL`].
impl<T: Scalar> TryFrom<Quaternion<T>> for Rotation3<T> {
    type Error = crate::RotationError;
    fn try_from(q: Quaternion<T>) -> Result<Self, Self::Error> {
        q.check_unit(crate::ROTATION_TOL)?;
        Ok(Rotation3::from_matrix_unchecked(q.rotation_matrix()))
    }
}

/// Euler parameters of nalgebra's `Rotation3` read as 𝓡 (Shepperd/Markley, canonical η ≥ 0).
/// nalgebra trusts a `Rotation3` to be orthonormal; for untrusted matrices use
/// [`Quaternion::from_rotation_matrix`], which checks.
///
/// Book: §2.15, (2.15.8–10).
impl<T: Scalar> From<Rotation3<T>> for Quaternion<T> {
    fn from(r: Rotation3<T>) -> Self {
        Quaternion::from_rotation_matrix_unchecked(r.matrix())
    }
}

/// The unit quaternion of Euler angles: q_i(α) ⊗ q_j(β) ⊗ q_k(γ) (intrinsic), canonical.
///
/// Book: §2.15, F2.15.7.
impl<T: Scalar> From<EulerAngles<T>> for UnitQuaternion<T> {
    fn from(e: EulerAngles<T>) -> Self {
        Unit::new_unchecked(e.quaternion().into())
    }
}

/// 𝓡_{D/A} of Euler angles (2.12.33), as nalgebra's `Rotation3`.
///
/// Book: (2.12.33), (2.12.40).
impl<T: Scalar> From<EulerAngles<T>> for Rotation3<T> {
    fn from(e: EulerAngles<T>) -> Self {
        Rotation3::from_matrix_unchecked(e.rotation_matrix())
    }
}

/// mint's quaternion of Euler angles (Hamilton, canonical η ≥ 0).
///
/// mint's own `EulerAngles<T, B>` is deliberately not converted: its basis markers do not say
/// unambiguously whether the angles are intrinsic or extrinsic (nalgebra reads `IntraXYZ` as
/// roll–pitch–yaw about fixed axes), and vectrix never guesses a convention.
///
/// Book: §2.15, F2.15.7.
impl<T: Scalar> From<EulerAngles<T>> for mint::Quaternion<T> {
    fn from(e: EulerAngles<T>) -> Self {
        e.quaternion().into()
    }
}

/// Euler parameters of a resolved axis–angle: (1, 0⃗) for the identity, (0, n̂) for a half turn,
/// (cos θ/2, sin θ/2 n̂) otherwise (2.15.20).
///
/// Book: (2.15.20), Facts 2.11.4–5.
impl<T: Scalar> From<AxisAngle<T, Vector3<T>>> for Quaternion<T> {
    fn from(x: AxisAngle<T, Vector3<T>>) -> Self {
        match x {
            AxisAngle::Identity => Quaternion::identity(),
            AxisAngle::HalfTurn(n) => Quaternion::from_parts(T::zero(), n),
            AxisAngle::General { axis, angle } => {
                let (s, c) = (angle * T::lit(0.5)).sin_cos();
                Quaternion::from_parts(c, axis * s)
            }
        }
    }
}

/// nalgebra's `UnitQuaternion` of a resolved axis–angle (the axis is unit by construction).
///
/// Book: (2.15.20).
impl<T: Scalar> From<AxisAngle<T, Vector3<T>>> for UnitQuaternion<T> {
    fn from(x: AxisAngle<T, Vector3<T>>) -> Self {
        Unit::new_unchecked(Quaternion::from(x).into())
    }
}

/// Rodrigues's 𝓡 of a resolved axis–angle, as nalgebra's `Rotation3`.
///
/// Book: (2.11.1), (2.15.14).
impl<T: Scalar> From<AxisAngle<T, Vector3<T>>> for Rotation3<T> {
    fn from(x: AxisAngle<T, Vector3<T>>) -> Self {
        Rotation3::from_matrix_unchecked(Quaternion::from(x).rotation_matrix())
    }
}

/// mint's quaternion of a resolved axis–angle.
///
/// Book: (2.15.20).
impl<T: Scalar> From<AxisAngle<T, Vector3<T>>> for mint::Quaternion<T> {
    fn from(x: AxisAngle<T, Vector3<T>>) -> Self {
        Quaternion::from(x).into()
    }
}

/// Eigenaxis and eigenangle of nalgebra's `UnitQuaternion`, with vectrix's singular cases as
/// variants (θ = 0, θ = π with the canonical axis sign).
///
/// Book: §2.11, Facts 2.11.4–5, (2.11.49).
impl<T: Scalar> From<UnitQuaternion<T>> for AxisAngle<T, Vector3<T>> {
    fn from(q: UnitQuaternion<T>) -> Self {
        Quaternion::from(q).axis_angle()
    }
}
