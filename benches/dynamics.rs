//! Dynamics benches: RNEA, ABA, CRBA on revolute chains (n = 1, 6, 12, 30, the chain of
//! `../shared/peers/bench_pinocchio.py`), rigid-body steps, and Lagrangian accelerations of an
//! n-link pendulum through dual numbers (n = 1..12, the system of `bench_sympy.py`).
//!
//! Run: `cargo bench --bench dynamics -- --warm-up-time 1 --measurement-time 3`.
use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use vectrix::dynamics::lagrange::accelerations;
use vectrix::dynamics::multibody::{Joint, Link, Model};
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;
use vectrix::statics::{MassProperties, Point, Wrench};

/// Pinocchio's benchmark chain: n revolute-Y joints, links of 0.3 along −z, unit masses.
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

fn tree_algorithms(c: &mut Criterion) {
    let mut g = c.benchmark_group("dynamics");
    for n in [1usize, 6, 12, 30] {
        let model = pinocchio_chain(n);
        let s = states(n, 64);
        let mut scratch = model.scratch();
        let mut aba_scratch = model.aba_scratch();
        let mut out = vec![0.0; n];
        let mut k = 0usize;
        g.bench_with_input(BenchmarkId::new("rnea", n), &n, |b, _| {
            b.iter(|| {
                k = (k + 1) % 61;
                model.rnea_unchecked(&s[k], &s[k + 1], &s[k + 2], &mut out, &mut scratch);
                black_box(out[0])
            })
        });
        g.bench_with_input(BenchmarkId::new("aba", n), &n, |b, _| {
            b.iter(|| {
                k = (k + 1) % 61;
                model.aba_unchecked(&s[k], &s[k + 1], &s[k + 2], &mut out, &mut aba_scratch).unwrap();
                black_box(out[0])
            })
        });
        g.bench_with_input(BenchmarkId::new("crba", n), &n, |b, _| {
            b.iter(|| {
                k = (k + 1) % 61;
                black_box(model.crba_unchecked(&s[k])[(0, 0)])
            })
        });
    }
    g.finish();
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

criterion_group!(benches, tree_algorithms, rigid_body_steps, lagrangian_pendulum);
criterion_main!(benches);
