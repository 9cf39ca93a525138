//! Gragg–Bulirsch–Stoer extrapolation of the explicit midpoint rule with order and step-size
//! control (Hairer's ODEX, without dense output): for smooth problems at tight tolerances it
//! reaches a given error with fewer evaluations than an 8th-order pair, because its order
//! rises with the tolerance. The midpoint rule and the table work on the increments y − y₀ of
//! the step (their rounding is relative to |h f|, not to |y|), which lowers the round-off floor
//! of long runs: Kepler e = 0.9 over 20 time units reaches 5·10⁻¹³ instead of 1.5·10⁻¹¹.
//!
//! Book: §4.11 (the rate equations are integrated numerically); HNW §II.9 (extrapolation
//! methods: Gragg's midpoint rule with its smoothing step, Aitken–Neville extrapolation in h²,
//! order and step-size control) and Hairer's `odex.f`, whose constants and control this follows.

use std::time::Instant;

use super::drive::Solution;
use super::gbs_lanes::{Lanes, offset};
use super::initial_step;
use crate::solver::Solver;
use crate::state::{State, check_state, eval, eval_into};
use crate::{OdeError, Rhs, Work};

pub use super::gbs_lanes::GBS_MAX_COLUMNS;

/// The Gragg–Bulirsch–Stoer method: at most `max_columns` rows of the extrapolation table
/// over the harmonic step sequence nⱼ = 2, 4, 6, 8, … (HNW §II.9, Deuflhard's choice), so an
/// accepted row j has order 2j. Default `max_columns` = 9 (ODEX's KM), valid 3 ..= 12.
///
/// Book: §4.11; HNW §II.9.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Gbs {
    /// Rows of the extrapolation table (KM), 3 ..= [`GBS_MAX_COLUMNS`].
    pub max_columns: usize,
}

/// An extrapolation solver: [`Gbs`] with its tolerances and limits ([`Solver`]), built with
/// [`Extrapolation::gbs`] and the setters; defaults rtol = 1e-6, atol = 1e-9. The local error
/// estimate T_jj − T_j,j−1 of the accepted row is kept at ‖err/sk‖ ≤ 1 with
/// sk = atol + rtol·max(|y₀|, |y₁|) per component (HNW (4.10)), and the result is T_jj (local
/// extrapolation). No dense output and no events: `.dense(true)` is refused.
///
/// ```
/// use nalgebra::Vector2;
/// use vectrix_ode::Extrapolation;
/// // ẍ = −x from x = 1 at rest, to t = 10: x = cos 10
/// let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], -y[0]);
/// let sol = Extrapolation::gbs().rtol(1e-12).atol(1e-12).solve(f, 0.0, &Vector2::new(1.0, 0.0), 10.0)?;
/// assert!((sol.last()[0] - 10f64.cos()).abs() < 1e-10);
/// # Ok::<(), vectrix_ode::OdeError>(())
/// ```
///
/// Book: §4.11; HNW §II.9.
pub type Extrapolation = Solver<Gbs>;

impl Solver<Gbs> {
    /// Gragg–Bulirsch–Stoer extrapolation with 9 columns (HNW §II.9, ODEX).
    pub const fn gbs() -> Self {
        Self::with_method(Gbs { max_columns: 9 })
    }

    /// At most `k` rows of the extrapolation table (checked by [`Extrapolation::solve`]:
    /// 3 ..= [`GBS_MAX_COLUMNS`]).
    pub fn max_columns(mut self, k: usize) -> Self {
        self.method.max_columns = k;
        self
    }

    /// The interval, tolerances and step bounds ([`Solver::check`]) and `max_columns`: the step
    /// bound h_max.
    pub(super) fn check_gbs(&self, t0: f64, t1: f64) -> Result<f64, OdeError> {
        let h_max = self.check(t0, t1)?;
        let km = self.method.max_columns;
        if !(3..=GBS_MAX_COLUMNS).contains(&km) {
            return Err(OdeError::InvalidSetting { name: "max_columns", value: km, valid: "3 ..= 12" });
        }
        Ok(h_max)
    }

