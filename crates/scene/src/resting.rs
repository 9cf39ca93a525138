//! Resting contact of a sphere on a plane (see the module doc of `contacts`): the switch from
//! bouncing to resting, the normal force while resting, lift-off, and keeping a resting sphere
//! on its plane.
//!
//! Book: §7.13; (6.10) normal reactions.

use nalgebra::Vector3;
use vectrix_ode::explicit::{DenseStep, bracket_zero};

use super::Scene;
use super::contacts::{ContactEvent, ContactEventKind, Contacts, Gap, SCAN_SEGMENTS};
use super::kin::{Kin, kinematics};
use super::parts::Effect;
use super::rhs::RhsScratch;

/// A resting sphere is moved back onto its plane when its gap or normal speed drifts past
/// this multiple of ε × its scale.
const HOLD_TOL_EPS: f64 = 64.0;
/// A resting contact with friction slips when its contact point moves faster than this
/// fraction of the speed scale √(|aₙ| r) (plus the speeds present).
const SLIP_TOL_REL: f64 = 1e-9;

/// A plane contact's data: body, radius, normal, friction.
struct PlaneContact {
    body: usize,
    r: f64,
    n: Vector3<f64>,
    mu: f64,
}

impl Scene {
    fn plane(&self, c: usize) -> Option<PlaneContact> {
        match &self.built.effects[self.contacts[c]] {
            Effect::Plane { body, r, n, mu, .. } => Some(PlaneContact { body: *body, r: *r, n: *n, mu: *mu }),
            _ => None,
        }
    }

    /// The acceleration of the centre of mass of root free body i for the joint accelerations
    /// v̇ (ground): a_c = a_o + α × ρ + ω × (ω × ρ), ρ the centre's offset; a free joint's rates
    /// are (ẋ in the joint frame, ω in the link).
    fn centre_accel(&self, kin: &Kin, i: usize, vd: &[f64]) -> Vector3<f64> {
        let b = &self.built.bodies[i];
        let e_l = kin.poses[i].0;
        let rho = e_l.transpose() * b.com;
        let a_o = b.orient.transpose() * Vector3::new(vd[b.vi], vd[b.vi + 1], vd[b.vi + 2]);
        let alpha = e_l.transpose() * Vector3::new(vd[b.vi + 3], vd[b.vi + 4], vd[b.vi + 5]);
        let w = kin.omega[i];
        a_o + alpha.cross(&rho) + w.cross(&w.cross(&rho))
    }

    /// Adds the resting contacts' normal forces N = max(0, −m aₙ) n (through the centre) to the
    /// joint accelerations v̇.
    pub(crate) fn rest_forces(&self, kin: &Kin, resting: &[bool], vd: &mut [f64]) {
        for (c, _) in resting.iter().enumerate().filter(|(_, r)| **r) {
            let Some(p) = self.plane(c) else { continue };
            let a_n = self.centre_accel(kin, p.body, vd).dot(&p.n);
            if a_n < 0.0 {
                // N/m = −aₙ along n: the centre's normal acceleration becomes zero
                let b = &self.built.bodies[p.body];
                let dv = b.orient * (p.n * -a_n);
                for k in 0..3 {
                    vd[b.vi + k] += dv[k];
                }
            }
        }
    }

    /// aₙ of plane contact c at (t, y) without its own normal force (the other resting
    /// contacts pushing): negative while the plane must push.
    /// For a joint stop, the opening part s q̈ of its coordinate's acceleration.
    fn free_normal_accel(&self, t: f64, y: &[f64], resting: &[bool], c: usize) -> Result<f64, String> {
        let (plane, stop) = (self.plane(c), self.stop(c));
        if plane.is_none() && stop.is_none() {
            return Ok(0.0);
        }
        let mut others = resting.to_vec();
        others[c] = false;
        let mut d = vec![0.0; y.len()];
        self.deriv_resting(t, y, &mut d, &mut RhsScratch::new(self), &others)?;
        let b = &self.built;
        let nq = b.model.nq();
        let Some(p) = plane else {
            let s = stop.ok_or("not a contact")?;
            return Ok(super::contacts::side(y[s.qi], s.lower, s.upper) * d[nq + s.vi]);
        };
        let kin = kinematics(&b.model, &y[..nq], &y[nq..])?;
        Ok(self.centre_accel(&kin, p.body, &d[nq..]).dot(&p.n))
    }

    /// Normal speed of plane contact c's centre along n (positive: opening), its gap, and the
    /// gap's resolution: [`GAP_ULPS`](super::contacts::GAP_ULPS) ulps of the lengths it is computed from.
    /// For a joint stop: its opening speed, gap and resolution in q.
    fn normal_motion(&self, y: &[f64], c: usize) -> Result<(f64, f64, f64), String> {
        if let Some(s) = self.stop(c) {
            let g = super::contacts::stop_gap(y[s.qi], y[self.built.model.nq() + s.vi], s.lower, s.upper);
            return Ok((g.opening, g.gap, g.resolution));
        }
        if self.plane(c).is_none() {
            return Err("not a plane contact".into());
        }
        let g = self.gaps(y)?[c];
        Ok((g.opening, g.gap, g.resolution))
    }

