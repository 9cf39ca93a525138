//! Link poses and twists of a scene's tree in the ground frame, the attitude rate q̇ of the
//! coordinates, and velocities of points fixed in bodies.
//!
//! Book: §4.5 (angular velocity adds along a chain), §5.x transport theorem
//! v_y = v_x + ω × r_{y/x}; (4.11.x) quaternion kinematics q̇ = ½ q ⊗ (0, ω).

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::Scalar;

use super::build::{At, Body};
use super::spec::JointSpec;
use vectrix_dynamics::multibody::{Model, Pose, PosesScratch};

/// Poses and twists: for each link 𝓞_{link/ground}, r_{origin}, ω and v_{origin} (ground), in
/// the scalar of the evaluation (f64, or dual numbers for exact derivatives).
#[derive(Debug, Clone)]
pub(crate) struct Kin<T: Scalar = f64> {
    pub poses: Vec<Pose<T>>,
    pub omega: Vec<Vector3<T>>,
    pub vel: Vec<Vector3<T>>,
}

/// A scene constant (f64) in the scalar T of an evaluation.
#[inline(always)]
pub(crate) fn lift<T: Scalar>(x: &Vector3<f64>) -> Vector3<T> {
    x.map(T::lit)
}

/// A scene matrix constant (f64) in the scalar T of an evaluation.
#[inline(always)]
pub(crate) fn lift33<T: Scalar>(x: &Matrix3<f64>) -> Matrix3<T> {
    x.map(T::lit)
}

/// Link twists for the velocities `v`, given the poses (bodies in any order: parents are
/// resolved recursively through `order`, parents first).
pub(crate) fn twists(
    bodies: &[Body],
    order: &[usize],
    poses: &[Pose],
    v: &[f64],
) -> (Vec<Vector3<f64>>, Vec<Vector3<f64>>) {
    let n = bodies.len();
    let mut omega = vec![Vector3::zeros(); n];
    let mut vel = vec![Vector3::zeros(); n];
    twists_into(bodies, order, poses, v, &mut omega, &mut vel);
    (omega, vel)
}

/// [`twists`] into caller-owned slices of the bodies' length, in any scalar.
pub(crate) fn twists_into<T: Scalar>(
    bodies: &[Body],
    order: &[usize],
    poses: &[Pose<T>],
    v: &[T],
    omega: &mut [Vector3<T>],
    vel: &mut [Vector3<T>],
) {
    let zero = Vector3::zeros();
    for &i in order {
        let b = &bodies[i];
        let (e_p, r_p, w_p, v_p) = match b.parent {
            Some(p) => (poses[p].0, poses[p].1, omega[p], vel[p]),
            None => (Matrix3::identity(), zero, zero, zero),
        };
        // 𝓞_{J/G} = 𝓞_{J/P} 𝓞_{P/G}; ground components of a joint-frame vector x: 𝓞_{J/G}ᵀ x
        let e_j = lift33::<T>(&b.orient) * e_p;
        let (e_l, r_l) = poses[i];
        let vv = &v[b.vi..];
        let axis = || e_j.tr_mul(&lift::<T>(&b.axis));
        let (w_rel, v_rel) = match &b.joint {
            JointSpec::Pin { .. } => (axis() * vv[0], zero),
            JointSpec::Sleeve { .. } => (zero, axis() * vv[0]),
            JointSpec::Collar { .. } => {
                let a = axis();
                (a * vv[1], a * vv[0])
            }
            JointSpec::Slot { .. } => (axis() * vv[1], e_j.tr_mul(&lift::<T>(&b.direction)) * vv[0]),
            JointSpec::Ball {} => (e_l.transpose() * Vector3::new(vv[0], vv[1], vv[2]), zero),
            JointSpec::Free {} => (
                e_l.transpose() * Vector3::new(vv[3], vv[4], vv[5]),
                e_j.transpose() * Vector3::new(vv[0], vv[1], vv[2]),
            ),
            JointSpec::Weld {} => (zero, zero),
        };
        omega[i] = w_p + w_rel;
        vel[i] = v_p + w_p.cross(&(r_l - r_p)) + v_rel;
    }
}

