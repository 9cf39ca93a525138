//! The vectrix side of the frontier: every problem through the library (every integrator that
//! applies: the adaptive pairs, extrapolation and, on the closed-form problems, the Taylor
//! method at a ladder of tolerances, the fixed-step methods at a ladder of step counts) and
//! through scenes (the three pairs DP5, DOP853 and Vern9, and GBS, at the same ladder of
//! tolerances).

use nalgebra::SVector;
use serde_json::{Value, json};
use vectrix::frames::Frame;
use vectrix::ode::explicit::{Adaptive, Extrapolation, Stepper, integrate_fixed};
use vectrix::ode::harness::{Reference, Separable};
use vectrix::ode::{
    AnyStepper, GaussLegendre, LieMethod, Method, RK4, Taylor, TaylorRhs, integrate_lie, stormer_verlet,
};
use vectrix::scene::Scene;

use crate::problems::{
    ARM7_Q0, CHAIN_T, EnergyPendulum, KEPLER, MODELS_DIR, PENDULUM, QUADRUPED_Q0, QUADRUPED_V0, TREE_T,
    TreeRhs, arm7_scene, chain_model, chain_scene, chain_y0, common_form, kepler_scene, max_abs_diff,
    pendulum_scene, quadruped_scene, rigid_body, rigid_scene, tree_model, tree_rhs,
};
use crate::timing::median_time;

/// Errors below this are round-off: a line stops there.
pub const FLOOR: f64 = 1e-13;

/// One point of a frontier (the JSON schema of `scripts/peers/frontier_common.py`).
#[derive(Debug, Clone)]
pub struct Point {
    pub problem: String,
    pub series: String,
    pub route: &'static str,
    pub method: String,
    pub param_name: &'static str,
    pub param: f64,
    pub error: f64,
    pub seconds: f64,
    pub repeats: usize,
    pub fevals: usize,
}

impl Point {
    pub fn to_json(&self) -> Value {
        json!({
            "problem": self.problem, "series": self.series, "tool": "vectrix", "route": self.route,
            "method": self.method, "param_name": self.param_name, "param": self.param,
            "error": if self.error.is_finite() { Some(self.error) } else { None },
            "seconds": self.seconds, "setup_seconds": 0.0, "repeats": self.repeats, "fevals": self.fevals,
        })
    }
}

/// The collected points and the ladders' limits.
pub struct Ctx {
    pub points: Vec<Point>,
    /// Fewer ladder rungs (a smoke run).
    pub quick: bool,
    /// A line stops once a run takes longer than this [s].
    pub cap: f64,
}

/// What one run returns: the final state (or the measured error) and the f-evals.
type Outcome = Result<(Vec<f64>, usize), String>;

impl Ctx {
    /// rtol = atol = 1e-3 … 1e-15, a decade apart. The peers' scipy ladders stop at 1e-14:
    /// solve_ivp raises any rtol below 100 ε to 2.2e-14, the tightest a scipy user can ask
    /// for; vectrix's pairs take rtol down to ε, and at 1e-15 DOP853 is still truncation-bound
    /// on Kepler e = 0.9 (error 1.7e-13 against 1.7e-12 at 1e-14), so a line goes on while it
    /// gains (it stops at the round-off floor [`FLOOR`]).
    fn tolerances(&self) -> Vec<f64> {
        if self.quick { vec![1e-3, 1e-6, 1e-9] } else { (3..=15).map(|k| 10f64.powi(-k)).collect() }
    }