    /// Puts plane contact c's sphere exactly on its plane with zero normal speed: the centre
    /// moves by −g n and its velocity loses its normal part (a free joint's translation and its
    /// rate are resolved in the joint frame).
    /// A joint stop's coordinate is put on the stop, its opening speed removed.
    pub(crate) fn place_on_plane(&self, y: &mut [f64], c: usize, gap: f64, u_n: f64) {
        if let Some(s) = self.stop(c) {
            let nq = self.built.model.nq();
            let side = super::contacts::side(y[s.qi], s.lower, s.upper);
            y[s.qi] -= side * gap;
            y[nq + s.vi] -= side * u_n;
            return;
        }
        let Some(p) = self.plane(c) else { return };
        let b = &self.built.bodies[p.body];
        let nq = self.built.model.nq();
        let (dx, dv) = (b.orient * (p.n * -gap), b.orient * (p.n * -u_n));
        for k in 0..3 {
            y[b.qi + k] += dx[k];
            y[nq + b.vi + k] += dv[k];
        }
    }

    /// After the impacts at `t`: every plane contact in flight that touches and whose rebound
    /// would fly for less than `tau_min` comes to rest (placed on its plane, a `Rest` event).
    /// Returns whether any did.
    ///
    /// # Errors
    /// Two spheres whose bounces accumulate, a resting contact in a scene with loops, rolling
    /// or inerters, or two resting contacts of one body whose normals are not perpendicular.
    pub(crate) fn settle(
        &self,
        t: f64,
        y: &mut [f64],
        contacts: &mut Contacts,
        tau_min: f64,
    ) -> Result<bool, String> {
        let mut changed = false;
        let gaps = self.gaps(y)?;
        for (c, g) in gaps.iter().enumerate() {
            if contacts.resting[c] || !g.touches() {
                continue;
            }
            let plane = self.plane(c);
            if plane.is_none() && self.stop(c).is_none() {
                self.spheres_part(t, y, c, g, contacts, tau_min)?;
                continue;
            }
            let (u_n, gap, resolution) = self.normal_motion(y, c)?;
            let a_n = self.free_normal_accel(t, y, &contacts.resting, c)?;
            // the rebound flies for 2uₙ/(−aₙ) and rises uₙ²/(−2aₙ): shorter than tau_min, or
            // lower than the gap's resolution (a flight no scan could see) → resting
            let a = (-a_n).max(0.0);
            if u_n > (0.5 * a * tau_min).max((2.0 * a * resolution).sqrt()) {
                continue;
            }
            if self.needs.constrained() {
                return Err(format!(
                    "the contact of effects[{}] comes to rest at t = {t:e} s in a scene with loops, rolling or \
                     inerters; resting contact is simulated for free spheres alone; valid: restitution 1, or a \
                     duration that ends before the bounces die out",
                    self.contacts[c]
                ));
            }
            for (c2, r2) in contacts.resting.iter().enumerate() {
                if let (true, Some(q), Some(p)) = (*r2, self.plane(c2), plane.as_ref())
                    && q.body == p.body
                    && q.n.dot(&p.n).abs() > 1e-12
                {
                    return Err(format!(
                        "body `{}` comes to rest on two planes whose normals are not perpendicular \
                         (effects[{}] and effects[{}]) at t = {t:e} s; valid: perpendicular resting planes",
                        self.built.bodies[q.body].name, self.contacts[c2], self.contacts[c]
                    ));
                }
            }
            self.place_on_plane(y, c, gap, u_n);
            contacts.resting[c] = true;
            contacts.record(ContactEvent {
                t,
                effect: self.contacts[c],
                kind: ContactEventKind::Rest,
                closing_speed: 0.0,
                opening_speed: u_n.max(0.0),
            });
            changed = true;
        }
        Ok(changed)
    }

    /// Two touching spheres after an impact must part: a rebound that the threshold of
    /// [`Scene::settle`] would call resting, while their free relative acceleration closes
    /// them, is bounces accumulating, which is not simulated between spheres. (Spheres that
    /// touch without closing, as after a perfectly plastic impact in free space, move on.)
    fn spheres_part(
        &self,
        t: f64,
        y: &[f64],
        c: usize,
        g: &Gap,
        contacts: &Contacts,
        tau_min: f64,
    ) -> Result<(), String> {
        let Effect::Spheres { a, b, .. } = self.built.effects[self.contacts[c]] else { return Ok(()) };
        let n = g.pos / g.pos.norm().max(f64::MIN_POSITIVE);
        let u = g.rate.dot(&n);
        let mut d = vec![0.0; y.len()];
        self.deriv_resting(t, y, &mut d, &mut RhsScratch::new(self), &contacts.resting)?;
        let nq = self.built.model.nq();
        let kin = kinematics(&self.built.model, &y[..nq], &y[nq..])?;
        let a_rel = (self.centre_accel(&kin, a, &d[nq..]) - self.centre_accel(&kin, b, &d[nq..])).dot(&n);
        let closing = (-a_rel).max(0.0);
        if closing > 0.0 && u <= (0.5 * closing * tau_min).max((2.0 * closing * g.resolution).sqrt()) {
            return Err(format!(
                "the spheres of effects[{}] stay in contact at t = {t:e} s (bounces accumulate at one instant); \
                 resting contact between spheres is not simulated; valid: restitution 1, or a duration that ends \
                 before the bounces die out",
                self.contacts[c]
            ));
        }
        Ok(())
    }

