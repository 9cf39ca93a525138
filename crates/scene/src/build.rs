//! From a scene file to a validated scene: names resolved to indices, joints to a
//! [`Model`](vectrix_dynamics::Model), shapes to mass properties, effects to their resolved form.
//!
//! Book: §7.11 (trees), §6.1–6.2 (mass properties), §1.5 (joints).

use nalgebra::{Matrix3, Rotation3, Unit, Vector3};

use super::SceneError;
use super::resolve::{direction, effect, loop_joint};
use super::source::{SceneSource, check_name};
use super::spec::{JointSpec, MassSpec, Profile, SceneSpec};
use vectrix_dynamics::multibody::{Joint, Link, Model};

/// A body after validation: indices, offsets and mass properties in link components.
#[derive(Debug, Clone)]
pub(crate) struct Body {
    pub name: String,
    pub parent: Option<usize>,
    pub joint: JointSpec,
    /// 𝓞_{J/P}: joint frame relative to the parent link frame.
    pub orient: Matrix3<f64>,
    pub mass: f64,
    pub com: Vector3<f64>,
    pub inertia: Matrix3<f64>,
    pub qi: usize,
    pub vi: usize,
}

pub(crate) use super::kin::At;

/// Effects with names resolved.
#[derive(Debug, Clone)]
pub(crate) enum Effect {
    /// Enters the model as its base acceleration (no per-body work in the right-hand side).
    Uniform {
        g: Vector3<f64>,
    },
    Central {
        mu: f64,
        centre: Vector3<f64>,
    },
    Mutual {
        g: f64,
    },
    Spring {
        a: At,
        b: At,
        k: f64,
        d: f64,
    },
    Dashpot {
        a: At,
        b: At,
        c: f64,
    },
    Inerter {
        a: At,
        b: At,
        b_in: f64,
    },
    RotSpring {
        dof: usize,
        kappa: f64,
        angle: f64,
    },
    RotDashpot {
        dof: usize,
        xi: f64,
    },
    RotInerter {
        dof: usize,
        beta: f64,
    },
    Dipoles {
        list: Vec<(usize, Vector3<f64>)>,
    },
    Force {
        at: At,
        dir: Vector3<f64>,
        profile: Profile,
    },
    Torque {
        body: usize,
        dir: Vector3<f64>,
        profile: Profile,
    },
    Spheres {
        a: usize,
        b: usize,
        ra: f64,
        rb: f64,
        e: f64,
        mu: f64,
    },
    /// A joint stop: q[qi] ∈ [lower, upper] (±∞ for none), speed v[vi], restitution e.
    JointStop {
        qi: usize,
        vi: usize,
        lower: f64,
        upper: f64,
        e: f64,
    },
    Plane {
        body: usize,
        r: f64,
        point: Vector3<f64>,
        n: Vector3<f64>,
        e: f64,
        mu: f64,
    },
    Rolling {
        body: usize,
        disk: bool,
        r: f64,
        point: Vector3<f64>,
        n: Vector3<f64>,
    },
    /// An aircraft's aerodynamics on a free body (see [`super::aero`]).
    Aero {
        body: usize,
        aircraft: Box<vectrix_flight::Aircraft>,
        /// δe, δa, δr.
        controls: Box<[Profile; 3]>,
    },
    /// Thrust along the tilted x axis of a body, at its centre of mass.
    Thrust {
        body: usize,
        profile: Profile,
        angle: f64,
    },
}

/// Errors are located by item path in the spanned document.
pub(crate) type Src<'a> = SceneSource<'a>;

/// (nq, nv) of a joint.
pub(crate) fn dims(j: &JointSpec) -> (usize, usize) {
    match j {
        JointSpec::Pin { .. } | JointSpec::Sleeve { .. } => (1, 1),
        JointSpec::Collar { .. } | JointSpec::Slot { .. } => (2, 2),
        JointSpec::Ball {} => (4, 3),
        JointSpec::Weld {} => (0, 0),
        JointSpec::Free {} => (7, 6),
    }
}

