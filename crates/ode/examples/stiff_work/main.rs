//! Stiff work–precision of vectrix-ode (issue 34 item 4): RADAU5 and BDF with exact Jacobians,
//! and DOP853 (the wrong method) beside them, on the five stiff problems of docs/accuracy.md
//! "Stiff problems" (see `problems.rs`): the damped spring chain, the pendulum on a stiff
//! spring, the hinge with a stiff damper, Robertson and Van der Pol μ = 1000 (VDPOL).
//!
//! `run` prints one JSON line per point — problem, tool, rtol, end error, steps, f-evals, LU
//! factorizations, Newton iterations, and the median wall time of repeated runs (≥ 5 runs or
//! 0.3 s) — in the schema of scripts/peers/stiff_scipy.py. `plot --data DIR --svg DIR` draws
//! one log–log panel per problem (error against time, one line per method) from the sitting's
//! JSON files. Both are run by `sh scripts/peers/stiff.sh`.
//!
//! Run: `cargo run --release -p vectrix-ode --example stiff_work -- run [--only chain] [--method RADAU5]`.

mod figure;
mod problems;

use std::time::Instant;

use nalgebra::SVector;
use problems::*;
use vectrix_ode::{Adaptive, Bdf, OdeError, Radau5, Solution};

/// Tolerances of the implicit methods and of DOP853.
const RTOLS: [f64; 7] = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10];
const DOP853_RTOLS: [f64; 4] = [1e-4, 1e-6, 1e-8, 1e-10];
/// DOP853 gives up here (Robertson to t = 10⁵ would need ~10⁹ steps at its stability limit).
const DOP853_MAX_STEPS: usize = 2_000_000;

/// Median wall time of repeated runs (≥ 5, or until 0.3 s, at most 200), and the last result.
fn timed<T>(mut run: impl FnMut() -> T) -> (f64, T) {
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

/// A JSON number; an infinite error (a failed run) as `Infinity`, which Python's json reads.
fn num(x: f64) -> String {
    if x.is_finite() { format!("{x:e}") } else { "Infinity".into() }
}

/// One problem: right-hand side, exact Jacobian, start, end time, atol/rtol and the error of an end state.
struct Problem<const D: usize> {
    id: &'static str,
    f: fn(f64, &SVector<f64, D>) -> SVector<f64, D>,
    jac: fn(f64, &SVector<f64, D>, &mut [f64]),
    y0: SVector<f64, D>,
    t_end: f64,
    atol_per_rtol: f64,
    err: ErrorOf<D>,
}

/// The error measure of an end state.
type ErrorOf<const D: usize> = Box<dyn Fn(&SVector<f64, D>) -> f64>;

/// A run's outcome: the solution, or the typed error that stopped it.
type Outcome<const D: usize> = Result<Solution<SVector<f64, D>>, OdeError>;

fn point<const D: usize>(p: &Problem<D>, tool: &str, rtol: f64, (secs, sol): (f64, Outcome<D>)) {
    let (err, w, note) = match &sol {
        Ok(s) => ((p.err)(s.last()), s.work, String::new()),
        Err(e) => (f64::INFINITY, Default::default(), format!(",\"note\":{:?}", e.to_string())),
    };
    println!(
        "{{\"problem\":\"{}\",\"tool\":\"vectrix {tool}\",\"rtol\":{rtol:e},\"err\":{},\"secs\":{secs:e},\"steps\":{},\"rejected\":{},\"fevals\":{},\"lu\":{},\"newton\":{},\"jacobians\":{}{note}}}",
        p.id,
        num(if err.is_nan() { f64::INFINITY } else { err }),
        w.accepted,
        w.rejected,
        w.fevals,
        w.factorizations,
        w.newton_iterations,
        w.jacobians,
    );
}

/// Which problem and method to run (`--only`, `--method`; all when `None`).
struct Filter {
    problem: Option<String>,
    method: Option<String>,
}

impl Filter {
    fn wants(&self, problem: &str, method: &str) -> bool {
        self.problem.as_deref().is_none_or(|p| p == problem)
            && self.method.as_deref().is_none_or(|m| m == method)
    }
}

fn sweep<const D: usize>(p: &Problem<D>, only: &Filter) {
    for rtol in RTOLS {
        let atol = rtol * p.atol_per_rtol;
        if only.wants(p.id, "RADAU5") {
            let r = Radau5::new().rtol(rtol).atol(atol);
            point(p, "RADAU5", rtol, timed(|| r.solve_with_jacobian(p.f, p.jac, 0.0, &p.y0, p.t_end)));
        }
        if only.wants(p.id, "BDF") {
            let b = Bdf::new().rtol(rtol).atol(atol);
            point(p, "BDF", rtol, timed(|| b.solve_with_jacobian(p.f, p.jac, 0.0, &p.y0, p.t_end)));
        }
    }
    for rtol in DOP853_RTOLS.into_iter().filter(|_| only.wants(p.id, "DOP853")) {
        let a = Adaptive::dop853().rtol(rtol).atol(rtol * p.atol_per_rtol).max_steps(DOP853_MAX_STEPS);
        point(p, "DOP853", rtol, timed(|| a.solve(p.f, 0.0, &p.y0, p.t_end)));
    }
}

/// y(t_end) of a case of tests/data/stiff_reference.json.
fn reference(name: &str) -> Vec<f64> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/stiff_reference.json");
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect(path)).expect("json");
    let case = v["cases"].as_array().and_then(|c| c.iter().find(|c| c["name"] == name)).expect(name);
    case["y"].as_array().expect("y").iter().map(|x| x.as_f64().expect("number")).collect()
}

