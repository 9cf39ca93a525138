//! MJCF (MuJoCo's XML) as bodies of a scene.
//!
//! # Mapping
//! * `<include file>` is read in place (relative to the model's folder, never outside it; at
//!   most [`MAX_INCLUDES`] files, each once); `<default>` classes (nested, `class`,
//!   `childclass`) give `<joint>` and `<geom>` attributes; `<compiler angle>` (degrees unless
//!   `radian`), `eulerseq` and `inertiafromgeom` are honoured.
//! * `<body pos quat|axisangle|euler|xyaxes|zaxis>`: its frame in the parent body. A body
//!   without joints is merged into its parent (the ground for a child of `<worldbody>`); a
//!   body with k joints is k bodies in a chain (the first k − 1 massless, named
//!   `BODY_j1`, …), each link frame at its joint's `pos`, turned as the body.
//! * `hinge` → pin, `slide` → sleeve about/along `axis` (default ẑ), `ball` → ball, `free`
//!   (and `<freejoint>`) → free with the joint frame the ground's: q = MuJoCo's qpos
//!   (position, quaternion w x y z), v = MuJoCo's qvel (velocity in the ground, ω in the
//!   body). q and v follow MuJoCo's order (bodies depth first, joints in body order).
//! * Mass: `<inertial pos quat… mass diaginertia|fullinertia>`, else (compiler
//!   `inertiafromgeom="auto"`, the default, or `"true"`) the geoms' as MuJoCo's compiler
//!   derives them: `sphere`, `capsule`, `cylinder`, `ellipsoid`, `box` of `density` (1000) or
//!   `mass`, placed by `pos`/`quat`/…/`fromto`. A mesh geom is never read: a body whose mass
//!   would come from one is refused (give it an `<inertial>`).
//! * `<equality>`: `<connect body1 body2 anchor>` → a ball loop; `<weld body1 body2 anchor>`
//!   → a weld loop holding the reference relative pose (anchor in body2's frame, as MuJoCo);
//!   `<joint joint1 joint2 polycoef="c0 c1 0 0 0">` → a coupler q₁ = c₀ + c₁ q₂ (linear
//!   polynomials only: a nonlinear one is left out with a warning).
//! * `<option gravity timestep>` → [`ImportedModel::gravity`], [`ImportedModel::timestep`];
//!   joint `range` → limits (data).
//!
//! Everything else (a weld's explicit `relpose`, `solref`/`solimp`, actuators, sensors, contacts, tendons, sites, cameras, lights,
//! assets, damping, armature, `ref`, …) is listed in [`ImportedModel::warnings`].
//!
//! Book: §7.11 (trees), §1.5 (joints), §6.2 (mass properties of shapes, parallel axis).

use std::collections::HashMap;
use std::path::Path;

use nalgebra::{Matrix3, Vector3};
use roxmltree::{Document, Node, NodeId};

use super::files::{confined, read_model};
use super::mass::{MassProps, axis_angle, quat};
use super::xml::{Tracked, count_capped, error_at, parse};
use super::{ImportedModel, MAX_INCLUDES, MAX_MODEL_LINKS};
use crate::SceneError;

/// A frame: rotation (columns = its axes) and origin, in some other frame.
type Fr = (Matrix3<f64>, Vector3<f64>);

/// Where an MJCF body's frame is: the body carrying it (`None` = ground) and the frame in
/// that body's link frame; and in the ground at the reference configuration.
#[derive(Clone, Copy)]
struct Place {
    host: Option<usize>,
    local: Fr,
    world: Fr,
}

struct Ctx<'a, 'i> {
    t: Tracked<'a, 'i>,
    docs: &'a [Document<'i>],
    includes: HashMap<(usize, NodeId), usize>,
    degree: bool,
    eulerseq: Vec<char>,
    from_geom: String,
    defaults: HashMap<String, Vec<Node<'a, 'i>>>,
    m: ImportedModel,
    mass: Vec<MassProps>,
    places: HashMap<String, Place>,
    /// `<equality>` children (connect, weld, joint), read once every body is placed.
    pending: Vec<Node<'a, 'i>>,
}

