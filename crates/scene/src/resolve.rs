//! Effects and loop-closing joints of a scene file with their names resolved and their numbers
//! checked (signs, unit vectors, restitutions, profiles), and the profiles' values p(t).
//!
//! Book: ch. 6 (force elements), §7.13 (impacts), §4.18 (rolling), §9.11 (loops).

use nalgebra::{Matrix3, Vector3};

use super::SceneError;
use super::build::{At, Body, Effect, Src, angle_dof, v3};
use super::spec::{Attach, EffectSpec, JointSpec, LoopSpec};
use vectrix_dynamics::multibody::Model;

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

type Index<'a> = dyn Fn(&str, &str) -> Result<Option<usize>, SceneError> + 'a;

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
            JointSpec::Pin { .. } | JointSpec::Sleeve { .. } => Ok(i),
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

pub(crate) fn effect(
    e: &EffectSpec,
    path: &str,
    bodies: &[Body],
    index: &Index,
    body_of: &BodyOf,
    src: &Src,
) -> Result<Effect, SceneError> {
    let key = |k: &str| format!("{path}.{k}");
    let at = |a: &Attach, k: &str| -> Result<At, SceneError> {
        Ok((index(&a.body, &format!("{path}.{k}.body"))?, v3(a.point)))
    };
    let dof = |name: &str| -> Result<usize, SceneError> {
        let b = &bodies[body_of(name, &key("body"))?];
        angle_dof(&b.joint).map(|k| b.vi + k).ok_or_else(|| {
            src.invalid(
                key("body"),
                format!(
                    "body `{name}` has no single joint angle; valid: a body on a pin, collar or slot joint"
                ),
            )
        })
    };
    let free = |name: &str, k: &str| -> Result<usize, SceneError> {
        let i = body_of(name, &key(k))?;
        if !matches!(bodies[i].joint, JointSpec::Free {}) || bodies[i].parent.is_some() {
            return Err(src.invalid(
                key(k),
                format!("body `{name}` must be on a free joint to the ground for impacts, rolling and aero effects"),
            ));
        }
        Ok(i)
    };
    // impacts and resting contact act on the sphere alone: it may carry no other body
    let alone = |name: &str, k: &str| -> Result<usize, SceneError> {
        let i = free(name, k)?;
        if let Some(child) = bodies.iter().find(|c| c.parent == Some(i)) {
            return Err(src.invalid(
                key(k),
                format!(
                    "body `{name}` carries body `{}`; valid: a contact's sphere on a free joint that carries no \
                     other body",
                    child.name
                ),
            ));
        }
        Ok(i)
    };
    let restitution = |x: f64| {
        if (0.0..=1.0).contains(&x) {
            Ok(x)
        } else {
            Err(src.invalid(key("restitution"), format!("e = {x}; valid: 0 ≤ e ≤ 1")))
        }
    };
    for (key, p) in e.profiles() {
        p.check(&format!("{path}.{key}"), src)?;
    }
    Ok(match e {
        EffectSpec::UniformGravity { g } => Effect::Uniform { g: v3(*g) },
        EffectSpec::CentralGravity { mu, centre } => {
            Effect::Central { mu: nonneg(*mu, "mu", path, src)?, centre: v3(*centre) }
        }
        EffectSpec::MutualGravitation { g } => Effect::Mutual { g: nonneg(*g, "g", path, src)? },
        EffectSpec::Spring { a, b, k, length } => Effect::Spring {
            a: at(a, "a")?,
            b: at(b, "b")?,
            k: nonneg(*k, "k", path, src)?,
            d: nonneg(*length, "length", path, src)?,
        },
        EffectSpec::Dashpot { a, b, c } => {
            Effect::Dashpot { a: at(a, "a")?, b: at(b, "b")?, c: nonneg(*c, "c", path, src)? }
        }
        EffectSpec::Inerter { a, b, inertance } => Effect::Inerter {
            a: at(a, "a")?,
            b: at(b, "b")?,
            b_in: nonneg(*inertance, "inertance", path, src)?,
        },
        EffectSpec::RotationalSpring { body, kappa, angle } => {
            Effect::RotSpring { dof: dof(body)?, kappa: nonneg(*kappa, "kappa", path, src)?, angle: *angle }
        }
        EffectSpec::RotationalDashpot { body, xi } => {
            Effect::RotDashpot { dof: dof(body)?, xi: nonneg(*xi, "xi", path, src)? }
        }
        EffectSpec::RotationalInerter { body, beta } => {
            Effect::RotInerter { dof: dof(body)?, beta: nonneg(*beta, "beta", path, src)? }
        }
        EffectSpec::Dipoles { dipoles } => Effect::Dipoles {
            list: dipoles
                .iter()
                .enumerate()
                .map(|(k, d)| Ok((body_of(&d.body, &key(&format!("dipoles[{k}].body")))?, v3(d.moment))))
                .collect::<Result<_, SceneError>>()?,
        },
        EffectSpec::Force { at: a, direction, profile } => {
            Effect::Force { at: at(a, "at")?, dir: v3(*direction), profile: profile.clone() }
        }
        EffectSpec::Torque { body, direction, profile } => Effect::Torque {
            body: body_of(body, &key("body"))?,
            dir: v3(*direction),
            profile: profile.clone(),
        },
        EffectSpec::ContactSpheres { a, b, radius_a, radius_b, restitution: e, friction } => {
            if a == b {
                return Err(
                    src.invalid(key("b"), format!("`{b}` is both spheres; valid: two different bodies"))
                );
            }
            Effect::Spheres {
                a: alone(a, "a")?,
                b: alone(b, "b")?,
                ra: nonneg(*radius_a, "radius_a", path, src)?,
                rb: nonneg(*radius_b, "radius_b", path, src)?,
                e: restitution(*e)?,
                mu: nonneg(*friction, "friction", path, src)?,
            }
        }
        EffectSpec::JointStop { body, lower, upper, restitution: e } => {
            let i = body_of(body, &key("body"))?;
            let b = &bodies[i];
            if !matches!(b.joint, JointSpec::Pin { .. } | JointSpec::Sleeve { .. }) {
                return Err(src.invalid(
                    key("body"),
                    format!("body `{body}`'s joint has more than one coordinate; valid: a body on a pin or sleeve joint"),
                ));
            }
            let (lo, hi) = (lower.unwrap_or(f64::NEG_INFINITY), upper.unwrap_or(f64::INFINITY));
            if (lower.is_none() && upper.is_none()) || lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
                return Err(src.invalid(
                    path,
                    format!(
                        "stops {lower:?} and {upper:?}; valid: `lower`, `upper` or both, with lower < upper"
                    ),
                ));
            }
            Effect::JointStop { qi: b.qi, vi: b.vi, lower: lo, upper: hi, e: restitution(*e)? }
        }
        EffectSpec::ContactPlane { body, radius, point, normal, restitution: e, friction } => Effect::Plane {
            body: alone(body, "body")?,
            r: nonneg(*radius, "radius", path, src)?,
            point: v3(*point),
            n: unit(*normal, "normal", path, src)?,
            e: restitution(*e)?,
            mu: nonneg(*friction, "friction", path, src)?,
        },
        EffectSpec::Aero {
            body,
            aircraft,
            rho,
            area,
            chord,
            span,
            coefficients,
            elevator,
            aileron,
            rudder,
        } => {
            let mut ac = super::aero::catalogue(aircraft)
                .ok_or_else(|| src.invalid(key("aircraft"), super::aero::unknown_aircraft(aircraft)))?;
            let positive = |v: &Option<f64>, name: &str, unit: &str| match v {
                Some(x) if !(x.is_finite() && *x > 0.0) => {
                    Err(src.invalid(key(name), format!("{name} = {x} {unit}; valid: a finite number > 0")))
                }
                _ => Ok(*v),
            };
            ac.rho = positive(rho, "rho", "kg/m³")?.unwrap_or(ac.rho);
            ac.geometry.area = positive(area, "area", "m²")?.unwrap_or(ac.geometry.area);
            ac.geometry.chord = positive(chord, "chord", "m")?.unwrap_or(ac.geometry.chord);
            ac.geometry.span = positive(span, "span", "m")?.unwrap_or(ac.geometry.span);
            for (name, &v) in coefficients {
                let at = key(&format!("coefficients.{name}"));
                if !v.is_finite() {
                    return Err(src.invalid(at, format!("{name} = {v}; valid: a finite number")));
                }
                if !super::aero::set_coefficient(&mut ac.coefficients, name, v) {
                    return Err(src.invalid(at, super::aero::unknown_coefficient(name)));
                }
            }
            ac.check().map_err(|e| src.invalid(key("coefficients"), e.to_string()))?;
            Effect::Aero {
                body: free(body, "body")?,
                aircraft: Box::new(ac),
                controls: Box::new([elevator.clone(), aileron.clone(), rudder.clone()]),
            }
        }
        EffectSpec::Thrust { body, profile, angle } => {
            Effect::Thrust { body: body_of(body, &key("body"))?, profile: profile.clone(), angle: *angle }
        }
        EffectSpec::Rolling { body, shape, radius, point, normal } => {
            let disk = match shape.as_str() {
                "disk" => true,
                "sphere" => false,
                s => return Err(src.invalid(key("shape"), format!("shape `{s}`; valid: sphere, disk"))),
            };
            Effect::Rolling {
                body: free(body, "body")?,
                disk,
                r: nonneg(*radius, "radius", path, src)?,
                point: v3(*point),
                n: unit(*normal, "normal", path, src)?,
            }
        }
    })
}
