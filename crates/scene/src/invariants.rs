//! Which conservation laws the declared effects imply, and the quantities themselves:
//! T + U, p = Σ m v_c, H_z = Σ (r_c − z) × m v_c + J ω.
//!
//! Book: §8.3 (conservative forces, energy), §7.4 (momentum), §7.6 (angular momentum about a
//! point), Fact 7.x (conservation when the external moment about z vanishes).

use nalgebra::Vector3;
use serde::Serialize;

use super::Scene;
use super::build::Built;
use super::forces::{Ground, centre, potential};
use super::kin::{Kin, lift, lift33};
use super::parts::Effect;
use vectrix_dynamics::multibody::Joint;
use vectrix_tensor::Scalar;

/// A conservation law implied by the declared effects.
///
/// Book: §7.4, §7.6, §8.3.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Invariant {
    /// T + U: every declared effect is conservative (no dashpots, applied loads, lossy impacts).
    Energy,
    /// p: no external force (every root joint free, no field of the ground, no plane).
    Momentum,
    /// H about a fixed point: every external force passes through it, no external torque.
    AngularMomentum {
        /// The point (ground components).
        about: [f64; 3],
    },
    /// The component of H about a fixed point along a fixed axis (uniform gravity along it).
    AngularMomentumAlong {
        /// The point.
        about: [f64; 3],
        /// The axis (unit, ground components).
        axis: [f64; 3],
    },
}

impl Invariant {
    /// Short name (`energy`, `momentum`, `angular_momentum`).
    pub fn name(&self) -> &'static str {
        match self {
            Invariant::Energy => "energy",
            Invariant::Momentum => "momentum",
            _ => "angular_momentum",
        }
    }
}

/// Invariants implied by the declared effects.
pub(crate) fn derive(b: &Built) -> Vec<Invariant> {
    let mut conservative = true;
    let mut external_force = false; // a force on the system not through one fixed point
    let mut points: Vec<Vector3<f64>> = Vec::new(); // external forces pass through these
    let mut uniform: Option<Vector3<f64>> = None;
    for body in &b.bodies {
        if body.parent.is_none() {
            match body.joint {
                Joint::Free => {}
                Joint::Ball => points.push(Vector3::zeros()), // pivot at the ground origin + offset below
                _ => external_force = true,
            }
        }
    }
    // ball pivots sit at their offsets: recover them from the model's first poses
    if let Ok(p) = b.model.poses(&b.q0) {
        let mut k = 0;
        for (i, body) in b.bodies.iter().enumerate() {
            if body.parent.is_none() && matches!(body.joint, Joint::Ball) {
                points[k] = p[i].1;
                k += 1;
            }
        }
    }
    // loop joints: between two bodies their forces are internal (and, ideal, do no work); to
    // the ground a ball's force passes through its fixed point, the others' do not
    for l in &b.loops {
        let ground = [l.a, l.b].into_iter().find(|x| x.0.is_none());
        match (ground, &l.kind) {
            // a coupler acts through joint torques (as a rotational spring does)
            (_, super::loops::LoopKind::Coupler { .. }) => external_force = true,
            (None, _) => {}
            (Some(g), super::loops::LoopKind::Ball) => points.push(g.1),
            (Some(_), _) => external_force = true,
        }
    }
    for e in &b.effects {
        let t = effect_terms(e, &mut points, &mut uniform);
        conservative &= t.0;
        external_force |= t.1;
    }
    let mut out = Vec::new();
    if conservative {
        out.push(Invariant::Energy);
    }
    if external_force {
        return out;
    }
    let first = points.first().copied();
    let single = points.iter().all(|p| (p - first.unwrap_or_default()).norm() <= 1e-12 * (1.0 + p.norm()));
    if points.is_empty() && uniform.is_none() {
        out.push(Invariant::Momentum);
    }
    if !single {
        return out;
    }
    let about = first.unwrap_or_default();
    match uniform {
        None => out.push(Invariant::AngularMomentum { about: about.into() }),
        Some(g) if g.norm() > 0.0 => {
            // scaled first: |g|² of components near 1e300 overflows and g/|g| would be 0⃗
            let axis = (g / g.amax()).normalize();
            out.push(Invariant::AngularMomentumAlong { about: about.into(), axis: axis.into() })
        }
        Some(_) => out.push(Invariant::AngularMomentum { about: about.into() }),
    }
    out
}

