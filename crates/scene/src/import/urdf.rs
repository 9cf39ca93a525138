//! URDF (ROS `urdf/XML`) as bodies of a scene.
//!
//! # Mapping
//! * `<joint type="revolute|continuous">` → pin about `<axis xyz>` (default x̂); `prismatic`
//!   → sleeve; `floating` → free (q = position in the parent, quaternion (η, ε) scalar first;
//!   v = velocity in the parent, ω in the link); `planar` → the book's planar motion as two
//!   sleeves across `axis` (massless bodies `CHILD_planar_u`, `CHILD_planar_w`) and a pin
//!   about it; `fixed` → the child merged into its parent (mass properties added by the
//!   parallel-axis theorem, its frame kept in [`ImportedModel::frames`]).
//! * The joint frame sits at `<origin xyz rpy>` of the parent link; at q = 0 the child link's
//!   frame is the joint frame (the scene's convention, and URDF's).
//! * `<inertial>`: `<origin>` places the centre of mass and turns the inertia axes;
//!   `<mass value>`, `<inertia ixx … izz>` (J_{B/c} entries, products as −J_xy is already in
//!   URDF's signs: ixy is the matrix entry). A link without `<inertial>` is massless.
//! * `<mimic joint multiplier offset>` → a coupler loop `JOINT_mimic` (q = multiplier ·
//!   q_joint + offset, a holonomic constraint with its multiplier, as Pinocchio's mimic joint).
//! * `<limit>`: kept as data ([`ImportedModel::limits`]); they do not act.
//! * The root link is the ground (its own mass properties act on nothing).
//! * Bodies come in depth-first order from the root, children in file order: Pinocchio's
//!   `buildModelFromUrdf` order, so q and v have Pinocchio's layout (except the free joint's
//!   quaternion, scalar first here, and its linear velocity, in the parent here and in the
//!   link in Pinocchio).
//!
//! Everything else (`<visual>`, `<collision>`, `<material>`, `<gazebo>`, `<transmission>`,
//! `<dynamics>`, `<calibration>`, `<safety_controller>`, unknown attributes) is
//! listed in [`ImportedModel::warnings`].
//!
//! Book: §7.11 (trees), §1.5 (pin, sleeve, planar), §6.2 (parallel-axis theorem).

use std::collections::HashMap;

use nalgebra::{Matrix3, Vector3};
use roxmltree::Node;

use super::mass::{MassProps, check_stated, rows, rpy};
use super::xml::{Tracked, count_capped, error_at, parse};
use super::{ImportedModel, JointLimit, LinkFrame, MAX_MODEL_LINKS};
use crate::SceneError;
use crate::spec::{BodySpec, JointSpec, LoopSpec, MassSpec};

struct RawLink<'a, 'i> {
    node: Node<'a, 'i>,
    name: String,
    inertial: Option<MassProps>,
}

struct RawJoint<'a, 'i> {
    node: Node<'a, 'i>,
    name: String,
    kind: String,
    parent: usize,
    child: usize,
    rot: Matrix3<f64>,
    xyz: Vector3<f64>,
    axis: Vector3<f64>,
    limit: Option<JointLimit>,
    /// `<mimic joint multiplier offset>`: this joint's q = multiplier · q_joint + offset.
    mimic: Option<(Node<'a, 'i>, String, f64, f64)>,
}

