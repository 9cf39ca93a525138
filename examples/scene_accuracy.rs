//! Work–precision of whole scene runs against exact solutions: a Kepler orbit (e = 0.9, three
//! periods; positions by Kepler's equation) and a torque-free asymmetric body (ω_B(t) by Jacobi
//! elliptic functions), at a ladder of requested accuracies. Prints the table of
//! docs/accuracy.md ("Scenes"): requested accuracy, global error, f-evals, steps, and the same
//! run with 100× the samples (the work must not change).
//!
//! `cargo run --release --example scene_accuracy`

use vectrix::scene::{Run, Scene};
use vectrix_ode::harness::RigidBody;

/// Kepler's equation M = E − e sin E by Newton; periapsis on +x at t = 0, counter-clockwise.
fn kepler(e: f64, t: f64) -> (f64, f64) {
    let m = t;
    let mut ea = m + e * m.sin();
    for _ in 0..60 {
        let d = (ea - e * ea.sin() - m) / (1.0 - e * ea.cos());
        ea -= d;
        if d.abs() < 1e-16 {
            break;
        }
    }
    (ea.cos() - e, (1.0 - e * e).sqrt() * ea.sin())
}

fn kepler_scene(acc: f64, samples: usize) -> Scene {
    let e: f64 = 0.9;
    let rp = 1.0 - e;
    let vp = ((1.0 + e) / rp).sqrt();
    let text = format!(
        "name = \"kepler\"\nduration = {}\nsamples = {samples}\naccuracy = {acc:e}\noutputs = [\"position:p\"]\n\
         [[bodies]]\nname = \"p\"\njoint = {{ type = \"free\" }}\nmass = {{ shape = \"sphere\", mass = 1.0, radius = \
         0.01 }}\nq = [{rp}, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]\nv = [0.0, {vp}, 0.0, 0.0, 0.0, 0.0]\n[[effects]]\ntype = \
         \"central_gravity\"\nmu = 1.0\n",
        6.0 * std::f64::consts::PI
    );
    Scene::from_toml(&text, "kepler").expect("valid")
}

fn torque_free_scene(acc: f64, samples: usize) -> Scene {
    let text = format!(
        "name = \"tf\"\nduration = 20.0\nsamples = {samples}\naccuracy = {acc:e}\noutputs = [\"omega_body:b\"]\n[[bodies]]\n\
         name = \"b\"\njoint = {{ type = \"free\" }}\nmass = {{ shape = \"value\", mass = 1.0, principal = [1.0, 2.0, \
         3.0] }}\nv = [0.0, 0.0, 0.0, 1.0, 0.0, 0.5]\n"
    );
    Scene::from_toml(&text, "tf").expect("valid")
}

fn kepler_error(r: &Run) -> f64 {
    let (x, y) = (r.column("position:p.x").unwrap_or_default(), r.column("position:p.y").unwrap_or_default());
    r.t.iter()
        .zip(x.iter().zip(&y))
        .map(|(&t, (&x, &y))| {
            let (ex, ey) = kepler(0.9, t);
            (x - ex).hypot(y - ey)
        })
        .fold(0.0, f64::max)
}

fn torque_free_error(r: &Run) -> f64 {
    let exact = RigidBody { inertia: [1.0, 2.0, 3.0], omega13: [1.0, 0.5], t_end: 20.0 };
    let cols: Vec<Vec<f64>> =
        ["x", "y", "z"].iter().map(|c| r.column(&format!("omega_body:b.{c}")).unwrap_or_default()).collect();
    r.t.iter()
        .enumerate()
        .map(|(k, &t)| {
            let w = exact.exact_omega(t);
            (0..3).map(|i| (cols[i][k] - w[i]).abs()).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

fn main() {
    type Make = fn(f64, usize) -> Scene;
    type Err = fn(&Run) -> f64;
    let problems: [(&str, Make, Err); 2] = [
        ("Kepler e = 0.9, 3 periods (max position error)", kepler_scene, kepler_error),
        ("torque-free body, t ≤ 20 (max ω error)", torque_free_scene, torque_free_error),
    ];
    for (name, make, err) in problems {
        println!("\n{name}\n");
        println!("| accuracy | error | f-evals | steps | f-evals with 100× samples | wall [ms] |");
        println!("|---|---|---|---|---|---|");
        for acc in [1e-4, 1e-6, 1e-8, 1e-10, 1e-11] {
            let r = make(acc, 300).run(&mut |_| {}).expect("runs");
            let dense = make(acc, 30_000).run(&mut |_| {}).expect("runs");
            println!(
                "| {acc:.0e} | {:.2e} | {} | {} | {} | {:.2} |",
                err(&r),
                r.work.fevals,
                r.work.accepted,
                dense.work.fevals,
                r.work.wall_seconds * 1e3
            );
        }
    }
}
