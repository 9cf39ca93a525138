//! The log map of an `f64` rotation matrix without a `libm` call: θ / (2 sin θ) from a
//! polynomial in whichever of cos θ, sin θ is well conditioned (the generic code takes asin).
//! A different formula from the generic code, so not its bits: within 4 ε of it (tested below).
//!
//! Book: §2.14 (log map), (2.11.1); notes ch2b §3.5.

use nalgebra::{Matrix3, Vector3};
use vectrix_simd::madd;

use crate::series::canonical_sign;

/// (G(1 − t) − 1)/t for t = 1 − cos φ ∈ [0, 0.3], where G(cos φ) = φ / sin φ = acos(x)/√(1 − x²):
/// degree 10, ascending, the Chebyshev interpolant of mpmath at 50 digits
/// (`mp.chebyfit(H, [0, 0.3], 11)`), G within 0.2 ε with these rounded coefficients. G is
/// analytic but for x ≤ −1, so the series in 1 − x converges fast on x ≥ 1/√2, and every
/// coefficient is positive (no cancellation).
const PHI_OVER_SIN: [f64; 11] = [
    0.3333333333333334,
    0.13333333333323752,
    0.05714285715559279,
    0.025396824738313475,
    0.011544028950451169,
    0.005327738017410276,
    0.002488947053473886,
    0.0011546510294283179,
    0.0006133984328641961,
    0.00012706634161320588,
    0.0002923482308981945,
];

/// φ / sin φ from t = 1 − cos φ, for cos φ ≥ 1/√2 (0 ≤ φ ≤ 45°), by Estrin's scheme (the
/// powers and the pairs independent, a short chain); 1 at t = 0 exactly. `F`: fused
/// multiply–add ([`madd`]; the build's choice, [`vectrix_simd::FUSED`]).
///
/// Book: (2.14.12–15) (the removable singularity of θ / sin θ at 0).
#[inline(always)]
fn phi_over_sin<const F: bool>(t: f64) -> f64 {
    let h = &PHI_OVER_SIN;
    let t2 = t * t;
    let t4 = t2 * t2;
    let t8 = t4 * t4;
    let p = |i: usize| madd::<F>(h[i + 1], t, h[i]);
    let q0 = madd::<F>(p(2), t2, p(0));
    let q1 = madd::<F>(p(6), t2, p(4));
    let q2 = madd::<F>(h[10], t2, p(8));
    let g = madd::<F>(q2, t8, madd::<F>(q1, t4, q0));
    madd::<F>(t, g, 1.0)
}

/// The log map of an `f64` rotation matrix ([`Quaternion::angle_vector_of_rotation_matrix`](crate::Quaternion::angle_vector_of_rotation_matrix)):
/// Θ = (θ / 2 sin θ) v, v = vee(𝓡 − 𝓡ᵀ) = 2 sin θ n̂, with θ / sin θ from [`phi_over_sin`] of
/// whichever of cos θ, sin θ is well conditioned; nearer the half turn than tr 𝓡 = −0.9 the
/// axis from the largest Shepperd pivot, as in the generic code.
///
/// Book: §2.14 (log map), (2.11.1) (vee(𝓡 − 𝓡ᵀ) = 2 sin θ n̂, tr 𝓡 = 1 + 2 cos θ); notes ch2b
/// §3.5.
#[inline(always)]
pub(crate) fn matrix_log<const F: bool>(r: &Matrix3<f64>) -> Vector3<f64> {
    use core::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, PI};
    let tr = r[(0, 0)] + r[(1, 1)] + r[(2, 2)];
    let v = Vector3::new(r[(2, 1)] - r[(1, 2)], r[(0, 2)] - r[(2, 0)], r[(1, 0)] - r[(0, 1)]);
    let c = (tr - 1.0) * 0.5;
    if c > FRAC_1_SQRT_2 {
        // θ < 45°: θ / (2 sin θ) = ½G(cos θ). 1 − c is exact (Sterbenz) and G is flat at 1
        // (G' = 1/3), so the rounding of c barely moves k; no |v|, so nothing underflows.
        return v * (0.5 * phi_over_sin::<F>(1.0 - c));
    }
    let n2 = v.x * v.x + v.y * v.y + v.z * v.z;
    // |v| = 2 sin θ ≥ 0.62 up to 162° (|v|² neither underflows nor overflows); beyond, |v| only
    // scales the correction π − θ, and an underflow there is far below an ulp of π.
    let rv = n2.sqrt();
    if c >= -FRAC_1_SQRT_2 {
        // 45° ≤ θ ≤ 135°: θ = π/2 − asin(cos θ), asin(cos θ) = cos θ·G(sin θ) (φ = π/2 − θ).
        let k = madd::<F>(-c, phi_over_sin::<F>(madd::<F>(-0.5, rv, 1.0)), FRAC_PI_2) / rv;
        return v * k;
    }
    // θ > 135°: θ = π − φ with sin φ = |v|/2, cos φ = −c, so θ / (2 sin θ) = π/|v| − ½G(−c).
    let g = phi_over_sin::<F>(1.0 + c);
    if tr > -0.9 {
        return v * madd::<F>(-0.5, g, PI / rv);
    }
    near_half_turn(r, PI - 0.5 * rv * g)
}

