//! Fixed-step explicit Runge–Kutta.

use std::time::Instant;

use super::Tableau;
use crate::error::{check_interval, check_step};
use crate::state::{State, check_state, combine, eval};
use crate::{OdeError, Work};

/// One explicit Runge–Kutta step of size h from (t, y) (HNW (1.8)).
///
/// Book: §4.11; HNW §II.1.
pub(crate) fn rk_step<S: State, F: FnMut(f64, &S) -> S>(
    tab: &Tableau,
    f: &mut F,
    t: f64,
    y: &S,
    h: f64,
    k: &mut Vec<S>,
    work: &mut Work,
) -> Result<S, OdeError> {
    k.clear();
    for (i, (ci, ai)) in tab.c.iter().zip(tab.a).enumerate() {
        // kᵢ = f(t + cᵢh, y + h Σ_{j<i} aᵢⱼ kⱼ)
        let yi = combine(y, h, ai, k);
        let ki = eval(f, t + ci * h, &yi, t, i + 1, &mut work.fevals)?;
        k.push(ki);
    }
    // y₁ = y + h Σ bᵢ kᵢ
    Ok(combine(y, h, tab.b, k))
}

/// Integrates y′ = f(t, y) from `t0` to `t1` with `n` equal steps of the explicit method
/// `tab`; returns y(t1) and the work. `observe(t, y)` is called after every step.
///
/// Book: §4.11; HNW §II.1.
///
/// # Errors
/// [`OdeError::InvalidInterval`], [`OdeError::NonPositiveStep`] for `n == 0`,
/// [`OdeError::NonFiniteState`], [`OdeError::RhsNotFinite`].
pub fn integrate_fixed<S: State, F: FnMut(f64, &S) -> S>(
    tab: &Tableau,
    mut f: F,
    t0: f64,
    y0: &S,
    t1: f64,
    n: usize,
    mut observe: impl FnMut(f64, &S),
) -> Result<(S, Work), OdeError> {
    let start = Instant::now();
    check_interval(t0, t1)?;
    let h = (t1 - t0) / n as f64;
    check_step(h)?;
    check_state(t0, y0)?;
    let mut work = Work::default();
    let mut k = Vec::with_capacity(tab.stages());
    let mut y = y0.clone();
    for i in 0..n {
        let t = t0 + i as f64 * h;
        y = rk_step(tab, &mut f, t, &y, h, &mut k, &mut work)?;
        work.accepted += 1;
        observe(t + h, &y);
    }
    work.wall = start.elapsed();
    Ok((y, work))
}
