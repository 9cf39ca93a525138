//! Batched conversions: many rotations per call, in SIMD.
//!
//! One call converts a whole slice, like scipy's `Rotation.from_rotvec(array)` or
//! `Rotation.as_euler(seq)`. The transcendental functions are fdlibm's kernels written without
//! branches (and, for angle vectors with |Θ| ≤ π, the Taylor series of cos h and sin h / h in
//! h²), so the loop runs four rotations per instruction with AVX2 and FMA. Those
//! features are detected when the program runs, and the portable build is used on other CPUs.
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

use nalgebra::Vector3;

use crate::euler_extract::{GIMBAL_LOCK_TOL, assemble, parity};
use crate::series::{all_finite, wrap_near};
use crate::vmath::{FMA_BUILTIN, HALF_PI_SQUARED, SIN_COS_MAX, atan2, cos_sinc_of_square, madd, sin_cos};
use crate::{EulerAngles, EulerSequence, EulerSolution, Quaternion, ROTATION_TOL, RotationError};

/// Elements per block: the unit of the fast-path choice (all |Θ| ≤ π) and of the rare-element
/// fix-up.
const BLOCK: usize = 64;

/// Defines `$name(args)`, which runs `$body::<true>` compiled for AVX2 + FMA when the CPU has
/// them (detected when the program runs) and the portable build `$body::<FMA_BUILTIN>` otherwise.
macro_rules! simd_entry {
    ($name:ident => $body:ident ($($arg:ident : $ty:ty),*)) => {
        fn $name($($arg: $ty),*) -> Result<(), RotationError> {
            #[cfg(target_arch = "x86_64")]
            {
                #[target_feature(enable = "avx2,fma")]
                fn avx2_fma($($arg: $ty),*) -> Result<(), RotationError> {
                    $body::<true>($($arg),*)
                }
                if !FMA_BUILTIN && std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
                    // SAFETY: AVX2 and FMA were detected on this CPU just above.
                    return unsafe { avx2_fma($($arg),*) };
                }
            }
            $body::<FMA_BUILTIN>($($arg),*)
        }
    };
}

/// sin xᵢ and cos xᵢ of many angles at once, in SIMD: for the other layers' loops over many
/// angles (the joint angles of a planar chain, `vectrix-dynamics`), where one [`crate::sin_cos`]
/// per element inside a longer loop would wait on that loop's chain. Each element is exactly
/// what [`crate::sin_cos`] returns (fdlibm's kernels without fused multiply–add, within 1 ulp;
/// `libm` beyond |x| = 2·10⁵ and for NaN or ±∞), with AVX2 when the CPU has it (detected when
/// the program runs) and the portable build otherwise: the same bits either way.
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
    #[cfg(target_arch = "x86_64")]
    {
        // AVX2 without FMA: the same operations, rounded the same, four lanes at a time
        #[target_feature(enable = "avx2")]
        fn avx2(x: &[f64], sin: &mut [f64], cos: &mut [f64]) {
            sin_cos_all(x, sin, cos)
        }
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: AVX2 was detected on this CPU just above.
            unsafe { avx2(x, sin, cos) };
            return Ok(());
        }
    }
    sin_cos_all(x, sin, cos);
    Ok(())
}

/// The body of [`sin_cos_slices`]: the branch-free kernel over every element, then `libm` for
/// the elements beyond its range.
#[inline(always)]
fn sin_cos_all(x: &[f64], sin: &mut [f64], cos: &mut [f64]) {
    for ((xk, sk), ck) in x.iter().zip(sin.iter_mut()).zip(cos.iter_mut()) {
        (*sk, *ck) = sin_cos::<false>(*xk);
    }
    for ((xk, sk), ck) in x.iter().zip(sin.iter_mut()).zip(cos.iter_mut()) {
        if xk.is_nan() || xk.abs() > SIN_COS_MAX {
            (*sk, *ck) = xk.sin_cos();
        }
    }
}

simd_entry!(exp_simd => exp_all(thetas: &[Vector3<f64>], out: &mut [Quaternion<f64>]));
simd_entry!(exp_vec_simd => exp_vec(thetas: &[Vector3<f64>], out: &mut Vec<Quaternion<f64>>));
simd_entry!(euler_simd => euler_all(
    qs: &[Quaternion<f64>],
    sequence: EulerSequence,
    angles: &mut [[f64; 3]],
    locks: &mut Vec<(usize, EulerSolution<f64>)>
));

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

