//! URDF and MJCF import against the peers on the same files (issue 35): Pinocchio's
//! `buildModelFromUrdf` and MuJoCo's `MjModel.from_xml_path` loaded examples/models/*, and
//! `scripts/import_reference.py` stored M(q), RNEA, ABA, link placements and Jacobians at
//! random states in tests/data/import_*.txt (conventions converted there, documented at its
//! top). Every quantity agrees to 1e-12 relative to its largest entry.
//!
//! Book: §7.11 (RNEA, ABA, CRBA on trees), §2.10 (placements), §4.5 (link velocities).

mod support;

use std::path::Path;

use nalgebra::{Matrix3, Vector3};
use support::nan_max;
use vectrix::scene::Scene;
use vectrix::scene::import::{ImportedModel, load_file};

/// Relative tolerance: rounding of two O(n)-deep recursions in double precision.
const REL: f64 = 1e-12;

#[derive(Default)]
struct State {
    q: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    tau: Vec<f64>,
    rnea: Vec<f64>,
    aba: Vec<f64>,
    crba: Vec<f64>,
    frames: Vec<(String, Vec<f64>)>,
    jacobians: Vec<(String, Vec<f64>)>,
}

struct Reference {
    joints: Vec<String>,
    links: Vec<String>,
    states: Vec<State>,
}

fn nums(it: std::str::SplitWhitespace) -> Vec<f64> {
    it.map(|t| t.parse().expect("a number")).collect()
}

fn read(name: &str) -> Reference {
    let text = std::fs::read_to_string(format!("tests/data/import_{}.txt", name.replace('.', "_"))).unwrap();
    let mut r = Reference { joints: vec![], links: vec![], states: vec![] };
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let mut it = line.split_whitespace();
        let key = it.next().unwrap_or("");
        let s = r.states.last_mut();
        match (key, s) {
            ("joints", _) => r.joints = it.map(String::from).collect(),
            ("links", _) => r.links = it.map(String::from).collect(),
            ("state", _) => r.states.push(State::default()),
            ("q", Some(s)) => s.q = nums(it),
            ("v", Some(s)) => s.v = nums(it),
            ("a", Some(s)) => s.a = nums(it),
            ("tau", Some(s)) => s.tau = nums(it),
            ("rnea", Some(s)) => s.rnea = nums(it),
            ("aba", Some(s)) => s.aba = nums(it),
            ("crba", Some(s)) => s.crba = nums(it),
            ("frame", Some(s)) => s.frames.push((it.next().unwrap().into(), nums(it))),
            ("jacobian", Some(s)) => s.jacobians.push((it.next().unwrap().into(), nums(it))),
            _ => {}
        }
    }
    assert!(!r.states.is_empty(), "{name}: no states in the reference file");
    r
}

/// max |got − want| / max |want|, NaN-propagating.
fn rel_err(got: &[f64], want: &[f64]) -> f64 {
    assert_eq!(got.len(), want.len());
    let scale = want.iter().fold(0.0, |m, x| nan_max(m, x.abs()));
    let err = got.iter().zip(want).fold(0.0, |m, (g, w)| nan_max(m, (g - w).abs()));
    err / scale.max(f64::MIN_POSITIVE)
}

fn check(what: &str, got: &[f64], want: &[f64]) {
    let e = rel_err(got, want);
    assert!(e <= REL, "{what}: relative error {e:e} > {REL:e}\n got  {got:?}\n want {want:?}");
}

/// The model as a scene sees it (gravity as the file says, else −9.81 ẑ).
fn load(name: &str) -> (ImportedModel, Scene) {
    let path = Path::new("examples/models").join(name);
    let dir = Path::new("examples/models").canonicalize().unwrap();
    let imported = load_file(&path.canonicalize().unwrap(), &dir, name.ends_with(".xml")).unwrap();
    let key = if name.ends_with(".xml") { "mjcf" } else { "urdf" };
    let toml = format!("name = \"t\"\nduration = 1.0\n[model]\n{key} = \"{name}\"\ngravity = true\n");
    let scene = Scene::from_toml(&toml, "examples/models/scene.toml").unwrap();
    (imported, scene)
}

