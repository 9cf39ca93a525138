//! The validated parts of a scene that every later stage reads: bodies with their indices
//! and mass properties, effects with names resolved, and the joint each body moves on (the
//! multibody model's [`Joint`], the one definition of a joint's coordinates).
//!
//! Book: §7.11 (trees), §1.5 (joints), ch. 6 (loads).

use nalgebra::{Matrix3, Vector3};

use super::profile::Profile;
use super::source::SceneSource;
use super::spec::JointSpec;
use vectrix_dynamics::multibody::Joint;

/// A body after validation: indices, offsets and mass properties in link components.
#[derive(Debug, Clone)]
pub(crate) struct Body {
    pub name: String,
    pub parent: Option<usize>,
    /// The joint as the multibody model defines it (its coordinates: [`Joint::nq`] …).
    pub joint: Joint,
    /// 𝓞_{J/P}: joint frame relative to the parent link frame.
    pub orient: Matrix3<f64>,
    pub mass: f64,
    pub com: Vector3<f64>,
    pub inertia: Matrix3<f64>,
    pub qi: usize,
    pub vi: usize,
}

pub(crate) use super::kin::At;

/// Effects with names resolved.
#[derive(Debug, Clone)]
pub(crate) enum Effect {
    /// Enters the model as its base acceleration (no per-body work in the right-hand side).
    Uniform {
        g: Vector3<f64>,
    },
    Central {
        mu: f64,
        centre: Vector3<f64>,
    },
    /// Every pair (i, j), i < j, of bodies with its G mᵢ mⱼ validated once.
    Mutual {
        pairs: Vec<(usize, usize, vectrix_statics::MutualGravitation)>,
    },
    Spring {
        a: At,
        b: At,
        k: f64,
        d: f64,
    },
    Dashpot {
        a: At,
        b: At,
        c: f64,
    },
    Inerter {
        a: At,
        b: At,
        b_in: f64,
    },
    RotSpring {
        dof: usize,
        kappa: f64,
        angle: f64,
    },
    RotDashpot {
        dof: usize,
        xi: f64,
    },
    RotInerter {
        dof: usize,
        beta: f64,
    },
    Dipoles {
        list: Vec<(usize, Vector3<f64>)>,
    },
    Force {
        at: At,
        dir: Vector3<f64>,
        profile: Profile,
    },
    Torque {
        body: usize,
        dir: Vector3<f64>,
        profile: Profile,
    },
    Spheres {
        a: usize,
        b: usize,
        ra: f64,
        rb: f64,
        e: f64,
        mu: f64,
    },
    /// A joint stop: q[qi] ∈ [lower, upper] (±∞ for none), speed v[vi], restitution e.
    JointStop {
        qi: usize,
        vi: usize,
        lower: f64,
        upper: f64,
        e: f64,
    },
    Plane {
        body: usize,
        r: f64,
        point: Vector3<f64>,
        n: Vector3<f64>,
        e: f64,
        mu: f64,
    },
    Rolling {
        body: usize,
        disk: bool,
        r: f64,
        point: Vector3<f64>,
        n: Vector3<f64>,
    },
    /// An aircraft's aerodynamics on a free body (see [`super::aero`]).
    Aero {
        body: usize,
        aircraft: Box<vectrix_flight::Aircraft>,
        /// δe, δa, δr.
        controls: Box<[Profile; 3]>,
    },
    /// Thrust along the tilted x axis of a body, at its centre of mass.
    Thrust {
        body: usize,
        profile: Profile,
        angle: f64,
    },
}

/// Errors are located by item path in the spanned document.
pub(crate) type Src<'a> = SceneSource<'a>;

/// The multibody joint a scene's joint spec declares (axes as written; the model normalizes
/// them and refuses zero ones).
pub(crate) fn joint_of(j: &JointSpec) -> Joint {
    match *j {
        JointSpec::Pin { axis } => Joint::Pin { axis: v3(axis) },
        JointSpec::Sleeve { axis } => Joint::Sleeve { axis: v3(axis) },
        JointSpec::Collar { axis } => Joint::Collar { axis: v3(axis) },
        JointSpec::Slot { axis, direction } => Joint::Slot { axis: v3(axis), direction: v3(direction) },
        JointSpec::Ball {} => Joint::Ball,
        JointSpec::Weld {} => Joint::Weld,
        JointSpec::Free {} => Joint::Free,
    }
}

pub(crate) fn v3(a: [f64; 3]) -> Vector3<f64> {
    Vector3::new(a[0], a[1], a[2])
}