    /// Solves y′ = f(t, y), y(t0) = y0 on [t0, t1], returning the accepted steps (no dense
    /// output).
    ///
    /// # Errors
    /// Bad input: [`OdeError::InvalidInterval`], [`OdeError::NonPositiveTolerance`],
    /// [`OdeError::NonPositiveStep`], [`OdeError::NonFiniteState`], [`OdeError::InvalidSetting`]
    /// (`max_columns` outside 3 ..= 12, or `.dense(true)`); during the run:
    /// [`OdeError::RhsNotFinite`], [`OdeError::StepSizeUnderflow`], [`OdeError::TooManySteps`],
    /// [`OdeError::DimensionMismatch`] when f returns a state of another length than y.
    pub fn solve<S: State, F: FnMut(f64, &S) -> S>(
        &self,
        f: F,
        t0: f64,
        y0: &S,
        t1: f64,
    ) -> Result<Solution<S>, OdeError> {
        self.solve_rhs(f, t0, y0, t1)
    }

    /// [`Extrapolation::solve`] for any [`Rhs`]: an [`crate::InPlace`] closure, or a type of
    /// the caller's that evaluates two states at once ([`Rhs::pairs`],
    /// [`Rhs::call_pair_into`]), whose rows are then built two at a time. The same steps and
    /// bits as `solve` with the same f; the evaluations may differ (rows built but not read).
    ///
    /// # Errors
    /// As [`Extrapolation::solve`].
    pub fn solve_rhs<S: State, F: Rhs<S>>(
        &self,
        mut f: F,
        t0: f64,
        y0: &S,
        t1: f64,
    ) -> Result<Solution<S>, OdeError> {
        let start = Instant::now();
        let h_max = self.check_gbs(t0, t1)?;
        if self.dense {
            return Err(OdeError::InvalidSetting {
                name: "dense",
                value: 1,
                valid: "false (0): extrapolation records no dense output",
            });
        }
        let (mut run, f0) = Run::start(self, &mut f, t0, y0, h_max)?;
        let mut ts = vec![t0];
        let mut ys = vec![y0.clone()];
        let mut dz = f0;
        let mut y = y0.clone();
        let mut t = t0;
        while t < t1 {
            let (t_new, y_new) = run.step(&mut f, t, &y, &dz, t1)?;
            t = t_new;
            y.clone_from(y_new);
            ts.push(t);
            ys.push(y.clone());
            if t < t1 {
                eval_into(&mut f, t, &y, &mut dz, (t, 1), &mut run.work.fevals)?;
            }
        }
        run.work.wall = start.elapsed();
        Ok(Solution {
            t: ts,
            y: ys,
            events: Vec::new(),
            terminated: false,
            work: run.work,
            dense: Vec::new(),
        })
    }
}

/// ODEX's step-size factors: FAC1, FAC2 bound the change of h (`odex.f`);
/// SAFE1, SAFE2 are the safety factors of the new step; SAFE3 shrinks h after a diverging
/// row; FAC3, FAC4 decide an order decrease or increase from the work per unit step.
const FAC1: f64 = 0.02;
const FAC2: f64 = 4.0;
const SAFE1: f64 = 0.65;
const SAFE2: f64 = 0.94;
const SAFE3: f64 = 0.5;
const FAC3: f64 = 0.8;
const FAC4: f64 = 0.9;