fn compare(name: &str) {
    let r = read(name);
    let (imported, scene) = load(name);
    assert_eq!(imported.joint_names, r.joints, "{name}: joint order differs from the peer's");
    let mut model = scene.model().clone();
    model.gravity = Vector3::from(imported.gravity.unwrap_or([0.0, 0.0, -9.81]));
    let bodies: Vec<&str> = scene.spec().bodies.iter().map(|b| b.name.as_str()).collect();
    for (k, s) in r.states.iter().enumerate() {
        let at = format!("{name} state {k}");
        let m = model.crba(&s.q).unwrap();
        let m_rows: Vec<f64> = (0..m.nrows())
            .flat_map(|i| (0..m.ncols()).map(move |j| (i, j)))
            .map(|(i, j)| m[(i, j)])
            .collect();
        check(&format!("{at}: M(q)"), &m_rows, &s.crba);
        check(&format!("{at}: RNEA"), &model.rnea(&s.q, &s.v, &s.a, None).unwrap().tau, &s.rnea);
        check(&format!("{at}: ABA"), &model.aba(&s.q, &s.v, &s.tau, None).unwrap(), &s.aba);
        assert_eq!(s.frames.len(), r.links.len(), "{at}: a placement per link");
        assert_eq!(s.jacobians.len(), r.links.len(), "{at}: a Jacobian per link");
        let poses = model.poses(&s.q).unwrap();
        let nv = model.nv();
        let twists: Vec<_> = (0..nv)
            .map(|c| {
                let mut e = vec![0.0; nv];
                e[c] = 1.0;
                model.twists(&s.q, &e).unwrap()
            })
            .collect();
        for ((link, want), (_, jac)) in s.frames.iter().zip(&s.jacobians) {
            let f = imported
                .frames
                .iter()
                .find(|f| &f.link == link)
                .unwrap_or_else(|| panic!("{at}: no frame {link}"));
            let host = bodies.iter().position(|b| *b == f.body);
            let (rh, ph) = host
                .map_or((Matrix3::identity(), Vector3::zeros()), |b| (poses[b].0.transpose(), poses[b].1));
            let rl = Matrix3::from_fn(|i, j| f.orientation[i][j]);
            let (r, p) = (rh * rl, ph + rh * Vector3::from(f.offset));
            let got: Vec<f64> = (0..3)
                .flat_map(|i| (0..3).map(move |j| (i, j)))
                .map(|(i, j)| r[(i, j)])
                .chain(p.iter().copied())
                .collect();
            check(&format!("{at}: placement of {link}"), &got, want);
            let mut j = vec![0.0; 6 * nv];
            for (c, tw) in twists.iter().enumerate() {
                let (w, v) = host.map_or((Vector3::zeros(), Vector3::zeros()), |b| {
                    (tw[b].omega, tw[b].velocity_of(&(p - ph)))
                });
                for i in 0..3 {
                    j[i * nv + c] = v[i];
                    j[(i + 3) * nv + c] = w[i];
                }
            }
            check(&format!("{at}: Jacobian of {link}"), &j, jac);
        }
    }
}

#[test]
fn arm7_urdf_matches_pinocchio() {
    compare("arm7.urdf");
}

#[test]
fn quadruped_urdf_matches_pinocchio() {
    compare("quadruped.urdf");
}

#[test]
fn double_pendulum_urdf_matches_pinocchio() {
    compare("double_pendulum.urdf");
}

#[test]
fn humanoid_mjcf_matches_mujoco() {
    compare("humanoid.xml");
}

#[test]
fn double_pendulum_mjcf_matches_mujoco() {
    compare("double_pendulum.xml");
}

#[test]
fn top_mjcf_matches_mujoco() {
    compare("top.xml");
}

#[test]
fn four_bar_mjcf_tree_matches_mujoco() {
    compare("four_bar.xml");
}
