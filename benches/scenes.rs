//! Scene benches: steps per second of the default scene (tennis-racket flip) and of a
//! 12-link pendulum chain; the cost of a declared contact that never touches (target ≤ 1.2×
//! the same scene without it); and `scene_overhead`: one right-hand-side evaluation of a
//! scene (`scene`) beside a hand-written right-hand side of the same system through the
//! multibody `Model` (`direct`) for a free body, a 12-link chain and a two-body orbit
//! (target: scene ≤ 1.2× direct).
//!
//! `cargo bench --bench scenes -- --warm-up-time 1 --measurement-time 3`
//! `cargo bench --bench scenes -- scene_overhead`
//!
//! Instruction counts (repeatable on a loaded machine): with `VECTRIX_ICOUNT=case:side:iters`
//! (case `free_body`, `chain12` or `two_body_orbit`; side `scene` or `direct`) the binary makes
//! `iters` right-hand-side evaluations and exits; under `valgrind --tool=callgrind` with two
//! values of `iters`, the difference over the difference of `iters` is the count per evaluation.
use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use nalgebra::Vector3;
use vectrix::dynamics::multibody::{AbaScratch, JointWrench, Model, Pose, PosesScratch};
use vectrix::scene::{DEFAULT_SCENE, Scene};

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

/// q̇ = ½ q ⊗ (0, ω) for a scalar-first unit quaternion and ω in the link frame.
#[inline]
fn quat_rate(q: &[f64], w: &[f64], out: &mut [f64]) {
    out[0] = 0.5 * (-q[1] * w[0] - q[2] * w[1] - q[3] * w[2]);
    out[1] = 0.5 * (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]);
    out[2] = 0.5 * (q[0] * w[1] + q[3] * w[0] - q[1] * w[2]);
    out[3] = 0.5 * (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]);
}

/// The hand-written right-hand sides, through the scene's own `Model`.
struct Direct<'a> {
    model: &'a Model,
    aba: AbaScratch,
    tau: Vec<f64>,
    world: PosesScratch,
    poses: Vec<Pose>,
    wrenches: Vec<JointWrench>,
}

impl<'a> Direct<'a> {
    fn new(model: &'a Model) -> Self {
        Self {
            model,
            aba: model.aba_scratch(),
            tau: vec![0.0; model.nv()],
            world: PosesScratch::default(),
            poses: Vec::new(),
            wrenches: vec![JointWrench::default(); model.links()],
        }
    }

    /// A free body: q = (x, q), v = (ẋ, ω); no loads.
    fn free_body(&mut self, y: &[f64], out: &mut [f64]) {
        let (q, v) = y.split_at(7);
        let (qd, vd) = out.split_at_mut(7);
        qd[..3].copy_from_slice(&v[..3]);
        quat_rate(&q[3..7], &v[3..6], &mut qd[3..7]);
        self.model.aba_into(q, v, &self.tau, None, vd, &mut self.aba).expect("aba");
    }

    /// A chain of pins under gravity (the model's base acceleration): q̇ = v.
    fn chain(&mut self, y: &[f64], out: &mut [f64]) {
        let n = self.model.nq();
        let (q, v) = y.split_at(n);
        let (qd, vd) = out.split_at_mut(n);
        qd.copy_from_slice(v);
        self.model.aba_into(q, v, &self.tau, None, vd, &mut self.aba).expect("aba");
    }

    /// Two free bodies (centres at the link origins) attracting each other: f = G m₁m₂ r/|r|³.
    fn orbit(&mut self, y: &[f64], out: &mut [f64], g: f64, m: [f64; 2]) {
        let (q, v) = y.split_at(14);
        let (qd, vd) = out.split_at_mut(14);
        for b in 0..2 {
            qd[7 * b..7 * b + 3].copy_from_slice(&v[6 * b..6 * b + 3]);
            quat_rate(&q[7 * b + 3..7 * b + 7], &v[6 * b + 3..6 * b + 6], &mut qd[7 * b + 3..7 * b + 7]);
        }
        self.model.poses_into(q, &mut self.world, &mut self.poses);
        let r: Vector3<f64> = self.poses[1].1 - self.poses[0].1;
        let f = r * (g * m[0] * m[1] / r.norm().powi(3));
        self.wrenches[0] = JointWrench { force: self.poses[0].0 * f, moment: Vector3::zeros() };
        self.wrenches[1] = JointWrench { force: self.poses[1].0 * (-f), moment: Vector3::zeros() };
        self.model.aba_into(q, v, &self.tau, Some(&self.wrenches), vd, &mut self.aba).expect("aba");
    }
}

const FREE_BODY: &str = "name = \"free\"\nduration = 1.0\n[[bodies]]\nname = \"b\"\njoint = { type = \"free\" }\n\
mass = { shape = \"box\", mass = 3.0, sides = [0.3, 0.6, 1.0] }\nv = [0.1, 0.0, 0.0, 1.0, 0.5, 2.0]\n";