/// Link bias accelerations at (q, v): the angular acceleration α and the acceleration of the
/// link origin of every link when every joint acceleration vanishes (v̇ = 0), ground
/// components. With them, d/dt of any velocity that is linear in v (a point velocity, a loop
/// closure, an inerter's length rate) splits exactly into its v̇ part and this bias: no finite
/// differences. Recursively, parent p → link i with ρ = r_i − r_p and the joint's relative
/// rates ω_rel = ω_i − ω_p, v_rel = v_i − v_p − ω_p × ρ:
///   α_i = α_p + ω_f × ω_rel (ω_f = ω_i for a ball or free joint, whose rates are in the link
///   frame; ω_p for the others, whose axes are fixed in the parent),
///   a_i = a_p + α_p × ρ + ω_p × (ω_p × ρ) + 2 ω_p × v_rel.
///
/// Book: §5.x (transport theorem), (4.5.x) angular velocity along a chain, (5.x.x) double
/// transport a = a₀ + α × r + ω × (ω × r).
pub(crate) fn bias_accelerations(
    bodies: &[Body],
    order: &[usize],
    kin: &Kin,
) -> (Vec<Vector3<f64>>, Vec<Vector3<f64>>) {
    let n = bodies.len();
    let (mut alpha, mut acc) = (vec![Vector3::zeros(); n], vec![Vector3::zeros(); n]);
    for &i in order {
        let b = &bodies[i];
        let (w_p, v_p, r_p, al_p, a_p) = match b.parent {
            Some(p) => (kin.omega[p], kin.vel[p], kin.poses[p].1, alpha[p], acc[p]),
            None => {
                (Vector3::zeros(), Vector3::zeros(), Vector3::zeros(), Vector3::zeros(), Vector3::zeros())
            }
        };
        let rho = kin.poses[i].1 - r_p;
        let w_rel = kin.omega[i] - w_p;
        let v_rel = kin.vel[i] - v_p - w_p.cross(&rho);
        let w_f = if matches!(b.joint, JointSpec::Ball {} | JointSpec::Free {}) { kin.omega[i] } else { w_p };
        alpha[i] = al_p + w_f.cross(&w_rel);
        acc[i] = a_p + al_p.cross(&rho) + w_p.cross(&w_p.cross(&rho)) + w_p.cross(&v_rel) * 2.0;
    }
    (alpha, acc)
}

/// Poses and twists at (q, v).
pub(crate) fn kinematics(
    model: &Model,
    bodies: &[Body],
    order: &[usize],
    q: &[f64],
    v: &[f64],
) -> Result<Kin, String> {
    let poses = model.poses(q).map_err(|e| e.to_string())?;
    let (omega, vel) = twists(bodies, order, &poses, v);
    Ok(Kin { poses, omega, vel })
}

/// [`kinematics`] into a reused [`Kin`] (`world` is work space): no allocation once grown; in
/// any scalar.
pub(crate) fn kinematics_into<T: Scalar>(
    model: &Model<T>,
    bodies: &[Body],
    order: &[usize],
    q: &[T],
    v: &[T],
    kin: &mut Kin<T>,
    world: &mut PosesScratch<T>,
) {
    model.poses_into(q, world, &mut kin.poses);
    let n = bodies.len();
    kin.omega.resize(n, Vector3::zeros());
    kin.vel.resize(n, Vector3::zeros());
    twists_into(bodies, order, &kin.poses, v, &mut kin.omega, &mut kin.vel);
}

impl<T: Scalar> Kin<T> {
    /// An empty buffer for [`kinematics_into`].
    pub fn empty() -> Self {
        Self { poses: Vec::new(), omega: Vec::new(), vel: Vec::new() }
    }

