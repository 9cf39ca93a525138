//! serde for every attitude representation (cargo feature `serde`).
//!
//! | type | JSON |
//! |---|---|
//! | [`Quaternion`] | `{"a": η, "b": ε₁, "c": ε₂, "d": ε₃}` (Hamilton, scalar first, as stored) |
//! | [`Axis`] | `1`, `2` or `3` (the book's index) |
//! | [`EulerKind`] | `"intrinsic"` or `"extrinsic"` |
//! | [`EulerSequence`] | `{"axes": [3, 2, 1], "kind": "intrinsic"}` |
//! | [`EulerAngles`] | `{"sequence": {…}, "angles": [α, β, γ]}` (radians, in the order applied) |
//! | [`AxisAngle`] | `"identity"`, `{"half_turn": [n₁, n₂, n₃]}` or `{"general": {"axis": [n₁, n₂, n₃], "angle": θ}}` |
//! | [`Rotation`] | `{"a": …, "b": …, "c": …, "d": …}`: its Euler parameters in the first frame F₀ |
//! | [`RigidDisplacement`] | `{"rotation": {…}, "translation": [x, y, z]}` (translation in F₀) |
//!
//! Frame-free objects (a [`Rotation`], the axis of `AxisAngle<T, Vector<T>>`, a translation)
//! have no components of their own; a file holds them resolved in the **first frame**
//! F₀ = `Frame::new()`. A [`Rotation`] is written with the sign of its rotor as stored (not the
//! canonical η ≥ 0), so a round trip gives back the same rotor, not only the same rotation.
//!
//! Reading checks what the constructors check and reports their error messages: a sequence
//! with equal neighbours, an axis index outside 1–3, a rotation whose quaternion is not unit
//! within [`ROTATION_TOL`], an axis–angle whose axis is not unit within [`ROTATION_TOL`] or
//! whose angle lies outside (0, π], and non-finite numbers. Gibbs vectors, modified Rodrigues
//! parameters, angle vectors and rotation matrices are `nalgebra` values: enable nalgebra's
//! `serde-serialize` feature (the facade's `serde` feature does) for them.
//!
//! Book: §2.11–2.17, (2.15.20), (2.16.3), §2.21. JSON forms: `docs/guide/interop.md`.

use nalgebra::Vector3;
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use vectrix_frames::{Frame, Resolve};
use vectrix_tensor::{Scalar, Vector};

use crate::series::all_finite;
use crate::{
    Axis, AxisAngle, EulerAngles, EulerKind, EulerSequence, Quaternion, ROTATION_TOL, RigidDisplacement,
    Rotation,
};

// ---------------------------------------------------------------------------------------
// Quaternion: the four Hamilton parts, as stored.

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Parts<T> {
    a: T,
    b: T,
    c: T,
    d: T,
}

/// `{"a": …, "b": …, "c": …, "d": …}` (2.16.3).
impl<T: Scalar + Serialize> Serialize for Quaternion<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        Parts { a: self.a, b: self.b, c: self.c, d: self.d }.serialize(s)
    }
}

/// Any quaternion with finite parts (a quaternion need not be unit: §2.16).
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for Quaternion<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let Parts { a, b, c, d: dd } = Parts::<T>::deserialize(d)?;
        if !all_finite([a, b, c, dd]) {
            return Err(D::Error::custom("non-finite quaternion part: every part must be a finite number"));
        }
        Ok(Quaternion::new(a, b, c, dd))
    }
}

// ---------------------------------------------------------------------------------------
// Axes, kinds, sequences, Euler angles.

/// The book's index 1, 2 or 3.
impl Serialize for Axis {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_u8(self.index() as u8)
    }
}

/// From 1, 2 or 3 ([`crate::RotationError::InvalidAxis`] otherwise).
impl<'de> Deserialize<'de> for Axis {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Axis::from_index(usize::from(u8::deserialize(d)?)).map_err(D::Error::custom)
    }
}

#[derive(Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
enum KindRepr {
    Intrinsic,
    Extrinsic,
}

/// `"intrinsic"` or `"extrinsic"`.
impl Serialize for EulerKind {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            EulerKind::Intrinsic => KindRepr::Intrinsic,
            EulerKind::Extrinsic => KindRepr::Extrinsic,
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for EulerKind {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Ok(match KindRepr::deserialize(d)? {
            KindRepr::Intrinsic => EulerKind::Intrinsic,
            KindRepr::Extrinsic => EulerKind::Extrinsic,
        })
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct SequenceRepr {
    axes: [Axis; 3],
    kind: EulerKind,
}

/// `{"axes": [3, 2, 1], "kind": "intrinsic"}`.
impl Serialize for EulerSequence {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        SequenceRepr { axes: self.axes(), kind: self.kind() }.serialize(s)
    }
}

/// Checked by [`EulerSequence::new`] (no equal neighbours).
impl<'de> Deserialize<'de> for EulerSequence {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let SequenceRepr { axes, kind } = SequenceRepr::deserialize(d)?;
        EulerSequence::new(axes, kind).map_err(D::Error::custom)
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct EulerRepr<T> {
    sequence: EulerSequence,
    angles: [T; 3],
}

/// `{"sequence": {…}, "angles": [α, β, γ]}` in radians, in the order applied (§2.12).
impl<T: Scalar + Serialize> Serialize for EulerAngles<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        EulerRepr { sequence: self.sequence, angles: self.angles }.serialize(s)
    }
}

