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
/// pair, the largest swept rtol whose error is ≤ target on every non-stiff problem (a problem
/// whose sweep stopped at the round-off floor at a looser rtol counts with that run); the pair
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
                // each problem's run at rtol, or the run at which its line stopped at the
                // round-off floor ([`crate::harness::sweep`]: error < 1e-13 at a looser rtol,
                // which a stricter one is not run to improve on; its time a lower bound)
                let runs: Vec<&Point> = non_stiff
                    .iter()
                    .filter_map(|name| {
                        let line = points.iter().filter(|p| p.method == method && p.problem == *name);
                        line.clone()
                            .find(|p| p.param == rtol)
                            .or_else(|| line.rev().find(|p| p.param > rtol && p.error < 1e-13))
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

#[cfg(test)]
mod tests {
    use super::{PROBLEMS, derive_accuracy};
    use crate::Work;
    use crate::harness::Point;

    fn point(problem: &str, param: f64, error: f64) -> Point {
        let work = Work::default();
        Point { problem: problem.into(), method: "DOP853", param, error, seconds: 1e-5, work, drift: None }
    }

    /// A problem whose sweep stopped at the round-off floor at a looser rtol still counts for a
    /// stricter target (with that run); one that stopped above the target does not.
    #[test]
    fn a_sweep_stopped_at_the_floor_meets_stricter_targets() {
        let non_stiff: Vec<&str> = PROBLEMS.iter().copied().filter(|p| !p.starts_with("stiff")).collect();
        let mut pts = Vec::new();
        // the first problem's line ended at rtol 1e-12 (8e-14 < 1e-13)
        pts.push(point(non_stiff[0], 1e-12, 8e-14));
        for name in &non_stiff[1..] {
            pts.push(point(name, 1e-12, 5e-11));
            pts.push(point(name, 1e-13, 4e-12));
        }
        let rows = derive_accuracy(&pts);
        let row = rows.iter().find(|r| r.target == 1e-11).expect("a 1e-11 row");
        assert_eq!((row.method, row.rtol), ("DOP853", 1e-13));
        // every problem's run summed once (to rounding)
        let want = 1e-5 * non_stiff.len() as f64;
        assert!((row.seconds - want).abs() <= 1e-15 * want * 8.0, "{}", row.seconds);
        // no rtol reaches 1e-12 on every problem
        assert!(rows.iter().all(|r| r.target > 1e-12));
    }
}
