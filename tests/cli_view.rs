//! Issue 36: every run's folder holds `view.html`, a self-contained 3-D view of the run. These
//! tests need no browser (scripts/browser-tests.sh opens the pages in headless Chromium): the
//! page is written (and skipped with `--no-view` or `view = false`), fetches nothing, holds
//! poses that agree with closed forms, stays bounded for long runs, counts in the byte budget,
//! and a hostile scene name never reaches a page.
//!
//! Book: §7.11 (poses of a tree of bodies), §2.12 (Euler parameters), §14.2 (aircraft).

mod support;

use std::path::Path;

use serde_json::Value;
use support::nan_max;
use vectrix_cli::{Outcome, run_with_args};

fn cli(args: &[&str]) -> Result<(Outcome, String), String> {
    let mut out = Vec::new();
    let r = run_with_args(std::iter::once("vectrix").chain(args.iter().copied()), &mut out);
    let text = String::from_utf8_lossy(&out).to_string();
    r.map(|o| (o, text)).map_err(|e| e.to_string())
}

/// A pendulum: a particle on a massless arm of length 1 m, released from rest at θ₀ = `q`.
fn pendulum(dir: &Path, name: &str, duration: f64, samples: usize, extra: &str) -> String {
    let text = format!(
        "name = \"{name}\"\nduration = {duration:.17e}\nsamples = {samples}\naccuracy = 1e-10\n\
         outputs = [\"position:bob\", \"energy\"]\n{extra}\n\
         [[bodies]]\nname = \"bob\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         mass = {{ shape = \"particle\", mass = 1.0 }}\ncom = [0.0, -1.0, 0.0]\nq = [1.0]\n\n\
         [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n"
    );
    let p = dir.join(format!("{name}.toml"));
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

/// The page's data: the JSON of its `<script type="application/json" id="vectrix-data">`.
fn data(page: &str) -> Value {
    let open = "<script type=\"application/json\" id=\"vectrix-data\">";
    let at = page.find(open).expect("data element") + open.len();
    let end = page[at..].find("</script>").unwrap();
    serde_json::from_str(&page[at..at + end]).unwrap()
}

fn nums(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().expect("a number")).collect()
}

