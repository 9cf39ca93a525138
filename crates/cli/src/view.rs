//! `view.html`: the self-contained 3-D view of a run (issue 36). The page inlines the vendored
//! three.js (`assets/three/`, pinned, with its licence), a small viewer (`assets/view.js`) and
//! the run's poses as JSON, so it opens from the file system with no network.
//!
//! The poses come from a second pass over the same scene that samples the integrator's dense
//! output at [`frames`] instants instead of the file's `samples` (the samples do not change the
//! steps taken, so the pass follows the same trajectory): at most [`MAX_FRAMES`] instants, and
//! at most [`MAX_POSES`] poses (instants × bodies), whatever the run's own samples, so a
//! 10⁶-sample run makes a page of the same size as a 10³-sample one. Between samples the page
//! interpolates positions linearly and attitudes by slerp.
//!
//! Bad input: every text in the page is escaped ([`page`]); a sample with a non-finite value
//! is dropped and counted (the page says how many); a run whose poses cannot be had (the
//! second pass fails) gets a page that says why and draws nothing that moves.
//!
//! Book: §2.10 (orientation matrices and their quaternions, §2.12), §7.11 (poses of a tree of
//! bodies), §14.2 (aircraft attitude by 3-2-1 Euler angles).

use std::sync::atomic::AtomicBool;

use nalgebra::{Matrix3, Rotation3, SymmetricEigen, UnitQuaternion, Vector3};
use serde_json::{Value, json};
use vectrix_scene::spec::{Attach, EffectSpec, LoopSpec, MassSpec};
use vectrix_scene::{Run, RunControl, Scene, SceneSource};
use vectrix_units::UnitSystem;

mod notebook;
mod page;

pub use notebook::View;
pub(crate) use page::{page, page_bound};

/// Most instants a view samples.
pub(crate) const MAX_FRAMES: usize = 1001;
/// Most poses (instants × bodies) a view holds.
pub(crate) const MAX_POSES: usize = 40_000;
/// Most output columns the heads-up line shows (the first ones declared).
pub(crate) const MAX_HUD_COLUMNS: usize = 16;

/// The instants a view of `rows` samples of `bodies` bodies takes: min(rows, [`MAX_FRAMES`],
/// [`MAX_POSES`]/bodies), at least 2.
pub(crate) fn frames(rows: usize, bodies: usize) -> usize {
    rows.min(MAX_FRAMES).min(MAX_POSES / bodies.max(1)).max(2)
}

/// A number rounded to 7 significant digits (what a drawing needs), for the page's JSON.
fn r7(x: f64) -> Value {
    format!("{x:.6e}").parse::<f64>().map_or(Value::Null, Value::from)
}

/// The unit quaternion (w, x, y, z) of the rotation taking link components to ground
/// components, R = 𝓞ᵀ (the pose's E maps ground components to link components).
///
/// Book: §2.12 (Euler parameters of a rotation).
fn quaternion(link_to_ground: Matrix3<f64>) -> [f64; 4] {
    let q = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(link_to_ground));
    [q.w, q.i, q.j, q.k]
}

/// How a body is drawn: by its mass shape with its dimensions. A body given by its inertia
/// (`value`) is drawn as the uniform box of the same mass and principal moments
/// (a² = 6(J₂ + J₃ − J₁)/m, …), along its principal axes.
///
/// Book: §6.1–6.2 (inertia of the solids).
fn shape(m: &MassSpec) -> Value {
    match m {
        MassSpec::Particle { .. } => json!({ "kind": "particle" }),
        MassSpec::Massless {} => json!({ "kind": "massless" }),
        MassSpec::Sphere { radius, .. } => json!({ "kind": "sphere", "radius": r7(*radius) }),
        MassSpec::Box { sides, .. } => json!({ "kind": "box", "sides": sides.map(r7) }),
        MassSpec::Rod { length, .. } => json!({ "kind": "rod", "length": r7(*length) }),
        MassSpec::Disk { radius, .. } => json!({ "kind": "disk", "radius": r7(*radius) }),
        MassSpec::Cylinder { radius, length, .. } => {
            json!({ "kind": "cylinder", "radius": r7(*radius), "length": r7(*length) })
        }
        // an aircraft body: the glyph of the flight view, in the link's own aircraft axes
        // (z down), sized by the catalogue's span
        MassSpec::Aircraft { model } => {
            // (a validated scene names a catalogue aircraft: `business_jet` is the one)
            let _ = model;
            let span = vectrix_flight::business_jet_in(vectrix_units::UnitSystem::Si).geometry.span;
            json!({ "kind": "aircraft", "span": r7(span), "length": r7(0.8 * span), "zdown": true })
        }
        MassSpec::Value { mass, principal, matrix } => {
            let j = match (principal, matrix) {
                (_, Some(m)) => Matrix3::from_fn(|i, k| m[i][k]),
                (Some(p), None) => Matrix3::from_diagonal(&Vector3::from(*p)),
                (None, None) => Matrix3::zeros(),
            };
            let e = SymmetricEigen::new(j);
            let mut axes = e.eigenvectors;
            if axes.determinant() < 0.0 {
                axes.set_column(2, &(-axes.column(2)));
            }
            let l = e.eigenvalues;
            let side = |a: usize, b: usize, c: usize| (6.0 * (l[b] + l[c] - l[a]) / mass).max(0.0).sqrt();
            let sides = [side(0, 1, 2), side(1, 2, 0), side(2, 0, 1)];
            json!({ "kind": "box", "sides": sides.map(r7), "axes": quaternion(axes).map(r7) })
        }
    }
}

