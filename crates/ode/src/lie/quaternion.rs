//! The exact quaternion step for constant angular velocity (4.11.17).

use nalgebra::{Matrix4, Vector3, Vector4};

/// q(t + h) = e^{Qh} q(t) for constant body angular velocity ω_B, with
/// Q = ½[[0, −ω_Bᵀ], [ω_B, −ω_B^×]] (4.11.15) and, since Q² = −¼|ω|² I,
/// e^{Qh} = cos(½|ω|h) I₄ + (2 sin(½|ω|h)/|ω|) Q (4.11.17).
///
/// # Conventions
/// q = (η, ε₁, ε₂, ε₃), scalar first (Euler parameters of 𝓡_{B/A}, Hamilton); ω_B are the
/// components of ω_{B/A} in B. Equivalent to `R.compose(&Rotor::exp(h ω⃗_b))` in
/// [`LieGroup`](crate::LieGroup) terms.
///
/// # Degenerate inputs
/// For |ω|h → 0 the factor 2 sin(½|ω|h)/|ω| = h·sinc(½|ω|h) uses its series below 1e-4.
///
/// Book: §4.11, (4.11.13), (4.11.15), (4.11.17).
pub fn quaternion_exact_step(q: &Vector4<f64>, omega_b: &Vector3<f64>, h: f64) -> Vector4<f64> {
    let w = omega_b.norm();
    let x = 0.5 * w * h;
    // 2 sin(x)/|ω| = h·sin(x)/x
    let s = if x.abs() < 1e-4 { h * (1.0 - x * x / 6.0) } else { h * x.sin() / x };
    // Q = ½[[0, −ωᵀ], [ω, −ω^×]]
    let (a, b, c) = (omega_b.x, omega_b.y, omega_b.z);
    #[rustfmt::skip]
    let big_q = Matrix4::new(
        0.0, -a,  -b,  -c,
        a,   0.0,  c,  -b,
        b,  -c,   0.0,  a,
        c,   b,  -a,   0.0,
    ) * 0.5;
    // (4.11.17): e^{Qh} = cos(½|ω|h) I₄ + (2 sin(½|ω|h)/|ω|) Q
    (Matrix4::identity() * x.cos() + big_q * s) * q
}
