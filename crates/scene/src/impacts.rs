//! Impacts of spheres with each other and with fixed planes: restitution along the normal
//! and Coulomb friction (sticking impulse capped at μ times the normal impulse), applied as
//! velocity jumps between integration steps.
//!
//! Book: §7.13 (collisions, restitution e (7.13.18)), §7.14 (impulses on rigid bodies).

use nalgebra::{Matrix3, Vector3};

use super::Scene;
use super::contacts::Gap;
use super::kin::Kin;
use super::parts::Effect;

/// Tangential speed below which friction does nothing.
const STICK_EPS: f64 = 1e-12;

/// A free body's response: inverse mass, inverse inertia (ground), centre, velocity of the
/// contact point.
struct Resp {
    i: usize,
    m_inv: f64,
    j_inv: Matrix3<f64>,
    d: Vector3<f64>,
    vp: Vector3<f64>,
}

impl Resp {
    /// Velocity change of the contact point per unit impulse along u, projected on u.
    fn k(&self, u: &Vector3<f64>) -> f64 {
        u.dot(&(u * self.m_inv + (self.j_inv * self.d.cross(u)).cross(&self.d)))
    }
}

impl Scene {
    fn resp(&self, kin: &Kin, i: usize, d: Vector3<f64>) -> Resp {
        let b = &self.built.bodies[i];
        let e = kin.poses[i].0;
        let j_inv = e.transpose() * b.inertia.try_inverse().unwrap_or_else(Matrix3::zeros) * e;
        let (c, vc) = kin.point(&(Some(i), b.com));
        let _ = c;
        Resp { i, m_inv: 1.0 / b.mass, j_inv, d, vp: vc + kin.omega[i].cross(&d) }
    }

    /// Applies impulse `j` (ground) at the contact of `r` to the velocity coordinates.
    fn kick(&self, kin: &Kin, r: &Resp, j: &Vector3<f64>, v: &mut [f64]) {
        let b = &self.built.bodies[r.i];
        let (e, _) = kin.poses[r.i];
        let dw = r.j_inv * r.d.cross(j);
        let dvc = j * r.m_inv;
        let dvo = dvc - dw.cross(&(e.transpose() * b.com));
        let lin = b.orient * dvo;
        let ang = e * dw;
        for k in 0..3 {
            v[b.vi + k] += lin[k];
            v[b.vi + 3 + k] += ang[k];
        }
    }

    /// Resolves every touching ([`Gap::touches`]; `gaps` at the state of `kin`), approaching
    /// contact that is not resting, once; returns the impacts as (contact, closing speed,
    /// opening speed) along the normal.
    pub(crate) fn impacts(
        &self,
        kin: &Kin,
        gaps: &[Gap],
        v: &mut [f64],
        resting: &[bool],
    ) -> Vec<(usize, f64, f64)> {
        let mut out = Vec::new();
        for (c, &k) in self.contacts.iter().enumerate() {
            if resting.get(c).copied().unwrap_or(false) || !gaps[c].touches() {
                continue;
            }
            let e = &self.built.effects[k];
            let (ra_, rb_, n, e_, mu) = match e {
                Effect::Spheres { a, b, ra, rb, e, mu } => {
                    let (xa, xb) = (
                        kin.point(&(Some(*a), self.built.bodies[*a].com)).0,
                        kin.point(&(Some(*b), self.built.bodies[*b].com)).0,
                    );
                    let Some(n) = (xa - xb).try_normalize(1e-300) else { continue };
                    (self.resp(kin, *a, -n * *ra), Some(self.resp(kin, *b, n * *rb)), n, *e, *mu)
                }
                Effect::Plane { body, r, n, e, mu, .. } => {
                    (self.resp(kin, *body, -n * *r), None, *n, *e, *mu)
                }
                _ => continue,
            };
            let u = ra_.vp - rb_.as_ref().map_or(Vector3::zeros(), |r| r.vp);
            let un = u.dot(&n);
            if un >= 0.0 {
                continue;
            }
            let kn = ra_.k(&n) + rb_.as_ref().map_or(0.0, |r| r.k(&n));
            let jn = -(1.0 + e_) * un / kn;
            let mut j = n * jn;
            let ut = u - n * un;
            if mu > 0.0
                && let Some(t) = ut.try_normalize(STICK_EPS)
            {
                let kt = ra_.k(&t) + rb_.as_ref().map_or(0.0, |r| r.k(&t));
                let jt = (ut.norm() / kt).min(mu * jn);
                j -= t * jt;
            }
            self.kick(kin, &ra_, &j, v);
            if let Some(rb) = &rb_ {
                self.kick(kin, rb, &(-j), v);
            }
            out.push((c, -un, -un * e_));
        }
        out
    }
}
