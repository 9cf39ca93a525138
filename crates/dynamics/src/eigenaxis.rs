//! Euler's equation in eigenaxis (angle-vector) coordinates (book §7.9).
//!
//! With the angle vector Θ⃗_{B/A} (same components in A and B), ω⃗_{B/A}|_B = S(Θ)Θ̇ where
//! S = I + βΘ^× + αΘ^{×2}, α = (θ − sinθ)/θ³, β = (cosθ − 1)/θ² (7.9.1–3): the right Jacobian
//! of SO(3), taken from the kinematics layer with its series branches near θ = 0.

use nalgebra::{Matrix3, Vector3};
use num_dual::Dual64;
use vectrix_kinematics::attitude::{jacobian_right, jacobian_right_inverse};

use crate::DynamicsError;
use crate::error::check_finite;

/// Θ̈ from Euler's equation J ω̇ + ω × Jω = M (7.8.13) with ω = S(Θ)Θ̇ (7.9.1):
/// Θ̈ = S⁻¹(J⁻¹(M − ω×Jω) − Ṡ Θ̇). Components in the body frame B; Ṡ Θ̇ is the exact
/// directional derivative of S along Θ̇ (dual numbers).
///
/// Book: §7.9, (7.9.1)–(7.9.3), (7.8.13).
///
/// # Errors
/// [`DynamicsError::NonFinite`]; [`DynamicsError::SingularMassMatrix`] when J|_B is not
/// positive definite (use [`crate::RigidBody::accelerations`] for thin bodies);
/// [`DynamicsError::Kinematics`] when |Θ| ≥ 2π where S is singular.
pub fn eigenaxis_acceleration(
    j_in_b: &Matrix3<f64>,
    theta: &Vector3<f64>,
    theta_dot: &Vector3<f64>,
    moment_in_b: &Vector3<f64>,
) -> Result<Vector3<f64>, DynamicsError> {
    check_finite(j_in_b.as_slice(), "inertia")?;
    check_finite(theta.as_slice(), "angle vector")?;
    check_finite(theta_dot.as_slice(), "angle-vector rate")?;
    check_finite(moment_in_b.as_slice(), "moment")?;
    // (7.9.1): ω = S(Θ) Θ̇
    let omega = jacobian_right(theta) * theta_dot;
    // Ṡ Θ̇ = d/dε [S(Θ + εΘ̇)] Θ̇
    let th_d: Vector3<Dual64> = theta.zip_map(theta_dot, Dual64::new);
    let s_dot_theta_dot = (jacobian_right(&th_d) * theta_dot.map(Dual64::from)).map(|x| x.eps);
    let chol = j_in_b.cholesky().ok_or_else(|| DynamicsError::SingularMassMatrix {
        detail: "J|_B is not positive definite".into(),
    })?;
    // (7.8.13): ω̇ = J⁻¹(M − ω × Jω)
    let omega_dot = chol.solve(&(moment_in_b - omega.cross(&(j_in_b * omega))));
    let s_inv = jacobian_right_inverse(theta)?;
    let theta_ddot = s_inv * (omega_dot - s_dot_theta_dot);
    // Huge rates (Θ̇ = 1e300) make ω × Jω overflow: a typed error, not ∞ or NaN in Ok.
    if !theta_ddot.iter().all(|x| x.is_finite()) {
        return Err(DynamicsError::Overflow { what: "angle-vector acceleration Θ̈" });
    }
    Ok(theta_ddot)
}
