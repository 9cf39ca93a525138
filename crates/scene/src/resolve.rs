//! Effects and loop-closing joints of a scene file with their names resolved and their numbers
//! checked (signs, unit vectors, restitutions, profiles), and the profiles' values p(t).
//!
//! Book: ch. 6 (force elements), §7.13 (impacts), §4.18 (rolling), §9.11 (loops).

use nalgebra::{Matrix3, Vector3};

use super::SceneError;
use super::parts::{At, Body, Effect, Src, v3};
use super::spec::{Attach, EffectSpec, LoopSpec};
use vectrix_dynamics::multibody::{Joint, Model};
use vectrix_statics::MutualGravitation;

fn nonneg(x: f64, what: &str, path: &str, src: &Src) -> Result<f64, SceneError> {
    if x >= 0.0 {
        Ok(x)
    } else {
        Err(src.invalid(format!("{path}.{what}"), format!("{what} = {x}; valid: ≥ 0")))
    }
}

fn unit(x: [f64; 3], what: &str, path: &str, src: &Src) -> Result<Vector3<f64>, SceneError> {
    match direction(x) {
        Some((d, n)) if n > 1e-12 => Ok(d),
        _ => Err(src.invalid(format!("{path}.{what}"), format!("{what} is zero; valid: a nonzero vector"))),
    }
}

/// The unit vector along x and |x|, scaled by the largest component first so that the norm
/// of a vector with components near 1e300 does not overflow (|x|² = ∞ made x/|x| = 0⃗, a
/// zero axis that the model, which normalizes by itself, did not share); `None` for 0⃗.
pub(crate) fn direction(x: [f64; 3]) -> Option<(Vector3<f64>, f64)> {
    let v = v3(x);
    let s = v.amax();
    // 0⃗ (s = 0) and a NaN component (s = NaN: a comparison that fails) have no direction
    if s.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    let w = v / s;
    let n = w.norm();
    Some((w / n, s * n))
}

pub(crate) type Index<'a> = dyn Fn(&str, &str) -> Result<Option<usize>, SceneError> + 'a;