/// The q and v layouts of a joint, as documented in docs/scenes.md.
pub(crate) fn layout(j: &JointSpec) -> (&'static str, &'static str) {
    match j {
        JointSpec::Pin { .. } => ("q = [θ] rad", "v = [θ̇] rad/s"),
        JointSpec::Sleeve { .. } => ("q = [s] m", "v = [ṡ] m/s"),
        JointSpec::Collar { .. } | JointSpec::Slot { .. } => ("q = [s m, θ rad]", "v = [ṡ m/s, θ̇ rad/s]"),
        JointSpec::Ball {} => {
            ("q = [η, ε₁, ε₂, ε₃] (unit quaternion)", "v = [ω₁, ω₂, ω₃] rad/s in the link frame")
        }
        JointSpec::Weld {} => ("q = [] (no coordinates)", "v = []"),
        JointSpec::Free {} => (
            "q = [x, y, z m, η, ε₁, ε₂, ε₃]",
            "v = [ẋ, ẏ, ż m/s in the joint frame, ω₁, ω₂, ω₃ rad/s in the link frame]",
        ),
    }
}

/// Index of the quaternion among a joint's coordinates, if it has one.
pub(crate) fn quat_index(j: &JointSpec) -> Option<usize> {
    match j {
        JointSpec::Ball {} => Some(0),
        JointSpec::Free {} => Some(3),
        _ => None,
    }
}

/// Index of the rotation angle among a joint's velocity coordinates, if it has one angle.
pub(crate) fn angle_dof(j: &JointSpec) -> Option<usize> {
    match j {
        JointSpec::Pin { .. } => Some(0),
        JointSpec::Collar { .. } | JointSpec::Slot { .. } => Some(1),
        _ => None,
    }
}

pub(crate) fn v3(a: [f64; 3]) -> Vector3<f64> {
    Vector3::new(a[0], a[1], a[2])
}

/// Mass m and J_{B/c} (link components) of a mass spec; on error the offending key and why.
///
/// Book: §6.1–6.2 (inertia of shapes); an inertia matrix must be symmetric and positive
/// semidefinite with principal moments obeying the triangle inequality J₁ ≤ J₂ + J₃ (§6.4).
fn mass_props(m: &MassSpec) -> Result<(f64, Matrix3<f64>), (&'static str, String)> {
    let pos = |x: f64, what: &'static str| {
        if x > 0.0 && x.is_finite() {
            Ok(x)
        } else {
            Err((what, format!("{what} = {x}; valid: a finite number > 0")))
        }
    };
    let (mass, j) = match m {
        MassSpec::Particle { mass } => (pos(*mass, "mass")?, Matrix3::zeros()),
        MassSpec::Massless {} => (0.0, Matrix3::zeros()),
        MassSpec::Sphere { mass, radius } => {
            let (m, r) = (pos(*mass, "mass")?, pos(*radius, "radius")?);
            (m, Matrix3::identity() * (0.4 * m * r * r))
        }
        MassSpec::Box { mass, sides } => {
            let m = pos(*mass, "mass")?;
            let [a, b, c] = [pos(sides[0], "sides")?, pos(sides[1], "sides")?, pos(sides[2], "sides")?];
            let d = Vector3::new(b * b + c * c, a * a + c * c, a * a + b * b) * (m / 12.0);
            (m, Matrix3::from_diagonal(&d))
        }
        MassSpec::Rod { mass, length } => {
            let (m, l) = (pos(*mass, "mass")?, pos(*length, "length")?);
            (m, Matrix3::from_diagonal(&Vector3::new(0.0, m * l * l / 12.0, m * l * l / 12.0)))
        }
        MassSpec::Cylinder { mass, radius, length } => {
            let (m, r, h) = (pos(*mass, "mass")?, pos(*radius, "radius")?, pos(*length, "length")?);
            let jt = m * (3.0 * r * r + h * h) / 12.0;
            (m, Matrix3::from_diagonal(&Vector3::new(jt, jt, m * r * r / 2.0)))
        }
        MassSpec::Disk { mass, radius } => {
            let (m, r) = (pos(*mass, "mass")?, pos(*radius, "radius")?);
            (m, Matrix3::from_diagonal(&Vector3::new(m * r * r / 4.0, m * r * r / 4.0, m * r * r / 2.0)))
        }
        MassSpec::Aircraft { model } => {
            let ac = super::aero::catalogue(model).ok_or(("model", super::aero::unknown_aircraft(model)))?;
            (ac.airframe.mass(), ac.airframe.inertia_matrix())
        }
        MassSpec::Value { mass, principal, matrix } => {
            let m = pos(*mass, "mass")?;
            let (key, j) = match (principal, matrix) {
                (Some(p), None) => ("principal", Matrix3::from_diagonal(&v3(*p))),
                (None, Some(r)) => ("matrix", Matrix3::from_fn(|i, j| r[i][j])),
                _ => return Err(("mass", "give exactly one of `principal` or `matrix`".into())),
            };
            check_inertia(&j).map_err(|msg| (key, msg))?;
            (m, j)
        }
    };
    if !j.iter().all(|x| x.is_finite()) {
        return Err((
            "mass",
            "the inertia overflows; valid: mass and size whose product m·l² is finite".into(),
        ));
    }
    Ok((mass, j))
}

