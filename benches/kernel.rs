//! Kernel benches (issue 2, item 16): each frame-free operation beside hand-written nalgebra
//! code for the same computation, in the same run. Targets: frame-free ops within 1.10× of
//! nalgebra; Hooke's law over 10⁶ strains no slower than numpy's `einsum(..., optimize=True)`
//! (`/work/shared/peers/bench_einsum.py`).
//!
//! Run: `cargo bench --bench kernel -- --warm-up-time 1 --measurement-time 3`.
//! Each micro-benchmark maps over N = 1024 inputs per iteration so that loop overhead and
//! black-box costs are amortised identically for both sides.
//!
//! Instruction counts: `VECTRIX_ICOUNT=hooke_apply_many:calls` runs `calls` calls of
//! `HookeMap::apply_many` on N strains and exits (for callgrind at 1000 and 2000 calls; the
//! difference / (1000·N) is the count per strain).

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group};
use nalgebra::{Matrix3, SMatrix, SVector, UnitQuaternion, Vector3};
use vectrix::prelude::*;

const N: usize = 1024;

/// Deterministic pseudo-random numbers in [−1, 1) (no rand dependency).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

struct Data {
    a: Frame,
    xs: Vec<Vector>,
    ys: Vec<Vector>,
    nxs: Vec<Vector3<f64>>,
    nys: Vec<Vector3<f64>>,
    m: Dyadic,
    nm: Matrix3<f64>,
}

fn data() -> Data {
    let mut s = 7u64;
    let a = Frame::new();
    let mut arr = || [lcg(&mut s), lcg(&mut s), lcg(&mut s)];
    let raw_x: Vec<[f64; 3]> = (0..N).map(|_| arr()).collect();
    let raw_y: Vec<[f64; 3]> = (0..N).map(|_| arr()).collect();
    let mm = Matrix3::from_fn(|r, c| ((3 * r + c) as f64 * 0.37).sin());
    Data {
        xs: raw_x.iter().map(|v| a.vector(*v)).collect(),
        ys: raw_y.iter().map(|v| a.vector(*v)).collect(),
        nxs: raw_x.iter().map(|v| Vector3::from(*v)).collect(),
        nys: raw_y.iter().map(|v| Vector3::from(*v)).collect(),
        m: a.dyadic(&mm),
        nm: mm,
        a,
    }
}

fn vector_ops(c: &mut Criterion) {
    let d = data();
    let mut g = c.benchmark_group("kernel/vector");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("add/vectrix", |b| {
        b.iter(|| {
            black_box(&d.xs).iter().zip(black_box(&d.ys)).fold(Vector::zero(), |acc, (x, y)| acc + (*x + *y))
        })
    });
    g.bench_function("add/nalgebra", |b| {
        b.iter(|| {
            black_box(&d.nxs)
                .iter()
                .zip(black_box(&d.nys))
                .fold(Vector3::zeros(), |acc, (x, y)| acc + (x + y))
        })
    });
    g.bench_function("dot/vectrix", |b| {
        b.iter(|| black_box(&d.xs).iter().zip(black_box(&d.ys)).map(|(x, y)| x.dot(y)).sum::<f64>())
    });
    g.bench_function("dot/nalgebra", |b| {
        b.iter(|| black_box(&d.nxs).iter().zip(black_box(&d.nys)).map(|(x, y)| x.dot(y)).sum::<f64>())
    });
    g.bench_function("cross/vectrix", |b| {
        b.iter(|| {
            black_box(&d.xs).iter().zip(black_box(&d.ys)).fold(Vector::zero(), |acc, (x, y)| acc + x.cross(y))
        })
    });
    g.bench_function("cross/nalgebra", |b| {
        b.iter(|| {
            black_box(&d.nxs)
                .iter()
                .zip(black_box(&d.nys))
                .fold(Vector3::zeros(), |acc, (x, y)| acc + x.cross(y))
        })
    });
    // x∧y = 𝒥(x×y): the nalgebra peer is the cross product; vectrix adds the cancellation-free
    // differences of products (notes §3), so this row shows the price of that accuracy.
    g.bench_function("wedge/nalgebra_cross", |b| {
        b.iter(|| {
            black_box(&d.nxs)
                .iter()
                .zip(black_box(&d.nys))
                .fold(Vector3::zeros(), |acc, (x, y)| acc + x.cross(y))
        })
    });
    g.bench_function("wedge/vectrix", |b| {
        b.iter(|| {
            black_box(&d.xs)
                .iter()
                .zip(black_box(&d.ys))
                .fold(Bivector::zero(), |acc, (x, y)| acc + x.wedge(y))
        })
    });
    g.finish();
}