const TWO_BODIES: &str = "name = \"two\"\nduration = 1.0\n[[bodies]]\nname = \"a\"\njoint = { type = \"free\" }\n\
mass = { shape = \"sphere\", mass = 1.0, radius = 0.01 }\nq = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]\n\
v = [0.0, 0.5, 0.0, 0.0, 0.0, 0.0]\n[[bodies]]\nname = \"b\"\njoint = { type = \"free\" }\n\
mass = { shape = \"sphere\", mass = 2.0, radius = 0.01 }\nq = [-0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]\n\
v = [0.0, -0.25, 0.0, 0.0, 0.0, 0.0]\n[[effects]]\ntype = \"mutual_gravitation\"\ng = 1.0\n";

fn scene_overhead(c: &mut Criterion) {
    let mut g = c.benchmark_group("scene_overhead");
    let free = Scene::from_toml(FREE_BODY, "free").expect("free body");
    let chain12 = Scene::from_toml(&chain(12), "chain").expect("chain");
    let two = Scene::from_toml(TWO_BODIES, "two").expect("two bodies");
    type Hand = fn(&mut Direct, &[f64], &mut [f64]);
    let cases: [(&str, &Scene, Hand); 3] = [
        ("free_body", &free, |d, y, o| d.free_body(y, o)),
        ("chain12", &chain12, |d, y, o| d.chain(y, o)),
        ("two_body_orbit", &two, |d, y, o| d.orbit(y, o, 1.0, [1.0, 2.0])),
    ];
    for (name, scene, hand) in cases {
        let y = scene.initial_state();
        let mut out = vec![0.0; y.len()];
        let mut out2 = vec![0.0; y.len()];
        // the two right-hand sides agree before they are timed
        let mut rhs = scene.rhs();
        rhs.eval(0.0, &y, &mut out).expect("scene rhs");
        let mut d = Direct::new(scene.model());
        hand(&mut d, &y, &mut out2);
        let err = out.iter().zip(&out2).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        assert!(err <= 1e-12 * out.iter().fold(1.0f64, |m, x| m.max(x.abs())), "{name}: {err:e}");
        g.bench_function(BenchmarkId::new("direct", name), |b| {
            b.iter(|| {
                hand(&mut d, black_box(&y), &mut out2);
                black_box(&out2);
            })
        });
        g.bench_function(BenchmarkId::new("scene", name), |b| {
            b.iter(|| {
                rhs.eval(0.0, black_box(&y), &mut out).expect("scene rhs");
                black_box(&out);
            })
        });
    }
    g.finish();
}

/// θ₂(2 s) of the four-bar from scripts/peers/bench_mujoco_four_bar.py (scipy DOP853 on the
/// index-1 equations in absolute angles, rtol = atol = 1e-12; independent of vectrix).
const FOUR_BAR_TH2_REF: f64 = 12.118579864419;

/// The peer script's initial state: assembled at θ₂ = 0.3 by Newton from (1.2, 1.9), crank rate
/// 6 rad/s, Φ_q q̇ = 0. Returns absolute angles and rates (θ₂, θ₃, θ₄).
fn four_bar_start() -> ([f64; 3], [f64; 3]) {
    let (a, b, c, d) = (1.0, 3.5, 3.0, 4.0);
    let (t2, mut t3, mut t4) = (0.3_f64, 1.2_f64, 1.9_f64);
    for _ in 0..50 {
        let r = [a * t2.cos() + b * t3.cos() - c * t4.cos() - d, a * t2.sin() + b * t3.sin() - c * t4.sin()];
        if r[0].abs().max(r[1].abs()) < 1e-15 {
            break;
        }
        // ∂r/∂(θ₃, θ₄)
        let j = [[-b * t3.sin(), c * t4.sin()], [b * t3.cos(), -c * t4.cos()]];
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        t3 -= (j[1][1] * r[0] - j[0][1] * r[1]) / det;
        t4 -= (-j[1][0] * r[0] + j[0][0] * r[1]) / det;
    }
    let w2 = 6.0;
    let j = [[-b * t3.sin(), c * t4.sin()], [b * t3.cos(), -c * t4.cos()]];
    let rhs = [a * t2.sin() * w2, -a * t2.cos() * w2];
    let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    let w3 = (j[1][1] * rhs[0] - j[0][1] * rhs[1]) / det;
    let w4 = (-j[1][0] * rhs[0] + j[0][0] * rhs[1]) / det;
    ([t2, t3, t4], [w2, w3, w4])
}