/// Reads an MJCF document (`file` names it in messages; includes are read from `dir`).
///
/// Book: §7.11.
///
/// # Errors
/// [`SceneError::Parse`] at the offending element: malformed XML, more than
/// [`MAX_MODEL_LINKS`] bodies, an include outside `dir`, missing, repeated or beyond
/// [`MAX_INCLUDES`], a repeated body name, an unknown joint or geom type, a free joint below
/// the top level, non-finite numbers, an inertia not positive definite, a body whose mass
/// would come from a mesh.
pub fn load_mjcf(text: &str, file: &str, dir: &Path) -> Result<ImportedModel, SceneError> {
    let mut texts: Vec<(String, String)> = vec![(file.to_string(), text.to_string())];
    let mut includes = HashMap::new();
    let mut bodies = 0;
    let mut k = 0;
    while k < texts.len() {
        bodies += count_capped(&texts[k].1, "<body", MAX_MODEL_LINKS);
        if bodies > MAX_MODEL_LINKS {
            return Err(error_at(
                &texts[k].0,
                (1, 1),
                format!("more than {MAX_MODEL_LINKS} bodies; valid: at most {MAX_MODEL_LINKS}"),
            ));
        }
        let (name_k, text_k) = texts[k].clone();
        let doc = parse(&text_k, &name_k)?;
        let at = |n: Node| {
            let p = doc.text_pos_at(n.range().start);
            (p.row as usize, p.col as usize)
        };
        for n in doc.descendants().filter(|n| n.has_tag_name("include")) {
            let f = n
                .attribute("file")
                .ok_or_else(|| error_at(&name_k, at(n), "<include>: missing attribute `file`"))?;
            let path = confined(dir, f).map_err(|m| error_at(&name_k, at(n), format!("<include>: {m}")))?;
            let shown = path.display().to_string();
            if texts.iter().any(|(name, _)| *name == shown) {
                return Err(error_at(
                    &name_k,
                    at(n),
                    format!("<include>: `{f}` is included twice (or includes itself); valid: each file once"),
                ));
            }
            if texts.len() > MAX_INCLUDES {
                return Err(error_at(
                    &name_k,
                    at(n),
                    format!("<include>: more than {MAX_INCLUDES} included files"),
                ));
            }
            let t = read_model(&path).map_err(|m| error_at(&name_k, at(n), format!("<include>: {m}")))?;
            includes.insert((k, n.id()), texts.len());
            texts.push((shown, t));
        }
        k += 1;
    }
    let docs: Vec<Document> = texts.iter().map(|(f, t)| parse(t, f)).collect::<Result<_, _>>()?;
    let mut t = Tracked::new(&docs[0], file);
    for (d, (f, _)) in docs.iter().zip(&texts).skip(1) {
        t.add(d, f);
    }
    let mut c = Ctx {
        t,
        docs: &docs,
        includes,
        degree: true,
        eulerseq: "xyz".chars().collect(),
        from_geom: "auto".into(),
        defaults: HashMap::new(),
        m: ImportedModel::default(),
        mass: Vec::new(),
        places: HashMap::new(),
        pending: Vec::new(),
    };
    let root = docs[0].root_element();
    if root.tag_name().name() != "mujoco" {
        return Err(c.t.err(root, "the root element is not <mujoco>; valid: an MJCF file"));
    }
    c.t.use_el(root);
    c.m.name = c.t.attr(root, "model").unwrap_or("mujoco").to_string();
    c.read(root)?;
    c.finish()?;
    let mut m = c.m;
    m.warnings = c.t.all_warnings();
    Ok(m)
}

impl<'a, 'i> Ctx<'a, 'i> {
    /// Element children with `<include>`s replaced by the included files' children.
    fn kids(&mut self, n: Node<'a, 'i>) -> Vec<Node<'a, 'i>> {
        let mut out = Vec::new();
        for c in n.children().filter(Node::is_element) {
            let key = (self.t.doc_of(c), c.id());
            match self.includes.get(&key).copied() {
                Some(d) if c.has_tag_name("include") => {
                    self.t.use_el(c);
                    self.t.attr(c, "file");
                    let r = self.docs[d].root_element();
                    self.t.use_el(r);
                    out.extend(self.kids(r));
                }
                _ => out.push(c),
            }
        }
        out
    }

