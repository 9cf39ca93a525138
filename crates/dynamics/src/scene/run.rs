//! Running a scene: adaptive integration between output samples (the method from the declared
//! accuracy through `vectrix_ode::Accuracy`, or named), impacts between steps, the requested
//! outputs at every sample and the drift of the checked invariants.
//!
//! Book: §4.11 (integration), §8.3 (energy), §7.4/§7.6 (momenta).

use std::cell::RefCell;
use std::time::{Duration, Instant};

use nalgebra::Vector3;
use serde::Serialize;
use vectrix_ode::Accuracy;
use vectrix_ode::explicit::Adaptive;

use super::build::Src;
use super::kin::{kinematics, normalize};
use super::spec::SceneSpec;
use super::{Invariant, Scene, SceneError};

/// Substeps per sample while a contact may close.
const CONTACT_SUBSTEPS: usize = 50;

/// The solver a scene asks for: `method`, else `accuracy`, else `Accuracy::RelTol(1e-6)`.
pub(crate) fn solver(spec: &SceneSpec, src: &Src) -> Result<Adaptive, SceneError> {
    if let Some(m) = &spec.method {
        if m.rtol.is_nan() || m.rtol <= 0.0 {
            return Err(src.err("rtol", "method.rtol", format!("rtol = {}; valid: > 0", m.rtol)));
        }
        let a = match m.name.as_str() {
            "dopri5" => Adaptive::dopri5(),
            "dop853" => Adaptive::dop853(),
            n => {
                return Err(src.err(
                    n,
                    "method.name",
                    format!("unknown method `{n}`; valid: dopri5, dop853"),
                ));
            }
        };
        return Ok(a.rtol(m.rtol).atol(m.rtol));
    }
    let tol = spec.accuracy.unwrap_or(1e-6);
    Accuracy::RelTol(tol).solver().map_err(|e| src.err("accuracy", "accuracy", e.to_string()))
}

/// Drift of one checked invariant over the run.
///
/// Book: §8.3, §7.4, §7.6.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Drift {
    /// The invariant.
    pub invariant: Invariant,
    /// Its initial value (the norm for vectors).
    pub initial: f64,
    /// max |x(t) − x(0)| (vector norm for vectors).
    pub max_abs: f64,
    /// max_abs / scale, scale = max(|x(0)|, the sum of the magnitudes of its terms at t = 0)
    /// (T for energy, Σ m|v_c| for momentum, Σ |r × m v| + |J ω| for H), so that an
    /// invariant whose value is zero still gets a meaningful relative drift.
    pub max_rel: f64,
}

/// What the run cost.
///
/// Book: §4.11.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct RunWork {
    /// Right-hand side evaluations.
    pub fevals: usize,
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Impacts resolved.
    pub impacts: usize,
    /// Wall time [s].
    pub wall_seconds: f64,
}

/// The result of a run: sampled outputs, invariant drift, work.
///
/// Book: §4.11, §8.3.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Run {
    /// Scene name.
    pub scene: String,
    /// Column names (after `t`).
    pub columns: Vec<String>,
    /// Sample times.
    pub t: Vec<f64>,
    /// One row of column values per sample.
    pub rows: Vec<Vec<f64>>,
    /// Invariants implied by the declared effects.
    pub invariants: Vec<Invariant>,
    /// Drift of the checked ones.
    pub drift: Vec<Drift>,
    /// Cost.
    pub work: RunWork,
    /// Final state y = (q, v).
    pub final_state: Vec<f64>,
}

impl Run {
    /// The samples of one column.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let k = self.columns.iter().position(|c| c == name)?;
        Some(self.rows.iter().map(|r| r[k]).collect())
    }

    /// trajectory.csv: header `t,<columns>`, one line per sample.
    pub fn to_csv(&self) -> String {
        let mut s = format!("t,{}\n", self.columns.join(","));
        for (t, r) in self.t.iter().zip(&self.rows) {
            s.push_str(&format!("{t:e}"));
            for x in r {
                s.push_str(&format!(",{x:e}"));
            }
            s.push('\n');
        }
        s
    }
}

/// Tracked invariant values: energy (scalar) or vectors.
struct Tracker {
    inv: Invariant,
    x0: Option<Vector3<f64>>,
    scale: f64,
    max: f64,
}