/// Reads a URDF document (`file` names it in messages).
///
/// Book: §7.11.
///
/// # Errors
/// [`SceneError::Parse`] at the offending element: malformed XML, more than
/// [`MAX_MODEL_LINKS`] links, a missing or repeated name, a joint naming an unknown link, a
/// link with two parent joints, a cycle, two roots, an unknown joint type, a zero axis, a
/// non-finite number, an `<inertial>` with mass ≤ 0 or an inertia not positive definite.
pub fn load_urdf(text: &str, file: &str) -> Result<ImportedModel, SceneError> {
    let links_seen = count_capped(text, "<link", MAX_MODEL_LINKS);
    if links_seen > MAX_MODEL_LINKS {
        return Err(error_at(
            file,
            (1, 1),
            format!("more than {MAX_MODEL_LINKS} links; valid: at most {MAX_MODEL_LINKS} links in one model"),
        ));
    }
    let doc = parse(text, file)?;
    let mut t = Tracked::new(&doc, file);
    let root = doc.root_element();
    if root.tag_name().name() != "robot" {
        return Err(t.err(root, "the root element is not <robot>; valid: a URDF file"));
    }
    t.use_el(root);
    let name = t.attr(root, "name").unwrap_or("robot").to_string();
    let mut links: Vec<RawLink> = Vec::new();
    let mut index: HashMap<String, usize> = HashMap::new();
    let mut joint_nodes = Vec::new();
    for n in root.children().filter(Node::is_element) {
        match n.tag_name().name() {
            "link" => {
                let l = read_link(&mut t, n)?;
                if index.insert(l.name.clone(), links.len()).is_some() {
                    return Err(
                        t.err(n, format!("link name `{}` is repeated; valid: unique link names", l.name))
                    );
                }
                links.push(l);
            }
            "joint" => joint_nodes.push(n),
            "material" => t.skip(n, "appearance is not used for dynamics"),
            "gazebo" | "transmission" => {
                t.skip(n, "simulator and actuator settings do not map onto the scene")
            }
            _ => {}
        }
    }
    let mut joints = Vec::new();
    let mut parent_joint: Vec<Option<usize>> = vec![None; links.len()];
    for n in joint_nodes {
        let j = read_joint(&mut t, n, &index)?;
        if let Some(k) = parent_joint[j.child] {
            return Err(t.err(
                n,
                format!(
                    "link `{}` already has parent joint `{}`; valid: one parent joint per link (a tree)",
                    links[j.child].name,
                    joints_name(&joints, k)
                ),
            ));
        }
        parent_joint[j.child] = Some(joints.len());
        joints.push(j);
    }
    let root_link = find_root(&t, &links, &parent_joint, &joints)?;
    let mut model = ImportedModel { name, ..ImportedModel::default() };
    emit(&t, &links, &joints, root_link, &mut model)?;
    mimics(&t, &links, &joints, &mut model)?;
    model.warnings = t.warnings(root);
    Ok(model)
}

fn joints_name(joints: &[RawJoint], k: usize) -> String {
    joints[k].name.clone()
}

fn read_link<'a, 'i>(t: &mut Tracked<'a, 'i>, n: Node<'a, 'i>) -> Result<RawLink<'a, 'i>, SceneError> {
    t.use_el(n);
    let name = t.req(n, "name")?.to_string();
    crate::source::check_name(&name, "link name", false).map_err(|m| t.err(n, m))?;
    if name == "ground" {
        return Err(t.err(n, "link name `ground` is reserved by the scene; valid: another name"));
    }
    let mut inertial = None;
    for c in n.children().filter(Node::is_element) {
        match c.tag_name().name() {
            "inertial" if inertial.is_none() => inertial = Some(read_inertial(t, c)?),
            "visual" | "collision" => {
                t.skip(c, "geometry is not read for dynamics (meshes are never opened)")
            }
            _ => {}
        }
    }
    Ok(RawLink { node: n, name, inertial })
}

/// `<origin xyz rpy>` of `n` (identity when absent).
fn origin<'i>(t: &mut Tracked<'_, 'i>, n: Node<'_, 'i>) -> Result<(Matrix3<f64>, Vector3<f64>), SceneError> {
    let Some(o) = n.children().find(|c| c.has_tag_name("origin")) else {
        return Ok((Matrix3::identity(), Vector3::zeros()));
    };
    t.use_el(o);
    let xyz = t.vec3(o, "xyz", [0.0; 3])?;
    let r = t.vec3(o, "rpy", [0.0; 3])?;
    Ok((rpy(r), Vector3::from(xyz)))
}

