//! Eigenaxis/eigenangle rates (book §4.7): analysis only. Never integrate (n̂, θ): n̂ is
//! undefined at θ = 0 and flips at θ = π (notes ch4-5 §3).
//!
//! n̂ has the same components in A and B; ṅ is the derivative of those components, which is
//! n̂^{A•}|_A = n̂^{B•}|_B (F4.7.2).

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::Scalar;

use crate::KinematicsError;

/// ω_{B/A}|_A = θ̇n̂ + (1 − cos θ)n̂×ṅ + sin θ ṅ (4.7.18).
///
/// Book: F4.7.2, (4.7.18).
pub fn omega_spatial_from_eigenaxis_rates<T: Scalar>(
    theta: T,
    theta_dot: T,
    n: &Vector3<T>,
    n_dot: &Vector3<T>,
) -> Vector3<T> {
    n * theta_dot + n.cross(n_dot) * (T::one() - theta.cos()) + n_dot * theta.sin()
}

/// ω_{B/A}|_B = θ̇n̂ − (1 − cos θ)n̂×ṅ + sin θ ṅ (4.7.19).
///
/// Book: (4.7.19).
pub fn omega_body_from_eigenaxis_rates<T: Scalar>(
    theta: T,
    theta_dot: T,
    n: &Vector3<T>,
    n_dot: &Vector3<T>,
) -> Vector3<T> {
    n * theta_dot - n.cross(n_dot) * (T::one() - theta.cos()) + n_dot * theta.sin()
}

/// α_{B/A}|_A = θ̈n̂ + θ̇[(1 + cos θ)ṅ + sin θ n̂×ṅ] + (1 − cos θ)n̂×n̈ + sin θ n̈ (4.8.1), the
/// derivative of (4.7.18); at θ = 0 it is θ̈n̂ + 2θ̇ṅ (F4.8.1 i).
///
/// Book: (4.8.1), Fact 4.8.1.
pub fn alpha_spatial_from_eigenaxis_rates<T: Scalar>(
    theta: [T; 3],
    n: &Vector3<T>,
    n_dot: &Vector3<T>,
    n_ddot: &Vector3<T>,
) -> Vector3<T> {
    let [th, thd, thdd] = theta;
    let (s, c) = (th.sin(), th.cos());
    n * thdd
        + (n_dot * (T::one() + c) + n.cross(n_dot) * s) * thd
        + n.cross(n_ddot) * (T::one() - c)
        + n_ddot * s
}

/// (θ̇, ṅ) from ω_{B/A}|_A: θ̇ = n̂·ω (4.7.22), ṅ = ½[cot(θ/2)(I − n̂n̂ᵀ) − n̂^×]ω (4.7.29).
///
/// Book: (4.7.22), (4.7.29).
///
/// # Errors
/// [`KinematicsError::SingularRateMap`] at θ = 0 (cot(θ/2) = ∞, n̂ undefined: (4.9.21));
/// [`KinematicsError::NonFinite`]; [`KinematicsError::OutOfRange`] when n̂ is not a unit
/// vector (to 1e-9); [`KinematicsError::Overflow`] when ṅ exceeds f64::MAX (θ near 0).
pub fn eigenaxis_rates_from_omega_spatial<T: Scalar>(
    theta: T,
    n: &Vector3<T>,
    omega_in_a: &Vector3<T>,
) -> Result<(T, Vector3<T>), KinematicsError> {
    rates(theta, n, omega_in_a, -T::one())
}

/// (θ̇, ṅ) from ω_{B/A}|_B: ṅ = ½[cot(θ/2)(I − n̂n̂ᵀ) + n̂^×]ω (4.7.31).
///
/// Book: (4.7.22), (4.7.31).
///
/// # Errors
/// As [`eigenaxis_rates_from_omega_spatial`].
pub fn eigenaxis_rates_from_omega_body<T: Scalar>(
    theta: T,
    n: &Vector3<T>,
    omega_in_b: &Vector3<T>,
) -> Result<(T, Vector3<T>), KinematicsError> {
    rates(theta, n, omega_in_b, T::one())
}

fn rates<T: Scalar>(
    theta: T,
    n: &Vector3<T>,
    w: &Vector3<T>,
    sign: T,
) -> Result<(T, Vector3<T>), KinematicsError> {
    if !(theta.re().is_finite() && n.iter().chain(w.iter()).all(|x| x.re().is_finite())) {
        return Err(KinematicsError::NonFinite { what: "θ, n̂ or ω" });
    }
    // n̂ is the eigenaxis: a unit vector (the rate map below assumes n̂ᵀn̂ = 1).
    let n_len = n.norm().re();
    if (n_len - 1.0).abs() > 1e-9 {
        return Err(KinematicsError::OutOfRange {
            what: "|n̂|",
            value: n_len,
            valid: "1 (n̂ is a unit eigenaxis, to 1e-9)",
        });
    }
    let half_sin = (theta * T::lit(0.5)).sin();
    if half_sin.re() == 0.0 {
        // θ ≡ 0: the eigenaxis is undefined and cot(θ/2) infinite (4.9.21)
        return Err(KinematicsError::SingularRateMap {
            representation: "eigenaxis",
            detail: "θ = 0: n̂ is undefined and cot(θ/2) infinite; use the angle vector or quaternion".into(),
        });
    }
    let cot = (theta * T::lit(0.5)).cos() / half_sin;
    let m = (Matrix3::identity() - n * n.transpose()) * cot + n.cross_matrix() * sign;
    let n_dot = crate::finite_or_overflow!(m * w * T::lit(0.5), "eigenaxis rate ṅ (cot(θ/2) for tiny θ)")?;
    Ok((n.dot(w), n_dot))
}
