//! MJCF bodies, joints, mass properties from `<inertial>` or geoms, and `<equality>`.
//!
//! Book: §7.11, §1.5, §6.2.

use nalgebra::{Matrix3, Vector3};
use roxmltree::Node;

use super::{Ctx, Fr, Place};
use crate::SceneError;
use crate::import::mass::{MassProps, check_stated, geom_unit, rows};
use crate::import::{JointLimit, LinkFrame};
use crate::spec::{Attach, BodySpec, JointSpec, LoopSpec, MassSpec};

/// A body of the walk: its element, where its parent's frame is, the inherited class.
type Item<'a, 'i> = (Node<'a, 'i>, Place, String);

impl<'a, 'i> Ctx<'a, 'i> {
    pub(super) fn worldbody(&mut self, w: Node<'a, 'i>) -> Result<(), SceneError> {
        self.t.use_el(w);
        let ground = Place { host: None, local: id(), world: id() };
        let mut stack: Vec<Item> = Vec::new();
        for c in self.kids(w).into_iter().rev() {
            match c.tag_name().name() {
                "body" => stack.push((c, ground, "main".into())),
                "geom" => {
                    self.t.skip(c, "static geometry of the ground (contacts are declared as scene effects)")
                }
                "site" | "camera" | "light" => self.t.skip(c, "not used for dynamics"),
                _ => {}
            }
        }
        while let Some((n, parent, class)) = stack.pop() {
            let kids = self.body(n, parent, &class)?;
            stack.extend(kids.into_iter().rev());
        }
        Ok(())
    }

    /// One `<body>`: its bodies in the scene, its mass, and its child bodies to walk.
    fn body(
        &mut self,
        n: Node<'a, 'i>,
        parent: Place,
        inherited: &str,
    ) -> Result<Vec<Item<'a, 'i>>, SceneError> {
        self.t.use_el(n);
        let name = match self.t.attr(n, "name") {
            Some(s) => s.to_string(),
            None => format!("body{}", self.places.len() + 1),
        };
        crate::source::check_name(&name, "body name", false).map_err(|m| self.t.err(n, m))?;
        if name == "ground" || self.places.contains_key(&name) {
            return Err(self
                .t
                .err(n, format!("body name `{name}` is reserved or repeated; valid: a new name")));
        }
        let childclass = match self.t.attr(n, "childclass") {
            Some(c) if self.defaults.contains_key(c) => c.to_string(),
            Some(c) => return Err(self.t.err(n, format!("unknown childclass `{c}`"))),
            None => inherited.to_string(),
        };
        let (rb, pb) = self.frame(n)?;
        let (rh, ph) = parent.local;
        let (rw, pw) = parent.world;
        let local = (rh * rb, ph + rh * pb);
        let world = (rw * rb, pw + rw * pb);
        let (mut inertial, mut joints, mut geoms, mut children) = (None, Vec::new(), Vec::new(), Vec::new());
        for c in self.kids(n) {
            match c.tag_name().name() {
                "inertial" if inertial.is_none() => inertial = Some(c),
                "joint" | "freejoint" => joints.push(c),
                "geom" => geoms.push(c),
                "body" => children.push(c),
                "site" | "camera" | "light" => self.t.skip(c, "not used for dynamics"),
                _ => {}
            }
        }
        let mp = self.mass_of(n, inertial, &geoms, &childclass)?;
        let here = if joints.is_empty() {
            // welded to the parent: merged into the body carrying it
            if let Some(b) = parent.host {
                self.mass[b] = self.mass[b].merged(&mp.moved(&local.0, &local.1));
            }
            let body = parent.host.map_or("ground".to_string(), |b| self.m.bodies[b].name.clone());
            self.m.frames.push(LinkFrame {
                link: name.clone(),
                body,
                offset: local.1.into(),
                orientation: rows(&local.0),
            });
            Place { host: parent.host, local, world }
        } else {
            self.joints(&name, &joints, parent, local, world, &childclass, mp)?
        };
        self.places.insert(name, here);
        Ok(children.into_iter().map(|c| (c, here, childclass.clone())).collect())
    }

