//! Kinematic trees of rigid bodies connected by the book's joints (book §1.5, Table 1.3,
//! §7.11), in reduced coordinates.
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use vectrix_frames::Frame;
use vectrix_statics::{INERTIA_REL_TOL, check_inertia};

use super::spatial::{BodyInertia, Xform};
use crate::DynamicsError;
use crate::error::check_finite;

/// A joint between a link and its parent (book Table 1.3 and §1.5: pin, sleeve, collar,
/// slot, ball; plus weld and free). Axes and directions are components in the joint frame,
/// which is placed in the parent link by [`Link::placement`].
///
/// Book: §1.5 (the five joint types), Table 1.3.
///
/// # Conventions
/// Coordinates q (and velocities v) per joint:
/// * `Pin` – rotation θ about `axis` (right-hand rule): q = [θ], v = [θ̇].
/// * `Sleeve` – translation s along `axis`: q = [s].
/// * `Collar` – translation s along `axis`, then rotation θ about the same axis: q = [s, θ].
/// * `Slot` – translation s along `direction` (a groove in the parent), then rotation θ about
///   `axis` ⊥ `direction` (the pin): q = [s, θ].
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
pub type Pose = (Matrix3<f64>, Vector3<f64>);

/// Elementary joints the book's joints are made of.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Elem {
    Revolute(Vector3<f64>),
    Prismatic(Vector3<f64>),
    Spherical,
    Fixed,
}

impl Elem {
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

    /// The joint transform for the coordinates `q` (length nq).
    #[inline(always)]
    pub fn xform(&self, q: &[f64]) -> Xform {
        match self {
            // passive rotation about a by θ: E = 𝓡(a, θ)ᵀ
            Elem::Revolute(a) => {
                // E = 𝓡(a, θ)ᵀ = c I − s a^× + (1 − c) a aᵀ (Rodrigues, transposed)
                let (s, c) = q[0].sin_cos();
                let k = 1.0 - c;
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
                let uq = UnitQuaternion::new_normalize(Quaternion::new(q[0], q[1], q[2], q[3]));
                Xform { E: uq.to_rotation_matrix().matrix().transpose(), r: Vector3::zeros() }
            }
            Elem::Fixed => Xform::identity(),
        }
    }
}

/// One elementary segment (a link, or a massless intermediate of a compound joint).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Segment {
    pub parent: Option<usize>,
    pub placement: Xform,
    pub elem: Elem,
    pub qi: usize,
    pub vi: usize,
    pub inertia: BodyInertia,
}

/// A validated kinematic tree in reduced coordinates, ready for RNEA, ABA and CRBA.
///
/// Book: §7.11.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    pub(crate) segs: Vec<Segment>,
    /// For each user link, the index of its (last) segment.
    pub(crate) link_seg: Vec<usize>,
    pub(crate) nq: usize,
    pub(crate) nv: usize,
    /// Gravitational acceleration g resolved in the ground frame.
    pub gravity: Vector3<f64>,
    pub(crate) q_neutral: Vec<f64>,
}

fn unit_axis(a: &Vector3<f64>, link: usize, what: &'static str) -> Result<Vector3<f64>, DynamicsError> {
    check_finite(a.as_slice(), "joint axis")?;
    let n = a.norm();
    if n <= 1e3 * f64::EPSILON {
        return Err(DynamicsError::ZeroAxis { link, what, length: n });
    }
    Ok(a / n)
}

