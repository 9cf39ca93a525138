//! The declared force elements as link wrenches and joint torques, built on the statics
//! layer's elements, and their potentials.
//!
//! Book: (6.7.1) springs, (6.8.1) dashpots, (6.12.1) gravitation, (6.13.11)/(6.13.18)
//! dipoles; potentials (8.3.10), (8.3.12), (6.13.9).

use nalgebra::Vector3;
use vectrix_frames::Frame;
use vectrix_statics::{
    CentralGravity, Dashpot, MutualGravitation, Spring, dipole_interaction, dipole_potential,
};
use vectrix_tensor::Scalar;

use super::kin::{Kin, lift};
use super::parts::{Body, Effect};
use vectrix_dynamics::multibody::JointWrench;

/// World vector ↔ frame-free vector through the ground frame ([`Frame::identity`], read and
/// written without arithmetic), in the scalar of an evaluation.
pub(crate) struct Ground<T: Scalar = f64>(std::marker::PhantomData<T>);

impl<T: Scalar> Ground<T> {
    pub fn new() -> Self {
        Self(std::marker::PhantomData)
    }
    #[inline]
    fn vec(&self, x: &Vector3<T>) -> vectrix_tensor::Vector<T> {
        Frame::identity_vector([x[0], x[1], x[2]])
    }
    #[inline]
    fn res(&self, x: &vectrix_tensor::Vector<T>) -> Vector3<T> {
        Frame::identity_components(x)
    }
}

/// Accumulates link wrenches (link components, about the link origin) and joint torques.
pub(crate) struct Loads<'a, T: Scalar = f64> {
    pub kin: &'a Kin<T>,
    pub wrenches: &'a mut [JointWrench<T>],
    pub tau: &'a mut [T],
}

impl<T: Scalar> Loads<'_, T> {
    /// Force f (ground) at ground point p on body i (nothing on the ground).
    pub fn force(&mut self, i: Option<usize>, p: &Vector3<T>, f: &Vector3<T>) {
        if let Some(i) = i {
            let (e, r) = self.kin.poses[i];
            self.wrenches[i].force += e * f;
            self.wrenches[i].moment += e * (p - r).cross(f);
        }
    }
    /// Force f (ground) at body i's centre of mass, `com` its link components: the link
    /// wrench is (𝓞 f, com × 𝓞 f), without going through the ground point.
    #[inline(always)]
    pub fn force_at_centre(&mut self, i: usize, com: &Vector3<f64>, f: &Vector3<T>) {
        let fl = self.kin.poses[i].0 * f;
        self.wrenches[i].force += fl;
        if *com != Vector3::zeros() {
            self.wrenches[i].moment += lift::<T>(com).cross(&fl);
        }
    }
    /// Pure torque (ground components) on body i.
    pub fn torque(&mut self, i: usize, m: &Vector3<T>) {
        let e = self.kin.poses[i].0;
        self.wrenches[i].moment += e * m;
    }
}

/// Ground position of a body's centre of mass.
#[inline]
pub(crate) fn centre<T: Scalar>(kin: &Kin<T>, b: &Body, i: usize) -> Vector3<T> {
    kin.position(&(Some(i), b.com))
}

