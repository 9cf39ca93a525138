//! The joints' velocity maps in ground components, for the hot path of a right-hand side: link
//! twists for any velocities at a configuration whose transforms are already known, the links'
//! bias accelerations (v̇ = 0), q̇ from v, and the renormalization of ball-joint quaternions;
//! all generic over the scalar (f64, or dual numbers for exact derivatives).
//!
//! Every joint is a sequence of elementary segments (revolute, prismatic, spherical, fixed);
//! segment s with parent p moves, in ground components, by
//!   ω_s = ω_p + ω_rel,  v_s = v_p + ω_p × (r_s − r_p) + v_rel,
//! where a pin about â turns by ω_rel = 𝓞_{J/G}ᵀ â θ̇, a slider along â moves by
//! v_rel = 𝓞_{J/G}ᵀ â ṡ (𝓞_{J/G} = 𝓞_{J/P} 𝓞_{P/G}: the joint frame, fixed in the parent), and a
//! ball turns by ω_rel = 𝓞_{S/G}ᵀ ω (ω resolved in the link).
//!
//! Book: §4.5 (angular velocities add along a chain), §5 (transport theorem
//! v_y = v_x + ω × r_{y/x}; double transport a = a₀ + α × r + ω × (ω × r)), (4.11.x)
//! quaternion kinematics q̇ = ½ q ⊗ (0, ω).

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

use super::joint::Elem;
use super::kinematics::LinkTwist;
use super::model::{Model, PosesScratch};
use super::segment::Segment;
use super::spatial::Xform;
use crate::DynamicsError;

/// The bias acceleration of a link: its angular acceleration α and the acceleration of its
/// origin when every joint acceleration vanishes (v̇ = 0), ground components. With it, d/dt of
/// anything linear in v (a point's velocity, a loop closure, an inerter's length rate) splits
/// exactly into its v̇ part and this bias.
///
/// Book: §4.5, §5 (a = a₀ + α × r + ω × (ω × r)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkAcceleration<T: Scalar = f64> {
    /// α_{link/ground} at v̇ = 0, ground components.
    pub alpha: Vector3<T>,
    /// Acceleration of the link origin at v̇ = 0, ground components.
    pub acceleration: Vector3<T>,
}

/// Work space of [`Model::twists_into`] and [`Model::bias_accelerations_into`]: the twists
/// (and accelerations) of every elementary segment of one evaluation, kept between calls so
/// that a right-hand side allocates nothing once it has grown.
#[derive(Debug, Clone)]
pub struct MotionScratch<T: Scalar = f64> {
    omega: Vec<Vector3<T>>,
    vel: Vec<Vector3<T>>,
    alpha: Vec<Vector3<T>>,
    acc: Vec<Vector3<T>>,
}

impl<T: Scalar> Default for MotionScratch<T> {
    fn default() -> Self {
        Self { omega: Vec::new(), vel: Vec::new(), alpha: Vec::new(), acc: Vec::new() }
    }
}

impl<T: Scalar> Model<T> {
    /// Segment twists (ground components) for the velocities `v` into `s`, at the configuration
    /// whose ground-to-segment transforms `world` holds.
    fn segment_twists(&self, world: &PosesScratch<T>, v: &[T], s: &mut MotionScratch<T>) {
        let world = &world.0;
        let n = self.segs.len();
        s.omega.resize(n, Vector3::zeros());
        s.vel.resize(n, Vector3::zeros());
        for (i, seg) in self.segs.iter().enumerate() {
            if self.free_seg[i] {
                // a free joint at the root carrying a leaf body ([`Model::aba_into`]'s free
                // leaves): its sliders along the joint frame's axes and its ball in one step
                if seg.parent.is_none() {
                    let vv = &v[seg.vi..seg.vi + 6];
                    let rate = Vector3::new(vv[0], vv[1], vv[2]);
                    let vel = if seg.placement_is_shift { rate } else { seg.placement.E.tr_mul(&rate) };
                    let w = world[i + 3].E.tr_mul(&Vector3::new(vv[3], vv[4], vv[5]));
                    // the sliders' frames do not turn; nothing but the next slider hangs from
                    // them, so their velocities (which no bias term reads, ω = 0) are the body's
                    s.omega[i..i + 3].fill(Vector3::zeros());
                    s.vel[i..i + 4].fill(vel);
                    s.omega[i + 3] = w;
                }
                continue;
            }
            let x = &world[i];
            let (w_p, mut v_p) = match seg.parent {
                Some(p) => (s.omega[p], s.vel[p]),
                None => (Vector3::zeros(), Vector3::zeros()),
            };
            // a parent that keeps the ground's orientation does not turn: ω_p = 0
            if let Some(p) = seg.parent
                && !seg.parent_upright
            {
                v_p += w_p.cross(&(x.r - world[p].r));
            }
            let vv = &v[seg.vi..];
            let (w, vel) = match &seg.elem {
                Elem::Revolute(a) => (w_p + ground_axis(seg, world, a) * vv[0], v_p),
                Elem::Prismatic(a) => (w_p, v_p + ground_axis(seg, world, a) * vv[0]),
                Elem::Spherical => (w_p + x.E.tr_mul(&Vector3::new(vv[0], vv[1], vv[2])), v_p),
                Elem::Fixed => (w_p, v_p),
            };
            s.omega[i] = w;
            s.vel[i] = vel;
        }
    }

