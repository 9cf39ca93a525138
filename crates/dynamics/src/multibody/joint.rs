//! The book's joints (§1.5, Table 1.3) and links, and the elementary joints (revolute,
//! prismatic, spherical, fixed) a tree is built from.
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use vectrix_tensor::Scalar;

use super::spatial::Xform;
use crate::DynamicsError;
use crate::error::check_finite;

/// A joint between a link and its parent (book Table 1.3 and §1.5: pin, sleeve, collar,
/// slot, ball; plus weld and free). Axes and directions are components in the joint frame,
/// which is placed in the parent link by [`Link::offset`] and [`Link::orientation`].
///
/// Book: §1.5 (the five joint types), Table 1.3.
///
/// # Conventions
/// Coordinates q (and velocities v) per joint:
/// * `Pin` – rotation θ about `axis` (right-hand rule): q = (θ), v = (θ̇).
/// * `Sleeve` – translation s along `axis`: q = (s).
/// * `Collar` – translation s along `axis`, then rotation θ about the same axis: q = (s, θ).
/// * `Slot` – translation s along `direction` (a groove in the parent), then rotation θ about
///   `axis` ⊥ `direction` (the pin): q = (s, θ).
/// * `Ball` – attitude as a unit quaternion (η, ε₁, ε₂, ε₃) of the link relative to the joint
///   frame, scalar first: q has 4 entries, v = ω_{link/joint} resolved in the link (3).
/// * `Weld` – no coordinates.
/// * `Free` – translation (x, y, z) resolved in the joint frame, then a ball: q has 7 entries,
///   v = (ẋ, ẏ, ż, ω in the link) has 6.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Joint {
    /// Rotation about one axis, no translation.
    Pin {
        /// Rotation axis (nonzero; normalized).
        axis: Vector3<f64>,
    },
    /// Translation along one direction, no rotation.
    Sleeve {
        /// Translation direction (nonzero; normalized).
        axis: Vector3<f64>,
    },
    /// Translation along and rotation about the same axis.
    Collar {
        /// The common axis (nonzero; normalized).
        axis: Vector3<f64>,
    },
    /// Translation along `direction`, rotation about `axis`, perpendicular.
    Slot {
        /// Rotation axis of the pin.
        axis: Vector3<f64>,
        /// Direction of the groove, perpendicular to `axis`.
        direction: Vector3<f64>,
    },
    /// Rotation about three axes (spherical joint).
    Ball,
    /// Rigid attachment.
    Weld,
    /// Six degrees of freedom (a floating body).
    Free,
}

impl Joint {
    /// Number of coordinates q of the joint (Table 1.3 and the conventions above): pin and
    /// sleeve 1, collar and slot 2, ball 4 (a unit quaternion), weld 0, free 7.
    ///
    /// Book: §1.5, Table 1.3.
    pub fn nq(&self) -> usize {
        match self {
            Joint::Pin { .. } | Joint::Sleeve { .. } => 1,
            Joint::Collar { .. } | Joint::Slot { .. } => 2,
            Joint::Ball => 4,
            Joint::Weld => 0,
            Joint::Free => 7,
        }
    }

    /// Number of velocity coordinates v of the joint (its degrees of freedom): pin and sleeve
    /// 1, collar and slot 2, ball 3, weld 0, free 6.
    ///
    /// Book: §1.5, Table 1.3.
    pub fn nv(&self) -> usize {
        match self {
            Joint::Ball => 3,
            Joint::Free => 6,
            j => j.nq(),
        }
    }

    /// Index of the unit quaternion (η, ε₁, ε₂, ε₃) among the joint's coordinates q: 0 for a
    /// ball, 3 for a free joint (after x, y, z), `None` for the others.
    ///
    /// Book: §2.15 (Euler parameters).
    pub fn quaternion_index(&self) -> Option<usize> {
        match self {
            Joint::Ball => Some(0),
            Joint::Free => Some(3),
            _ => None,
        }
    }

    /// Index of the joint's one rotation angle θ among its coordinates (q and v align there):
    /// 0 for a pin, 1 for a collar or slot (after s), `None` for the others.
    ///
    /// Book: §1.5, Table 1.3.
    pub fn angle_index(&self) -> Option<usize> {
        match self {
            Joint::Pin { .. } => Some(0),
            Joint::Collar { .. } | Joint::Slot { .. } => Some(1),
            _ => None,
        }
    }

    /// The coordinates q and velocities v of the joint in words, with units, as the
    /// conventions above state them (for messages that say what a joint expects).
    ///
    /// Book: §1.5, Table 1.3.
    pub fn layout(&self) -> (&'static str, &'static str) {
        match self {
            Joint::Pin { .. } => ("q = [θ] rad", "v = [θ̇] rad/s"),
            Joint::Sleeve { .. } => ("q = [s] m", "v = [ṡ] m/s"),
            Joint::Collar { .. } | Joint::Slot { .. } => ("q = [s m, θ rad]", "v = [ṡ m/s, θ̇ rad/s]"),
            Joint::Ball => {
                ("q = [η, ε₁, ε₂, ε₃] (unit quaternion)", "v = [ω₁, ω₂, ω₃] rad/s in the link frame")
            }
            Joint::Weld => ("q = [] (no coordinates)", "v = []"),
            Joint::Free => (
                "q = [x, y, z m, η, ε₁, ε₂, ε₃]",
                "v = [ẋ, ẏ, ż m/s in the joint frame, ω₁, ω₂, ω₃ rad/s in the link frame]",
            ),
        }
    }
}

