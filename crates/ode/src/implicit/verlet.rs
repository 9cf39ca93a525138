//! Störmer–Verlet for separable second-order systems q̈ = a(t, q).

use std::time::Instant;

use crate::error::{check_interval, check_step};
use crate::state::{State, check_state, eval};
use crate::{OdeError, Work};

/// Integrates q̈ = a(t, q) (H = ½|v|² + V(q), a = −∇V) with `n` velocity-Verlet steps:
/// v½ = v + (h/2) a(t, q), q₁ = q + h v½, v₁ = v½ + (h/2) a(t + h, q₁). Order 2, symplectic,
/// symmetric; one evaluation of a per step. Returns (q, v) at `t1`.
///
/// Book: §4.11; HLW §I.1.4, (1.17).
///
/// # Errors
/// [`OdeError::InvalidInterval`], [`OdeError::NonPositiveStep`] (n = 0),
/// [`OdeError::NonFiniteState`], [`OdeError::RhsNotFinite`],
/// [`OdeError::DimensionMismatch`] when q and v differ in length.
#[allow(clippy::too_many_arguments)]
pub fn stormer_verlet<Q: State, A: FnMut(f64, &Q) -> Q>(
    mut accel: A,
    t0: f64,
    q0: &Q,
    v0: &Q,
    t1: f64,
    n: usize,
    mut observe: impl FnMut(f64, &Q, &Q),
) -> Result<((Q, Q), Work), OdeError> {
    let start = Instant::now();
    check_interval(t0, t1)?;
    let h = (t1 - t0) / n as f64;
    check_step(h)?;
    check_state(t0, q0)?;
    check_state(t0, v0)?;
    if q0.dim() != v0.dim() {
        return Err(OdeError::DimensionMismatch { what: "v0", got: v0.dim(), expected: q0.dim() });
    }
    let mut work = Work::default();
    let (mut q, mut v) = (q0.clone(), v0.clone());
    let mut a = eval(&mut accel, t0, &q, t0, 1, &mut work.fevals)?;
    for step in 0..n {
        let t = t0 + step as f64 * h;
        // v½ = v + (h/2) a(t, q); q₁ = q + h v½
        for ((vi, qi), ai) in v.as_mut_slice().iter_mut().zip(q.as_mut_slice()).zip(a.as_slice()) {
            *vi += 0.5 * h * ai;
            *qi += h * *vi;
        }
        // v₁ = v½ + (h/2) a(t + h, q₁); a(t + h, q₁) is reused next step
        a = eval(&mut accel, t + h, &q, t, 1, &mut work.fevals)?;
        for (vi, ai) in v.as_mut_slice().iter_mut().zip(a.as_slice()) {
            *vi += 0.5 * h * ai;
        }
        work.accepted += 1;
        observe(t + h, &q, &v);
    }
    work.wall = start.elapsed();
    Ok(((q, v), work))
}
