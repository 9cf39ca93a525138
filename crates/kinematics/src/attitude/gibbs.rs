//! Gibbs-vector rates (book §4.12).
//!
//! g = ε/η = tan(θ/2)n̂ (undefined at θ = π). Components are the same in A and B (F4.12.1), so
//! ġ is the derivative of those components.

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

use crate::KinematicsError;

fn check<T: Scalar>(x: &Vector3<T>, y: &Vector3<T>) -> Result<(), KinematicsError> {
    if x.iter().chain(y.iter()).all(|v| v.re().is_finite()) {
        Ok(())
    } else {
        Err(KinematicsError::NonFinite { what: "attitude parameters or rates" })
    }
}

/// `Ok(v)` when finite, else [`KinematicsError::Overflow`] (finite inputs, true result beyond
/// f64::MAX).
fn finite<T: Scalar>(v: Vector3<T>, what: &'static str) -> Result<Vector3<T>, KinematicsError> {
    if v.iter().all(|x| x.re().is_finite()) { Ok(v) } else { Err(KinematicsError::Overflow { what }) }
}

/// |g| without overflow or underflow.
fn norm<T: Scalar>(g: &Vector3<T>) -> T {
    let m = g.x.abs().max(g.y.abs()).max(g.z.abs());
    if m == T::zero() { m } else { (g / m).norm() * m }
}

/// 2/(1 + |g|²)(ġ + σ g×ġ) for σ = ±1. For |g| ≤ 1 the plain formula (exact derivatives
/// at g = 0 for dual numbers); above, in terms of r = 1/|g| and ĝ, so that |g|² never
/// overflows: 2r²/(1 + r²) ġ + σ 2r/(1 + r²) ĝ×ġ.
fn inverse_map<T: Scalar>(g: &Vector3<T>, g_dot: &Vector3<T>, sigma: T) -> Vector3<T> {
    let (one, two, n) = (T::one(), T::lit(2.0), norm(g));
    if n.re() <= 1.0 {
        return (g_dot + g.cross(g_dot) * sigma) * (two / (one + n * n));
    }
    let r = one / n;
    let d = one + r * r;
    g_dot * (two * r * r / d) + (g / n).cross(g_dot) * (sigma * two * r / d)
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
    // ½(ω + g(g·ω) + g×ω): g(g·ω) instead of (ggᵀ)ω, which overflows first
    finite((omega_in_b + g * g.dot(omega_in_b) + g.cross(omega_in_b)) * T::lit(0.5), "Gibbs rate ġ")
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
    finite((omega_in_a + g * g.dot(omega_in_a) - g.cross(omega_in_a)) * T::lit(0.5), "Gibbs rate ġ")
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
    // 2/(1 + |g|²)(ġ − g×ġ)
    finite(inverse_map(g, g_dot, -T::one()), "ω from the Gibbs rate")
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
    // 2/(1 + |g|²)(ġ + g×ġ)
    finite(inverse_map(g, g_dot, T::one()), "ω from the Gibbs rate")
}
