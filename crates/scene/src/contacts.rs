//! Contacts during a run: touch events that are never stepped over, and resting contact once
//! bounces accumulate.
//!
//! **Touch events.** A contact is *armed* once its gap exceeds half its resolution (8 ulps of
//! the lengths it is computed from), or is positive and closing. On every accepted step the
//! gaps of the armed contacts are followed along the step's interpolant: the step is cut into
//! [`SCAN_SEGMENTS`] pieces, and a piece [a, b] is split until it is provably clear or short.
//! The gap is 1-Lipschitz in the position it follows (the normal part of the centre of a sphere
//! on a plane, the separation x_a − x_b of two spheres), so on a piece whose path length is ℓ the gap stays
//! above (g_a + g_b − ℓ)/2: the piece is clear when g_a + g_b > ℓ, with ℓ estimated as the larger
//! of twice the chord and 1.5 × the largest speed × the piece's duration. A contact that starts
//! a step touching and opening (just after its impact, placed on its surface to a rounding
//! either side) is armed at its first gap above half its resolution, found by probes at
//! t₀ + h/2ᵏ, so the flight after a bounce is followed like any other: this
//! is what let a ball fall through the floor after its first bounce before. The first closing piece is bracketed
//! to a few ulps of t (Illinois secant, [`bracket_zero`]).
//!
//! **Resting contact.** After an impact on a plane, when the rebound would fly for less than
//! [`REST_TIME_REL`] × the duration, or rise less than the resolution of the gap (8 ulps of the
//! lengths it is computed from: a flight no scan could see), the contact switches to *resting*
//! (bounces accumulating at the Zeno point t∞ = t₀(1 + e)/(1 − e) of a bouncing ball end there): the normal
//! speed is set to zero, and the plane pushes with the normal force N = max(0, −m aₙ) through
//! the centre, aₙ being the centre's normal acceleration without it, so the sphere stays on the
//! plane and slides along it. Lift-off is a located event: the first zero of aₙ on the
//! interpolant where the plane would have to pull. Friction acts in impacts only; a resting
//! contact with friction > 0 whose contact point slips (sliding, sticking and rolling friction
//! are not simulated) ends the run with an error rather than a frictionless answer, as do two
//! spheres whose bounces accumulate.
//!
//! Book: §7.13 (impacts, restitution (7.13.18)), §7.14; (Fact 7.13.1).

use nalgebra::Vector3;
use serde::Serialize;
use vectrix_ode::explicit::{DenseStep, bracket_zero};

use super::Scene;
use super::kin::{Kin, kinematics};
use super::parts::Effect;

/// Ulps of the lengths a plane contact's gap is computed from that make its resolution: a
/// rebound lower than that is a flight no scan could see, so the contact rests instead.
pub(crate) const GAP_ULPS: f64 = 8.0;
/// A contact within this fraction of its size (radius, sum of radii, a stop's scale) touches:
/// for the impacts at a located instant (placing a sphere on a tilted plane can leave its
/// gap a rounding above zero) and for the switch to resting after an impact.
pub(crate) const TOUCH_REL: f64 = 1e-9;
/// Segments every step is first cut into when its contacts are scanned.
pub(crate) const SCAN_SEGMENTS: usize = 4;
/// Most points at which one step's contact gaps are evaluated.
pub(crate) const MAX_CONTACT_SCAN: usize = 4096;
/// A rebound that would fly for less than this fraction of the run's duration comes to rest
/// (the contact switches to resting): bounces accumulating at the Zeno point end there, with
/// the remaining bounces' heights below g (REST_TIME_REL · duration)²/8.
pub const REST_TIME_REL: f64 = 1e-9;
/// Most contact events a run records (impacts beyond it are still counted in its work).
pub const MAX_CONTACT_EVENTS: usize = 100_000;

/// One declared contact's geometry at one state.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Gap {
    /// Sphere–sphere |x_a − x_b| − r_a − r_b, sphere–plane (x − p)·n − r; negative when
    /// penetrating.
    pub gap: f64,
    /// The position the gap follows (x_a − x_b, or the normal part (x·n) n of x): the gap is
    /// 1-Lipschitz in it.
    pub pos: Vector3<f64>,
    /// Its rate.
    pub rate: Vector3<f64>,
    /// The gap's rate ġ (positive: opening).
    pub opening: f64,
    /// The contact's size (r_a + r_b, or r).
    pub size: f64,
    /// The gap's resolution: [`GAP_ULPS`] ulps of the lengths it is computed from (the
    /// centres' and the plane point's distances from the origin and the size).
    pub resolution: f64,
}

