//! From a scene file to a validated scene: names resolved to indices, joints to a
//! [`Model`](vectrix_dynamics::Model), shapes to mass properties, effects to their resolved form.
//!
//! Book: §7.11 (trees), §6.1–6.2 (mass properties), §1.5 (joints).

use nalgebra::{Matrix3, Rotation3, Unit};

use super::SceneError;
use super::mass::mass_props;
use super::parts::{Body, Effect, Src, v3};
use super::resolve::{direction, effect, loop_joint};
use super::source::check_name;
use super::spec::{JointSpec, MassSpec, SceneSpec};
use vectrix_dynamics::multibody::{Link, Model};

/// Checks every number of the spec is finite (TOML admits `inf` and `nan`).
/// The largest magnitude a number of a scene may have (SI): products of two such numbers stay
/// finite, so masses, speeds, loads and their energies mean something; beyond it a run would
/// produce ∞ or NaN, or an integrator step of zero, instead of an answer.
pub const MAX_MAGNITUDE: f64 = 1e150;

fn check_finite(spec: &SceneSpec, src: &Src) -> Result<(), SceneError> {
    fn walk(v: &toml::Value, path: &str, bad: &mut Option<(String, f64)>) {
        match v {
            toml::Value::Float(x) if (x.is_nan() || x.abs() > MAX_MAGNITUDE) && bad.is_none() => {
                *bad = Some((path.to_string(), *x))
            }
            toml::Value::Array(a) => {
                a.iter().enumerate().for_each(|(i, x)| walk(x, &format!("{path}[{i}]"), bad))
            }
            toml::Value::Table(t) => t.iter().for_each(|(k, x)| walk(x, &format!("{path}.{k}"), bad)),
            _ => {}
        }
    }
    let value = toml::Value::try_from(spec).map_err(|e| src.invalid("", e.to_string()))?;
    let mut bad = None;
    walk(&value, "", &mut bad);
    if let Some((path, x)) = bad {
        let what = if x.is_finite() { format!("{x:e}") } else { "a non-finite number".into() };
        return Err(src.invalid(
            path.trim_start_matches('.'),
            format!("{what}; valid: finite numbers of magnitude at most {MAX_MAGNITUDE:e} (SI)"),
        ));
    }
    Ok(())
}

/// The validated parts of a scene.
pub(crate) struct Built {
    pub model: Model,
    pub bodies: Vec<Body>,
    pub effects: Vec<Effect>,
    pub loops: Vec<super::loops::Loop>,
    pub q0: Vec<f64>,
    pub v0: Vec<f64>,
}

/// Validates `spec` and assembles the model and the effects.
pub(crate) fn build(spec: &SceneSpec, src: &Src) -> Result<Built, SceneError> {
    check_finite(spec, src)?;
    check_name(&spec.name, "scene name", true).map_err(|m| src.invalid("name", m))?;
    if spec.bodies.is_empty() {
        return Err(src.invalid("bodies", "no bodies; valid: at least one [[bodies]] table"));
    }
    let names: Vec<&str> = spec.bodies.iter().map(|b| b.name.as_str()).collect();
    let index = |name: &str, path: &str| -> Result<Option<usize>, SceneError> {
        if name == "ground" {
            return Ok(None);
        }
        names.iter().position(|n| *n == name).map(Some).ok_or_else(|| {
            let joints = spec.joint_aliases.keys().map(String::as_str);
            let hint = super::error::did_you_mean(name, names.iter().copied().chain(joints));
            src.invalid(path, format!("unknown body `{name}`{hint}; valid: ground, {}", names.join(", ")))
        })
    };
    let body_of = |name: &str, path: &str| -> Result<usize, SceneError> {
        index(name, path)?.ok_or_else(|| src.invalid(path, "the ground cannot move; valid: a body name"))
    };
    let mut bodies = Vec::with_capacity(spec.bodies.len());
    let (mut nq, mut nv) = (0, 0);
    for i in 0..spec.bodies.len() {
        let b = body(spec, i, (nq, nv), &index, src)?;
        (nq, nv) = (nq + b.joint.nq(), nv + b.joint.nv());
        bodies.push(b);
    }
    let mut model = model_of(spec, &bodies, src)?;
    let (q0, v0) = initial_state(spec, &bodies, &model, src)?;
    let effects = spec
        .effects
        .iter()
        .enumerate()
        .map(|(i, e)| effect(e, &format!("effects[{i}]"), &bodies, &index, &body_of, src))
        .collect::<Result<Vec<_>, _>>()?;
    for e in &effects {
        if let Effect::Uniform { g } = e {
            model.gravity += g;
        }
    }
    let loops = spec
        .loops
        .iter()
        .enumerate()
        .map(|(i, l)| loop_joint(l, &format!("loops[{i}]"), &index, (&model, &bodies), &q0, src))
        .collect::<Result<Vec<_>, _>>()?;
    check_loop_names(spec, &names, src)?;
    Ok(Built { model, bodies, effects, loops, q0, v0 })
}

