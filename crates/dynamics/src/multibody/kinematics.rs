//! Forward kinematics of a tree beyond poses: link twists in the ground frame, and the
//! kinetic and potential energies, generic over the scalar (so a `Model<Dual64>` gives their
//! exact derivatives: ∂T/∂v = generalized momentum, ∂V/∂q = −gravity forces).
//!
//! Book: §4.5 (angular velocities add along a chain), §5 (transport theorem
//! v_y = v_x + ω × r_{y/x}), §8.1 (kinetic energy ½𝒱ᵀ𝒥𝒱), §8.4 (potential −m g·r_c).

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

use super::model::Model;
use super::rnea::joint_motion;
use super::spatial::Xform;
use crate::DynamicsError;

/// The motion of a link: its angular velocity ω_{link/ground} and the velocity of its frame
/// origin relative to the ground origin with respect to the ground, both resolved in the
/// ground frame.
///
/// Book: §4.5, §5 (v_y = v_x + ω × r_{y/x}).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkTwist<T: Scalar = f64> {
    /// ω_{link/ground}, ground components.
    pub omega: Vector3<T>,
    /// Velocity of the link origin, ground components.
    pub velocity: Vector3<T>,
}

impl<T: Scalar> LinkTwist<T> {
    /// Velocity of the point of the link at `r` (ground components) from the link origin:
    /// v + ω × r.
    pub fn velocity_of(&self, r: &Vector3<T>) -> Vector3<T> {
        self.velocity + self.omega.cross(r)
    }
}

/// A twist (ω, v) in body components.
type BodyTwist<T> = (Vector3<T>, Vector3<T>);

impl<T: Scalar> Model<T> {
    /// Body-frame twists (ω, v) of every segment and the ground-to-segment transforms.
    fn body_twists(&self, q: &[T], v: &[T]) -> (Vec<Xform<T>>, Vec<BodyTwist<T>>) {
        let n = self.segs.len();
        let mut world: Vec<Xform<T>> = Vec::with_capacity(n);
        let mut tw: Vec<BodyTwist<T>> = Vec::with_capacity(n);
        for (i, seg) in self.segs.iter().enumerate() {
            let x = self.seg_xform(i, q, None);
            let (wp, vp, xw) = match seg.parent {
                Some(p) => (tw[p].0, tw[p].1, world[p].then(&x)),
                None => (Vector3::zeros(), Vector3::zeros(), x),
            };
            // 𝒱_i = X_i 𝒱_p + S q̇_i (body components)
            let (mut w, mut vel) = x.motion(&wp, &vp);
            let (sw, sv) = joint_motion(&seg.elem, &v[seg.vi..]);
            w += sw;
            vel += sv;
            world.push(xw);
            tw.push((w, vel));
        }
        (world, tw)
    }

    /// Link twists at (q, v): for each link (user order) ω_{link/ground} and the velocity of
    /// its origin, resolved in the ground frame (the companion of [`Model::poses`]).
    ///
    /// Book: §4.5, §5.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`],
    /// [`DynamicsError::OutOfRange`] (a ball-joint quaternion of norm below 1e-6),
    /// [`DynamicsError::Overflow`].
    pub fn twists(&self, q: &[T], v: &[T]) -> Result<Vec<LinkTwist<T>>, DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        let (world, tw) = self.body_twists(q, v);
        let out: Vec<LinkTwist<T>> = self
            .link_seg
            .iter()
            .map(|&k| LinkTwist { omega: world[k].E.tr_mul(&tw[k].0), velocity: world[k].E.tr_mul(&tw[k].1) })
            .collect();
        if !out.iter().all(|t| {
            crate::error::all_finite(t.omega.as_slice()) && crate::error::all_finite(t.velocity.as_slice())
        }) {
            return Err(DynamicsError::Overflow { what: "link twists" });
        }
        Ok(out)
    }

    /// Kinetic energy T = ½ Σ 𝒱ᵢᵀ 𝒥ᵢ 𝒱ᵢ = ½ vᵀ M(q) v.
    ///
    /// Book: §8.1, (8.1.x); §9.3 (T = ½ q̇ᵀ M q̇).
    ///
    /// # Errors
    /// As [`Model::twists`].
    pub fn kinetic_energy(&self, q: &[T], v: &[T]) -> Result<T, DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        let (_, tw) = self.body_twists(q, v);
        let mut t = T::zero();
        for (seg, (w, vel)) in self.segs.iter().zip(&tw) {
            let (n, f) = seg.inertia.apply(w, vel);
            t += w.dot(&n) + vel.dot(&f);
        }
        let t = t * T::lit(0.5);
        if !t.re().is_finite() {
            return Err(DynamicsError::Overflow { what: "kinetic energy" });
        }
        Ok(t)
    }

    /// Gravitational potential energy V = −Σ mᵢ g·r_{cᵢ} (zero at the ground origin).
    ///
    /// Book: §8.4 (uniform gravity).
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`],
    /// [`DynamicsError::OutOfRange`] (a ball-joint quaternion of norm below 1e-6),
    /// [`DynamicsError::Overflow`].
    pub fn potential_energy(&self, q: &[T]) -> Result<T, DynamicsError> {
        self.check_q(q)?;
        let world = self.world_xforms(q);
        let mut v = T::zero();
        for (seg, x) in self.segs.iter().zip(&world) {
            // m r_c = m p + Eᵀ h (h = m c in link components)
            let mr = x.r * seg.inertia.m + x.E.tr_mul(&seg.inertia.h);
            v -= self.gravity.dot(&mr);
        }
        if !v.re().is_finite() {
            return Err(DynamicsError::Overflow { what: "potential energy" });
        }
        Ok(v)
    }
}