    /// Link twists for the velocities `v` at the configuration whose transforms `world` holds
    /// as [`Model::poses_into`] left it: for each link (user order) ω_{link/ground} and the
    /// velocity of its origin, ground components, into `out`. Without input checks (the hot
    /// path of a right-hand side; [`Model::twists`] is the checked call). Several velocities
    /// at one configuration (the columns of a constraint Jacobian) reuse `world`.
    ///
    /// Book: §4.5 (ω adds along a chain), §5 (transport theorem v_y = v_x + ω × r_{y/x}).
    ///
    /// # Panics
    /// If `v` is shorter than [`Model::nv`] or `world` was not filled by this model.
    pub fn twists_into(
        &self,
        world: &PosesScratch<T>,
        v: &[T],
        scratch: &mut MotionScratch<T>,
        out: &mut Vec<LinkTwist<T>>,
    ) {
        self.segment_twists(world, v, scratch);
        out.clear();
        out.extend(
            self.link_seg.iter().map(|&k| LinkTwist { omega: scratch.omega[k], velocity: scratch.vel[k] }),
        );
    }

    /// Link bias accelerations (v̇ = 0) at the velocities `v` and the configuration whose
    /// transforms `world` holds as [`Model::poses_into`] left it, into `out` (user link
    /// order). Recursively, parent p → segment s with ρ = r_s − r_p and the joint's relative
    /// rates ω_rel = ω_s − ω_p, v_rel = v_s − v_p − ω_p × ρ:
    ///   α_s = α_p + ω_f × ω_rel (ω_f = ω_s for a ball, whose rates are resolved in the link;
    ///   ω_p for pins and sliders, whose axes are fixed in the parent),
    ///   a_s = a_p + α_p × ρ + ω_p × (ω_p × ρ) + 2 ω_p × v_rel.
    /// Without input checks ([`Model::bias_accelerations`] is the checked call).
    ///
    /// Book: §4.5, §5 (transport theorem, a = a₀ + α × r + ω × (ω × r)).
    ///
    /// # Panics
    /// If `v` is shorter than [`Model::nv`] or `world` was not filled by this model.
    pub fn bias_accelerations_into(
        &self,
        world: &PosesScratch<T>,
        v: &[T],
        scratch: &mut MotionScratch<T>,
        out: &mut Vec<LinkAcceleration<T>>,
    ) {
        self.segment_twists(world, v, scratch);
        let (world, s) = (&world.0, scratch);
        let n = self.segs.len();
        s.alpha.resize(n, Vector3::zeros());
        s.acc.resize(n, Vector3::zeros());
        let two = T::lit(2.0);
        for (i, seg) in self.segs.iter().enumerate() {
            let Some(p) = seg.parent else {
                // a root's joint frame is the ground's: no bias
                s.alpha[i] = Vector3::zeros();
                s.acc[i] = Vector3::zeros();
                continue;
            };
            let (w_p, al_p) = (s.omega[p], s.alpha[p]);
            let rho = world[i].r - world[p].r;
            let w_rel = s.omega[i] - w_p;
            let v_rel = s.vel[i] - s.vel[p] - w_p.cross(&rho);
            let w_f = if seg.elem == Elem::Spherical { s.omega[i] } else { w_p };
            s.alpha[i] = al_p + w_f.cross(&w_rel);
            s.acc[i] = s.acc[p] + al_p.cross(&rho) + w_p.cross(&w_p.cross(&rho)) + w_p.cross(&v_rel) * two;
        }
        out.clear();
        out.extend(
            self.link_seg.iter().map(|&k| LinkAcceleration { alpha: s.alpha[k], acceleration: s.acc[k] }),
        );
    }