    fn read(&mut self, root: Node<'a, 'i>) -> Result<(), SceneError> {
        let kids = self.kids(root);
        // compiler and defaults first: they change how everything else reads
        for n in &kids {
            match n.tag_name().name() {
                "compiler" => self.compiler(*n)?,
                "default" => self.default(*n, None)?,
                _ => {}
            }
        }
        for n in kids {
            match n.tag_name().name() {
                "option" => {
                    self.t.use_el(n);
                    self.m.timestep = self.t.nums(n, "timestep", Some(1))?.map(|v| v[0]);
                    self.m.gravity = self.t.nums(n, "gravity", Some(3))?.map(|v| [v[0], v[1], v[2]]);
                }
                "worldbody" => self.worldbody(n)?,
                "equality" => self.equality(n)?,
                "asset" => self.t.skip(n, "assets (meshes, textures) are never read for dynamics"),
                "visual" => self.t.skip(n, "appearance is not used for dynamics"),
                _ => {}
            }
        }
        Ok(())
    }

    fn compiler(&mut self, n: Node<'a, 'i>) -> Result<(), SceneError> {
        self.t.use_el(n);
        if let Some(a) = self.t.attr(n, "angle") {
            self.degree = match a {
                "degree" => true,
                "radian" => false,
                _ => return Err(self.t.err(n, format!("angle=\"{a}\"; valid: degree, radian"))),
            };
        }
        if let Some(s) = self.t.attr(n, "eulerseq") {
            if s.len() != 3 || !s.chars().all(|c| "xyzXYZ".contains(c)) {
                return Err(self.t.err(n, format!("eulerseq=\"{s}\"; valid: three of x y z X Y Z")));
            }
            self.eulerseq = s.chars().collect();
        }
        if let Some(g) = self.t.attr(n, "inertiafromgeom") {
            if !["auto", "true", "false"].contains(&g) {
                return Err(self.t.err(n, format!("inertiafromgeom=\"{g}\"; valid: auto, true, false")));
            }
            self.from_geom = g.into();
        }
        Ok(())
    }

    /// A `<default>` element: its class (`main` at the top) and the chain of its ancestors.
    fn default(&mut self, n: Node<'a, 'i>, parent: Option<&str>) -> Result<(), SceneError> {
        self.t.use_el(n);
        let class = match (self.t.attr(n, "class"), parent) {
            (Some(c), _) => c.to_string(),
            (None, None) => "main".into(),
            (None, Some(_)) => return Err(self.t.err(n, "a nested <default> needs `class`")),
        };
        let mut chain = vec![n];
        if let Some(p) = parent {
            chain.extend(self.defaults.get(p).cloned().unwrap_or_default());
        }
        self.defaults.insert(class.clone(), chain);
        for c in self.kids(n) {
            match c.tag_name().name() {
                "default" => self.default(c, Some(&class))?,
                "joint" | "geom" => self.t.use_el(c),
                _ => {}
            }
        }
        Ok(())
    }

    /// The element holding attribute `name` for `n` (itself, else its class's defaults).
    fn provider(&mut self, n: Node<'a, 'i>, name: &str, class: &str) -> Option<Node<'a, 'i>> {
        if n.has_attribute(name) {
            return Some(n);
        }
        let tag = n.tag_name().name();
        let chain = self.defaults.get(class)?.clone();
        chain.iter().find_map(|d| d.children().find(|c| c.has_tag_name(tag) && c.has_attribute(name)))
    }

    fn dnums(
        &mut self,
        n: Node<'a, 'i>,
        name: &str,
        class: &str,
        len: Option<usize>,
    ) -> Result<Option<Vec<f64>>, SceneError> {
        match self.provider(n, name, class) {
            Some(p) => self.t.nums(p, name, len),
            None => Ok(None),
        }
    }

