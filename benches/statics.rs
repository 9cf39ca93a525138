//! Statics benches (issue 6): mass properties beside hand-written nalgebra code for the same
//! computation, in the same run, plus the free-body least-squares solve.
//!
//! - `particles/*`: m_B, c and J⃗_{B/c} of N = 64 particles ((6.1.1), (6.1.2), (6.2.3)).
//! - `principal/*`: principal axes of an inertia dyadic (validation, sorted moments,
//!   multiplicities, right-handed frame) vs nalgebra `SymmetricEigen` + sort + det fix.
//! - `parallel_axis/*`: J⃗_{B/z} from J⃗_{B/c} (6.2.26).
//! - `freebody/pyramid`: the 4-body, 9-unknown sphere pyramid of Problem 6.15.3 (faer SVD).
//!
//! Run: `cargo bench --bench statics -- --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{Matrix3, SymmetricEigen, Vector3};
use vectrix::prelude::*;
use vectrix::statics::{
    AppliedForce, FREE_BODY_REL_TOL, FreeBodyProblem, INERTIA_REL_TOL, MassProperties, Point, PrincipalAxes,
};

/// Deterministic pseudo-random numbers in [−1, 1) (no rand dependency).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

fn particles_nalgebra(ps: &[(f64, Vector3<f64>)]) -> (f64, Vector3<f64>, Matrix3<f64>) {
    let m: f64 = ps.iter().map(|p| p.0).sum();
    let c = ps.iter().fold(Vector3::zeros(), |s, (mi, r)| s + r * *mi) / m;
    let j = ps.iter().fold(Matrix3::zeros(), |j, (mi, r)| {
        let d = r - c;
        j + (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * *mi
    });
    (m, c, j)
}

fn principal_nalgebra(j: &Matrix3<f64>) -> ([f64; 3], Matrix3<f64>) {
    let e = SymmetricEigen::new(*j);
    let mut idx = [0usize, 1, 2];
    idx.sort_by(|&a, &b| e.eigenvalues[b].total_cmp(&e.eigenvalues[a]));
    let mut s = Matrix3::from_columns(&[
        e.eigenvectors.column(idx[0]).into_owned(),
        e.eigenvectors.column(idx[1]).into_owned(),
        e.eigenvectors.column(idx[2]).into_owned(),
    ]);
    if s.determinant() < 0.0 {
        s = -s;
    }
    ([e.eigenvalues[idx[0]], e.eigenvalues[idx[1]], e.eigenvalues[idx[2]]], s)
}

fn pyramid() -> FreeBodyProblem {
    let a = Frame::new();
    let rc = 2.0 / 3f64.sqrt();
    let h = (4.0 - rc * rc).sqrt();
    let mut fb = FreeBodyProblem::new();
    let top = fb.add_body();
    let top_c = Point::at(a.vector([0.0, 0.0, h]));
    fb.apply_force(top, AppliedForce::new(a.vector([0.0, 0.0, -1.0]), top_c)).unwrap();
    for k in 0..3 {
        let phi = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let (cx, cy) = (rc * phi.cos(), rc * phi.sin());
        let b = fb.add_body();
        let bc = Point::at(a.vector([cx, cy, 0.0]));
        let r = top_c.position_rel(&bc);
        fb.unknown_force(top, Some(b), r, bc.displaced(r * 0.5)).unwrap();
        fb.unknown_force(b, None, a.k(), Point::at(a.vector([cx, cy, -1.0]))).unwrap();
        fb.unknown_force(
            b,
            None,
            a.vector([-cx, -cy, 0.0]),
            Point::at(a.vector([cx * 1.866, cy * 1.866, 0.0])),
        )
        .unwrap();
    }
    fb
}

fn benches(c: &mut Criterion) {
    let a = Frame::new();
    let mut s = 11u64;
    let raw: Vec<(f64, [f64; 3])> =
        (0..64).map(|_| (1.5 + lcg(&mut s), [lcg(&mut s), lcg(&mut s), lcg(&mut s)])).collect();
    let ps: Vec<(f64, Point)> = raw.iter().map(|(m, x)| (*m, Point::at(a.vector(*x)))).collect();
    let nps: Vec<(f64, Vector3<f64>)> = raw.iter().map(|(m, x)| (*m, Vector3::from(*x))).collect();

    let mut g = c.benchmark_group("statics");
    g.bench_function("particles/vectrix", |b| {
        b.iter(|| MassProperties::from_particles(black_box(&ps)).unwrap())
    });
    g.bench_function("particles/nalgebra", |b| b.iter(|| particles_nalgebra(black_box(&nps))));

    let body = MassProperties::from_particles(&ps).unwrap();
    let j = body.inertia_about_centre();
    let nj = j.resolve(&a);
    g.bench_function("principal/vectrix", |b| {
        b.iter(|| PrincipalAxes::of(black_box(&j), INERTIA_REL_TOL).unwrap())
    });
    g.bench_function("principal/nalgebra", |b| b.iter(|| principal_nalgebra(black_box(&nj))));

    let z = Point::at(a.vector([0.3, -0.7, 1.1]));
    let (nm, nc, nz) =
        (body.mass(), body.centre_of_mass().position().resolve(&a), Vector3::new(0.3, -0.7, 1.1));
    g.bench_function("parallel_axis/vectrix", |b| b.iter(|| black_box(&body).inertia_about(black_box(&z))));
    g.bench_function("parallel_axis/nalgebra", |b| {
        b.iter(|| {
            let r = black_box(nz) - nc;
            black_box(nj) + (Matrix3::identity() * r.norm_squared() - r * r.transpose()) * nm
        })
    });

    let fb = pyramid();
    g.bench_function("freebody/pyramid", |b| b.iter(|| black_box(&fb).solve(FREE_BODY_REL_TOL).unwrap()));
    g.finish();
}

criterion_group!(statics, benches);
criterion_main!(statics);
