//! Collisions and impulses (book §7.13–7.14).

use vectrix_statics::{MassProperties, Point};
use vectrix_tensor::Vector;

use crate::rigid::solve_on_range;
use crate::{DynamicsError, RigidBody};

fn check_e(e: f64) -> Result<(), DynamicsError> {
    if (0.0..=1.0).contains(&e) {
        Ok(())
    } else {
        Err(DynamicsError::OutOfRange {
            what: "coefficient of restitution e", value: e, valid: "0 ≤ e ≤ 1"
        })
    }
}

fn check_masses(m1: f64, m2: f64) -> Result<(), DynamicsError> {
    for m in [m1, m2] {
        if !(m.is_finite() && m > 0.0) {
            return Err(DynamicsError::OutOfRange { what: "mass", value: m, valid: "a finite number > 0" });
        }
    }
    Ok(())
}

/// Central (1-D) collision of two particles with restitution e (Fact 7.13.1):
/// u₁⁺ = ((m₁ − e m₂)u₁ + (1 + e)m₂u₂)/(m₁ + m₂), u₂⁺ = ((1 + e)m₁u₁ + (m₂ − e m₁)u₂)/(m₁ + m₂)
/// (7.13.20–21), so that e = (u₂⁺ − u₁⁺)/(u₁ − u₂) (7.13.18) and momentum is conserved.
///
/// Book: §7.13, Fact 7.13.1, (7.13.18)–(7.13.21).
///
/// # Errors
/// [`DynamicsError::OutOfRange`] for e ∉ [0, 1] or masses ≤ 0;
/// [`DynamicsError::NonFinite`]; [`DynamicsError::Overflow`] for speeds beyond f64::MAX;
/// [`DynamicsError::Separating`] when u₁ ≤ u₂ (particle 1,
/// behind, does not catch up with particle 2).
pub fn restitution_1d(m1: f64, m2: f64, u1: f64, u2: f64, e: f64) -> Result<(f64, f64), DynamicsError> {
    crate::error::check_finite(&[m1, m2, u1, u2, e], "collision input")?;
    check_masses(m1, m2)?;
    check_e(e)?;
    if u1 - u2 <= 0.0 {
        return Err(DynamicsError::Separating { approach: u1 - u2 });
    }
    let mb = m1 + m2;
    let after =
        (((m1 - e * m2) * u1 + (1.0 + e) * m2 * u2) / mb, ((1.0 + e) * m1 * u1 + (m2 - e * m1) * u2) / mb);
    if !(after.0.is_finite() && after.1.is_finite()) {
        return Err(DynamicsError::Overflow { what: "speeds after the collision" });
    }
    Ok(after)
}

/// Kinetic energy lost in a central collision, ΔT = ½(1 − e²) m₁m₂/(m₁ + m₂) (u₁ − u₂)².
///
/// Book: (7.13.22) **corrected**: the printed formula lacks the factor ½ (notes ch6-8 errata).
///
/// # Errors
/// [`DynamicsError::OutOfRange`] for a mass that is not finite and > 0 (m₁ = m₂ = 0
/// would be 0/0) or e outside [0, 1]; [`DynamicsError::NonFinite`] for a non-finite speed;
/// [`DynamicsError::Overflow`] when ΔT exceeds the largest finite number.
pub fn collision_energy_loss(m1: f64, m2: f64, u1: f64, u2: f64, e: f64) -> Result<f64, DynamicsError> {
    check_masses(m1, m2)?;
    check_e(e)?;
    if !(u1.is_finite() && u2.is_finite()) {
        return Err(DynamicsError::NonFinite { what: "approach speeds u₁, u₂" });
    }
    // reduced mass m₁m₂/(m₁ + m₂) = m₁/(1 + m₁/m₂): no overflow of m₁m₂ for huge masses
    let mu = m1 / (1.0 + m1 / m2);
    let du = u1 - u2;
    let loss = 0.5 * (1.0 - e * e) * mu * du * du;
    if loss.is_finite() { Ok(loss) } else { Err(DynamicsError::Overflow { what: "energy loss ΔT" }) }
}

