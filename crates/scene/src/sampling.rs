//! What a run keeps at its samples besides the rows: the checked invariants with their drift,
//! the largest state component, and the verdict on whether a finished run can be trusted.
//!
//! Book: §8.3 (energy), §7.4/§7.6 (momenta).

use std::time::Instant;

use nalgebra::Vector3;

use super::kin::{Kin, kinematics};
use super::outcome::{Drift, InvariantValue, Run, Stop, StopReason};
use super::project::ProjectScratch;
use super::{Invariant, Scene, SceneError};

/// Largest relative drift (`Drift::max_rel`) of a checked invariant that a complete run may
/// have: beyond it the numbers no longer conserve what the declared effects conserve, and
/// the run is marked incomplete ([`StopReason::InvariantDrift`]).
pub const MAX_TRUSTED_DRIFT: f64 = 1e-3;
/// Largest magnitude of a state component (q or v, SI) that a complete run may reach: about
/// √f64::MAX, beyond which squared speeds and lengths (T = ½ m v², |r|²) overflow and an
/// angle has no digit left below a turn ([`StopReason::StateOutOfRange`]).
pub const MAX_TRUSTED_STATE: f64 = 1e154;

/// Tracked invariant values at the samples.
pub(crate) struct Tracker {
    pub inv: Invariant,
    pub x0: Option<Vector3<f64>>,
    pub last: Vector3<f64>,
    pub scale: f64,
    pub max: f64,
}

impl Tracker {
    fn value(&self, x: Vector3<f64>) -> InvariantValue {
        match self.inv {
            Invariant::Energy | Invariant::AngularMomentumAlong { .. } => InvariantValue::Scalar(x[0]),
            _ => InvariantValue::Vector(x.into()),
        }
    }
}

/// What the samples keep besides the rows: the checked invariants, the largest |y_i| with its
/// time and index, and the projection's work space.
pub(crate) struct Sampler {
    pub trackers: Vec<Tracker>,
    pub peak: (f64, f64, usize),
    pub projection: ProjectScratch,
}

impl Scene {
    fn invariant_value(&self, inv: &Invariant, kin: &Kin, q: &[f64], v: &[f64]) -> Vector3<f64> {
        match inv {
            Invariant::Energy => Vector3::new(self.energy(kin, q, v), 0.0, 0.0),
            Invariant::Momentum => self.momentum(kin),
            Invariant::AngularMomentum { about } => self.angular_momentum(kin, &Vector3::from(*about)),
            Invariant::AngularMomentumAlong { about, axis } => {
                let h = self.angular_momentum(kin, &Vector3::from(*about));
                Vector3::new(h.dot(&Vector3::from(*axis)), 0.0, 0.0)
            }
        }
    }

    /// The outputs and invariants at a sample (t, y) into `run` and `s`: the state normalized
    /// (and, with constraints, projected: a sample between step ends comes from the
    /// interpolant), then the row of the declared outputs.
    pub(crate) fn record(&self, s: &mut Sampler, run: &mut Run, t: f64, y: &[f64]) -> Result<(), SceneError> {
        let b = &self.built;
        let nq = b.model.nq();
        let fail = |e: String| SceneError::Run { t, message: e };
        let mut y = y.to_vec();
        b.model.normalize_quaternions(&mut y[..nq]);
        if let Some((i, x)) = y.iter().map(|x| x.abs()).enumerate().max_by(|a, b| a.1.total_cmp(&b.1))
            && x > s.peak.0
        {
            s.peak = (x, t, i);
        }
        if self.has_constraints() {
            let (_, after) = self.project(&mut y, &mut s.projection).map_err(fail)?;
            run.max_constraint_violation = Some(run.max_constraint_violation.unwrap_or_default().max(after));
        }
        let lambda =
            if self.needs_multipliers() { Some(self.multipliers(t, &y).map_err(fail)?) } else { None };
        let (q, v) = y.split_at(nq);
        let kin = kinematics(&b.model, q, v).map_err(fail)?;
        let mut row = Vec::with_capacity(run.columns.len());
        self.row(&kin, q, v, lambda.as_ref(), &mut row);
        run.t.push(t);
        run.rows.push(row);
        for tr in &mut s.trackers {
            let x = self.invariant_value(&tr.inv, &kin, q, v);
            // the size of the invariant's terms over the run (at t = 0 alone a pendulum
            // released from rest has no kinetic term to measure a drift against)
            tr.scale = tr.scale.max(self.invariant_scale(&tr.inv, &kin, v));
            let x0 = *tr.x0.get_or_insert(x);
            tr.last = x;
            tr.max = tr.max.max((x - x0).norm());
        }
        Ok(())
    }

    /// The drift of the checked invariants, the final state and the wall time; a run that
    /// reached its duration with numbers outside their meaningful range is marked incomplete
    /// (`peak`: the largest |y_i| at the samples, its time and index).
    pub(crate) fn finish(
        &self,
        mut run: Run,
        trackers: Vec<Tracker>,
        mut y: Vec<f64>,
        start: Instant,
        peak: (f64, f64, usize),
    ) -> Run {
        run.drift = trackers
            .into_iter()
            .map(|tr| {
                let x0 = tr.x0.unwrap_or_default();
                Drift {
                    initial: tr.value(x0),
                    last: tr.value(tr.last),
                    max_abs: tr.max,
                    scale: x0.norm().max(tr.scale),
                    max_rel: tr.max / x0.norm().max(tr.scale).max(f64::MIN_POSITIVE),
                    invariant: tr.inv,
                }
            })
            .collect();
        if run.stop.is_none() {
            run.stop = self.untrusted(&run, peak);
        }
        self.built.model.normalize_quaternions(&mut y[..self.built.model.nq()]);
        run.final_state = y;
        run.work.wall_seconds = start.elapsed().as_secs_f64();
        run
    }

    /// Why a run that reached its duration cannot be trusted, if it cannot: a state component
    /// above [`MAX_TRUSTED_STATE`] (`peak`: its magnitude, time and index in y = (q, v)), or a
    /// checked invariant (conserved by the declared effects) whose relative drift reached
    /// [`MAX_TRUSTED_DRIFT`] or is not finite.
    fn untrusted(&self, run: &Run, (x, t, i): (f64, f64, usize)) -> Option<Stop> {
        let t_end = run.t.last().copied().unwrap_or(0.0);
        if x > MAX_TRUSTED_STATE || x.is_nan() {
            let nq = self.built.model.nq();
            let which = if i < nq { format!("q[{i}]") } else { format!("v[{}]", i - nq) };
            return Some(Stop {
                reason: StopReason::StateOutOfRange,
                t,
                message: format!(
                    "the state component {which} reached {x:e} at t = {t} s, beyond {MAX_TRUSTED_STATE:e} (about \
                     √ of the largest f64), where energies and squared lengths overflow and angles have no digits \
                     left; valid: an initial state and motion well inside ±{MAX_TRUSTED_STATE:e} (SI)"
                ),
            });
        }
        let d = run.drift.iter().find(|d| d.max_rel >= MAX_TRUSTED_DRIFT || d.max_rel.is_nan())?;
        Some(Stop {
            reason: StopReason::InvariantDrift,
            t: t_end,
            message: format!(
                "{} drifted by {:.2e} relative to its scale over the run, not below {MAX_TRUSTED_DRIFT:e}, although \
                 the declared effects conserve it: the numbers do not mean what they say; valid: a tighter \
                 accuracy, a shorter duration, or an initial state whose terms f64 can resolve",
                d.invariant.name(),
                d.max_rel
            ),
        })
    }
}
