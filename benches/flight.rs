//! Flight-dynamics benches (book ch. 11–14) on the business jet of Tables 14.1–14.2:
//! trim (bounded Levenberg–Marquardt with dual-number Jacobians), 12-state dual-number
//! linearization (28 forward passes), one evaluation of the implicit equations of motion,
//! and the modes of the table-built longitudinal and lateral models.
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use vectrix::flight::*;

fn flight(c: &mut Criterion) {
    let ac = business_jet();
    let level = TrimSpec::Straight { airspeed: BUSINESS_JET_U0, gamma: 0.0 };
    let climb = TrimSpec::Straight { airspeed: 650.0, gamma: 0.05 };
    let turn = TrimSpec::LevelTurn { airspeed: BUSINESS_JET_U0, turn_rate: 0.02 };
    let lim = TrimLimits::default();
    c.bench_function("flight/trim_level", |b| b.iter(|| trim(black_box(&ac), level, lim).unwrap()));
    c.bench_function("flight/trim_climb", |b| b.iter(|| trim(black_box(&ac), climb, lim).unwrap()));
    c.bench_function("flight/trim_turn", |b| b.iter(|| trim(black_box(&ac), turn, lim).unwrap()));
    let t = trim(&ac, level, lim).unwrap();
    c.bench_function("flight/linearize_12_state", |b| b.iter(|| linearize(black_box(&ac), &t).unwrap()));
    c.bench_function("flight/dynamics_eval", |b| {
        b.iter(|| ac.dynamics(black_box(&t.state), black_box(&t.controls)).unwrap())
    });
    let lon = business_jet_longitudinal();
    let lat = business_jet_lateral();
    c.bench_function("flight/longitudinal_modes", |b| {
        b.iter(|| longitudinal_modes(black_box(lon).state_space().unwrap().a()).unwrap())
    });
    c.bench_function("flight/lateral_modes", |b| {
        b.iter(|| lateral_modes(black_box(lat).state_space().unwrap().a()).unwrap())
    });
}

criterion_group!(benches, flight);
criterion_main!(benches);