fn run(only: &Filter) {
    let mut y0 = SVector::<f64, 12>::zeros();
    y0.as_mut_slice()[..N].copy_from_slice(&X0);
    let exact = chain_exact(CHAIN_T);
    let amplitude = X0.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    sweep(
        &Problem {
            id: "chain",
            f: chain,
            jac: chain_jacobian,
            y0,
            t_end: CHAIN_T,
            atol_per_rtol: 1e-3,
            err: Box::new(move |y| abs_err(&y.as_slice()[..N], &exact, amplitude)),
        },
        only,
    );
    let want = reference("spring_pendulum");
    sweep(
        &Problem {
            id: "pendulum",
            f: pendulum,
            jac: pendulum_jacobian,
            y0: pendulum_y0(),
            t_end: PEND_T,
            atol_per_rtol: 1.0,
            err: Box::new(move |y| abs_err(&y.as_slice()[..2], &want[..2], PEND_L0)),
        },
        only,
    );
    let want = damper_exact(DAMP_T);
    sweep(
        &Problem {
            id: "damper",
            f: damper,
            jac: damper_jacobian,
            y0: SVector::<f64, 2>::new(DAMP_THETA0, DAMP_OMEGA0),
            t_end: DAMP_T,
            atol_per_rtol: 1.0,
            err: Box::new(move |y| abs_err(&[y[0]], &[want], DAMP_THETA0)),
        },
        only,
    );
    let want = reference("robertson_1e5");
    sweep(
        &Problem {
            id: "robertson",
            f: robertson,
            jac: robertson_jacobian,
            y0: SVector::<f64, 3>::new(1.0, 0.0, 0.0),
            t_end: 1e5,
            atol_per_rtol: 1e-6,
            err: Box::new(move |y| rel_err(y.as_slice(), &want)),
        },
        only,
    );
    sweep(
        &Problem {
            id: "vdp",
            f: vdpol,
            jac: vdpol_jacobian,
            y0: SVector::<f64, 2>::new(2.0, 0.0),
            t_end: 2.0,
            atol_per_rtol: 1.0,
            err: Box::new(|y| rel_err(y.as_slice(), &VDPOL_END)),
        },
        only,
    );
}

fn arg(args: &[String], key: &str) -> Option<String> {
    args.iter().position(|a| a == key).and_then(|i| args.get(i + 1).cloned())
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    match args.get(1).map(String::as_str) {
        None | Some("run") => run(&Filter { problem: arg(&args, "--only"), method: arg(&args, "--method") }),
        Some("plot") => figure::plot(
            &arg(&args, "--data").unwrap_or_else(|| "docs/accuracy/stiff-data".into()),
            &arg(&args, "--svg").unwrap_or_else(|| "docs/accuracy".into()),
        ),
        Some(other) => {
            eprintln!(
                "usage: stiff_work [run [--only PROBLEM] [--method RADAU5|BDF|DOP853] | plot --data DIR --svg DIR] (got {other})"
            );
            std::process::exit(2);
        }
    }
}
