//! The `[model]` table: a URDF or MJCF file, confined to the scene file's folder tree, read
//! into the scene's bodies and loops.
//!
//! Book: §7.11.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use super::files::{confined, read_model};
use super::{ImportWarning, ImportedModel, mjcf, urdf};
use crate::SceneError;
use crate::source::SceneSource;
use crate::spec::{BodySpec, EffectSpec, LimitsMode, SceneSpec};

/// Standard gravity, −ẑ [m/s²]: the default of a model without `<option gravity>`.
const G0: [f64; 3] = [0.0, 0.0, -9.81];

/// Reads the model file at `path` (`mjcf` picks the format; MJCF includes stay inside `dir`).
///
/// # Errors
/// [`SceneError::Parse`] located in the model file; a read failure as a message.
pub fn load_file(path: &Path, dir: &Path, is_mjcf: bool) -> Result<ImportedModel, SceneError> {
    let shown = path.display().to_string();
    let text = read_model(path).map_err(|m| SceneError::Parse {
        file: shown.clone(),
        line: 1,
        column: 1,
        message: m,
    })?;
    if is_mjcf { mjcf::load_mjcf(&text, &shown, dir) } else { urdf::load_urdf(&text, &shown) }
}

/// The scene with its `[model]` read in: the model's bodies after the scene's own, its loops
/// after the scene's, uniform gravity added when `gravity = true`; `model` is then cleared
/// (so expanding again changes nothing). Returns the warnings of what did not map.
///
/// Book: §7.11.
///
/// # Errors
/// [`SceneError::Invalid`] at `model.*` (both or neither file, a path leaving the folder,
/// a missing file); the model file's own errors ([`SceneError::Parse`] at its line); with
/// `strict`, the first warning as an error.
pub fn expand(mut spec: SceneSpec, src: &SceneSource) -> Result<(SceneSpec, Vec<ImportWarning>), SceneError> {
    let Some(m) = spec.model.take() else { return Ok((spec, Vec::new())) };
    let (key, rel, is_mjcf) = match (&m.urdf, &m.mjcf) {
        (Some(u), None) => ("model.urdf", u.clone(), false),
        (None, Some(x)) => ("model.mjcf", x.clone(), true),
        _ => return Err(src.invalid("model", "give exactly one of `urdf` and `mjcf`")),
    };
    let dir = match Path::new(src.file()).parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let path = confined(&dir, &rel).map_err(|e| src.invalid(key, e))?;
    let base = dir.canonicalize().unwrap_or(dir);
    let model = load_file(&path, &base, is_mjcf)?;
    model.check_strict(m.strict)?;
    let mut bodies = model.bodies;
    let alias = joint_aliases(&bodies, &model.joint_names, &spec);
    for (key, map, is_q) in [("q", &m.q, true), ("v", &m.v, false)] {
        for (name, x) in map {
            let body = alias.get(name).unwrap_or(name);
            let Some(k) = bodies.iter().position(|b| &b.name == body) else {
                let known = bodies.iter().map(|b| b.name.as_str()).chain(alias.keys().map(String::as_str));
                let hint = crate::error::did_you_mean(name, known);
                return Err(src.invalid(
                    format!("model.{key}.{name}"),
                    format!("`{name}` is neither a moving body nor a joint of the model{hint}; valid: a body or joint name"),
                ));
            };
            if is_q { bodies[k].q = Some(x.clone()) } else { bodies[k].v = Some(x.clone()) }
        }
    }
    rename_references(&mut spec, &alias).map_err(|e| src.invalid("model", e))?;
    spec.joint_aliases = alias.into_iter().collect();
    if !(0.0..=1.0).contains(&m.limit_restitution) {
        return Err(src.invalid(
            "model.limit_restitution",
            format!("e = {}; valid: a restitution in [0, 1]", m.limit_restitution),
        ));
    }
    if m.limits == LimitsMode::Contact {
        // each limit with a range becomes a joint stop (MuJoCo's limits; Pinocchio keeps data)
        for l in &model.limits {
            if let Some((lo, hi)) = l.range {
                spec.effects.push(EffectSpec::JointStop {
                    body: l.body.clone(),
                    lower: Some(lo),
                    upper: Some(hi),
                    restitution: m.limit_restitution,
                });
            }
        }
    }
    spec.bodies.extend(bodies);
    spec.loops.extend(model.loops);
    if m.gravity {
        spec.effects.push(EffectSpec::UniformGravity { g: model.gravity.unwrap_or(G0) });
    }
    Ok((spec, model.warnings))
}