    /// Runs `run(param)` along `params`, timing each and measuring `error(final state)`;
    /// stops a line at the round-off floor or once a run exceeds the cap.
    #[allow(clippy::too_many_arguments)]
    fn ladder(
        &mut self,
        problem: &str,
        route: &'static str,
        method: &str,
        param_name: &'static str,
        params: &[f64],
        mut run: impl FnMut(f64) -> Outcome,
        error: impl Fn(&[f64]) -> f64,
    ) {
        // FRONTIER_ROUTE=scene (or library): one route alone, e.g. for a before/after sitting
        if std::env::var("FRONTIER_ROUTE").is_ok_and(|r| r != route) {
            return;
        }
        let series = match route {
            "scene" => format!("vectrix scene {method}"),
            _ => format!("vectrix {method}"),
        };
        for &param in params {
            let (seconds, repeats, out) = median_time(|| run(param));
            let (error, fevals) = match out {
                Ok((y, fevals)) => (error(&y), fevals),
                Err(_) => (f64::INFINITY, 0),
            };
            eprintln!(
                "  {problem:16} {series:28} {param_name}={param:<10.3e} error {error:9.2e}  {seconds:.3e} s  x{repeats}"
            );
            self.points.push(Point {
                problem: problem.into(),
                series: series.clone(),
                route,
                method: method.into(),
                param_name,
                param,
                error,
                seconds,
                repeats,
                fevals,
            });
            if error < FLOOR || seconds > self.cap {
                break;
            }
        }
    }

    /// Step counts ⌈t_end·2ᵏ⌉, k = 0, 1, … (quick: every third).
    fn steps(&self, t_end: f64, kmax: i32) -> Vec<f64> {
        let stride = if self.quick { 3 } else { 1 };
        (0..=kmax).step_by(stride).map(|k| (t_end * 2f64.powi(k)).ceil()).collect()
    }

    /// A reference problem through the library: DP5, DOP853 and Vern9 at every tolerance, RK4,
    /// Gauss4 and Gauss6 at every step count.
    pub fn library<const N: usize, R: Reference<N>>(&mut self, id: &str, p: &R) {
        let (y0, t_end) = (p.y0(), p.t_end());
        let err = |y: &[f64]| p.error(&SVector::<f64, N>::from_column_slice(y));
        let tols = self.tolerances();
        for (name, a) in
            [("DP5", Adaptive::dopri5()), ("DOP853", Adaptive::dop853()), ("Vern9", Adaptive::vern9())]
        {
            let run = |tol: f64| -> Outcome {
                let s = a
                    .rtol(tol)
                    .atol(tol)
                    .solve(|t, y| p.rhs(t, y), 0.0, &y0, t_end)
                    .map_err(|e| e.to_string())?;
                Ok((s.last().as_slice().to_vec(), s.work.fevals))
            };
            self.ladder(id, "library", name, "rtol", &tols, run, err);
        }
        let run = |tol: f64| -> Outcome {
            let s = Extrapolation::gbs()
                .rtol(tol)
                .atol(tol)
                .solve(|t, y| p.rhs(t, y), 0.0, &y0, t_end)
                .map_err(|e| e.to_string())?;
            Ok((s.last().as_slice().to_vec(), s.work.fevals))
        };
        self.ladder(id, "library", "GBS", "rtol", &tols, run, err);
        let steps = self.steps(t_end, 22);
        self.ladder(
            id,
            "library",
            "RK4",
            "steps",
            &steps,
            |n| {
                let (y, w) =
                    integrate_fixed(&RK4, |t, y| p.rhs(t, y), 0.0, &y0, t_end, n as usize, |_, _| {})
                        .map_err(|e| e.to_string())?;
                Ok((y.as_slice().to_vec(), w.fevals))
            },
            err,
        );
        for g in [GaussLegendre::Gauss4, GaussLegendre::Gauss6] {
            let run = |n: f64| -> Outcome {
                let (y, w) = g
                    .integrate(|t, y| p.rhs(t, y), 0.0, &y0, t_end, n as usize, |_, _| {})
                    .map_err(|e| e.to_string())?;
                Ok((y.as_slice().to_vec(), w.fevals))
            };
            self.ladder(id, "library", g.name(), "steps", &steps, run, err);
        }
    }

    /// The Taylor integrator at every tolerance, on a problem whose right-hand side is also
    /// written over series ([`TaylorRhs`]: the closed-form problems).
    pub fn taylor<const N: usize, R: Reference<N> + TaylorRhs<N>>(&mut self, id: &str, p: &R) {
        let (y0, t_end) = (p.y0(), p.t_end());
        let err = |y: &[f64]| p.error(&SVector::<f64, N>::from_column_slice(y));
        let tols = self.tolerances();
        let run = |tol: f64| -> Outcome {
            let s = Taylor::new().rtol(tol).atol(tol).solve(p, 0.0, &y0, t_end).map_err(|e| e.to_string())?;
            Ok((s.last().as_slice().to_vec(), s.work.fevals))
        };
        self.ladder(id, "library", "Taylor", "rtol", &tols, run, err);
    }