/// One run's extrapolation table and controller state (shared by [`Extrapolation::solve`] and
/// [`GbsStepper`](super::GbsStepper)).
pub(super) struct Run<S> {
    rtol: f64,
    atol: f64,
    h_max: f64,
    max_steps: usize,
    km: usize,
    /// Step numbers nⱼ (index j − 1).
    nj: [usize; GBS_MAX_COLUMNS + 1],
    /// Evaluations to build row j (index j − 1): Aⱼ = 1 + Σ_{i≤j} nᵢ.
    a: [f64; GBS_MAX_COLUMNS + 1],
    /// Optimal step for each row (index j − 1) and the work per unit step Wⱼ = Aⱼ/Hⱼ.
    hh: [f64; GBS_MAX_COLUMNS + 1],
    w: [f64; GBS_MAX_COLUMNS + 1],
    /// The current column target k (ODEX's K) and step h.
    k: usize,
    h: f64,
    /// The last step was rejected.
    reject: bool,
    /// The last attempt ended in row k − 1 (whether paired rows build row k speculatively).
    stopped_early: bool,
    /// max(4·err, 1) of the previous row of this attempt (a row whose error does not fall
    /// below it diverges).
    err_old: f64,
    /// The extrapolation table of increments y₁ − y₀, T[0] the best (ODEX's layout).
    table: Vec<S>,
    /// Gragg's midpoint rule for the rows, in one lane or two.
    lanes: Lanes<S>,
    /// y₀ + T[0], the accepted step's result.
    out: S,
    pub(super) work: Work,
}

/// How an attempted step ended.
enum Verdict {
    /// Accepted in this row.
    Accept(usize),
    /// Rejected after this row.
    Reject(usize),
    /// A row diverged: reject with h·SAFE3.
    Diverged,
}

impl<S: State> Run<S> {
    /// Checks y0, evaluates f(t0, y0) (returned) and picks the first step (`h0`, or HNW's
    /// starting step for order 2k − 1), with the step bound `h_max` that
    /// [`Solver::check_gbs`] returned for the settings and interval.
    pub(super) fn start<F: Rhs<S>>(
        cfg: &Solver<Gbs>,
        f: &mut F,
        t0: f64,
        y0: &S,
        h_max: f64,
    ) -> Result<(Self, S), OdeError> {
        check_state(t0, y0)?;
        let mut run = Run::new(cfg, cfg.method.max_columns, h_max, y0);
        let f0 = eval(f, t0, y0, t0, 1, &mut run.work.fevals)?;
        run.h = match cfg.h0 {
            Some(h0) => h0.min(h_max),
            None => {
                let order = (2 * run.k - 1) as f64;
                initial_step(f, t0, y0, &f0, order, h_max, (cfg.rtol, cfg.atol), &mut run.work)?
            }
        };
        Ok((run, f0))
    }

    /// The step the controller proposes next.
    pub(super) fn proposed(&self) -> f64 {
        self.h
    }

    /// Caps the steps at `h_max` (a stepper's new end).
    pub(super) fn set_h_max(&mut self, h_max: f64) {
        self.h_max = h_max;
    }

    fn new(cfg: &Solver<Gbs>, km: usize, h_max: f64, y0: &S) -> Self {
        let mut nj = [0; GBS_MAX_COLUMNS + 1];
        let mut a = [0.0; GBS_MAX_COLUMNS + 1];
        for j in 0..=GBS_MAX_COLUMNS {
            nj[j] = 2 * (j + 1);
            a[j] = if j == 0 { (nj[0] + 1) as f64 } else { a[j - 1] + nj[j] as f64 };
        }
        // ODEX's starting column: higher for tighter tolerances
        let k = ((-(cfg.rtol + 1e-40).log10() * 0.6 + 1.5).floor() as usize).clamp(2, km - 1);
        Self {
            rtol: cfg.rtol,
            atol: cfg.atol,
            h_max,
            max_steps: cfg.max_steps,
            km,
            nj,
            a,
            hh: [0.0; GBS_MAX_COLUMNS + 1],
            w: [0.0; GBS_MAX_COLUMNS + 1],
            k,
            h: 0.0,
            reject: false,
            stopped_early: false,
            err_old: f64::INFINITY,
            table: vec![y0.clone(); km],
            lanes: Lanes::new(y0),
            out: y0.clone(),
            work: Work::default(),
        }
    }