    /// Link bias accelerations at (q, v) (see [`Model::bias_accelerations_into`]), checked.
    ///
    /// Book: §4.5, §5.
    ///
    /// # Errors
    /// As [`Model::twists`].
    pub fn bias_accelerations(&self, q: &[T], v: &[T]) -> Result<Vec<LinkAcceleration<T>>, DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        let (mut world, mut poses, mut out) = (PosesScratch::default(), Vec::new(), Vec::new());
        self.poses_into(q, &mut world, &mut poses);
        self.bias_accelerations_into(&world, v, &mut MotionScratch::default(), &mut out);
        if !out.iter().all(|a| {
            crate::error::all_finite(a.alpha.as_slice())
                && crate::error::all_finite(a.acceleration.as_slice())
        }) {
            return Err(DynamicsError::Overflow { what: "bias accelerations" });
        }
        Ok(out)
    }

    /// q̇ from v into `out` (length nq): q̇ = v for pins and sliders, and for a ball (also the
    /// ball of a free joint) q̇ = ½ q ⊗ (0, ω) with ω resolved in the link. Without input
    /// checks (the hot path of a right-hand side).
    ///
    /// Book: (4.11.x) quaternion kinematics, Euler parameters (§2.15).
    ///
    /// # Panics
    /// If q or `out` is shorter than [`Model::nq`] or `v` shorter than [`Model::nv`].
    pub fn qdot_into(&self, q: &[T], v: &[T], out: &mut [T]) {
        let half = T::lit(0.5);
        for s in &self.segs {
            let (qi, vi) = (s.qi, s.vi);
            match s.elem {
                Elem::Revolute(_) | Elem::Prismatic(_) => out[qi] = v[vi],
                Elem::Spherical => {
                    let (e0, e1, e2, e3) = (q[qi], q[qi + 1], q[qi + 2], q[qi + 3]);
                    let (p, r, w) = (v[vi], v[vi + 1], v[vi + 2]);
                    out[qi] = half * (-e1 * p - e2 * r - e3 * w);
                    out[qi + 1] = half * (e0 * p + e2 * w - e3 * r);
                    out[qi + 2] = half * (e0 * r + e3 * p - e1 * w);
                    out[qi + 3] = half * (e0 * w + e1 * r - e2 * p);
                }
                Elem::Fixed => {}
            }
        }
    }

    /// Divides every ball-joint quaternion of q by its norm ([`normalize_quaternion`]; the
    /// other coordinates are untouched).
    ///
    /// Book: §2.15 (Euler parameters have unit norm).
    ///
    /// # Panics
    /// If q is shorter than [`Model::nq`].
    pub fn normalize_quaternions(&self, q: &mut [T]) {
        for s in self.segs.iter().filter(|s| s.elem == Elem::Spherical) {
            normalize_quaternion(&mut q[s.qi..s.qi + 4]);
        }
    }

    /// Checks a configuration as every checked call does: its length [`Model::nq`], finite
    /// numbers, and ball-joint quaternions of norm in [1e-6, 1e150] (they are normalized where
    /// used). For callers of the unchecked hot paths ([`Model::poses_into`],
    /// [`Model::twists_into`]).
    ///
    /// Book: §2.15 (Euler parameters).
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`],
    /// [`DynamicsError::OutOfRange`].
    pub fn check_configuration(&self, q: &[T]) -> Result<(), DynamicsError> {
        self.check_q(q)
    }
}

/// The map v ↦ q̇ of a model, compiled once for a hot path ([`Model::qdot_plan`]): runs of
/// one-coordinate segments (pins, sliders) whose q̇ is a copy of v, ball joints whose
/// q̇ = ½ q ⊗ (0, ω), and free joints (a run of three then a ball) as one step. [`QdotPlan::apply`]
/// gives exactly what [`Model::qdot_into`] gives.
///
/// Book: (4.11.x) quaternion kinematics, Euler parameters (§2.15).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct QdotPlan {
    steps: Vec<QdotStep>,
    nq: usize,
    nv: usize,
}

/// One step of a [`QdotPlan`], at (first q index, first v index).
#[derive(Debug, Clone, Copy, PartialEq)]
enum QdotStep {
    /// q̇ = v over a run of this many coordinates.
    Copy(usize, usize, usize),
    /// A ball joint's quaternion rate.
    Ball(usize, usize),
    /// A free joint: three copied coordinates, then the ball's quaternion rate.
    Free(usize, usize),
}

/// ė = ½ e ⊗ (0, ω) for Euler parameters e = (η, ε) and ω in the link frame.
#[inline(always)]
fn quaternion_rate<T: Scalar>(e: &[T; 4], w: &[T; 3], o: &mut [T; 4]) {
    let ([e0, e1, e2, e3], [p, r, w], half) = (*e, *w, T::lit(0.5));
    o[0] = half * (-e1 * p - e2 * r - e3 * w);
    o[1] = half * (e0 * p + e2 * w - e3 * r);
    o[2] = half * (e0 * r + e3 * p - e1 * w);
    o[3] = half * (e0 * w + e1 * r - e2 * p);
}

impl QdotPlan {
    /// q̇ from (q, v) into `out`, as [`Model::qdot_into`] computes it.
    ///
    /// Book: (4.11.x) quaternion kinematics.
    ///
    /// # Panics
    /// If q or `out` is shorter than the model's nq or `v` shorter than its nv.
    #[inline]
    pub fn apply<T: Scalar>(&self, q: &[T], v: &[T], out: &mut [T]) {
        let (q, v, out) = (&q[..self.nq], &v[..self.nv], &mut out[..self.nq]);
        // the plan's indices lie inside nq and nv by construction; a step that would not is
        // skipped rather than indexed
        for &step in &self.steps {
            match step {
                QdotStep::Copy(qi, vi, n) => {
                    if let (Some(o), Some(x)) = (out.get_mut(qi..qi + n), v.get(vi..vi + n)) {
                        o.copy_from_slice(x);
                    }
                }
                QdotStep::Ball(qi, vi) => {
                    if let (Some(e), Some(w), Some(o)) = (quad(q, qi), triple(v, vi), quad_mut(out, qi)) {
                        quaternion_rate(e, w, o);
                    }
                }
                QdotStep::Free(qi, vi) => {
                    let (Some(e), Some(x)) = (quad(q, qi + 3), v.get(vi..vi + 6)) else { continue };
                    let Some(o) = out.get_mut(qi..qi + 7) else { continue };
                    let (o3, o4) = o.split_at_mut(3);
                    let (x3, w) = x.split_at(3);
                    o3.copy_from_slice(x3);
                    if let (Ok(w), Ok(o4)) = (<&[T; 3]>::try_from(w), <&mut [T; 4]>::try_from(o4)) {
                        quaternion_rate(e, w, o4);
                    }
                }
            }
        }
    }
}

fn quad<T>(x: &[T], i: usize) -> Option<&[T; 4]> {
    x.get(i..i + 4).and_then(|e| e.try_into().ok())
}

fn quad_mut<T>(x: &mut [T], i: usize) -> Option<&mut [T; 4]> {
    x.get_mut(i..i + 4).and_then(|e| e.try_into().ok())
}

fn triple<T>(x: &[T], i: usize) -> Option<&[T; 3]> {
    x.get(i..i + 3).and_then(|e| e.try_into().ok())
}

impl<T: Scalar> Model<T> {
    /// The model's v ↦ q̇ map compiled for repeated use ([`QdotPlan`]).
    ///
    /// Book: (4.11.x) quaternion kinematics.
    pub fn qdot_plan(&self) -> QdotPlan {
        let mut steps: Vec<QdotStep> = Vec::new();
        for s in &self.segs {
            match s.elem {
                Elem::Revolute(_) | Elem::Prismatic(_) => match steps.last_mut() {
                    Some(QdotStep::Copy(qi, vi, n)) if *qi + *n == s.qi && *vi + *n == s.vi => *n += 1,
                    _ => steps.push(QdotStep::Copy(s.qi, s.vi, 1)),
                },
                Elem::Spherical => match steps.last_mut() {
                    // a free joint's three slides run straight into its ball
                    Some(step @ &mut QdotStep::Copy(qi, vi, 3)) if qi + 3 == s.qi && vi + 3 == s.vi => {
                        *step = QdotStep::Free(qi, vi);
                    }
                    _ => steps.push(QdotStep::Ball(s.qi, s.vi)),
                },
                Elem::Fixed => {}
            }
        }
        QdotPlan { steps, nq: self.nq(), nv: self.nv() }
    }
}

/// Divides the Euler parameters (η, ε₁, ε₂, ε₃) by their norm √(η² + ε·ε); a zero quaternion
/// is left as it is.
///
/// Book: §2.15 (Euler parameters have unit norm).
///
/// # Panics
/// If `e` has fewer than four entries.
pub fn normalize_quaternion<T: Scalar>(e: &mut [T]) {
    let e = &mut e[..4];
    let n = e.iter().fold(T::zero(), |acc, x| acc + *x * *x).sqrt();
    if n > T::zero() {
        e.iter_mut().for_each(|x| *x /= n);
    }
}

/// Ground components of a segment's joint-frame axis: 𝓞_{J/G}ᵀ â with 𝓞_{J/G} = 𝓞_{J/P} 𝓞_{P/G}
/// (exactly â behind a placement without rotation on the ground or an upright parent).
#[inline(always)]
fn ground_axis<T: Scalar>(seg: &Segment<T>, world: &[Xform<T>], a: &Vector3<T>) -> Vector3<T> {
    match seg.parent {
        None if seg.placement_is_shift => *a,
        Some(_) if seg.placement_is_shift && seg.parent_upright => *a,
        Some(p) if seg.placement_is_shift => world[p].E.tr_mul(a),
        Some(p) => (seg.placement.E * world[p].E).tr_mul(a),
        None => seg.placement.E.tr_mul(a),
    }
}

#[cfg(test)]
#[path = "motion_tests.rs"]
mod tests;
