//! Stiffness detection for [`Accuracy`](crate::Accuracy), as LSODA switches (Petzold 1983):
//! the run starts with the explicit pair of the accuracy table and, every
//! [`STIFF_CHECK_EVERY`] accepted steps, estimates the spectral radius ρ of ∂f/∂y at the
//! current point by power iteration on finite-difference Jacobian–vector products. When the
//! proposed step times ρ has reached [`STIFF_H_RHO`] (half DOP853's stability interval on the
//! negative real axis, ≈ 6: the step is held by stability, not accuracy) on two checks in a
//! row, and the rest of the interval would cost at least [`STIFF_MIN_STEPS`] explicit steps for
//! stability alone — or when an explicit step overflows or shrinks to the round-off floor,
//! instability showing before a check — the run continues from that point with the stiff
//! method of
//! [`STIFF_ACCURACY_TABLE`](crate::STIFF_ACCURACY_TABLE). The choice and why are returned in a
//! [`Choice`].
//!
//! Book: §4.11; HW §IV.1 (stiffness), §IV.2 (stability domains: DOP853's reaches ≈ −6 on the
//! real axis); Hairer's `dop853.f` (the stiffness test hλ > 6.1 from two f-values near the step
//! end); Petzold, SIAM J. Sci. Stat. Comput. 4 (1983) (LSODA's automatic switching).

use std::cell::RefCell;
use std::time::Instant;

use crate::explicit::{Solution, Stepper};
use crate::state::State;
use crate::{Adaptive, OdeError, Work};

/// Accepted explicit steps between two stiffness checks.
pub const STIFF_CHECK_EVERY: usize = 25;
/// Stiff when h·ρ ≥ this on two checks in a row (DOP853's real stability interval is ≈ 6; a
/// step held at that limit has h·ρ close to it, an accuracy-limited one far below).
pub const STIFF_H_RHO: f64 = 3.0;
/// …and ρ·(t1 − t)/6, the explicit steps the rest of the run needs for stability alone, is at
/// least this (a stiff tail of a few steps is not worth the switch).
pub const STIFF_MIN_STEPS: f64 = 100.0;
/// Power iterations of the spectral-radius estimate (one f-evaluation each).
const POWER_ITERATIONS: usize = 8;

/// The method [`Accuracy`](crate::Accuracy) ran and why.
///
/// Book: §4.11.
#[derive(Debug, Clone, PartialEq)]
pub struct Choice {
    /// `dop853` (explicit throughout), or the stiff method it switched to (`radau5`, `bdf`).
    pub method: &'static str,
    /// Its relative (= absolute) local tolerance.
    pub rtol: f64,
    /// Where the run switched to the stiff method (`None`: it did not).
    pub switched_at: Option<f64>,
    /// The numbers behind the choice.
    pub reason: String,
}

impl core::fmt::Display for Choice {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{} at rtol = atol = {:e} ({})", self.method, self.rtol, self.reason)
    }
}

/// ρ(∂f/∂y) at (t, y) by power iteration: vₖ₊₁ = (f(y + δv̂ₖ) − f(y))/δ with δ = √ε·max(1, ‖y‖);
/// returns ‖vₖ₊₁‖ after [`POWER_ITERATIONS`] (a lower bound of ρ that converges at the rate of
/// the two largest |λ|, fast exactly when the problem is stiff). `None` if an f-value is not
/// finite. Counts its evaluations in `fevals`.
pub(crate) fn spectral_radius<S: State>(
    f: &mut impl FnMut(f64, &S) -> S,
    t: f64,
    y: &S,
    fevals: &mut usize,
) -> Option<f64> {
    let n = y.dim();
    let ynorm = y.as_slice().iter().map(|v| v * v).sum::<f64>().sqrt();
    let delta = f64::EPSILON.sqrt() * ynorm.max(1.0);
    *fevals += 1;
    let f0 = f(t, y);
    // a fixed start that is not orthogonal to a fast mode in general: 1, −½, ⅓, −¼, …
    let mut v: Vec<f64> = (0..n).map(|i| if i % 2 == 0 { 1.0 } else { -1.0 } / (i as f64 + 1.0)).collect();
    let mut rho = 0.0;
    let mut yp = y.clone();
    for _ in 0..POWER_ITERATIONS {
        let norm = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        if !(norm.is_finite() && norm > 0.0) {
            return if norm == 0.0 { Some(rho) } else { None };
        }
        for ((o, yi), vi) in yp.as_mut_slice().iter_mut().zip(y.as_slice()).zip(&v) {
            *o = yi + delta * vi / norm;
        }
        *fevals += 1;
        let fp = f(t, &yp);
        for ((vi, a), b) in v.iter_mut().zip(fp.as_slice()).zip(f0.as_slice()) {
            *vi = (a - b) / delta;
        }
        rho = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        if !rho.is_finite() {
            return None;
        }
    }
    Some(rho)
}