    /// One accepted step from (t, y) with f(t, y) = dz, towards t1: returns the new time and
    /// state (y plus the best table entry).
    pub(super) fn step<F: Rhs<S>>(
        &mut self,
        f: &mut F,
        t: f64,
        y: &S,
        dz: &S,
        t1: f64,
    ) -> Result<(f64, &S), OdeError> {
        loop {
            if self.work.accepted + self.work.rejected >= self.max_steps {
                return Err(OdeError::TooManySteps { t, max_steps: self.max_steps });
            }
            let mut h = self.h.min(self.h_max);
            if 0.1 * h <= t.abs() * f64::EPSILON {
                return Err(OdeError::StepSizeUnderflow { t, h });
            }
            // the last step lands exactly on t1 (Hairer: if t + 1.01h ≥ t1, h = t1 − t)
            let last = t + 1.01 * h >= t1;
            if last {
                h = t1 - t;
            }
            self.h = h;
            self.err_old = f64::INFINITY;
            match self.attempt(f, t, y, dz)? {
                Verdict::Accept(kc) => {
                    self.accept(kc);
                    // y₁ = y₀ + the best increment
                    offset(&mut self.out, y, &self.table[0]);
                    return Ok((if last { t1 } else { t + h }, &self.out));
                }
                Verdict::Reject(kc) => {
                    let mut k = self.k.min(kc).min(self.km - 1);
                    if k > 2 && self.w[k - 2] < self.w[k - 1] * FAC3 {
                        k -= 1;
                    }
                    self.k = k;
                    self.h = self.hh[k - 1];
                }
                // a diverging row: a smaller step, the same column
                Verdict::Diverged => self.h = h * SAFE3,
            }
            self.work.rejected += 1;
            self.reject = true;
        }
    }

    /// Rows 1 … k − 1, then the convergence monitor in rows k − 1, k and k + 1 (HNW §II.9,
    /// ODEX): accept in the first row whose error is ≤ 1, reject early when the error is too
    /// large to fall below 1 within the rows left.
    fn attempt<F: Rhs<S>>(&mut self, f: &mut F, t: f64, y: &S, dz: &S) -> Result<Verdict, OdeError> {
        let k = self.k;
        self.lanes.clear();
        if f.pairs() {
            // row k too, unless the controller may stop after row k − 1 (it can when k > 2 and
            // the last step was accepted) and did so in the last attempt
            let upto = if k == 2 || self.reject || !self.stopped_early { k } else { k - 1 };
            let at = (t, self.h, y, dz);
            self.lanes.rows(f, upto, &self.nj, at, &mut self.table, &mut self.work.fevals);
        }
        let mut err = 0.0;
        for j in 1..k {
            match self.row(f, j, t, y, dz)? {
                Some(e) => err = e,
                None => return Ok(Verdict::Diverged),
            }
        }
        let (nk, nk1, n1) = (self.nj[k - 1] as f64, self.nj[k] as f64, self.nj[0] as f64);
        if k != 2 && !self.reject {
            self.stopped_early = true;
            if err <= 1.0 {
                return Ok(Verdict::Accept(k - 1));
            }
            if err > (nk1 * nk / (n1 * n1)).powi(2) {
                return Ok(Verdict::Reject(k - 1));
            }
            self.stopped_early = false;
        }
        let Some(err) = self.row(f, k, t, y, dz)? else { return Ok(Verdict::Diverged) };
        if err <= 1.0 {
            return Ok(Verdict::Accept(k));
        }
        if err > (nk1 / n1).powi(2) {
            return Ok(Verdict::Reject(k));
        }
        let Some(err) = self.row(f, k + 1, t, y, dz)? else { return Ok(Verdict::Diverged) };
        Ok(if err <= 1.0 { Verdict::Accept(k + 1) } else { Verdict::Reject(k + 1) })
    }

