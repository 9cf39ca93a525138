//! Angle-vector rates (book §4.9): ω|_A = J_l(Θ)Θ̇, ω|_B = J_r(Θ)Θ̇ and their inverses.
//!
//! Θ = θn̂ is the angle vector of R⃗_{B/A} = exp(Θ⃗^×); its components are the same in A and B,
//! and Θ̇ is the derivative of those components (F4.9.1).
//!
//! J_l = I + a Θ^× + b Θ^{×2},  J_r = I − a Θ^× + b Θ^{×2},
//! J_l⁻¹ = I − ½Θ^× + c Θ^{×2},  J_r⁻¹ = I + ½Θ^× + c Θ^{×2},
//! a = (1 − cos θ)/θ², b = (θ − sin θ)/θ³, c = (2 − θ cot(θ/2))/(2θ²)   (4.9.10–20).
//!
//! Series below θ = 10⁻² (notes ch4-5 §3: the naive b has error 5·10⁻³ at θ = 10⁻⁷):
//! a = ½ − θ²/24 + θ⁴/720, b = 1/6 − θ²/120 + θ⁴/5040, c = 1/12 + θ²/720 + θ⁴/30240.

use core::f64::consts::PI;

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::{Scalar, wrap_angle};

use crate::KinematicsError;

const SERIES_BELOW: f64 = 1e-2;

fn coefficients<T: Scalar>(theta: T) -> (T, T) {
    let t2 = theta * theta;
    if theta.re() < SERIES_BELOW {
        // truncation θ⁶/40320 < 3·10⁻¹⁷ at θ = 10⁻²
        (
            T::lit(0.5) - t2 / T::lit(24.0) + t2 * t2 / T::lit(720.0),
            T::lit(1.0 / 6.0) - t2 / T::lit(120.0) + t2 * t2 / T::lit(5040.0),
        )
    } else {
        // 1 − cos θ = 2 sin²(θ/2): no cancellation
        let s = (theta * T::lit(0.5)).sin();
        (T::lit(2.0) * s * s / t2, (theta - theta.sin()) / (t2 * theta))
    }
}

fn inverse_coefficient<T: Scalar>(theta: T) -> T {
    let t2 = theta * theta;
    if theta.re() < SERIES_BELOW {
        T::lit(1.0 / 12.0) + t2 / T::lit(720.0) + t2 * t2 / T::lit(30240.0)
    } else {
        let h = theta * T::lit(0.5);
        (T::lit(2.0) - theta * h.cos() / h.sin()) / (T::lit(2.0) * t2)
    }
}

fn check<T: Scalar>(x: &Vector3<T>, what: &'static str) -> Result<(), KinematicsError> {
    if x.iter().all(|v| v.re().is_finite()) { Ok(()) } else { Err(KinematicsError::NonFinite { what }) }
}

/// J_l(Θ) = ∫₀¹ exp(τΘ^×)dτ: ω_{B/A}|_A = J_l Θ̇ (4.9.7–10).
///
/// Book: (4.9.7), (4.9.10).
pub fn jacobian_left<T: Scalar>(th: &Vector3<T>) -> Matrix3<T> {
    let mut theta = th.norm();
    if theta.re().is_infinite() {
        // |Θ|² overflowed: scale by the largest component.
        let m = th.x.abs().max(th.y.abs()).max(th.z.abs());
        let s = th / m;
        theta = s.norm() * m;
        if theta.re().is_infinite() && m.re().is_finite() {
            // θ itself beyond f64::MAX (every component near it): the limit θ → ∞ of the
            // bounded coefficients below, (1 − cos θ)/θ → 0 and 1 − sin θ/θ → 1.
            let x = (s / s.norm()).cross_matrix();
            return Matrix3::identity() + x * x;
        }
    }
    if theta.re() < SERIES_BELOW || !theta.re().is_finite() {
        let (a, b) = coefficients(theta);
        let x = th.cross_matrix();
        return Matrix3::identity() + x * a + x * x * b;
    }
    // Large θ in terms of n̂ = Θ/θ, so that Θ^{×2} never overflows (Θ = 1e300 î):
    // J_l = I + (1 − cos θ)/θ n̂^× + (1 − sin θ/θ) n̂^{×2}
    let x = (th / theta).cross_matrix();
    let s = (theta * T::lit(0.5)).sin();
    Matrix3::identity() + x * (T::lit(2.0) * s * s / theta) + x * x * (T::one() - theta.sin() / theta)
}

