//! Dynamics benches: RNEA, ABA, CRBA and the analytical derivatives of RNEA and ABA on
//! revolute chains (n = 1, 6, 12, 30, the chain of `../shared/peers/bench_pinocchio.py` and
//! `benches/peers/pin_chain.cpp`), the same through dual numbers, rigid-body steps, and
//! Lagrangian accelerations of an n-link pendulum through dual numbers (n = 1..12, the system
//! of `bench_sympy.py`).
//!
//! Run: `cargo bench --bench dynamics -- --warm-up-time 1 --measurement-time 3`; beside
//! Pinocchio C++ in one sitting: `sh benches/peers/run.sh` (see docs/performance.md).
//!
//! Instruction counts (repeatable on a loaded machine): with `VECTRIX_ICOUNT=algo:n:iters`
//! the binary runs `iters` calls of one algorithm (`rnea`, `aba`, `aba_pair`, `aba_twice`,
//! `crba`, `rnea_derivatives`, `aba_derivatives`) on the n-link chain and exits, e.g.
//! `valgrind --tool=callgrind --callgrind-out-file=/tmp/x.out target/release/deps/dynamics-* `
//! with `VECTRIX_ICOUNT=crba:6:1000` and again with `:2000`; the difference / 1000 is the
//! count per call (set-up cancels).
use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use vectrix::dynamics::lagrange::accelerations;
use vectrix::dynamics::multibody::{AbaDerivatives, Joint, Link, Model, RneaDerivatives};
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;
use vectrix::statics::{MassProperties, Point, Wrench};

/// Pinocchio's benchmark chain: n revolute-Y joints, links of 0.3 along −z, unit masses
/// (planar: vectrix's ABA reduces it, `Model::planar_axis`).
fn pinocchio_chain(n: usize) -> Model {
    let (l, m) = (0.3, 1.0);
    let inertia = Matrix3::from_diagonal(&Vector3::new(m * l * l / 12.0, m * l * l / 12.0, 1e-4));
    let links: Vec<Link> = (0..n)
        .map(|i| {
            let offset = Vector3::new(0.0, 0.0, if i == 0 { 0.0 } else { -l });
            Link::new(
                i.checked_sub(1),
                Joint::Pin { axis: Vector3::y() },
                offset,
                m,
                Vector3::new(0.0, 0.0, -l / 2.0),
                inertia,
            )
        })
        .collect();
    let mut model = Model::new(&links).unwrap();
    model.gravity = Vector3::new(0.0, 0.0, -9.81);
    model
}

fn states(n: usize, count: usize) -> Vec<Vec<f64>> {
    // deterministic pseudo-random states in [−1, 1]
    let mut x = 0.123_456_789f64;
    (0..count)
        .map(|_| {
            (0..n)
                .map(|_| {
                    x = (x * 997.0 + 0.412_345_678).fract();
                    2.0 * x - 1.0
                })
                .collect()
        })
        .collect()
}

/// Everything one chain needs for the five algorithms, with caller-owned scratch.
struct Chain {
    model: Model,
    s: Vec<Vec<f64>>,
    scratch: vectrix::dynamics::multibody::Scratch,
    aba: vectrix::dynamics::multibody::AbaScratch,
    /// The same chain with the planar reduction off (the spatial passes).
    spatial: Model,
    crba: vectrix::dynamics::multibody::CrbaScratch,
    deriv: vectrix::dynamics::multibody::DerivativeScratch,
    h: vectrix::nalgebra::DMatrix<f64>,
    rd: RneaDerivatives,
    ad: AbaDerivatives,
    out: Vec<f64>,
    out2: Vec<f64>,
    k: usize,
}

impl Chain {
    fn new(n: usize) -> Self {
        let model = pinocchio_chain(n);
        let mut spatial = model.clone();
        spatial.disable_planar_reduction();
        Self {
            spatial,
            s: states(n, 64),
            scratch: model.scratch(),
            aba: model.aba_scratch(),
            crba: model.crba_scratch(),
            deriv: model.derivative_scratch(),
            h: vectrix::nalgebra::DMatrix::zeros(n, n),
            rd: RneaDerivatives::zeros(&model),
            ad: AbaDerivatives::zeros(&model),
            out: vec![0.0; n],
            out2: vec![0.0; n],
            k: 0,
            model,
        }
    }