/// Collision of two smooth spheres with centres c₁, c₂: the normal components along the line
/// of centres n̂ = r̂_{c₂/c₁} change by (7.13.20–21), the tangential components are unchanged
/// (7.13.9–10). Returns (v⃗₁⁺, v⃗₂⁺).
///
/// Book: §7.13, (7.13.9)–(7.13.21).
///
/// # Errors
/// As [`restitution_1d`]; [`DynamicsError::OutOfRange`] when the centres coincide.
pub fn sphere_collision(
    m1: f64,
    m2: f64,
    c1: &Point,
    c2: &Point,
    v1: &Vector,
    v2: &Vector,
    e: f64,
) -> Result<(Vector, Vector), DynamicsError> {
    if !(c1.is_finite() && c2.is_finite() && v1.is_finite() && v2.is_finite()) {
        return Err(DynamicsError::NonFinite { what: "sphere centres or velocities" });
    }
    let d = c2.position_rel(c1);
    let n = d.unit().ok_or(DynamicsError::OutOfRange {
        what: "distance between centres",
        value: d.norm(),
        valid: "> 0 (distinct centres define the contact normal)",
    })?;
    let (u1, u2) = (v1.dot(&n), v2.dot(&n));
    let (u1p, u2p) = restitution_1d(m1, m2, u1, u2, e)?;
    Ok((*v1 + n * (u1p - u1), *v2 + n * (u2p - u2)))
}

/// Result of a rigid-body impact: the impulse magnitude j along n̂ and the velocities after.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impact {
    /// Impulse j ≥ 0: body 1 receives −j n̂, body 2 receives +j n̂.
    pub impulse: f64,
    /// Body 1 after the impact.
    pub body1: RigidBody,
    /// Body 2 after the impact (unchanged copy of the input when it is immovable ground).
    pub body2: Option<RigidBody>,
}

/// Δv⃗_c and Δω⃗ of a body (at rest or moving) hit by the impulse P⃗ at the point P:
/// m Δv⃗_c = P⃗ (7.14.2), J⃗_{B/c} Δω⃗ = r⃗_{P/c} × P⃗ (7.14.3), solved on the range of J⃗
/// (rank-aware, like [`RigidBody::accelerations`]).
///
/// Book: §7.14, (7.14.2)–(7.14.3).
///
/// # Errors
/// [`DynamicsError::TorqueOnInertAxis`] for an angular impulse about the axis of a thin body;
/// statics errors for invalid inertia.
pub fn impulse_response(
    props: &MassProperties,
    at: &Point,
    impulse: &Vector,
) -> Result<(Vector, Vector), DynamicsError> {
    if !(at.is_finite() && impulse.is_finite()) {
        return Err(DynamicsError::NonFinite { what: "impulse or its point" });
    }
    let r_p_c = at.position_rel(&props.centre_of_mass());
    Ok((*impulse / props.mass(), solve_on_range(props, &r_p_c.cross(impulse))?))
}

