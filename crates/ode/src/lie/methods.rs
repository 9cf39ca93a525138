//! Lie-group integrators for y′ = y·ξ(t, y): exponential Euler, RKMK4 and Crouch–Grossman.

use std::time::Instant;

use super::LieGroup;
use crate::error::{check_interval, check_step};
use crate::{OdeError, Work};

/// A fixed-step Lie-group method. The update is a product of exponentials, so the state
/// stays on the group whatever the step size.
///
/// Book: §4.11 (attitude kinematics (4.11.13), exact step (4.11.17)); HLW §IV.8.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LieMethod {
    /// y₁ = y·exp(hξ(t, y)), order 1. For the attitude with ξ = ω_b this is the exact
    /// quaternion step (4.11.17) with ω frozen over the step.
    ExponentialEuler,
    /// Runge–Kutta–Munthe-Kaas with the classical RK4 coefficients and the dexp⁻¹ series
    /// truncated after the B₂ term, order 4.
    Rkmk4,
    /// Crouch–Grossman 3-stage method of order 3 (no brackets, products of exponentials).
    CrouchGrossman3,
}

impl LieMethod {
    /// Name for tables.
    pub fn name(self) -> &'static str {
        match self {
            Self::ExponentialEuler => "ExpEuler",
            Self::Rkmk4 => "RKMK4",
            Self::CrouchGrossman3 => "CG3",
        }
    }
    /// Classical order.
    pub fn order(self) -> u32 {
        match self {
            Self::ExponentialEuler => 1,
            Self::Rkmk4 => 4,
            Self::CrouchGrossman3 => 3,
        }
    }
}

/// dexp⁻¹ for the right-trivialized form: with y = y₀·exp(Ω), Ω′ = dexp⁻¹_{−Ω}(ξ)
/// = ξ + ½[Ω, ξ] + (1/12)[Ω, [Ω, ξ]] + … (Bernoulli numbers B₁ = −½, B₂ = 1/6; the series
/// is truncated after B₂, enough for order 4, Munthe-Kaas 1999).
///
/// Book: HLW §III.4, Lemma III.4.2, (4.7).
pub fn dexpinv<G: LieGroup>(omega: &G::Algebra, xi: &G::Algebra) -> G::Algebra {
    let ad1 = G::bracket(omega, xi);
    let ad2 = G::bracket(omega, &ad1);
    G::axpy(&G::axpy(xi, 0.5, &ad1), 1.0 / 12.0, &ad2)
}

/// Evaluates ξ(t, y) and checks it is finite.
fn eval<G: LieGroup, F: FnMut(f64, &G) -> G::Algebra>(
    f: &mut F,
    t: f64,
    y: &G,
    step_start: f64,
    stage: usize,
    work: &mut Work,
) -> Result<G::Algebra, OdeError> {
    work.fevals += 1;
    let xi = f(t, y);
    let m = G::algebra_magnitude(&xi);
    if m.is_finite() {
        Ok(xi)
    } else {
        Err(OdeError::RhsNotFinite { t, step_start, stage, index: 0, value: m })
    }
}

/// Crouch–Grossman 3 (HLW Table IV.8.1 after Crouch & Grossman 1993):
/// c = (0, 3/4, 17/24), a₂₁ = 3/4, a₃₁ = 119/216, a₃₂ = 17/108, b = (13/51, −2/3, 24/17).
const CG3_C: [f64; 3] = [0.0, 3.0 / 4.0, 17.0 / 24.0];
const CG3_A21: f64 = 3.0 / 4.0;
const CG3_A31: f64 = 119.0 / 216.0;
const CG3_A32: f64 = 17.0 / 108.0;
const CG3_B: [f64; 3] = [13.0 / 51.0, -2.0 / 3.0, 24.0 / 17.0];