/// Any finite angles (Euler angles are not wrapped: §2.12).
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for EulerAngles<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let EulerRepr { sequence, angles } = EulerRepr::<T>::deserialize(d)?;
        if !all_finite(angles) {
            return Err(D::Error::custom("non-finite Euler angle: every angle must be a finite number"));
        }
        Ok(EulerAngles::new(sequence, angles))
    }
}

// ---------------------------------------------------------------------------------------
// Eigenaxis and eigenangle.

#[derive(Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
enum AxisAngleRepr<T> {
    Identity,
    HalfTurn([T; 3]),
    General { axis: [T; 3], angle: T },
}

fn axis_angle_repr<T: Scalar, V: Copy>(
    x: &AxisAngle<T, V>,
    comps: impl Fn(&V) -> [T; 3],
) -> AxisAngleRepr<T> {
    match x {
        AxisAngle::Identity => AxisAngleRepr::Identity,
        AxisAngle::HalfTurn(n) => AxisAngleRepr::HalfTurn(comps(n)),
        AxisAngle::General { axis, angle } => AxisAngleRepr::General { axis: comps(axis), angle: *angle },
    }
}

/// Checks the Euler's-theorem invariants (§2.11): a finite unit axis within [`ROTATION_TOL`],
/// θ ∈ (0, π] for `General`.
fn axis_angle_from<T: Scalar, V, E: serde::de::Error>(
    r: AxisAngleRepr<T>,
    make: impl Fn([T; 3]) -> V,
) -> Result<AxisAngle<T, V>, E> {
    let unit = |n: [T; 3]| {
        let norm = Vector3::from(n).norm().re();
        if !all_finite(n) || (norm - 1.0).abs() > ROTATION_TOL {
            return Err(E::custom(format!(
                "eigenaxis {:?} has norm {norm:e}: it must be a finite unit vector (within {ROTATION_TOL:e})",
                n.map(|x| x.re())
            )));
        }
        Ok(make(n))
    };
    Ok(match r {
        AxisAngleRepr::Identity => AxisAngle::Identity,
        AxisAngleRepr::HalfTurn(n) => AxisAngle::HalfTurn(unit(n)?),
        AxisAngleRepr::General { axis, angle } => {
            let t = angle.re();
            // Fact 2.11.4–5: θ = 0 and θ = π are their own variants, so General holds θ > 0 up
            // to π (2 atan2(|ε|, η) rounds to fl(π) when η is a few ulps above 0).
            if !(t > 0.0 && t <= core::f64::consts::PI) {
                return Err(E::custom(format!(
                    "eigenangle θ = {t} of a general axis–angle must lie in (0, π]; use \"identity\" for θ = 0"
                )));
            }
            AxisAngle::General { axis: unit(axis)?, angle }
        }
    })
}

/// Resolved axis–angle (from [`Quaternion::axis_angle`]): the axis as `[n₁, n₂, n₃]`.
impl<T: Scalar + Serialize> Serialize for AxisAngle<T, Vector3<T>> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        axis_angle_repr(self, |n| [n.x, n.y, n.z]).serialize(s)
    }
}

impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for AxisAngle<T, Vector3<T>> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        axis_angle_from(AxisAngleRepr::deserialize(d)?, Vector3::from)
    }
}

/// Physical axis–angle (from [`Rotation::axis_angle`]): the axis resolved in F₀.
impl<T: Scalar + Serialize> Serialize for AxisAngle<T, Vector<T>> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let f0 = Frame::<T>::identity();
        axis_angle_repr(self, |n| n.resolve(&f0).into()).serialize(s)
    }
}

impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for AxisAngle<T, Vector<T>> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let f0 = Frame::<T>::identity();
        axis_angle_from(AxisAngleRepr::deserialize(d)?, |n| f0.vector(n))
    }
}

// ---------------------------------------------------------------------------------------
// Physical rotations and rigid displacements.

impl<T: Scalar> Rotation<T> {
    /// R = q₀ − 𝒥q⃗ (3.9.17) resolved in F₀ with the rotor's own sign (not canonicalised).
    fn stored_parts_in_first_frame(&self) -> Quaternion<T> {
        let r = self.rotor();
        let e = -r.bivector().undual().resolve(&Frame::identity());
        Quaternion::from_parts(r.scalar(), e)
    }
}

/// Its Euler parameters in F₀, with the rotor's sign as stored.
impl<T: Scalar + Serialize> Serialize for Rotation<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.stored_parts_in_first_frame().serialize(s)
    }
}

/// Checked by [`Rotation::from_quaternion_in`] with [`ROTATION_TOL`] (finite, unit).
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for Rotation<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let q = Quaternion::<T>::deserialize(d)?;
        Rotation::from_quaternion_in(&Frame::identity(), &q, ROTATION_TOL).map_err(D::Error::custom)
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RigidRepr<T: Scalar> {
    rotation: Rotation<T>,
    translation: Vector<T>,
}

/// `{"rotation": {…}, "translation": [x, y, z]}` (F2.21.1), both in F₀.
impl<T: Scalar + Serialize> Serialize for RigidDisplacement<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        RigidRepr { rotation: self.rotation, translation: self.translation }.serialize(s)
    }
}

impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for RigidDisplacement<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let RigidRepr { rotation, translation } = RigidRepr::<T>::deserialize(d)?;
        Ok(RigidDisplacement::new(rotation, translation))
    }
}