/// Adds every declared force effect at time t (uniform gravity is the model's; impacts,
/// rolling and inerters are handled elsewhere), in the scalar of the evaluation (f64, or dual
/// numbers for exact derivatives); `u` adds to the magnitudes of the `force` and `torque`
/// effects, in their order (the inputs of a linearization), when given. `(t, piece)`: the time
/// and, in a run, the piece between two corners of the load profiles that it lies on
/// ([`Profile::eval_on`](super::profile::Profile::eval_on)).
#[allow(clippy::too_many_arguments)]
pub(crate) fn apply<T: Scalar>(
    effects: &[Effect],
    bodies: &[Body],
    g: &Ground<T>,
    (t, piece): (f64, Option<(f64, f64)>),
    v: &[T],
    q_angle: &dyn Fn(usize) -> T,
    u: Option<&[T]>,
    loads: &mut Loads<T>,
) -> Result<(), String> {
    let err = |e: vectrix_statics::StaticsError| e.to_string();
    let c = T::lit;
    let mut input = 0;
    let mut magnitude = |p: f64| {
        let m = c(p) + u.and_then(|u| u.get(input).copied()).unwrap_or_else(T::zero);
        input += 1;
        m
    };
    for e in effects {
        match e {
            Effect::Central { mu, centre: x0 } => {
                let cg = CentralGravity::new(c(*mu)).map_err(err)?;
                for (i, b) in bodies.iter().enumerate() {
                    let x = centre(loads.kin, b, i);
                    let f = g.res(&cg.force(c(b.mass), &g.vec(&(x - lift(x0)))).map_err(err)?);
                    loads.force_at_centre(i, &b.com, &f);
                }
            }
            Effect::Mutual { pairs } => mutual(pairs, bodies, g, loads)?,
            Effect::Spring { a, b, k, d } => {
                let (pa, pb) = (loads.kin.position(a), loads.kin.position(b));
                let f =
                    g.res(&Spring::new(c(*k), c(*d)).map_err(err)?.force(&g.vec(&(pb - pa))).map_err(err)?);
                loads.force(b.0, &pb, &f);
                loads.force(a.0, &pa, &(-f));
            }
            Effect::Dashpot { a, b, c: damping } => {
                let (pa, va) = loads.kin.point(a);
                let (pb, vb) = loads.kin.point(b);
                let f = g.res(
                    &Dashpot::new(c(*damping))
                        .map_err(err)?
                        .force(&g.vec(&(pb - pa)), &g.vec(&(vb - va)))
                        .map_err(err)?,
                );
                loads.force(b.0, &pb, &f);
                loads.force(a.0, &pa, &(-f));
            }
            Effect::RotSpring { dof, kappa, angle } => {
                loads.tau[*dof] -= c(*kappa) * (q_angle(*dof) - c(*angle))
            }
            Effect::RotDashpot { dof, xi } => loads.tau[*dof] -= c(*xi) * v[*dof],
            Effect::Dipoles { list } => dipoles(list, bodies, g, loads)?,
            Effect::Force { at, dir, profile } => {
                let p = loads.kin.position(at);
                let f = lift::<T>(dir) * magnitude(profile.eval_on(t, piece));
                loads.force(at.0, &p, &f);
            }
            Effect::Torque { body, dir, profile } => {
                let m = lift::<T>(dir) * magnitude(profile.eval_on(t, piece));
                loads.torque(*body, &m)
            }
            Effect::Thrust { body, profile, angle } => {
                // (11.2.11): F_T [cos Φ_T, 0, −sin Φ_T] in link components, at the centre of mass
                let f_t = magnitude(profile.eval_on(t, piece));
                let e = loads.kin.poses[*body].0;
                let f = e.tr_mul(&Vector3::new(c(angle.cos()), T::zero(), c(-angle.sin()))) * f_t;
                loads.force_at_centre(*body, &bodies[*body].com, &f);
            }
            Effect::Aero { body, aircraft, controls } => {
                // at α̇ = β̇ = 0; the rate terms are solved after ABA (`aero::aero_rates`)
                let u = [0, 1, 2].map(|k| magnitude(controls[k].eval_on(t, piece)));
                let b = &bodies[*body];
                let (vel, omega) = super::aero::air_velocity(loads.kin, b, *body);
                let w = super::aero::wrench(aircraft, b, &vel, &omega, u, (T::zero(), T::zero()))?;
                loads.wrenches[*body].force += w.force;
                loads.wrenches[*body].moment += w.moment;
            }
            Effect::Uniform { .. }
            | Effect::Inerter { .. }
            | Effect::RotInerter { .. }
            | Effect::Spheres { .. }
            | Effect::Plane { .. }
            | Effect::JointStop { .. }
            | Effect::Rolling { .. } => {}
        }
    }
    Ok(())
}

/// Newton's gravitation between every pair of bodies (centres of mass), each pair's G mᵢ mⱼ
/// checked when the scene was built.
///
/// Book: (6.12.1) (gravitation).
fn mutual<T: Scalar>(
    pairs: &[(usize, usize, MutualGravitation)],
    bodies: &[Body],
    g: &Ground<T>,
    loads: &mut Loads<T>,
) -> Result<(), String> {
    for &(i, j, pair) in pairs {
        let (xi, xj) = (centre(loads.kin, &bodies[i], i), centre(loads.kin, &bodies[j], j));
        let f = g.res(&pair.cast::<T>().force_on_y(&g.vec(&(xi - xj))).map_err(|e| e.to_string())?);
        loads.force_at_centre(i, &bodies[i].com, &f);
        loads.force_at_centre(j, &bodies[j].com, &(-f));
    }
    Ok(())
}