/// Impact of two rigid bodies (or of body 1 with immovable ground when `body2` is `None`) at
/// the contact point P with the friction-free normal n̂ (pointing from body 1 to body 2):
/// j = (1 + e) v_approach / (1/m₁ + 1/m₂ + n̂·[(J₁⁻¹(r₁×n̂))×r₁ + (J₂⁻¹(r₂×n̂))×r₂]), the
/// impulse that reverses e times the normal approach speed of the contact points.
/// It reduces to (7.13.20–21) for central impacts.
///
/// Book: §7.13–7.14 generalised (notes ch6-8 §3, "rigid-body generalisation"); (7.14.2)–(7.14.3).
///
/// # Errors
/// [`DynamicsError::OutOfRange`] (e ∉ [0, 1], zero normal),
/// [`DynamicsError::Separating`] when the contact points are not approaching, and the errors
/// of [`impulse_response`].
pub fn rigid_impact(
    body1: &RigidBody,
    body2: Option<&RigidBody>,
    contact: &Point,
    normal: &Vector,
    e: f64,
) -> Result<Impact, DynamicsError> {
    check_e(e)?;
    let n = normal.unit().ok_or(DynamicsError::OutOfRange {
        what: "contact normal length",
        value: normal.norm(),
        valid: "> 0",
    })?;
    let v2 = body2.map_or(Vector::zero(), |b| b.velocity_of(contact));
    let approach = (body1.velocity_of(contact) - v2).dot(&n);
    if !approach.is_finite() {
        return Err(DynamicsError::NonFinite { what: "body velocities" });
    }
    if approach <= 0.0 {
        return Err(DynamicsError::Separating { approach });
    }
    // response of each contact point's normal velocity to a unit impulse
    let unit_response = |b: &RigidBody, sign: f64| -> Result<f64, DynamicsError> {
        let (dv, dw) = impulse_response(&b.props, contact, &(n * sign))?;
        let r = contact.position_rel(&b.props.centre_of_mass());
        Ok((dv + dw.cross(&r)).dot(&n) * sign)
    };
    let mut k = unit_response(body1, -1.0)?;
    if let Some(b2) = body2 {
        k += unit_response(b2, 1.0)?;
    }
    let j = (1.0 + e) * approach / k;
    let apply = |b: &RigidBody, sign: f64| -> Result<RigidBody, DynamicsError> {
        let (dv, dw) = impulse_response(&b.props, contact, &(n * (sign * j)))?;
        Ok(RigidBody::new(b.props, b.v_c + dv, b.omega + dw))
    };
    Ok(Impact { impulse: j, body1: apply(body1, -1.0)?, body2: body2.map(|b| apply(b, 1.0)).transpose()? })
}

/// The centre of percussion R of an impulse along n̂ at P on a body at rest: the body point
/// whose velocity just after the impulse is zero, r⃗_{R/c} = (a⃗ × n̂)/(m|a⃗|²) with
/// a⃗ = J⃗_c⁻¹(r⃗_{P/c} × n̂) (7.14.1).
///
/// Book: §7.14, (7.14.1), Ex 7.14.2–7.14.3.
///
/// # Errors
/// [`DynamicsError::NoPercussionCentre`] when the impulse passes through c (pure translation,
/// a⃗ = 0) or when a⃗·n̂ ≠ 0 (n̂ not along a principal direction: the motion is a screw and
/// no point is at rest); errors of [`impulse_response`].
pub fn centre_of_percussion(
    props: &MassProperties,
    at: &Point,
    normal: &Vector,
) -> Result<Point, DynamicsError> {
    let n = normal.unit().ok_or(DynamicsError::OutOfRange {
        what: "impulse direction length",
        value: normal.norm(),
        valid: "> 0",
    })?;
    let r_p_c = at.position_rel(&props.centre_of_mass());
    let a = solve_on_range(props, &r_p_c.cross(&n))?;
    let scale = r_p_c.norm() / props.inertia_about_centre().norm().max(f64::MIN_POSITIVE);
    if a.norm() <= 1e-12 * scale {
        return Err(DynamicsError::NoPercussionCentre {
            detail: "the impulse passes through the centre of mass",
        });
    }
    if a.dot(&n).abs() > 1e-9 * a.norm() {
        return Err(DynamicsError::NoPercussionCentre {
            detail: "J⁻¹(r_{P/c} × n̂) is not perpendicular to n̂: no body point is at rest after the impulse",
        });
    }
    // r⃗ = (a⃗ × n̂)/(m|a⃗|²) = (â × n̂)/(m|a⃗|): no |a⃗|² overflow or underflow
    let p = props.centre_of_mass().displaced(a.cross(&n) / a.norm() / (props.mass() * a.norm()));
    if !p.is_finite() {
        return Err(DynamicsError::Overflow { what: "centre of percussion" });
    }
    Ok(p)
}