    /// Störmer–Verlet on a separable problem y = (q, v).
    pub fn verlet<const N: usize, const M: usize, R: Reference<N> + Separable<M>>(
        &mut self,
        id: &str,
        p: &R,
    ) {
        let (y0, t_end) = (p.y0(), p.t_end());
        let q0 = SVector::<f64, M>::from_fn(|i, _| y0[i]);
        let v0 = SVector::<f64, M>::from_fn(|i, _| y0[M + i]);
        let steps = self.steps(t_end, 24);
        let run = |n: f64| -> Outcome {
            let ((q, v), w) =
                stormer_verlet(|_, q| p.accel(q), 0.0, &q0, &v0, t_end, n as usize, |_, _, _| {})
                    .map_err(|e| e.to_string())?;
            Ok(([q.as_slice(), v.as_slice()].concat(), w.fevals))
        };
        let err = |y: &[f64]| p.error(&SVector::<f64, N>::from_column_slice(y));
        self.ladder(id, "library", "Verlet", "steps", &steps, run, err);
    }

    /// The rigid body on Rotor × ℝ³ by the Lie-group methods (the error on ω as elsewhere).
    pub fn lie(&mut self, id: &str) {
        let rb = rigid_body();
        let a = Frame::new();
        let f = rb.lie_rhs(&a);
        let y0 = rb.lie_y0(&a);
        let steps = self.steps(rb.t_end, 22);
        for m in [LieMethod::Rkmk4, LieMethod::CrouchGrossman3] {
            let run = |n: f64| -> Outcome {
                let (y, w) = integrate_lie(m, &f, 0.0, &y0, rb.t_end, n as usize, |_, _| {})
                    .map_err(|e| e.to_string())?;
                Ok((vec![rb.lie_error(&a, &y).0], w.fevals))
            };
            self.ladder(id, "library", m.name(), "steps", &steps, run, |e| e[0]);
        }
    }

    /// A scene at every tolerance with the three pairs and GBS; `error` reads the run's final state.
    /// The scene files are parsed and validated before the timed runs.
    pub fn scene(&mut self, id: &str, toml: impl Fn(&str, f64) -> String, error: impl Fn(&[f64]) -> f64) {
        self.scene_in(id, "frontier", toml, error);
    }

    /// [`Ctx::scene`] with the scene files read as `dir` (where the files they name are).
    fn scene_in(
        &mut self,
        id: &str,
        dir: &str,
        toml: impl Fn(&str, f64) -> String,
        error: impl Fn(&[f64]) -> f64,
    ) {
        let tols = self.tolerances();
        for (name, key) in [("DP5", "dopri5"), ("DOP853", "dop853"), ("Vern9", "vern9"), ("GBS", "gbs")] {
            let scenes: Vec<(f64, Scene)> = tols
                .iter()
                .map(|&tol| match Scene::from_toml(&toml(key, tol), dir) {
                    Ok(s) => (tol, s),
                    Err(e) => panic!("{id}: the frontier's scene is invalid: {e}"),
                })
                .collect();
            let run = |tol: f64| -> Outcome {
                let scene = &scenes.iter().find(|(t, _)| *t == tol).expect("built above").1;
                let run = scene.run(&mut |_| {}).map_err(|e| e.to_string())?;
                if !run.is_complete() {
                    return Err("stopped early".into());
                }
                Ok((run.final_state, run.work.fevals))
            };
            self.ladder(id, "scene", name, "rtol", &tols, run, &error);
        }
    }

    /// The rigid body: library, Lie-group methods and the ball-joint scene.
    pub fn rigid_body(&mut self) {
        let id = "rigid-body";
        let rb = rigid_body();
        self.library(id, &rb);
        self.taylor(id, &rb);
        self.lie(id);
        let exact = rb.exact_omega(rb.t_end);
        // the scene's state is (quaternion, ω in link components)
        self.scene(id, rigid_scene, |y| max_abs_diff(&y[4..7], exact.as_slice()));
    }