/// Joint name → body name for every joint of the model that moves exactly one body (a URDF
/// planar joint moves three and is left to its bodies' names) and names no body of the model
/// or of the scene (a body name always wins).
fn joint_aliases(bodies: &[BodySpec], joints: &[String], spec: &SceneSpec) -> HashMap<String, String> {
    let is_body = |n: &str| bodies.iter().chain(&spec.bodies).any(|b| b.name == n);
    let mut alias = HashMap::new();
    for (b, j) in bodies.iter().zip(joints) {
        if joints.iter().filter(|k| *k == j).count() == 1 && !is_body(j) {
            alias.insert(j.clone(), b.name.clone());
        }
    }
    alias
}

/// Joint names used where the scene names a body (effects' `body`, `a`, `b`, `leader`,
/// loops' ends, `parent`, `outputs` as `KIND:JOINT`) replaced by their body's name.
///
/// # Errors
/// A message when the effects or loops do not survive the round trip through TOML values
/// (they always should: they were read from TOML).
fn rename_references(spec: &mut SceneSpec, alias: &HashMap<String, String>) -> Result<(), String> {
    if alias.is_empty() {
        return Ok(());
    }
    fn walk(v: &mut toml::Value, alias: &HashMap<String, String>) {
        match v {
            toml::Value::Table(t) => {
                for (k, x) in t.iter_mut() {
                    match x {
                        toml::Value::String(s) if matches!(k.as_str(), "body" | "a" | "b" | "leader") => {
                            if let Some(b) = alias.get(s.as_str()) {
                                *s = b.clone();
                            }
                        }
                        _ => walk(x, alias),
                    }
                }
            }
            toml::Value::Array(a) => a.iter_mut().for_each(|x| walk(x, alias)),
            _ => {}
        }
    }
    let mut effects = toml::Value::try_from(&spec.effects).map_err(|e| e.to_string())?;
    walk(&mut effects, alias);
    spec.effects = effects.try_into().map_err(|e: toml::de::Error| e.to_string())?;
    let mut loops = toml::Value::try_from(&spec.loops).map_err(|e| e.to_string())?;
    walk(&mut loops, alias);
    spec.loops = loops.try_into().map_err(|e: toml::de::Error| e.to_string())?;
    for b in &mut spec.bodies {
        if let Some(p) = alias.get(&b.parent) {
            b.parent = p.clone();
        }
    }
    for o in &mut spec.outputs {
        if let Some((kind, name)) = o.split_once(':')
            && kind != "reaction"
            && let Some(b) = alias.get(name)
        {
            *o = format!("{kind}:{b}");
        }
    }
    Ok(())
}

/// A scene for a model file alone (`vectrix run arm.urdf`): the model with gravity, 2 s, its
/// coordinates as outputs (the default of a scene without `outputs`).
///
/// Book: §7.11.
pub fn model_scene_toml(file_name: &str, is_mjcf: bool) -> String {
    let stem = Path::new(file_name).file_stem().and_then(|s| s.to_str()).unwrap_or("model");
    let name: String =
        stem.chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' { c } else { '_' }).take(64).collect();
    let key = if is_mjcf { "mjcf" } else { "urdf" };
    let quoted = toml::Value::String(file_name.to_string());
    // the neutral configuration is projected onto the model's loops (a gear with an offset, a
    // weld): a model alone starts assembled, as MuJoCo's solver pulls its equalities closed
    format!(
        "name = \"{name}\"\nduration = 2.0\nassemble = true\n\n[model]\n{key} = {quoted}\ngravity = true\n"
    )
}
