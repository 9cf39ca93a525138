//! Modified-Rodrigues-parameter rates (not in the book; extends §4.12).
//!
//! p = ε/(1 + η) = tan(θ/4)n̂, |p| ≤ 1 with the shadow set −p/|p|² beyond; components are the
//! same in A and B, so ṗ is the derivative of those components.

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::Scalar;

use crate::KinematicsError;

fn check<T: Scalar>(x: &Vector3<T>, y: &Vector3<T>) -> Result<(), KinematicsError> {
    if x.iter().chain(y.iter()).all(|v| v.re().is_finite()) {
        Ok(())
    } else {
        Err(KinematicsError::NonFinite { what: "attitude parameters or rates" })
    }
}

/// MRP body form: ṗ = ¼[(1 − |p|²)I + 2p^× + 2ppᵀ] ω_B (Schaub & Junkins (3.153); not in the
/// book, which stops at Gibbs).
///
/// Book: extends §4.12.
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn mrp_rate_body<T: Scalar>(
    p: &Vector3<T>,
    omega_in_b: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(p, omega_in_b)?;
    let two = T::lit(2.0);
    let m = Matrix3::identity() * (T::one() - p.norm_squared())
        + p.cross_matrix() * two
        + p * p.transpose() * two;
    crate::finite_or_overflow!(m * omega_in_b * T::lit(0.25), "MRP rate ṗ")
}

/// MRP spatial form: ṗ = ¼[(1 − |p|²)I − 2p^× + 2ppᵀ] ω_A.
///
/// Book: extends §4.12.
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn mrp_rate_spatial<T: Scalar>(
    p: &Vector3<T>,
    omega_in_a: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(p, omega_in_a)?;
    let two = T::lit(2.0);
    let m = Matrix3::identity() * (T::one() - p.norm_squared()) - p.cross_matrix() * two
        + p * p.transpose() * two;
    crate::finite_or_overflow!(m * omega_in_a * T::lit(0.25), "MRP rate ṗ")
}

/// MRP inverse, body form: ω_B = 4/(1 + |p|²)² [(1 − |p|²)I − 2p^× + 2ppᵀ] ṗ.
///
/// Book: extends §4.12.
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn omega_body_from_mrp_rate<T: Scalar>(
    p: &Vector3<T>,
    p_dot: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(p, p_dot)?;
    let (two, s) = (T::lit(2.0), T::one() + p.norm_squared());
    let m = Matrix3::identity() * (T::one() - p.norm_squared()) - p.cross_matrix() * two
        + p * p.transpose() * two;
    crate::finite_or_overflow!(m * p_dot * (T::lit(4.0) / (s * s)), "ω from the MRP rate")
}

/// MRP inverse, spatial form: ω_A = 4/(1 + |p|²)² [(1 − |p|²)I + 2p^× + 2ppᵀ] ṗ.
///
/// Book: extends §4.12.
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn omega_spatial_from_mrp_rate<T: Scalar>(
    p: &Vector3<T>,
    p_dot: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(p, p_dot)?;
    let (two, s) = (T::lit(2.0), T::one() + p.norm_squared());
    let m = Matrix3::identity() * (T::one() - p.norm_squared())
        + p.cross_matrix() * two
        + p * p.transpose() * two;
    crate::finite_or_overflow!(m * p_dot * (T::lit(4.0) / (s * s)), "ω from the MRP rate")
}