/// The forces and torques between every pair of magnetic dipoles (moments fixed in their
/// bodies, at the centres of mass).
///
/// Book: (6.13.11), (6.13.18) (dipoles).
fn dipoles<T: Scalar>(
    list: &[(usize, Vector3<f64>)],
    bodies: &[Body],
    g: &Ground<T>,
    loads: &mut Loads<T>,
) -> Result<(), String> {
    for (x, (bi, mi)) in list.iter().enumerate() {
        for (bj, mj) in &list[x + 1..] {
            let (ei, ej) = (loads.kin.poses[*bi].0, loads.kin.poses[*bj].0);
            let (zi, zj) = (centre(loads.kin, &bodies[*bi], *bi), centre(loads.kin, &bodies[*bj], *bj));
            let p = dipole_interaction(
                &g.vec(&(ei.transpose() * lift::<T>(mi))),
                &g.vec(&(ej.transpose() * lift::<T>(mj))),
                &g.vec(&(zi - zj)),
            )
            .map_err(|e| e.to_string())?;
            loads.force_at_centre(*bi, &bodies[*bi].com, &g.res(&p.force_on_z));
            loads.force_at_centre(*bj, &bodies[*bj].com, &g.res(&p.force_on_y));
            loads.torque(*bi, &g.res(&p.torque_on_z));
            loads.torque(*bj, &g.res(&p.torque_on_y));
        }
    }
    Ok(())
}

/// Potential energy of the conservative declared effects, in any scalar.
pub(crate) fn potential<T: Scalar>(
    effects: &[Effect],
    bodies: &[Body],
    kin: &Kin<T>,
    g: &Ground<T>,
    q_angle: &dyn Fn(usize) -> T,
) -> T {
    let (c, nan) = (T::lit, T::lit(f64::NAN));
    let mut u = T::zero();
    for e in effects {
        match e {
            Effect::Uniform { g: gv } => {
                for (i, b) in bodies.iter().enumerate() {
                    u -= c(b.mass) * lift::<T>(gv).dot(&centre(kin, b, i));
                }
            }
            Effect::Central { mu, centre: x0 } => {
                for (i, b) in bodies.iter().enumerate() {
                    if let Ok(cg) = CentralGravity::new(c(*mu)) {
                        u += cg.potential(c(b.mass), &g.vec(&(centre(kin, b, i) - lift(x0)))).unwrap_or(nan);
                    }
                }
            }
            Effect::Mutual { pairs } => {
                for &(i, j, pair) in pairs {
                    let r = centre(kin, &bodies[i], i) - centre(kin, &bodies[j], j);
                    u += pair.cast::<T>().potential(&g.vec(&r)).unwrap_or(nan);
                }
            }
            Effect::Spring { a, b, k, d } => {
                let r = kin.point(b).0 - kin.point(a).0;
                u += Spring::new(c(*k), c(*d)).map_or(nan, |s| s.potential(&g.vec(&r)));
            }
            Effect::RotSpring { dof, kappa, angle } => {
                let d = q_angle(*dof) - c(*angle);
                u += T::lit(0.5) * c(*kappa) * d * d
            }
            Effect::Dipoles { list } => {
                for (x, (bi, mi)) in list.iter().enumerate() {
                    for (bj, mj) in &list[x + 1..] {
                        let (ei, ej) = (kin.poses[*bi].0, kin.poses[*bj].0);
                        let r = centre(kin, &bodies[*bi], *bi) - centre(kin, &bodies[*bj], *bj);
                        u += dipole_potential(
                            &g.vec(&(ei.transpose() * lift::<T>(mi))),
                            &g.vec(&(ej.transpose() * lift::<T>(mj))),
                            &g.vec(&r),
                        )
                        .unwrap_or(nan);
                    }
                }
            }
            _ => {}
        }
    }
    u
}