/// Principal Euler angles of many rotations, from [`EulerAngles::from_quaternions`]: one
/// `[α, β, γ]` per rotation (in the order applied), the gimbal-locked elements listed with
/// their full [`EulerSolution`], and the alternate solutions on request.
///
/// Book: §2.13, Facts 2.13.3–8.
#[derive(Debug, Clone, PartialEq)]
pub struct EulerBatch {
    sequence: EulerSequence,
    angles: Vec<[f64; 3]>,
    locks: Vec<(usize, EulerSolution<f64>)>,
}

impl EulerBatch {
    /// The sequence of every element.
    pub fn sequence(&self) -> EulerSequence {
        self.sequence
    }

    /// Number of rotations.
    pub fn len(&self) -> usize {
        self.angles.len()
    }

    /// `true` for an empty batch.
    pub fn is_empty(&self) -> bool {
        self.angles.is_empty()
    }

    /// The principal angles [α, β, γ] (order applied) of each rotation; at gimbal lock the
    /// representative (combination, β, 0), as scipy's `as_euler` does (scipy also warns).
    pub fn angles(&self) -> &[[f64; 3]] {
        &self.angles
    }

    /// The angles, consuming the batch.
    pub fn into_angles(self) -> Vec<[f64; 3]> {
        self.angles
    }

    /// The gimbal-locked elements, ascending: (index, [`EulerSolution::GimbalLock`]).
    pub fn gimbal_locks(&self) -> &[(usize, EulerSolution<f64>)] {
        &self.locks
    }

    /// Element `i` as [`EulerAngles`] (the principal solution or the lock representative);
    /// `None` past the end.
    pub fn principal(&self, i: usize) -> Option<EulerAngles<f64>> {
        self.angles.get(i).map(|a| EulerAngles::new(self.sequence, *a))
    }

    /// Element `i` as the full [`EulerSolution`], what [`EulerAngles::from_quaternion`] returns
    /// for it: `Regular` with the principal and the alternate solution, or `GimbalLock`.
    /// `None` past the end.
    ///
    /// Book: Facts 2.13.3–8 (the alternate is (α+π, π−β, γ+π) for Tait–Bryan sequences and
    /// (α+π, −β, γ+π) for symmetric ones, wrapped into (−π, π]).
    pub fn solution(&self, i: usize) -> Option<EulerSolution<f64>> {
        let a = *self.angles.get(i)?;
        if let Ok(k) = self.locks.binary_search_by_key(&i, |(j, _)| *j) {
            return Some(self.locks[k].1);
        }
        // Back to the intrinsic order the extraction works in, then its common ending.
        let (_, reversed) = self.sequence.as_intrinsic_reversed();
        let intrinsic = if reversed { [a[2], a[1], a[0]] } else { a };
        Some(assemble(self.sequence, reversed, intrinsic, None))
    }
}

impl EulerAngles<f64> {
    /// Euler angles of many rotations at once from their Euler parameters q_{D/A}, in SIMD:
    /// the quaternion-pair extraction of [`EulerAngles::from_quaternion`] (accurate through
    /// gimbal lock, where the route through 𝓡(q) is not). Element by element it agrees with
    /// [`EulerAngles::from_quaternion`] to a few ulps, and gimbal lock is decided by that
    /// function itself. scipy's `Rotation.as_euler(seq)` is the peer.
    ///
    /// Book: §2.13, Facts 2.13.3–8 (corrected signs), (2.15.14).
    ///
    /// # Errors
    /// [`RotationError::AtElement`] for the first quaternion that is not finite
    /// ([`RotationError::NonFinite`]) or not a unit quaternion within [`ROTATION_TOL`]
    /// ([`RotationError::NotUnit`]).
    ///
    /// ```
    /// use vectrix_rotation::{EulerAngles, EulerSequence, Quaternion};
    ///
    /// let e = EulerAngles::new(EulerSequence::S321, [0.3, -0.2, 0.1]);
    /// let batch = EulerAngles::from_quaternions(&[e.quaternion(); 3], EulerSequence::S321)?;
    /// assert!((batch.angles()[2][0] - 0.3).abs() < 1e-15);
    /// assert!(batch.gimbal_locks().is_empty());
    /// # Ok::<(), vectrix_rotation::RotationError>(())
    /// ```
    #[doc(alias = "as_euler")]
    pub fn from_quaternions(
        qs: &[Quaternion<f64>],
        sequence: EulerSequence,
    ) -> Result<EulerBatch, RotationError> {
        let mut batch = EulerBatch { sequence, angles: vec![[0.0; 3]; qs.len()], locks: Vec::new() };
        let (angles, locks) = (&mut batch.angles, &mut batch.locks);
        euler_simd(qs, sequence, angles, locks)?;
        Ok(batch)
    }
}

