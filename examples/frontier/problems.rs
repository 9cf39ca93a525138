//! The problems of the peer frontier, their error measures and their scene files; the same
//! definitions as `scripts/peers/frontier_common.py` (see its docstring).

use std::f64::consts::PI;

use nalgebra::{Matrix3, SVector, Vector3};
use vectrix::dynamics::multibody::{Joint, Link, Model};
use vectrix::ode::harness::elliptic::elliptic_k;
use vectrix::ode::harness::{Kepler, Pendulum, Reference, RigidBody};

/// Link length, capsule radius, link mass and gravity of the chain of
/// `../shared/peers/bench_mujoco.py`.
pub const LINK: f64 = 0.3;
/// Capsule radius [m].
pub const RADIUS: f64 = 0.02;
/// Link mass [kg].
pub const MASS: f64 = 1.0;
/// Gravity [m/s²] along −z.
pub const GRAVITY: f64 = 9.81;
/// The chains' end time [s].
pub const CHAIN_T: f64 = 1.0;
/// The chain lengths.
pub const CHAIN_NS: [usize; 5] = [1, 2, 6, 12, 30];

/// The spatial trees (examples/models/), their end time and initial angles: the 7-DOF arm of
/// arm7.urdf from rest at these angles (joint1 … joint7, rad), τ = 0, g = 9.81 m/s² along −z,
/// t ≤ 1 s. Kept in step with scripts/peers/spatial_reference.sh, which wrote the reference.
pub const ARM7_Q0: [f64; 7] = [0.3, 1.2, -0.5, -0.8, 0.4, 0.6, -0.2];
/// The spatial trees' end time [s].
pub const TREE_T: f64 = 1.0;

/// A model file of examples/models/ as a scene reads it (`[model] urdf = …`), with g = 9.81
/// m/s² along −z as Pinocchio's default.
pub fn tree_model(file: &str) -> Model {
    let toml = format!("name = \"tree\"\nduration = 1.0\n[model]\nurdf = \"{file}\"\n");
    let scene = vectrix::scene::Scene::from_toml(&toml, MODELS_DIR).unwrap_or_else(|e| panic!("{file}: {e}"));
    let mut m = scene.model().clone();
    m.gravity = Vector3::new(0.0, 0.0, -GRAVITY);
    m
}

/// The floating quadruped of quadruped.urdf: its trunk at the free joint's placement (0.45 m
/// up), level, turning at ω = (0.3, 0.5, 1.0) rad/s in its own frame, the legs at rest bent
/// (hip, thigh, calf of fl, fr, hl, hr), τ = 0, falling freely for `TREE_T`. vectrix's layout:
/// q = (x, y, z, η, ε₁, ε₂, ε₃, 12 angles), v = (ẋ, ẏ, ż, ω, 12 rates); kept in step with
/// scripts/peers/spatial_reference.sh.
pub const QUADRUPED_Q0: [f64; 19] =
    [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.2, 0.7, -1.4, -0.2, 0.7, -1.4, 0.2, -0.7, 1.4, -0.2, -0.7, 1.4];
/// The quadruped's initial velocities (see [`QUADRUPED_Q0`]).
pub const QUADRUPED_V0: [f64; 18] =
    [0.0, 0.0, 0.0, 0.3, 0.5, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];

/// The quadruped as a scene file: the URDF with gravity, angles and the trunk's spin by link.
pub fn quadruped_scene(method: &str, rtol: f64) -> String {
    let mut s = header("quadruped", TREE_T, 1, method, rtol);
    s += "\n[model]\nurdf = \"quadruped.urdf\"\ngravity = true\n\n[model.q]\n";
    for (k, leg) in ["fl", "fr", "hl", "hr"].iter().enumerate() {
        for (j, part) in ["hip", "thigh", "calf"].iter().enumerate() {
            s += &format!("{leg}_{part} = [{:?}]\n", QUADRUPED_Q0[7 + 3 * k + j]);
        }
    }
    let w = &QUADRUPED_V0[3..6];
    s += &format!("\n[model.v]\ntrunk = [0.0, 0.0, 0.0, {:?}, {:?}, {:?}]\n", w[0], w[1], w[2]);
    s
}