/// A loop-closing joint with names resolved and its geometry in the bodies' link frames.
pub(crate) fn loop_joint(
    l: &LoopSpec,
    path: &str,
    index: &Index,
    (model, bodies): (&Model, &[Body]),
    q0: &[f64],
    src: &Src,
) -> Result<super::loops::Loop, SceneError> {
    use super::loops::{Loop, LoopKind, normals};
    let (name, a, b) = match l {
        LoopSpec::Ball { name, a, b }
        | LoopSpec::Pin { name, a, b, .. }
        | LoopSpec::PointOnLine { name, a, b, .. }
        | LoopSpec::PointOnPlane { name, a, b, .. }
        | LoopSpec::Weld { name, a, b } => (name, a, b),
        LoopSpec::Coupler { name, body, leader, ratio, offset } => {
            return coupler(name, (body, leader.as_deref()), (*ratio, *offset), path, index, bodies, src);
        }
    };
    let at = |x: &Attach, k: &str| -> Result<At, SceneError> {
        Ok((index(&x.body, &format!("{path}.{k}.body"))?, v3(x.point)))
    };
    let (a, b) = (at(a, "a")?, at(b, "b")?);
    if a.0.is_none() && b.0.is_none() {
        return Err(
            src.invalid(format!("{path}.a.body"), "both ends are the ground; valid: at least one body")
        );
    }
    if a.0 == b.0 {
        return Err(
            src.invalid(format!("{path}.b.body"), "both ends are the same body; valid: two different bodies")
        );
    }
    let kind = match l {
        LoopSpec::Ball { .. } => LoopKind::Ball,
        LoopSpec::Pin { axis, .. } => {
            let ax = unit(*axis, "axis", path, src)?;
            let (e1_a, e2_a) = normals(&ax);
            // the axis in b's link frame at q₀: 𝓞_{B/G} 𝓞_{A/G}ᵀ axis
            let poses = model.poses(q0).map_err(|e| src.invalid(path, e.to_string()))?;
            let o = |x: Option<usize>| x.map_or_else(Matrix3::identity, |i| poses[i].0);
            let axis_b = o(b.0) * o(a.0).transpose() * ax;
            LoopKind::Pin { e1_a, e2_a, axis_b }
        }
        LoopSpec::PointOnLine { direction, .. } => {
            let (n1_b, n2_b) = normals(&unit(*direction, "direction", path, src)?);
            LoopKind::Line { n1_b, n2_b }
        }
        LoopSpec::PointOnPlane { normal, .. } => LoopKind::Plane { n_b: unit(*normal, "normal", path, src)? },
        LoopSpec::Weld { .. } => {
            // u_b: the a-axes after w (y→z, z→x, x→y) carried into b's link frame at q₀,
            // 𝓞_{B/G} 𝓞_{A/G}ᵀ ê, so that every u_b·w_a is 0 at q₀
            let poses = model.poses(q0).map_err(|e| src.invalid(path, e.to_string()))?;
            let o = |x: Option<usize>| x.map_or_else(Matrix3::identity, |i| poses[i].0);
            let to_b = o(b.0) * o(a.0).transpose();
            let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
            LoopKind::Weld { pairs: [(to_b * y, z), (to_b * z, x), (to_b * x, y)] }
        }
        // (returned above; repeated so that the match needs no panic)
        LoopSpec::Coupler { name, body, leader, ratio, offset } => {
            return coupler(name, (body, leader.as_deref()), (*ratio, *offset), path, index, bodies, src);
        }
    };
    Ok(Loop { name: name.clone(), kind, a, b })
}
/// A coupler with its bodies resolved to joint coordinates: both joints must have one
/// coordinate (pin or sleeve), and differ.
fn coupler(
    name: &str,
    (body, leader): (&str, Option<&str>),
    (ratio, offset): (f64, f64),
    path: &str,
    index: &Index,
    bodies: &[Body],
    src: &Src,
) -> Result<super::loops::Loop, SceneError> {
    use super::loops::{Loop, LoopKind};
    let one_coordinate = |who: &str, key: &str| -> Result<usize, SceneError> {
        let at = format!("{path}.{key}");
        let i = index(who, &at)?.ok_or_else(|| {
            src.invalid(&at, "the ground has no joint; valid: a body on a pin or sleeve joint")
        })?;
        match bodies[i].joint {
            Joint::Pin { .. } | Joint::Sleeve { .. } => Ok(i),
            _ => Err(src.invalid(
                &at,
                format!("body `{who}`'s joint has more than one coordinate; valid: a body on a pin or sleeve joint"),
            )),
        }
    };
    for (x, what) in [(ratio, "ratio"), (offset, "offset")] {
        if !x.is_finite() {
            return Err(
                src.invalid(format!("{path}.{what}"), format!("{what} = {x}; valid: a finite number"))
            );
        }
    }
    let ia = one_coordinate(body, "body")?;
    let lead = match leader {
        Some(l) => {
            let ib = one_coordinate(l, "leader")?;
            if ib == ia {
                return Err(src.invalid(
                    format!("{path}.leader"),
                    "the leader is the body itself; valid: another body (or no leader to lock the joint)",
                ));
            }
            Some(ib)
        }
        None => None,
    };
    let (ba, lead_at) = (&bodies[ia], lead.map(|i| (&bodies[i], i)));
    Ok(Loop {
        name: name.to_string(),
        kind: LoopKind::Coupler {
            qa: ba.qi,
            va: ba.vi,
            lead: lead_at.map(|(b, _)| (b.qi, b.vi)),
            ratio,
            offset,
        },
        a: (Some(ia), Vector3::zeros()),
        b: (lead_at.map(|(_, i)| i), Vector3::zeros()),
    })
}