/// J_r(Θ) = J_l(−Θ) = J_l(Θ)ᵀ: ω_{B/A}|_B = J_r Θ̇ (4.9.11).
///
/// Book: (4.9.11).
pub fn jacobian_right<T: Scalar>(th: &Vector3<T>) -> Matrix3<T> {
    jacobian_left(&(-th))
}

fn checked_inverse_coefficient<T: Scalar>(th: &Vector3<T>) -> Result<T, KinematicsError> {
    check(th, "angle vector Θ")?;
    let theta = th.norm();
    // cot(θ/2) is infinite at θ = 2π: J⁻¹ does not exist there
    if theta.re() >= 2.0 * PI * (1.0 - 1e-9) {
        return Err(KinematicsError::SingularRateMap {
            representation: "angle vector",
            detail: format!(
                "|Θ| = {} is at or beyond 2π where J⁻¹ is singular; rewrap to |Θ| ≤ π first",
                theta.re()
            ),
        });
    }
    Ok(inverse_coefficient(theta))
}

/// J_l⁻¹(Θ) = I − ½Θ^× + cΘ^{×2}: Θ̇ = J_l⁻¹ ω_{B/A}|_A (4.9.16; the OCR misplaces c).
///
/// Book: (4.9.16), (4.9.18–20), F5.5.1 (5.5.72).
///
/// # Errors
/// [`KinematicsError::SingularRateMap`] for |Θ| ≥ 2π (use [`rewrap_angle_vector`]);
/// [`KinematicsError::NonFinite`].
pub fn jacobian_left_inverse<T: Scalar>(th: &Vector3<T>) -> Result<Matrix3<T>, KinematicsError> {
    let c = checked_inverse_coefficient(th)?;
    let x = th.cross_matrix();
    Ok(Matrix3::identity() - x * T::lit(0.5) + x * x * c)
}

/// J_r⁻¹(Θ) = I + ½Θ^× + cΘ^{×2}: Θ̇ = J_r⁻¹ ω_{B/A}|_B (4.9.17).
///
/// Book: (4.9.17).
///
/// # Errors
/// As [`jacobian_left_inverse`].
pub fn jacobian_right_inverse<T: Scalar>(th: &Vector3<T>) -> Result<Matrix3<T>, KinematicsError> {
    let c = checked_inverse_coefficient(th)?;
    let x = th.cross_matrix();
    Ok(Matrix3::identity() + x * T::lit(0.5) + x * x * c)
}

/// Θ̇ from ω_{B/A}|_B (body form).
///
/// Book: (4.9.17).
///
/// # Errors
/// As [`jacobian_left_inverse`], and for non-finite ω.
pub fn angle_vector_rate_body<T: Scalar>(
    th: &Vector3<T>,
    omega_in_b: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(omega_in_b, "ω")?;
    crate::finite_or_overflow!(jacobian_right_inverse(th)? * omega_in_b, "angle-vector rate Θ̇")
}

/// Θ̇ from ω_{B/A}|_A (spatial form).
///
/// Book: (4.9.16).
///
/// # Errors
/// As [`angle_vector_rate_body`].
pub fn angle_vector_rate_spatial<T: Scalar>(
    th: &Vector3<T>,
    omega_in_a: &Vector3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    check(omega_in_a, "ω")?;
    crate::finite_or_overflow!(jacobian_left_inverse(th)? * omega_in_a, "angle-vector rate Θ̇")
}

/// The same rotation with |Θ| ≤ π: Θ ← Θ̂·wrap(|Θ|) (for |Θ| ∈ (π, 3π) this is Θ(1 − 2π/|Θ|),
/// notes ch4-5 §3). Keeps the inverse Jacobians away from their singularity at |Θ| = 2π.
///
/// Book: §4.9 (θ ∈ [0, π]).
pub fn rewrap_angle_vector<T: Scalar>(th: &Vector3<T>) -> Vector3<T> {
    let theta = th.norm();
    // a few ulps above π is π rounded (e.g. |n̂·π| for a unit n̂): leave it, do not flip to −Θ
    if theta.re() <= PI * (1.0 + 4.0 * f64::EPSILON) || !theta.re().is_finite() {
        return *th;
    }
    th * (wrap_angle(theta) / theta)
}