/// A tree's end state (q, v) in the frontier's common form (scripts/peers/cpp/pin_dump.hpp
/// `common_form`): as it is for a fixed base; with a free joint at the root (nq ≠ nv), the
/// attitude quaternion's sign chosen so that η ≥ 0 (vectrix's free joint already has the
/// position and its rate in the joint frame, ω in the body).
pub fn common_form(model: &Model, y: &[f64]) -> Vec<f64> {
    let mut out = y.to_vec();
    if model.nq() != model.nv() && out.len() >= 7 && out[3] < 0.0 {
        out[3..7].iter_mut().for_each(|x| *x = -*x);
    }
    out
}

/// The scene path the tree scenes are read as (their model files are beside it).
pub const MODELS_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/models/frontier.toml");

/// The arm as a scene file: the URDF with gravity and the initial angles by link name.
pub fn arm7_scene(method: &str, rtol: f64) -> String {
    let mut s = header("arm7", TREE_T, 1, method, rtol);
    s += "\n[model]\nurdf = \"arm7.urdf\"\ngravity = true\n\n[model.q]\n";
    for (i, q) in ARM7_Q0.iter().enumerate() {
        s += &format!("link{} = [{q:?}]\n", i + 1);
    }
    s
}

/// The extended-precision end state (q, v) of a spatial tree, the doubles nearest the
/// quadruple-precision values of `tests/data/spatial_reference.json`
/// (scripts/peers/spatial_reference.sh: Pinocchio's ABA in float128 under fixed-step GBS), and
/// its `rounding_spread`: how far the end state moves when every number of the model moves
/// within ±1 ulp (two parsers' equally valid doubles of the same file).
pub fn spatial_reference(id: &str) -> Option<(Vec<f64>, f64)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/spatial_reference.json");
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    let tree = &doc["trees"][id];
    let state =
        tree["state"].as_array()?.iter().map(serde_json::Value::as_f64).collect::<Option<Vec<f64>>>()?;
    Some((state, tree["rounding_spread"].as_f64()?))
}

/// y′ = (q̇(q, v), ABA(q, v, τ)) of a tree (N = nq + nv states): q̇ = v for pins and sliders,
/// a free joint's quaternion by `Model::qdot_into`; NaN accelerations if ABA refuses.
///
/// Book: §7.11 (ABA), §2.15 (quaternion rates).
#[inline]
pub fn tree_rhs<const N: usize>(
    model: &vectrix::dynamics::multibody::Model,
    tau: &[f64],
    scratch: &mut vectrix::dynamics::multibody::AbaScratch,
    y: &SVector<f64, N>,
) -> SVector<f64, N> {
    let nq = model.nq();
    let mut out = SVector::<f64, N>::zeros();
    let (q, v) = y.as_slice().split_at(nq);
    let (qd, vd) = out.as_mut_slice().split_at_mut(nq);
    if nq == v.len() {
        qd.copy_from_slice(v);
    } else {
        // a free joint's quaternion: q̇ = ½ q ⊗ (0, ω)
        model.qdot_into(q, v, qd);
    }
    if model.aba_into(q, v, tau, None, vd, scratch).is_err() {
        vd.fill(f64::NAN);
    }
    out
}

/// [`tree_rhs`] as an [`Rhs`](vectrix::ode::Rhs) that evaluates two states at once where the
/// model can (`Model::aba_pair_unchecked`: a planar chain of pins), which GBS uses to build
/// two rows of its table side by side (`Extrapolation::solve_rhs`).
pub struct TreeRhs<'a> {
    pub model: &'a vectrix::dynamics::multibody::Model,
    pub tau: &'a [f64],
    pub scratch: vectrix::dynamics::multibody::AbaScratch,
}