impl Gap {
    /// Touching: the gap at most [`TOUCH_REL`] × the contact's size (a located touch leaves it a
    /// rounding either side of zero).
    pub(crate) fn touches(&self) -> bool {
        self.gap <= TOUCH_REL * self.size
    }
}

/// +1 when the nearer stop is the lower one (the gap opens with q̇ > 0), −1 for the upper.
pub(crate) fn side(q: f64, lower: f64, upper: f64) -> f64 {
    if q - lower <= upper - q { 1.0 } else { -1.0 }
}

/// The gap of a stop at (q, q̇): min(q − lower, upper − q), following q itself.
pub(crate) fn stop_gap(q: f64, v: f64, lower: f64, upper: f64) -> Gap {
    let finite = |x: f64| if x.is_finite() { x.abs() } else { 0.0 };
    // the scale of the tolerances: 1 rad (or m), or the stops' own size
    let size = 1.0_f64.max(finite(lower)).max(finite(upper));
    Gap {
        gap: (q - lower).min(upper - q),
        pos: Vector3::new(q, 0.0, 0.0),
        rate: Vector3::new(v, 0.0, 0.0),
        opening: side(q, lower, upper) * v,
        size,
        resolution: GAP_ULPS * f64::EPSILON * size,
    }
}

/// What happened at a contact.
///
/// Book: §7.13.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactEventKind {
    /// An impact (restitution and friction impulses).
    Impact,
    /// Bounces accumulated: the contact rests from here (normal speed set to zero).
    Rest,
    /// A resting contact lets go (the plane would have to pull).
    LiftOff,
}

/// One contact event of a run.
///
/// Book: §7.13.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactEvent {
    /// When [s].
    pub t: f64,
    /// Which contact: its index in the scene's `effects`.
    pub effect: usize,
    /// What happened.
    pub kind: ContactEventKind,
    /// The normal speed of approach before it (positive: closing) [m/s].
    pub closing_speed: f64,
    /// The normal speed of separation after it (positive: opening) [m/s].
    pub opening_speed: f64,
}

/// The state of the contacts through a run: which rest, and the events so far.
#[derive(Debug, Clone, Default)]
pub(crate) struct Contacts {
    /// Per contact (declaration order among the contact effects, `Scene::contacts` gives each
    /// one's effect index): resting?
    pub resting: Vec<bool>,
    pub events: Vec<ContactEvent>,
}

impl Contacts {
    pub fn record(&mut self, e: ContactEvent) {
        if self.events.len() < MAX_CONTACT_EVENTS {
            self.events.push(e);
        }
    }
}

impl Scene {
    /// The contact effects' indices in `effects`, in declaration order.
    pub(crate) fn contact_effects(&self) -> Vec<usize> {
        let b = &self.built;
        (0..b.effects.len())
            .filter(|&k| {
                matches!(
                    b.effects[k],
                    Effect::Spheres { .. } | Effect::Plane { .. } | Effect::JointStop { .. }
                )
            })
            .collect()
    }

    /// Every declared contact's gap in declaration order (see [`Gap`]); `kin` is at the state y.
    pub(crate) fn contact_gaps(&self, kin: &Kin, y: &[f64]) -> Vec<Gap> {
        let c = |i: usize| kin.point(&(Some(i), self.built.bodies[i].com));
        self.built
            .effects
            .iter()
            .filter_map(|e| match e {
                Effect::Spheres { a, b, ra, rb, .. } => {
                    let ((xa, va), (xb, vb)) = (c(*a), c(*b));
                    let (d, u) = (xa - xb, va - vb);
                    let opening = u.dot(&d) / d.norm().max(f64::MIN_POSITIVE);
                    let resolution = GAP_ULPS * f64::EPSILON * (xa.norm() + xb.norm() + ra + rb);
                    Some(Gap { gap: d.norm() - ra - rb, pos: d, rate: u, opening, size: ra + rb, resolution })
                }
                Effect::Plane { body, r, point, n, .. } => {
                    // the gap follows the centre's normal part alone: sliding along the plane
                    // does not make its path long
                    let (x, v) = c(*body);
                    let (gap, opening) = ((x - point).dot(n) - r, v.dot(n));
                    let resolution = GAP_ULPS * f64::EPSILON * (x.norm() + point.norm() + r);
                    Some(Gap { gap, pos: n * x.dot(n), rate: n * opening, opening, size: *r, resolution })
                }
                Effect::JointStop { qi, vi, lower, upper, .. } => {
                    Some(stop_gap(y[*qi], y[self.built.model.nq() + vi], *lower, *upper))
                }
                _ => None,
            })
            .collect()
    }

