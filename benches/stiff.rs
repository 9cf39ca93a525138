//! Stiff problems (issue 34): RADAU5 and BDF of vectrix-ode with exact Jacobians, and DOP853 where it
//! finishes, on Robertson's kinetics (t = 0..1e5), Van der Pol μ = 1000 in the Test Set's scaled form VDPOL (ε = 1e-6, t = 0..2) and the
//! damped spring chain of `tests/ode`'s `radau5.rs` (6 masses, k/m = 1e6, C = 1e-2 K,
//! t = 0..0.02) at rtol = 1e-6 and 1e-9. The end-time errors against the references
//! (tests/data/stiff_reference.json, VDPOL's published end state, the chain's modal closed form) and the peers (diffsol,
//! scipy) are in docs/accuracy.md, "Stiff problems".
//!
//! Run: `cargo bench --bench stiff -- --warm-up-time 1 --measurement-time 3`.
use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{SVector, Vector2, Vector3};
use vectrix::ode::harness::{
    robertson, robertson_jacobian as robertson_jac, vdpol as vdp, vdpol_jacobian as vdp_jac,
};
use vectrix::ode::{Adaptive, Bdf, Radau5};

const N: usize = 6;
type Chain = SVector<f64, 12>;

fn lap(v: &[f64], i: usize) -> f64 {
    let l = if i > 0 { v[i - 1] } else { 0.0 };
    let r = if i + 1 < N { v[i + 1] } else { 0.0 };
    2.0 * v[i] - l - r
}

fn chain(_: f64, y: &Chain) -> Chain {
    let mut d = Chain::zeros();
    let (x, v) = (&y.as_slice()[..N], &y.as_slice()[N..]);
    for i in 0..N {
        d[i] = v[i];
        d[N + i] = -1e6 * lap(x, i) - 1e4 * lap(v, i);
    }
    d
}

fn chain_jac(_: f64, _: &Chain, j: &mut [f64]) {
    j.fill(0.0);
    for i in 0..N {
        j[i * 2 * N + N + i] = 1.0;
        for (c, w) in [(i as isize - 1, -1.0), (i as isize, 2.0), (i as isize + 1, -1.0)] {
            if (0..N as isize).contains(&c) {
                j[(N + i) * 2 * N + c as usize] = -1e6 * w;
                j[(N + i) * 2 * N + N + c as usize] = -1e4 * w;
            }
        }
    }
}

fn stiff(c: &mut Criterion) {
    let mut g = c.benchmark_group("stiff");
    for rtol in [1e-6, 1e-9] {
        let r = Radau5::new().rtol(rtol).atol(rtol * 1e-6);
        let y0 = Vector3::new(1.0, 0.0, 0.0);
        g.bench_function(format!("robertson radau5 rtol {rtol:e}"), |b| {
            b.iter(|| r.solve_with_jacobian(robertson, robertson_jac, 0.0, black_box(&y0), 1e5).unwrap())
        });
        let bdf = Bdf::new().rtol(rtol).atol(rtol * 1e-6);
        g.bench_function(format!("robertson bdf rtol {rtol:e}"), |b| {
            b.iter(|| bdf.solve_with_jacobian(robertson, robertson_jac, 0.0, black_box(&y0), 1e5).unwrap())
        });
        let r = Radau5::new().rtol(rtol).atol(rtol);
        let y0 = Vector2::new(2.0, 0.0);
        g.bench_function(format!("vdp1000 radau5 rtol {rtol:e}"), |b| {
            b.iter(|| r.solve_with_jacobian(vdp, vdp_jac, 0.0, black_box(&y0), 2.0).unwrap())
        });
        let bdf = Bdf::new().rtol(rtol).atol(rtol);
        g.bench_function(format!("vdp1000 bdf rtol {rtol:e}"), |b| {
            b.iter(|| bdf.solve_with_jacobian(vdp, vdp_jac, 0.0, black_box(&y0), 2.0).unwrap())
        });
        let mut y0 = Chain::zeros();
        y0.as_mut_slice()[..N].copy_from_slice(&[1e-3, -2e-3, 0.5e-3, 1.5e-3, 0.0, -1e-3]);
        let r = Radau5::new().rtol(rtol).atol(rtol * 1e-3);
        g.bench_function(format!("chain radau5 rtol {rtol:e}"), |b| {
            b.iter(|| r.solve_with_jacobian(chain, chain_jac, 0.0, black_box(&y0), 0.02).unwrap())
        });
        // the wrong method: DOP853 at its stability limit on the same chain
        let a = Adaptive::dop853().rtol(rtol).atol(rtol * 1e-3);
        g.bench_function(format!("chain dop853 rtol {rtol:e}"), |b| {
            b.iter(|| a.solve(chain, 0.0, black_box(&y0), 0.02).unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, stiff);
criterion_main!(benches);
