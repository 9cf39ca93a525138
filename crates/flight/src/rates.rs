//! Angular velocity and attitude rates: Euler-angle rates (10.9.8–9) with an error at
//! gimbal lock, and quaternion rates as the singularity-free alternative.
//!
//! Book: §10.9, (10.9.1), (10.9.8), (10.9.9), (10.9.23); §9.7 (9.7.37); notes ch9-14 §3.
//!
//! # Conventions
//! ω⃗_{AC/E}|_AC = [P, Q, R]. The quaternion is q_{AC/E} = (η, ε) Hamilton, scalar first, with
//! 𝓡_{AC/E} = 𝓞_{AC/E}ᵀ its rotation matrix.

use nalgebra::Matrix3;
use vectrix_tensor::Scalar;

use crate::{Euler321, FlightError};

/// |cos Θ| below which Euler-angle rates are refused (Θ within ≈ 1e-8 rad of ±90°).
pub const GIMBAL_LOCK_TOL: f64 = 1e-8;

/// S(Φ, Θ) with ω|_AC = S [Φ̇, Θ̇, Ψ̇]: S = [[1, 0, −sΘ], [0, cΦ, cΘsΦ], [0, −sΦ, cΘcΦ]] (10.9.8),
/// det S = cos Θ.
///
/// Book: (10.9.8), (9.3.23).
pub fn euler_rate_matrix<T: Scalar>(phi: T, theta: T) -> Matrix3<T> {
    let (sp, cp) = (phi.sin(), phi.cos());
    let (st, ct) = (theta.sin(), theta.cos());
    let (z, one) = (T::zero(), T::one());
    Matrix3::new(one, z, -st, z, cp, ct * sp, z, -sp, ct * cp)
}

/// ω|_AC = [P, Q, R] from the attitude and the rates [Φ̇, Θ̇, Ψ̇] (10.9.8).
///
/// Book: (10.9.8).
pub fn body_rates<T: Scalar>(euler: &Euler321<T>, rates: [T; 3]) -> [T; 3] {
    let w = euler_rate_matrix(euler.phi, euler.theta) * nalgebra::Vector3::from(rates);
    [w[0], w[1], w[2]]
}

/// [Φ̇, Θ̇, Ψ̇] from [P, Q, R] (10.9.9): Φ̇ = P + (Q sΦ + R cΦ) tan Θ, Θ̇ = Q cΦ − R sΦ,
/// Ψ̇ = (Q sΦ + R cΦ) sec Θ. ((11.4.2) orders the rates [Ψ̇, Θ̇, Φ̇]: a typo.)
///
/// Book: (10.9.9).
///
/// # Errors
/// [`FlightError::GimbalLock`] when |cos Θ| < [`GIMBAL_LOCK_TOL`]: use
/// [`quaternion_rates`] there.
pub fn euler_rates<T: Scalar>(euler: &Euler321<T>, pqr: [T; 3]) -> Result<[T; 3], FlightError> {
    let [p, q, r] = pqr;
    let ct = euler.theta.cos();
    // det S = cos Θ: (10.9.9) divides by it
    if ct.re().abs() < GIMBAL_LOCK_TOL || !ct.re().is_finite() {
        return Err(FlightError::GimbalLock { cos_theta: ct.re() });
    }
    let (sp, cp) = (euler.phi.sin(), euler.phi.cos());
    let k = q * sp + r * cp;
    Ok([p + k * euler.theta.sin() / ct, q * cp - r * sp, k / ct])
}

/// q̇ = ½ q ⊗ (0, ω|_AC) for q = q_{AC/E} (Hamilton, scalar first): the singularity-free
/// alternative to (10.9.9), equivalent to (9.7.37).
///
/// Book: (9.7.37); §10.9 (alternative at Θ = ±90°).
pub fn quaternion_rates<T: Scalar>(q: [T; 4], pqr: [T; 3]) -> [T; 4] {
    let half = T::lit(0.5);
    let [q0, q1, q2, q3] = q;
    let [p, qq, r] = pqr;
    [
        half * (-q1 * p - q2 * qq - q3 * r),
        half * (q0 * p + q2 * r - q3 * qq),
        half * (q0 * qq + q3 * p - q1 * r),
        half * (q0 * r + q1 * qq - q2 * p),
    ]
}

/// q_{AC/E} of 3-2-1 angles: q = q₃(Ψ) ⊗ q₂(Θ) ⊗ q₁(Φ) (body-axis sequence).
///
/// Book: §10.3 (3-2-1 sequence); Euler parameters §2.15.
pub fn quaternion_from_euler321<T: Scalar>(e: &Euler321<T>) -> [T; 4] {
    let half = T::lit(0.5);
    let (sy, cy) = ((e.psi * half).sin(), (e.psi * half).cos());
    let (sp, cp) = ((e.theta * half).sin(), (e.theta * half).cos());
    let (sr, cr) = ((e.phi * half).sin(), (e.phi * half).cos());
    [
        cr * cp * cy + sr * sp * sy,
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
    ]
}

/// 𝓞_{AC/E} of a unit quaternion q_{AC/E} (the transpose of its rotation matrix).
///
/// Book: §2.15; (10.3.16).
pub fn orientation_from_quaternion<T: Scalar>(q: [T; 4]) -> Matrix3<T> {
    let [w, x, y, z] = q;
    let (one, two) = (T::one(), T::lit(2.0));
    let r = Matrix3::new(
        one - two * (y * y + z * z),
        two * (x * y - w * z),
        two * (x * z + w * y),
        two * (x * y + w * z),
        one - two * (x * x + z * z),
        two * (y * z - w * x),
        two * (x * z - w * y),
        two * (y * z + w * x),
        one - two * (x * x + y * y),
    );
    r.transpose()
}
