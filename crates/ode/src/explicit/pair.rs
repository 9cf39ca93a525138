//! The embedded pairs of the adaptive explicit methods, their solver type, and how a run
//! starts: Hairer's starting step.
//!
//! Book: §4.11; HNW §II.4.

use crate::Rhs;
use crate::solver::Solver;
use crate::state::{State, eval};
use crate::{OdeError, Work};

/// The embedded pair of an adaptive explicit method.
///
/// Book: §4.11; HNW §II.4–II.10.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Pair {
    /// Dormand–Prince 5(4), dense output of order 4, 6 evaluations per step (FSAL).
    Dopri5,
    /// Dormand–Prince 8(5,3), dense output of order 7, 12 evaluations per step (+3 for
    /// dense output).
    Dop853,
    /// Verner's 9(8) pair ("most efficient", Numer. Algorithms 53, 2010), 16 evaluations per
    /// step; no interpolant (a run lands on the times it needs, as extrapolation's): for
    /// tolerances of 1e-10 and below, where its 9th order takes fewer evaluations than DOP853.
    Vern9,
}

/// An adaptive explicit solver: the pair with its tolerances and limits ([`Solver`]). Built
/// with [`Adaptive::dopri5`], [`Adaptive::dop853`] or [`Adaptive::vern9`] and the setters;
/// defaults rtol = 1e-6, atol = 1e-9.
///
/// The local error is kept at ‖err/sk‖ ≤ 1 with sk = atol + rtol·max(|y|, |y₁|) per component
/// (HNW (4.10)); the step size follows Hairer's controller (PI with β = 0.04 and safety
/// factor 0.9 for DOPRI5, I-controller for DOP853 with safety factor 0.8 where `dop853.f` has
/// 0.9, as MATLAB's `ode45` has: on the frontier problems a lower factor trades tolerance for
/// error alone, while the rejected steps it avoids are pure cost, 28 % of Kepler e = 0.9's
/// evaluations at 0.9; docs/performance.md § Work–precision). Vern9 has the I-controller with
/// exponent 1/9 (its estimate is the difference of orders 9 and 8, ‖err‖ = O(h⁹)), err^{1/9}
/// to 1.3e-5 relative (an exponent split and a quartic: the factor is clamped and scaled by a
/// safety factor, and libm's two cube roots cost 15 % of Kepler's time), and DOP853's clamps and
/// safety factor (0.9 cost more evaluations on the frontier problems, 0.7 no fewer) and the RMS
/// norm of the estimate (HNW (4.11)).
///
/// Book: §4.11; HNW §II.4.
pub type Adaptive = Solver<Pair>;

impl Solver<Pair> {
    /// Dormand–Prince 5(4).
    pub const fn dopri5() -> Self {
        Self::with_method(Pair::Dopri5)
    }
    /// DOP853.
    pub const fn dop853() -> Self {
        Self::with_method(Pair::Dop853)
    }
    /// Verner's 9(8) pair ([`Pair::Vern9`]).
    pub const fn vern9() -> Self {
        Self::with_method(Pair::Vern9)
    }
}

/// Classical order of the propagated solution.
pub(crate) fn order(p: Pair) -> f64 {
    match p {
        Pair::Dopri5 => 5.0,
        Pair::Dop853 => 8.0,
        Pair::Vern9 => 9.0,
    }
}

/// √(Σ xᵢ²/n), the plain sum of squares when it is finite (the same bits as always), else
/// scaled by the largest |xᵢ| so that rates beyond 1e154 of their tolerance do not square to ∞
/// (which made the starting step 0).
fn rms(n: usize, x: impl Fn(usize) -> f64) -> f64 {
    let plain = (0..n).fold(0.0, |s, i| s + x(i).powi(2));
    if plain.is_finite() {
        return (plain / n as f64).sqrt();
    }
    let m =
        (0..n).fold(0.0_f64, |m, i| if x(i).is_nan() || m.is_nan() { f64::NAN } else { m.max(x(i).abs()) });
    if !(m.is_finite() && m > 0.0) {
        return m;
    }
    m * ((0..n).fold(0.0, |s, i| s + (x(i) / m).powi(2)) / n as f64).sqrt()
}

/// Hairer's starting step `hinit`: h with ‖h f₀‖ ≈ 0.01‖y₀‖, refined by an estimate of
/// the second derivative so that the first local error is near the tolerance.
#[allow(clippy::too_many_arguments)]
pub(crate) fn initial_step<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    f0: &S,
    order: f64,
    h_max: f64,
    (rtol, atol): (f64, f64),
    work: &mut Work,
) -> Result<f64, OdeError> {
    let sk = |i: usize| atol + rtol * y.as_slice()[i].abs();
    let (dnf, dny) = (rms(y.dim(), |i| f0.as_slice()[i] / sk(i)), rms(y.dim(), |i| y.as_slice()[i] / sk(i)));
    let mut h = if dnf <= 1e-5 || dny <= 1e-5 { 1e-6 } else { 0.01 * dny / dnf };
    h = h.min(h_max);
    // explicit Euler step y + h f₀ and the derivative there
    let mut y1 = y.clone();
    for (a, b) in y1.as_mut_slice().iter_mut().zip(f0.as_slice()) {
        *a += h * b;
    }
    let f1 = eval(f, t + h, &y1, t, 1, &mut work.fevals)?;
    let der2 = rms(y.dim(), |i| (f1.as_slice()[i] - f0.as_slice()[i]) / sk(i)) / h;
    let der12 = der2.abs().max(dnf);
    let h1 = if der12 <= 1e-15 { (h * 1e-3).max(1e-6) } else { (0.01 / der12).powf(1.0 / order) };
    Ok((100.0 * h).min(h1).min(h_max))
}
