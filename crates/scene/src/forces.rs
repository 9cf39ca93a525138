//! The declared force elements as link wrenches and joint torques, built on the statics
//! layer's elements, and their potentials.
//!
//! Book: (6.7.1) springs, (6.8.1) dashpots, (6.12.1) gravitation, (6.13.11)/(6.13.18)
//! dipoles; potentials (8.3.10), (8.3.12), (6.13.9).

use nalgebra::Vector3;
use vectrix_frames::Frame;
use vectrix_statics::{CentralGravity, Dashpot, Spring, dipole_interaction, dipole_potential};

use super::build::{Body, Effect, eval_profile};
use super::kin::Kin;
use vectrix_dynamics::multibody::JointWrench;

/// World vector ↔ frame-free vector through the ground frame.
pub(crate) struct Ground(Frame);

impl Ground {
    pub fn new() -> Self {
        Self(Frame::new())
    }
    fn vec(&self, x: &Vector3<f64>) -> vectrix_tensor::Vector {
        self.0.vector([x[0], x[1], x[2]])
    }
    fn res(&self, x: &vectrix_tensor::Vector) -> Vector3<f64> {
        use vectrix_frames::Resolve;
        x.resolve(&self.0)
    }
}

/// Accumulates link wrenches (link components, about the link origin) and joint torques.
pub(crate) struct Loads<'a> {
    pub kin: &'a Kin,
    pub wrenches: &'a mut [JointWrench],
    pub tau: &'a mut [f64],
}

impl Loads<'_> {
    /// Force f (ground) at ground point p on body i (nothing on the ground).
    pub fn force(&mut self, i: Option<usize>, p: &Vector3<f64>, f: &Vector3<f64>) {
        if let Some(i) = i {
            let (e, r) = self.kin.poses[i];
            self.wrenches[i].force += e * f;
            self.wrenches[i].moment += e * (p - r).cross(f);
        }
    }
    /// Pure torque (ground components) on body i.
    pub fn torque(&mut self, i: usize, m: &Vector3<f64>) {
        let e = self.kin.poses[i].0;
        self.wrenches[i].moment += e * m;
    }
}

/// Ground position of a body's centre of mass.
pub(crate) fn centre(kin: &Kin, b: &Body, i: usize) -> Vector3<f64> {
    kin.point(&(Some(i), b.com)).0
}