type BodyOf<'a> = dyn Fn(&str, &str) -> Result<usize, SceneError> + 'a;

/// What resolving one effect needs: its path, the bodies, name lookups and the source.
struct Ctx<'a> {
    path: &'a str,
    bodies: &'a [Body],
    index: &'a Index<'a>,
    body_of: &'a BodyOf<'a>,
    src: &'a Src<'a>,
}

impl Ctx<'_> {
    fn key(&self, k: &str) -> String {
        format!("{}.{k}", self.path)
    }

    /// A point fixed in a body (or the ground) from an `{ body, point }` table at key `k`.
    fn at(&self, a: &Attach, k: &str) -> Result<At, SceneError> {
        Ok(((self.index)(&a.body, &format!("{}.{k}.body", self.path))?, v3(a.point)))
    }

    /// The velocity index of the one joint angle of body `name`.
    fn dof(&self, name: &str) -> Result<usize, SceneError> {
        let b = &self.bodies[(self.body_of)(name, &self.key("body"))?];
        b.joint.angle_index().map(|k| b.vi + k).ok_or_else(|| {
            self.src.invalid(
                self.key("body"),
                format!(
                    "body `{name}` has no single joint angle; valid: a body on a pin, collar or slot joint"
                ),
            )
        })
    }

    /// Body `name` (at key `k`), which must be on a free joint to the ground.
    fn free(&self, name: &str, k: &str) -> Result<usize, SceneError> {
        let i = (self.body_of)(name, &self.key(k))?;
        if !matches!(self.bodies[i].joint, Joint::Free) || self.bodies[i].parent.is_some() {
            return Err(self.src.invalid(
                self.key(k),
                format!("body `{name}` must be on a free joint to the ground for impacts, rolling and aero effects"),
            ));
        }
        Ok(i)
    }

    /// A contact's sphere: free, and carrying no other body (impacts and resting contact act
    /// on the sphere alone).
    fn alone(&self, name: &str, k: &str) -> Result<usize, SceneError> {
        let i = self.free(name, k)?;
        if let Some(child) = self.bodies.iter().find(|c| c.parent == Some(i)) {
            return Err(self.src.invalid(
                self.key(k),
                format!(
                    "body `{name}` carries body `{}`; valid: a contact's sphere on a free joint that carries no \
                     other body",
                    child.name
                ),
            ));
        }
        Ok(i)
    }

    fn restitution(&self, x: f64) -> Result<f64, SceneError> {
        if (0.0..=1.0).contains(&x) {
            Ok(x)
        } else {
            Err(self.src.invalid(self.key("restitution"), format!("e = {x}; valid: 0 ≤ e ≤ 1")))
        }
    }

    fn nonneg(&self, x: f64, what: &str) -> Result<f64, SceneError> {
        nonneg(x, what, self.path, self.src)
    }

    /// Mutual gravitation's pairs (i, j), i < j, each with G mᵢ mⱼ checked here once (a product
    /// past the largest finite number is refused at `g`).
    fn gravitation_pairs(&self, g: f64) -> Result<Vec<(usize, usize, MutualGravitation)>, SceneError> {
        let g = self.nonneg(g, "g")?;
        let n = self.bodies.len();
        let mut pairs = Vec::with_capacity(n * n.saturating_sub(1) / 2);
        for (i, bi) in self.bodies.iter().enumerate() {
            for (j, bj) in self.bodies.iter().enumerate().skip(i + 1) {
                let pair = MutualGravitation::new(g, bi.mass, bj.mass).map_err(|e| {
                    self.src.invalid(self.key("g"), format!("bodies `{}` and `{}`: {e}", bi.name, bj.name))
                })?;
                pairs.push((i, j, pair));
            }
        }
        Ok(pairs)
    }
}