/// The end of [`matrix_log`] beyond 162° (tr 𝓡 ≤ −0.9), kept out of line: θ (from
/// θ = π − ½|v|·G(−cos θ), π exactly at θ = π) times the axis from the largest diagonal pivot
/// (the trace is never the largest there), 4p·q with p the pivot component, whose ε is ∥ n̂
/// with the sign of η·p, as `Quaternion::shepperd_unnormalized` and the generic code.
/// |4p·ε| ≥ 2.2 for a rotation, so |ε|² neither underflows nor overflows.
///
/// Book: §2.15 (2.15.8–10) (the largest pivot); Fact 2.11.5 (the ± at π).
#[cold]
#[inline(never)]
fn near_half_turn(r: &Matrix3<f64>, theta: f64) -> Vector3<f64> {
    let (r11, r22, r33) = (r[(0, 0)], r[(1, 1)], r[(2, 2)]);
    // (4p·η, 4p·ε) for the pivot p = ε₁, ε₂ or ε₃
    let (eta, e) = if r11 >= r22 && r11 >= r33 {
        (
            r[(2, 1)] - r[(1, 2)],
            Vector3::new(1.0 + r11 - r22 - r33, r[(0, 1)] + r[(1, 0)], r[(0, 2)] + r[(2, 0)]),
        )
    } else if r22 >= r33 {
        (
            r[(0, 2)] - r[(2, 0)],
            Vector3::new(r[(0, 1)] + r[(1, 0)], 1.0 + r22 - r11 - r33, r[(1, 2)] + r[(2, 1)]),
        )
    } else {
        (
            r[(1, 0)] - r[(0, 1)],
            Vector3::new(r[(0, 2)] + r[(2, 0)], r[(1, 2)] + r[(2, 1)], 1.0 + r33 - r11 - r22),
        )
    };
    let k = theta / (e.x * e.x + e.y * e.y + e.z * e.z).sqrt();
    if eta > 0.0 {
        e * k
    } else if eta < 0.0 {
        e * -k
    } else {
        // θ = π exactly: ±n̂ describe the same half-turn; the canonical sign (DESIGN §4)
        canonical_sign(e) * k
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Quaternion;

    /// Both builds of the kernel (with and without fused multiply–add; the public function
    /// runs the build's choice, `vectrix_simd::FUSED`) agree with the generic asin code to
    /// 4 ε of max(θ, 1), relatively at tiny angles (a different formula: not bit for bit), on
    /// every side of the switches at 45°, 135° and 162° and at the hard angles 0, 1e-300,
    /// 1e-16, 1e-8, π − 1e-8, π.
    #[test]
    fn f64_matrix_log_matches_the_generic_code_within_4_eps() {
        let pi = core::f64::consts::PI;
        let axes = [
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(1.0, 2.0, 2.0) / 3.0,
            Vector3::new(-0.3, 0.1, 0.95).normalize(),
            Vector3::new(0.0, -1.0, 1e-9).normalize(),
        ];
        let mut angles = vec![0.0, 1e-300, 1e-16, 1e-8, 1e-4, 0.5, 1.5, 2.0, 2.5, 3.0, 3.1];
        for edge in [pi / 4.0, 3.0 * pi / 4.0, 2.8274, pi] {
            angles.extend([edge - 1e-9, edge, edge + 1e-9].into_iter().filter(|t| *t <= pi));
        }
        angles.extend([pi - 1e-4, pi - 1e-8, pi - 1e-12]);
        for n in axes {
            for &th in &angles {
                let r = Quaternion::from_axis_angle(&n, th).unwrap().rotation_matrix();
                let want = Quaternion::angle_vector_of_rotation_matrix_generic(&r);
                let public = Quaternion::angle_vector_of_rotation_matrix(&r);
                let build = matrix_log::<{ vectrix_simd::FUSED }>(&r);
                assert_eq!(public.map(f64::to_bits), build.map(f64::to_bits), "θ = {th:e}");
                for got in [matrix_log::<false>(&r), matrix_log::<true>(&r)] {
                    // at θ = π both ±πn̂ are right
                    let (d, e) = ((got - want).amax(), (got + want).amax());
                    let err = if th == pi { d.min(e) } else { d };
                    let scale = if th < 1e-3 { th } else { th.max(1.0) };
                    assert!(err <= 4.0 * f64::EPSILON * scale, "θ = {th:e}, n = {n:?}: {got:?} vs {want:?}");
                }
            }
        }
    }
}