fn read_inertial<'i>(t: &mut Tracked<'_, 'i>, n: Node<'_, 'i>) -> Result<MassProps, SceneError> {
    t.use_el(n);
    let (r, c) = origin(t, n)?;
    let child = |name: &str| n.children().find(|c| c.has_tag_name(name));
    let m_node = child("mass").ok_or_else(|| t.err(n, "missing <mass>"))?;
    t.use_el(m_node);
    let m = t.nums(m_node, "value", Some(1))?.ok_or_else(|| t.err(m_node, "missing attribute `value`"))?[0];
    let i_node = child("inertia").ok_or_else(|| t.err(n, "missing <inertia>"))?;
    t.use_el(i_node);
    let mut g = |k: &str| t.num(i_node, k, 0.0);
    let (xx, xy, xz, yy, yz, zz) = (g("ixx")?, g("ixy")?, g("ixz")?, g("iyy")?, g("iyz")?, g("izz")?);
    let j = Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz);
    check_stated(m, &j).map_err(|e| t.err(n, e))?;
    Ok(MassProps { m, c: Vector3::zeros(), j }.moved(&r, &c))
}

fn read_joint<'a, 'i>(
    t: &mut Tracked<'a, 'i>,
    n: Node<'a, 'i>,
    index: &HashMap<String, usize>,
) -> Result<RawJoint<'a, 'i>, SceneError> {
    t.use_el(n);
    let name = t.req(n, "name")?.to_string();
    let kind = t.req(n, "type")?.to_string();
    const KINDS: &str = "revolute, continuous, prismatic, fixed, floating, planar";
    if !KINDS.split(", ").any(|k| k == kind) {
        return Err(t.err(n, format!("joint `{name}` has unknown type `{kind}`; valid: {KINDS}")));
    }
    let mut link_of = |tag: &str| -> Result<usize, SceneError> {
        let c =
            n.children().find(|c| c.has_tag_name(tag)).ok_or_else(|| t.err(n, format!("missing <{tag}>")))?;
        t.use_el(c);
        let l = t.req(c, "link")?;
        index
            .get(l)
            .copied()
            .ok_or_else(|| t.err(c, format!("unknown link `{l}`; valid: a <link> of this file")))
    };
    let parent = link_of("parent")?;
    let child = link_of("child")?;
    if parent == child {
        return Err(t.err(n, format!("joint `{name}` joins a link to itself; valid: a tree")));
    }
    let (rot, xyz) = origin(t, n)?;
    let mut axis = Vector3::x();
    if let Some(a) = n.children().find(|c| c.has_tag_name("axis")) {
        t.use_el(a);
        axis = Vector3::from(t.vec3(a, "xyz", [1.0, 0.0, 0.0])?);
        if matches!(kind.as_str(), "fixed" | "floating") {
            t.skip(a, "a fixed or floating joint has no axis");
        } else if axis.norm() == 0.0 {
            return Err(t.err(a, "zero axis; valid: a nonzero vector"));
        }
    }
    let mut limit = None;
    if let Some(l) = n.children().find(|c| c.has_tag_name("limit")) {
        t.use_el(l);
        let range = match kind.as_str() {
            "revolute" | "prismatic" => Some((t.num(l, "lower", 0.0)?, t.num(l, "upper", 0.0)?)),
            _ => None,
        };
        let (effort, velocity) = (t.num(l, "effort", f64::INFINITY)?, t.num(l, "velocity", f64::INFINITY)?);
        limit = Some(JointLimit { joint: name.clone(), body: String::new(), range, effort, velocity });
    }
    let mut mimic = None;
    if let Some(c) = n.children().find(|c| c.has_tag_name("mimic")) {
        t.use_el(c);
        let leader = t.req(c, "joint")?.to_string();
        mimic = Some((c, leader, t.num(c, "multiplier", 1.0)?, t.num(c, "offset", 0.0)?));
    }
    Ok(RawJoint { node: n, name, kind, parent, child, rot, xyz, axis, limit, mimic })
}