/// A given inertia matrix must be symmetric and positive semidefinite with principal moments
/// obeying the triangle inequality (a physical body, §6.4).
fn check_inertia(j: &Matrix3<f64>) -> Result<(), String> {
    let scale = j.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let tol = 64.0 * f64::EPSILON * scale;
    if (j - j.transpose()).iter().any(|x| x.abs() > tol) {
        return Err("the inertia matrix is not symmetric; valid: rows of a symmetric matrix".into());
    }
    let mut p: Vec<f64> = j.symmetric_eigenvalues().iter().copied().collect();
    p.sort_by(f64::total_cmp);
    if p[0] < -tol || p[2] > p[0] + p[1] + tol {
        return Err(format!(
            "principal moments {:?} are not those of a body; valid: each ≥ 0 and the largest ≤ the sum of the \
             other two (§6.4)",
            p
        ));
    }
    Ok(())
}

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
    let mut bodies = Vec::new();
    let (mut nq, mut nv) = (0, 0);
    for (i, b) in spec.bodies.iter().enumerate() {
        let path = format!("bodies[{i}]");
        check_name(&b.name, "body name", false).map_err(|m| src.invalid(format!("{path}.name"), m))?;
        if b.name == "ground" || names[..i].contains(&b.name.as_str()) {
            return Err(src.invalid(
                format!("{path}.name"),
                format!(
                    "body name `{}` is reserved or repeated; valid: a new name other than `ground`",
                    b.name
                ),
            ));
        }
        let parent = index(&b.parent, &format!("{path}.parent"))?;
        if parent == Some(i) {
            return Err(src.invalid(
                format!("{path}.parent"),
                "a body cannot be its own parent; joints must form a tree",
            ));
        }
        let orient = match (&b.frame, &b.orientation) {
            // issue 35 (import): a joint frame turned in its parent, 𝓞_{J/P} = Rᵀ
            (None, Some(rows)) => {
                super::import::orientation(rows).map_err(|m| src.invalid(format!("{path}.orientation"), m))?
            }
            (Some(_), Some(_)) => {
                return Err(src.invalid(
                    format!("{path}.orientation"),
                    "both `frame` and `orientation`; valid: one of them",
                ));
            }
            (None, None) => Matrix3::identity(),
            (Some(f), None) => {
                let k = spec.frames.iter().position(|x| &x.name == f).ok_or_else(|| {
                    src.invalid(
                        format!("{path}.frame"),
                        format!("unknown frame `{f}`; declare it in [[frames]]"),
                    )
                })?;
                let fr = &spec.frames[k];
                let axis =
                    direction(fr.axis).filter(|(_, n)| *n > 1e-12).map(|(d, _)| Unit::new_unchecked(d));
                let axis = axis.ok_or_else(|| {
                    src.invalid(format!("frames[{k}].axis"), "zero axis; valid: a nonzero vector")
                })?;
                // 𝓞_{J/G} = 𝓡ᵀ of the active rotation of the ground axes
                Rotation3::from_axis_angle(&axis, fr.angle).matrix().transpose()
            }
        };
        let (mass, inertia) =
            mass_props(&b.mass).map_err(|(k, m)| src.invalid(format!("{path}.mass.{k}"), m))?;
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
        let (jq, jv) = dims(&b.joint);
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
                    format!("bodies[{i}].joint.{key}"),
                    format!("{key} = {a:?} has no direction; valid: a nonzero vector"),
                ));
            }
        }
        bodies.push(Body {
            name: b.name.clone(),
            parent,
            joint: b.joint.clone(),
            orient,
            mass,
            com: v3(b.com),
            inertia,
            qi: nq,
            vi: nv,
        });
        nq += jq;
        nv += jv;
    }
    let links: Vec<Link> = spec
        .bodies
        .iter()
        .zip(&bodies)
        .map(|(s, b)| {
            let joint = match s.joint {
                JointSpec::Pin { axis } => Joint::Pin { axis: v3(axis) },
                JointSpec::Sleeve { axis } => Joint::Sleeve { axis: v3(axis) },
                JointSpec::Collar { axis } => Joint::Collar { axis: v3(axis) },
                JointSpec::Slot { axis, direction } => {
                    Joint::Slot { axis: v3(axis), direction: v3(direction) }
                }
                JointSpec::Ball {} => Joint::Ball,
                JointSpec::Weld {} => Joint::Weld,
                JointSpec::Free {} => Joint::Free,
            };
            let mut l = Link::new(b.parent, joint, v3(s.offset), b.mass, b.com, b.inertia);
            l.orientation = b.orient;
            l
        })
        .collect();
    let model = Model::new(&links).map_err(|e| {
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
    })?;
    let mut q0 = model.neutral();
    let mut v0 = vec![0.0; model.nv()];
    for (i, (s, b)) in spec.bodies.iter().zip(&bodies).enumerate() {
        let (jq, jv) = dims(&b.joint);
        if let Some(q) = &s.q {
            if q.len() != jq {
                return Err(src.invalid(
                    format!("bodies[{i}].q"),
                    format!("{} values; valid: {jq} for this joint ({})", q.len(), layout(&b.joint).0),
                ));
            }
            q0[b.qi..b.qi + jq].copy_from_slice(q);
        }
        if let Some(v) = &s.v {
            if v.len() != jv {
                return Err(src.invalid(
                    format!("bodies[{i}].v"),
                    format!("{} values; valid: {jv} for this joint ({})", v.len(), layout(&b.joint).1),
                ));
            }
            v0[b.vi..b.vi + jv].copy_from_slice(v);
        }
        // a quaternion must be nonzero; it is normalized
        if let Some(k) = quat_index(&b.joint) {
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
    let effects = spec
        .effects
        .iter()
        .enumerate()
        .map(|(i, e)| effect(e, &format!("effects[{i}]"), &bodies, &index, &body_of, src))
        .collect::<Result<Vec<_>, _>>()?;
    let mut model = model;
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
    for (i, l) in spec.loops.iter().enumerate() {
        check_name(l.name(), "loop name", false).map_err(|m| src.invalid(format!("loops[{i}].name"), m))?;
        if spec.loops[..i].iter().any(|x| x.name() == l.name()) || names.contains(&l.name()) {
            return Err(src.invalid(
                format!("loops[{i}].name"),
                format!("loop name `{}` is repeated or names a body; valid: a new name", l.name()),
            ));
        }
    }
    Ok(Built { model, bodies, effects, loops, q0, v0 })
}