/// One step of `method` from (t, y) with size h.
fn step<G: LieGroup, F: FnMut(f64, &G) -> G::Algebra>(
    method: LieMethod,
    f: &mut F,
    t: f64,
    y: &G,
    h: f64,
    work: &mut Work,
) -> Result<G, OdeError> {
    let exp_h = |c: f64, xi: &G::Algebra| G::exp(&G::scale(c * h, xi));
    match method {
        LieMethod::ExponentialEuler => {
            // y₁ = y·exp(hξ(t, y))
            let xi = eval(f, t, y, t, 1, work)?;
            Ok(y.compose(&exp_h(1.0, &xi)))
        }
        LieMethod::Rkmk4 => {
            // kᵢ = h dexp⁻¹_{−Ωᵢ}(ξ(t + cᵢh, y·exp Ωᵢ)), Ω₁ = 0, Ω₂ = k₁/2, Ω₃ = k₂/2, Ω₄ = k₃
            let xi1 = eval(f, t, y, t, 1, work)?;
            let k1 = G::scale(h, &xi1);
            let o2 = G::scale(0.5, &k1);
            let xi2 = eval(f, t + 0.5 * h, &y.compose(&G::exp(&o2)), t, 2, work)?;
            let k2 = G::scale(h, &dexpinv::<G>(&o2, &xi2));
            let o3 = G::scale(0.5, &k2);
            let xi3 = eval(f, t + 0.5 * h, &y.compose(&G::exp(&o3)), t, 3, work)?;
            let k3 = G::scale(h, &dexpinv::<G>(&o3, &xi3));
            let xi4 = eval(f, t + h, &y.compose(&G::exp(&k3)), t, 4, work)?;
            let k4 = G::scale(h, &dexpinv::<G>(&k3, &xi4));
            // Ω = (k₁ + 2k₂ + 2k₃ + k₄)/6; y₁ = y·exp(Ω)
            let s = G::axpy(&G::axpy(&G::axpy(&k1, 2.0, &k2), 2.0, &k3), 1.0, &k4);
            let omega = G::scale(1.0 / 6.0, &s);
            Ok(y.compose(&G::exp(&omega)))
        }
        LieMethod::CrouchGrossman3 => {
            // Yᵢ = y·exp(h aᵢ₁ξ₁)···exp(h aᵢ,ᵢ₋₁ξᵢ₋₁); y₁ = y·exp(h b₁ξ₁)·exp(h b₂ξ₂)·exp(h b₃ξ₃)
            let xi1 = eval(f, t, y, t, 1, work)?;
            let y2 = y.compose(&exp_h(CG3_A21, &xi1));
            let xi2 = eval(f, t + CG3_C[1] * h, &y2, t, 2, work)?;
            let y3 = y.compose(&exp_h(CG3_A31, &xi1)).compose(&exp_h(CG3_A32, &xi2));
            let xi3 = eval(f, t + CG3_C[2] * h, &y3, t, 3, work)?;
            Ok(y.compose(&exp_h(CG3_B[0], &xi1))
                .compose(&exp_h(CG3_B[1], &xi2))
                .compose(&exp_h(CG3_B[2], &xi3)))
        }
    }
}

/// Integrates y′ = y·ξ(t, y) on a Lie group with `n` equal steps of `method`; returns
/// y(t1) and the work. `observe(t, y)` runs after every step.
///
/// Book: §4.11, (4.11.13), (4.11.17); HLW §IV.8.
///
/// # Errors
/// [`OdeError::InvalidInterval`], [`OdeError::NonPositiveStep`] (n = 0),
/// [`OdeError::NonFiniteState`] (index 0: a group element has no component index),
/// [`OdeError::RhsNotFinite`] (index 0, value = the offending magnitude).
pub fn integrate_lie<G: LieGroup, F: FnMut(f64, &G) -> G::Algebra>(
    method: LieMethod,
    mut f: F,
    t0: f64,
    y0: &G,
    t1: f64,
    n: usize,
    mut observe: impl FnMut(f64, &G),
) -> Result<(G, Work), OdeError> {
    let start = Instant::now();
    check_interval(t0, t1)?;
    let h = (t1 - t0) / n as f64;
    check_step(h)?;
    let m = y0.magnitude();
    if !m.is_finite() {
        return Err(OdeError::NonFiniteState { t: t0, index: 0, value: m });
    }
    let mut work = Work::default();
    let mut y = y0.clone();
    for i in 0..n {
        let t = t0 + i as f64 * h;
        y = step(method, &mut f, t, &y, h, &mut work)?;
        work.accepted += 1;
        observe(t + h, &y);
    }
    work.wall = start.elapsed();
    Ok((y, work))
}
