//! 6D velocity and acceleration of a chain of rigid bodies (book §4.13–4.14).
//!
//! Numbering: the base is body 0 (F_A), the moving bodies are 1, …, n (F_B, F_C, F_D, …).
//! Joint z_0 is fixed in the base and body 1; joint z_k (k ≥ 1) is fixed in bodies k and k+1,
//! and z_n is the end effector, fixed in body n. The offset r⃗_{z_k/z_{k−1}} is fixed in body k
//! (4.13.15).
//!
//! **The book's off-by-one pairing.** The 6D velocity at joint z_k is
//! 𝒱_k = [v⃗_{z_k/z_0/A}; ω⃗_{k+1/A}]: its angular part belongs to the *next* body (body k+1),
//! except at the end effector, where it is ω⃗_{n/A}. The types below carry both indices
//! ([`JointTwist::joint`], [`JointTwist::body`]) so the pairing is never implicit.

use nalgebra::{Matrix3, Vector3, Vector6};
use vectrix_tensor::{Scalar, Vector};

use crate::motion::finite_vector;
use crate::{KinematicsError, LabeledFrame};

/// Link k of a chain: body k's motion relative to body k−1 and the joint offset
/// r⃗_{z_k/z_{k−1}} fixed in body k.
///
/// Book: §4.13, (4.13.15).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkMotion<T: Scalar = f64> {
    /// Body k's frame at this instant.
    pub body: LabeledFrame<T>,
    /// ω⃗_{k/k−1}.
    pub omega_rel_prev: Vector<T>,
    /// α⃗_{k/k−1}.
    pub alpha_rel_prev: Vector<T>,
    /// r⃗_{z_k/z_{k−1}}, fixed in body k.
    pub r_joint_prev_joint: Vector<T>,
}

/// The 6D velocity 𝒱_k at joint z_k: v⃗_{z_k/z_0/A} paired with ω⃗ of body `body`
/// (= k+1, or n at the end effector).
///
/// Book: §4.13, (4.13.33–38).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointTwist<T: Scalar = f64> {
    /// k: the joint z_k whose velocity is `v_joint`.
    pub joint: usize,
    /// v⃗_{z_k/z_0/A}.
    pub v_joint: Vector<T>,
    /// The body whose angular velocity is `omega_body`: k+1 (the off-by-one pairing), or n
    /// at the end effector.
    pub body: usize,
    /// ω⃗_{body/A}.
    pub omega_body: Vector<T>,
}

/// The 6D acceleration 𝒜_k at joint z_k.
///
/// Book: §4.14, (4.14.1–16).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointAccel<T: Scalar = f64> {
    /// k: the joint z_k.
    pub joint: usize,
    /// The *mixed* acceleration a⃗_{z_k/z_0/A/k} = (v⃗_{z_k/z_0/A})^{k•}, the linear row of 𝒜_k,
    /// taken with respect to body k (the body carrying r⃗_{z_k/z_{k−1}}; the base for k = 0).
    pub a_joint_mixed: Vector<T>,
    /// The true acceleration a⃗_{z_k/z_0/A} = a⃗_{z_k/z_0/A/k} + ω⃗_{k/A} × v⃗_{z_k/z_0/A}.
    pub a_joint: Vector<T>,
    /// The body whose angular acceleration is `alpha_body` (k+1, or n at the end effector).
    pub body: usize,
    /// α⃗_{body/A}, the true angular acceleration.
    pub alpha_body: Vector<T>,
}

/// The 6D velocities and accelerations at joints z_0, …, z_n.
///
/// Book: §4.13–4.14.
#[derive(Debug, Clone, PartialEq)]
pub struct ChainKinematics<T: Scalar = f64> {
    /// 𝒱_0, …, 𝒱_n.
    pub twists: Vec<JointTwist<T>>,
    /// 𝒜_0, …, 𝒜_n.
    pub accels: Vec<JointAccel<T>>,
}

/// 𝒯_{k/k−1} 𝒳 = [x_v − r⃗_{z_k/z_{k−1}} × x_ω; x_ω] (physical form).
fn shift<T: Scalar>(r: &Vector<T>, v: &Vector<T>, w: &Vector<T>) -> Vector<T> {
    *v - r.cross(w)
}