/// One effect of the file with its names resolved and its numbers checked.
pub(crate) fn effect(
    e: &EffectSpec,
    path: &str,
    bodies: &[Body],
    index: &Index,
    body_of: &BodyOf,
    src: &Src,
) -> Result<Effect, SceneError> {
    let c = Ctx { path, bodies, index, body_of, src };
    for (key, p) in e.profiles() {
        p.check(&c.key(key), src)?;
    }
    Ok(match e {
        EffectSpec::UniformGravity { g } => Effect::Uniform { g: v3(*g) },
        EffectSpec::CentralGravity { mu, centre } => {
            Effect::Central { mu: c.nonneg(*mu, "mu")?, centre: v3(*centre) }
        }
        EffectSpec::MutualGravitation { g } => Effect::Mutual { pairs: c.gravitation_pairs(*g)? },
        EffectSpec::Spring { a, b, k, length } => Effect::Spring {
            a: c.at(a, "a")?,
            b: c.at(b, "b")?,
            k: c.nonneg(*k, "k")?,
            d: c.nonneg(*length, "length")?,
        },
        EffectSpec::Dashpot { a, b, c: damping } => {
            Effect::Dashpot { a: c.at(a, "a")?, b: c.at(b, "b")?, c: c.nonneg(*damping, "c")? }
        }
        EffectSpec::Inerter { a, b, inertance } => {
            Effect::Inerter { a: c.at(a, "a")?, b: c.at(b, "b")?, b_in: c.nonneg(*inertance, "inertance")? }
        }
        EffectSpec::RotationalSpring { body, kappa, angle } => {
            Effect::RotSpring { dof: c.dof(body)?, kappa: c.nonneg(*kappa, "kappa")?, angle: *angle }
        }
        EffectSpec::RotationalDashpot { body, xi } => {
            Effect::RotDashpot { dof: c.dof(body)?, xi: c.nonneg(*xi, "xi")? }
        }
        EffectSpec::RotationalInerter { body, beta } => {
            Effect::RotInerter { dof: c.dof(body)?, beta: c.nonneg(*beta, "beta")? }
        }
        EffectSpec::Dipoles { dipoles } => Effect::Dipoles {
            list: dipoles
                .iter()
                .enumerate()
                .map(|(k, d)| Ok((body_of(&d.body, &c.key(&format!("dipoles[{k}].body")))?, v3(d.moment))))
                .collect::<Result<_, SceneError>>()?,
        },
        EffectSpec::Force { at: a, direction, profile } => {
            Effect::Force { at: c.at(a, "at")?, dir: v3(*direction), profile: profile.clone() }
        }
        EffectSpec::Torque { body, direction, profile } => Effect::Torque {
            body: body_of(body, &c.key("body"))?,
            dir: v3(*direction),
            profile: profile.clone(),
        },
        EffectSpec::ContactSpheres { a, b, radius_a, radius_b, restitution: e, friction } => {
            if a == b {
                return Err(
                    src.invalid(c.key("b"), format!("`{b}` is both spheres; valid: two different bodies"))
                );
            }
            Effect::Spheres {
                a: c.alone(a, "a")?,
                b: c.alone(b, "b")?,
                ra: c.nonneg(*radius_a, "radius_a")?,
                rb: c.nonneg(*radius_b, "radius_b")?,
                e: c.restitution(*e)?,
                mu: c.nonneg(*friction, "friction")?,
            }
        }
        EffectSpec::JointStop { body, lower, upper, restitution: e } => {
            joint_stop(&c, body, (*lower, *upper), *e)?
        }
        EffectSpec::ContactPlane { body, radius, point, normal, restitution: e, friction } => Effect::Plane {
            body: c.alone(body, "body")?,
            r: c.nonneg(*radius, "radius")?,
            point: v3(*point),
            n: unit(*normal, "normal", path, src)?,
            e: c.restitution(*e)?,
            mu: c.nonneg(*friction, "friction")?,
        },
        EffectSpec::Aero { .. } => aero(&c, e)?,
        EffectSpec::Thrust { body, profile, angle } => {
            Effect::Thrust { body: body_of(body, &c.key("body"))?, profile: profile.clone(), angle: *angle }
        }
        EffectSpec::Rolling { body, shape, radius, point, normal } => {
            let disk = match shape.as_str() {
                "disk" => true,
                "sphere" => false,
                s => return Err(src.invalid(c.key("shape"), format!("shape `{s}`; valid: sphere, disk"))),
            };
            Effect::Rolling {
                body: c.free(body, "body")?,
                disk,
                r: c.nonneg(*radius, "radius")?,
                point: v3(*point),
                n: unit(*normal, "normal", path, src)?,
            }
        }
    })
}

