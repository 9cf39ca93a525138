//! Constrained dynamics benches (book §9.11): the four-bar of `tests/ch09/four_bar.rs` through
//! the library route (`MapForm`: T built from the bar poses, constraint terms by dual numbers,
//! the KKT solve), one f-eval and 2 s runs of `ConstrainedIntegrator` (DOPRI5, projection
//! after each accepted step) at a ladder of tolerances, each run's error |θ₂(2 s) − θ₂,ref|
//! printed once beside it. The MuJoCo side of the comparison is
//! `scripts/peers/bench_mujoco_four_bar.py` (same mechanism, same reference: scipy DOP853 at
//! rtol 1e-12, which `examples/constraints_accuracy.rs` reproduces to 12 digits).
//!
//! Run: `cargo bench --bench constraints -- --warm-up-time 1 --measurement-time 3`.
#[path = "../tests/ch09/mechanisms.rs"]
mod mechanisms;

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use mechanisms::FourBar;
use vectrix::dynamics::constraints::{ConstrainedIntegrator, MapForm, map_constrained_accelerations};
use vectrix::ode::Adaptive;

/// θ₂(2 s) from scipy's DOP853 at rtol 1e-12 (scripts/peers/bench_mujoco_four_bar.py).
const THETA2_REF: f64 = 12.118579864419;

fn four_bar(c: &mut Criterion) {
    let fb = FourBar { a: 1.0, b: 3.5, c: 3.0, d: 4.0, rho: 1.0, g: 9.81 };
    let (q0, qd0) = fb.start(0.3, &[0.3, 1.2, 1.9], 6.0);
    c.bench_function("constraints/four_bar f-eval (MapForm, KKT)", |b| {
        b.iter(|| {
            map_constrained_accelerations(black_box(&fb), black_box(&q0), black_box(&qd0), 0.0).unwrap()
        })
    });
    let mut g = c.benchmark_group("constraints/four_bar_2s_dopri5_projected");
    for rtol in [1e-6, 1e-8, 1e-10] {
        let integrator = ConstrainedIntegrator::new(Adaptive::dopri5().rtol(rtol).atol(rtol));
        let run = integrator.integrate(&MapForm(&fb), &q0, &qd0, 0.0, 2.0).unwrap();
        let last = run.t.len() - 1;
        eprintln!(
            "rtol {rtol:.0e}: |θ₂ − θ₂,ref| = {:.1e}, max |φ| = {:.1e}, f-evals {}, steps {}",
            (run.q(last)[0] - THETA2_REF).abs(),
            run.max_constraint_violation.position,
            run.work.fevals,
            run.work.accepted
        );
        g.bench_with_input(BenchmarkId::from_parameter(format!("{rtol:.0e}")), &integrator, |b, integ| {
            b.iter(|| integ.integrate(&MapForm(black_box(&fb)), &q0, &qd0, 0.0, 2.0).unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, four_bar);
criterion_main!(benches);