/// The index of an attached body (−1 for the ground) and the point, for a line in the page.
fn attach(a: &Attach, names: &[&str]) -> Value {
    let k = names.iter().position(|n| *n == a.body).map_or(-1, |k| k as i64);
    json!([k, r7(a.point[0]), r7(a.point[1]), r7(a.point[2])])
}

/// What the page draws besides the bodies: loops, force elements, gravity, named frames.
fn scenery(scene: &Scene) -> (Vec<Value>, Value, Vec<Value>, Vec<Value>) {
    let spec = scene.spec();
    let names: Vec<&str> = spec.bodies.iter().map(|b| b.name.as_str()).collect();
    let mut links = Vec::new();
    for l in &spec.loops {
        let (kind, name, a, b) = match l {
            LoopSpec::Ball { name, a, b } => ("ball", name, a, b),
            LoopSpec::Pin { name, a, b, .. } => ("pin", name, a, b),
            LoopSpec::PointOnLine { name, a, b, .. } => ("point_on_line", name, a, b),
            LoopSpec::PointOnPlane { name, a, b, .. } => ("point_on_plane", name, a, b),
            LoopSpec::Weld { name, a, b } => ("weld", name, a, b),
            // a joint-coordinate coupling has no points to draw
            LoopSpec::Coupler { .. } => continue,
        };
        links.push(json!({ "kind": kind, "name": name, "a": attach(a, &names), "b": attach(b, &names) }));
    }
    let (mut gravity, mut centres) = (Value::Null, Vec::new());
    for e in &spec.effects {
        let (kind, a, b) = match e {
            EffectSpec::Spring { a, b, .. } => ("spring", a, b),
            EffectSpec::Dashpot { a, b, .. } => ("dashpot", a, b),
            EffectSpec::Inerter { a, b, .. } => ("inerter", a, b),
            EffectSpec::UniformGravity { g } => {
                gravity = Value::Array(g.map(r7).to_vec());
                continue;
            }
            EffectSpec::CentralGravity { centre, .. } => {
                centres.push(Value::Array(centre.map(r7).to_vec()));
                continue;
            }
            _ => continue,
        };
        links.push(json!({ "kind": kind, "name": kind, "a": attach(a, &names), "b": attach(b, &names) }));
    }
    let frames = spec
        .frames
        .iter()
        .map(|f| {
            let axis = Vector3::from(f.axis);
            let q = nalgebra::Unit::try_new(axis, 1e-300)
                .map_or(UnitQuaternion::identity(), |u| UnitQuaternion::from_axis_angle(&u, f.angle));
            json!({ "name": f.name, "q": [r7(q.w), r7(q.i), r7(q.j), r7(q.k)] })
        })
        .collect();
    (links, gravity, centres, frames)
}

/// The heads-up columns of a run: names, units and the values per instant (at most
/// [`MAX_HUD_COLUMNS`]).
fn hud(columns: &[String], units: &[String], rows: &[Vec<f64>], keep: &[bool]) -> Value {
    let n = columns.len().min(MAX_HUD_COLUMNS);
    let values: Vec<Value> =
        rows.iter().zip(keep).filter(|(_, k)| **k).flat_map(|(r, _)| r[..n].iter().map(|x| r7(*x))).collect();
    json!({ "names": &columns[..n], "units": &units[..n], "values": values })
}

/// The self-contained page (`view.html`) of a body-scene run, as `vectrix run` writes it: the
/// scene `scene` read from `text` (its file `file`), its run `run` in `units` (of which only
/// the end time, the completion and the number of declared columns are read: the poses come
/// from a second pass at the view's instants, stopped early when `cancel` is set). At most
/// [`MAX_FRAMES`] instants and [`MAX_POSES`] poses, so the page stays within
/// [`crate::scene_page_bound`] whatever the run's samples. A run whose poses cannot be had gets a
/// page that says why.
///
/// Book: §2.10, §2.12 (attitudes as quaternions), §7.11 (poses of a tree of bodies).
pub fn scene_page(
    scene: &Scene,
    source: (&str, &str),
    run: &Run,
    units: UnitSystem,
    cancel: Option<&AtomicBool>,
) -> String {
    let name = &scene.spec().name;
    let data = scene_view(scene, source, run, units, cancel).unwrap_or_else(|why| no_poses(name, &why));
    page(name, &data)
}

