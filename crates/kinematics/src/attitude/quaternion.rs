//! Euler-parameter rates (book §4.11): q̇ = ½ E(q) ω_B and its inverse.
//!
//! q = (η, ε) = (a, b, c, d) scalar first (Hamilton), the Euler parameters of 𝓡_{B/A}.
//! Rates are returned as `Vector4` (η̇, ε̇₁, ε̇₂, ε̇₃): a rate is not a unit quaternion.

use nalgebra::{Matrix4, Vector3, Vector4};
use vectrix_rotation::Quaternion;
use vectrix_tensor::Scalar;

use crate::KinematicsError;

fn check<T: Scalar>(xs: &[T], what: &'static str) -> Result<(), KinematicsError> {
    if xs.iter().all(|v| v.re().is_finite()) { Ok(()) } else { Err(KinematicsError::NonFinite { what }) }
}

/// Q(ω_B) = ½[[0, −ω_Bᵀ], [ω_B, −ω_B^×]], with q̇ = Q(ω_B)q (4.11.15).
///
/// Book: (4.11.15).
pub fn quaternion_rate_matrix<T: Scalar>(omega_in_b: &Vector3<T>) -> Matrix4<T> {
    let (x, y, z) = (omega_in_b.x, omega_in_b.y, omega_in_b.z);
    let o = T::zero();
    Matrix4::new(o, -x, -y, -z, x, o, z, -y, y, -z, o, x, z, y, -x, o) * T::lit(0.5)
}

/// Body form: η̇ = −½ε·ω_B, ε̇ = ½(ηω_B + ε×ω_B) (4.11.13).
///
/// Book: F4.11.2, (4.11.13).
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn quaternion_rate_body<T: Scalar>(
    q: &Quaternion<T>,
    omega_in_b: &Vector3<T>,
) -> Result<Vector4<T>, KinematicsError> {
    check(&[q.a, q.b, q.c, q.d, omega_in_b.x, omega_in_b.y, omega_in_b.z], "q or ω")?;
    let (eta, eps) = (q.eta(), q.epsilon());
    let h = T::lit(0.5);
    let ed = (omega_in_b * eta + eps.cross(omega_in_b)) * h;
    crate::finite_or_overflow!(Vector4::new(-eps.dot(omega_in_b) * h, ed.x, ed.y, ed.z), "quaternion rate q̇")
}

/// Spatial form (derived in the notes): η̇ = −½ε·ω_A, ε̇ = ½(ηω_A − ε×ω_A).
///
/// Book: F4.11.3 with ω_A = 𝓡_{B/A}ω_B.
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn quaternion_rate_spatial<T: Scalar>(
    q: &Quaternion<T>,
    omega_in_a: &Vector3<T>,
) -> Result<Vector4<T>, KinematicsError> {
    check(&[q.a, q.b, q.c, q.d, omega_in_a.x, omega_in_a.y, omega_in_a.z], "q or ω")?;
    let (eta, eps) = (q.eta(), q.epsilon());
    let h = T::lit(0.5);
    let ed = (omega_in_a * eta - eps.cross(omega_in_a)) * h;
    crate::finite_or_overflow!(Vector4::new(-eps.dot(omega_in_a) * h, ed.x, ed.y, ed.z), "quaternion rate q̇")
}

/// Inverse, body form: ω_B = 2[[−b, a, d, −c], [−c, −d, a, b], [−d, c, −b, a]] q̇
/// = 2(ηε̇ − η̇ε − ε×ε̇) (4.11.12), for a unit q.
///
/// Book: (4.11.12).
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn omega_body_from_quaternion_rate<T: Scalar>(
    q: &Quaternion<T>,
    q_dot: &Vector4<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(&[q.a, q.b, q.c, q.d, q_dot.x, q_dot.y, q_dot.z, q_dot.w], "q or q̇")?;
    let (eta, eps) = (q.eta(), q.epsilon());
    let (eta_d, eps_d) = (q_dot.x, Vector3::new(q_dot.y, q_dot.z, q_dot.w));
    crate::finite_or_overflow!(
        (eps_d * eta - eps * eta_d - eps.cross(&eps_d)) * T::lit(2.0),
        "ω from the quaternion rate"
    )
}

/// Inverse, spatial form: ω_A = 2(ηε̇ − η̇ε + ε×ε̇).
///
/// Book: (4.11.12) with ω_A = 𝓡_{B/A}ω_B.
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn omega_spatial_from_quaternion_rate<T: Scalar>(
    q: &Quaternion<T>,
    q_dot: &Vector4<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(&[q.a, q.b, q.c, q.d, q_dot.x, q_dot.y, q_dot.z, q_dot.w], "q or q̇")?;
    let (eta, eps) = (q.eta(), q.epsilon());
    let (eta_d, eps_d) = (q_dot.x, Vector3::new(q_dot.y, q_dot.z, q_dot.w));
    crate::finite_or_overflow!(
        (eps_d * eta - eps * eta_d + eps.cross(&eps_d)) * T::lit(2.0),
        "ω from the quaternion rate"
    )
}