fn dyadic_and_resolve(c: &mut Criterion) {
    let d = data();
    let mut g = c.benchmark_group("kernel/dyadic");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("dyadic_vector/vectrix", |b| {
        let m = black_box(d.m);
        b.iter(|| black_box(&d.xs).iter().fold(Vector::zero(), |acc, x| acc + m * *x))
    });
    g.bench_function("dyadic_vector/nalgebra", |b| {
        let m = black_box(d.nm);
        b.iter(|| black_box(&d.nxs).iter().fold(Vector3::zeros(), |acc, x| acc + m * x))
    });
    // Resolution x|_B = F_Bᵀ x: vectrix through a frame; nalgebra the same transpose product.
    let bf = d.a.rotated_by_rotor(&Rotor::from_axis_angle(&d.a.vector([1.0, 2.0, 3.0]), 0.7).unwrap());
    // F_B's columns in the first frame A (whose axes are the kernel's reference basis): 𝓡_{B/A}
    let axes = bf.rotation_rel(&d.a);
    g.bench_function("resolve/vectrix", |b| {
        let bf = black_box(&bf);
        b.iter(|| black_box(&d.xs).iter().fold(Vector3::zeros(), |acc, x| acc + x.resolve(bf)))
    });
    g.bench_function("resolve/nalgebra", |b| {
        let axes = black_box(axes);
        b.iter(|| black_box(&d.nxs).iter().fold(Vector3::zeros(), |acc, x| acc + axes.tr_mul(x)))
    });
    g.finish();
}

fn rotor_sandwich(c: &mut Criterion) {
    let d = data();
    let r = Rotor::from_axis_angle(&d.a.vector([1.0, -2.0, 0.5]), 1.1).unwrap();
    // The same rotation as a Hamilton quaternion q = (s, q⃗), R = q₀ − 𝒥q⃗.
    let qv = -r.bivector().undual().resolve(&d.a);
    let (s, q) = (r.scalar(), qv);
    let uq = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(s, q.x, q.y, q.z));
    let mut g = c.benchmark_group("kernel/rotor");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("sandwich/vectrix", |b| {
        let r = black_box(r);
        b.iter(|| black_box(&d.xs).iter().fold(Vector::zero(), |acc, x| acc + r.sandwich(x)))
    });
    g.bench_function("sandwich/nalgebra_handwritten", |b| {
        let (s, q) = (black_box(s), black_box(q));
        b.iter(|| {
            black_box(&d.nxs).iter().fold(Vector3::zeros(), |acc, x| {
                // x + 2s(q×x) + 2q×(q×x)
                let t = q.cross(x) * 2.0;
                acc + (x + t * s + q.cross(&t))
            })
        })
    });
    g.bench_function("sandwich/nalgebra_unit_quaternion", |b| {
        let uq = black_box(uq);
        b.iter(|| black_box(&d.nxs).iter().fold(Vector3::zeros(), |acc, x| acc + uq * x))
    });
    g.finish();
}

