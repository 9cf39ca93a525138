//! Rotation benches: every conversion, compose and apply, each beside nalgebra's equivalent in
//! the same run (DESIGN §6). Each iteration processes a batch of N random rotations, so the
//! figures are per rotation (divide by N; criterion's throughput line shows elements/s).
//!
//! The `batched_1e6` group times the batched (SIMD) conversions on 10⁶ rotations per call, the
//! size of scipy's batched calls.
//!
//! Run: `cargo bench --bench rotation -- --warm-up-time 1 --measurement-time 3`.
//!
//! Instruction counts (repeatable on a loaded machine): with `VECTRIX_ICOUNT=conversion:passes`
//! the binary runs `passes` passes of one conversion over the N inputs and exits (the names
//! are those of [`icount_driver`]); run it under `valgrind --tool=callgrind` at 1000 and 2000
//! passes, and the difference / (1000·N) is the count per conversion (set-up cancels).
//! Peer (scipy, batched, per rotation): `~/.venv-peers/bin/python ../shared/peers/bench_rotation.py`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group};
use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};
use vectrix::prelude::*;

const N: usize = 256;

/// Deterministic pseudo-random numbers (xorshift), no extra dependency.
fn rng(seed: &mut u64) -> f64 {
    *seed ^= *seed << 13;
    *seed ^= *seed >> 7;
    *seed ^= *seed << 17;
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

struct Data {
    a: Frame,
    rot: Vec<Rotation>,
    quat: Vec<Quaternion>,
    mat: Vec<Matrix3<f64>>,
    rotvec: Vec<Vector3<f64>>,
    gibbs: Vec<Vector3<f64>>,
    mrp: Vec<Vector3<f64>>,
    euler: Vec<EulerAngles>,
    vecs: Vec<Vector3<f64>>,
    pvecs: Vec<Vector>,
    na_q: Vec<UnitQuaternion<f64>>,
    na_r: Vec<Rotation3<f64>>,
}

fn data() -> Data {
    let mut s = 0x9E37_79B9_7F4A_7C15u64;
    let a = Frame::new();
    let mut quat = Vec::new();
    for _ in 0..N {
        let q = Quaternion::new(rng(&mut s) - 0.5, rng(&mut s) - 0.5, rng(&mut s) - 0.5, rng(&mut s) - 0.5);
        quat.push(q.normalize().expect("nonzero").canonical());
    }
    let rot: Vec<Rotation> =
        quat.iter().map(|q| Rotation::from_quaternion_in(&a, q, 1e-12).expect("unit")).collect();
    let mat: Vec<Matrix3<f64>> = quat.iter().map(|q| q.rotation_matrix()).collect();
    let vecs: Vec<Vector3<f64>> =
        (0..N).map(|_| Vector3::new(rng(&mut s) - 0.5, rng(&mut s) - 0.5, rng(&mut s) - 0.5)).collect();
    Data {
        rotvec: quat.iter().map(|q| q.angle_vector()).collect(),
        gibbs: quat.iter().map(|q| q.gibbs().expect("not π")).collect(),
        mrp: quat.iter().map(|q| q.mrp()).collect(),
        euler: quat
            .iter()
            .map(|q| EulerAngles::from_quaternion(q, EulerSequence::S321).principal())
            .collect(),
        pvecs: vecs.iter().map(|v| a.vector([v.x, v.y, v.z])).collect(),
        na_q: quat.iter().map(|q| q.to_unit_quaternion()).collect(),
        na_r: mat.iter().map(|m| Rotation3::from_matrix_unchecked(*m)).collect(),
        a,
        rot,
        quat,
        mat,
        vecs,
    }
}

/// Benches `f` over the batch as `group/name`.
fn run<I, O>(c: &mut Criterion, group: &str, name: &str, inputs: &[I], f: impl Fn(&I) -> O) {
    let mut g = c.benchmark_group(group);
    g.throughput(Throughput::Elements(inputs.len() as u64));
    g.bench_function(BenchmarkId::from_parameter(name), |b| {
        b.iter(|| {
            for x in black_box(inputs) {
                black_box(f(x));
            }
        })
    });
    g.finish();
}

fn compose_apply(c: &mut Criterion) {
    let d = data();
    let pairs: Vec<(Rotation, Rotation)> =
        d.rot.iter().zip(d.rot.iter().rev()).map(|(x, y)| (*x, *y)).collect();
    let na_pairs: Vec<_> = d.na_q.iter().zip(d.na_q.iter().rev()).map(|(x, y)| (*x, *y)).collect();
    let dy_pairs: Vec<_> = pairs.iter().map(|(x, y)| (x.to_dyadic(), y.to_dyadic())).collect();
    let r3_pairs: Vec<_> = d.na_r.iter().zip(d.na_r.iter().rev()).map(|(x, y)| (*x, *y)).collect();
    let q_pairs: Vec<_> = d.quat.iter().zip(d.quat.iter().rev()).map(|(x, y)| (*x, *y)).collect();
    run(c, "compose", "vectrix Rotation (rotor)", &pairs, |(x, y)| *x * *y);
    run(c, "compose", "vectrix Dyadic (dyad)", &dy_pairs, |(x, y)| *x * *y);
    run(c, "compose", "vectrix compose_quaternion", &q_pairs, |(x, y)| compose_quaternion(x, y));
    run(c, "compose", "nalgebra UnitQuaternion", &na_pairs, |(x, y)| x * y);
    run(c, "compose", "nalgebra Rotation3", &r3_pairs, |(x, y)| x * y);

    let rv: Vec<_> = d.rot.iter().zip(&d.pvecs).map(|(r, v)| (*r, *v)).collect();
    let dv: Vec<_> = d.rot.iter().zip(&d.pvecs).map(|(r, v)| (r.to_dyadic(), *v)).collect();
    let nv: Vec<_> = d.na_q.iter().zip(&d.vecs).map(|(r, v)| (*r, *v)).collect();
    let n3: Vec<_> = d.na_r.iter().zip(&d.vecs).map(|(r, v)| (*r, *v)).collect();
    run(c, "apply", "vectrix Rotation (rotor)", &rv, |(r, v)| r.apply(v));
    run(c, "apply", "vectrix Dyadic (dyad)", &dv, |(r, v)| r.apply(v));
    run(c, "apply", "nalgebra UnitQuaternion", &nv, |(r, v)| r * v);
    run(c, "apply", "nalgebra Rotation3", &n3, |(r, v)| r * v);
}

fn conversions(c: &mut Criterion) {
    let d = data();
    let a = d.a;
    // matrix → quaternion
    run(
        c,
        "matrix_to_quaternion",
        "vectrix (Shepperd/Markley)",
        &d.mat,
        Quaternion::from_rotation_matrix_unchecked,
    );
    run(c, "matrix_to_quaternion", "vectrix checked", &d.mat, |m| {
        Quaternion::from_rotation_matrix(m, ROTATION_TOL)
    });
    run(
        c,
        "matrix_to_quaternion",
        "nalgebra from_rotation_matrix",
        &d.na_r,
        UnitQuaternion::from_rotation_matrix,
    );
    // quaternion → matrix
    run(c, "quaternion_to_matrix", "vectrix", &d.quat, |q| q.rotation_matrix());
    run(c, "quaternion_to_matrix", "nalgebra to_rotation_matrix", &d.na_q, |q| q.to_rotation_matrix());
    // quaternion → angle vector (log) and back (exp)
    run(c, "quaternion_to_rotvec", "vectrix angle_vector", &d.quat, |q| q.angle_vector());
    run(c, "quaternion_to_rotvec", "nalgebra scaled_axis", &d.na_q, |q| q.scaled_axis());
    run(c, "rotvec_to_quaternion", "vectrix from_angle_vector", &d.rotvec, Quaternion::from_angle_vector);
    run(c, "rotvec_to_quaternion", "nalgebra from_scaled_axis", &d.rotvec, |v| {
        UnitQuaternion::from_scaled_axis(*v)
    });
    // matrix → angle vector
    run(c, "matrix_to_rotvec", "vectrix", &d.mat, Quaternion::angle_vector_of_rotation_matrix);
    run(c, "matrix_to_rotvec", "nalgebra Rotation3::scaled_axis", &d.na_r, |r| r.scaled_axis());
    // axis-angle
    run(c, "quaternion_to_axis_angle", "vectrix axis_angle", &d.quat, |q| q.axis_angle());
    run(c, "quaternion_to_axis_angle", "nalgebra axis_angle", &d.na_q, |q| q.axis_angle());
    let axes: Vec<(Unit<Vector3<f64>>, f64)> =
        d.na_q.iter().map(|q| q.axis_angle().expect("not identity")).collect();
    run(c, "axis_angle_to_quaternion", "vectrix from_axis_angle", &axes, |(n, t)| {
        Quaternion::from_axis_angle(n.as_ref(), *t)
    });
    run(c, "axis_angle_to_quaternion", "nalgebra from_axis_angle", &axes, |(n, t)| {
        UnitQuaternion::from_axis_angle(n, *t)
    });
    // Euler 3-2-1 (nalgebra's euler_angles is intrinsic ZYX: roll, pitch, yaw)
    run(c, "matrix_to_euler321", "vectrix", &d.mat, |m| {
        EulerAngles::from_rotation_matrix_unchecked(m, EulerSequence::S321, GIMBAL_LOCK_TOL)
    });
    run(c, "matrix_to_euler321", "nalgebra euler_angles", &d.na_r, |r| r.euler_angles());
    run(c, "quaternion_to_euler321", "vectrix", &d.quat, |q| {
        EulerAngles::from_quaternion(q, EulerSequence::S321)
    });
    run(c, "quaternion_to_euler321", "nalgebra euler_angles", &d.na_q, |q| q.euler_angles());
    let rpy: Vec<(f64, f64, f64)> = d.euler.iter().map(|e| (e.angles[2], e.angles[1], e.angles[0])).collect();
    run(c, "euler321_to_quaternion", "vectrix", &d.euler, |e| e.quaternion());
    run(c, "euler321_to_quaternion", "nalgebra from_euler_angles", &rpy, |(r, p, y)| {
        UnitQuaternion::from_euler_angles(*r, *p, *y)
    });
    run(c, "euler321_to_matrix", "vectrix", &d.euler, |e| e.rotation_matrix());
    run(c, "euler321_to_matrix", "nalgebra Rotation3::from_euler_angles", &rpy, |(r, p, y)| {
        Rotation3::from_euler_angles(*r, *p, *y)
    });
    let e313: Vec<EulerSequence> = vec![EulerSequence::S313; 1];
    run(c, "matrix_to_euler313", "vectrix", &d.mat, |m| {
        EulerAngles::from_rotation_matrix_unchecked(m, e313[0], GIMBAL_LOCK_TOL)
    });
    // Gibbs and MRP (no nalgebra equivalent)
    run(c, "quaternion_to_gibbs", "vectrix", &d.quat, |q| q.gibbs());
    run(c, "gibbs_to_quaternion", "vectrix", &d.gibbs, Quaternion::from_gibbs);
    run(c, "quaternion_to_mrp", "vectrix", &d.quat, |q| q.mrp());
    run(c, "mrp_to_quaternion", "vectrix", &d.mrp, Quaternion::from_mrp);
    // The physical rotation and a frame
    run(c, "rotation_to_matrix_in_frame", "vectrix Rotation::rotation_matrix_in", &d.rot, |r| {
        r.rotation_matrix_in(&a)
    });
    run(c, "matrix_in_frame_to_rotation", "vectrix Rotation::from_rotation_matrix_in", &d.mat, |m| {
        Rotation::from_rotation_matrix_in(&a, m, ROTATION_TOL)
    });
    run(c, "nearest_rotation", "vectrix polar (SVD)", &d.mat, nearest_rotation);
}

/// Batched conversions, 1e6 rotations per call like scipy's batched `Rotation` (per-rotation
/// figures: divide by 1e6, or read criterion's throughput line). The one-rotation function in a
/// loop runs beside each batched call, on the same data.
fn batched(c: &mut Criterion) {
    const M: usize = 1_000_000;
    let mut s = 0x2545_F491_4F6C_DD1Du64;
    let quat: Vec<Quaternion> = (0..M)
        .map(|_| {
            let q =
                Quaternion::new(rng(&mut s) - 0.5, rng(&mut s) - 0.5, rng(&mut s) - 0.5, rng(&mut s) - 0.5);
            q.normalize().expect("nonzero").canonical()
        })
        .collect();
    let rotvec: Vec<Vector3<f64>> = quat.iter().map(|q| q.angle_vector()).collect();
    let mut g = c.benchmark_group("batched_1e6");
    g.throughput(Throughput::Elements(M as u64));
    g.sample_size(20);
    g.bench_function("from_rotvec: Quaternion::from_angle_vectors", |b| {
        b.iter(|| Quaternion::from_angle_vectors(black_box(&rotvec)).expect("finite"))
    });
    g.bench_function("from_rotvec: loop of from_angle_vector", |b| {
        b.iter(|| black_box(&rotvec).iter().map(Quaternion::from_angle_vector).collect::<Vec<_>>())
    });
    for (name, seq) in [("ZYX", EulerSequence::S321), ("zxz", EulerSequence::S313.extrinsic())] {
        g.bench_function(format!("as_euler('{name}'): EulerAngles::from_quaternions"), |b| {
            b.iter(|| EulerAngles::from_quaternions(black_box(&quat), seq).expect("unit"))
        });
        g.bench_function(format!("as_euler('{name}'): loop of from_quaternion"), |b| {
            b.iter(|| {
                black_box(&quat)
                    .iter()
                    .map(|q| EulerAngles::from_quaternion(q, seq).principal())
                    .collect::<Vec<_>>()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, compose_apply, conversions, batched);

/// `VECTRIX_ICOUNT=conversion:passes`: `passes` passes of one conversion over the N inputs of
/// [`data`], then exit (for callgrind).
fn icount_driver() -> bool {
    let Ok(spec) = std::env::var("VECTRIX_ICOUNT") else { return false };
    let (name, passes) = spec.split_once(':').expect("VECTRIX_ICOUNT=conversion:passes");
    let passes: usize = passes.parse().expect("a number of passes");
    let d = data();
    let axes: Vec<(Vector3<f64>, f64)> = d
        .quat
        .iter()
        .map(|q| (q.axis_angle().axis().expect("not identity"), q.axis_angle().angle()))
        .collect();
    let sum = |v: Vector3<f64>| v.x + v.y + v.z;
    let pass = || -> f64 {
        match name {
            "matrix_to_quaternion" => {
                d.mat.iter().map(|m| Quaternion::from_rotation_matrix_unchecked(black_box(m)).a).sum()
            }
            "matrix_to_rotvec" => {
                d.mat.iter().map(|m| sum(Quaternion::angle_vector_of_rotation_matrix(black_box(m)))).sum()
            }
            "axis_angle_to_quaternion" => axes
                .iter()
                .map(|(n, t)| Quaternion::from_axis_angle(black_box(n), black_box(*t)).expect("unit").a)
                .sum(),
            "rotvec_to_quaternion" => {
                d.rotvec.iter().map(|v| Quaternion::from_angle_vector(black_box(v)).a).sum()
            }
            "quaternion_to_rotvec" => d.quat.iter().map(|q| sum(black_box(q).angle_vector())).sum(),
            "quaternion_to_euler321" => d
                .quat
                .iter()
                .map(|q| {
                    EulerAngles::from_quaternion(black_box(q), EulerSequence::S321).principal().angles[0]
                })
                .sum(),
            "euler321_to_quaternion" => d.euler.iter().map(|e| black_box(e).quaternion().a).sum(),
            "batched_from_rotvec" => Quaternion::from_angle_vectors(black_box(&d.rotvec))
                .expect("finite")
                .iter()
                .map(|q| q.a)
                .sum(),
            "batched_as_euler321" => EulerAngles::from_quaternions(black_box(&d.quat), EulerSequence::S321)
                .expect("unit")
                .angles()
                .iter()
                .map(|a| a[0])
                .sum(),
            other => panic!("unknown conversion {other}"),
        }
    };
    let mut sink = 0.0;
    for _ in 0..passes {
        sink += pass();
    }
    println!("{name} passes={passes} sink={sink}");
    true
}

fn main() {
    if icount_driver() {
        return;
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
}
