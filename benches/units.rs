//! Units benches (issue 21): what the typed layer costs on a hot path, and what the edges cost.
//!
//! - `moments/untyped`: M⃗ = Σ r⃗_i × f⃗_i over N = 256 kernel `Vector`s (§6.3).
//! - `moments/typed`: the same with `Physical<Length>` × `Physical<Force>` → `Physical<Moment>`;
//!   `#[repr(transparent)]` wrappers, so it should cost exactly what the untyped loop costs.
//! - `moments/uom` (with `--features uom`): the same with `uom` scalars, three components of
//!   `Length` and `Force` per vector, products typed by `uom` as `Torque`.
//! - `edges/*`: parsing a quantity string and converting it exactly to SI (a scene loader's
//!   cost per value), and a typed constructor from a value and a unit name.
//!
//! Run: `cargo bench --bench units -- --warm-up-time 1 --measurement-time 3`, and for the
//! `uom` row `cargo bench --bench units --features uom -- moments/uom`. Instruction counts
//! (load-independent): see docs/performance.md, section "Units".

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use vectrix::prelude::*;
use vectrix::units::kind::{Force, Length, Moment};
use vectrix::units::{Dimension, Measure, Physical, Quantity};

/// Deterministic pseudo-random numbers in [−1, 1) (no rand dependency).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

const N: usize = 256;

/// Σ r⃗_i × f⃗_i, untyped.
#[inline(never)]
pub fn moments_untyped(rf: &[(Vector, Vector)]) -> Vector {
    rf.iter().fold(Vector::zero(), |m, (r, f)| m + r.cross(f))
}

/// Σ r⃗_i × f⃗_i, typed.
#[inline(never)]
pub fn moments_typed(rf: &[(Physical<Length>, Physical<Force>)]) -> Physical<Moment> {
    rf.iter().fold(Physical::zero(), |m, (r, f)| m + r.cross(f))
}

#[cfg(feature = "uom")]
mod with_uom {
    use vectrix::uom::si::f64::{Force, Length, Torque};

    /// Σ r_i × f_i with uom scalars (components in one frame).
    #[inline(never)]
    pub fn moments_uom(rf: &[([Length; 3], [Force; 3])]) -> [Torque; 3] {
        let zero = Torque::default();
        rf.iter().fold([zero; 3], |m, (r, f)| {
            [
                m[0] + (r[1] * f[2] - r[2] * f[1]).into(),
                m[1] + (r[2] * f[0] - r[0] * f[2]).into(),
                m[2] + (r[0] * f[1] - r[1] * f[0]).into(),
            ]
        })
    }
}

fn moments(c: &mut Criterion) {
    let a = Frame::new();
    let mut seed = 21;
    let mut next = || [lcg(&mut seed), lcg(&mut seed), lcg(&mut seed)];
    let raw: Vec<([f64; 3], [f64; 3])> = (0..N).map(|_| (next(), next())).collect();
    let untyped: Vec<(Vector, Vector)> = raw.iter().map(|(r, f)| (a.vector(*r), a.vector(*f))).collect();
    let typed: Vec<(Physical<Length>, Physical<Force>)> =
        untyped.iter().map(|(r, f)| (Physical::from_si(*r), Physical::from_si(*f))).collect();
    let mut g = c.benchmark_group("moments");
    g.bench_function("untyped", |b| b.iter(|| moments_untyped(black_box(&untyped))));
    g.bench_function("typed", |b| b.iter(|| moments_typed(black_box(&typed))));
    #[cfg(feature = "uom")]
    {
        use vectrix::uom::si::f64::{Force, Length};
        use vectrix::uom::si::force::newton;
        use vectrix::uom::si::length::meter;
        let with_uom: Vec<_> =
            raw.iter().map(|(r, f)| (r.map(Length::new::<meter>), f.map(Force::new::<newton>))).collect();
        g.bench_function("uom", |b| b.iter(|| with_uom::moments_uom(black_box(&with_uom))));
    }
    g.finish();
}

fn edges(c: &mut Criterion) {
    let mut g = c.benchmark_group("edges");
    g.bench_function("parse_to_si", |b| {
        b.iter(|| Quantity::parse(black_box("-32.174 ft/s^2")).and_then(|q| q.to_si(Dimension::ACCELERATION)))
    });
    g.bench_function("parse_to_si_composite", |b| {
        b.iter(|| {
            Quantity::parse(black_box("27915 slug*ft^2")).and_then(|q| q.to_si(Dimension::MOMENT_OF_INERTIA))
        })
    });
    g.bench_function("measure_new", |b| b.iter(|| Measure::<Length>::new(black_box(3.5), black_box("ft"))));
    g.finish();
}

criterion_group!(benches, moments, edges);
criterion_main!(benches);
