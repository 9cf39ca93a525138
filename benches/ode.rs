//! Integrator benches and peers in the same run (issue 4, item 6).
//!
//! * DOP853 and DOPRI5 of vectrix-ode against the `ode_solvers` crate (Hairer's codes ported
//!   to Rust) on Kepler e = 0.5 and e = 0.9 at rtol = atol = 1e-10: time here, end-time error
//!   printed once before the timings; both store every step, no dense output (`ode_solvers`
//!   with `OutputType::Sparse`, since its default dense mode costs 3 more evaluations a step) (target: vectrix DOP853 no slower at equal or better
//!   error on e = 0.9).
//! * The torque-free rigid body of `../shared/peers/bench_rigidbody.py` (I = (1, 2, 3),
//!   ω₀ = (0.1, 2, 0.1), quaternion kinematics, t = 0..100, DOP853 at rtol = 1e-10,
//!   atol = 1e-12): target ≥ 50× faster than scipy's `solve_ivp(DOP853)` run in the same
//!   sitting.
//!
//! Run: `cargo bench --bench ode -- --warm-up-time 1 --measurement-time 3`.
use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{SVector, Vector3, Vector4};
use ode_solvers::{Dop853, Dopri5, OutputType, System};
use vectrix::ode::Adaptive;
use vectrix::ode::harness::{Kepler, Reference, euler_equations, quaternion_rate};

type State4 = SVector<f64, 4>;
type State7 = SVector<f64, 7>;
/// `ode_solvers` 0.6 is built on nalgebra 0.34: its own vector types.
type Peer4 = ode_solvers::SVector<f64, 4>;
type Peer7 = ode_solvers::SVector<f64, 7>;

/// The Kepler problem r̈ = −r/|r|³ as an `ode_solvers` system (same arithmetic as ours).
struct KeplerSys;

impl System<f64, Peer4> for KeplerSys {
    fn system(&self, _: f64, y: &Peer4, dy: &mut Peer4) {
        let r2 = y[0] * y[0] + y[1] * y[1];
        let r3 = r2 * r2.sqrt();
        *dy = Peer4::new(y[2], y[3], -y[0] / r3, -y[1] / r3);
    }
}

fn peer4(y: &State4) -> Peer4 {
    Peer4::from_fn(|i, _| y[i])
}

fn ours4(y: &Peer4) -> State4 {
    State4::from_fn(|i, _| y[i])
}

/// scipy's rigid body: y = (ω, q) with q scalar first here (the peer script stores it scalar
/// last; the dynamics are the same).
fn rigid_rhs(_: f64, y: &State7) -> State7 {
    let w = Vector3::new(y[0], y[1], y[2]);
    let dw = euler_equations(&[1.0, 2.0, 3.0], &w);
    let dq = quaternion_rate(&Vector4::new(y[3], y[4], y[5], y[6]), &w);
    State7::from_column_slice(&[dw[0], dw[1], dw[2], dq[0], dq[1], dq[2], dq[3]])
}

struct RigidSys;

impl System<f64, Peer7> for RigidSys {
    fn system(&self, t: f64, y: &Peer7, dy: &mut Peer7) {
        let d = rigid_rhs(t, &State7::from_fn(|i, _| y[i]));
        *dy = Peer7::from_fn(|i, _| d[i]);
    }
}

fn rigid_y0() -> State7 {
    State7::from_column_slice(&[0.1, 2.0, 0.1, 1.0, 0.0, 0.0, 0.0])
}

