//! Magnetic dipole pairs (book §6.13): forces equal and opposite but not collinear, and
//! torques that balance only with the moment of the force pair (6.13.19).
//!
//! Gaussian units μ₀/4π = 1 as in the book; multiply forces, torques and potentials by μ₀/4π
//! (and fields by μ₀/4π) for SI.

use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::StaticsError;
use crate::check::{check_vec, finite_or_overflow, unit_sep};

/// The dipole field dyadic 𝒥⃗(r⃗) = (3r̂r̂′ − I⃗)/|r⃗|³ (6.13.8), traceless (divergence-free field).
///
/// Book: (6.13.7)–(6.13.8).
///
/// # Errors
/// [`StaticsError::CoincidentPoints`] for r⃗ = 0⃗.
pub fn dipole_field_dyadic<T: Scalar>(r_z_y: &Vector<T>) -> Result<Dyadic<T>, StaticsError> {
    let (r_hat, len) = unit_sep(r_z_y, "magnetic dipoles")?;
    let d = (r_hat.outer(&r_hat) * T::lit(3.0) - Dyadic::identity()) * (T::one() / (len * len * len));
    if d.is_finite() { Ok(d) } else { Err(StaticsError::Overflow { what: "dipole field 1/|r|³" }) }
}

/// The field of the dipole m⃗_y at z: B⃗_y(r⃗_{z/y}) = (3(r̂·m⃗_y)r̂ − m⃗_y)/|r⃗|³ (6.13.1).
///
/// Book: (6.13.1), (6.13.7).
///
/// # Errors
/// [`StaticsError::CoincidentPoints`]; [`StaticsError::NonFinite`].
pub fn dipole_field<T: Scalar>(m_y: &Vector<T>, r_z_y: &Vector<T>) -> Result<Vector<T>, StaticsError> {
    check_vec(m_y, "dipole moment")?;
    finite_or_overflow(dipole_field_dyadic(r_z_y)?.apply(m_y), "dipole field")
}

/// Forces and torques between the dipoles m⃗_z at z and m⃗_y at y.
///
/// Book: Facts 6.13.1, 6.13.4, 6.13.5.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DipolePair<T: Scalar = f64> {
    /// f⃗_{z/y}, the force on m⃗_z (6.13.11).
    pub force_on_z: Vector<T>,
    /// f⃗_{y/z} = −f⃗_{z/y} (6.13.12).
    pub force_on_y: Vector<T>,
    /// τ⃗_{z/y} = m⃗_z × B⃗_y (6.13.10), (6.13.18).
    pub torque_on_z: Vector<T>,
    /// τ⃗_{y/z} = m⃗_y × B⃗_z.
    pub torque_on_y: Vector<T>,
    /// τ⃗_f = r⃗_{z/y} × f⃗_{z/y} (6.13.22): the moment of the non-collinear force pair.
    pub force_pair_torque: Vector<T>,
}

/// The interaction of dipoles m⃗_z (at z) and m⃗_y (at y), r⃗ = r⃗_{z/y}:
/// f⃗_{z/y} = (3/|r⃗|⁴)[(m⃗_y·r̂)m⃗_z + (m⃗_z·r̂)m⃗_y + (m⃗_z·m⃗_y)r̂ − 5(m⃗_y·r̂)(m⃗_z·r̂)r̂] (6.13.11),
/// τ⃗_{z/y} = [3(r̂·m⃗_y)(m⃗_z × r̂) − m⃗_z × m⃗_y]/|r⃗|³ (6.13.18), and the partners; they satisfy
/// τ⃗_{z/y} + τ⃗_{y/z} + r⃗_{z/y} × f⃗_{z/y} = 0⃗ (6.13.19).
///
/// Book: (6.13.11), (6.13.12), (6.13.18), (6.13.19), (6.13.22).
///
/// # Errors
/// [`StaticsError::CoincidentPoints`] for z = y; [`StaticsError::NonFinite`].
pub fn dipole_interaction<T: Scalar>(
    m_z: &Vector<T>,
    m_y: &Vector<T>,
    r_z_y: &Vector<T>,
) -> Result<DipolePair<T>, StaticsError> {
    check_vec(m_z, "dipole moment m_z")?;
    check_vec(m_y, "dipole moment m_y")?;
    let (r_hat, len) = unit_sep(r_z_y, "magnetic dipoles")?;
    let (a, b) = (m_y.dot(&r_hat), m_z.dot(&r_hat));
    let three = T::lit(3.0);
    // (6.13.11)
    let f = (*m_z * a + *m_y * b + r_hat * (m_z.dot(m_y) - T::lit(5.0) * a * b)) * (three / len.powi(4));
    let inv3 = T::one() / (len * len * len);
    // (6.13.18) and its mirror with r̂_{y/z} = −r̂
    let tau_z = (m_z.cross(&r_hat) * (three * a) - m_z.cross(m_y)) * inv3;
    let tau_y = (m_y.cross(&(-r_hat)) * (-three * b) - m_y.cross(m_z)) * inv3;
    Ok(DipolePair {
        force_on_z: finite_or_overflow(f, "dipole force")?,
        force_on_y: -f,
        torque_on_z: finite_or_overflow(tau_z, "dipole torque")?,
        torque_on_y: finite_or_overflow(tau_y, "dipole torque")?,
        force_pair_torque: finite_or_overflow(r_z_y.cross(&f), "dipole force-pair torque")?,
    })
}

/// Interaction energy U = −m⃗_z·B⃗_y(r⃗_{z/y}), with f⃗_{z/y} = −∂U/∂r⃗_{z/y} (6.13.9).
///
/// Book: (6.13.9); §8.3.
///
/// # Errors
/// As [`dipole_interaction`].
pub fn dipole_potential<T: Scalar>(
    m_z: &Vector<T>,
    m_y: &Vector<T>,
    r_z_y: &Vector<T>,
) -> Result<T, StaticsError> {
    check_vec(m_z, "dipole moment m_z")?;
    let u = -m_z.dot(&dipole_field(m_y, r_z_y)?);
    if u.re().is_finite() { Ok(u) } else { Err(StaticsError::Overflow { what: "dipole potential" }) }
}