/// Complete elliptic integral of the first kind K(k) by the arithmetic–geometric mean:
/// K = π / (2 AGM(1, √(1 − k²))) (Abramowitz & Stegun 17.6).
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..40 {
        (a, b) = ((a + b) / 2.0, (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

/// The default scene's folder holds view.html, listed in the folder's manifest; the page holds
/// every sample (801 ≤ 1001) of the racket's pose: a free body with no translational velocity
/// stays at the origin, its attitude a unit quaternion, identity at t = 0; the heads-up values
/// at t = 0 are the first row of trajectory.csv.
#[test]
fn the_default_scene_writes_its_view() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let (outcome, _) = cli(&["run", "--quiet", "--out", out.to_str().unwrap()]).unwrap();
    assert_eq!(outcome, Outcome::Complete);
    let folder = out.join("tennis_racket");
    let page = std::fs::read_to_string(folder.join("view.html")).unwrap();
    assert!(
        std::fs::read_to_string(folder.join(".vectrix-output")).unwrap().lines().any(|l| l == "view.html")
    );
    assert!(page.contains("<title>tennis_racket · vectrix view</title>"));
    let d = data(&page);
    assert_eq!(d["kind"], "bodies");
    assert_eq!(d["bodies"][0]["name"], "racket");
    let t = nums(&d["t"]);
    let pose = nums(&d["pose"]);
    assert_eq!((t.len(), pose.len()), (801, 801 * 7));
    assert_eq!((t[0], t[800]), (0.0, 40.0));
    for p in pose.chunks(7) {
        assert_eq!(&p[..3], &[0.0, 0.0, 0.0], "the centre of mass stays put");
        let n = p[3..].iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!((n - 1.0).abs() < 1e-6, "|q| = {n} (7 significant digits kept)");
    }
    assert_eq!(&pose[3..7], &[1.0, 0.0, 0.0, 0.0]);
    let csv = std::fs::read_to_string(folder.join("trajectory.csv")).unwrap();
    let first: Vec<f64> =
        csv.lines().nth(1).unwrap().split(',').skip(1).map(|x| x.parse().unwrap()).collect();
    let hud = nums(&d["hud"]["values"]);
    let n = d["hud"]["names"].as_array().unwrap().len();
    assert_eq!(n, first.len());
    for (h, c) in hud[..n].iter().zip(&first) {
        assert!((h - c).abs() <= 1e-6 * c.abs().max(1e-300), "{h} vs {c}");
    }
}

/// The pendulum of 1 m released from rest at θ₀ = 1 rad swings back to −θ₀ after half its
/// exact period T = 4 K(sin(θ₀/2)) √(L/g): the page's pose there is a turn of −1 rad about z,
/// (w, x, y, z) = (cos ½, 0, 0, −sin ½), with the pivot at the origin, and at T it is back at
/// +1 rad. Tolerance 2e-6: the run's accuracy 1e-10 and the page's 7 significant digits.
#[test]
fn pendulum_poses_follow_the_exact_period() {
    let dir = tempfile::tempdir().unwrap();
    let period = 4.0 * elliptic_k(0.5_f64.sin()) * (1.0 / 9.81_f64).sqrt();
    let p = pendulum(dir.path(), "pend", period, 1000, "");
    let out = dir.path().join("out");
    cli(&["run", &p, "--quiet", "--out", out.to_str().unwrap()]).unwrap();
    let d = data(&std::fs::read_to_string(out.join("pend/view.html")).unwrap());
    let pose = nums(&d["pose"]);
    let t = nums(&d["t"]);
    assert_eq!(t.len(), 1001);
    let close = |got: &[f64], want: [f64; 7], what: &str| {
        // q and −q are one attitude: compare with the sign of w
        let s = if got[3] < 0.0 { -1.0 } else { 1.0 };
        for (i, (g, w)) in got.iter().zip(want).enumerate() {
            let g = if i >= 3 { s * g } else { *g };
            assert!((g - w).abs() < 2e-6, "{what}: entry {i} is {g}, expected {w}");
        }
    };
    let (c, s) = (0.5_f64.cos(), 0.5_f64.sin());
    close(&pose[..7], [0.0, 0.0, 0.0, c, 0.0, 0.0, s], "t = 0");
    assert!((t[500] - period / 2.0).abs() < 1e-6 * period);
    close(&pose[500 * 7..501 * 7], [0.0, 0.0, 0.0, c, 0.0, 0.0, -s], "t = T/2");
    close(&pose[1000 * 7..], [0.0, 0.0, 0.0, c, 0.0, 0.0, s], "t = T");
    // the bob's position is an output: its trail is drawn, gravity points down
    assert_eq!(d["trails"], serde_json::json!([0]));
    assert_eq!(nums(&d["gravity"]), [0.0, -9.81, 0.0]);
    assert_eq!(nums(&d["up"]), [0.0, 1.0, 0.0]);
}

/// `--no-view` and `view = false` skip the page; nothing else changes.
#[test]
fn no_view_and_view_false_skip_the_page() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    let p = pendulum(dir.path(), "a", 0.5, 10, "");
    cli(&["run", &p, "--quiet", "--out", o, "--no-view"]).unwrap();
    assert!(out.join("a/summary.json").exists() && !out.join("a/view.html").exists());
    let p = pendulum(dir.path(), "b", 0.5, 10, "view = false");
    cli(&["run", &p, "--quiet", "--out", o]).unwrap();
    assert!(out.join("b/summary.json").exists() && !out.join("b/view.html").exists());
    let p = pendulum(dir.path(), "c", 0.5, 10, "view = true");
    cli(&["run", &p, "--quiet", "--out", o]).unwrap();
    assert!(out.join("c/view.html").exists());
    // a misspelt key is still an error
    let p = pendulum(dir.path(), "d", 0.5, 10, "veiw = false");
    assert!(cli(&["run", &p, "--quiet", "--out", o]).unwrap_err().contains("veiw"));
}

/// A run of 2·10⁵ samples makes a page of the same size as one of 10³ (both sampled at 1001
/// instants), within the bound the budget counts; 10⁶ samples would too (the instants are
/// min(samples + 1, 1001, 40 000/bodies)).
#[test]
fn a_long_run_makes_a_bounded_page() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    let short = pendulum(dir.path(), "short", 0.5, 1000, "");
    let long = pendulum(dir.path(), "long", 0.5, 200_000, "");
    cli(&["run", &short, "--quiet", "--out", o]).unwrap();
    cli(&["run", &long, "--quiet", "--out", o]).unwrap();
    let a = std::fs::read_to_string(out.join("short/view.html")).unwrap();
    let b = std::fs::read_to_string(out.join("long/view.html")).unwrap();
    assert_eq!(nums(&data(&b)["t"]).len(), 1001);
    let (na, nb) = (a.len() as f64, b.len() as f64);
    assert!((nb / na - 1.0).abs() < 0.02, "{na} vs {nb} bytes");
    assert!(nb < 1.0e6, "{nb} bytes");
}

/// The page counts in `--max-output-bytes`: a budget that the other files fit in but not the
/// page (three.js alone is 0.7 MB) is refused before the run, naming view.html; without the
/// page the same budget runs.
#[test]
fn the_page_counts_in_the_byte_budget() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    let p = pendulum(dir.path(), "p", 0.5, 10, "");
    let e = cli(&["run", &p, "--quiet", "--out", o, "--max-output-bytes", "500kB"]).unwrap_err();
    assert!(e.contains("samples: the output would take up to") && e.contains("view.html"), "{e}");
    assert!(!out.exists());
    cli(&["run", &p, "--quiet", "--out", o, "--max-output-bytes", "500kB", "--no-view"]).unwrap();
    assert!(out.join("p/summary.json").exists());
}

