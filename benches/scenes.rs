//! Scene benches: steps per second of the default scene (tennis-racket flip) and of a
//! 12-link pendulum chain; the cost of a declared contact that never touches (target ≤ 1.2×
//! the same scene without it).
//!
//! `cargo bench --bench scenes -- --warm-up-time 1 --measurement-time 3`
use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use vectrix::dynamics::scene::{DEFAULT_SCENE, Scene};

/// A chain of n pin-jointed rods under gravity, every other axis ŷ (a spatial chain).
fn chain(n: usize) -> String {
    let mut s = String::from(
        "name = \"chain\"\nduration = 1.0\nsamples = 50\naccuracy = 1e-6\n\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, 0.0, -9.81]\n",
    );
    for i in 0..n {
        let axis = if i % 2 == 0 { "[0.0, 0.0, 1.0]" } else { "[0.0, 1.0, 0.0]" };
        let parent = if i == 0 {
            String::new()
        } else {
            format!("parent = \"l{}\"\noffset = [0.3, 0.0, 0.0]\n", i - 1)
        };
        s += &format!(
            "\n[[bodies]]\nname = \"l{i}\"\n{parent}joint = {{ type = \"pin\", axis = {axis} }}\nmass = {{ shape = \"rod\", mass = 1.0, length = 0.3 }}\ncom = [0.15, 0.0, 0.0]\nq = [0.1]\n"
        );
    }
    s
}

/// A Kepler orbit, optionally with a sphere–plane contact declared far below the orbit.
fn orbit(contact: bool) -> String {
    let mut s = String::from(
        "name = \"orbit\"\nduration = 6.283185307179586\nsamples = 200\naccuracy = 1e-8\n\n[[bodies]]\nname = \"p\"\njoint = { type = \"free\" }\nmass = { shape = \"sphere\", mass = 1.0, radius = 0.01 }\nq = [0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]\nv = [0.0, 1.7320508075688772, 0.0, 0.0, 0.0, 0.0]\n\n[[effects]]\ntype = \"central_gravity\"\nmu = 1.0\n",
    );
    if contact {
        s += "\n[[effects]]\ntype = \"contact_plane\"\nbody = \"p\"\nradius = 0.01\npoint = [0.0, 0.0, -10.0]\nnormal = [0.0, 0.0, 1.0]\nrestitution = 0.5\n";
    }
    s
}

fn steps_per_second(name: &str, scene: &Scene) {
    let run = scene.run(&mut |_| {}).expect("runs");
    let steps = run.work.accepted as f64;
    eprintln!(
        "{name}: {} accepted steps, {} f-evals in {:.4} s: {:.0} steps/s, {:.0} f-evals/s",
        run.work.accepted,
        run.work.fevals,
        run.work.wall_seconds,
        steps / run.work.wall_seconds,
        run.work.fevals as f64 / run.work.wall_seconds
    );
}

fn scenes(c: &mut Criterion) {
    let mut default = Scene::from_toml(DEFAULT_SCENE, "default").expect("default scene");
    let mut spec = default.spec().clone();
    spec.duration = 10.0;
    spec.samples = 200;
    default = Scene::from_spec(spec).expect("valid");
    let chain12 = Scene::from_toml(&chain(12), "chain").expect("chain");
    let free = Scene::from_toml(&orbit(false), "orbit").expect("orbit");
    let contact = Scene::from_toml(&orbit(true), "orbit+contact").expect("orbit+contact");
    steps_per_second("default scene (t = 0…10)", &default);
    steps_per_second("12-link chain (t = 0…1)", &chain12);
    steps_per_second("orbit without contact", &free);
    steps_per_second("orbit with contact declared", &contact);
    let mut g = c.benchmark_group("scenes");
    g.sample_size(10);
    g.bench_function("default_tennis_racket_10s", |b| {
        b.iter(|| black_box(default.run(&mut |_| {}).expect("runs")))
    });
    g.bench_function("chain12_1s", |b| b.iter(|| black_box(chain12.run(&mut |_| {}).expect("runs"))));
    g.bench_function("orbit_no_contact", |b| b.iter(|| black_box(free.run(&mut |_| {}).expect("runs"))));
    g.bench_function("orbit_contact_declared_never_touching", |b| {
        b.iter(|| black_box(contact.run(&mut |_| {}).expect("runs")))
    });
    g.finish();
}

criterion_group!(benches, scenes);
criterion_main!(benches);