fn kepler(c: &mut Criterion) {
    const RTOL: f64 = 1e-10;
    for e in [0.5, 0.9] {
        let k = Kepler { e };
        let (y0, t1) = (k.y0(), k.t_end());
        // errors and work, once, outside the timings
        let ours = Adaptive::dop853().rtol(RTOL).atol(RTOL).solve(|t, y| k.rhs(t, y), 0.0, &y0, t1).unwrap();
        let ours5 = Adaptive::dopri5().rtol(RTOL).atol(RTOL).solve(|t, y| k.rhs(t, y), 0.0, &y0, t1).unwrap();
        let mut peer = Dop853::new(KeplerSys, 0.0, t1, t1, peer4(&y0), RTOL, RTOL);
        peer.set_output(OutputType::Sparse);
        let st = peer.integrate().unwrap();
        let peer_err = k.error(&ours4(peer.y_out().last().unwrap()));
        let mut peer5 = Dopri5::new(KeplerSys, 0.0, t1, t1, peer4(&y0), RTOL, RTOL);
        peer5.set_output(OutputType::Sparse);
        let st5 = peer5.integrate().unwrap();
        let peer5_err = k.error(&ours4(peer5.y_out().last().unwrap()));
        println!(
            "Kepler e={e} rtol={RTOL:e}: vectrix DOP853 error {:.2e} ({} f-evals) | ode_solvers Dop853 error {:.2e} ({} f-evals)",
            k.error(ours.last()),
            ours.work.fevals,
            peer_err,
            st.num_eval
        );
        println!(
            "Kepler e={e} rtol={RTOL:e}: vectrix DOPRI5 error {:.2e} ({} f-evals) | ode_solvers Dopri5 error {:.2e} ({} f-evals)",
            k.error(ours5.last()),
            ours5.work.fevals,
            peer5_err,
            st5.num_eval
        );
        let mut g = c.benchmark_group(format!("ode/kepler_e{e}_rtol1e-10"));
        g.bench_function("vectrix DOP853", |b| {
            b.iter(|| {
                Adaptive::dop853()
                    .rtol(RTOL)
                    .atol(RTOL)
                    .solve(|t, y| k.rhs(t, y), 0.0, black_box(&y0), t1)
                    .unwrap()
            })
        });
        g.bench_function("ode_solvers Dop853", |b| {
            b.iter(|| {
                let mut s = Dop853::new(KeplerSys, 0.0, t1, t1, black_box(peer4(&y0)), RTOL, RTOL);
                s.set_output(OutputType::Sparse);
                s.integrate().unwrap()
            })
        });
        g.bench_function("vectrix DOPRI5", |b| {
            b.iter(|| {
                Adaptive::dopri5()
                    .rtol(RTOL)
                    .atol(RTOL)
                    .solve(|t, y| k.rhs(t, y), 0.0, black_box(&y0), t1)
                    .unwrap()
            })
        });
        g.bench_function("ode_solvers Dopri5", |b| {
            b.iter(|| {
                let mut s = Dopri5::new(KeplerSys, 0.0, t1, t1, black_box(peer4(&y0)), RTOL, RTOL);
                s.set_output(OutputType::Sparse);
                s.integrate().unwrap()
            })
        });
        g.finish();
    }
}

fn rigid_body(c: &mut Criterion) {
    // scipy's settings: rtol = 1e-10, atol = rtol·1e-2
    const RTOL: f64 = 1e-10;
    const ATOL: f64 = 1e-12;
    let y0 = rigid_y0();
    let sol = Adaptive::dop853().rtol(RTOL).atol(ATOL).solve(rigid_rhs, 0.0, &y0, 100.0).unwrap();
    let y = sol.last();
    let w = Vector3::new(y[0], y[1], y[2]);
    let i = [1.0, 2.0, 3.0];
    let energy = |w: &Vector3<f64>| 0.5 * (i[0] * w[0] * w[0] + i[1] * w[1] * w[1] + i[2] * w[2] * w[2]);
    let w0 = Vector3::new(0.1, 2.0, 0.1);
    println!(
        "rigid body t=100 rtol=1e-10: vectrix DOP853 {} | |dE| = {:.1e}, |q|-1 = {:.1e}",
        sol.work,
        (energy(&w) - energy(&w0)).abs(),
        (Vector4::new(y[3], y[4], y[5], y[6]).norm() - 1.0).abs()
    );
    let mut g = c.benchmark_group("ode/rigidbody_t100_rtol1e-10");
    g.bench_function("vectrix DOP853", |b| {
        b.iter(|| {
            Adaptive::dop853().rtol(RTOL).atol(ATOL).solve(rigid_rhs, 0.0, black_box(&y0), 100.0).unwrap()
        })
    });
    g.bench_function("ode_solvers Dop853", |b| {
        b.iter(|| {
            let mut s =
                Dop853::new(RigidSys, 0.0, 100.0, 100.0, black_box(Peer7::from_fn(|i, _| y0[i])), RTOL, ATOL);
            s.set_output(OutputType::Sparse);
            s.integrate().unwrap()
        })
    });
    g.finish();
}

criterion_group!(benches, kepler, rigid_body);
criterion_main!(benches);