/// What one effect implies: (conservative, a force on the system not through one fixed
/// point); the fixed points its external forces pass through and the uniform field it adds.
fn effect_terms(
    e: &Effect,
    points: &mut Vec<Vector3<f64>>,
    uniform: &mut Option<Vector3<f64>>,
) -> (bool, bool) {
    let ground_ends = |ends: [&super::parts::At; 2], points: &mut Vec<Vector3<f64>>| {
        points.extend(ends.into_iter().filter(|end| end.0.is_none()).map(|end| end.1))
    };
    match e {
        Effect::Uniform { g } => {
            *uniform = Some(uniform.unwrap_or_default() + g);
            (true, false)
        }
        Effect::Central { centre, .. } => {
            points.push(*centre);
            (true, false)
        }
        Effect::Spring { a, b, .. } | Effect::Inerter { a, b, .. } => {
            ground_ends([a, b], points);
            (true, false)
        }
        Effect::Dashpot { a, b, .. } => {
            ground_ends([a, b], points);
            (false, false)
        }
        Effect::RotSpring { .. } | Effect::RotInerter { .. } => (true, true),
        Effect::RotDashpot { .. } => (false, true),
        Effect::Force { .. } | Effect::Torque { .. } | Effect::Aero { .. } | Effect::Thrust { .. } => {
            (false, true)
        }
        Effect::Spheres { e, mu, .. } => (*e == 1.0 && *mu == 0.0, false),
        Effect::Plane { e, mu, .. } => (*e == 1.0 && *mu == 0.0, true),
        Effect::Rolling { .. } => (true, true),
        // a stop acts through a joint torque (as a rotational spring does)
        Effect::JointStop { e, .. } => (*e == 1.0, true),
        Effect::Mutual { .. } | Effect::Dipoles { .. } => (true, false),
    }
}

impl Scene {
    /// Kinetic energy T = Σ ½ m v_c² + ½ ω·J ω (+ ½ b ℓ̇² of inerters), from a full [`Kin`].
    pub(crate) fn kinetic<T: Scalar>(&self, kin: &Kin<T>, v: &[T]) -> T {
        let (half, c) = (T::lit(0.5), T::lit);
        let mut t = T::zero();
        for (i, b) in self.built.bodies.iter().enumerate() {
            let (e, _) = kin.poses[i];
            let (_, vc) = kin.point(&(Some(i), b.com));
            let w = e * kin.omega[i];
            t += half * c(b.mass) * vc.norm_squared() + half * w.dot(&(lift33::<T>(&b.inertia) * w));
        }
        for e in &self.built.effects {
            match e {
                Effect::Inerter { a, b, b_in } => {
                    let (pa, va) = kin.point(a);
                    let (pb, vb) = kin.point(b);
                    let rate = (pb - pa).try_normalize(c(1e-300)).map_or(T::zero(), |r| r.dot(&(vb - va)));
                    t += half * c(*b_in) * rate * rate;
                }
                Effect::RotInerter { dof, beta } => t += half * c(*beta) * v[*dof] * v[*dof],
                _ => {}
            }
        }
        t
    }

    /// Total energy T + U.
    pub(crate) fn energy<T: Scalar>(&self, kin: &Kin<T>, q: &[T], v: &[T]) -> T {
        let q_angle = |dof: usize| self.angle_of_dof(q, dof);
        self.kinetic(kin, v)
            + potential(&self.built.effects, &self.built.bodies, kin, &Ground::new(), &q_angle)
    }

    /// Sum of the magnitudes of an invariant's terms: the scale of its relative drift.
    pub(crate) fn invariant_scale(&self, inv: &Invariant, kin: &Kin, v: &[f64]) -> f64 {
        let bodies = self.built.bodies.iter().enumerate();
        match inv {
            Invariant::Energy => self.kinetic(kin, v),
            Invariant::Momentum => bodies.map(|(i, b)| b.mass * kin.point(&(Some(i), b.com)).1.norm()).sum(),
            Invariant::AngularMomentum { about } | Invariant::AngularMomentumAlong { about, .. } => bodies
                .map(|(i, b)| {
                    let (e, _) = kin.poses[i];
                    let vc = kin.point(&(Some(i), b.com)).1;
                    let r = centre(kin, b, i) - Vector3::from(*about);
                    b.mass * r.norm() * vc.norm() + (b.inertia * (e * kin.omega[i])).norm()
                })
                .sum(),
        }
    }

    /// p = Σ m v_c.
    pub(crate) fn momentum<T: Scalar>(&self, kin: &Kin<T>) -> Vector3<T> {
        let bodies = self.built.bodies.iter().enumerate();
        bodies.fold(Vector3::zeros(), |p, (i, b)| p + kin.point(&(Some(i), b.com)).1 * T::lit(b.mass))
    }

    /// H about the fixed point z: Σ (r_c − z) × m v_c + J_c ω (7.6.x).
    pub(crate) fn angular_momentum<T: Scalar>(&self, kin: &Kin<T>, z: &Vector3<f64>) -> Vector3<T> {
        let mut h = Vector3::zeros();
        for (i, b) in self.built.bodies.iter().enumerate() {
            let (e, _) = kin.poses[i];
            let (_, vc) = kin.point(&(Some(i), b.com));
            let rc = centre(kin, b, i);
            h += (rc - lift::<T>(z)).cross(&vc) * T::lit(b.mass)
                + e.transpose() * (lift33::<T>(&b.inertia) * (e * kin.omega[i]));
        }
        h
    }
}
