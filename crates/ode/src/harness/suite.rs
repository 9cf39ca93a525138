//! The whole harness: every reference problem with every method that applies, and the
//! summaries derived from it.

use super::problems::{Kepler, Oscillator, Pendulum, SpringChain};
use super::rigid::RigidBody;
use super::run::{Budget, Method, Point, sweep, sweep_lie, sweep_verlet};
use crate::explicit::{EULER, HEUN, Pair, RK4};
use crate::{GaussLegendre, LieMethod};

/// The vector-space methods every non-stiff problem runs.
const COMMON: [Method; 8] = [
    Method::Fixed(EULER),
    Method::Fixed(HEUN),
    Method::Fixed(RK4),
    Method::Adaptive(Pair::Dopri5),
    Method::Adaptive(Pair::Dop853),
    Method::Gauss(GaussLegendre::Midpoint),
    Method::Gauss(GaussLegendre::Gauss4),
    Method::Gauss(GaussLegendre::Gauss6),
];

/// The problem names in the order [`run_all`] runs them (one diagram each).
pub const PROBLEMS: [&str; 7] = [
    "oscillator",
    "pendulum θ0=3.0",
    "Kepler e=0",
    "Kepler e=0.5",
    "Kepler e=0.9",
    "rigid body",
    "stiff chain α=1000",
];

/// File stems of the diagrams, parallel to [`PROBLEMS`].
pub const FILE_STEMS: [&str; 7] =
    ["oscillator", "pendulum", "kepler-e0", "kepler-e0.5", "kepler-e0.9", "rigid-body", "stiff-chain"];

/// Runs every reference problem with every applicable method: the oscillator, the pendulum
/// at θ₀ = 3 rad, Kepler at e = 0, 0.5, 0.9 (with Störmer–Verlet as well), the torque-free
/// rigid body (with the Lie-group methods on Rotor × ℝ³) and the stiff chain.
///
/// Book: §4.11; HNW §II.10.
pub fn run_all(budget: Budget) -> Vec<Point> {
    let mut pts = Vec::new();
    let osc = Oscillator;
    let pend = Pendulum { theta0: 3.0 };
    for m in COMMON {
        pts.extend(sweep(&osc, m, budget));
    }
    pts.extend(sweep_verlet(&osc, budget));
    for m in COMMON {
        pts.extend(sweep(&pend, m, budget));
    }
    pts.extend(sweep_verlet(&pend, budget));
    for e in [0.0, 0.5, 0.9] {
        let k = Kepler { e };
        for m in COMMON {
            pts.extend(sweep(&k, m, budget));
        }
        pts.extend(sweep_verlet(&k, budget));
    }
    let rb = RigidBody::default();
    for m in COMMON {
        pts.extend(sweep(&rb, m, budget));
    }
    for m in [LieMethod::ExponentialEuler, LieMethod::CrouchGrossman3, LieMethod::Rkmk4] {
        pts.extend(sweep_lie(&rb, m, budget));
    }
    let chain = SpringChain { alpha: 1000.0 };
    for m in COMMON {
        pts.extend(sweep(&chain, m, budget));
    }
    pts
}

/// The cheapest run (least wall time) of `problem` whose error is at most `target`.
///
/// Book: §4.11.
pub fn cheapest<'a>(points: &'a [Point], problem: &str, target: f64) -> Option<&'a Point> {
    points
        .iter()
        .filter(|p| p.problem == problem && p.error <= target)
        .min_by(|a, b| a.seconds.total_cmp(&b.seconds))
}

/// One row of the accuracy table derived from the harness: to reach a global error of
/// `target` on every non-stiff reference problem, run `method` at rtol = atol = `rtol`;
/// `seconds` is the summed wall time over those problems.
///
/// Book: §4.11.
#[derive(Debug, Clone, PartialEq)]
pub struct Derived {
    /// Target global error.
    pub target: f64,
    /// Method name ("DP5" or "DOP853").
    pub method: &'static str,
    /// The largest swept rtol that met the target everywhere.
    pub rtol: f64,
    /// Summed wall time over the non-stiff problems at that rtol.
    pub seconds: f64,
}

/// Derives the [`crate::Accuracy`] table: for each target 10⁻³ … 10⁻¹², and each adaptive
/// pair, the largest swept rtol whose error is ≤ target on every non-stiff problem; the pair
/// with the smaller summed time wins.
///
/// Book: §4.11.
pub fn derive_accuracy(points: &[Point]) -> Vec<Derived> {
    let non_stiff: Vec<&str> = PROBLEMS.iter().copied().filter(|p| !p.starts_with("stiff")).collect();
    let mut rows = Vec::new();
    for k in 3..=12 {
        let target = 10f64.powi(-k);
        let mut best: Option<Derived> = None;
        for method in ["DP5", "DOP853"] {
            let mut rtols: Vec<f64> =
                points.iter().filter(|p| p.method == method).map(|p| p.param).collect::<Vec<_>>();
            rtols.sort_by(|a, b| b.total_cmp(a));
            rtols.dedup();
            for rtol in rtols {
                let runs: Vec<&Point> = points
                    .iter()
                    .filter(|p| {
                        p.method == method && p.param == rtol && non_stiff.contains(&p.problem.as_str())
                    })
                    .collect();
                if runs.len() == non_stiff.len() && runs.iter().all(|p| p.error <= target) {
                    let seconds = runs.iter().map(|p| p.seconds).sum();
                    if best.as_ref().is_none_or(|b| seconds < b.seconds) {
                        best = Some(Derived { target, method, rtol, seconds });
                    }
                    break;
                }
            }
        }
        rows.extend(best);
    }
    rows
}