/// Euler extraction over all blocks (see [`EulerAngles::from_quaternions`]): one loop per
/// intrinsic sequence (i, j, k), monomorphised so the component indices are constants, straight
/// from the quaternions into the angles.
#[inline(always)]
fn euler_all<const F: bool>(
    qs: &[Quaternion<f64>],
    sequence: EulerSequence,
    angles: &mut [[f64; 3]],
    locks: &mut Vec<(usize, EulerSolution<f64>)>,
) -> Result<(), RotationError> {
    let (seq, reversed) = sequence.as_intrinsic_reversed();
    let [ai, aj, ak] = seq.axes();
    macro_rules! by_sequence {
        ($(($i:literal, $j:literal, $k:literal)),*) => {
            match (ai.i0(), aj.i0(), ak.i0()) {
                $(($i, $j, $k) => euler_seq::<F, $i, $j, $k>(qs, sequence, reversed, angles, locks),)*
                _ => unreachable!("EulerSequence holds distinct adjacent axes"),
            }
        };
    }
    by_sequence!(
        (0, 1, 2),
        (0, 2, 1),
        (1, 2, 0),
        (1, 0, 2),
        (2, 0, 1),
        (2, 1, 0),
        (0, 1, 0),
        (0, 2, 0),
        (1, 2, 1),
        (1, 0, 1),
        (2, 0, 2),
        (2, 1, 2)
    )
}