/// The one link without a parent joint, every link reachable from it.
fn find_root(
    t: &Tracked,
    links: &[RawLink],
    parent_joint: &[Option<usize>],
    joints: &[RawJoint],
) -> Result<usize, SceneError> {
    let roots: Vec<usize> = (0..links.len()).filter(|&i| parent_joint[i].is_none()).collect();
    match roots.as_slice() {
        [] if links.is_empty() => Err(error_at(&t.file, (1, 1), "no <link>; valid: at least one link")),
        [] => Err(t.err(
            joints[0].node,
            "every link has a parent joint, so the joints form a cycle; valid: a tree with one root link",
        )),
        [r] => {
            // walk up from every link: a link that never reaches the root sits on a cycle
            for (i, l) in links.iter().enumerate() {
                let mut k = i;
                for _ in 0..=links.len() {
                    match parent_joint[k] {
                        None => break,
                        Some(j) => k = joints[j].parent,
                    }
                }
                if k != *r {
                    return Err(t.err(
                        l.node,
                        format!(
                            "link `{}` is its own ancestor through the joints (a cycle); valid: a tree",
                            l.name
                        ),
                    ));
                }
            }
            Ok(*r)
        }
        [a, b, ..] => {
            let (la, _) = t.pos(links[*a].node);
            Err(t.err(
                links[*b].node,
                format!(
                    "two root links, `{}` (line {la}) and `{}`; valid: one root (join them by a joint)",
                    links[*a].name, links[*b].name
                ),
            ))
        }
    }
}

/// Where a link's frame is: in the body carrying it (`None` = the ground), turned by R, at p.
type Host = (Option<usize>, Matrix3<f64>, Vector3<f64>);

fn emit(
    t: &Tracked,
    links: &[RawLink],
    joints: &[RawJoint],
    root: usize,
    m: &mut ImportedModel,
) -> Result<(), SceneError> {
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); links.len()];
    for (k, j) in joints.iter().enumerate() {
        children[j.parent].push(k);
    }
    let mut host: Vec<Host> = vec![(None, Matrix3::identity(), Vector3::zeros()); links.len()];
    let mut mass: Vec<MassProps> = Vec::new();
    frame(m, &links[root].name, "ground", &Matrix3::identity(), &Vector3::zeros());
    // depth first, children in file order (Pinocchio's order)
    let mut stack: Vec<usize> = children[root].iter().rev().copied().collect();
    while let Some(k) = stack.pop() {
        let j = &joints[k];
        let (hb, r, p) = host[j.parent];
        let (rj, pj) = (r * j.rot, p + r * j.xyz);
        let host_name = |b: Option<usize>, m: &ImportedModel| {
            b.map_or("ground".to_string(), |b| m.bodies[b].name.clone())
        };
        let child = &links[j.child];
        let own = child.inertial.unwrap_or_else(MassProps::zero);
        if j.kind == "fixed" {
            host[j.child] = (hb, rj, pj);
            if let Some(b) = hb {
                mass[b] = mass[b].merged(&own.moved(&rj, &pj));
            }
            let hn = host_name(hb, m);
            frame(m, &child.name, &hn, &rj, &pj);
        } else {
            let mut parent = host_name(hb, m);
            let (mut rj, mut pj) = (rj, pj);
            if j.kind == "planar" {
                // two massless sliders across the normal, then the pin about it
                let n = j.axis.normalize();
                let u = if n.x.abs() < 0.9 { Vector3::x() } else { Vector3::y() };
                let u = (u - n * n.dot(&u)).normalize();
                let w = n.cross(&u);
                for (suffix, d) in [("u", u), ("w", w)] {
                    let name = format!("{}_planar_{suffix}", child.name);
                    push_body(
                        m,
                        &mut mass,
                        name.clone(),
                        parent,
                        JointSpec::Sleeve { axis: d.into() },
                        &rj,
                        &pj,
                        &j.name,
                    );
                    parent = name;
                    (rj, pj) = (Matrix3::identity(), Vector3::zeros());
                }
            }
            let joint = match j.kind.as_str() {
                "revolute" | "continuous" | "planar" => JointSpec::Pin { axis: j.axis.into() },
                "prismatic" => JointSpec::Sleeve { axis: j.axis.into() },
                _ => JointSpec::Free {},
            };
            push_body(m, &mut mass, child.name.clone(), parent, joint, &rj, &pj, &j.name);
            let b = m.bodies.len() - 1;
            mass[b] = own;
            host[j.child] = (Some(b), Matrix3::identity(), Vector3::zeros());
            frame(m, &child.name, &child.name, &Matrix3::identity(), &Vector3::zeros());
            if let Some(l) = &j.limit {
                m.limits.push(JointLimit { body: child.name.clone(), ..l.clone() });
            }
        }
        stack.extend(children[j.child].iter().rev());
    }
    for (b, mp) in mass.iter().enumerate() {
        if mp.m > 0.0 {
            m.bodies[b].mass = MassSpec::Value { mass: mp.m, principal: None, matrix: Some(rows(&mp.j)) };
            m.bodies[b].com = mp.c.into();
        } else if !m.bodies.iter().any(|c| c.parent == m.bodies[b].name) {
            let l = links.iter().find(|l| l.name == m.bodies[b].name).map_or(links[root].node, |l| l.node);
            return Err(t.err(
                l,
                format!(
                    "link `{}` moves but has no <inertial> and carries nothing: its motion is undetermined; valid: an <inertial>",
                    m.bodies[b].name
                ),
            ));
        }
    }
    Ok(())
}