/// 6D velocity and acceleration at every joint z_0, …, z_n of a chain `links` = bodies 1..n
/// (physical form, base first).
///
/// Velocity (4.13.33–38): 𝒱_0 = [0⃗; ω⃗_{1/A}],
/// 𝒱_k = 𝒯_{k/k−1}𝒱_{k−1} + [0⃗; ω⃗_{k+1/k}] (no added term at k = n),
/// 𝒯_{k/k−1} = [[I, −r⃗^×_{z_k/z_{k−1}}], [0, I]].
///
/// Acceleration (4.14.5–7): 𝒜_0 = [0⃗; α⃗_{1/A}],
/// 𝒜_k = 𝒯_{k/k−1}𝒜_{k−1} + [ω⃗_{k−1/k} × v⃗_{z_{k−1}/z_0/A}; α⃗_{k+1/k} + ω⃗_{k/A} × ω⃗_{k+1/k}].
///
/// Book: §4.13–4.14, (4.13.33–38), (4.14.1–16).
///
/// # Errors
/// [`KinematicsError::EmptyChain`]; [`KinematicsError::NonFinite`].
pub fn chain_kinematics<T: Scalar>(links: &[LinkMotion<T>]) -> Result<ChainKinematics<T>, KinematicsError> {
    let n = links.len();
    let first = links.first().ok_or(KinematicsError::EmptyChain { what: "chain_kinematics" })?;
    for l in links {
        finite_vector(&l.omega_rel_prev, "ω_{k/k−1}")?;
        finite_vector(&l.alpha_rel_prev, "α_{k/k−1}")?;
        finite_vector(&l.r_joint_prev_joint, "r_{z_k/z_{k−1}}")?;
    }
    let zero = Vector::zero();
    let mut twists = vec![JointTwist { joint: 0, v_joint: zero, body: 1, omega_body: first.omega_rel_prev }];
    let mut accels = vec![JointAccel {
        joint: 0,
        a_joint_mixed: zero,
        a_joint: zero,
        body: 1,
        alpha_body: first.alpha_rel_prev,
    }];
    for k in 1..=n {
        let link = &links[k - 1];
        let prev_v = twists[k - 1];
        let prev_a = accels[k - 1];
        // ω_{k/A}, α_{k/A}: the angular rows of 𝒱_{k−1}, 𝒜_{k−1} (off by one)
        let (omega_k, alpha_k) = (prev_v.omega_body, prev_a.alpha_body);
        let r = &link.r_joint_prev_joint;
        // (4.13.36): linear row v_{z_k} = v_{z_{k−1}} − r × ω_{k/A}
        let v_joint = shift(r, &prev_v.v_joint, &omega_k);
        // ω_{k−1/k} × v_{z_{k−1}}: the velocity-product term of (4.14.6)
        let coriolis = (-link.omega_rel_prev).cross(&prev_v.v_joint);
        let a_joint_mixed = shift(r, &prev_a.a_joint_mixed, &alpha_k) + coriolis;
        let (body, omega_body, alpha_body) = match links.get(k) {
            // (4.13.37), (4.14.6): [0; ω_{k+1/k}], [..; α_{k+1/k} + ω_{k/A} × ω_{k+1/k}]
            Some(next) => (
                k + 1,
                omega_k + next.omega_rel_prev,
                alpha_k + next.alpha_rel_prev + omega_k.cross(&next.omega_rel_prev),
            ),
            // end effector (4.13.38): no next body
            None => (k, omega_k, alpha_k),
        };
        twists.push(JointTwist { joint: k, v_joint, body, omega_body });
        accels.push(JointAccel {
            joint: k,
            a_joint_mixed,
            a_joint: a_joint_mixed + omega_k.cross(&v_joint),
            body,
            alpha_body,
        });
    }
    Ok(ChainKinematics { twists, accels })
}

/// Link k in resolved form: 𝓞_{k/k−1}, ω_{k/k−1}|_k and r_{z_k/z_{k−1}}|_k.
///
/// Book: (4.13.33–38).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResolvedLink<T: Scalar = f64> {
    /// 𝓞_{k/k−1} (unused for k = 1: 𝓞_{B/A} is not needed).
    pub o_k_prev: Matrix3<T>,
    /// ω_{k/k−1}|_k.
    pub omega_rel_prev_in_k: Vector3<T>,
    /// r_{z_k/z_{k−1}}|_k.
    pub r_joint_prev_joint_in_k: Vector3<T>,
}

/// The velocity recursion in resolved form: 𝒱_k|_k = 𝒯_{k/k−1}|𝒱_{k−1}|_{k−1} + [0; ω_{k+1/k}|_k]
/// with 𝒯_{k/k−1}| = [[𝓞_{k/k−1}, −r^×_{z_k/z_{k−1}|k}𝓞_{k/k−1}], [0, 𝓞_{k/k−1}]].
/// Each 𝒱_k = [v_{z_k/z_0/A}; ω_{k+1/A}] is resolved in body k; 𝒱_0 is resolved in body 1, so
/// 𝓞_{1/0} is never needed.
///
/// Book: (4.13.33–38).
///
/// # Errors
/// [`KinematicsError::EmptyChain`]; [`KinematicsError::NonFinite`].
pub fn chain_velocity_resolved<T: Scalar>(
    links: &[ResolvedLink<T>],
) -> Result<Vec<Vector6<T>>, KinematicsError> {
    let first = links.first().ok_or(KinematicsError::EmptyChain { what: "chain_velocity_resolved" })?;
    let finite = links.iter().all(|l| {
        l.o_k_prev
            .iter()
            .chain(l.omega_rel_prev_in_k.iter())
            .chain(l.r_joint_prev_joint_in_k.iter())
            .all(|x| x.re().is_finite())
    });
    if !finite {
        return Err(KinematicsError::NonFinite { what: "resolved chain link" });
    }
    let stack = |v: Vector3<T>, w: Vector3<T>| Vector6::new(v.x, v.y, v.z, w.x, w.y, w.z);
    let mut out = vec![stack(Vector3::zeros(), first.omega_rel_prev_in_k)];
    for k in 1..=links.len() {
        let link = &links[k - 1];
        let prev = out[k - 1];
        let (v_prev, w_prev) = (prev.fixed_rows::<3>(0).into_owned(), prev.fixed_rows::<3>(3).into_owned());
        // 𝒱_0 is already resolved in body 1, so 𝓞 = I for the first step
        let o = if k == 1 { Matrix3::identity() } else { link.o_k_prev };
        let w_k = o * w_prev; // ω_{k/A}|_k
        let v = o * v_prev - link.r_joint_prev_joint_in_k.cross(&w_k);
        // [0; ω_{k+1/k}|_k] with ω_{k+1/k}|_k = 𝓞_{k+1/k}ᵀ ω_{k+1/k}|_{k+1}
        let w = match links.get(k) {
            Some(next) => w_k + next.o_k_prev.transpose() * next.omega_rel_prev_in_k,
            None => w_k,
        };
        out.push(stack(v, w));
    }
    Ok(out)
}
