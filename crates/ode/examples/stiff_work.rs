//! Stiff work–precision of vectrix-ode's RADAU5 and BDF (exact Jacobians) and, on Van der Pol,
//! DOP853 (the wrong method): Robertson to t = 10⁵ (atol = 10⁻⁶·rtol) against scipy Radau at
//! 1e-13 (tests/data/stiff_reference.json), VDPOL (ε = 10⁻⁶, t = 2, atol = rtol) against the
//! Test Set. One markdown row per point: end error (largest relative component error), steps,
//! f-evaluations, median wall time of repeated runs (≥ 5 runs or 0.3 s). The scipy side in the
//! same sitting: `~/.venv-peers/bin/python scripts/peers/stiff_scipy.py`.
//!
//! Run: `cargo run --release -p vectrix-ode --example stiff_work` (docs/accuracy.md).

use std::time::Instant;

use nalgebra::{Vector2, Vector3};
use vectrix_ode::harness::{
    robertson, robertson_jacobian as robertson_jac, vdpol as vdp, vdpol_jacobian as vdp_jac,
};
use vectrix_ode::{Adaptive, Bdf, Radau5, Solution, State};

/// Median wall time of repeated runs, and the last run.
fn timed<S: State>(mut run: impl FnMut() -> Solution<S>) -> (f64, Solution<S>) {
    let (mut times, start) = (Vec::new(), Instant::now());
    let mut last = run();
    while times.len() < 5 || (start.elapsed().as_secs_f64() < 0.3 && times.len() < 200) {
        let t = Instant::now();
        last = run();
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], last)
}

fn row<S: State>(problem: &str, method: &str, rtol: f64, want: &[f64], (secs, sol): (f64, Solution<S>)) {
    let err = sol.last().as_slice().iter().zip(want).fold(0.0f64, |m, (g, w)| m.max(((g - w) / w).abs()));
    println!(
        "| {problem} | {method} | {rtol:.0e} | {err:.1e} | {} | {} | {secs:.2e} |",
        sol.work.accepted, sol.work.fevals
    );
}

fn main() {
    println!(
        "| problem | method | rtol | end error | steps | f-evals | time [s] |\n|---|---|---|---|---|---|---|"
    );
    let rob = [0.017865921142100057, 7.274751468436544e-08, 0.9821340061103884];
    let y0 = Vector3::new(1.0, 0.0, 0.0);
    for rtol in [1e-4, 1e-6, 1e-8, 1e-10] {
        let r = Radau5::new().rtol(rtol).atol(rtol * 1e-6);
        row(
            "Robertson t = 1e5",
            "RADAU5",
            rtol,
            &rob,
            timed(|| r.solve_with_jacobian(robertson, robertson_jac, 0.0, &y0, 1e5).unwrap()),
        );
        let b = Bdf::new().rtol(rtol).atol(rtol * 1e-6);
        row(
            "Robertson t = 1e5",
            "BDF",
            rtol,
            &rob,
            timed(|| b.solve_with_jacobian(robertson, robertson_jac, 0.0, &y0, 1e5).unwrap()),
        );
    }
    let want = [1.706167732170483, -0.8928097010247975];
    let y0 = Vector2::new(2.0, 0.0);
    for rtol in [1e-4, 1e-6, 1e-8, 1e-10] {
        let r = Radau5::new().rtol(rtol).atol(rtol);
        row(
            "VDPOL",
            "RADAU5",
            rtol,
            &want,
            timed(|| r.solve_with_jacobian(vdp, vdp_jac, 0.0, &y0, 2.0).unwrap()),
        );
        let b = Bdf::new().rtol(rtol).atol(rtol);
        row(
            "VDPOL",
            "BDF",
            rtol,
            &want,
            timed(|| b.solve_with_jacobian(vdp, vdp_jac, 0.0, &y0, 2.0).unwrap()),
        );
    }
    let a = Adaptive::dop853().rtol(1e-6).atol(1e-6);
    row("VDPOL", "DOP853 (wrong method)", 1e-6, &want, timed(|| a.solve(vdp, 0.0, &y0, 2.0).unwrap()));
}
