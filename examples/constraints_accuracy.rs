//! Accuracy of constrained dynamics (book §9.11–9.14), for docs/accuracy.md:
//!
//! 1. a four-bar under gravity for 60 s at several tolerances, with and without projection
//!    after each accepted step: constraint violation, energy error, work;
//! 2. the Cartesian double pendulum (two rod constraints) against its joint coordinates on a
//!    grid of states including the hard set (hanging, inverted);
//! 3. Kane's equations of the rolling disk against sympy's KanesMethod
//!    (tests/data/ch09_kane_rolling_disk.json) and against Lagrange's equations with
//!    multipliers.
//!
//! Run: `cargo run --release --example constraints_accuracy` (deterministic).

#[path = "../tests/ch09/mechanisms.rs"]
mod mechanisms;
#[path = "../tests/ch09/rolling.rs"]
mod rolling;

use std::f64::consts::PI;

use mechanisms::{CartesianDoublePendulum, FourBar, JointDoublePendulum};
use rolling::{KaneDisk, RollingDisk};
use vectrix::dynamics::constraints::kane::kane_accelerations;
use vectrix::dynamics::constraints::{
    ConstrainedIntegrator, MapForm, constrained_accelerations, map_constrained_accelerations,
};
use vectrix::dynamics::lagrange::{accelerations, map_kinetic_energy};
use vectrix::ode::Adaptive;
use vectrix::prelude::*;

fn four_bar_table() {
    let fb = FourBar { a: 1.0, b: 3.5, c: 3.0, d: 4.0, rho: 1.0, g: 9.81 };
    let (q0, qd0) = fb.start(0.3, &[0.3, 1.2, 1.9], 6.0);
    let energy = |q: &[f64], qd: &[f64]| {
        map_kinetic_energy(&fb, q, qd, 0.0).expect("finite") + KinematicMap::potential(&fb, q, 0.0)
    };
    let e0 = energy(&q0, &qd0);
    // the state scripts/peers/bench_mujoco_four_bar.py takes as its reference (from scipy)
    let tight = ConstrainedIntegrator::new(Adaptive::dop853().rtol(1e-12).atol(1e-12))
        .integrate(&MapForm(&fb), &q0, &qd0, 0.0, 2.0)
        .expect("runs");
    println!("four-bar θ₂(2 s) = {:.12} (DOP853, rtol 1e-12, projected)\n", tight.q(tight.t.len() - 1)[0]);
    println!("## four-bar, 60 s, DOPRI5 (rtol = atol)\n");
    println!(
        "| rtol | projection | max \\|φ\\|∞ | max \\|Φ_q q̇\\|∞ | max rel. energy error | f-evals | projections |"
    );
    println!("|---|---|---|---|---|---|---|");
    for rtol in [1e-6, 1e-8, 1e-10] {
        for project in [true, false] {
            let mut integrator = ConstrainedIntegrator::new(Adaptive::dopri5().rtol(rtol).atol(rtol));
            integrator.project_steps = project;
            let run = integrator.integrate(&MapForm(&fb), &q0, &qd0, 0.0, 60.0).expect("runs");
            let e_err =
                (0..run.t.len()).map(|i| ((energy(run.q(i), run.qd(i)) - e0) / e0).abs()).fold(0.0, f64::max);
            let v = run.max_constraint_violation;
            println!(
                "| {rtol:.0e} | {} | {:.1e} | {:.1e} | {e_err:.1e} | {} | {} |",
                if project { "every step" } else { "none" },
                v.position,
                v.velocity,
                run.work.fevals,
                run.projections
            );
        }
    }
}

