//! Angular velocity and attitude rates: Euler-angle rates (10.9.8–9) with an error at
//! gimbal lock, quaternion rates as the singularity-free alternative, and the rates of the
//! flight-path angles μ, γ, η (10.9.17–22) with an error on a vertical flight path.
//!
//! Book: §10.9, (10.9.1), (10.9.8), (10.9.9), (10.9.10)–(10.9.22), (10.9.23); §9.7 (9.7.37);
//! notes ch9-14 §3.
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
/// [`quaternion_rates`] there; [`FlightError::NonFinite`] for NaN/∞ angles or rates, or rates
/// beyond f64::MAX.
pub fn euler_rates<T: Scalar>(euler: &Euler321<T>, pqr: [T; 3]) -> Result<[T; 3], FlightError> {
    let [p, q, r] = pqr;
    let inputs = [euler.psi, euler.theta, euler.phi, p, q, r];
    if !inputs.iter().all(|x| x.re().is_finite()) {
        return Err(FlightError::NonFinite { what: "Euler angles or body rates" });
    }
    let ct = euler.theta.cos();
    // det S = cos Θ: (10.9.9) divides by it
    if ct.re().abs() < GIMBAL_LOCK_TOL {
        return Err(FlightError::GimbalLock { cos_theta: ct.re() });
    }
    let (sp, cp) = (euler.phi.sin(), euler.phi.cos());
    let k = q * sp + r * cp;
    let rates = [p + k * euler.theta.sin() / ct, q * cp - r * sp, k / ct];
    if !rates.iter().all(|x| x.re().is_finite()) {
        return Err(FlightError::NonFinite {
            what: "Euler angle rates (overflow of the body rates / cos Θ)",
        });
    }
    Ok(rates)
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

/// The matrix [î_W|_AC  ĵ_G|_AC  k̂_F|_AC] of (10.9.18), columns (10.9.14)–(10.9.16):
/// ω|_AC = [î_W ĵ_G k̂_F]|_AC [μ̇, γ̇, η̇] + α̇ ĵ_AC|_AC − β̇ k̂_S|_AC (10.9.17); det = cos γ.
///
/// Book: (10.9.14)–(10.9.18).
pub fn wind_angle_rate_matrix<T: Scalar>(alpha: T, beta: T, mu: T, gamma: T) -> Matrix3<T> {
    let (sa, ca) = (alpha.sin(), alpha.cos());
    let (sb, cb) = (beta.sin(), beta.cos());
    let (sm, cm) = (mu.sin(), mu.cos());
    let (sg, cg) = (gamma.sin(), gamma.cos());
    // î_W (10.9.14), ĵ_G (10.9.15), k̂_F (10.9.16), as columns
    Matrix3::new(
        ca * cb,
        sa * sm - ca * sb * cm,
        -(sa * cm + ca * sb * sm) * cg - ca * cb * sg,
        sb,
        cb * cm,
        cb * sm * cg - sb * sg,
        sa * cb,
        -ca * sm - sa * sb * cm,
        (ca * cm - sa * sb * sm) * cg - sa * cb * sg,
    )
}

/// ω|_AC = [P, Q, R] from the rates of the flight-path angles [μ̇, γ̇, η̇] and of the
/// aerodynamic angles α̇, β̇ (10.9.17): the angular velocity as the sum of the five relative
/// angular velocities F_AC/F_S/F_W/F_G/F_F/F_E (10.9.10–11).
///
/// Book: (10.9.10)–(10.9.17).
pub fn body_rates_from_wind_angle_rates<T: Scalar>(
    aero: &crate::AeroAngles<T>,
    path: &crate::FlightPathAngles<T>,
    mu_gamma_eta_dot: [T; 3],
    alpha_dot: T,
    beta_dot: T,
) -> [T; 3] {
    let w = wind_angle_rate_matrix(aero.alpha, aero.beta, path.mu, path.gamma)
        * nalgebra::Vector3::from(mu_gamma_eta_dot);
    let (sa, ca) = (aero.alpha.sin(), aero.alpha.cos());
    // + α̇ ĵ_AC|_AC − β̇ k̂_S|_AC, k̂_S|_AC = [−sin α, 0, cos α] (10.9.13)
    [w[0] + beta_dot * sa, w[1] + alpha_dot, w[2] - beta_dot * ca]
}

/// [μ̇, γ̇, η̇] from ω|_AC = [P, Q, R] and α̇, β̇: (10.9.19) with the columns a, b, c of the
/// inverse written out (10.9.20)–(10.9.22),
/// [μ̇, γ̇, η̇] = [a b c] [P − β̇ sin α, Q − α̇, R + β̇ cos α].
///
/// Book: (10.9.19)–(10.9.22).
///
/// # Errors
/// [`FlightError::VerticalFlightPath`] when |cos γ| < [`GIMBAL_LOCK_TOL`] (the determinant
/// of (10.9.18) is cos γ: heading and bank of the velocity are undefined on a vertical path).
pub fn wind_angle_rates<T: Scalar>(
    aero: &crate::AeroAngles<T>,
    path: &crate::FlightPathAngles<T>,
    pqr: [T; 3],
    alpha_dot: T,
    beta_dot: T,
) -> Result<[T; 3], FlightError> {
    let cg = path.gamma.cos();
    if cg.re().abs() < GIMBAL_LOCK_TOL || !cg.re().is_finite() {
        return Err(FlightError::VerticalFlightPath { cos_gamma: cg.re() });
    }
    let (sa, ca) = (aero.alpha.sin(), aero.alpha.cos());
    let (sb, cb) = (aero.beta.sin(), aero.beta.cos());
    let (sm, cm) = (path.mu.sin(), path.mu.cos());
    let sg = path.gamma.sin();
    let [p, q, r] = pqr;
    let x = [p - beta_dot * sa, q - alpha_dot, r + beta_dot * ca];
    // columns a (10.9.20), b (10.9.21), c (10.9.22), each over cos γ
    let a = [
        -sa * cm * sg + ca * cb * cg - ca * sb * sm * sg,
        (sa * sm - ca * sb * cm) * cg,
        -sa * cm - ca * sb * sm,
    ];
    let b = [sb * cg + cb * sm * sg, cb * cm * cg, cb * sm];
    let c = [
        ca * cm * sg + sa * cb * cg - sa * sb * sm * sg,
        (-ca * sm - sa * sb * cm) * cg,
        ca * cm - sa * sb * sm,
    ];
    Ok([0, 1, 2].map(|i| (a[i] * x[0] + b[i] * x[1] + c[i] * x[2]) / cg))
}