    /// The contacts' gaps at state y.
    pub(crate) fn gaps(&self, y: &[f64]) -> Result<Vec<Gap>, String> {
        let b = &self.built;
        let nq = b.model.nq();
        let kin = kinematics(&b.model, &y[..nq], &y[nq..])?;
        Ok(self.contact_gaps(&kin, y))
    }

    /// The first instant in (t₀, t₁] at which a contact in flight closes on the step's
    /// interpolant, found as the module doc describes; `floor` is the shortest piece split.
    ///
    /// # Errors
    /// When the kinematics fail, a gap is NaN, or the scan needs more than
    /// [`MAX_CONTACT_SCAN`] points (a contact grazing for a whole step).
    pub(crate) fn first_touch(
        &self,
        dense: &DenseStep<Vec<f64>>,
        (t0, g0): (f64, &[Gap]),
        (t1, g1): (f64, &[Gap]),
        flight: &[bool],
        floor: f64,
    ) -> Result<Option<f64>, String> {
        let gaps_at = |t: f64| self.gaps(&dense.eval(t));
        // a contact within half its gap's resolution of touching is not armed unless it
        // closes: just after its impact (or lift-off) it may sit a rounding above its surface,
        // and the next rounding below would be a touch that is not one
        let arms = |g: &Gap| g.gap > 0.5 * g.resolution;
        let mut armed: Vec<bool> = g0.iter().map(|g| arms(g) || (g.gap > 0.0 && g.opening < 0.0)).collect();
        let mut left = (t0, g0.to_vec());
        // the step's pieces; a contact that starts touching and opening (just after its
        // impact) arms at its first gap above half its resolution: probes at t₀ + h/2ᵏ down to
        // `floor` find it within any flight the resting threshold lets through (longer than
        // 4 floor, higher than the gap's resolution: a probe in the flight's second quarter
        // sees ¾ of its height), before it can land again
        let h = t1 - t0;
        let mut ts: Vec<f64> =
            (1..SCAN_SEGMENTS).map(|k| t0 + h * (k as f64 / SCAN_SEGMENTS as f64)).collect();
        if g0.iter().zip(flight).any(|(g, f)| *f && !arms(g) && g.opening > 0.0) {
            let mut dt = 0.5 * h / SCAN_SEGMENTS as f64;
            while dt >= floor && t0 + dt > t0 {
                ts.push(t0 + dt);
                dt *= 0.5;
            }
        }
        ts.sort_by(|a, b| b.total_cmp(a));
        ts.dedup();
        // right ends still to visit, the nearest last
        let mut pending: Vec<(f64, Option<Vec<Gap>>)> = vec![(t1, Some(g1.to_vec()))];
        pending.extend(ts.into_iter().map(|t| (t, None)));
        let mut points = 0;
        while let Some((tb, known)) = pending.pop() {
            let gb = match known {
                Some(g) => g,
                None => {
                    points += 1;
                    if points > MAX_CONTACT_SCAN {
                        return Err(format!(
                            "a contact grazes its surface for the whole step [{t0:e}, {t1:e}] s: more than \
                             {MAX_CONTACT_SCAN} points were needed to follow its gap; valid: a contact that \
                             either touches or separates"
                        ));
                    }
                    gaps_at(tb)?
                }
            };
            let ta = left.0;
            let (mut split, mut hits) = (false, Vec::new());
            for (c, (a, b)) in left.1.iter().zip(&gb).enumerate() {
                if !flight[c] {
                    continue;
                }
                if a.gap.is_nan() || b.gap.is_nan() {
                    return Err(format!("the gap of a contact is not a number at t = {tb:e} s"));
                }
                // ℓ: the path length of the gap's position over [ta, tb], estimated
                let path =
                    (2.0 * (b.pos - a.pos).norm()).max(1.5 * a.rate.norm().max(b.rate.norm()) * (tb - ta));
                let long = tb - ta > floor;
                // (a contact not armed touches, and arms where its gap opens)
                if armed[c] {
                    if b.gap <= 0.0 {
                        hits.push(c);
                    } else if a.gap + b.gap <= path && long {
                        split = true; // the gap may dip below zero inside
                    }
                }
            }
            let tm = 0.5 * (ta + tb);
            if split && tm > ta && tm < tb {
                pending.push((tb, Some(gb)));
                pending.push((tm, None));
                continue;
            }
            if !hits.is_empty() {
                let mut te = f64::INFINITY;
                for c in hits {
                    let g = |t: f64| gaps_at(t).map_or(-1.0, |g| g[c].gap);
                    let (_, tz) = bracket_zero(g, (ta, left.1[c].gap), (tb, gb[c].gap));
                    te = te.min(tz);
                }
                return Ok(Some(te));
            }
            for (c, g) in gb.iter().enumerate() {
                armed[c] |= arms(g);
            }
            left = (tb, gb);
        }
        Ok(None)
    }

