//! Batched conversions: many rotations per call, in SIMD.
//!
//! One call converts a whole slice, like scipy's `Rotation.from_rotvec(array)` or
//! `Rotation.as_euler(seq)`. The transcendental functions are fdlibm's kernels written without
//! branches (and, for angle vectors with |Θ| ≤ π, the Taylor series of cos h and sin h / h in
//! h²), so the loop runs four rotations per instruction with AVX2 (`vectrix_simd::dispatch!`:
//! detected when the program runs, the portable build on other CPUs, the same bits either
//! way; fused multiply–add only where the build says so, `vectrix_simd::FUSED_LOOPS`).
//! Each element agrees with its one-rotation counterpart
//! ([`Quaternion::from_angle_vector`], [`EulerAngles::from_quaternion`]) to a few ulps: the
//! kernels are within 1 ulp of the platform's `libm` (tested in `vmath`).
//!
//! The rare cases are left to the one-rotation code, element by element, so nothing differs
//! there:
//! - angles beyond the reduction range (|Θ| > 4·10⁵);
//! - a quaternion at exactly η = 0 (which needs the canonical sign);
//! - gimbal lock;
//! - bad input, which becomes an error naming the element
//!   ([`RotationError::AtElement`]).
//!
//! Book: §2.13 (Euler angles, Facts 2.13.3–8), §2.14–2.15 (angle vector and Euler parameters).

use vectrix_tensor::Scalar;

use crate::RotationError;

mod euler;
mod exp;

pub use euler::EulerBatch;

/// Elements per block: the unit of the fast-path choice (all |Θ| ≤ π) and of the rare-element
/// fix-up.
const BLOCK: usize = 64;

/// sin xᵢ and cos xᵢ of many angles at once, in SIMD: for the other layers' loops over many
/// angles (the joint angles of a planar chain, `vectrix-dynamics`), where one [`crate::sin_cos`]
/// per element inside a longer loop would wait on that loop's chain. Each element is exactly
/// what [`crate::sin_cos`] returns (fdlibm's kernels, within 1 ulp; `libm` beyond |x| = 2·10⁵
/// and for NaN or ±∞), with AVX2 when the CPU has it (detected when the program runs) and the
/// portable build otherwise: the same bits either way. [`Scalar::fast_sin_cos_slices`] for
/// `f64`.
///
/// Book: (2.12.17–19), the elementary rotations.
///
/// # Errors
/// [`RotationError::LengthMismatch`] when `sin` or `cos` is not as long as `x` (nothing is
/// written then).
///
/// ```
/// let x = [0.0, 1.0, -2.5, 1e6];
/// let (mut s, mut c) = ([0.0; 4], [0.0; 4]);
/// vectrix_rotation::sin_cos_slices(&x, &mut s, &mut c).unwrap();
/// for k in 0..4 {
///     assert_eq!((s[k], c[k]), vectrix_rotation::sin_cos(x[k]));
/// }
/// ```
pub fn sin_cos_slices(x: &[f64], sin: &mut [f64], cos: &mut [f64]) -> Result<(), RotationError> {
    for out in [sin.len(), cos.len()] {
        if out != x.len() {
            return Err(RotationError::LengthMismatch { input: x.len(), output: out });
        }
    }
    f64::fast_sin_cos_slices(x, sin, cos);
    Ok(())
}

#[cfg(test)]
pub(super) mod tests {
    use nalgebra::Vector3;

    use super::*;

    pub(super) fn xorshift(s: &mut u64) -> f64 {
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        (*s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    }

    /// Blocks of canonical angle vectors (|Θ| ≤ π, the series path), then blocks up to
    /// |Θ| = 40 (the reduced path), then canonical again; 300 is not a multiple of the block.
    pub(super) fn thetas() -> Vec<Vector3<f64>> {
        let mut s = 0x0123_4567_89AB_CDEFu64;
        (0..300)
            .map(|i| {
                let scale = if (128..192).contains(&i) { 40.0 } else { 3.6 };
                let v = Vector3::new(xorshift(&mut s), xorshift(&mut s), xorshift(&mut s)) * scale;
                if scale < 4.0 && v.norm() > core::f64::consts::PI { v * 0.5 } else { v }
            })
            .collect()
    }

    /// Element by element what [`crate::sin_cos`] returns, bit for bit (the dispatch itself is
    /// tested in vectrix-simd), and within an ulp or two of libm.
    #[test]
    fn sin_cos_slices_is_sin_cos_element_by_element() {
        let mut seed = 0x2545_f491_4f6c_dd1d;
        let mut x = vec![0.0, -0.0, 5e-324, 1e-300, 1e-16, 1e-8, 2e5, 2.1e5, 1e300, f64::NAN, f64::INFINITY];
        x.extend((0..257).map(|_| 80.0 * xorshift(&mut seed)));
        let n = x.len();
        let (mut s, mut c) = (vec![0.0; n], vec![0.0; n]);
        sin_cos_slices(&x, &mut s, &mut c).unwrap();
        for k in 0..n {
            let (ws, wc) = crate::sin_cos(x[k]);
            for (got, want) in [(s[k], ws), (c[k], wc)] {
                assert!(got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()), "x = {:e}", x[k]);
            }
            if x[k].is_finite() {
                let (ls, lc) = x[k].sin_cos();
                assert!((s[k] - ls).abs() <= 2.0 * f64::EPSILON * ls.abs().max(f64::MIN_POSITIVE));
                assert!((c[k] - lc).abs() <= 2.0 * f64::EPSILON * lc.abs().max(f64::MIN_POSITIVE));
            }
        }
    }

    /// Outputs of another length are a typed error, and nothing is written.
    #[test]
    fn sin_cos_slices_rejects_other_lengths() {
        let x = [0.5; 5];
        let (mut s, mut c) = ([7.0; 4], [7.0; 5]);
        assert_eq!(
            sin_cos_slices(&x, &mut s, &mut c),
            Err(RotationError::LengthMismatch { input: 5, output: 4 })
        );
        assert_eq!((s, c), ([7.0; 4], [7.0; 5]));
        let (mut s, mut c) = ([7.0; 5], [7.0; 6]);
        assert_eq!(
            sin_cos_slices(&x, &mut s, &mut c),
            Err(RotationError::LengthMismatch { input: 5, output: 6 })
        );
        assert_eq!((s, c), ([7.0; 5], [7.0; 6]));
        assert_eq!(sin_cos_slices(&[], &mut [], &mut []), Ok(()));
    }
}
