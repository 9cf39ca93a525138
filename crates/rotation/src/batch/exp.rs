//! The exponential map of many angle vectors at once ([`Quaternion::from_angle_vectors`]).
//!
//! Book: §2.14 (2.14.3), §2.15 (2.15.5–6).

use nalgebra::Vector3;
use vectrix_simd::vmath::{HALF_PI_SQUARED, SIN_COS_MAX, cos_sinc_of_square, sin_cos};
use vectrix_simd::{FUSED_LOOPS, madd};

use super::BLOCK;
use crate::series::all_finite;
use crate::{Quaternion, RotationError};

vectrix_simd::dispatch! {
    fn exp_simd(thetas: &[Vector3<f64>], out: &mut [Quaternion<f64>]) -> Result<(), RotationError> =
        exp_all::<FUSED_LOOPS>;
}

vectrix_simd::dispatch! {
    fn exp_vec_simd(thetas: &[Vector3<f64>], out: &mut Vec<Quaternion<f64>>) -> Result<(), RotationError> =
        exp_vec::<FUSED_LOOPS>;
}

impl Quaternion<f64> {
    /// The exponential map of many angle vectors at once: q = (cos(θ/2), sin(θ/2) n̂) for
    /// each Θ = θn̂, canonical (η ≥ 0), in SIMD. Element by element it agrees with
    /// [`Quaternion::from_angle_vector`] to a few ulps; scipy's `Rotation.from_rotvec(array)`
    /// is the peer.
    ///
    /// Book: §2.14 (2.14.3), §2.15 (2.15.5–6).
    ///
    /// # Errors
    /// [`RotationError::AtElement`] wrapping [`RotationError::NonFinite`] for the first angle
    /// vector with a NaN or infinite component.
    ///
    /// ```
    /// use nalgebra::Vector3;
    /// use vectrix_rotation::Quaternion;
    ///
    /// let thetas = [Vector3::new(0.0, 0.0, std::f64::consts::FRAC_PI_2), Vector3::zeros()];
    /// let qs = Quaternion::from_angle_vectors(&thetas)?;
    /// assert!((qs[0].a - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-16);
    /// assert_eq!(qs[1], Quaternion::identity());
    /// # Ok::<(), vectrix_rotation::RotationError>(())
    /// ```
    #[doc(alias = "from_rotvec")]
    pub fn from_angle_vectors(thetas: &[Vector3<f64>]) -> Result<Vec<Self>, RotationError> {
        let mut out = Vec::with_capacity(thetas.len());
        exp_vec_simd(thetas, &mut out)?;
        Ok(out)
    }

    /// [`Quaternion::from_angle_vectors`] into a buffer the caller owns (no allocation).
    ///
    /// Book: §2.14, §2.15.
    ///
    /// # Errors
    /// [`RotationError::LengthMismatch`] when `out.len() != thetas.len()`; otherwise as
    /// [`Quaternion::from_angle_vectors`] (on error `out` holds partial results).
    pub fn from_angle_vectors_into(thetas: &[Vector3<f64>], out: &mut [Self]) -> Result<(), RotationError> {
        if out.len() != thetas.len() {
            return Err(RotationError::LengthMismatch { input: thetas.len(), output: out.len() });
        }
        exp_simd(thetas, out)
    }
}

/// One lane of the exponential map: the canonical quaternion and whether the lane is rare
/// (|Θ|/2 beyond the reduction range, non-finite, or η = 0 exactly).
#[inline(always)]
fn exp_lane<const F: bool>(x: f64, y: f64, z: f64) -> ((f64, f64, f64, f64), bool) {
    let h = 0.5 * madd::<F>(x, x, madd::<F>(y, y, z * z)).sqrt();
    let (s, c) = sin_cos::<F>(h);
    // ½ sin(h)/h → ½ at h = 0 (and below 1e-154, where h² underflows, sin h = h).
    let k = if h == 0.0 { 0.5 } else { 0.5 * s / h };
    // Canonical sign η ≥ 0 (η = 0 exactly goes to the one-rotation code).
    let k = if c < 0.0 { -k } else { k };
    ((c.abs(), x * k, y * k, z * k), h.is_nan() | (h > SIN_COS_MAX) | (c == 0.0))
}

/// u = |Θ|²/4 = h².
#[inline(always)]
fn half_angle_squared<const F: bool>(v: &Vector3<f64>) -> f64 {
    0.25 * madd::<F>(v.x, v.x, madd::<F>(v.y, v.y, v.z * v.z))
}