    /// The first contact event of an accepted step [t₀, t₁]: a contact in flight that closes
    /// ([`Scene::first_touch`]) or a resting contact that lets go, whichever comes first.
    /// Without one, no contact in flight may end the step penetrating: that would be a touch
    /// the scan missed, and the run fails rather than pass through.
    ///
    /// # Errors
    /// As [`Scene::first_touch`], and for a missed touch.
    pub(crate) fn next_contact_event(
        &self,
        dense: &DenseStep<Vec<f64>>,
        (t0, g0): (f64, &[Gap]),
        (t1, g1): (f64, &[Gap]),
        y1: &[f64],
        contacts: &Contacts,
        tau_min: f64,
    ) -> Result<Option<NextContact>, String> {
        let flight: Vec<bool> = contacts.resting.iter().map(|r| !r).collect();
        let touch = self.first_touch(dense, (t0, g0), (t1, g1), &flight, tau_min / 4.0)?;
        let lift = if contacts.resting.contains(&true) {
            self.first_lift_off(dense, (t0, t1), y1, &contacts.resting)?
        } else {
            None
        };
        Ok(match (touch, lift) {
            (Some(t), Some((tl, c))) if tl < t => Some(NextContact::LiftOff(tl, c)),
            (Some(t), _) => Some(NextContact::Touch(t)),
            (None, Some((tl, c))) => Some(NextContact::LiftOff(tl, c)),
            (None, None) => {
                for (c, g) in g1.iter().enumerate() {
                    if flight[c] && g.gap < -1e-9 * g.size {
                        return Err(format!(
                            "the contact of effects[{}] ends a step at t = {t1:e} s penetrating by {:e} m without \
                             a located touch",
                            self.contacts[c], -g.gap
                        ));
                    }
                }
                None
            }
        })
    }

    /// Resolves the impacts at `t` into y's velocities and records them; returns how many.
    pub(crate) fn impact_at(
        &self,
        t: f64,
        y: &mut [f64],
        contacts: &mut Contacts,
        work: &mut super::RunWork,
    ) -> Result<usize, String> {
        let b = &self.built;
        let nq = b.model.nq();
        // the located instant leaves a sphere up to a few ulps inside its plane: it is put on
        // the plane, so that no bounce loses (or gains) the energy of that rounding
        for (c, g) in self.gaps(y)?.iter().enumerate() {
            if !contacts.resting[c] && g.gap < 0.0 && g.gap > -TOUCH_REL * g.size {
                self.place_on_plane(y, c, g.gap, 0.0);
            }
        }
        let kin = kinematics(&b.model, &y[..nq], &y[nq..])?;
        let gaps = self.contact_gaps(&kin, y);
        let (q, v) = y.split_at_mut(nq);
        let mut hits = self.impacts(&kin, &gaps, v, &contacts.resting);
        hits.extend(self.stop_impacts(q, v, &contacts.resting)?);
        for &(c, closing_speed, opening_speed) in &hits {
            let (effect, kind) = (self.contacts[c], ContactEventKind::Impact);
            contacts.record(ContactEvent { t, effect, kind, closing_speed, opening_speed });
        }
        work.impacts += hits.len();
        Ok(hits.len())
    }
}

/// The next contact event of a step.
#[derive(Debug, Clone, Copy)]
pub(crate) enum NextContact {
    /// A contact in flight closes at t.
    Touch(f64),
    /// Resting contact c lets go at t.
    LiftOff(f64, usize),
}

impl NextContact {
    pub fn t(&self) -> f64 {
        match self {
            Self::Touch(t) | Self::LiftOff(t, _) => *t,
        }
    }
}