    /// One call of `algo` on the next state; returns one output number.
    fn run(&mut self, algo: &str) -> f64 {
        self.k = (self.k + 1) % 61;
        let (q, v, a) = (&self.s[self.k], &self.s[self.k + 1], &self.s[self.k + 2]);
        match algo {
            "rnea" => {
                self.model.rnea_unchecked(q, v, a, &mut self.out, &mut self.scratch);
                self.out[0]
            }
            "aba" => {
                self.model.aba_unchecked(q, v, a, &mut self.out, &mut self.aba).unwrap();
                self.out[0]
            }
            // two states: one paired call, and two single calls (each pair's second state is
            // the next one's v, so that the two are different states)
            "aba_pair" => {
                let (first, second) = ((&q[..], &v[..]), (&v[..], &a[..]));
                let out = (&mut self.out[..], &mut self.out2[..]);
                self.model.aba_pair_unchecked(first, second, a, out, &mut self.aba).unwrap();
                self.out[0] + self.out2[0]
            }
            "aba_twice" => {
                self.model.aba_unchecked(q, v, a, &mut self.out, &mut self.aba).unwrap();
                self.model.aba_unchecked(v, a, a, &mut self.out2, &mut self.aba).unwrap();
                self.out[0] + self.out2[0]
            }
            "aba_spatial" => {
                self.spatial.aba_unchecked(q, v, a, &mut self.out, &mut self.aba).unwrap();
                self.out[0]
            }
            "crba" => {
                self.model.crba_into(q, &mut self.h, &mut self.crba);
                self.h[(0, 0)]
            }
            "rnea_derivatives" => {
                self.model.rnea_derivatives_into(q, v, a, None, &mut self.rd, &mut self.deriv);
                self.rd.dtau_dq[(0, 0)] + self.rd.dtau_dv[(0, 0)]
            }
            "aba_derivatives" => {
                self.model.aba_derivatives_into(q, v, a, None, &mut self.ad, &mut self.deriv).unwrap();
                self.ad.dvdot_dq[(0, 0)] + self.ad.dvdot_dv[(0, 0)] + self.ad.dvdot_dtau[(0, 0)]
            }
            other => panic!("unknown algorithm {other}"),
        }
    }
}

/// `aba` takes the planar passes on this chain (every pin about ŷ, `Model::planar_axis`);
/// `aba_spatial` is the same chain through the spatial passes, what a general tree costs;
/// `aba_pair` two states in one call (`Model::aba_pair_unchecked`, what GBS's paired rows
/// take) beside `aba_twice`, the same two states in two calls.
const ALGORITHMS: [&str; 8] =
    ["rnea", "aba", "aba_pair", "aba_twice", "aba_spatial", "crba", "rnea_derivatives", "aba_derivatives"];

fn tree_algorithms(c: &mut Criterion) {
    let mut g = c.benchmark_group("dynamics");
    for n in [1usize, 6, 12, 30] {
        let mut chain = Chain::new(n);
        for algo in ALGORITHMS {
            g.bench_with_input(BenchmarkId::new(algo, n), &n, |b, _| b.iter(|| black_box(chain.run(algo))));
        }
    }
    g.finish();
}

/// The dual-number route beside the analytical one: v̇ and one directional derivative
/// ∂v̇/∂q·e₀ by ABA over `Dual64` (a full Jacobian costs nv such passes).
fn dual_derivatives(c: &mut Criterion) {
    use vectrix::num_dual::Dual64;
    let mut g = c.benchmark_group("dynamics/dual");
    for n in [6usize, 30] {
        let model = pinocchio_chain(n).cast::<Dual64>();
        let s = states(n, 3);
        let lift = |x: &[f64]| x.iter().map(|&x| Dual64::from(x)).collect::<Vec<_>>();
        let mut q = lift(&s[0]);
        q[0].eps = 1.0;
        let (v, tau) = (lift(&s[1]), lift(&s[2]));
        let mut scratch = model.aba_scratch();
        let mut out = vec![Dual64::from(0.0); n];
        g.bench_with_input(BenchmarkId::new("aba_dual64_one_direction", n), &n, |b, _| {
            b.iter(|| {
                model.aba_unchecked(&q, &v, &tau, &mut out, &mut scratch).unwrap();
                black_box(out[0].eps)
            })
        });
    }
    g.finish();
}

/// `algo:n:iters` from an environment variable of the drivers below.
fn driver_spec(var: &str) -> Option<(String, usize, usize)> {
    let spec = std::env::var(var).ok()?;
    let parts: Vec<&str> = spec.split(':').collect();
    let bad = || panic!("{var} must be algo:n:iters, got {spec}");
    if parts.len() != 3 {
        bad();
    }
    Some((
        parts[0].to_string(),
        parts[1].parse().unwrap_or_else(|_| bad()),
        parts[2].parse().unwrap_or_else(|_| bad()),
    ))
}

