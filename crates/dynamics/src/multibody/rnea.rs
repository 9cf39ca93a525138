//! Inverse dynamics by the recursive Newton–Euler algorithm with joint reaction wrenches
//! (book §7.11), generic over the scalar.

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

use super::joint::Elem;
use super::model::{Model, Trig};
use super::spatial::{Xform, cross_force};
use super::wrench::{JointWrench, LinkWrenches};
use crate::DynamicsError;

/// Result of inverse dynamics: generalized forces τ and the joint reaction wrenches.
#[derive(Debug, Clone, PartialEq)]
pub struct InverseDynamics<T: Scalar = f64> {
    /// τ: joint torques/forces, one per velocity coordinate.
    pub tau: Vec<T>,
    /// For each link (user order), the wrench its joint transmits.
    pub wrenches: Vec<JointWrench<T>>,
}

impl<T: Scalar> Model<T> {
    /// Inverse dynamics τ = ID(q, v, v̇) by the recursive Newton–Euler algorithm: an outward
    /// pass for twists and accelerations, then an inward pass accumulating the per-body
    /// equations 𝒥𝒜 + 𝒱^×𝒥𝒱 = ℱ_ext + ℱ_in − ℱ_out (7.11.13–15) from the tips to the base.
    /// Gravity enters as a base acceleration −g. `f_ext` (optional) are external wrenches on
    /// the links.
    ///
    /// Book: §7.11, (7.11.13)–(7.11.22); RBDA Table 5.1.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`] (an input),
    /// [`DynamicsError::Overflow`] (finite inputs whose τ overflows, e.g. v ≈ 1e200),
    /// [`DynamicsError::OutOfRange`] (a ball-joint quaternion of norm below 1e-6).
    pub fn rnea(
        &self,
        q: &[T],
        v: &[T],
        vdot: &[T],
        f_ext: Option<&LinkWrenches<T>>,
    ) -> Result<InverseDynamics<T>, DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        self.check_v(vdot, "v̇")?;
        self.check_wrenches(f_ext)?;
        let mut tau = vec![T::zero(); self.nv];
        let mut scratch = Scratch::new(self);
        self.rnea_into(q, v, vdot, f_ext, &mut tau, &mut scratch);
        let wrenches: Vec<JointWrench<T>> = self
            .link_seg
            .iter()
            .map(|&k| JointWrench { force: scratch.nodes[k].f, moment: scratch.nodes[k].n })
            .collect();
        let wrench_finite = wrenches.iter().all(|w| {
            crate::error::all_finite(w.force.as_slice()) && crate::error::all_finite(w.moment.as_slice())
        });
        if !(crate::error::all_finite(&tau) && wrench_finite) {
            return Err(DynamicsError::Overflow { what: "inverse dynamics τ" });
        }
        Ok(InverseDynamics { tau, wrenches })
    }

    /// τ only, with caller-provided scratch (no allocation): the hot path of the benches.
    /// Inputs are not checked, and an overflow (inputs near 1e200) shows as non-finite τ;
    /// use [`Model::rnea`] for user input.
    ///
    /// Book: §7.11.
    pub fn rnea_unchecked(&self, q: &[T], v: &[T], vdot: &[T], tau: &mut [T], scratch: &mut Scratch<T>) {
        self.rnea_into(q, v, vdot, None, tau, scratch);
    }

    pub(crate) fn check_wrenches(&self, f_ext: Option<&LinkWrenches<T>>) -> Result<(), DynamicsError> {
        if let Some(f) = f_ext {
            crate::error::check_len(f.len(), self.links(), "external wrenches")?;
            for w in f {
                crate::error::check_finite_t(w.force.as_slice(), "external wrench force")?;
                crate::error::check_finite_t(w.moment.as_slice(), "external wrench moment")?;
            }
        }
        Ok(())
    }

    fn rnea_into(
        &self,
        q: &[T],
        v: &[T],
        vdot: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        tau: &mut [T],
        s: &mut Scratch<T>,
    ) {
        let a0 = -self.gravity;
        s.trig.fill(q);
        // outward pass: 𝒱_i = X_i 𝒱_p + S q̇_i, 𝒜_i = X_i 𝒜_p + S q̈_i + 𝒱_i ×m S q̇_i
        let mut i = 0;
        while i < self.segs.len() {
            if self.free_at_root(i) {
                self.rnea_free_outward(i, q, v, vdot, &a0, s);
                i += 4;
            } else {
                self.rnea_outward(i, q, v, vdot, &a0, s);
                i += 1;
            }
        }
        if let Some(fe) = f_ext {
            for (l, &k) in self.link_seg.iter().enumerate() {
                s.nodes[k].n -= fe[l].moment;
                s.nodes[k].f -= fe[l].force;
            }
        }
        // inward pass: τ_i = Sᵀ ℱ_i, ℱ_p += X_iᵀ ℱ_i (7.11.20–22)
        let mut i = self.segs.len();
        while i > 0 {
            i -= 1;
            let seg = &self.segs[i];
            let (head, tail) = s.nodes.split_at_mut(i);
            let node = &tail[0];
            project_force(&seg.elem, &node.n, &node.f, &mut tau[seg.vi..]);
            if i >= 3 && self.free_at_root(i - 3) {
                // the ball of a free joint: its force passes unchanged through the three
                // sliders (no rotation between them), whose τ are its components, and no
                // further (the sliders hang from the ground)
                let fp = seg.turn.rotate_back(&node.x.E, &node.f);
                for k in 0..3 {
                    tau[self.segs[i - 3 + k].vi] = fp[k];
                }
                i -= 3;
            } else if let Some(p) = seg.parent {
                let (np, fp) = seg.turn.force_to_parent(&node.x, &node.n, &node.f);
                let parent = &mut head[p];
                parent.n += np;
                parent.f += fp;
            }
        }
    }

    /// The outward step of one segment: its transform, twist, acceleration and the wrench
    /// 𝒥𝒜 + 𝒱 ×f 𝒥𝒱 its joint must transmit (7.11.13–15).
    #[inline(always)]
    fn rnea_outward(&self, i: usize, q: &[T], v: &[T], vdot: &[T], a0: &Vector3<T>, s: &mut Scratch<T>) {
        let seg = &self.segs[i];
        let x = self.seg_xform(i, q, s.trig.get(i));
        let (head, tail) = s.nodes.split_at_mut(i);
        let ((wp, vp), (ap, lp)) = match seg.parent {
            Some(p) => {
                let n = &head[p];
                ((n.w, n.v), (n.aw, n.av))
            }
            None => ((Vector3::zeros(), Vector3::zeros()), (Vector3::zeros(), *a0)),
        };
        let (mut w, mut vel) = seg.turn.motion(&x, &wp, &vp);
        let (mut aw, mut av) = seg.turn.motion(&x, &ap, &lp);
        let (sw, sv) = joint_motion(&seg.elem, &v[seg.vi..]);
        let (saw, sav) = joint_motion(&seg.elem, &vdot[seg.vi..]);
        w += sw;
        vel += sv;
        let (cw, cv) = joint_bias(&seg.elem, &w, &vel, &sw, &sv);
        aw += saw + cw;
        av += sav + cv;
        // ℱ_i = 𝒥𝒜 + 𝒱 ×f 𝒥𝒱 (zero for a massless segment)
        let (n, f) = if seg.massless {
            (Vector3::zeros(), Vector3::zeros())
        } else {
            body_wrench(seg, &w, &vel, &aw, &av)
        };
        tail[0] = Node { x, w, v: vel, aw, av, n, f };
    }

    /// The outward step of a free joint at the root (segments f..f+4, [`Model::free_at_root`])
    /// at once: the sliders do not turn, so their twists are (0, ṗ) and their accelerations
    /// (0, E₀(−g) + p̈) in the joint frame's axes (E₀ its placement's rotation); the ball then
    /// gives the body ω = q̇_ball, v = E ṗ, ω̇ = q̈_ball (ω × ω = 0) and E(E₀(−g) + p̈) + v × ω.
    /// The same numbers as four outward steps, without their products by zero.
    #[inline(always)]
    fn rnea_free_outward(&self, f: usize, q: &[T], v: &[T], vdot: &[T], a0: &Vector3<T>, s: &mut Scratch<T>) {
        let x0 = self.seg_xform(f, q, None);
        let (mut vel, mut acc) = (Vector3::zeros(), self.segs[f].turn.rotate(&x0.E, a0));
        let z = Vector3::zeros();
        for k in 0..3 {
            let j = self.segs[f + k].vi;
            vel[k] = v[j];
            acc[k] += vdot[j];
            let x = if k == 0 { x0 } else { self.seg_xform(f + k, q, None) };
            s.nodes[f + k] = Node { x, w: z, v: vel, aw: z, av: acc, n: z, f: z };
        }
        let b = f + 3;
        let (seg, x) = (&self.segs[b], self.seg_xform(b, q, None));
        let j = seg.vi;
        let w = Vector3::new(v[j], v[j + 1], v[j + 2]);
        let aw = Vector3::new(vdot[j], vdot[j + 1], vdot[j + 2]);
        let vel = seg.turn.rotate(&x.E, &vel);
        let av = seg.turn.rotate(&x.E, &acc) + vel.cross(&w);
        let (n, f) = body_wrench(seg, &w, &vel, &aw, &av);
        s.nodes[b] = Node { x, w, v: vel, aw, av, n, f };
    }
}