/// Body `i` of the spec, validated, its coordinates starting at (qi, vi).
fn body(
    spec: &SceneSpec,
    i: usize,
    (qi, vi): (usize, usize),
    index: &super::resolve::Index,
    src: &Src,
) -> Result<Body, SceneError> {
    let b = &spec.bodies[i];
    let path = format!("bodies[{i}]");
    check_name(&b.name, "body name", false).map_err(|m| src.invalid(format!("{path}.name"), m))?;
    if b.name == "ground" || spec.bodies[..i].iter().any(|x| x.name == b.name) {
        return Err(src.invalid(
            format!("{path}.name"),
            format!("body name `{}` is reserved or repeated; valid: a new name other than `ground`", b.name),
        ));
    }
    let parent = index(&b.parent, &format!("{path}.parent"))?;
    if parent == Some(i) {
        return Err(
            src.invalid(format!("{path}.parent"), "a body cannot be its own parent; joints must form a tree")
        );
    }
    let orient = joint_orientation(spec, i, src)?;
    let (mass, inertia) = mass_props(&b.mass).map_err(|(k, m)| src.invalid(format!("{path}.mass.{k}"), m))?;
    if matches!(b.mass, MassSpec::Massless {}) && !spec.bodies.iter().any(|c| c.parent == b.name) {
        return Err(src.invalid(
            format!("{path}.mass"),
            format!(
                "`{}` is massless and carries no body: its motion is undetermined; valid: a massless link \
                 only between its parent and another body (a gimbal ring, an arm), else give it a mass",
                b.name
            ),
        ));
    }
    // a joint's axis and groove must be directions: refused at the key itself
    let axes: Vec<(&str, &[f64; 3])> = match &b.joint {
        JointSpec::Pin { axis } | JointSpec::Sleeve { axis } | JointSpec::Collar { axis } => {
            vec![("axis", axis)]
        }
        JointSpec::Slot { axis, direction } => vec![("axis", axis), ("direction", direction)],
        _ => vec![],
    };
    for (key, a) in axes {
        if !direction(*a).is_some_and(|(_, n)| n > 1e-12) {
            return Err(src.invalid(
                format!("{path}.joint.{key}"),
                format!("{key} = {a:?} has no direction; valid: a nonzero vector"),
            ));
        }
    }
    let joint = super::parts::joint_of(&b.joint);
    Ok(Body { name: b.name.clone(), parent, joint, orient, mass, com: v3(b.com), inertia, qi, vi })
}

/// 𝓞_{J/P} of body `i`'s joint frame: from its `orientation` rows (issue 35, imported models),
/// a named frame of `[[frames]]`, or the identity.
fn joint_orientation(spec: &SceneSpec, i: usize, src: &Src) -> Result<Matrix3<f64>, SceneError> {
    let (b, path) = (&spec.bodies[i], format!("bodies[{i}]"));
    match (&b.frame, &b.orientation) {
        // issue 35 (import): a joint frame turned in its parent, 𝓞_{J/P} = Rᵀ
        (None, Some(rows)) => {
            super::import::orientation(rows).map_err(|m| src.invalid(format!("{path}.orientation"), m))
        }
        (Some(_), Some(_)) => {
            Err(src
                .invalid(format!("{path}.orientation"), "both `frame` and `orientation`; valid: one of them"))
        }
        (None, None) => Ok(Matrix3::identity()),
        (Some(f), None) => {
            let k = spec.frames.iter().position(|x| &x.name == f).ok_or_else(|| {
                src.invalid(format!("{path}.frame"), format!("unknown frame `{f}`; declare it in [[frames]]"))
            })?;
            let fr = &spec.frames[k];
            let axis = direction(fr.axis).filter(|(_, n)| *n > 1e-12).map(|(d, _)| Unit::new_unchecked(d));
            let axis = axis.ok_or_else(|| {
                src.invalid(format!("frames[{k}].axis"), "zero axis; valid: a nonzero vector")
            })?;
            // 𝓞_{J/G} = 𝓡ᵀ of the active rotation of the ground axes
            Ok(Rotation3::from_axis_angle(&axis, fr.angle).matrix().transpose())
        }
    }
}