/// The view of a body scene whose run is `run` (in `units`): a second pass of `scene` at the
/// view's instants, read from `text` (its file `file`), and the poses of every body.
///
/// # Errors
/// A message when the second pass fails; the page then says so.
pub(crate) fn scene_view(
    scene: &Scene,
    (text, file): (&str, &str),
    run: &Run,
    units: UnitSystem,
    cancel: Option<&AtomicBool>,
) -> Result<Value, String> {
    let spec = scene.spec();
    let nb = spec.bodies.len();
    let mut s = spec.clone();
    let t_end = run.t.last().copied().unwrap_or(0.0);
    if !run.is_complete() && t_end > 0.0 {
        s.duration = t_end;
    }
    s.samples = frames(spec.samples + 1, nb) - 1;
    if !s.outputs.iter().any(|o| o == "q") {
        s.outputs.push("q".into());
    }
    let src = SceneSource::new(text, file).map_err(|e| e.to_string())?;
    let pass = Scene::from_spec_in(s, &src).map_err(|e| e.to_string())?;
    let r = if t_end > 0.0 {
        pass.run_with(RunControl { progress: &mut |_| {}, cancel }).map_err(|e| e.to_string())?
    } else {
        return Err("the run has no motion to show: it stopped at t = 0".into());
    };
    let nq = scene.model().nq();
    let q_at: Vec<usize> = (0..nq)
        .map(|k| r.columns.iter().position(|c| *c == format!("q{k}")).ok_or("no q column in the view's pass"))
        .collect::<Result<_, _>>()?;
    let (t, pose, keep) = finite_samples(r.t.iter().zip(&r.rows).map(|(ti, row)| {
        let q: Vec<f64> = q_at.iter().map(|&k| row[k]).collect();
        let one = scene.model().poses(&q).ok().map(|ps| {
            ps.iter()
                .flat_map(|(e, p)| {
                    let [w, x, y, z] = quaternion(e.transpose());
                    [p[0], p[1], p[2], w, x, y, z]
                })
                .collect::<Vec<f64>>()
        });
        // the heads-up values must be finite too
        (*ti, one.filter(|_| row.iter().all(|x| x.is_finite())))
    }));
    let dropped = keep.iter().filter(|k| !**k).count();
    let declared = run.columns.len();
    let shown = r.clone().in_units(units).map_err(|e| e.to_string())?;
    let hud = hud(&shown.columns[..declared], &shown.units[..declared], &shown.rows, &keep);
    let (links, gravity, centres, named) = scenery(scene);
    let bodies: Vec<Value> = spec
        .bodies
        .iter()
        .map(|b| {
            let parent = spec.bodies.iter().position(|p| p.name == b.parent).map_or(-1, |k| k as i64);
            json!({
                "name": b.name, "shape": shape(&b.mass), "com": b.com.map(r7), "parent": parent,
                "offset": b.offset.map(r7),
            })
        })
        .collect();
    let trails: Vec<usize> = spec
        .outputs
        .iter()
        .filter_map(|o| o.strip_prefix("position:"))
        .filter_map(|n| spec.bodies.iter().position(|b| b.name == n))
        .collect();
    Ok(json!({
        "name": spec.name, "kind": "bodies", "t": t, "duration": r7(spec.duration),
        "complete": run.is_complete(), "bodies": bodies, "pose": pose, "links": links,
        "gravity": gravity, "centres": centres, "frames": named, "trails": trails, "hud": hud,
        "dropped": dropped, "up": up(&gravity),
    }))
}

/// The view's "up": against uniform gravity, else the ground z axis.
fn up(gravity: &Value) -> Value {
    let g: Vec<f64> =
        gravity.as_array().map(|a| a.iter().filter_map(Value::as_f64).collect()).unwrap_or_default();
    match g.as_slice() {
        [x, y, z] if x.hypot(*y).hypot(*z) > 0.0 => {
            let n = x.hypot(*y).hypot(*z);
            json!([r7(-x / n), r7(-y / n), r7(-z / n)])
        }
        _ => json!([0, 0, 1]),
    }
}

/// The samples `(t, pose numbers)` whose time and numbers are all finite (`None` marks a
/// sample that has a non-finite value elsewhere): their times and numbers, rounded, and which
/// samples were kept. A dropped sample is never drawn; the page counts them.
fn finite_samples(
    samples: impl Iterator<Item = (f64, Option<Vec<f64>>)>,
) -> (Vec<Value>, Vec<Value>, Vec<bool>) {
    let (mut t, mut pose, mut keep) = (Vec::new(), Vec::new(), Vec::new());
    for (ti, one) in samples {
        match one.filter(|v| ti.is_finite() && v.iter().all(|x| x.is_finite())) {
            Some(v) => {
                t.push(r7(ti));
                pose.extend(v.into_iter().map(r7));
                keep.push(true);
            }
            None => keep.push(false),
        }
    }
    (t, pose, keep)
}

/// The data of a page that has no poses to show, with the reason.
pub(crate) fn no_poses(name: &str, why: &str) -> Value {
    json!({
        "name": name, "kind": "none", "t": [], "duration": 0, "complete": false, "bodies": [],
        "pose": [], "links": [], "gravity": null, "centres": [], "frames": [], "trails": [],
        "hud": { "names": [], "units": [], "values": [] }, "dropped": 0, "up": [0, 0, 1],
        "note": format!("no poses to show: {why}"),
    })
}

#[cfg(test)]
mod tests;