fn double_pendulum_table() {
    let p = CartesianDoublePendulum { m1: 1.2, m2: 0.7, l1: 1.0, l2: 0.6, g: 9.81 };
    let angles = [0.0, 1e-8, 0.5, PI / 2.0, 2.5, PI - 1e-8, PI, -PI / 3.0];
    let mut worst: f64 = 0.0;
    let mut count = 0;
    for &a in &angles {
        for &b in &angles {
            for w in [[0.0, 0.0], [1.5, -3.0], [-6.0, 6.0]] {
                let alpha = accelerations(&JointDoublePendulum(&p), &[a, b], &w, 0.0).expect("regular");
                let ((s1, c1), (s2, c2)) = (a.sin_cos(), b.sin_cos());
                let q = [s1, -c1, s1 + 0.6 * s2, -c1 - 0.6 * c2];
                let qd = [c1 * w[0], s1 * w[0], c1 * w[0] + 0.6 * c2 * w[1], s1 * w[0] + 0.6 * s2 * w[1]];
                let a1 = [c1 * alpha[0] - s1 * w[0] * w[0], s1 * alpha[0] + c1 * w[0] * w[0]];
                let a21 =
                    [0.6 * (c2 * alpha[1] - s2 * w[1] * w[1]), 0.6 * (s2 * alpha[1] + c2 * w[1] * w[1])];
                let want = [a1[0], a1[1], a1[0] + a21[0], a1[1] + a21[1]];
                let s = constrained_accelerations(&p, &q, &qd, 0.0).expect("independent rods");
                let scale = p.g + w[0] * w[0] + w[1] * w[1];
                for (got, want) in s.qdd.iter().zip(want) {
                    worst = worst.max((got - want).abs() / (f64::EPSILON * scale));
                }
                count += 1;
            }
        }
    }
    println!("\n## Cartesian double pendulum vs joint coordinates\n");
    println!("{count} states (θ over 0, 1e-8, π/2, π − 1e-8, π, …): max |Δq̈| = {worst:.1} ε·(g + θ̇₁² + θ̇₂²)");
}

fn kane_table() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/ch09_kane_rolling_disk.json");
    let data: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("reference data")).expect("JSON");
    let (m, r, g) =
        (data["params"]["m"].as_f64(), data["params"]["r"].as_f64(), data["params"]["g"].as_f64());
    let (m, r, g) = (m.expect("m"), r.expect("r"), g.expect("g"));
    let disk = RollingDisk { m, r, g, incline: 0.0, all_rows: false };
    let sys = KaneDisk(RollingDisk { m, r, g, incline: 0.0, all_rows: false });
    let (mut vs_sympy, mut vs_lagrange): (f64, f64) = (0.0, 0.0);
    let cases = data["cases"].as_array().expect("cases");
    for case in cases {
        let lean = case["lean"].as_f64().expect("lean");
        let u: Vec<f64> =
            case["u"].as_array().expect("u").iter().map(|x| x.as_f64().expect("number")).collect();
        let want: Vec<f64> = case["udot"]
            .as_array()
            .expect("udot")
            .iter()
            .map(|x| x.as_str().expect("string").parse().expect("number"))
            .collect();
        let q = [0.3, -1.0, 0.4, lean, 1.3];
        let k = kane_accelerations(&sys, &q, &u, 0.0).expect("regular");
        let scale = (disk.g / disk.r + u.iter().map(|x| x * x).sum::<f64>()) / lean.cos();
        for (got, want) in k.ud.iter().zip(&want) {
            vs_sympy = vs_sympy.max((got - want).abs() / (f64::EPSILON * scale));
        }
        // the same state through Lagrange's equations with the two no-slip multipliers
        let (s, c) = lean.sin_cos();
        let psid = u[2] / c;
        let qd = disk.rolling_rates(&q, [psid, u[0], u[1] - psid * s]);
        let l = map_constrained_accelerations(&disk, &q, &qd, 0.0).expect("regular");
        let rate = [l.qdd[3], l.qdd[2] * s + qd[2] * qd[3] * c + l.qdd[4], l.qdd[2] * c - qd[2] * qd[3] * s];
        for (got, want) in k.ud.iter().zip(rate) {
            vs_lagrange = vs_lagrange.max((got - want).abs() / (f64::EPSILON * scale));
        }
    }
    println!("\n## Rolling disk, Kane's equations (u = ω|_L)\n");
    println!(
        "{} states: max |Δu̇| vs sympy KanesMethod = {vs_sympy:.2} ε·scale; vs Lagrange with multipliers = {vs_lagrange:.2} ε·scale (scale = (g/r + |u|²)/cos θ)",
        cases.len()
    );
}

fn main() {
    four_bar_table();
    double_pendulum_table();
    kane_table();
}