impl<const N: usize> vectrix::ode::Rhs<SVector<f64, N>> for TreeRhs<'_> {
    const IN_PLACE: bool = false;
    fn call(&mut self, _: f64, y: &SVector<f64, N>) -> SVector<f64, N> {
        tree_rhs(self.model, self.tau, &mut self.scratch, y)
    }
    fn call_into(&mut self, _: f64, y: &SVector<f64, N>, out: &mut SVector<f64, N>) {
        *out = tree_rhs(self.model, self.tau, &mut self.scratch, y);
    }
    fn pairs(&self) -> bool {
        self.model.aba_pairs()
    }
    fn call_pair_into(
        &mut self,
        (_, ya, oa): (f64, &SVector<f64, N>, &mut SVector<f64, N>),
        (_, yb, ob): (f64, &SVector<f64, N>, &mut SVector<f64, N>),
    ) {
        let nq = self.model.nq();
        if !self.model.aba_pairs() {
            *oa = tree_rhs(self.model, self.tau, &mut self.scratch, ya);
            *ob = tree_rhs(self.model, self.tau, &mut self.scratch, yb);
            return;
        }
        let (qa, va) = ya.as_slice().split_at(nq);
        let (qb, vb) = yb.as_slice().split_at(nq);
        let (qda, vda) = oa.as_mut_slice().split_at_mut(nq);
        let (qdb, vdb) = ob.as_mut_slice().split_at_mut(nq);
        qda.copy_from_slice(va);
        qdb.copy_from_slice(vb);
        if self.model.aba_pair_unchecked((qa, va), (qb, vb), self.tau, (vda, vdb), &mut self.scratch).is_err()
        {
            *oa = tree_rhs(self.model, self.tau, &mut self.scratch, ya);
            *ob = tree_rhs(self.model, self.tau, &mut self.scratch, yb);
        }
    }
}

/// The torque-free body of the harness: I = (1, 2, 3), ω(0) = (1, 0, 0.5), t ∈ [0, 20].
pub fn rigid_body() -> RigidBody {
    RigidBody { inertia: [1.0, 2.0, 3.0], omega13: [1.0, 0.5], t_end: 20.0 }
}

/// Kepler from periapsis, e = 0.9, t ∈ [0, 20].
pub const KEPLER: Kepler = Kepler { e: 0.9 };

/// θ̈ = −sin θ from rest at θ₀ = 3 rad, t ∈ [0, 10].
pub const PENDULUM: Pendulum = Pendulum { theta0: 3.0 };

/// Principal moments (about the centre; perpendicular, axial) of a solid capsule of mass m,
/// radius r and cylinder length h, uniform density: a cylinder and two hemispherical caps
/// (each cap's centre of mass 3r/8 from its flat face, so its parallel-axis shift is
/// h²/4 + 3hr/8 beyond its own 2r²/5 … as MuJoCo computes it for `type="capsule"`).
pub fn capsule_inertia(r: f64, h: f64, m: f64) -> (f64, f64) {
    let vol = PI * r * r * h + 4.0 / 3.0 * PI * r.powi(3);
    let mc = m * PI * r * r * h / vol;
    let ms = m - mc;
    let axial = mc * r * r / 2.0 + ms * 2.0 * r * r / 5.0;
    let perp = mc * (h * h / 12.0 + r * r / 4.0) + ms * (2.0 * r * r / 5.0 + h * h / 4.0 + 3.0 * h * r / 8.0);
    (perp, axial)
}

/// q(0) of the n-link chain: (0.7, 0.1, …, 0.1) rad (relative hinge angles), v(0) = 0.
pub fn chain_q0(n: usize) -> Vec<f64> {
    (0..n).map(|i| if i == 0 { 0.7 } else { 0.1 }).collect()
}