/// Every `<mimic>` as a coupler loop `JOINT_mimic`: the follower's body's coordinate is
/// `multiplier` times the leader's plus `offset` (both revolute, continuous or prismatic).
fn mimics(
    t: &Tracked,
    links: &[RawLink],
    joints: &[RawJoint],
    m: &mut ImportedModel,
) -> Result<(), SceneError> {
    const ONE: [&str; 3] = ["revolute", "continuous", "prismatic"];
    for j in joints {
        let Some((c, leader, ratio, offset)) = &j.mimic else { continue };
        if !ONE.contains(&j.kind.as_str()) {
            return Err(t.err(
                *c,
                format!(
                    "joint `{}` is {}; valid: <mimic> on a revolute, continuous or prismatic joint",
                    j.name, j.kind
                ),
            ));
        }
        let l = joints.iter().find(|x| &x.name == leader).ok_or_else(|| {
            t.err(
                *c,
                format!(
                    "unknown joint `{leader}`; valid: a revolute, continuous or prismatic joint of this file"
                ),
            )
        })?;
        if !ONE.contains(&l.kind.as_str()) || l.name == j.name {
            return Err(t.err(
                *c,
                format!(
                    "joint `{leader}` ({}) cannot lead; valid: another revolute, continuous or prismatic joint",
                    l.kind
                ),
            ));
        }
        m.loops.push(LoopSpec::Coupler {
            name: format!("{}_mimic", j.name),
            body: links[j.child].name.clone(),
            leader: Some(links[l.child].name.clone()),
            ratio: *ratio,
            offset: *offset,
        });
    }
    Ok(())
}

fn frame(m: &mut ImportedModel, link: &str, body: &str, r: &Matrix3<f64>, p: &Vector3<f64>) {
    m.frames.push(LinkFrame {
        link: link.into(),
        body: body.into(),
        offset: (*p).into(),
        orientation: rows(r),
    });
}

#[allow(clippy::too_many_arguments)]
fn push_body(
    m: &mut ImportedModel,
    mass: &mut Vec<MassProps>,
    name: String,
    parent: String,
    joint: JointSpec,
    r: &Matrix3<f64>,
    p: &Vector3<f64>,
    joint_name: &str,
) {
    let orientation = (*r != Matrix3::identity()).then(|| rows(r));
    m.bodies.push(BodySpec {
        name,
        parent,
        joint,
        offset: (*p).into(),
        frame: None,
        orientation,
        mass: MassSpec::Massless {},
        com: [0.0; 3],
        q: None,
        v: None,
    });
    m.joint_names.push(joint_name.into());
    mass.push(MassProps::zero());
}
