//! Kinematics benches: propagating an attitude 10⁶ steps in each representation (book §4.8–4.12)
//! under a constant body angular velocity, whose exact solution 𝓡(t) = 𝓡(0)e^{ω^×t} (F4.8.2)
//! gives the error. Before timing, a table of final errors (‖𝓡 − 𝓡_exact‖_max and the
//! orthonormality defect ‖𝓡ᵀ𝓡 − I‖_max) is printed; criterion then times each propagation.
//! A hand-written nalgebra `UnitQuaternion` loop is the peer baseline.
//!
//! Run: `cargo bench --bench kinematics -- --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;
use std::time::Instant;

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use vectrix::kinematics::attitude::{Propagator, propagate_attitude};
use vectrix::ode::LieMethod;
use vectrix::rotation::{EulerAngles, EulerSequence};

const STEPS: usize = 1_000_000;
const H: f64 = 1e-3;

fn setup() -> (Matrix3<f64>, Vector3<f64>) {
    (EulerAngles::new(EulerSequence::S321, [0.3, -0.4, 0.8]).rotation_matrix(), Vector3::new(0.5, -0.3, 0.9))
}

fn exp_so3(w: Vector3<f64>) -> Matrix3<f64> {
    let t = w.norm();
    let x = w.cross_matrix();
    let s = (0.5 * t).sin();
    Matrix3::identity() + x * (t.sin() / t) + x * x * (2.0 * s * s / (t * t))
}

fn methods() -> Vec<(&'static str, Propagator)> {
    vec![
        ("euler_321_rk4", Propagator::EulerRk4 { sequence: EulerSequence::S321, tol: 1e-12 }),
        ("euler_313_rk4", Propagator::EulerRk4 { sequence: EulerSequence::S313, tol: 1e-12 }),
        ("angle_vector_rk4", Propagator::AngleVectorRk4),
        ("quaternion_rk4", Propagator::QuaternionRk4 { renormalize: false }),
        ("quaternion_rk4_renorm", Propagator::QuaternionRk4 { renormalize: true }),
        ("gibbs_rk4", Propagator::GibbsRk4),
        ("mrp_rk4_shadow", Propagator::MrpRk4),
        ("poisson_rk4", Propagator::PoissonRk4 { renormalize: false }),
        ("poisson_rk4_renorm", Propagator::PoissonRk4 { renormalize: true }),
        ("quaternion_exact", Propagator::QuaternionExact),
        ("rotor_exp_euler", Propagator::RotorLie(LieMethod::ExponentialEuler)),
        ("rotor_rkmk4", Propagator::RotorLie(LieMethod::Rkmk4)),
        ("rotor_cg3", Propagator::RotorLie(LieMethod::CrouchGrossman3)),
        ("matrix_exp_euler", Propagator::MatrixLie(LieMethod::ExponentialEuler)),
        ("matrix_rkmk4", Propagator::MatrixLie(LieMethod::Rkmk4)),
    ]
}

/// The peer: nalgebra's unit quaternion, q ← q·exp(hω/2) per step, written by hand.
fn nalgebra_peer(r0: &Matrix3<f64>, w: Vector3<f64>) -> Matrix3<f64> {
    let mut q = UnitQuaternion::from_matrix(r0);
    let dq = UnitQuaternion::from_scaled_axis(w * H);
    for _ in 0..STEPS {
        q = black_box(q) * dq;
    }
    *q.to_rotation_matrix().matrix()
}

fn table() {
    let (r0, w) = setup();
    let t1 = H * STEPS as f64;
    let exact = r0 * exp_so3(w * t1);
    println!("\n| method | ‖𝓡 − 𝓡_exact‖_max | ‖𝓡ᵀ𝓡 − I‖_max | wall (one run) |");
    println!("|---|---|---|---|");
    let row = |name: &str, r: Result<Matrix3<f64>, String>, secs: f64| match r {
        Ok(r) => println!(
            "| {name} | {:.2e} | {:.2e} | {:.3} s |",
            (r - exact).amax(),
            (r.transpose() * r - Matrix3::identity()).amax(),
            secs
        ),
        Err(e) => println!("| {name} | fails: {e} | | {secs:.3} s |"),
    };
    for (name, m) in methods() {
        let start = Instant::now();
        let r = propagate_attitude(m, &r0, |_| w, 0.0, t1, STEPS).map_err(|e| e.to_string());
        row(name, r, start.elapsed().as_secs_f64());
    }
    let start = Instant::now();
    let r = nalgebra_peer(&r0, w);
    row("nalgebra UnitQuaternion (peer)", Ok(r), start.elapsed().as_secs_f64());
}

fn bench(c: &mut Criterion) {
    table();
    let (r0, w) = setup();
    let t1 = H * STEPS as f64;
    let mut g = c.benchmark_group("kinematics/propagate_1e6");
    g.sample_size(10);
    for (name, m) in methods() {
        g.bench_function(name, |b| b.iter(|| propagate_attitude(m, black_box(&r0), |_| w, 0.0, t1, STEPS)));
    }
    g.bench_function("nalgebra_unit_quaternion_peer", |b| b.iter(|| nalgebra_peer(black_box(&r0), w)));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