/// The exponential map over all blocks (see [`Quaternion::from_angle_vectors`]).
#[inline(always)]
fn exp_all<const F: bool>(thetas: &[Vector3<f64>], out: &mut [Quaternion<f64>]) -> Result<(), RotationError> {
    for (b, (inp, outp)) in thetas.chunks(BLOCK).zip(out.chunks_mut(BLOCK)).enumerate() {
        exp_block::<F>(b * BLOCK, inp, outp)?;
    }
    Ok(())
}

/// The exponential map into a new vector, block by block without initialising it first.
#[inline(always)]
fn exp_vec<const F: bool>(
    thetas: &[Vector3<f64>],
    out: &mut Vec<Quaternion<f64>>,
) -> Result<(), RotationError> {
    let mut buf = [Quaternion::identity(); BLOCK];
    for (b, inp) in thetas.chunks(BLOCK).enumerate() {
        exp_block::<F>(b * BLOCK, inp, &mut buf[..inp.len()])?;
        out.extend_from_slice(&buf[..inp.len()]);
    }
    Ok(())
}

/// One block (≤ [`BLOCK`] elements starting at `start`) of the exponential map.
#[inline(always)]
fn exp_block<const F: bool>(
    start: usize,
    inp: &[Vector3<f64>],
    outp: &mut [Quaternion<f64>],
) -> Result<(), RotationError> {
    let mut rare = false;
    // |Θ| ≤ π in the whole block (the range of scipy's and `angle_vector`'s output): the even
    // series in h², without sqrt, range reduction or division.
    if inp.iter().fold(true, |ok, v| ok & (half_angle_squared::<F>(v) <= HALF_PI_SQUARED)) {
        for (v, q) in inp.iter().zip(outp.iter_mut()) {
            let (c, sinc) = cos_sinc_of_square::<F>(half_angle_squared::<F>(v));
            // Canonical sign η ≥ 0 (η = 0 exactly goes to the one-rotation code).
            let k = if c < 0.0 { -0.5 * sinc } else { 0.5 * sinc };
            *q = Quaternion::new(c.abs(), v.x * k, v.y * k, v.z * k);
            rare |= c == 0.0;
        }
    } else {
        // Any |Θ|: h = |Θ|/2 reduced modulo π/2.
        for (v, q) in inp.iter().zip(outp.iter_mut()) {
            let ((a, b, c, d), r) = exp_lane::<F>(v.x, v.y, v.z);
            *q = Quaternion::new(a, b, c, d);
            rare |= r;
        }
    }
    if rare {
        for (i, (v, q)) in inp.iter().zip(outp.iter_mut()).enumerate() {
            if !all_finite([v.x, v.y, v.z]) {
                return Err(RotationError::at(start + i, RotationError::NonFinite { what: "angle vector" }));
            }
            if 0.5 * v.norm() > SIN_COS_MAX || q.a == 0.0 {
                *q = Quaternion::from_angle_vector(v);
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::tests::thetas;

    /// The portable build (F = false) and the fused one (F = true; a software `fma` on CPUs
    /// without one) both agree with the one-rotation exponential map to a few ulps × |Θ|; the
    /// public, dispatched call (AVX2 here when the CPU has it) gives the bits of the portable
    /// body of the build's choice.
    #[test]
    fn both_builds_of_the_exponential_map_match_one_by_one() {
        let th = thetas();
        for fused in [false, true] {
            let mut out = vec![Quaternion::identity(); th.len()];
            if fused { exp_all::<true>(&th, &mut out) } else { exp_all::<false>(&th, &mut out) }.unwrap();
            let mut v = Vec::new();
            if fused { exp_vec::<true>(&th, &mut v) } else { exp_vec::<false>(&th, &mut v) }.unwrap();
            assert_eq!(out, v);
            for (t, q) in th.iter().zip(&out) {
                let one = Quaternion::from_angle_vector(t);
                let err = (q.to_vector4() - one.to_vector4()).amax();
                assert!(err <= 4.0 * f64::EPSILON * t.norm().max(1.0), "fused = {fused}, Θ = {t:?}: {err:e}");
            }
        }
    }

    #[test]
    fn dispatched_exponential_map_is_the_portable_body_bitwise() {
        let mut th = thetas();
        let pi = core::f64::consts::PI;
        for t in [0.0, 1e-300, 1e-16, 1e-8, pi - 1e-8, pi, 4e5, 5e5] {
            th.extend([Vector3::new(t, 0.0, 0.0), Vector3::new(1.0, 2.0, 2.0) * (t / 3.0)]);
        }
        let dispatched = Quaternion::from_angle_vectors(&th).unwrap();
        let mut portable = vec![Quaternion::identity(); th.len()];
        exp_all::<FUSED_LOOPS>(&th, &mut portable).unwrap();
        for (d, p) in dispatched.iter().zip(&portable) {
            assert_eq!(d.to_vector4().map(f64::to_bits), p.to_vector4().map(f64::to_bits));
        }
    }
}
