//! vectrix-dynamics' scene layer under hostile input (docs/robustness.md): scene files with
//! hostile numbers (a mass of 1e-320, `nan`, `inf`, 1e308, huge sample counts, empty and
//! hostile names) are refused with a `file:line:column`, or load into a scene whose dynamics
//! keep their laws, checked independently: M symmetric positive definite with T = ½vᵀMv and
//! M v̇ = Q at the state; energy conserved along a run of a conservative scene; the double
//! pendulum's normal modes ω² = (g/l)(2 ± √2); a run converted to imperial units by the
//! exact factors; the source locator's spans inside the text.

use crate::support::NanAmax;
use std::sync::atomic::AtomicBool;

use nalgebra::{DMatrix, DVector};
use vectrix::scene::spec::{LoopSpec, Profile};
use vectrix::scene::{
    EquilibriumResidual, InvariantValue, LinearModel, RunControl, Scene, SceneError, SceneSource,
    body_schema, check_name,
};
use vectrix::units::UnitSystem;

use crate::harness::{err_or, finite, refused};

/// The double pendulum of two unit point masses on unit rods, hanging at rest (an
/// equilibrium) or released from `q`.
pub(crate) fn double_pendulum(q: [f64; 2], extra: &str) -> String {
    format!(
        r#"name = "dp"
duration = 0.5
samples = 11
accuracy = 1e-10
outputs = ["coordinates:upper", "energy"]
checks = ["energy"]
{extra}
[[bodies]]
name = "upper"
joint = {{ type = "pin", axis = [0.0, 0.0, 1.0] }}
mass = {{ shape = "particle", mass = 1.0 }}
com = [0.0, -1.0, 0.0]
q = [{:?}]

[[bodies]]
name = "lower"
parent = "upper"
joint = {{ type = "pin", axis = [0.0, 0.0, 1.0] }}
offset = [0.0, -1.0, 0.0]
mass = {{ shape = "particle", mass = 1.0 }}
com = [0.0, -1.0, 0.0]
q = [{:?}]

[[effects]]
type = "uniform_gravity"
g = [0.0, -9.81, 0.0]
"#,
        q[0], q[1]
    )
}

/// TOML spellings of the hostile numbers (TOML has `nan` and `inf`).
const HOSTILE_TOML: [&str; 14] = [
    "0.0",
    "-0.0",
    "5e-324",
    "1e-320",
    "2.2250738585072014e-308",
    "1e-300",
    "-1e-300",
    "1e300",
    "-1e300",
    "1.7976931348623157e308",
    "inf",
    "-inf",
    "nan",
    "-nan",
];

/// A refusal names the file, line and column: `dp.toml:L:C: …`.
pub(crate) fn located(e: &SceneError) -> bool {
    let s = e.to_string();
    let mut parts = s.splitn(4, ':');
    parts.next() == Some("dp.toml")
        && parts.next().is_some_and(|l| l.parse::<usize>().is_ok_and(|l| l >= 1))
        && parts.next().is_some_and(|c| c.parse::<usize>().is_ok_and(|c| c >= 1))
}

/// The laws of an accepted scene at its initial state: finite y₀ and y′; M symmetric
/// positive definite; T = ½vᵀMv; M v̇ = Q (no inerters or rolling in these scenes).
fn sound(s: &Scene) -> bool {
    let y0 = s.initial_state();
    let nq = s.model().nq();
    if !finite(&y0) || y0.len() != nq + s.model().nv() {
        return false;
    }
    let Ok(d) = s.derivative(0.0, &y0) else { return true };
    let Ok(st) = s.query(0.0, &y0) else { return true };
    let m = &st.mass_matrix;
    let v = DVector::from_column_slice(&y0[nq..]);
    let vd = DVector::from_column_slice(&d[nq..]);
    let t = 0.5 * v.dot(&(m * &v));
    let q_scale = st.generalized_forces.nan_amax() + m.nan_amax() * vd.nan_amax();
    finite(&d)
        && (m - m.transpose()).nan_amax() <= 1e-12 * m.nan_amax()
        && m.clone().cholesky().is_some()
        && (st.kinetic - t).abs() <= 1e-9 * t.abs().max(f64::MIN_POSITIVE)
        && (m * &vd - &st.generalized_forces).nan_amax() <= 1e-9 * q_scale.max(f64::MIN_POSITIVE)
}