    /// Kepler e = 0.9: library, Verlet and the free-particle scene.
    pub fn kepler(&mut self) {
        let id = "kepler-e0.9";
        self.library(id, &KEPLER);
        self.taylor(id, &KEPLER);
        self.verlet(id, &KEPLER);
        let exact = KEPLER.exact(KEPLER.t_end());
        // the scene's state is (x, y, z, quaternion, ẋ, ẏ, ż, ω)
        self.scene(id, kepler_scene, |y| max_abs_diff(&[y[0], y[1], y[7], y[8]], exact.as_slice()));
    }

    /// The pendulum at θ₀ = 3: library, Verlet and the particle-on-a-pin scene.
    pub fn pendulum(&mut self) {
        let id = "pendulum";
        self.library(id, &PENDULUM);
        self.taylor(id, &PENDULUM);
        self.verlet(id, &PENDULUM);
        let exact = PENDULUM.exact(PENDULUM.t_end());
        self.scene(
            id,
            |m, tol| pendulum_scene(PENDULUM.theta0, PENDULUM.t_end(), 1, m, tol),
            |y| max_abs_diff(y, exact.as_slice()),
        );
    }

    /// The n-link chain (N = 2n states) through `Model::aba_into` and through its scene.
    pub fn chain<const N: usize>(&mut self, reference: &[f64]) {
        let n = N / 2;
        let scene = |m: &str, tol| chain_scene(n, m, tol);
        self.tree::<N>(
            &format!("chain-{n}"),
            &chain_model(n),
            chain_y0::<N>(),
            CHAIN_T,
            reference,
            "frontier",
            scene,
        );
    }

    /// The 7-DOF arm of examples/models/arm7.urdf through `Model::aba_into` and its scene.
    pub fn arm7(&mut self, reference: &[f64]) {
        let y0 = SVector::<f64, 14>::from_fn(|i, _| if i < 7 { ARM7_Q0[i] } else { 0.0 });
        self.tree::<14>("arm7", &tree_model("arm7.urdf"), y0, TREE_T, reference, MODELS_DIR, arm7_scene);
    }

    /// The floating quadruped of examples/models/quadruped.urdf (19 + 18 states) the same way.
    pub fn quadruped(&mut self, reference: &[f64]) {
        let y0 = SVector::<f64, 37>::from_iterator(QUADRUPED_Q0.into_iter().chain(QUADRUPED_V0));
        let model = tree_model("quadruped.urdf");
        self.tree::<37>("quadruped", &model, y0, TREE_T, reference, MODELS_DIR, quadruped_scene);
    }