/// ℱ = 𝒥𝒜 + 𝒱 ×f 𝒥𝒱 of one body with twist (ω, v) and acceleration (ω̇, a) (7.11.13).
#[inline(always)]
fn body_wrench<T: Scalar>(
    seg: &super::segment::Segment<T>,
    w: &Vector3<T>,
    vel: &Vector3<T>,
    aw: &Vector3<T>,
    av: &Vector3<T>,
) -> (Vector3<T>, Vector3<T>) {
    let (hn, hf) = seg.inertia.apply(w, vel);
    let (in_, if_) = seg.inertia.apply(aw, av);
    let (gn, gf) = cross_force(w, vel, &hn, &hf);
    (in_ + gn, if_ + gf)
}

/// S q̇ for one elementary joint: (ω, v) in the child frame.
#[inline(always)]
pub(crate) fn joint_motion<T: Scalar>(elem: &Elem<T>, qd: &[T]) -> (Vector3<T>, Vector3<T>) {
    match elem {
        Elem::Revolute(a) => (a * qd[0], Vector3::zeros()),
        Elem::Prismatic(a) => (Vector3::zeros(), a * qd[0]),
        Elem::Spherical => (Vector3::new(qd[0], qd[1], qd[2]), Vector3::zeros()),
        Elem::Fixed => (Vector3::zeros(), Vector3::zeros()),
    }
}