/// The name `</script><script>alert(1)</script>` cannot reach a page: a scene name becomes a
/// folder name and is refused (the page's own escaping is tested in the crate, view/tests.rs).
#[test]
fn a_hostile_scene_name_is_refused_before_any_page() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(pendulum(dir.path(), "p", 0.5, 10, ""))
        .unwrap()
        .replace("name = \"p\"", "name = \"</script><script>alert(1)</script>\"");
    let p = dir.path().join("hostile.toml");
    std::fs::write(&p, text).unwrap();
    let out = dir.path().join("out");
    let e = cli(&["run", p.to_str().unwrap(), "--quiet", "--out", out.to_str().unwrap()]).unwrap_err();
    assert!(e.contains("scene name \"</script><script>alert(1)</script>\" contains '<'"), "{e}");
    assert!(!out.exists());
}

/// An aircraft scene's page shows the aircraft: in the elevator doublet the motion stays in the
/// vertical plane (φ = ψ = 0), so at every instant the body's attitude (link to ground, the
/// book's earth frame with z down) is the pitch θ of the heads-up column `euler321:jet.theta`:
/// a turn of θ about y, (cos θ/2, 0, sin θ/2, 0). Tolerance 2e-6: 7 significant digits.
#[test]
fn an_aircraft_scene_view_shows_the_aircraft() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string("examples/scenes/business_jet_doublet.toml")
        .unwrap()
        .replace("duration = 120.0", "duration = 10.0")
        .replace("samples = 1200", "samples = 100")
        .replace(
            "outputs = [\"velocity_body:jet\", \"air:jet\", \"omega_body:jet\", \"euler321:jet\", \"position:jet\"]",
            "outputs = [\"euler321:jet\"]",
        );
    let p = dir.path().join("jet.toml");
    std::fs::write(&p, text).unwrap();
    let out = dir.path().join("out");
    cli(&["run", p.to_str().unwrap(), "--quiet", "--out", out.to_str().unwrap()]).unwrap();
    let d = data(&std::fs::read_to_string(out.join("business_jet_doublet/view.html")).unwrap());
    assert_eq!(d["bodies"][0]["shape"]["kind"], "aircraft");
    assert_eq!(
        d["hud"]["names"],
        serde_json::json!(["euler321:jet.psi", "euler321:jet.theta", "euler321:jet.phi"])
    );
    // up is against gravity: −z of the earth frame
    assert_eq!(nums(&d["up"]), [0.0, 0.0, -1.0]);
    let t = nums(&d["t"]);
    assert_eq!(t.len(), 101);
    let hud = nums(&d["hud"]["values"]);
    let pose = nums(&d["pose"]);
    let mut largest = 0.0_f64;
    for k in 0..t.len() {
        let theta = hud[3 * k + 1];
        largest = nan_max(largest, theta.abs());
        let q = &pose[7 * k + 3..7 * k + 7];
        let want = [(theta / 2.0).cos(), 0.0, (theta / 2.0).sin(), 0.0];
        for (g, w) in q.iter().zip(want) {
            assert!((g - w).abs() < 2e-6, "t = {}: {q:?} vs {want:?}", t[k]);
        }
    }
    assert!(largest > 1e-4, "the doublet pitches the jet: largest |θ| = {largest}");
}

/// A `cylinder` mass (solid, axis along the link z axis) has the closed-form inertia
/// J_x = J_y = m(3r² + h²)/12, J_z = m r²/2 (the free body's mass matrix, relative 1e-15) and
/// is drawn as a cylinder of its radius and length.
#[test]
fn a_cylinder_has_its_closed_form_inertia_and_is_drawn_with_its_dimensions() {
    let text = "name = \"can\"\nduration = 1.0\nsamples = 10\n[[bodies]]\nname = \"can\"\njoint = { type = \"free\" }\n\
mass = { shape = \"cylinder\", mass = 2.0, radius = 0.3, length = 1.2 }\nv = [0.0, 0.0, 0.0, 0.1, 0.2, 3.0]\n";
    let scene = vectrix::scene::Scene::from_toml(text, "can.toml").unwrap();
    let m = scene.query(0.0, &scene.initial_state()).unwrap().mass_matrix;
    let (mass, r, h) = (2.0_f64, 0.3_f64, 1.2_f64);
    let want = [
        mass,
        mass,
        mass,
        mass * (3.0 * r * r + h * h) / 12.0,
        mass * (3.0 * r * r + h * h) / 12.0,
        mass * r * r / 2.0,
    ];
    for (k, w) in want.iter().enumerate() {
        assert!((m[(k, k)] - w).abs() <= 1e-15 * w, "M[{k}][{k}] = {} vs {w}", m[(k, k)]);
    }
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("can.toml");
    std::fs::write(&p, text).unwrap();
    let out = dir.path().join("out");
    cli(&["run", p.to_str().unwrap(), "--quiet", "--out", out.to_str().unwrap()]).unwrap();
    let d = data(&std::fs::read_to_string(out.join("can/view.html")).unwrap());
    assert_eq!(
        d["bodies"][0]["shape"],
        serde_json::json!({ "kind": "cylinder", "radius": 0.3, "length": 1.2 })
    );
}