impl Scene {
    fn invariant_value(&self, inv: &Invariant, kin: &super::kin::Kin, q: &[f64], v: &[f64]) -> Vector3<f64> {
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

    /// Runs the scene; `progress` is called with the fraction done after every sample.
    ///
    /// Book: §4.11, §7.11, §7.13.
    ///
    /// # Errors
    /// [`SceneError::Run`] when the integrator or the dynamics fail.
    pub fn run(&self, progress: &mut dyn FnMut(f64)) -> Result<Run, SceneError> {
        let start = Instant::now();
        let b = &self.built;
        let nq = b.model.nq();
        let spec = self.spec();
        let mut trackers: Vec<Tracker> = self
            .invariants()
            .iter()
            .filter(|i| spec.checks.iter().any(|c| c == i.name()))
            .map(|i| Tracker { inv: i.clone(), x0: None, scale: 0.0, max: 0.0 })
            .collect();
        let want_kin = !self.outputs.is_empty() || !trackers.is_empty() || self.needs.impacts;
        let mut y = self.initial_state();
        let mut run = Run {
            scene: spec.name.clone(),
            columns: self.columns(),
            t: Vec::with_capacity(spec.samples + 1),
            rows: Vec::with_capacity(spec.samples + 1),
            invariants: self.invariants().to_vec(),
            drift: Vec::new(),
            work: RunWork::default(),
            final_state: Vec::new(),
        };
        let dt = spec.duration / spec.samples as f64;
        let failure: RefCell<Option<String>> = RefCell::new(None);
        let f = |t: f64, y: &Vec<f64>| match self.deriv(t, y) {
            Ok(d) => d,
            Err(e) => {
                failure.borrow_mut().get_or_insert(e);
                vec![f64::NAN; y.len()]
            }
        };
        let mut solver = self.solver;
        let fail = |t: f64, e: String| SceneError::Run { t, message: e };
        for k in 0..=spec.samples {
            let t = k as f64 * dt;
            if k > 0 {
                let t0 = (k - 1) as f64 * dt;
                let near = if self.needs.impacts {
                    let kin = kinematics(&b.model, &b.bodies, &self.order, &y[..nq], &y[nq..])
                        .map_err(|e| fail(t0, e))?;
                    self.contact_near(&kin, dt)
                } else {
                    false
                };
                let sub = if near { CONTACT_SUBSTEPS } else { 1 };
                for s in 0..sub {
                    let (ta, tb) = (t0 + dt * s as f64 / sub as f64, t0 + dt * (s + 1) as f64 / sub as f64);
                    let sol = solver.solve(f, ta, &y, tb).map_err(|e| {
                        fail(ta, failure.borrow_mut().take().unwrap_or_else(|| e.to_string()))
                    })?;
                    if sol.t.len() >= 2 {
                        solver.h0 = Some(sol.t[sol.t.len() - 1] - sol.t[sol.t.len() - 2]);
                    }
                    run.work.fevals += sol.work.fevals;
                    run.work.accepted += sol.work.accepted;
                    run.work.rejected += sol.work.rejected;
                    y = sol.last().clone();
                    normalize(&b.bodies, &mut y[..nq]);
                    if self.needs.impacts {
                        let (q, v) = y.split_at_mut(nq);
                        let kin =
                            kinematics(&b.model, &b.bodies, &self.order, q, v).map_err(|e| fail(tb, e))?;
                        run.work.impacts += self.impacts(&kin, v);
                    }
                }
            }
            if want_kin {
                let (q, v) = y.split_at(nq);
                let kin = kinematics(&b.model, &b.bodies, &self.order, q, v).map_err(|e| fail(t, e))?;
                let mut row = Vec::new();
                self.row(&kin, q, v, &mut row);
                run.t.push(t);
                run.rows.push(row);
                for tr in &mut trackers {
                    let x = self.invariant_value(&tr.inv, &kin, q, v);
                    if tr.x0.is_none() {
                        tr.scale = self.invariant_scale(&tr.inv, &kin, v);
                    }
                    let x0 = *tr.x0.get_or_insert(x);
                    tr.max = tr.max.max((x - x0).norm());
                }
            }
            progress(k as f64 / spec.samples as f64);
        }
        run.drift = trackers
            .into_iter()
            .map(|tr| {
                let initial = tr.x0.map_or(0.0, |x| x.norm());
                Drift {
                    invariant: tr.inv,
                    initial,
                    max_abs: tr.max,
                    max_rel: tr.max / initial.max(tr.scale).max(f64::MIN_POSITIVE),
                }
            })
            .collect();
        run.final_state = y;
        run.work.wall_seconds = Duration::as_secs_f64(&start.elapsed());
        Ok(run)
    }
}