fn hooke(c: &mut Criterion) {
    let a = Frame::new();
    let mut s = 11u64;
    let strains_raw: Vec<Matrix3<f64>> = (0..N)
        .map(|_| {
            let m = Matrix3::from_fn(|_, _| lcg(&mut s));
            (m + m.transpose()) * 0.5
        })
        .collect();
    let strains: Vec<Dyadic> = strains_raw.iter().map(|m| a.dyadic(m)).collect();
    let mat = Isotropic::from_lame(1.2, 0.8).unwrap();
    let k = mat.stiffness();
    let map = HookeMap::new(&k).unwrap();
    // Hand-written nalgebra: the 9 × 9 matrix of σ_kn = Σ c_klmn ε_ml on column-major vec.
    let kr = k.resolve(&a);
    let mut h = SMatrix::<f64, 9, 9>::zeros();
    for kk in 0..3 {
        for l in 0..3 {
            for m in 0..3 {
                for n in 0..3 {
                    h[(kk + 3 * n, m + 3 * l)] += kr[(3 * kk + l, 3 * m + n)];
                }
            }
        }
    }
    let mut g = c.benchmark_group("kernel/hooke");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("contraction_map/vectrix", |b| {
        let map = black_box(&map);
        b.iter(|| black_box(&strains).iter().fold(Dyadic::zero(), |acc, e| acc + map.apply(e)))
    });
    g.bench_function("contraction_map/nalgebra", |b| {
        let h = black_box(&h);
        b.iter(|| {
            black_box(&strains_raw).iter().fold(Matrix3::zeros(), |acc, e| {
                let s = h * SVector::<f64, 9>::from_column_slice(e.as_slice());
                acc + Matrix3::from_column_slice(s.as_slice())
            })
        })
    });
    g.bench_function("closed_form/vectrix", |b| {
        let mat = black_box(mat);
        b.iter(|| black_box(&strains).iter().fold(Dyadic::zero(), |acc, e| acc + mat.stress(e)))
    });
    g.bench_function("closed_form/nalgebra", |b| {
        let (lam, mu) = black_box((1.2, 0.8));
        b.iter(|| {
            black_box(&strains_raw).iter().fold(Matrix3::zeros(), |acc, e| {
                // The same formula as `Isotropic::stress`: μ(ε + εᵀ) + λ (tr ε) I.
                acc + ((e + e.transpose()) * mu + Matrix3::identity() * (lam * e.trace()))
            })
        })
    });
    g.finish();
    // The general fused contraction (any types, heap-allocated result), for reference.
    let mut g = c.benchmark_group("kernel/hooke_general");
    let e0 = strains[0];
    g.bench_function("fused_contracted_product/vectrix", |b| {
        b.iter(|| vectrix::tensor::hooke(black_box(&k), black_box(&e0)).unwrap())
    });
    g.finish();
}

fn hooke_million(c: &mut Criterion) {
    const M: usize = 1_000_000;
    let a = Frame::new();
    let mut s = 13u64;
    let raw: Vec<Matrix3<f64>> = (0..M)
        .map(|_| {
            let m = Matrix3::from_fn(|_, _| lcg(&mut s));
            (m + m.transpose()) * 0.5
        })
        .collect();
    let strains: Vec<Dyadic> = raw.iter().map(|m| a.dyadic(m)).collect();
    let mat = Isotropic::from_lame(1.2, 0.8).unwrap();
    let map = HookeMap::new(&mat.stiffness()).unwrap();
    let mut out = vec![Dyadic::zero(); M];
    let mut g = c.benchmark_group("kernel/hooke_1e6");
    g.sample_size(10);
    g.throughput(Throughput::Elements(M as u64));
    g.bench_with_input(BenchmarkId::new("contraction_map/vectrix", M), &strains, |b, e| {
        b.iter(|| map.apply_many(black_box(e), &mut out).unwrap())
    });
    g.bench_with_input(BenchmarkId::new("closed_form/vectrix", M), &strains, |b, e| {
        b.iter(|| {
            for (o, x) in out.iter_mut().zip(black_box(e)) {
                *o = mat.stress(x);
            }
        })
    });
    g.finish();
}

criterion_group!(benches, vector_ops, dyadic_and_resolve, rotor_sandwich, hooke, hooke_million);

/// `VECTRIX_ICOUNT=hooke_apply_many:calls`: `calls` calls of `HookeMap::apply_many` on N
/// strains, then exit (for callgrind).
fn icount_driver() -> bool {
    let Ok(spec) = std::env::var("VECTRIX_ICOUNT") else { return false };
    let (name, calls) = spec.split_once(':').expect("VECTRIX_ICOUNT=name:calls");
    assert_eq!(name, "hooke_apply_many", "the one instruction-count driver of this bench");
    let calls: usize = calls.parse().expect("a number of calls");
    let a = Frame::new();
    let mut s = 11u64;
    let strains: Vec<Dyadic> = (0..N)
        .map(|_| {
            let m = Matrix3::from_fn(|_, _| lcg(&mut s));
            a.dyadic(&((m + m.transpose()) * 0.5))
        })
        .collect();
    let map = HookeMap::new(&Isotropic::from_lame(1.2, 0.8).unwrap().stiffness()).unwrap();
    let mut out = vec![Dyadic::zero(); N];
    for _ in 0..calls {
        map.apply_many(black_box(&strains), &mut out).unwrap();
        black_box(&mut out);
    }
    println!("{name} calls={calls} sigma={:?}", out[0].resolve(&a)[(0, 0)]);
    true
}

fn main() {
    if icount_driver() {
        return;
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
}