/// The peer's four-bar as a scene (bars of unit density: masses 1, 3.5, 3; gravity 9.81 in the
/// plane), DOPRI5 at `rtol`, over 2 s.
fn four_bar_scene(rtol: f64) -> Scene {
    let ([t2, t3, t4], [w2, w3, w4]) = four_bar_start();
    let text = format!(
        "name = \"four_bar\"\nduration = 2.0\nsamples = 2\nmethod = {{ name = \"dopri5\", rtol = {rtol:e} }}\n\
         outputs = [\"coordinates:crank\"]\n\
         [[bodies]]\nname = \"crank\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         mass = {{ shape = \"rod\", mass = 1.0, length = 1.0 }}\ncom = [0.5, 0.0, 0.0]\nq = [{t2:e}]\nv = [{w2:e}]\n\
         [[bodies]]\nname = \"coupler\"\nparent = \"crank\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         offset = [1.0, 0.0, 0.0]\nmass = {{ shape = \"rod\", mass = 3.5, length = 3.5 }}\ncom = [1.75, 0.0, 0.0]\n\
         q = [{:e}]\nv = [{:e}]\n\
         [[bodies]]\nname = \"rocker\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\noffset = [4.0, 0.0, 0.0]\n\
         mass = {{ shape = \"rod\", mass = 3.0, length = 3.0 }}\ncom = [1.5, 0.0, 0.0]\nq = [{t4:e}]\nv = [{w4:e}]\n\
         [[loops]]\ntype = \"pin\"\nname = \"tip\"\na = {{ body = \"coupler\", point = [3.5, 0.0, 0.0] }}\n\
         b = {{ body = \"rocker\", point = [3.0, 0.0, 0.0] }}\naxis = [0.0, 0.0, 1.0]\n\
         [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n",
        t3 - t2,
        w3 - w2
    );
    Scene::from_toml(&text, "four_bar").expect("the peer's four-bar as a scene")
}

/// The four-bar scene beside MuJoCo (scripts/peers/bench_mujoco_four_bar.py, same sitting):
/// prints the error of θ₂(2 s) and the largest violation of each setting, then times them.
fn four_bar_vs_mujoco(c: &mut Criterion) {
    let mut g = c.benchmark_group("four_bar_scene_2s");
    g.sample_size(10);
    for rtol in [1e-6, 1e-8, 1e-10] {
        let scene = four_bar_scene(rtol);
        let run = scene.run(&mut |_| {}).expect("runs");
        let th2 = run.column("coordinates:crank.0").expect("crank angle");
        let v = run.max_constraint_violation.unwrap_or_default();
        println!(
            "four-bar scene rtol {rtol:e}: |θ₂(2) − ref| = {:.1e}, max |φ| {:.1e}, |G v| {:.1e}, {} f-evals, {} projections",
            (th2[th2.len() - 1] - FOUR_BAR_TH2_REF).abs(),
            v.position,
            v.velocity,
            run.work.fevals,
            run.work.projections
        );
        g.bench_function(BenchmarkId::from_parameter(format!("rtol_{rtol:e}")), |b| {
            b.iter(|| black_box(scene.run(&mut |_| {}).expect("runs")))
        });
    }
    g.finish();
}

/// `VECTRIX_ICOUNT=case:side:iters`: `iters` evaluations of one scene_overhead case and exit.
fn icount_driver() -> bool {
    let Ok(spec) = std::env::var("VECTRIX_ICOUNT") else { return false };
    let parts: Vec<&str> = spec.split(':').collect();
    let [case, side, iters] = parts[..] else { panic!("VECTRIX_ICOUNT must be case:side:iters, got {spec}") };
    let iters: usize = iters.parse().expect("iters");
    type Hand = fn(&mut Direct, &[f64], &mut [f64]);
    let (text, hand): (String, Hand) = match case {
        "free_body" => (FREE_BODY.to_string(), |d, y, o| d.free_body(y, o)),
        "chain12" => (chain(12), |d, y, o| d.chain(y, o)),
        "two_body_orbit" => (TWO_BODIES.to_string(), |d, y, o| d.orbit(y, o, 1.0, [1.0, 2.0])),
        _ => panic!("case: free_body, chain12 or two_body_orbit"),
    };
    let scene = Scene::from_toml(&text, case).expect("scene");
    let y = scene.initial_state();
    let mut out = vec![0.0; y.len()];
    let (mut rhs, mut d) = (scene.rhs(), Direct::new(scene.model()));
    for _ in 0..iters {
        match side {
            "scene" => rhs.eval(0.0, black_box(&y), &mut out).expect("scene rhs"),
            _ => hand(&mut d, black_box(&y), &mut out),
        }
        black_box(&out);
    }
    println!("{case} {side} iters={iters} out0={}", out[0]);
    true
}

criterion_group!(benches, scenes, scene_overhead, four_bar_vs_mujoco);

fn main() {
    if icount_driver() {
        return;
    }
    benches();
    criterion::Criterion::default().configure_from_args().final_summary();
}