cases! {
    // Loading (file format): every hostile number at every numeric key of a scene, every
    // hostile sample count and name, is refused at its line and column or gives a sound
    // scene; save → load gives the same scene.
    scene_loading ["Scene::from_toml", "Scene::from_source", "Scene::from_spec", "Scene::from_spec_in", "Scene::spec",
        "Scene::to_toml", "Scene::model", "Scene::initial_state", "Scene::invariants", "Invariant::name",
        "Scene::columns"] {
        let text = double_pendulum([0.4, -0.3], "");
        let s = Scene::from_toml(&text, "dp.toml").unwrap();
        assert!(sound(&s));
        // the columns a run writes are known before it runs; a repeated output is refused
        assert_eq!(s.columns(), ["coordinates:upper.0", "energy"]);
        let twice = text.replacen("outputs = [\"coordinates:upper\", \"energy\"]", "outputs = [\"energy\", \"energy\"]", 1);
        match Scene::from_toml(&twice, "dp.toml") {
            Ok(_) => panic!("a repeated output accepted"),
            Err(e) => assert!(located(&e) && e.to_string().contains("repeats outputs[0]"), "{e}"),
        }
        assert_eq!(s.model().nq(), 2);
        assert!(s.invariants().iter().any(|i| i.name() == "energy"));
        assert!(s.invariants().iter().all(|i| ["energy", "momentum", "angular_momentum"].contains(&i.name())));
        let back = Scene::from_toml(&s.to_toml().unwrap(), "dp.toml").unwrap();
        assert_eq!(back.spec(), s.spec());
        let src = SceneSource::new(&text, "dp.toml").unwrap();
        assert_eq!(Scene::from_source(&src).unwrap().spec(), s.spec());
        for x in HOSTILE_TOML {
            let keys = [
                ("mass = 1.0", format!("mass = {x}")),
                ("com = [0.0, -1.0, 0.0]\nq = [0.4]", format!("com = [0.0, {x}, 0.0]\nq = [0.4]")),
                ("q = [0.4]", format!("q = [{x}]")),
                ("q = [-0.3]", format!("q = [-0.3]\nv = [{x}]")),
                ("g = [0.0, -9.81, 0.0]", format!("g = [0.0, {x}, 0.0]")),
                ("duration = 0.5", format!("duration = {x}")),
                ("accuracy = 1e-10", format!("accuracy = {x}")),
                ("axis = [0.0, 0.0, 1.0] }\nmass", format!("axis = [0.0, {x}, {x}] }}\nmass")),
                ("offset = [0.0, -1.0, 0.0]", format!("offset = [{x}, -1.0, 0.0]")),
                ("duration = 0.5", format!("duration = 0.5\nmax_wall_seconds = {x}")),
            ];
            for (from, to) in keys {
                assert!(text.contains(from), "{from}");
                let t = text.replacen(from, &to, 1);
                match Scene::from_toml(&t, "dp.toml") {
                    Ok(s) => assert!(sound(&s), "{to:?}: accepted, but not sound: {:?} {:?}", s.derivative(0.0, &s.initial_state()), s.query(0.0, &s.initial_state())),
                    Err(e) => assert!(located(&e), "{to}: {e}"),
                }
            }
        }
        for n in ["0", "1", "-1", "1000001", "9223372036854775807", "18446744073709551615", "1e3", "\"many\""] {
            let t = text.replacen("samples = 11", &format!("samples = {n}"), 1);
            match Scene::from_toml(&t, "dp.toml") {
                Ok(s) => assert!((1..=vectrix::scene::MAX_SAMPLES).contains(&s.spec().samples), "samples = {n}"),
                Err(e) => assert!(located(&e), "samples = {n}: {e}"),
            }
        }
        for name in ["", "..", "/", "a/b", ".hidden", "\u{202e}evil", "nul\\u0000", &"x".repeat(100_000)] {
            let t = text.replacen("name = \"dp\"", &format!("name = {name:?}"), 1);
            refused(Scene::from_toml(&t, "dp.toml"), &format!("scene name {name:.20?}"));
            let t = text.replacen("name = \"upper\"", &format!("name = {name:?}"), 1);
            refused(Scene::from_toml(&t, "dp.toml"), &format!("body name {name:.20?}"));
        }
        // a particle's mass of 1e-320 (subnormal): refused or sound, never ∞ in y′
        let tiny = text.replace("mass = 1.0", "mass = 1e-320");
        err_or(Scene::from_toml(&tiny, "dp.toml"), "mass 1e-320", sound);
        for bad in ["", "[[bodies]", "name = ", "\u{0}", "bodies = 3", "name = \"dp\"\nname = \"dp\""] {
            match Scene::from_toml(bad, "dp.toml") {
                Ok(s) => panic!("{bad:?} accepted: {s:?}"),
                Err(e) => assert!(located(&e), "{bad:?}: {e}"),
            }
        }
        // a spec changed in memory is validated like a file
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1.0, -0.0, 0.0] {
            let mut spec = s.spec().clone();
            spec.duration = x;
            refused(Scene::from_spec(spec.clone()), "from_spec(duration)");
            refused(Scene::from_spec_in(spec, &src), "from_spec_in(duration)");
        }
        assert!(Scene::from_spec(s.spec().clone()).is_ok_and(|t| sound(&t)));
        let mut spec = s.spec().clone();
        spec.bodies[1].parent = "nobody".into();
        refused(Scene::from_spec_in(spec, &src), "from_spec_in(unknown parent)");
        // a huge file is refused before parsing
        let big = "#".repeat(vectrix::scene::MAX_SCENE_BYTES + 1);
        refused(Scene::from_toml(&big, "dp.toml"), "4 MiB + 1 of comments");
    }

    // The state functions (§9.3, §7.11): at hostile states, `query`, `derivative` and the
    // reusable right-hand side refuse (wrong length, non-finite) or give M SPD, T = ½vᵀMv,
    // M v̇ = Q, q̇ = v (pins) and the same y′.
    scene_state ["Scene::query", "Scene::derivative", "Scene::rhs", "SceneRhs::eval"] {
        let s = Scene::from_toml(&double_pendulum([0.4, -0.3], ""), "dp.toml").unwrap();
        let mut rhs = s.rhs();
        for a in crate::harness::hostile() {
            for k in 0..4 {
                let mut y = vec![0.4, -0.3, 0.7, -1.2];
                y[k] = a;
                let d = s.derivative(0.0, &y);
                err_or(d.clone(), "derivative", |d| finite(d) && d[0] == y[2] && d[1] == y[3]);
                err_or(s.query(0.0, &y), "query", |st| {
                    let m = &st.mass_matrix;
                    let v = DVector::from_column_slice(&y[2..]);
                    let t = 0.5 * v.dot(&(m * &v));
                    let scale = st.generalized_forces.nan_amax() + m.nan_amax() * st.accelerations.nan_amax();
                    m.clone().cholesky().is_some()
                        && st.kinetic.is_finite()
                        && st.potential.is_finite()
                        && (st.kinetic - t).abs() <= 1e-9 * t.abs().max(f64::MIN_POSITIVE)
                        && (m * &st.accelerations - &st.generalized_forces).nan_amax() <= 1e-9 * scale.max(f64::MIN_POSITIVE)
                });
                let mut out = vec![0.0; 4];
                err_or(rhs.eval(0.0, &y, &mut out).map(|()| out.clone()), "SceneRhs::eval", |o| {
                    d.as_ref().is_ok_and(|d| d.iter().zip(o).all(|(a, b)| (a - b).abs() <= 1e-12 * (1.0 + a.abs())))
                });
            }
            err_or(s.derivative(a, &[0.4, -0.3, 0.7, -1.2]), "derivative(t)", |d| finite(d));
        }
        refused(s.derivative(0.0, &[0.4, -0.3, 0.7]), "derivative(short y)");
        refused(s.query(0.0, &[]), "query(empty y)");
        refused(rhs.eval(0.0, &[0.0; 4], &mut [0.0; 3]), "eval(short out)");
        refused(rhs.eval(0.0, &[0.0; 5], &mut [0.0; 4]), "eval(long y)");
    }

    // Runs (§4.11, §8.3): a conservative scene keeps T + U (energy column within the
    // integrator's accuracy); the CSV has one line per sample; imperial units divide the
    // energy by 1.3558179483314004 J/(ft·lbf) exactly; a cancelled run is marked incomplete.
    scene_runs ["Scene::run", "Scene::run_with", "Run::column", "Run::in_units", "Run::is_complete", "Run::to_csv",
        "InvariantValue::as_slice"] {
        let s = Scene::from_toml(&double_pendulum([0.4, -0.3], ""), "dp.toml").unwrap();
        let run = s.run(&mut |_| {}).unwrap();
        // `samples` intervals: t = 0 and 11 more rows
        assert!(run.is_complete() && run.t.len() == 12, "{:?} {:?}", run.stop, run.t);
        let e = run.column("energy").unwrap();
        // U = −Σ m g·r_c: −9.81(cos θ₁) − 9.81(cos θ₁ + cos(θ₁ + θ₂)) at rest
        let e0 = -9.81 * (2.0 * 0.4f64.cos() + (0.4f64 - 0.3).cos());
        assert!((e[0] - e0).abs() <= 1e-12 * e0.abs(), "{} vs {e0}", e[0]);
        assert!(e.iter().all(|x| (x - e0).abs() <= 1e-7 * e0.abs()), "energy drifts: {e:?}");
        assert!(run.column("no such column").is_none() && run.column("").is_none());
        let csv = run.to_csv();
        assert_eq!(csv.lines().count(), 1 + run.t.len());
        assert!(!csv.contains("NaN") && !csv.contains("inf"));
        for d in &run.drift {
            assert!(matches!(d.initial.as_slice().len(), 1 | 3) && finite(d.last.as_slice()));
        }
        assert_eq!(InvariantValue::Vector([1.0, 2.0, 3.0]).as_slice(), &[1.0, 2.0, 3.0]);
        assert_eq!(InvariantValue::Scalar(f64::NAN).as_slice().len(), 1);
        let imp = run.clone().in_units(UnitSystem::Imperial).unwrap();
        let ei = imp.column("energy").unwrap();
        assert!(ei.iter().zip(&e).all(|(a, b)| (a * 1.3558179483314004 - b).abs() <= 4.0 * f64::EPSILON * b.abs()));
        assert_eq!(imp.column("coordinates:upper"), run.column("coordinates:upper"));
        // values that overflow in the new unit are refused, not written as ∞
        let mut huge = run.clone();
        for r in &mut huge.rows {
            for x in r.iter_mut() {
                *x = f64::MAX;
            }
        }
        err_or(huge.in_units(UnitSystem::Imperial), "in_units(f64::MAX J)", |r| r.rows.iter().flatten().all(|x| x.is_finite()));
        let cancel = AtomicBool::new(true);
        let stopped = s.run_with(RunControl { progress: &mut |_| {}, cancel: Some(&cancel) }).unwrap();
        assert!(!stopped.is_complete() && stopped.rows.iter().flatten().all(|x| x.is_finite()));
        // a run with hostile budgets stops early or completes; never non-finite rows
        for extra in ["max_steps = 1", "max_steps = 0", "max_wall_seconds = 1e-300", "max_wall_seconds = 5e-324"] {
            let t = double_pendulum([0.4, -0.3], extra);
            if let Ok(s) = Scene::from_toml(&t, "dp.toml") {
                err_or(s.run(&mut |_| {}), extra, |r| r.rows.iter().flatten().all(|x| x.is_finite()));
            }
        }
        // a duration the integrator cannot cover in its budget: refused up front or stopped
        let long = double_pendulum([0.4, -0.3], "").replace("duration = 0.5", "duration = 1e300");
        if let Ok(s) = Scene::from_toml(&long, "dp.toml") {
            err_or(s.run(&mut |_| {}), "duration 1e300", |r| !r.is_complete() && r.rows.iter().flatten().all(|x| x.is_finite()));
        }
    }

    // Contacts (§7.13): a ball dropped on a plane with hostile restitutions and heights
    // never ends below the plane or with non-finite rows; contacts.csv has one line per event
    // and no non-finite number; imperial speeds are the SI ones over 0.3048 exactly.
    scene_contacts ["Run::contacts_csv"] {
        let ball = |h: f64, e: f64| format!(
            "name = \"b\"\nduration = 2.0\nsamples = 40\noutputs = [\"position:b\"]\n[[bodies]]\nname = \"b\"\n\
             joint = {{ type = \"free\" }}\nmass = {{ shape = \"sphere\", mass = 1.0, radius = 0.1 }}\n\
             q = [0.0, 0.0, {}, 1.0, 0.0, 0.0, 0.0]\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, 0.0, -9.81]\n\
             [[effects]]\ntype = \"contact_plane\"\nbody = \"b\"\nradius = 0.1\npoint = [0.0, 0.0, 0.0]\n\
             normal = [0.0, 0.0, 1.0]\nrestitution = {e}\nfriction = 0.0\n", 0.1 + h);
        for h in [0.0, 1e-300, 1e-12, 0.5, 1e3] {
            for e in [0.0, 1e-300, 0.5, 1.0 - 1e-12, 1.0] {
                let Ok(s) = Scene::from_toml(&ball(h, e), "b.toml") else { continue };
                err_or(s.run(&mut |_| {}), "contact run", |r| {
                    let z = r.column("position:b.z").unwrap();
                    let csv = r.contacts_csv();
                    z.iter().all(|z| z.is_finite() && *z >= 0.1 - 1e-9)
                        && csv.lines().count() == 1 + r.contacts.len()
                        && !csv.contains("NaN") && !csv.contains("inf")
                });
            }
        }
        let r = Scene::from_toml(&ball(1.0, 0.5), "b.toml").unwrap().run(&mut |_| {}).unwrap();
        let imp = r.clone().in_units(UnitSystem::Imperial).unwrap();
        assert!(imp.contacts_csv().starts_with("t [s],effect,event,closing_speed [ft/s]"));
        assert!(imp.contacts.iter().zip(&r.contacts).all(|(a, b)| (a.closing_speed * 0.3048 - b.closing_speed).abs() <= 2.0 * f64::EPSILON * b.closing_speed));
    }

    // Trim (§12.3): from hostile starting angles the double pendulum trims to an equilibrium
    // (every |v̇| ≤ TRIM_TOL, finite state) or is refused at `trim`; a scene without `[trim]`
    // has no report.
    scene_trim ["Scene::trimmed", "Scene::trimmed_holding", "Scene::trim_report"] {
        let free = ["dq:upper.0".to_string(), "dq:lower.0".to_string()];
        for x in crate::harness::hostile() {
            let Ok(s) = Scene::from_toml(&double_pendulum([x, 0.1], ""), "dp.toml") else { continue };
            assert!(s.trim_report().is_none());
            err_or(s.trimmed(&free), "trimmed", |(spec, r)| {
                r.residual <= vectrix::scene::TRIM_TOL
                    && spec.bodies.iter().all(|b| b.q.as_ref().is_some_and(|q| q.iter().all(|x| x.is_finite())))
            });
        }
        let s = Scene::from_toml(&double_pendulum([0.4, -0.3], ""), "dp.toml").unwrap();
        refused(s.trimmed(&[]), "trimmed(no unknowns)");
        refused(s.trimmed(&["dq:nobody.0".to_string()]), "trimmed(unknown)");
        // held output columns at hostile targets: steady and on target, or refused at `trim`
        use std::collections::BTreeMap;
        let held = |name: &str, x: f64| BTreeMap::from([(name.to_string(), x)]);
        for c in s.columns().iter().take(2) {
            for x in crate::harness::hostile() {
                err_or(s.trimmed_holding(&free, &held(c, x)), "trimmed_holding", |(_, r)| {
                    r.residual <= vectrix::scene::TRIM_TOL
                });
            }
        }
        refused(s.trimmed_holding(&free, &held("no_such_column", 0.0)), "trimmed_holding(unknown column)");
    }

    // Linearization (§12.6): the hanging double pendulum of unit masses and rods has
    // ω² = (g/l)(2 ± √2), purely imaginary poles; LinearModel::new refuses non-finite
    // entries and shapes that disagree, and its modes have ωn = |λ|.
    scene_linearize ["Scene::linearize", "LinearModel::new", "Scene::jacobian"] {
        let s = Scene::from_toml(&double_pendulum([0.0, 0.0], ""), "dp.toml").unwrap();
        // the exact Jacobian at hostile states: finite, with ∂q̇/∂v = I, or refused
        for x in crate::harness::hostile() {
            err_or(s.jacobian(0.0, &[x, 0.2, -0.1, 0.3]), "jacobian", |(fy, fu)| {
                finite(fy.as_slice()) && fu.ncols() == 0 && fy[(0, 2)] == 1.0 && fy[(1, 3)] == 1.0 && fy[(0, 3)] == 0.0
            });
        }
        refused(s.jacobian(0.0, &[0.0; 3]), "jacobian(short y)");
        let lin = s.linearize().unwrap();
        let g = 9.81;
        let want = [g * (2.0 - 2f64.sqrt()), g * (2.0 + 2f64.sqrt())];
        let mut w2: Vec<f64> = lin.modes.iter().map(|m| m.natural_frequency * m.natural_frequency).collect();
        w2.sort_by(f64::total_cmp);
        assert!(w2.len() == 2 && w2.iter().zip(want).all(|(a, b)| (a - b).abs() <= 1e-6 * b), "{w2:?}");
        assert!(lin.eigenvalues.iter().all(|l| l[0].abs() <= 1e-6));
        // not at rest: linearized anyway, the residual says so
        let moving = Scene::from_toml(&double_pendulum([0.4, -0.3], ""), "dp.toml").unwrap();
        err_or(moving.linearize(), "linearize(moving)", |l| !l.residual.ok && finite(l.a.as_slice()));
        let r = EquilibriumResidual { velocity: 0.0, acceleration: 0.0, ok: true };
        let names = |n: usize| (0..n).map(|k| format!("x{k}")).collect::<Vec<_>>();
        for x in crate::harness::hostile() {
            let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -4.0, x]);
            let m = LinearModel::new("t".into(), names(2), vec![], vec![], (a, DMatrix::zeros(2, 0), DMatrix::zeros(0, 2), DMatrix::zeros(0, 0)), false, r);
            err_or(m, "LinearModel::new", |m| {
                m.modes.iter().all(|md| {
                    let l = nalgebra::Complex::new(md.eigenvalue[0], md.eigenvalue[1]);
                    md.natural_frequency.is_finite() && (md.natural_frequency - l.norm()).abs() <= 1e-12 * (1.0 + l.norm())
                })
            });
        }
        refused(LinearModel::new("t".into(), names(3), vec![], vec![], (DMatrix::zeros(2, 2), DMatrix::zeros(2, 0), DMatrix::zeros(0, 2), DMatrix::zeros(0, 0)), false, r), "A of the wrong size");
        let empty = LinearModel::new("t".into(), vec![], vec![], vec![], (DMatrix::zeros(0, 0), DMatrix::zeros(0, 0), DMatrix::zeros(0, 0), DMatrix::zeros(0, 0)), false, r);
        err_or(empty, "LinearModel::new(empty)", |m| m.modes.is_empty());
    }

    // URDF and MJCF import (issue 35): hostile XML (empty, not XML, an unknown joint type, NaN
    // and huge numbers, a mesh path outside the folder) is a typed error or a model whose
    // every warning is located; strict refuses a model with warnings; a scene without `[model]`
    // expands to itself; the gallery's arm loads from its file and its model scene parses.
    scene_import ["import::urdf::load_urdf", "import::mjcf::load_mjcf", "ImportedModel::check_strict",
        "expand", "load_file", "model_scene_toml", "Scene::import_warnings"] {
        use vectrix::scene::import;
        let dir = std::env::temp_dir();
        let texts = [
            "", "not xml", "<robot/>", "<mujoco/>",
            "<robot name=\"r\"><link name=\"a\"><inertial><mass value=\"nan\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link></robot>",
            "<robot name=\"r\"><link name=\"a\"><inertial><mass value=\"1e308\"/><inertia ixx=\"1e308\" iyy=\"1e308\" izz=\"1e308\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial><visual><geometry><mesh filename=\"/etc/passwd\"/></geometry></visual></link></robot>",
            "<mujoco><worldbody><body name=\"b\"><joint type=\"warp\"/><geom type=\"sphere\" size=\"0.1\"/></body></worldbody></mujoco>",
            "<mujoco><worldbody><body name=\"b\"><freejoint/><geom type=\"sphere\" size=\"nan\"/></body></worldbody></mujoco>",
            "<mujoco><include file=\"../../etc/passwd\"/></mujoco>",
        ];
        for text in texts {
            let located = |m: &import::ImportedModel| m.warnings.iter().all(|w| w.line >= 1 && w.column >= 1);
            err_or(import::urdf::load_urdf(text, "t.urdf"), "load_urdf", located);
            err_or(import::mjcf::load_mjcf(text, "t.xml", &dir), "load_mjcf", located);
            if let Ok(m) = import::urdf::load_urdf(text, "t.urdf") {
                assert!(m.check_strict(false).is_ok());
                assert_eq!(m.check_strict(true).is_err(), !m.warnings.is_empty());
            }
        }
        let arm = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/models/arm7.urdf");
        let folder = std::path::Path::new(arm).parent().unwrap();
        err_or(import::load_file(std::path::Path::new(arm), folder, false), "load_file(arm7)", |m| !m.bodies.is_empty());
        refused(import::load_file(std::path::Path::new("/nonexistent/x.urdf"), folder, false), "load_file(missing)");
        let text = import::model_scene_toml("../arm7.urdf", false);
        assert!(toml::from_str::<toml::Value>(&text).is_ok(), "{text}");
        let plain = double_pendulum([0.4, -0.3], "");
        let src = SceneSource::new(&plain, "dp.toml").unwrap();
        let spec: vectrix::scene::SceneSpec = src.deserialize().unwrap();
        err_or(import::expand(spec.clone(), &src), "expand(no model)", |(s, w)| *s == spec && w.is_empty());
        assert!(Scene::from_toml(&plain, "dp.toml").unwrap().import_warnings().is_empty());
    }

    // The method a scene runs with (issue 34): named, or chosen by the stiffness test, with a
    // reason and a positive tolerance; the stiff example picks RADAU5 with an exact Jacobian,
    // the hanging double pendulum keeps the explicit pair.
    scene_method_choice ["Scene::method_choice"] {
        for x in crate::harness::hostile() {
            let Ok(s) = Scene::from_toml(&double_pendulum([x, 0.1], ""), "dp.toml") else { continue };
            let c = s.method_choice();
            assert!(c.rtol > 0.0 && !c.reason.is_empty(), "{c:?}");
        }
        let stiff = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/scenes/stiff_spring_pendulum.toml")).unwrap();
        let c = Scene::from_toml(&stiff, "s.toml").unwrap().method_choice().clone();
        assert_eq!(c.name, "radau5", "{c:?}");
        assert!(c.jacobian.starts_with("exact"), "{c:?}");
        let c = Scene::from_toml(&double_pendulum([0.0, 0.0], ""), "dp.toml").unwrap().method_choice().clone();
        assert_ne!(c.name, "radau5", "{c:?}");
    }

    // Quantity errors in a scene's words: the units library's byte positions are left out,
    // everything else is kept.
    scene_unit_message ["unit_message"] {
        for text in ["abc", "", "1 kgg", "1e999 kg", "nan kg", "1 kg kg", "1 m/s/s/", "\u{0}", "1 ° C"] {
            if let Err(e) = vectrix_units::Quantity::parse(text) {
                let m = vectrix::scene::unit_message(&e);
                assert!(!m.contains(" at bytes ") && !m.is_empty(), "{text:?}: {m}");
                assert!(e.to_string().starts_with(m.split('`').next().unwrap_or("")), "{text:?}: {m}");
            }
        }
    }

    // Load profiles and loop names (spec): shifting adds du at every t (and nothing to times);
    // a loop reports its name.
    scene_spec_values ["Profile::shifted", "Profile::eval", "LoopSpec::name"] {
        // compared through their Debug text, so that NaN + du = NaN compares equal
        let same = |a: &Profile, b: &Profile| format!("{a:?}") == format!("{b:?}");
        for du in crate::harness::hostile() {
            assert!(same(&Profile::Constant { value: 1.0 }.shifted(du), &Profile::Constant { value: 1.0 + du }));
            let t = Profile::Table { t: vec![0.0, 1.0], value: vec![2.0, 3.0] }.shifted(du);
            assert!(same(&t, &Profile::Table { t: vec![0.0, 1.0], value: vec![2.0 + du, 3.0 + du] }));
            let r = Profile::Ramp { t0: 0.0, t1: 1.0, from: 0.0, to: 1.0 }.shifted(du);
            assert!(same(&r, &Profile::Ramp { t0: 0.0, t1: 1.0, from: 0.0 + du, to: 1.0 + du }));
            let st = Profile::Step { at: 1.0, before: 0.0, after: 2.0 }.shifted(du);
            assert!(same(&st, &Profile::Step { at: 1.0, before: 0.0 + du, after: 2.0 + du }));
            let sn = Profile::Sine { amplitude: 1.0, omega: 2.0, phase: 0.0, offset: 0.5 }.shifted(du);
            assert!(same(&sn, &Profile::Sine { amplitude: 1.0, omega: 2.0, phase: 0.0, offset: 0.5 + du }));
            // §14.2: a doublet is +A on [t₀, t₀+w), −A on [t₀+w, t₀+2w); a pulse +A on [t₀, t₀+w)
            let d = Profile::Doublet { start: 1.0, width: 0.5, amplitude: 2.0, offset: 0.25 };
            let p = Profile::Pulse { start: 1.0, width: 0.5, amplitude: 2.0, offset: 0.25 };
            for (t, dv, pv) in [(0.999, 0.25, 0.25), (1.0, 2.25, 2.25), (1.5, -1.75, 0.25), (1.999, -1.75, 0.25), (2.0, 0.25, 0.25)] {
                assert_eq!((d.eval(t), p.eval(t)), (dv, pv), "t = {t}");
            }
            // hostile times give a value of the profile's own, never a panic
            let v = d.eval(du);
            assert!(v.is_nan() || [0.25, 2.25, -1.75].contains(&v), "doublet({du}) = {v}");
        }
        let four_bar = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/scenes/four_bar.toml")).unwrap();
        let s = Scene::from_toml(&four_bar, "four_bar.toml").unwrap();
        assert_eq!(s.spec().loops[0].name(), "coupler_rocker");
        let src = SceneSource::new(&four_bar, "four_bar.toml").unwrap();
        let spec: vectrix::scene::SceneSpec = src.deserialize().unwrap();
        assert!(matches!(&spec.loops[0], LoopSpec::Pin { name, .. } if name == "coupler_rocker"));
    }

    // The source locator (file format): hostile paths ("", unknown keys, indices past the
    // end or past usize::MAX, brackets without keys) and offsets give spans inside the text
    // and 1-based line/column; TOML errors and invalid items are located; names are checked.
    scene_source ["SceneSource::new", "SceneSource::file", "SceneSource::text", "SceneSource::has_key",
        "SceneSource::deserialize", "SceneSource::deserialize_with", "SceneSource::value_span", "SceneSource::span",
        "SceneSource::locate", "SceneSource::invalid", "SceneSource::invalid_at", "SceneError::from_toml",
        "check_name"] {
        let text = double_pendulum([0.4, -0.3], "");
        let src = SceneSource::new(&text, "dp.toml").unwrap();
        assert_eq!((src.file(), src.text()), ("dp.toml", text.as_str()));
        assert!(src.has_key("bodies") && !src.has_key("aircraft") && !src.has_key(""));
        let span = src.span("bodies[1].q");
        assert!(text[span.clone()].starts_with('q'), "{:?}", &text[span]);
        let vs = src.value_span("bodies[1].q");
        assert_eq!(&text[vs], "[-0.3]");
        for path in ["", ".", "[", "]", "[]", "bodies[", "bodies[99]", "bodies[18446744073709551616]", "bodies[1].q[7]",
            "no.such.key", "bodies..name", "bodies[0][0][0]", "\u{202e}", "name.x"] {
            for r in [src.span(path), src.value_span(path)] {
                assert!(r.start <= r.end && r.end <= text.len(), "{path:?}: {r:?}");
            }
            let (l, c) = src.locate(path);
            assert!(l >= 1 && c >= 1 && l <= text.lines().count() + 1, "{path:?}");
            let e = src.invalid(path, "bad");
            assert!(matches!(e, SceneError::Invalid { line, column, .. } if line >= 1 && column >= 1));
        }
        for offset in [0, 1, text.len(), text.len() + 1, usize::MAX] {
            let e = src.invalid_at(offset, "x", "bad");
            assert!(matches!(e, SceneError::Invalid { line, column, .. } if line >= 1 && column >= 1 && line <= text.lines().count() + 1));
        }
        let multibyte = "name = \"é\"\n# ü\nx = 1";
        let s2 = SceneSource::new(multibyte, "m.toml").unwrap();
        for offset in 0..multibyte.len() + 2 {
            let _ = s2.invalid_at(offset, "x", "inside a character");
        }
        let v: toml::Value = src.deserialize().unwrap();
        assert!(v.get("bodies").is_some());
        refused(src.deserialize::<u8>(), "deserialize into the wrong type");
        let spec: vectrix::scene::SceneSpec = src.deserialize_with(&body_schema).unwrap();
        assert_eq!(spec.bodies.len(), 2);
        let with_units = text.replacen("q = [0.4]", "q = [\"30 deg\"]", 1);
        let s3 = SceneSource::new(&with_units, "dp.toml").unwrap();
        let spec: vectrix::scene::SceneSpec = s3.deserialize_with(&body_schema).unwrap();
        assert!((spec.bodies[0].q.as_ref().unwrap()[0] - std::f64::consts::FRAC_PI_6).abs() <= f64::EPSILON);
        for bad in ["\"1e999 deg\"", "\"nan deg\"", "\"inf deg\"", "\"1 kg\"", "\"deg\"", "\"\"", "\"1 parsec^99\""] {
            let t = text.replacen("q = [0.4]", &format!("q = [{bad}]"), 1);
            let s = SceneSource::new(&t, "dp.toml").unwrap();
            match s.deserialize_with::<vectrix::scene::SceneSpec>(&body_schema) {
                Ok(spec) => assert!(spec.bodies[0].q.as_ref().is_some_and(|q| q[0].is_finite()), "{bad}"),
                Err(e) => assert!(located(&e), "{bad}: {e}"),
            }
        }
        for bad in ["[", "a = ", "a = 1\na = 2", "\"unterminated", "x = [1, 2"] {
            let e = SceneSource::new(bad, "dp.toml").unwrap_err();
            assert!(located(&e), "{bad}: {e}");
            let te = toml::from_str::<toml::Value>(bad).unwrap_err();
            assert!(matches!(SceneError::from_toml(&te, bad, "f"), SceneError::Parse { line, column, .. } if line >= 1 && column >= 1));
            // a text that does not match the error's span still gives a location
            assert!(matches!(SceneError::from_toml(&te, "", "f"), SceneError::Parse { line: 1, column: 1, .. }));
        }
        for (name, dot, ok) in [("dp", false, true), ("a-b_c9", false, true), ("v1.2", true, true), ("v1.2", false, false),
            ("", true, false), (".x", true, false), ("..", true, false), ("a/b", true, false), ("a b", true, false),
            ("\u{202e}", true, false), ("a\0", true, false), ("é", true, false)] {
            assert_eq!(check_name(name, "name", dot).is_ok(), ok, "{name:?}");
        }
        assert!(check_name(&"x".repeat(64), "name", false).is_ok() && check_name(&"x".repeat(65), "name", false).is_err());
        assert!(check_name(&"x".repeat(1_000_000), "name", false).is_err());
    }
}
