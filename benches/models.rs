//! RNEA, ABA, CRBA and their derivatives on the imported 3-D trees of examples/models/ (issue
//! 35, item 4): the 7-DOF arm (arm7.urdf), the floating quadruped (quadruped.urdf, 12 joints
//! and a free base) and the humanoid (humanoid.xml), the same files Pinocchio C++ loads in
//! benches/peers/pin_models.cpp.
//!
//! Instruction counts (repeatable on a loaded machine): with `VECTRIX_ICOUNT_MODEL=algo:file:iters`
//! the binary runs `iters` calls of one algorithm on the model and exits; `sh
//! benches/peers/icount_models.sh` takes the difference of two runs under callgrind (set-up
//! cancels) beside Pinocchio's.
use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use vectrix::dynamics::multibody::{AbaDerivatives, Model, RneaDerivatives};
use vectrix::nalgebra::{DMatrix, Vector3};
use vectrix::scene::Scene;

/// The model of examples/models/`file` as a scene sees it, gravity −9.81 ẑ.
fn load(file: &str) -> Model {
    let key = if file.ends_with(".xml") { "mjcf" } else { "urdf" };
    let toml = format!("name = \"b\"\nduration = 1.0\n[model]\n{key} = \"{file}\"\n");
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/models/scene.toml");
    let scene = Scene::from_toml(&toml, dir).unwrap_or_else(|e| panic!("{e}"));
    let mut model = scene.model().clone();
    model.gravity = Vector3::new(0.0, 0.0, -9.81);
    model
}

/// `count` deterministic states (q, v, a): q = neutral ⊕ random displacement in [−1, 1].
fn states(model: &Model, count: usize) -> Vec<(Vec<f64>, Vec<f64>, Vec<f64>)> {
    let mut x = 0.123_456_789f64;
    let mut r = |n: usize| -> Vec<f64> {
        (0..n)
            .map(|_| {
                x = (x * 997.0 + 0.412_345_678).fract();
                2.0 * x - 1.0
            })
            .collect()
    };
    let nv = model.nv();
    (0..count)
        .map(|_| {
            let q = model.integrate(&model.neutral(), &r(nv), 1.0).unwrap();
            (q, r(nv), r(nv))
        })
        .collect()
}

struct Bench {
    model: Model,
    s: Vec<(Vec<f64>, Vec<f64>, Vec<f64>)>,
    scratch: vectrix::dynamics::multibody::Scratch,
    aba: vectrix::dynamics::multibody::AbaScratch,
    crba: vectrix::dynamics::multibody::CrbaScratch,
    deriv: vectrix::dynamics::multibody::DerivativeScratch,
    h: DMatrix<f64>,
    rd: RneaDerivatives,
    ad: AbaDerivatives,
    out: Vec<f64>,
    k: usize,
}

impl Bench {
    fn new(file: &str) -> Self {
        let model = load(file);
        let nv = model.nv();
        Self {
            s: states(&model, 64),
            scratch: model.scratch(),
            aba: model.aba_scratch(),
            crba: model.crba_scratch(),
            deriv: model.derivative_scratch(),
            h: DMatrix::zeros(nv, nv),
            rd: RneaDerivatives::zeros(&model),
            ad: AbaDerivatives::zeros(&model),
            out: vec![0.0; nv],
            k: 0,
            model,
        }
    }

    /// One call of `algo` on the next state; returns one output number.
    fn run(&mut self, algo: &str) -> f64 {
        self.k = (self.k + 1) % self.s.len();
        let (q, v, a) = &self.s[self.k];
        match algo {
            "rnea" => {
                self.model.rnea_unchecked(q, v, a, &mut self.out, &mut self.scratch);
                self.out[0]
            }
            "aba" => {
                self.model.aba_unchecked(q, v, a, &mut self.out, &mut self.aba).unwrap();
                self.out[0]
            }
            "crba" => {
                self.model.crba_into(q, &mut self.h, &mut self.crba);
                self.h[(0, 0)]
            }
            "rnea_derivatives" => {
                self.model.rnea_derivatives_into(q, v, a, None, &mut self.rd, &mut self.deriv);
                self.rd.dtau_dq[(0, 0)] + self.rd.dtau_dv[(0, 0)]
            }
            "aba_derivatives" => {
                self.model.aba_derivatives_into(q, v, a, None, &mut self.ad, &mut self.deriv).unwrap();
                self.ad.dvdot_dq[(0, 0)] + self.ad.dvdot_dv[(0, 0)] + self.ad.dvdot_dtau[(0, 0)]
            }
            other => panic!("unknown algorithm {other}"),
        }
    }
}

const MODELS: [&str; 3] = ["arm7.urdf", "quadruped.urdf", "humanoid.xml"];
const ALGORITHMS: [&str; 5] = ["rnea", "aba", "crba", "rnea_derivatives", "aba_derivatives"];

/// `VECTRIX_ICOUNT_MODEL=algo:file:iters`: run one algorithm `iters` times and exit.
fn icount_driver() -> bool {
    let Ok(spec) = std::env::var("VECTRIX_ICOUNT_MODEL") else { return false };
    let p: Vec<&str> = spec.split(':').collect();
    assert!(p.len() == 3, "VECTRIX_ICOUNT_MODEL must be algo:file:iters, got {spec}");
    let iters: usize = p[2].parse().expect("iters");
    let mut b = Bench::new(p[1]);
    let mut sink = 0.0;
    for _ in 0..iters {
        sink += b.run(p[0]);
    }
    println!("{} {} iters={iters} sink={sink}", p[0], p[1]);
    true
}

fn models(c: &mut Criterion) {
    let mut g = c.benchmark_group("dynamics/models");
    for file in MODELS {
        let mut b = Bench::new(file);
        for algo in ALGORITHMS {
            g.bench_function(BenchmarkId::new(algo, file), |bch| bch.iter(|| black_box(b.run(algo))));
        }
    }
    g.finish();
}

criterion_group!(benches, models);

fn main() {
    if icount_driver() {
        return;
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
}