    /// The bodies of a jointed `<body>` (one per joint), returning where its frame is.
    #[allow(clippy::too_many_arguments)]
    fn joints(
        &mut self,
        name: &str,
        joints: &[Node<'a, 'i>],
        parent: Place,
        local: Fr,
        world: Fr,
        class: &str,
        mp: MassProps,
    ) -> Result<Place, SceneError> {
        let mut parent_name = parent.host.map_or("ground".to_string(), |b| self.m.bodies[b].name.clone());
        let mut prev = Vector3::zeros();
        let count = joints.len();
        for (k, j) in joints.iter().enumerate() {
            self.t.use_el(*j);
            let jc = self.class_of(*j, class)?;
            let kind = if j.has_tag_name("freejoint") {
                "free"
            } else {
                self.dstr(*j, "type", &jc).unwrap_or("hinge")
            };
            let jname = self.t.attr(*j, "name").map_or(format!("{name}_joint{}", k + 1), str::to_string);
            let last = k + 1 == count;
            let bname = if last { name.to_string() } else { format!("{name}_j{}", k + 1) };
            let (joint, offset, orient, q) = if kind == "free" {
                if parent.host.is_some() || count > 1 {
                    return Err(self
                        .t
                        .err(*j, "a free joint must be the only joint of a child of <worldbody>"));
                }
                let (rw, pw) = world;
                let u = nalgebra::UnitQuaternion::from_matrix(&rw);
                let q = vec![pw.x, pw.y, pw.z, u.w, u.i, u.j, u.k];
                (JointSpec::Free {}, Vector3::zeros(), Matrix3::identity(), Some(q))
            } else {
                let pos = Vector3::from(
                    self.dnums(*j, "pos", &jc, Some(3))?.map_or([0.0; 3], |v| [v[0], v[1], v[2]]),
                );
                let axis =
                    self.dnums(*j, "axis", &jc, Some(3))?.map_or([0.0, 0.0, 1.0], |v| [v[0], v[1], v[2]]);
                if Vector3::from(axis).norm() == 0.0 {
                    return Err(self.t.err(*j, "zero axis; valid: a nonzero vector"));
                }
                let joint = match kind {
                    "hinge" => JointSpec::Pin { axis },
                    "slide" => JointSpec::Sleeve { axis },
                    "ball" => JointSpec::Ball {},
                    _ => {
                        return Err(self.t.err(
                            *j,
                            format!("unknown joint type `{kind}`; valid: hinge, slide, ball, free"),
                        ));
                    }
                };
                self.limit(*j, &jc, &jname, &bname, kind)?;
                // every link frame of the body sits at its joint's position, turned as the body
                let (off, orient) = if k == 0 {
                    (local.1 + local.0 * pos, local.0)
                } else {
                    (pos - prev, Matrix3::identity())
                };
                prev = pos;
                (joint, off, orient, None)
            };
            let orientation = (orient != Matrix3::identity()).then(|| rows(&orient));
            self.m.bodies.push(BodySpec {
                name: bname.clone(),
                parent: parent_name.clone(),
                joint,
                offset: offset.into(),
                frame: None,
                orientation,
                mass: MassSpec::Massless {},
                com: [0.0; 3],
                q,
                v: None,
            });
            self.m.joint_names.push(jname);
            self.mass.push(MassProps::zero());
            parent_name = bname;
        }
        let b = self.m.bodies.len() - 1;
        // the body's frame in its last link frame: shifted back by the last joint's position
        let shift = -prev;
        self.mass[b] = mp.moved(&Matrix3::identity(), &shift);
        let link = LinkFrame {
            link: name.into(),
            body: name.into(),
            offset: shift.into(),
            orientation: rows(&Matrix3::identity()),
        };
        self.m.frames.push(link);
        Ok(Place { host: Some(b), local: (Matrix3::identity(), shift), world })
    }

    fn limit(
        &mut self,
        j: Node<'a, 'i>,
        jc: &str,
        joint: &str,
        body: &str,
        kind: &str,
    ) -> Result<(), SceneError> {
        let limited = self.dstr(j, "limited", jc);
        let Some(r) = self.dnums(j, "range", jc, Some(2))? else { return Ok(()) };
        if limited == Some("false") {
            return Ok(());
        }
        let k = if kind == "hinge" { self.angle(1.0) } else { 1.0 };
        self.m.limits.push(JointLimit {
            joint: joint.into(),
            body: body.into(),
            range: Some((r[0] * k, r[1] * k)),
            effort: f64::INFINITY,
            velocity: f64::INFINITY,
        });
        Ok(())
    }