/// One rigid link of a tree: its parent (`None` = the inertial ground), the joint into it,
/// where the joint frame sits in the parent link, and the link's mass properties.
///
/// Book: §7.11 (chains), §6.1–6.2 (mass properties).
///
/// # Conventions
/// Everything is resolved in link frames: `offset` = r_{joint/parent origin}|_{parent},
/// `orientation` = 𝓞_{J/P} (passive: x|_J = 𝓞_{J/P} x|_P) of the joint frame relative to the
/// parent link frame; at q = 0 the link frame coincides with the joint frame. `com` is the
/// centre of mass and `inertia` is J_{B/c} resolved in the link frame (matrix entries, so
/// products of inertia enter as −J_xy).
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// Parent link index, or `None` for the ground.
    pub parent: Option<usize>,
    /// The joint connecting this link to its parent.
    pub joint: Joint,
    /// r_{joint/parent origin} resolved in the parent link frame.
    pub offset: Vector3<f64>,
    /// 𝓞_{J/P}.
    pub orientation: Matrix3<f64>,
    /// m ≥ 0 (a massless link needs massive descendants for forward dynamics).
    pub mass: f64,
    /// r_{c/link origin} resolved in the link frame.
    pub com: Vector3<f64>,
    /// J_{B/c} resolved in the link frame.
    pub inertia: Matrix3<f64>,
}

impl Link {
    /// A link with the given parent and joint, at `offset` in the parent, no rotation of the
    /// joint frame, with mass m, centre `com` and J_{B/c} = `inertia` (link frame).
    pub fn new(
        parent: Option<usize>,
        joint: Joint,
        offset: Vector3<f64>,
        mass: f64,
        com: Vector3<f64>,
        inertia: Matrix3<f64>,
    ) -> Self {
        Self { parent, joint, offset, orientation: Matrix3::identity(), mass, com, inertia }
    }
}

/// A link pose: 𝓞_{link/ground} and r_{link origin/ground origin} resolved in the ground frame.
pub type Pose<T = f64> = (Matrix3<T>, Vector3<T>);

/// Elementary joints the book's joints are made of.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Elem<T: Scalar> {
    Revolute(Vector3<T>),
    Prismatic(Vector3<T>),
    Spherical,
    Fixed,
}

impl Elem<f64> {
    pub(crate) fn cast<U: Scalar>(&self) -> Elem<U> {
        match self {
            Elem::Revolute(a) => Elem::Revolute(a.map(U::lit)),
            Elem::Prismatic(a) => Elem::Prismatic(a.map(U::lit)),
            Elem::Spherical => Elem::Spherical,
            Elem::Fixed => Elem::Fixed,
        }
    }
}

impl<T: Scalar> Elem<T> {
    pub fn nq(&self) -> usize {
        match self {
            Elem::Revolute(_) | Elem::Prismatic(_) => 1,
            Elem::Spherical => 4,
            Elem::Fixed => 0,
        }
    }
    pub fn nv(&self) -> usize {
        match self {
            Elem::Revolute(_) | Elem::Prismatic(_) => 1,
            Elem::Spherical => 3,
            Elem::Fixed => 0,
        }
    }

    /// The joint transform for the coordinates `q` (length nq); `sc`: a revolute joint's
    /// (sin θ, cos θ) when the caller has it (computed with the other joints'), else computed
    /// here (the same bits either way).
    #[inline(always)]
    pub fn xform(&self, q: &[T], sc: Option<(T, T)>) -> Xform<T> {
        match self {
            Elem::Revolute(a) => {
                // passive rotation about a by θ: E = 𝓡(a, θ)ᵀ = c 1 − s a^× + (1 − c) a aᵀ
                // (Rodrigues (2.11.1), transposed)
                let (s, c) = sc.unwrap_or_else(|| q[0].fast_sin_cos());
                let (o, z0) = (T::one(), T::zero());
                // about a coordinate axis (±x̂, ±ŷ, ±ẑ): the same matrix with its zeros and
                // ones exact, and 30 fewer operations
                if a.y == z0 && a.z == z0 {
                    let s = s * a.x;
                    return Xform { E: Matrix3::new(o, z0, z0, z0, c, s, z0, -s, c), r: Vector3::zeros() };
                }
                if a.x == z0 && a.z == z0 {
                    let s = s * a.y;
                    return Xform { E: Matrix3::new(c, z0, -s, z0, o, z0, s, z0, c), r: Vector3::zeros() };
                }
                if a.x == z0 && a.y == z0 {
                    let s = s * a.z;
                    return Xform { E: Matrix3::new(c, s, z0, -s, c, z0, z0, z0, o), r: Vector3::zeros() };
                }
                let k = T::one() - c;
                let (x, y, z) = (a.x, a.y, a.z);
                let e = Matrix3::new(
                    c + k * x * x,
                    k * x * y + s * z,
                    k * x * z - s * y,
                    k * x * y - s * z,
                    c + k * y * y,
                    k * y * z + s * x,
                    k * x * z + s * y,
                    k * y * z - s * x,
                    c + k * z * z,
                );
                Xform { E: e, r: Vector3::zeros() }
            }
            Elem::Prismatic(a) => Xform { E: Matrix3::identity(), r: a * q[0] },
            Elem::Spherical => {
                // 𝓞_{C/P} = 𝓡(q)ᵀ of the normalized quaternion (η, ε), scalar first
                let uq = UnitQuaternion::new_normalize(Quaternion::new(q[0], q[1], q[2], q[3]));
                Xform { E: uq.to_rotation_matrix().matrix().transpose(), r: Vector3::zeros() }
            }
            Elem::Fixed => Xform::identity(),
        }
    }
}