/// A joint stop on a pin or sleeve: `lower`, `upper` or both, lower < upper.
fn joint_stop(
    c: &Ctx,
    body: &str,
    (lower, upper): (Option<f64>, Option<f64>),
    e: f64,
) -> Result<Effect, SceneError> {
    let b = &c.bodies[(c.body_of)(body, &c.key("body"))?];
    if !matches!(b.joint, Joint::Pin { .. } | Joint::Sleeve { .. }) {
        return Err(c.src.invalid(
            c.key("body"),
            format!(
                "body `{body}`'s joint has more than one coordinate; valid: a body on a pin or sleeve joint"
            ),
        ));
    }
    let (lo, hi) = (lower.unwrap_or(f64::NEG_INFINITY), upper.unwrap_or(f64::INFINITY));
    if (lower.is_none() && upper.is_none()) || lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
        return Err(c.src.invalid(
            c.path,
            format!("stops {lower:?} and {upper:?}; valid: `lower`, `upper` or both, with lower < upper"),
        ));
    }
    Ok(Effect::JointStop { qi: b.qi, vi: b.vi, lower: lo, upper: hi, e: c.restitution(e)? })
}

/// An aircraft's aerodynamics on a free body: the catalogue's aircraft with the file's
/// overrides (ρ, reference area, chord, span, coefficients) and its control profiles.
fn aero(c: &Ctx, e: &EffectSpec) -> Result<Effect, SceneError> {
    let EffectSpec::Aero { body, aircraft, rho, area, chord, span, coefficients, elevator, aileron, rudder } =
        e
    else {
        return Err(c.src.invalid(c.path, "an aero effect was expected here"));
    };
    let src = c.src;
    let mut ac = super::aero::catalogue(aircraft)
        .ok_or_else(|| src.invalid(c.key("aircraft"), super::aero::unknown_aircraft(aircraft)))?;
    let positive = |v: &Option<f64>, name: &str, unit: &str| match v {
        Some(x) if !(x.is_finite() && *x > 0.0) => {
            Err(src.invalid(c.key(name), format!("{name} = {x} {unit}; valid: a finite number > 0")))
        }
        _ => Ok(*v),
    };
    ac.rho = positive(rho, "rho", "kg/m³")?.unwrap_or(ac.rho);
    ac.geometry.area = positive(area, "area", "m²")?.unwrap_or(ac.geometry.area);
    ac.geometry.chord = positive(chord, "chord", "m")?.unwrap_or(ac.geometry.chord);
    ac.geometry.span = positive(span, "span", "m")?.unwrap_or(ac.geometry.span);
    for (name, &v) in coefficients {
        let at = c.key(&format!("coefficients.{name}"));
        if !v.is_finite() {
            return Err(src.invalid(at, format!("{name} = {v}; valid: a finite number")));
        }
        if !super::aero::set_coefficient(&mut ac.coefficients, name, v) {
            return Err(src.invalid(at, super::aero::unknown_coefficient(name)));
        }
    }
    ac.check().map_err(|e| src.invalid(c.key("coefficients"), e.to_string()))?;
    Ok(Effect::Aero {
        body: c.free(body, "body")?,
        aircraft: Box::new(ac),
        controls: Box::new([elevator.clone(), aileron.clone(), rudder.clone()]),
    })
}