/// The multibody model of the validated bodies; its refusals (a cycle, a joint's geometry)
/// located at the body's key.
fn model_of(spec: &SceneSpec, bodies: &[Body], src: &Src) -> Result<Model, SceneError> {
    let links: Vec<Link> = spec
        .bodies
        .iter()
        .zip(bodies)
        .map(|(s, b)| {
            let mut l = Link::new(b.parent, b.joint, v3(s.offset), b.mass, b.com, b.inertia);
            l.orientation = b.orient;
            l
        })
        .collect();
    Model::new(&links).map_err(|e| {
        use vectrix_dynamics::DynamicsError as D;
        // a cycle is in the parents; a bad axis or geometry in the joint
        let (i, key) = match &e {
            D::Cyclic { link } => (*link, "parent"),
            D::ZeroAxis { link, .. } | D::JointGeometry { link, .. } => (*link, "joint"),
            _ => (0, "joint"),
        };
        let message = match &e {
            D::Cyclic { .. } => format!(
                "body `{}` is its own ancestor through its parents; valid: parents that form a tree rooted at \
                 the ground",
                spec.bodies[i].name
            ),
            _ => format!("{e} (joints must form a tree)"),
        };
        src.invalid(format!("bodies[{i}].{key}"), message)
    })
}

/// The initial state (q₀, v₀): the model's neutral configuration with each body's `q` and `v`
/// written over it, quaternions normalized.
fn initial_state(
    spec: &SceneSpec,
    bodies: &[Body],
    model: &Model,
    src: &Src,
) -> Result<(Vec<f64>, Vec<f64>), SceneError> {
    let mut q0 = model.neutral();
    let mut v0 = vec![0.0; model.nv()];
    for (i, (s, b)) in spec.bodies.iter().zip(bodies).enumerate() {
        let (jq, jv) = (b.joint.nq(), b.joint.nv());
        if let Some(q) = &s.q {
            if q.len() != jq {
                return Err(src.invalid(
                    format!("bodies[{i}].q"),
                    format!("{} values; valid: {jq} for this joint ({})", q.len(), b.joint.layout().0),
                ));
            }
            q0[b.qi..b.qi + jq].copy_from_slice(q);
        }
        if let Some(v) = &s.v {
            if v.len() != jv {
                return Err(src.invalid(
                    format!("bodies[{i}].v"),
                    format!("{} values; valid: {jv} for this joint ({})", v.len(), b.joint.layout().1),
                ));
            }
            v0[b.vi..b.vi + jv].copy_from_slice(v);
        }
        // a quaternion must be nonzero; it is normalized
        if let Some(k) = b.joint.quaternion_index() {
            let qq = &mut q0[b.qi + k..b.qi + k + 4];
            let n = qq.iter().map(|x| x * x).sum::<f64>().sqrt();
            if !(n > 1e-150 && n.is_finite()) {
                return Err(src.invalid(
                    format!("bodies[{i}].q"),
                    format!("the quaternion has norm {n:e}; valid: a nonzero (η, ε₁, ε₂, ε₃), normalized on loading"),
                ));
            }
            qq.iter_mut().for_each(|x| *x /= n);
        }
    }
    Ok((q0, v0))
}

/// Loop names are valid, unique, and name no body.
fn check_loop_names(spec: &SceneSpec, names: &[&str], src: &Src) -> Result<(), SceneError> {
    for (i, l) in spec.loops.iter().enumerate() {
        check_name(l.name(), "loop name", false).map_err(|m| src.invalid(format!("loops[{i}].name"), m))?;
        if spec.loops[..i].iter().any(|x| x.name() == l.name()) || names.contains(&l.name()) {
            return Err(src.invalid(
                format!("loops[{i}].name"),
                format!("loop name `{}` is repeated or names a body; valid: a new name", l.name()),
            ));
        }
    }
    Ok(())
}