    /// A tree (N = nq + nv states) from y0 over [0, t_end] through `Model::aba_into` (DP5,
    /// DOP853, Vern9, GBS, RK4, Gauss6) and through its scene file (read as `dir`, where its model
    /// files are); the end state compared in the common form ([`common_form`]).
    #[allow(clippy::too_many_arguments)]
    fn tree<const N: usize>(
        &mut self,
        id: &str,
        model: &vectrix::dynamics::multibody::Model,
        y0: SVector<f64, N>,
        t_end: f64,
        reference: &[f64],
        dir: &str,
        scene: impl Fn(&str, f64) -> String,
    ) {
        let (id, y0) = (id.to_string(), &y0);
        let tau = vec![0.0; model.nv()];
        let err = |y: &[f64]| max_abs_diff(&common_form(model, y), reference);
        let tols = self.tolerances();
        for (name, a) in
            [("DP5", Adaptive::dopri5()), ("DOP853", Adaptive::dop853()), ("Vern9", Adaptive::vern9())]
        {
            let run = |tol: f64| -> Outcome {
                let mut scratch = model.aba_scratch();
                let f = |_: f64, y: &SVector<f64, N>| tree_rhs(model, &tau, &mut scratch, y);
                let s = a.rtol(tol).atol(tol).solve(f, 0.0, y0, t_end).map_err(|e| e.to_string())?;
                Ok((s.last().as_slice().to_vec(), s.work.fevals))
            };
            self.ladder(&id, "library", name, "rtol", &tols, run, err);
        }
        // GBS builds two rows of its table at once where the model evaluates two states at once
        // (a chain of pins: `Model::aba_pair_unchecked`)
        let run = |tol: f64| -> Outcome {
            let f = TreeRhs { model, tau: &tau, scratch: model.aba_scratch() };
            let s = Extrapolation::gbs()
                .rtol(tol)
                .atol(tol)
                .solve_rhs(f, 0.0, y0, t_end)
                .map_err(|e| e.to_string())?;
            Ok((s.last().as_slice().to_vec(), s.work.fevals))
        };
        self.ladder(&id, "library", "GBS", "rtol", &tols, run, err);
        let steps = self.steps(t_end, 20);
        let run = |k: f64| -> Outcome {
            let mut scratch = model.aba_scratch();
            let f = |_: f64, y: &SVector<f64, N>| tree_rhs(model, &tau, &mut scratch, y);
            let (y, w) =
                integrate_fixed(&RK4, f, 0.0, y0, t_end, k as usize, |_, _| {}).map_err(|e| e.to_string())?;
            Ok((y.as_slice().to_vec(), w.fevals))
        };
        self.ladder(&id, "library", "RK4", "steps", &steps, run, err);
        let run = |k: f64| -> Outcome {
            let mut scratch = model.aba_scratch();
            let f = |_: f64, y: &SVector<f64, N>| tree_rhs(model, &tau, &mut scratch, y);
            let (y, w) = GaussLegendre::Gauss6
                .integrate(f, 0.0, y0, t_end, k as usize, |_, _| {})
                .map_err(|e| e.to_string())?;
            Ok((y.as_slice().to_vec(), w.fevals))
        };
        self.ladder(&id, "library", "Gauss6", "steps", &steps, run, err);
        self.scene_in(&id, dir, scene, err);
    }

