//! The integrator's own cost per evaluation on a small state (issue 39, "Compiled peers" in
//! docs/performance.md): Kepler e = 0.9 (`vectrix::ode::harness::Kepler`, HNW §II.10's test
//! problem) through DOP853 at rtol = atol = 1e-9, REPS whole runs through `Adaptive::solve`
//! (which keeps every accepted step) or through a bare `Stepper` loop (which keeps none). Meant
//! for instruction counts, which do not depend on the machine's load:
//!
//! ```sh
//! cargo build --release --example ode_overhead
//! for r in 100 200; do valgrind --tool=callgrind target/release/examples/ode_overhead solve $r; done
//! ```
//!
//! (the difference of the two totals over 100 runs and the printed evaluations give the
//! instructions per evaluation; `stepper` instead of `solve` for the bare loop).
use nalgebra::Vector4;
use vectrix::ode::explicit::{Adaptive, Stepper};
use vectrix::ode::harness::{Kepler, Reference};
fn main() {
    let k = Kepler { e: 0.9 };
    let mode = std::env::args().nth(1).unwrap_or_default();
    if mode != "solve" && mode != "stepper" {
        eprintln!("usage: ode_overhead solve|stepper [REPS]");
        std::process::exit(2);
    }
    let reps: usize = std::env::args().nth(2).and_then(|s| s.parse().ok()).unwrap_or(1);
    let a = Adaptive::dop853().rtol(1e-9).atol(1e-9);
    let f = |t: f64, y: &Vector4<f64>| k.rhs(t, y);
    let mut acc = 0.0;
    let mut fe = 0;
    for _ in 0..reps {
        if mode == "solve" {
            let s = a.solve(f, 0.0, &k.y0(), k.t_end()).expect("Kepler e = 0.9 integrates at 1e-9");
            acc += s.last()[0];
            fe = s.work.fevals;
        } else {
            let mut st = Stepper::new(&a, f, 0.0, k.y0(), k.t_end()).expect("a valid configuration");
            while !st.done() {
                st.step().expect("Kepler e = 0.9 integrates at 1e-9");
            }
            acc += st.y()[0];
            fe = st.work().fevals;
        }
    }
    println!("{mode} {acc} fevals {fe}");
}