    /// The first lift-off in (t₀, t₁] of a resting contact: a zero of its free normal
    /// acceleration aₙ (negative while the plane pushes), looked for at the step's
    /// [`SCAN_SEGMENTS`] points and bracketed on the interpolant. Returns (t, contact).
    ///
    /// # Errors
    /// When the dynamics fail on the interpolant.
    pub(crate) fn first_lift_off(
        &self,
        dense: &DenseStep<Vec<f64>>,
        (t0, t1): (f64, f64),
        y1: &[f64],
        resting: &[bool],
    ) -> Result<Option<(f64, usize)>, String> {
        let mut first: Option<(f64, usize)> = None;
        for c in (0..resting.len()).filter(|&c| resting[c]) {
            let a_at = |t: f64| -> Result<f64, String> {
                let y = if t == t1 { y1.to_vec() } else { dense.eval(t) };
                self.free_normal_accel(t, &y, resting, c)
            };
            let mut a = (t0, a_at(t0)?);
            for k in 1..=SCAN_SEGMENTS {
                let tk =
                    if k == SCAN_SEGMENTS { t1 } else { t0 + (t1 - t0) * (k as f64 / SCAN_SEGMENTS as f64) };
                if first.is_some_and(|(t, _)| tk > t) {
                    break;
                }
                let ak = a_at(tk)?;
                if ak > 0.0 {
                    let (_, tz) = bracket_zero(|t| a_at(t).unwrap_or(1.0), (a.0, a.1.min(0.0)), (tk, ak));
                    if first.is_none_or(|(t, _)| tz < t) {
                        first = Some((tz, c));
                    }
                    break;
                }
                a = (tk, ak);
            }
        }
        Ok(first)
    }

    /// At a step end: resting spheres that drifted off their planes are put back (returns
    /// whether any was); a resting contact with friction whose contact point slips is an error.
    ///
    /// # Errors
    /// A slipping resting contact with friction > 0 (see the module doc of `contacts`).
    pub(crate) fn hold_resting(&self, t: f64, y: &mut [f64], contacts: &Contacts) -> Result<bool, String> {
        let mut moved = false;
        for c in (0..contacts.resting.len()).filter(|&c| contacts.resting[c]) {
            if let Some(s) = self.stop(c) {
                // a held stop drifts by the integration error of q̈ = 0: put it back
                let nq = self.built.model.nq();
                let g = super::contacts::stop_gap(y[s.qi], y[nq + s.vi], s.lower, s.upper);
                let a = self.free_normal_accel(t, y, &contacts.resting, c)?;
                let tol = HOLD_TOL_EPS * f64::EPSILON;
                if g.gap.abs() > tol * g.size || g.opening.abs() > tol * ((a.abs() * g.size).sqrt() + 1.0) {
                    self.place_on_plane(y, c, g.gap, g.opening);
                    moved = true;
                }
                continue;
            }
            let Some(p) = self.plane(c) else { continue };
            let b = &self.built;
            let nq = b.model.nq();
            let kin = kinematics(&b.model, &y[..nq], &y[nq..])?;
            let (x_c, v_c) = kin.point(&(Some(p.body), b.bodies[p.body].com));
            let gap = self.contact_gaps(&kin, y)[c].gap;
            let u_n = v_c.dot(&p.n);
            let a_n = self.free_normal_accel(t, y, &contacts.resting, c)?;
            // speeds are measured against √(|aₙ| r) and the speeds present
            let scale = (a_n.abs() * p.r).sqrt() + v_c.norm() + kin.omega[p.body].norm() * p.r;
            if p.mu > 0.0 {
                // the contact point's velocity v_c + ω × (−r n), without its normal part
                let v_p = v_c + kin.omega[p.body].cross(&(p.n * -p.r));
                let slip = (v_p - p.n * v_p.dot(&p.n)).norm();
                if slip > SLIP_TOL_REL * scale {
                    return Err(format!(
                        "the resting contact of effects[{}] slips at {slip:e} m/s at t = {t:e} s with friction \
                         {}; sliding, sticking and rolling friction in resting contact are not simulated; valid: \
                         friction = 0 (frictionless resting contact), or a `rolling` effect",
                        self.contacts[c], p.mu
                    ));
                }
            }
            let tol = HOLD_TOL_EPS * f64::EPSILON;
            if gap.abs() > tol * (p.r + x_c.norm()) || u_n.abs() > tol * scale {
                self.place_on_plane(y, c, gap, u_n);
                moved = true;
            }
        }
        Ok(moved)
    }
}