    /// The energy problem: max relative energy error at the checkpoints over 10⁴ periods.
    pub fn energy(&mut self) {
        let id = "energy-pendulum";
        let t_end = EnergyPendulum::t_end();
        let cps = EnergyPendulum::checkpoints();
        let cp_time = |k: usize| t_end * (k as f64 / cps as f64);
        let y0 = SVector::<f64, 2>::new(EnergyPendulum::THETA0, 0.0);
        let f = |_: f64, y: &SVector<f64, 2>| SVector::<f64, 2>::new(y[1], -y[0].sin());
        let tols = self.tolerances();
        for (name, a) in [("DP5", Adaptive::dopri5()), ("DOP853", Adaptive::dop853())] {
            // one integration, the checkpoints read off the dense output (as a scene does)
            let run = |tol: f64| -> Outcome {
                let e = |x: vectrix::ode::OdeError| x.to_string();
                let mut st = Stepper::new(&a.rtol(tol).atol(tol), f, 0.0, y0, t_end).map_err(e)?;
                let (mut worst, mut next) = (0.0f64, 1);
                while !st.done() {
                    st.step().map_err(e)?;
                    while next <= cps && cp_time(next) <= st.t() {
                        let y =
                            if next == cps { *st.y() } else { st.dense().map_err(e)?.eval(cp_time(next)) };
                        worst = worst.max(EnergyPendulum::rel(y[0], y[1]));
                        next += 1;
                    }
                }
                Ok((vec![worst], st.work().fevals))
            };
            self.ladder(id, "library", name, "rtol", &tols, run, |e| e[0]);
        }
        // the methods without an interpolant land on every checkpoint, as Odeint's RKF78 does
        // (`integrate_times`) and a scene does: Vern9 and GBS
        let landing = [
            (
                "Vern9",
                (|tol: f64| Method::Explicit(Adaptive::vern9().rtol(tol).atol(tol))) as fn(f64) -> Method,
            ),
            ("GBS", |tol: f64| Method::Gbs(Extrapolation::gbs().rtol(tol).atol(tol))),
        ];
        for (name, method) in landing {
            let run = |tol: f64| -> Outcome {
                let e = |x: vectrix::ode::OdeError| x.to_string();
                let none = None::<fn(f64, &SVector<f64, 2>, &mut [f64])>;
                let mut st = AnyStepper::new(&method(tol), f, none, 0.0, y0, cp_time(1)).map_err(e)?;
                let mut worst = 0.0f64;
                for k in 1..=cps {
                    if k > 1 {
                        st.set_end(cp_time(k)).map_err(e)?;
                    }
                    while !st.done() {
                        st.step().map_err(e)?;
                    }
                    worst = worst.max(EnergyPendulum::rel(st.y()[0], st.y()[1]));
                }
                Ok((vec![worst], st.work().fevals))
            };
            self.ladder(id, "library", name, "rtol", &tols, run, |e| e[0]);
        }
        // fixed steps: s steps a period, a checkpoint every EVERY·s steps
        let per_period: Vec<f64> =
            if self.quick { vec![8.0, 64.0] } else { (2..=12).map(|k| 2f64.powi(k)).collect() };
        let every = |s: f64| EnergyPendulum::EVERY * s as usize;
        let total = |s: f64| EnergyPendulum::PERIODS * s as usize;
        let run = |s: f64| -> Outcome {
            let (mut worst, mut k) = (0.0f64, 0usize);
            let (_, w) = integrate_fixed(&RK4, f, 0.0, &y0, t_end, total(s), |_, y| {
                k += 1;
                if k % every(s) == 0 {
                    worst = worst.max(EnergyPendulum::rel(y[0], y[1]));
                }
            })
            .map_err(|e| e.to_string())?;
            Ok((vec![worst], w.fevals))
        };
        self.ladder(id, "library", "RK4", "steps/period", &per_period, run, |e| e[0]);
        let q0 = SVector::<f64, 1>::new(EnergyPendulum::THETA0);
        let v0 = SVector::<f64, 1>::zeros();
        let run = |s: f64| -> Outcome {
            let (mut worst, mut k) = (0.0f64, 0usize);
            let (_, w) = stormer_verlet(
                |_, q| q.map(|x| -x.sin()),
                0.0,
                &q0,
                &v0,
                t_end,
                total(s),
                |_, q, v| {
                    k += 1;
                    if k % every(s) == 0 {
                        worst = worst.max(EnergyPendulum::rel(q[0], v[0]));
                    }
                },
            )
            .map_err(|e| e.to_string())?;
            Ok((vec![worst], w.fevals))
        };
        self.ladder(id, "library", "Verlet", "steps/period", &per_period, run, |e| e[0]);
        for g in [GaussLegendre::Gauss4, GaussLegendre::Gauss6] {
            let run = |s: f64| -> Outcome {
                let (mut worst, mut k) = (0.0f64, 0usize);
                let (_, w) = g
                    .integrate(f, 0.0, &y0, t_end, total(s), |_, y| {
                        k += 1;
                        if k % every(s) == 0 {
                            worst = worst.max(EnergyPendulum::rel(y[0], y[1]));
                        }
                    })
                    .map_err(|e| e.to_string())?;
                Ok((vec![worst], w.fevals))
            };
            self.ladder(id, "library", g.name(), "steps/period", &per_period, run, |e| e[0]);
        }
        // the scene checks the energy at its 1000 samples (every 10 periods) itself
        let tols = self.tolerances();
        for (name, key) in [("DP5", "dopri5"), ("DOP853", "dop853"), ("Vern9", "vern9"), ("GBS", "gbs")] {
            let scenes: Vec<(f64, Scene)> = tols
                .iter()
                .map(|&tol| {
                    let text = pendulum_scene(EnergyPendulum::THETA0, t_end, cps, key, tol);
                    (tol, Scene::from_toml(&text, "frontier").expect("valid scene"))
                })
                .collect();
            let run = |tol: f64| -> Outcome {
                let scene = &scenes.iter().find(|(t, _)| *t == tol).expect("built above").1;
                let run = scene.run(&mut |_| {}).map_err(|e| e.to_string())?;
                if !run.is_complete() {
                    return Err("stopped early".into());
                }
                // drift.max_abs = max |E − E(0)| over the samples
                Ok((vec![run.drift[0].max_abs / EnergyPendulum::e0()], run.work.fevals))
            };
            self.ladder(id, "scene", name, "rtol", &tols, run, |e| e[0]);
        }
    }
}