/// Adds every declared force effect at time t (uniform gravity is the model's; impacts,
/// rolling and inerters are handled elsewhere).
pub(crate) fn apply(
    effects: &[Effect],
    bodies: &[Body],
    g: &Ground,
    t: f64,
    v: &[f64],
    q_angle: &dyn Fn(usize) -> f64,
    loads: &mut Loads,
) -> Result<(), String> {
    let err = |e: vectrix_statics::StaticsError| e.to_string();
    for e in effects {
        match e {
            Effect::Central { mu, centre: c } => {
                let cg = CentralGravity::new(*mu).map_err(err)?;
                for (i, b) in bodies.iter().enumerate() {
                    let x = centre(loads.kin, b, i);
                    let f = g.res(&cg.force(b.mass, &g.vec(&(x - c))).map_err(err)?);
                    loads.force(Some(i), &x, &f);
                }
            }
            Effect::Mutual { g: gc } => {
                for i in 0..bodies.len() {
                    for j in i + 1..bodies.len() {
                        let (xi, xj) = (centre(loads.kin, &bodies[i], i), centre(loads.kin, &bodies[j], j));
                        let pair = vectrix_statics::mutual_gravitation(
                            *gc,
                            bodies[i].mass,
                            bodies[j].mass,
                            &g.vec(&(xi - xj)),
                        )
                        .map_err(err)?;
                        let f = g.res(&pair.on_y);
                        loads.force(Some(i), &xi, &f);
                        loads.force(Some(j), &xj, &(-f));
                    }
                }
            }
            Effect::Spring { a, b, k, d } => {
                let (pa, _) = loads.kin.point(a);
                let (pb, _) = loads.kin.point(b);
                let f = g.res(&Spring::new(*k, *d).map_err(err)?.force(&g.vec(&(pb - pa))).map_err(err)?);
                loads.force(b.0, &pb, &f);
                loads.force(a.0, &pa, &(-f));
            }
            Effect::Dashpot { a, b, c } => {
                let (pa, va) = loads.kin.point(a);
                let (pb, vb) = loads.kin.point(b);
                let f = g.res(
                    &Dashpot::new(*c)
                        .map_err(err)?
                        .force(&g.vec(&(pb - pa)), &g.vec(&(vb - va)))
                        .map_err(err)?,
                );
                loads.force(b.0, &pb, &f);
                loads.force(a.0, &pa, &(-f));
            }
            Effect::RotSpring { dof, kappa, angle } => loads.tau[*dof] -= kappa * (q_angle(*dof) - angle),
            Effect::RotDashpot { dof, xi } => loads.tau[*dof] -= xi * v[*dof],
            Effect::Dipoles { list } => {
                for (x, (bi, mi)) in list.iter().enumerate() {
                    for (bj, mj) in &list[x + 1..] {
                        let (ei, ej) = (loads.kin.poses[*bi].0, loads.kin.poses[*bj].0);
                        let (zi, zj) =
                            (centre(loads.kin, &bodies[*bi], *bi), centre(loads.kin, &bodies[*bj], *bj));
                        let p = dipole_interaction(
                            &g.vec(&(ei.transpose() * mi)),
                            &g.vec(&(ej.transpose() * mj)),
                            &g.vec(&(zi - zj)),
                        )
                        .map_err(err)?;
                        loads.force(Some(*bi), &zi, &g.res(&p.force_on_z));
                        loads.force(Some(*bj), &zj, &g.res(&p.force_on_y));
                        loads.torque(*bi, &g.res(&p.torque_on_z));
                        loads.torque(*bj, &g.res(&p.torque_on_y));
                    }
                }
            }
            Effect::Force { at, dir, profile } => {
                let (p, _) = loads.kin.point(at);
                loads.force(at.0, &p, &(dir * eval_profile(profile, t)));
            }
            Effect::Torque { body, dir, profile } => loads.torque(*body, &(dir * eval_profile(profile, t))),
            Effect::Uniform { .. }
            | Effect::Inerter { .. }
            | Effect::RotInerter { .. }
            | Effect::Spheres { .. }
            | Effect::Plane { .. }
            | Effect::Rolling { .. } => {}
        }
    }
    Ok(())
}

/// Potential energy of the conservative declared effects.
pub(crate) fn potential(
    effects: &[Effect],
    bodies: &[Body],
    kin: &Kin,
    g: &Ground,
    q_angle: &dyn Fn(usize) -> f64,
) -> f64 {
    let mut u = 0.0;
    for e in effects {
        match e {
            Effect::Uniform { g: gv } => {
                u -= bodies.iter().enumerate().map(|(i, b)| b.mass * gv.dot(&centre(kin, b, i))).sum::<f64>();
            }
            Effect::Central { mu, centre: c } => {
                for (i, b) in bodies.iter().enumerate() {
                    if let Ok(cg) = CentralGravity::new(*mu) {
                        u += cg.potential(b.mass, &g.vec(&(centre(kin, b, i) - c))).unwrap_or(f64::NAN);
                    }
                }
            }
            Effect::Mutual { g: gc } => {
                for i in 0..bodies.len() {
                    for j in i + 1..bodies.len() {
                        let r = centre(kin, &bodies[i], i) - centre(kin, &bodies[j], j);
                        u -= gc * bodies[i].mass * bodies[j].mass / r.norm();
                    }
                }
            }
            Effect::Spring { a, b, k, d } => {
                let r = kin.point(b).0 - kin.point(a).0;
                u += Spring::new(*k, *d).map_or(f64::NAN, |s| s.potential(&g.vec(&r)));
            }
            Effect::RotSpring { dof, kappa, angle } => u += 0.5 * kappa * (q_angle(*dof) - angle).powi(2),
            Effect::Dipoles { list } => {
                for (x, (bi, mi)) in list.iter().enumerate() {
                    for (bj, mj) in &list[x + 1..] {
                        let (ei, ej) = (kin.poses[*bi].0, kin.poses[*bj].0);
                        let r = centre(kin, &bodies[*bi], *bi) - centre(kin, &bodies[*bj], *bj);
                        u += dipole_potential(
                            &g.vec(&(ei.transpose() * mi)),
                            &g.vec(&(ej.transpose() * mj)),
                            &g.vec(&r),
                        )
                        .unwrap_or(f64::NAN);
                    }
                }
            }
            _ => {}
        }
    }
    u
}