/// The chain of bench_mujoco.py as a multibody model: link i hangs from hinge i about ŷ,
/// its centre at −(l/2)ẑ and the next hinge at −lẑ (link frame), gravity −9.81ẑ.
pub fn chain_model(n: usize) -> Model {
    let (perp, axial) = capsule_inertia(RADIUS, LINK, MASS);
    let inertia = Matrix3::from_diagonal(&Vector3::new(perp, perp, axial));
    let links: Vec<Link> = (0..n)
        .map(|i| {
            let offset = if i == 0 { Vector3::zeros() } else { Vector3::new(0.0, 0.0, -LINK) };
            Link::new(
                i.checked_sub(1),
                Joint::Pin { axis: Vector3::y() },
                offset,
                MASS,
                Vector3::new(0.0, 0.0, -LINK / 2.0),
                inertia,
            )
        })
        .collect();
    let mut m = Model::new(&links).expect("the chain is a valid tree");
    m.gravity = Vector3::new(0.0, 0.0, -GRAVITY);
    m
}

/// The chain as a scene file (pins about ŷ, `value` masses with the capsule's moments).
pub fn chain_scene(n: usize, method: &str, rtol: f64) -> String {
    let (perp, axial) = capsule_inertia(RADIUS, LINK, MASS);
    let mut s = header("chain", CHAIN_T, 1, method, rtol);
    s += &format!("\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, 0.0, {:?}]\n", -GRAVITY);
    for (i, q) in chain_q0(n).iter().enumerate() {
        let parent = if i == 0 {
            String::new()
        } else {
            format!("parent = \"l{}\"\noffset = [0.0, 0.0, {:?}]\n", i - 1, -LINK)
        };
        s += &format!(
            "\n[[bodies]]\nname = \"l{i}\"\n{parent}joint = {{ type = \"pin\", axis = [0.0, 1.0, 0.0] }}\n\
             mass = {{ shape = \"value\", mass = {MASS:?}, principal = [{perp:?}, {perp:?}, {axial:?}] }}\n\
             com = [0.0, 0.0, {:?}]\nq = [{q:?}]\n",
            -LINK / 2.0
        );
    }
    s
}

fn header(name: &str, duration: f64, samples: usize, method: &str, rtol: f64) -> String {
    format!(
        "name = \"{name}\"\nduration = {duration:?}\nsamples = {samples}\nmethod = {{ name = \"{method}\", rtol = {rtol:?} }}\n"
    )
}

/// The torque-free body as a scene: a ball joint on the ground (v = ω in link components).
pub fn rigid_scene(method: &str, rtol: f64) -> String {
    let rb = rigid_body();
    let w = rb.exact_omega(0.0);
    header("rigid_body", rb.t_end, 1, method, rtol)
        + &format!(
            "\n[[bodies]]\nname = \"b\"\njoint = {{ type = \"ball\" }}\n\
             mass = {{ shape = \"value\", mass = 1.0, principal = [{:?}, {:?}, {:?}] }}\nv = [{:?}, {:?}, {:?}]\n",
            rb.inertia[0], rb.inertia[1], rb.inertia[2], w[0], w[1], w[2]
        )
}

/// Kepler as a scene: a free particle (a small sphere) around a central field μ = 1.
pub fn kepler_scene(method: &str, rtol: f64) -> String {
    let y0 = KEPLER.y0();
    header("kepler", KEPLER.t_end(), 1, method, rtol)
        + &format!(
            "\n[[bodies]]\nname = \"p\"\njoint = {{ type = \"free\" }}\n\
             mass = {{ shape = \"sphere\", mass = 1.0, radius = 0.01 }}\n\
             q = [{:?}, {:?}, 0.0, 1.0, 0.0, 0.0, 0.0]\nv = [{:?}, {:?}, 0.0, 0.0, 0.0, 0.0]\n\n\
             [[effects]]\ntype = \"central_gravity\"\nmu = 1.0\ncentre = [0.0, 0.0, 0.0]\n",
            y0[0], y0[1], y0[2], y0[3]
        )
}