fn elems(joint: &Joint, link: usize) -> Result<Vec<Elem>, DynamicsError> {
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

/// Parents before children; errors for missing parents and cycles.
fn topological_order(links: &[Link]) -> Result<Vec<usize>, DynamicsError> {
    let n = links.len();
    for (i, l) in links.iter().enumerate() {
        if let Some(p) = l.parent
            && p >= n
        {
            return Err(DynamicsError::Disconnected { link: i, parent: p, links: n });
        }
    }
    // depth by walking up; a walk longer than n links means a cycle
    let mut depth = vec![0usize; n];
    for (i, d) in depth.iter_mut().enumerate() {
        let (mut j, mut k) = (i, 0usize);
        while let Some(p) = links[j].parent {
            k += 1;
            if k > n {
                return Err(DynamicsError::Cyclic { link: i });
            }
            j = p;
        }
        *d = k;
    }
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by_key(|&i| (depth[i], i));
    Ok(order)
}

impl Model {
    /// Validates the links and builds the tree. Gravity defaults to zero; set
    /// [`Model::gravity`] (components in the ground frame).
    ///
    /// Book: §7.11; §1.5 (joints); Fact 6.2.7 (valid inertia).
    ///
    /// # Errors
    /// [`DynamicsError::Disconnected`] (a parent index that does not exist),
    /// [`DynamicsError::Cyclic`], [`DynamicsError::ZeroAxis`], [`DynamicsError::JointGeometry`]
    /// (slot axis not ⊥ direction), [`DynamicsError::InvalidParameter`] (mass < 0),
    /// [`DynamicsError::InvalidInertia`] (not symmetric, not PSD, rank 1, triangle inequality),
    /// [`DynamicsError::NonFinite`].
    pub fn new(links: &[Link]) -> Result<Self, DynamicsError> {
        let order = topological_order(links)?;
        // q/v offsets in the user's link order
        let mut q_off = vec![0usize; links.len()];
        let mut v_off = vec![0usize; links.len()];
        let mut expanded = Vec::with_capacity(links.len());
        let (mut nq, mut nv) = (0, 0);
        for (i, l) in links.iter().enumerate() {
            check_finite(l.offset.as_slice(), "link offset")?;
            check_finite(l.orientation.as_slice(), "link orientation")?;
            check_finite(l.com.as_slice(), "centre of mass")?;
            if !(l.mass.is_finite() && l.mass >= 0.0) {
                return Err(DynamicsError::InvalidParameter {
                    what: "link mass",
                    value: l.mass,
                    valid: "finite ≥ 0",
                });
            }
            check_inertia(&Frame::new().dyadic(&l.inertia), INERTIA_REL_TOL)
                .map_err(|source| DynamicsError::InvalidInertia { what: format!("link {i}"), source })?;
            vectrix_rotation::check_rotation_matrix(&l.orientation, 1e-9)
                .map_err(|e| DynamicsError::JointGeometry { link: i, detail: e.to_string() })?;
            let e = elems(&l.joint, i)?;
            q_off[i] = nq;
            v_off[i] = nv;
            nq += e.iter().map(Elem::nq).sum::<usize>();
            nv += e.iter().map(Elem::nv).sum::<usize>();
            expanded.push(e);
        }
        let mut segs: Vec<Segment> = Vec::new();
        let mut link_seg = vec![0usize; links.len()];
        let mut q_neutral = vec![0.0; nq];
        for &i in &order {
            let l = &links[i];
            let mut parent = l.parent.map(|p| link_seg[p]);
            let mut placement = Xform { E: l.orientation, r: l.offset };
            let (mut qi, mut vi) = (q_off[i], v_off[i]);
            let count = expanded[i].len();
            for (k, elem) in expanded[i].iter().enumerate() {
                let last = k + 1 == count;
                let inertia = if last {
                    BodyInertia::from_centre(l.mass, &l.com, &l.inertia)
                } else {
                    BodyInertia { m: 0.0, h: Vector3::zeros(), I: Matrix3::zeros() }
                };
                if *elem == Elem::Spherical {
                    q_neutral[qi] = 1.0;
                }
                segs.push(Segment { parent, placement, elem: *elem, qi, vi, inertia });
                parent = Some(segs.len() - 1);
                placement = Xform::identity();
                qi += elem.nq();
                vi += elem.nv();
            }
            link_seg[i] = segs.len() - 1;
        }
        Ok(Self { segs, link_seg, nq, nv, gravity: Vector3::zeros(), q_neutral })
    }

    /// A chain of n pin joints about ẑ, each link a thin-ish rod of mass m and length l along
    /// x̂ (centre at l/2, J_c = diag(m l²/1200, m l²/12, m l²/12)): the benchmark chain.
    ///
    /// Book: §7.11 (chains).
    ///
    /// # Errors
    /// As [`Model::new`] (n = 0 gives an empty model, which is valid).
    pub fn revolute_chain(n: usize, m: f64, l: f64) -> Result<Self, DynamicsError> {
        let j = Matrix3::from_diagonal(&Vector3::new(m * l * l / 1200.0, m * l * l / 12.0, m * l * l / 12.0));
        let links: Vec<Link> = (0..n)
            .map(|i| {
                let offset = if i == 0 { Vector3::zeros() } else { Vector3::new(l, 0.0, 0.0) };
                // alternate ẑ and ŷ axes so that the chain is spatial
                let axis = if i % 2 == 0 { Vector3::z() } else { Vector3::y() };
                Link::new(
                    i.checked_sub(1),
                    Joint::Pin { axis },
                    offset,
                    m,
                    Vector3::new(l / 2.0, 0.0, 0.0),
                    j,
                )
            })
            .collect();
        Self::new(&links)
    }

    /// Number of configuration coordinates (quaternions count 4).
    pub fn nq(&self) -> usize {
        self.nq
    }

    /// Number of velocity coordinates (degrees of freedom).
    pub fn nv(&self) -> usize {
        self.nv
    }

    /// Number of links.
    pub fn links(&self) -> usize {
        self.link_seg.len()
    }

    /// The neutral configuration: zero for every coordinate, identity quaternions.
    pub fn neutral(&self) -> Vec<f64> {
        self.q_neutral.clone()
    }

    /// q ⊕ v dt: adds v dt to every coordinate, and for ball joints composes the quaternion
    /// with exp(ω dt / 2) (ω in the link frame), keeping it unit.
    ///
    /// Book: §4.11 (exact quaternion step (4.11.17)).
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`].
    pub fn integrate(&self, q: &[f64], v: &[f64], dt: f64) -> Result<Vec<f64>, DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        let mut out = q.to_vec();
        for s in &self.segs {
            match s.elem {
                Elem::Revolute(_) | Elem::Prismatic(_) => out[s.qi] += v[s.vi] * dt,
                Elem::Spherical => {
                    let q0 = UnitQuaternion::new_normalize(Quaternion::new(
                        q[s.qi],
                        q[s.qi + 1],
                        q[s.qi + 2],
                        q[s.qi + 3],
                    ));
                    let w = Vector3::new(v[s.vi], v[s.vi + 1], v[s.vi + 2]);
                    let q1 = q0 * UnitQuaternion::from_scaled_axis(w * dt);
                    out[s.qi..s.qi + 4].copy_from_slice(&[q1.w, q1.i, q1.j, q1.k]);
                }
                Elem::Fixed => {}
            }
        }
        Ok(out)
    }

    pub(crate) fn check_q(&self, q: &[f64]) -> Result<(), DynamicsError> {
        crate::error::check_len(q.len(), self.nq, "q")?;
        check_finite(q, "q")?;
        for s in &self.segs {
            if s.elem == Elem::Spherical {
                let n = q[s.qi..s.qi + 4].iter().map(|x| x * x).sum::<f64>().sqrt();
                if n < 1e-6 {
                    return Err(DynamicsError::InvalidParameter {
                        what: "ball-joint quaternion norm",
                        value: n,
                        valid: "a nonzero quaternion (it is normalized)",
                    });
                }
            }
        }
        Ok(())
    }

    pub(crate) fn check_v(&self, v: &[f64], what: &'static str) -> Result<(), DynamicsError> {
        crate::error::check_len(v.len(), self.nv, what)?;
        check_finite(v, what)
    }

    /// Link poses: for each link, 𝓞_{link/ground} and r_{link origin/ground origin}|_ground.
    ///
    /// Book: §2.22 (chains), (2.10.46) composition.
    ///
    /// # Errors
    /// As [`Model::integrate`].
    pub fn poses(&self, q: &[f64]) -> Result<Vec<Pose>, DynamicsError> {
        self.check_q(q)?;
        let (mut world, mut out) = (Vec::new(), Vec::new());
        self.poses_into(q, &mut world, &mut out);
        Ok(out)
    }

    /// [`Model::poses`] into caller-owned buffers (no allocation once they have grown), without
    /// input checks: the hot path of a right-hand side. `world` is work space.
    pub fn poses_into(&self, q: &[f64], world: &mut Vec<Pose>, out: &mut Vec<Pose>) {
        world.clear();
        for s in &self.segs {
            let x = s.placement.then(&s.elem.xform(&q[s.qi..]));
            let w = match s.parent {
                Some(p) => Xform { E: world[p].0, r: world[p].1 }.then(&x),
                None => x,
            };
            world.push((w.E, w.r));
        }
        out.clear();
        out.extend(self.link_seg.iter().map(|&k| world[k]));
    }
}