    fn dstr(&mut self, n: Node<'a, 'i>, name: &str, class: &str) -> Option<&'a str> {
        let p = self.provider(n, name, class)?;
        self.t.attr(p, name)
    }

    /// The class of an element: its own `class`, else the inherited `childclass`.
    fn class_of(&mut self, n: Node<'a, 'i>, inherited: &str) -> Result<String, SceneError> {
        match self.t.attr(n, "class") {
            Some(c) if self.defaults.contains_key(c) => Ok(c.into()),
            Some(c) => Err(self.t.err(n, format!("unknown class `{c}`; valid: a <default class>"))),
            None => Ok(inherited.into()),
        }
    }

    fn angle(&self, x: f64) -> f64 {
        if self.degree { x.to_radians() } else { x }
    }

    /// `pos` and one of `quat`, `axisangle`, `euler`, `xyaxes`, `zaxis` of `n`.
    fn frame(&mut self, n: Node<'a, 'i>) -> Result<Fr, SceneError> {
        let p = Vector3::from(self.t.vec3(n, "pos", [0.0; 3])?);
        let mut r = None;
        let set = |r: &mut Option<Matrix3<f64>>, m: Option<Matrix3<f64>>, what: &str, t: &Tracked| {
            if r.is_some() {
                return Err(t.err(n, format!("more than one orientation (`{what}` and another); valid: one")));
            }
            *r = Some(m.ok_or_else(|| t.err(n, format!("`{what}` is degenerate (zero length)")))?);
            Ok(())
        };
        if let Some(q) = self.t.nums(n, "quat", Some(4))? {
            set(&mut r, quat([q[0], q[1], q[2], q[3]]), "quat", &self.t)?;
        }
        if let Some(a) = self.t.nums(n, "axisangle", Some(4))? {
            let m = axis_angle(Vector3::new(a[0], a[1], a[2]), self.angle(a[3]));
            set(&mut r, m, "axisangle", &self.t)?;
        }
        if let Some(e) = self.t.nums(n, "euler", Some(3))? {
            let mut m = Matrix3::identity();
            for (k, ch) in self.eulerseq.clone().iter().enumerate() {
                let axis = match ch.to_ascii_lowercase() {
                    'x' => Vector3::x(),
                    'y' => Vector3::y(),
                    _ => Vector3::z(),
                };
                let rk = axis_angle(axis, self.angle(e[k])).unwrap_or_else(Matrix3::identity);
                m = if ch.is_ascii_lowercase() { m * rk } else { rk * m };
            }
            set(&mut r, Some(m), "euler", &self.t)?;
        }
        if let Some(a) = self.t.nums(n, "xyaxes", Some(6))? {
            let x = Vector3::new(a[0], a[1], a[2]);
            let y = Vector3::new(a[3], a[4], a[5]);
            let m = x.try_normalize(0.0).and_then(|x| {
                let y = (y - x * x.dot(&y)).try_normalize(0.0)?;
                Some(Matrix3::from_columns(&[x, y, x.cross(&y)]))
            });
            set(&mut r, m, "xyaxes", &self.t)?;
        }
        if let Some(z) = self.t.nums(n, "zaxis", Some(3))? {
            set(&mut r, z_to(Vector3::new(z[0], z[1], z[2])), "zaxis", &self.t)?;
        }
        Ok((r.unwrap_or_else(Matrix3::identity), p))
    }
}

/// The smallest rotation taking ẑ to the direction of `z` (MuJoCo's `zaxis`).
fn z_to(z: Vector3<f64>) -> Option<Matrix3<f64>> {
    let z = z.try_normalize(0.0)?;
    let c = Vector3::z().cross(&z);
    let s = c.norm();
    if s < 1e-14 {
        return Some(if z.z > 0.0 {
            Matrix3::identity()
        } else {
            Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, -1.0))
        });
    }
    axis_angle(c / s, s.atan2(z.z))
}

#[path = "mjcf_body.rs"]
mod body;