pub(crate) fn unit_axis(
    a: &Vector3<f64>,
    link: usize,
    what: &'static str,
) -> Result<Vector3<f64>, DynamicsError> {
    check_finite(a.as_slice(), "joint axis")?;
    // scaled by the largest component: |a|² of an axis (0, 1e300, 1e300) overflows, and a/∞
    // would be the zero axis
    let s = a.amax();
    let w = if s > 0.0 { a / s } else { *a };
    let n = s * w.norm();
    if n <= 1e3 * f64::EPSILON {
        return Err(DynamicsError::ZeroAxis { link, what, length: n });
    }
    Ok(w / w.norm())
}

pub(crate) fn elems(joint: &Joint, link: usize) -> Result<Vec<Elem<f64>>, DynamicsError> {
    Ok(match joint {
        Joint::Pin { axis } => vec![Elem::Revolute(unit_axis(axis, link, "pin axis")?)],
        Joint::Sleeve { axis } => vec![Elem::Prismatic(unit_axis(axis, link, "sleeve axis")?)],
        Joint::Collar { axis } => {
            let a = unit_axis(axis, link, "collar axis")?;
            vec![Elem::Prismatic(a), Elem::Revolute(a)]
        }
        Joint::Slot { axis, direction } => {
            let a = unit_axis(axis, link, "slot pin axis")?;
            let d = unit_axis(direction, link, "slot direction")?;
            if a.dot(&d).abs() > 1e-9 {
                return Err(DynamicsError::JointGeometry {
                    link,
                    detail: format!(
                        "slot axis and direction have cosine {:e}; they must be perpendicular",
                        a.dot(&d)
                    ),
                });
            }
            vec![Elem::Prismatic(d), Elem::Revolute(a)]
        }
        Joint::Ball => vec![Elem::Spherical],
        Joint::Weld => vec![Elem::Fixed],
        Joint::Free => vec![
            Elem::Prismatic(Vector3::x()),
            Elem::Prismatic(Vector3::y()),
            Elem::Prismatic(Vector3::z()),
            Elem::Spherical,
        ],
    })
}

/// For a pin or slider whose unit axis is ±x̂, ±ŷ or ±ẑ exactly: the axis index and whether
/// it points the negative way.
pub(crate) fn coordinate_axis(elem: &Elem<f64>) -> Option<(usize, bool)> {
    let (Elem::Revolute(a) | Elem::Prismatic(a)) = elem else { return None };
    (0..3).find(|&k| a[(k + 1) % 3] == 0.0 && a[(k + 2) % 3] == 0.0).map(|k| (k, a[k] < 0.0))
}

#[cfg(test)]
mod layout_tests {
    use super::*;

    /// The joint's own counts are those of the elementary joints the model builds it from (one
    /// definition of a joint's coordinates).
    #[test]
    fn joint_counts_are_those_of_its_elementary_joints() {
        let (x, y) = (Vector3::x(), Vector3::y());
        let joints = [
            Joint::Pin { axis: x },
            Joint::Sleeve { axis: x },
            Joint::Collar { axis: x },
            Joint::Slot { axis: x, direction: y },
            Joint::Ball,
            Joint::Weld,
            Joint::Free,
        ];
        for j in joints {
            let e = elems(&j, 0).unwrap();
            assert_eq!(j.nq(), e.iter().map(Elem::nq).sum::<usize>(), "{j:?}");
            assert_eq!(j.nv(), e.iter().map(Elem::nv).sum::<usize>(), "{j:?}");
            let sph = e.iter().position(|x| *x == Elem::Spherical);
            assert_eq!(j.quaternion_index(), sph.map(|k| e[..k].iter().map(Elem::nq).sum()), "{j:?}");
            let rev = e.iter().position(|x| matches!(x, Elem::Revolute(_)));
            assert_eq!(j.angle_index(), rev.map(|k| e[..k].iter().map(Elem::nv).sum()), "{j:?}");
        }
    }
}
