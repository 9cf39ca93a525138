//! Gibbs-vector rates (book §4.12).
//!
//! g = ε/η = tan(θ/2)n̂ (undefined at θ = π). Components are the same in A and B (F4.12.1), so
//! ġ is the derivative of those components.

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

/// Body form: ġ = ½(I + ggᵀ + g^×) ω_B (4.12.4; the OCR's left side ω^{B•} is ġ).
///
/// Book: (4.12.4).
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn gibbs_rate_body<T: Scalar>(
    g: &Vector3<T>,
    omega_in_b: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(g, omega_in_b)?;
    Ok((Matrix3::identity() + g * g.transpose() + g.cross_matrix()) * omega_in_b * T::lit(0.5))
}

/// Spatial form (derived in the notes): ġ = ½(I + ggᵀ − g^×) ω_A.
///
/// Book: (4.12.4) with ω_A = 𝓡_{B/A}ω_B.
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn gibbs_rate_spatial<T: Scalar>(
    g: &Vector3<T>,
    omega_in_a: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(g, omega_in_a)?;
    Ok((Matrix3::identity() + g * g.transpose() - g.cross_matrix()) * omega_in_a * T::lit(0.5))
}

/// Inverse, body form: ω_B = 2/(1 + |g|²) (I − g^×) ġ (4.12.5).
///
/// Book: (4.12.5).
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn omega_body_from_gibbs_rate<T: Scalar>(
    g: &Vector3<T>,
    g_dot: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(g, g_dot)?;
    Ok((Matrix3::identity() - g.cross_matrix()) * g_dot * (T::lit(2.0) / (T::one() + g.norm_squared())))
}

/// Inverse, spatial form: ω_A = 2/(1 + |g|²) (I + g^×) ġ.
///
/// Book: (4.12.5) with ω_A = 𝓡_{B/A}ω_B.
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn omega_spatial_from_gibbs_rate<T: Scalar>(
    g: &Vector3<T>,
    g_dot: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(g, g_dot)?;
    Ok((Matrix3::identity() + g.cross_matrix()) * g_dot * (T::lit(2.0) / (T::one() + g.norm_squared())))
}