    /// Mass properties of a body in its own frame: `<inertial>`, else its geoms'.
    fn mass_of(
        &mut self,
        n: Node<'a, 'i>,
        inertial: Option<Node<'a, 'i>>,
        geoms: &[Node<'a, 'i>],
        class: &str,
    ) -> Result<MassProps, SceneError> {
        let use_geoms = self.from_geom == "true" || (self.from_geom == "auto" && inertial.is_none());
        if let Some(i) = inertial {
            if use_geoms {
                self.t.skip(i, "compiler inertiafromgeom=\"true\" takes the mass from the geoms");
            } else {
                self.t.use_el(i);
                let (r, c) = self.frame(i)?;
                let m = self
                    .t
                    .nums(i, "mass", Some(1))?
                    .ok_or_else(|| self.t.err(i, "missing attribute `mass`"))?[0];
                let j = if let Some(d) = self.t.nums(i, "diaginertia", Some(3))? {
                    Matrix3::from_diagonal(&Vector3::new(d[0], d[1], d[2]))
                } else if let Some(f) = self.t.nums(i, "fullinertia", Some(6))? {
                    Matrix3::new(f[0], f[3], f[4], f[3], f[1], f[5], f[4], f[5], f[2])
                } else {
                    return Err(self.t.err(i, "missing `diaginertia` or `fullinertia`"));
                };
                check_stated(m, &j).map_err(|e| self.t.err(i, e))?;
                for g in geoms {
                    self.t.skip(
                        *g,
                        "the body's mass comes from its <inertial>; geometry is not used for dynamics",
                    );
                }
                return Ok(MassProps { m, c: Vector3::zeros(), j }.moved(&r, &c));
            }
        }
        let mut total = MassProps::zero();
        for g in geoms {
            self.t.use_el(*g);
            let gc = self.class_of(*g, class)?;
            if !use_geoms {
                continue;
            }
            let kind = self.dstr(*g, "type", &gc).unwrap_or("sphere");
            let mut size = self.dnums(*g, "size", &gc, None)?.unwrap_or_default();
            let (mut r, mut p) = self.frame(*g)?;
            if let Some(ft) = self.dnums(*g, "fromto", &gc, Some(6))? {
                let (a, b) = (Vector3::new(ft[0], ft[1], ft[2]), Vector3::new(ft[3], ft[4], ft[5]));
                r = super::z_to(b - a).ok_or_else(|| self.t.err(*g, "`fromto` of zero length"))?;
                p = (a + b) / 2.0;
                let half = (b - a).norm() / 2.0;
                let k = if matches!(kind, "box" | "ellipsoid") { 2 } else { 1 };
                size.resize(size.len().max(k + 1), 0.0);
                size[k] = half;
            }
            if matches!(kind, "mesh" | "hfield" | "sdf") {
                return Err(self.t.err(
                    *g,
                    format!("the body's mass would come from a {kind} geom, which is never read; valid: an <inertial> in the body"),
                ));
            }
            if kind == "plane" {
                continue;
            }
            let (vol, unit) = geom_unit(kind, &size).ok_or_else(|| {
                self.t.err(*g, format!("geom type `{kind}` with size {size:?}; valid: sphere, capsule, cylinder, ellipsoid, box with their sizes"))
            })?;
            let mass = match self.dnums(*g, "mass", &gc, Some(1))? {
                Some(m) => m[0],
                None => vol * self.dnums(*g, "density", &gc, Some(1))?.map_or(1000.0, |d| d[0]),
            };
            if vol.is_nan() || vol <= 0.0 || mass.is_nan() || mass < 0.0 {
                return Err(self
                    .t
                    .err(*g, "zero volume or negative mass; valid: positive sizes and mass ≥ 0"));
            }
            let j = Matrix3::from_diagonal(&(unit * (mass / vol)));
            total = total.merged(&MassProps { m: mass, c: Vector3::zeros(), j }.moved(&r, &p));
        }
        if total.m > 0.0 {
            check_stated(total.m, &total.j)
                .map_err(|e| self.t.err(n, format!("inertia from the geoms: {e}")))?;
        }
        Ok(total)
    }

    pub(super) fn equality(&mut self, e: Node<'a, 'i>) -> Result<(), SceneError> {
        self.t.use_el(e);
        for c in self.kids(e) {
            match c.tag_name().name() {
                "connect" | "weld" | "joint" => self.pending.push(c),
                _ => {}
            }
        }
        Ok(())
    }