/// `VECTRIX_TIME=algo:n:iters`: seven repetitions of `iters` calls, printed like the C++
/// harness (`benches/peers/pin_chain.cpp`: median, min, max per call), for interleaved runs
/// beside it on a loaded machine, where the minimum is the steadier figure.
fn time_driver() -> bool {
    let Some((algo, n, iters)) = driver_spec("VECTRIX_TIME") else { return false };
    let algo = algo.as_str();
    let mut chain = Chain::new(n);
    let mut sink = 0.0;
    let mut t: Vec<f64> = (0..7)
        .map(|_| {
            let t0 = std::time::Instant::now();
            for _ in 0..iters {
                sink += chain.run(algo);
            }
            t0.elapsed().as_secs_f64() / iters as f64
        })
        .collect();
    t.sort_by(f64::total_cmp);
    println!(
        "{{\"what\": \"vectrix {algo}\", \"n\": {n}, \"median\": {:.4e}, \"min\": {:.4e}, \"max\": {:.4e}, \"number\": {iters}, \"sink\": {}}}",
        t[3],
        t[0],
        t[6],
        black_box(sink).is_finite()
    );
    true
}

/// `VECTRIX_ICOUNT=algo:n:iters`: run one algorithm `iters` times and exit (for callgrind).
fn icount_driver() -> bool {
    let Some((algo, n, iters)) = driver_spec("VECTRIX_ICOUNT") else { return false };
    let algo = algo.as_str();
    let mut chain = Chain::new(n);
    let mut sink = 0.0;
    for _ in 0..iters {
        sink += chain.run(algo);
    }
    println!("{algo} n={n} iters={iters} sink={sink}");
    true
}

fn rigid_body_steps(c: &mut Criterion) {
    let mut g = c.benchmark_group("dynamics/rigid_body");
    let b = Frame::new();
    let props = MassProperties::new(
        1.0,
        Point::origin(),
        b.dyadic(&Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0))),
    )
    .unwrap();
    let torque = Wrench::torque(b.vector([0.01, 0.0, -0.02]), Point::origin());
    // one RK4 step of Euler's equation, frame-free (rank-aware solve in the principal frame)
    g.bench_function("rk4_step_frame_free", |bench| {
        let mut w = b.vector([0.3, 1.0, 0.2]);
        let h = 1e-3;
        bench.iter(|| {
            let acc =
                |w: &Vector| RigidBody::new(props, Vector::zero(), *w).accelerations(&torque).unwrap().1;
            let k1 = acc(&w);
            let k2 = acc(&(w + k1 * (h / 2.0)));
            let k3 = acc(&(w + k2 * (h / 2.0)));
            let k4 = acc(&(w + k3 * h));
            w += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
            black_box(w)
        })
    });
    // one semi-implicit Euler step of a free-floating body (free joint: ABA + quaternion update)
    let free = Model::new(&[Link::new(
        None,
        Joint::Free,
        Vector3::zeros(),
        1.0,
        Vector3::zeros(),
        Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
    )])
    .unwrap();
    g.bench_function("free_joint_aba_step", |bench| {
        let mut q = free.neutral();
        let mut v = vec![0.1, 0.0, 0.0, 0.3, 1.0, 0.2];
        let tau = vec![0.0; 6];
        let mut a = vec![0.0; 6];
        let mut s = free.aba_scratch();
        bench.iter(|| {
            free.aba_unchecked(&q, &v, &tau, &mut a, &mut s).unwrap();
            for (vi, ai) in v.iter_mut().zip(&a) {
                *vi += 1e-3 * ai;
            }
            q = free.integrate(&q, &v, 1e-3).unwrap();
            black_box(q[3])
        })
    });
    g.finish();
}

/// The n-link planar pendulum of bench_sympy.py: point masses m_i on massless rods l_i,
/// absolute angles, gravity along x.
struct NPendulum {
    n: usize,
}

impl Lagrangian for NPendulum {
    fn dof(&self) -> usize {
        self.n
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let (mut vx, mut vy, mut t) = (T::zero(), T::zero(), T::zero());
        for i in 0..self.n {
            // rod i along (cos q_i, sin q_i): velocity −sin q_i q̇_i, cos q_i q̇_i
            vx -= q[i].sin() * qd[i];
            vy += q[i].cos() * qd[i];
            t += T::lit(0.5) * (vx * vx + vy * vy);
        }
        t
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        let (mut x, mut u) = (T::zero(), T::zero());
        for qi in q.iter().take(self.n) {
            x += qi.cos();
            u -= T::lit(9.81) * x;
        }
        u
    }
}

fn lagrangian_pendulum(c: &mut Criterion) {
    let mut g = c.benchmark_group("dynamics/lagrange_dual");
    for n in [1usize, 2, 4, 6, 8, 12] {
        let sys = NPendulum { n };
        let s = states(n, 2);
        g.bench_with_input(BenchmarkId::new("accelerations", n), &n, |b, _| {
            b.iter(|| black_box(accelerations(&sys, &s[0], &s[1], 0.0).unwrap()[0]))
        });
    }
    g.finish();
}

criterion_group!(benches, tree_algorithms, dual_derivatives, rigid_body_steps, lagrangian_pendulum);

fn main() {
    if icount_driver() || time_driver() {
        return;
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
}