/// The bias acceleration 𝒱 ×m S q̇ = (ω × ω_S, ω × v_S + v × ω_S) of a joint's motion
/// (ω_S, v_S) = S q̇ in a segment moving with (ω, v), by joint type: a pin or ball has v_S = 0,
/// a slider ω_S = 0 (the same numbers as the full product, without its exact zeros).
#[inline(always)]
pub(crate) fn joint_bias<T: Scalar>(
    elem: &Elem<T>,
    w: &Vector3<T>,
    v: &Vector3<T>,
    sw: &Vector3<T>,
    sv: &Vector3<T>,
) -> (Vector3<T>, Vector3<T>) {
    match elem {
        Elem::Revolute(_) | Elem::Spherical => (w.cross(sw), v.cross(sw)),
        Elem::Prismatic(_) => (Vector3::zeros(), w.cross(sv)),
        Elem::Fixed => (Vector3::zeros(), Vector3::zeros()),
    }
}

/// Sᵀ ℱ for one elementary joint, written into `out`.
#[inline(always)]
pub(crate) fn project_force<T: Scalar>(elem: &Elem<T>, n: &Vector3<T>, f: &Vector3<T>, out: &mut [T]) {
    match elem {
        Elem::Revolute(a) => out[0] = a.dot(n),
        Elem::Prismatic(a) => out[0] = a.dot(f),
        Elem::Spherical => out[..3].copy_from_slice(n.as_slice()),
        Elem::Fixed => {}
    }
}

/// What RNEA keeps of one elementary segment: its joint-to-parent transform, its twist (ω, v)
/// and acceleration (ω̇, a) in its own axes, and the wrench (n, f) its joint transmits.
#[derive(Debug, Clone)]
pub(crate) struct Node<T: Scalar> {
    pub(crate) x: Xform<T>,
    pub(crate) w: Vector3<T>,
    pub(crate) v: Vector3<T>,
    pub(crate) aw: Vector3<T>,
    pub(crate) av: Vector3<T>,
    pub(crate) n: Vector3<T>,
    pub(crate) f: Vector3<T>,
}

/// Work space of the tree algorithms (one entry per elementary segment, each segment's numbers
/// together).
#[derive(Debug, Clone)]
pub struct Scratch<T: Scalar = f64> {
    pub(crate) nodes: Vec<Node<T>>,
    /// The revolute joints' sines and cosines, computed together.
    trig: Trig<T>,
}

impl<T: Scalar> Scratch<T> {
    /// Work space for `model` (use [`Model::scratch`]).
    pub(crate) fn new(model: &Model<T>) -> Self {
        let z = Vector3::zeros();
        let node = Node { x: Xform::identity(), w: z, v: z, aw: z, av: z, n: z, f: z };
        Self { nodes: vec![node; model.segs.len()], trig: Trig::of(model) }
    }
}

impl<T: Scalar> Model<T> {
    /// A work space sized for this model, for the `_unchecked` hot paths.
    pub fn scratch(&self) -> Scratch<T> {
        Scratch::new(self)
    }
}