    /// Ground position and velocity of a point fixed in a body (or in the ground).
    pub fn point(&self, at: &At) -> (Vector3<T>, Vector3<T>) {
        match at.0 {
            None => (lift(&at.1), Vector3::zeros()),
            Some(i) => {
                let (e, r) = self.poses[i];
                let d = e.transpose() * lift::<T>(&at.1);
                (r + d, self.vel[i] + self.omega[i].cross(&d))
            }
        }
    }
}

impl Kin {
    /// The bias acceleration (v̇ = 0) of a point fixed in a body (or in the ground), given the
    /// links' bias accelerations: a = a_o + α × d + ω × (ω × d).
    pub fn point_bias(&self, at: &At, alpha: &[Vector3<f64>], acc: &[Vector3<f64>]) -> Vector3<f64> {
        match at.0 {
            None => Vector3::zeros(),
            Some(i) => {
                let d = self.poses[i].0.transpose() * at.1;
                acc[i] + alpha[i].cross(&d) + self.omega[i].cross(&self.omega[i].cross(&d))
            }
        }
    }
}

/// Parents before children.
pub(crate) fn tree_order(bodies: &[Body]) -> Vec<usize> {
    let depth = |mut i: usize| {
        let mut d = 0;
        while let Some(p) = bodies[i].parent {
            d += 1;
            i = p;
            if d > bodies.len() {
                break;
            }
        }
        d
    };
    let mut order: Vec<usize> = (0..bodies.len()).collect();
    order.sort_by_key(|&i| (depth(i), i));
    order
}

/// q̇ from v: scalar joints q̇ = v, quaternions q̇ = ½ q ⊗ (0, ω_link), free translation ẋ = v.
pub(crate) fn qdot<T: Scalar>(bodies: &[Body], q: &[T], v: &[T], out: &mut [T]) {
    let half = T::lit(0.5);
    let quat = |qq: &[T], w: &[T], o: &mut [T]| {
        let (e0, e1, e2, e3) = (qq[0], qq[1], qq[2], qq[3]);
        let (p, r, s) = (w[0], w[1], w[2]);
        o[0] = half * (-e1 * p - e2 * r - e3 * s);
        o[1] = half * (e0 * p + e2 * s - e3 * r);
        o[2] = half * (e0 * r + e3 * p - e1 * s);
        o[3] = half * (e0 * s + e1 * r - e2 * p);
    };
    for b in bodies {
        let (qi, vi) = (b.qi, b.vi);
        match b.joint {
            JointSpec::Pin { .. } | JointSpec::Sleeve { .. } => out[qi] = v[vi],
            JointSpec::Collar { .. } | JointSpec::Slot { .. } => {
                out[qi] = v[vi];
                out[qi + 1] = v[vi + 1];
            }
            JointSpec::Ball {} => quat(&q[qi..qi + 4], &v[vi..vi + 3], &mut out[qi..qi + 4]),
            JointSpec::Free {} => {
                out[qi..qi + 3].copy_from_slice(&v[vi..vi + 3]);
                quat(&q[qi + 3..qi + 7], &v[vi + 3..vi + 6], &mut out[qi + 3..qi + 7]);
            }
            JointSpec::Weld {} => {}
        }
    }
}

/// Renormalizes every quaternion of q.
pub(crate) fn normalize<T: Scalar>(bodies: &[Body], q: &mut [T]) {
    for b in bodies {
        let k = match b.joint {
            JointSpec::Ball {} => b.qi,
            JointSpec::Free {} => b.qi + 3,
            _ => continue,
        };
        let n = q[k..k + 4].iter().fold(T::zero(), |s, x| s + *x * *x).sqrt();
        if n > T::zero() {
            q[k..k + 4].iter_mut().for_each(|x| *x /= n);
        }
    }
}