/// The unit pendulum as a scene: a particle at distance 1 on a pin about ẑ, g = 1 along −ŷ.
pub fn pendulum_scene(theta0: f64, duration: f64, samples: usize, method: &str, rtol: f64) -> String {
    let checks = if samples > 1 { "checks = [\"energy\"]\n" } else { "" };
    header("pendulum", duration, samples, method, rtol)
        + checks
        + &format!(
            "\n[[bodies]]\nname = \"bob\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
             mass = {{ shape = \"particle\", mass = 1.0 }}\ncom = [0.0, -1.0, 0.0]\nq = [{theta0:?}]\n\n\
             [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -1.0, 0.0]\n"
        )
}

/// The energy problem: θ̈ = −sin θ from rest at θ₀ = 1 rad over 10⁴ periods, energy checked
/// every 10 periods.
pub struct EnergyPendulum;

impl EnergyPendulum {
    /// Amplitude [rad].
    pub const THETA0: f64 = 1.0;
    /// Number of periods.
    pub const PERIODS: usize = 10_000;
    /// Periods between checkpoints.
    pub const EVERY: usize = 10;

    /// The period 4K(sin²(θ₀/2)).
    pub fn period() -> f64 {
        4.0 * elliptic_k((0.5 * Self::THETA0).sin().powi(2)).expect("m < 1")
    }
    /// End time.
    pub fn t_end() -> f64 {
        Self::PERIODS as f64 * Self::period()
    }
    /// Number of checkpoints after t = 0.
    pub fn checkpoints() -> usize {
        Self::PERIODS / Self::EVERY
    }
    /// E₀ = 1 − cos θ₀, the energy above the bottom.
    pub fn e0() -> f64 {
        1.0 - Self::THETA0.cos()
    }
    /// |E − E₀|/E₀ with E = θ̇²/2 + 1 − cos θ.
    pub fn rel(theta: f64, omega: f64) -> f64 {
        (0.5 * omega * omega + 1.0 - theta.cos() - Self::e0()).abs() / Self::e0()
    }
}

/// max-norm distance of two states, ∞ if either is not finite (every component is tested:
/// `f64::max` alone would drop a NaN).
pub fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    let finite = a.iter().chain(b).all(|x| x.is_finite());
    let e = a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
    if finite && a.len() == b.len() { e } else { f64::INFINITY }
}

/// The closed-form problems whose end states have an extended-precision reference.
pub const CLOSED_FORMS: [&str; 3] = ["rigid-body", "kepler-e0.9", "pendulum"];

/// The extended-precision end state of a closed-form problem (`rigid-body`: ω(20) in body
/// components; `kepler-e0.9`: (x, y, ẋ, ẏ)(20); `pendulum`: (θ, θ̇)(10)), as the nearest
/// doubles of mpmath's 40-digit values: `scripts/peers/closed_form_reference_mp.py`, committed
/// as `tests/data/closed_form_reference_mp.json`; the peers measure their errors against it.
/// Reference: Landau & Lifshitz, Mechanics §37 (the body); Kepler's equation; the pendulum's
/// Jacobi elliptic solution (Book §4.11).
pub fn closed_form_mp(id: &str) -> Option<Vec<f64>> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/closed_form_reference_mp.json");
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    doc["problems"][id]["state"].as_array()?.iter().map(serde_json::Value::as_f64).collect()
}

/// The same end state from vectrix's double-precision closed forms (`vectrix::ode::harness`),
/// which the vectrix routes of the frontier measure their errors against.
pub fn closed_form_f64(id: &str) -> Option<Vec<f64>> {
    match id {
        "rigid-body" => {
            let rb = rigid_body();
            Some(rb.exact_omega(rb.t_end).as_slice().to_vec())
        }
        "kepler-e0.9" => Some(KEPLER.exact(KEPLER.t_end()).as_slice().to_vec()),
        "pendulum" => Some(PENDULUM.exact(PENDULUM.t_end()).as_slice().to_vec()),
        _ => None,
    }
}

/// The chain's state y = (q, v) as a fixed-size vector.
pub fn chain_y0<const N: usize>() -> SVector<f64, N> {
    let n = N / 2;
    let q = chain_q0(n);
    SVector::from_fn(|i, _| if i < n { q[i] } else { 0.0 })
}