    /// `<connect>`: the anchor (body1's frame) is a point of both bodies at the reference
    /// configuration: a ball loop. `<weld>`: the anchor (body2's frame, MuJoCo's convention)
    /// is a point of both, and the bodies keep the relative pose of the reference
    /// configuration: a weld loop (an explicit `relpose` with a nonzero quaternion is not
    /// read, and so is listed in the warnings).
    fn connect(&mut self, c: Node<'a, 'i>, k: usize) -> Result<(), SceneError> {
        self.t.use_el(c);
        let weld = c.has_tag_name("weld");
        let b1 = self.t.req(c, "body1")?.to_string();
        let b2 = self.t.attr(c, "body2").unwrap_or("world").to_string();
        let anchor = Vector3::from(self.t.vec3(c, "anchor", [0.0; 3])?);
        let tag = if weld { "weld" } else { "connect" };
        let name = self.t.attr(c, "name").map_or(format!("{tag}{k}"), str::to_string);
        if weld {
            // relpose "pos quat" with quat = 0 (MuJoCo's default) means the reference pose
            let rel = crate::import::xml::numbers(c.attribute("relpose").unwrap_or("0 1 0 0 0 0 0"))
                .map_err(|m| self.t.err(c, format!("attribute `relpose`: {m}")))?;
            if rel.len() == 7 && rel[3..].iter().all(|x| *x == 0.0) {
                self.t.attr(c, "relpose");
            }
        }
        let place = |s: &Self, b: &str| -> Result<Place, SceneError> {
            if b == "world" {
                return Ok(Place { host: None, local: id(), world: id() });
            }
            s.places.get(b).copied().ok_or_else(|| s.t.err(c, format!("unknown body `{b}`")))
        };
        let (p1, p2) = (place(self, &b1)?, place(self, &b2)?);
        // the anchor in the world, then in the other body's frame
        let (own, other) = if weld { (p2, p1) } else { (p1, p2) };
        let w = own.world.0 * anchor + own.world.1;
        let there = other.world.0.transpose() * (w - other.world.1);
        let (x1, x2) = if weld { (there, anchor) } else { (anchor, there) };
        let at = |s: &Self, p: &Place, x: Vector3<f64>| Attach {
            body: p.host.map_or("ground".to_string(), |b| s.m.bodies[b].name.clone()),
            point: (p.local.0 * x + p.local.1).into(),
        };
        let (a, b) = (at(self, &p1, x1), at(self, &p2, x2));
        if a.body == b.body {
            return Err(self
                .t
                .err(c, format!("`{b1}` and `{b2}` are one rigid body; valid: two bodies that move apart")));
        }
        self.m.loops.push(if weld { LoopSpec::Weld { name, a, b } } else { LoopSpec::Ball { name, a, b } });
        Ok(())
    }

    /// `<joint joint1 joint2 polycoef>`: q₁ = c₀ + c₁ q₂ (MuJoCo's y − y₀ = Σ cₖ (x − x₀)ᵏ
    /// with the reference positions 0) as a coupler loop; a nonlinear polynomial does not map
    /// and the element is left out with a warning.
    fn joint_equality(&mut self, c: Node<'a, 'i>, k: usize) -> Result<(), SceneError> {
        let coef = match c.attribute("polycoef") {
            Some(text) => crate::import::xml::numbers(text)
                .map_err(|m| self.t.err(c, format!("attribute `polycoef`: {m}")))?,
            None => vec![0.0, 1.0, 0.0, 0.0, 0.0],
        };
        if coef.len() != 5 {
            return Err(self.t.err(c, format!("attribute `polycoef` has {} numbers; valid: 5", coef.len())));
        }
        if coef[2..].iter().any(|x| *x != 0.0) {
            self.t.skip(
                c,
                "a nonlinear joint coupling (polycoef c2, c3 or c4 nonzero); only q1 = c0 + c1 q2 maps",
            );
            return Ok(());
        }
        self.t.use_el(c);
        self.t.attr(c, "polycoef");
        let body_of = |s: &mut Self, key: &str| -> Result<Option<String>, SceneError> {
            let Some(j) = s.t.attr(c, key) else { return Ok(None) };
            let i = s.m.joint_names.iter().position(|n| n == j).ok_or_else(|| {
                s.t.err(c, format!("unknown joint `{j}`; valid: a hinge or slide <joint> of this model"))
            })?;
            Ok(Some(s.m.bodies[i].name.clone()))
        };
        let body = body_of(self, "joint1")?.ok_or_else(|| self.t.err(c, "missing attribute `joint1`"))?;
        let leader = body_of(self, "joint2")?;
        let name = self.t.attr(c, "name").map_or(format!("joint{k}"), str::to_string);
        let ratio = if leader.is_some() { coef[1] } else { 1.0 };
        self.m.loops.push(LoopSpec::Coupler { name, body, leader, ratio, offset: coef[0] });
        Ok(())
    }

    /// Mass properties onto the bodies, then the loops (every body placed by now).
    pub(super) fn finish(&mut self) -> Result<(), SceneError> {
        for (k, c) in std::mem::take(&mut self.pending).into_iter().enumerate() {
            if c.has_tag_name("joint") {
                self.joint_equality(c, k + 1)?;
            } else {
                self.connect(c, k + 1)?;
            }
        }
        for (b, mp) in self.mass.iter().enumerate() {
            if mp.m > 0.0 {
                self.m.bodies[b].mass =
                    MassSpec::Value { mass: mp.m, principal: None, matrix: Some(rows(&mp.j)) };
                self.m.bodies[b].com = mp.c.into();
            }
        }
        Ok(())
    }
}

fn id() -> Fr {
    (Matrix3::identity(), Vector3::zeros())
}