/// Runs `explicit` with the stiffness checks; on a stiff verdict hands the rest of the interval
/// to `stiff` (started from the current point with finite-difference Jacobians: the caller's f
/// is f64 only). The records of both parts make one [`Solution`], their work is summed.
pub(crate) fn solve_switching<S: State, F: FnMut(f64, &S) -> S>(
    explicit: &Adaptive,
    stiff: &crate::Method,
    f: F,
    t0: f64,
    y0: &S,
    t1: f64,
) -> Result<(Solution<S>, Choice), OdeError> {
    let start = Instant::now();
    let fc = RefCell::new(f);
    let mut sol = Solution {
        t: vec![t0],
        y: vec![y0.clone()],
        events: Vec::new(),
        terminated: false,
        work: Work::default(),
        dense: Vec::new(),
    };
    let mut probe_fevals = 0usize;
    let mut st = Stepper::new(explicit, |t: f64, y: &S| (fc.borrow_mut())(t, y), t0, y0.clone(), t1)?;
    let (mut hits, mut last_rho) = (0usize, 0.0);
    let mut switch: Option<(f64, String)> = None;
    while !st.done() {
        // a stage that overflows, or a step driven to the round-off floor, is the explicit
        // method's instability showing before a check could see it: the stiff method takes over
        // from the last accepted point (and reports the same error if f itself is at fault)
        if let Err(e) = st.step() {
            match e {
                OdeError::RhsNotFinite { .. } | OdeError::StepSizeUnderflow { .. } => {
                    let t = st.t();
                    switch = Some((t, format!("stiff from t = {t:.6e}: DOP853's next step failed ({e})")));
                    break;
                }
                other => return Err(other),
            }
        }
        sol.t.push(st.t());
        sol.y.push(st.y().clone());
        if st.work().accepted % STIFF_CHECK_EVERY != 0 || st.done() {
            continue;
        }
        let (t, h) = (st.t(), st.proposed_step());
        let Some(rho) = spectral_radius(&mut *fc.borrow_mut(), t, st.y(), &mut probe_fevals) else {
            continue;
        };
        last_rho = rho;
        let stability_steps = rho * (t1 - t) / 6.0;
        hits = if h * rho >= STIFF_H_RHO && stability_steps >= STIFF_MIN_STEPS { hits + 1 } else { 0 };
        if hits >= 2 {
            switch = Some((
                t,
                format!(
                    "stiff from t = {t:.6e}: ρ(∂f/∂y) ≈ {rho:.3e} /s, h·ρ = {:.2} ≥ {STIFF_H_RHO} on two checks \
                     (DOP853 held by stability), ≳ {stability_steps:.1e} explicit steps left for stability alone",
                    h * rho
                ),
            ));
            break;
        }
    }
    let mut work = st.work();
    drop(st);
    let choice = match switch {
        None => Choice {
            method: "dop853",
            rtol: explicit.rtol,
            switched_at: None,
            reason: format!(
                "accuracy table; not stiff: h·ρ < {STIFF_H_RHO} or too short a stiff tail at the checks every \
                 {STIFF_CHECK_EVERY} steps (last ρ ≈ {last_rho:.3e} /s)"
            ),
        },
        Some((ts, reason)) => {
            let ys = sol.y.last().cloned().unwrap_or_else(|| y0.clone());
            let g = |t: f64, y: &S| (fc.borrow_mut())(t, y);
            let rest = match stiff {
                crate::Method::Radau5(r) => r.solve(g, ts, &ys, t1)?,
                crate::Method::Bdf(b) => b.solve(g, ts, &ys, t1)?,
                crate::Method::Explicit(a) => a.solve(g, ts, &ys, t1)?,
                crate::Method::Gbs(e) => e.solve(g, ts, &ys, t1)?,
            };
            sol.t.extend_from_slice(&rest.t[1..]);
            sol.y.extend_from_slice(&rest.y[1..]);
            add_work(&mut work, &rest.work);
            let (rtol, _) = stiff.tolerances();
            Choice { method: stiff.name(), rtol, switched_at: Some(ts), reason }
        }
    };
    work.fevals += probe_fevals;
    sol.work = work;
    sol.work.wall = start.elapsed();
    Ok((sol, choice))
}

/// a += b, counter by counter.
fn add_work(a: &mut Work, b: &Work) {
    a.fevals += b.fevals;
    a.accepted += b.accepted;
    a.rejected += b.rejected;
    a.jacobians += b.jacobians;
    a.factorizations += b.factorizations;
    a.newton_iterations += b.newton_iterations;
    a.fd_jacobian_fevals += b.fd_jacobian_fevals;
}