/// [`euler_all`] for the intrinsic sequence (I, J, K) (zero-based; `reversed` for an extrinsic
/// one, whose angles come out in the opposite order).
#[inline(always)]
fn euler_seq<const F: bool, const I: usize, const J: usize, const K: usize>(
    qs: &[Quaternion<f64>],
    sequence: EulerSequence,
    reversed: bool,
    angles: &mut [[f64; 3]],
    locks: &mut Vec<(usize, EulerSolution<f64>)>,
) -> Result<(), RotationError> {
    let e = parity(I, J);
    let m = 3 - I - J; // the third axis of a symmetric sequence (I = K)
    // Flag lanes near the lock for the one-rotation code, which decides (its hypot may differ
    // from sqrt(x² + y²) in the last bit).
    let lock_flag = 2.0 * GIMBAL_LOCK_TOL;
    for (blk, (inp, outp)) in qs.chunks(BLOCK).zip(angles.chunks_mut(BLOCK)).enumerate() {
        let mut rare = false;
        for (q, out) in inp.iter().zip(outp.iter_mut()) {
            // The half-sum/half-difference pairs of `EulerAngles::from_quaternion` (Bernardes &
            // Viollet), the same formulas in the same order.
            let (w, comp) = (q.a, [q.b, q.c, q.d]);
            let (alpha, beta, gamma, measure);
            if I != K {
                let (qi, qj, qk) = (comp[I], comp[J], comp[K]);
                let (a, b, c, d) = (w + qj, qi + e * qk, w - qj, qi - e * qk);
                measure = madd::<F>(a, a, b * b).sqrt() * madd::<F>(c, c, d * d).sqrt();
                beta = atan2::<F>(2.0 * (w * qj + e * qi * qk), measure);
                let (phi_p, phi_m) = (atan2::<F>(b, a), atan2::<F>(d, c));
                alpha = phi_p + phi_m;
                gamma = e * (phi_p - phi_m);
            } else {
                let (a, b, c, d) = (w, comp[I], comp[J], e * comp[m]);
                let (h_ab, h_cd) = (madd::<F>(a, a, b * b).sqrt(), madd::<F>(c, c, d * d).sqrt());
                beta = 2.0 * atan2::<F>(h_cd, h_ab);
                let (th_p, th_m) = (atan2::<F>(b, a), atan2::<F>(d, c));
                alpha = th_p + th_m;
                gamma = th_p - th_m;
                measure = 2.0 * h_ab * h_cd;
            }
            let (alpha, gamma) = (wrap_near(alpha), wrap_near(gamma));
            *out = if reversed { [gamma, beta, alpha] } else { [alpha, beta, gamma] };
            let n2 =
                madd::<F>(w, w, madd::<F>(comp[0], comp[0], madd::<F>(comp[1], comp[1], comp[2] * comp[2])));
            rare |= (measure <= lock_flag) | n2.is_nan() | ((n2 - 1.0).abs() > ROTATION_TOL);
        }
        if rare {
            for (l, (q, out)) in inp.iter().zip(outp.iter_mut()).enumerate() {
                let index = blk * BLOCK + l;
                q.check_unit(ROTATION_TOL).map_err(|err| RotationError::at(index, err))?;
                let s = EulerAngles::from_quaternion(q, sequence);
                if let EulerSolution::GimbalLock { representative, .. } = s {
                    *out = representative.angles;
                    locks.push((index, s));
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn xorshift(s: &mut u64) -> f64 {
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        (*s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    }

    /// Blocks of canonical angle vectors (|Θ| ≤ π, the series path), then blocks up to
    /// |Θ| = 40 (the reduced path), then canonical again; 300 is not a multiple of the block.
    fn thetas() -> Vec<Vector3<f64>> {
        let mut s = 0x0123_4567_89AB_CDEFu64;
        (0..300)
            .map(|i| {
                let scale = if (128..192).contains(&i) { 40.0 } else { 3.6 };
                let v = Vector3::new(xorshift(&mut s), xorshift(&mut s), xorshift(&mut s)) * scale;
                if scale < 4.0 && v.norm() > core::f64::consts::PI { v * 0.5 } else { v }
            })
            .collect()
    }

    /// The portable build (F = false) and the fused one (F = true; a software `fma` on CPUs
    /// without one) both agree with the one-rotation exponential map to a few ulps × |Θ|.
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

    /// Both builds of the Euler extraction agree with the one-rotation code in every sequence.
    #[test]
    fn both_builds_of_the_euler_extraction_match_one_by_one() {
        let qs: Vec<Quaternion<f64>> = thetas().iter().map(Quaternion::from_angle_vector).collect();
        for seq in EulerSequence::ALL.into_iter().flat_map(|s| [s, s.extrinsic()]) {
            for fused in [false, true] {
                let (mut angles, mut locks) = (vec![[0.0; 3]; qs.len()], Vec::new());
                if fused {
                    euler_all::<true>(&qs, seq, &mut angles, &mut locks)
                } else {
                    euler_all::<false>(&qs, seq, &mut angles, &mut locks)
                }
                .unwrap();
                assert!(locks.is_empty());
                for (q, a) in qs.iter().zip(&angles) {
                    let one = EulerAngles::from_quaternion(q, seq).principal().angles;
                    for (x, y) in a.iter().zip(&one) {
                        let d = wrap_near(x - y).abs();
                        assert!(d <= 4.0 * f64::EPSILON * 4.0, "{seq:?} fused = {fused}: {a:?} vs {one:?}");
                    }
                }
            }
        }
    }

    /// The hard set of the joint angles: zeros of both signs, subnormals, tiny and huge,
    /// multiples of π/2 and their neighbours (where the reduction cancels), the reduction's
    /// boundary 2·10⁵ and beyond, and the non-finite values; plus a pseudo-random sweep.
    fn joint_angles() -> Vec<f64> {
        let mut x = vec![0.0, -0.0, 5e-324, -1e-310, 1e-20, 2e5, -2e5, 2e5 + 1e-10, 1e6, -3e8, 1e300];
        x.extend([f64::NAN, f64::INFINITY, f64::NEG_INFINITY]);
        for k in -8i32..=8 {
            let m = f64::from(k) * std::f64::consts::FRAC_PI_2;
            x.extend([m, m.next_up(), m.next_down()]);
        }
        let mut seed = 0x2545_f491_4f6c_dd1d;
        x.extend((0..257).map(|_| 80.0 * xorshift(&mut seed)));
        x
    }

    /// Bit-identical to [`crate::sin_cos`] element by element, on the dispatched path (AVX2
    /// here when the CPU has it) and the portable body alike, including NaN's bits' class.
    #[test]
    fn sin_cos_slices_is_sin_cos_element_by_element() {
        let x = joint_angles();
        let n = x.len();
        let (mut s, mut c) = (vec![0.0; n], vec![0.0; n]);
        sin_cos_slices(&x, &mut s, &mut c).unwrap();
        let (mut s2, mut c2) = (vec![0.0; n], vec![0.0; n]);
        sin_cos_all(&x, &mut s2, &mut c2);
        for k in 0..n {
            let (ws, wc) = crate::sin_cos(x[k]);
            for (got, want) in [(s[k], ws), (c[k], wc), (s2[k], ws), (c2[k], wc)] {
                assert!(
                    got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                    "x = {:e}: got {got:e}, want {want:e}",
                    x[k]
                );
            }
        }
        // and within an ulp or two of libm (the kernel's own accuracy, tested in `vmath`)
        for k in (0..n).filter(|&k| x[k].is_finite() && x[k].abs() <= 1e6) {
            let (ls, lc) = x[k].sin_cos();
            assert!(
                (s[k] - ls).abs() <= 2.0 * f64::EPSILON * ls.abs().max(f64::MIN_POSITIVE),
                "sin {:e}",
                x[k]
            );
            assert!(
                (c[k] - lc).abs() <= 2.0 * f64::EPSILON * lc.abs().max(f64::MIN_POSITIVE),
                "cos {:e}",
                x[k]
            );
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