    /// Order and step for the next step after acceptance in row kc (HNW §II.9, `odex.f`).
    fn accept(&mut self, kc: usize) {
        self.work.accepted += 1;
        let (w, km, k) = (&self.w, self.km, self.k);
        // w and hh are indexed by row − 1
        let wr = |j: usize| w[j - 1];
        let kopt = if kc == 2 {
            if self.reject { 2 } else { 3.min(km - 1) }
        } else if kc <= k {
            let mut kopt = kc;
            if wr(kc - 1) < wr(kc) * FAC3 {
                kopt = kc - 1;
            }
            if wr(kc) < wr(kc - 1) * FAC4 {
                kopt = (kc + 1).min(km - 1);
            }
            kopt
        } else {
            let mut kopt = kc - 1;
            if kc > 3 && wr(kc - 2) < wr(kc - 1) * FAC3 {
                kopt = kc - 2;
            }
            if wr(kc) < wr(kopt) * FAC4 {
                kopt = kc.min(km - 1);
            }
            kopt
        };
        if self.reject {
            self.k = kopt.min(kc);
            self.h = self.h.min(self.hh[self.k - 1]);
            self.reject = false;
            return;
        }
        self.h = if kopt <= kc {
            self.hh[kopt - 1]
        } else if kc < k && wr(kc) < wr(kc - 1) * FAC4 {
            self.hh[kc - 1] * self.a[kopt] / self.a[kc - 1]
        } else {
            self.hh[kc - 1] * self.a[kopt - 1] / self.a[kc - 1]
        };
        self.k = kopt;
    }

    /// Row j (1-based) of the table: Gragg's midpoint rule with nⱼ steps of H/nⱼ and the final
    /// smoothing step (HNW §II.9) on the increments y − y₀ (built here by lane A, unless the
    /// paired rows of this attempt left it ready: `gbs_lanes`), extrapolated by Aitken–Neville
    /// in h²; then the error
    /// estimate and the optimal step for this row. `None` when the row diverges: its error is
    /// not finite, beyond 1/ε, or (from row 3) not below max(4·err, 1) of the row before.
    fn row<F: Rhs<S>>(
        &mut self,
        f: &mut F,
        j: usize,
        t: f64,
        y: &S,
        dz: &S,
    ) -> Result<Option<f64>, OdeError> {
        let (h, n) = (self.h, self.nj[j - 1]);
        self.lanes.row(f, (j, n), (t, h, y, dz), &mut self.table, &mut self.work.fevals)?;
        if j == 1 {
            return Ok(Some(0.0));
        }
        // Aitken–Neville: T[l−1] ← T[l] + (T[l] − T[l−1]) / ((nⱼ/n_l)² − 1), l = j−1 … 1
        for l in (1..j).rev() {
            let fac = (n as f64 / self.nj[l - 1] as f64).powi(2) - 1.0;
            let (lo, hi) = self.table.split_at_mut(l);
            for (tl1, tl) in lo[l - 1].as_mut_slice().iter_mut().zip(hi[0].as_slice()) {
                *tl1 = tl + (tl - *tl1) / fac;
            }
        }
        // ‖T_jj − T_j,j−1‖ in the weighted RMS norm, sk = atol + rtol·max(|y₀|, |y₀ + T_jj|)
        let (best, next) = (self.table[0].as_slice(), self.table[1].as_slice());
        let mut sum = 0.0;
        for ((b, c), y0) in best.iter().zip(next).zip(y.as_slice()) {
            let sk = self.atol + self.rtol * y0.abs().max((y0 + b).abs());
            sum += ((b - c) / sk).powi(2);
        }
        let err = (sum / best.len().max(1) as f64).sqrt();
        // diverging (or overflowing) rows are refused at once
        if !err.is_finite() || err * f64::EPSILON >= 1.0 || (j > 2 && err >= self.err_old) {
            return Ok(None);
        }
        self.err_old = (4.0 * err).max(1.0);
        let expo = 1.0 / (2 * j - 1) as f64;
        let facmin = FAC1.powf(expo);
        let fac = (FAC2 / facmin).min(facmin.max((err / SAFE1).powf(expo) / SAFE2));
        self.hh[j - 1] = (h / fac).min(self.h_max);
        self.w[j - 1] = self.a[j - 1] / self.hh[j - 1];
        Ok(Some(err))
    }
}
