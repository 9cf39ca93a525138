//! Linear-systems benches (book ch. 15–16) beside python-control and scipy, which are timed
//! in the same sitting by `~/.venv-peers/bin/python /work/shared/peers/bench_control.py`.
//!
//! The system is a stable 10th-order SISO state-space model built like python-control's
//! `rss(10, 1, 1)`: five complex pole pairs, a random similarity transform, random B and C
//! (a fixed linear-congruential generator, so every run times the same system).
use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::DMatrix;
use std::hint::black_box;
use vectrix::lti::*;

/// Deterministic uniform numbers in [−1, 1).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
}

fn rss10() -> StateSpace {
    let mut r = Lcg(7);
    let n = 10;
    let mut j = DMatrix::zeros(n, n);
    for k in 0..5 {
        let sigma = -0.1 - 1.9 * (r.next() + 1.0) / 2.0;
        let omega = 0.1 + 9.9 * (r.next() + 1.0) / 2.0;
        j[(2 * k, 2 * k)] = sigma;
        j[(2 * k + 1, 2 * k + 1)] = sigma;
        j[(2 * k, 2 * k + 1)] = omega;
        j[(2 * k + 1, 2 * k)] = -omega;
    }
    let t = DMatrix::from_fn(n, n, |i, k| if i == k { 1.0 } else { 0.0 } + 0.3 * r.next());
    let a = &t * j * t.clone().try_inverse().expect("well-conditioned transform");
    let b = DMatrix::from_fn(n, 1, |_, _| r.next());
    let c = DMatrix::from_fn(1, n, |_, _| r.next());
    StateSpace::new(a, b, c, DMatrix::zeros(1, 1)).expect("valid model")
}

fn random_matrix(n: usize, seed: u64) -> DMatrix<f64> {
    let mut r = Lcg(seed);
    // Like the peer script: standard-normal-ish entries / √n (uniform with the same variance).
    DMatrix::from_fn(n, n, |_, _| r.next() * 3f64.sqrt() / (n as f64).sqrt())
}

fn benches(c: &mut Criterion) {
    let sys = rss10();
    let g = sys.to_tf(0, 0).expect("tf");
    let zpk = g.to_zpk().expect("zpk");
    let w = logspace(-2.0, 3.0, 1000).expect("grid");
    let t = time_grid(20.0, 1000).expect("grid");

    c.bench_function("lti/freqresp zpk (n=10, 1000 w)", |b| b.iter(|| zpk.freqresp(black_box(&w))));
    // a transfer function computes its zeros and poles once and caches them: "first call"
    // rows build a fresh tf in every iteration (as the peers recompute everything per call)
    let fresh = || TransferFunction::from_polynomials(g.num().clone(), g.den().clone()).expect("tf");
    c.bench_function("lti/freqresp tf first call (n=10, 1000 w)", |b| {
        b.iter(|| black_box(fresh()).freqresp(&w))
    });
    c.bench_function("lti/bode tf first call (roots + dB + continuous phase)", |b| {
        b.iter(|| black_box(fresh()).bode(&w))
    });
    c.bench_function("lti/freqresp ss (ss→tf, G(jω), n=10, 1000 w)", |b| {
        b.iter(|| black_box(&sys).to_tf(0, 0).and_then(|g| g.freqresp(&w)))
    });
    c.bench_function("lti/bode ss (ss→tf→zpk, dB + phase)", |b| {
        b.iter(|| black_box(&sys).bode(0, 0, &w))
    });
    c.bench_function("lti/margins tf first call (n=10)", |b| b.iter(|| black_box(fresh()).margins()));
    c.bench_function("lti/margins ss (incl. ss→tf)", |b| {
        b.iter(|| black_box(&sys).to_tf(0, 0).and_then(|g| g.margins()))
    });
    c.bench_function("lti/step ss (n=10, 1000 t)", |b| {
        b.iter(|| response(black_box(&sys), InputKind::Step, 0, 1.0, 0.0, &t))
    });
    c.bench_function("lti/step tf first call (n=10, 1000 t)", |b| b.iter(|| black_box(fresh()).step(&t)));
    c.bench_function("lti/ss2tf (n=10)", |b| b.iter(|| black_box(&sys).to_tf(0, 0)));
    for (n, seed) in [(10, 1), (100, 2)] {
        let m = random_matrix(n, seed);
        c.bench_function(&format!("lti/expm {n}x{n}"), |b| b.iter(|| expm(black_box(&m))));
        let m10 = &m * 10.0;
        c.bench_function(&format!("lti/expm {n}x{n} (x10 scaled)"), |b| b.iter(|| expm(black_box(&m10))));
    }
}

criterion_group!(lti, benches);
criterion_main!(lti);
