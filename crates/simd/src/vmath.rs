//! Branch-free sin/cos and atan2 for the `f64` paths of vectrix: `Scalar`'s hooks for `f64`
//! (vectrix-tensor), the batched conversions of vectrix-rotation and the joint angles of the
//! planar passes.
//!
//! These are fdlibm's kernels (the C library behind most `libm`s: `e_rem_pio2.c`, `k_sin.c`,
//! `k_cos.c`, `s_atan.c`, `e_atan2.c`, © Sun Microsystems, freely redistributable) rewritten
//! without branches: every case is computed and the answer is selected, so that LLVM turns a
//! loop calling them into SIMD code (4 lanes with AVX2). Accuracy is fdlibm's, under 1 ulp on
//! the ranges used here; `tests` below measure the error against the platform's `libm` over
//! hard sets (near 0, near multiples of π/2, both axes, every octant).
//!
//! `F` selects fused multiply–add ([`madd`]); the callers pass [`crate::FUSED`] (one value)
//! or [`crate::FUSED_LOOPS`] (the batched conversions). Both variants are accurate; they may
//! differ in the last bit.

// The constants are fdlibm's decimal literals verbatim (so they can be checked against its
// source); they round to the same doubles as the shorter forms clippy suggests.
#![allow(clippy::excessive_precision)]

use crate::{FUSED, madd};

/// 1.5·2⁵²: adding it rounds a double of magnitude < 2⁵¹ to an integer held in the low bits.
const TOINT: f64 = 6_755_399_441_055_744.0;
/// 2/π.
const INV_PIO2: f64 = core::f64::consts::FRAC_2_PI;
/// π/2 = PIO2_1 + PIO2_2 + PIO2_2T, the first two with 33 bits so that n·PIO2_i is exact for
/// |n| < 2²⁰ (fdlibm `e_rem_pio2.c`).
const PIO2_1: f64 = 1.570_796_326_734_125_614_17;
const PIO2_2: f64 = 6.077_100_506_303_965_976_60e-11;
const PIO2_2T: f64 = 2.022_266_248_795_950_631_54e-21;

/// The largest |x| [`sin_cos`] reduces (|n| < 2¹⁷ ≪ 2²⁰); callers send larger or non-finite
/// arguments to `libm` ([`sin_cos_or_libm`]).
pub const SIN_COS_MAX: f64 = 2.0e5;

const S1: f64 = -1.666_666_666_666_663_243_48e-1;
const S2: f64 = 8.333_333_333_322_489_461_24e-3;
const S3: f64 = -1.984_126_982_985_794_931_34e-4;
const S4: f64 = 2.755_731_370_707_006_767_89e-6;
const S5: f64 = -2.505_076_025_340_686_341_95e-8;
const S6: f64 = 1.589_690_995_211_550_102_21e-10;

const C1: f64 = 4.166_666_666_666_660_190_37e-2;
const C2: f64 = -1.388_888_888_887_410_957_49e-3;
const C3: f64 = 2.480_158_728_947_672_941_78e-5;
const C4: f64 = -2.755_731_435_139_066_330_35e-7;
const C5: f64 = 2.087_572_321_298_174_827_90e-9;
const C6: f64 = -1.135_964_755_778_819_482_65e-11;

/// (sin x, cos x) for |x| ≤ [`SIN_COS_MAX`], each within 1 ulp: Cody–Waite reduction
/// x = nπ/2 + (y₀ + y₁) with π/2 to 119 bits, then fdlibm's kernels on |y₀| ≤ π/4 and the
/// quadrant n mod 4 chosen by selects. Outside the range the result is meaningless (callers
/// check).
#[inline(always)]
pub fn sin_cos<const F: bool>(x: f64) -> (f64, f64) {
    // n = round(x·2/π); the low bits of t hold n mod 4 (two's complement, also for n < 0).
    let t = x * INV_PIO2 + TOINT;
    let n = t - TOINT;
    let quadrant = t.to_bits();
    // Two Cody–Waite steps (fdlibm's medium case with its second iteration always taken).
    let r0 = x - n * PIO2_1; // exact: n·PIO2_1 has ≤ 53 bits and r0 ≈ x − nπ/2 (Sterbenz)
    let w0 = n * PIO2_2; // exact
    let r = r0 - w0;
    let w = n * PIO2_2T - ((r0 - r) - w0);
    let y0 = r - w;
    let y1 = (r - y0) - w;
    // k_sin.c / k_cos.c on y0 + y1.
    let z = y0 * y0;
    let v = z * y0;
    let rs = madd::<F>(z, madd::<F>(z, madd::<F>(z, madd::<F>(z, S6, S5), S4), S3), S2);
    let s = y0 - ((z * (0.5 * y1 - v * rs) - y1) - v * S1);
    let w4 = z * z;
    let rc = z * madd::<F>(z, madd::<F>(z, C3, C2), C1) + w4 * w4 * madd::<F>(z, madd::<F>(z, C6, C5), C4);
    let hz = 0.5 * z;
    let one_hz = 1.0 - hz;
    let c = one_hz + (((1.0 - one_hz) - hz) + (z * rc - y0 * y1));
    // Quadrant: (sin, cos) = (s, c), (c, −s), (−s, −c), (−c, s) for n mod 4 = 0, 1, 2, 3.
    let swap = quadrant & 1 != 0;
    let (a, b) = if swap { (c, s) } else { (s, c) };
    let sin = f64::from_bits(a.to_bits() ^ ((quadrant & 2) << 62));
    let cos = f64::from_bits(b.to_bits() ^ (((quadrant + 1) & 2) << 62));
    (sin, cos)
}

/// (sin x, cos x) by [`sin_cos`]`::<FUSED>` for |x| ≤ [`SIN_COS_MAX`], by `libm` beyond and
/// for NaN or ±∞: what `Scalar::fast_sin_cos` returns for `f64`.
#[inline(always)]
pub fn sin_cos_or_libm(x: f64) -> (f64, f64) {
    if x.abs() <= SIN_COS_MAX { sin_cos::<FUSED>(x) } else { x.sin_cos() }
}

crate::dispatch! {
    /// [`sin_cos_or_libm`] of every element of `x` into `sin` and `cos` (zipped: the caller
    /// passes three slices of one length). The branch-free kernel runs over every element
    /// first, then `libm` over the few beyond its range, so the loop vectorises; compiled for
    /// AVX2 where the CPU has it ([`crate::dispatch!`]): the same bits on every CPU.
    pub fn sin_cos_slices(x: &[f64], sin: &mut [f64], cos: &mut [f64]) = sin_cos_all;
}

/// The body of [`sin_cos_slices`]: blocks of four lanes straight from and into the slices, a
/// last partial block padded with zeros (each lane's bits are the kernel's either way), and
/// whether every element is in the kernel's range noted on the way, so that the `libm` pass
/// over the few beyond it runs only when there are some.
#[inline(always)]
fn sin_cos_all(x: &[f64], sin: &mut [f64], cos: &mut [f64]) {
    const W: usize = 4;
    let n = x.len().min(sin.len()).min(cos.len());
    let (x, sin, cos) = (&x[..n], &mut sin[..n], &mut cos[..n]);
    // 1 in a lane whose |x| is not ≤ SIN_COS_MAX (NaN included)
    let mut beyond = [0u64; W];
    let full = n - n % W;
    let blocks =
        x[..full].chunks_exact(W).zip(sin[..full].chunks_exact_mut(W)).zip(cos[..full].chunks_exact_mut(W));
    for ((xb, sb), cb) in blocks {
        for k in 0..W {
            (sb[k], cb[k]) = sin_cos::<FUSED>(xb[k]);
            beyond[k] |= u64::from(beyond_kernel(xb[k]));
        }
    }
    if full < n {
        let xb: [f64; W] = core::array::from_fn(|k| x.get(full + k).copied().unwrap_or(0.0));
        let (mut sb, mut cb) = ([0.0; W], [0.0; W]);
        for k in 0..W {
            (sb[k], cb[k]) = sin_cos::<FUSED>(xb[k]);
            beyond[k] |= u64::from(beyond_kernel(xb[k]));
        }
        for ((k, sk), ck) in (full..n).zip(&sb).zip(&cb) {
            (sin[k], cos[k]) = (*sk, *ck);
        }
    }
    if beyond.iter().any(|&b| b != 0) {
        for ((xk, sk), ck) in x.iter().zip(sin.iter_mut()).zip(cos.iter_mut()) {
            if beyond_kernel(*xk) {
                (*sk, *ck) = xk.sin_cos();
            }
        }
    }
}

/// NaN or |x| > [`SIN_COS_MAX`]: `libm`'s, not the kernel's (`|`, not `||`: no branch).
#[inline(always)]
fn beyond_kernel(x: f64) -> bool {
    x.is_nan() | (x.abs() > SIN_COS_MAX)
}

/// The range of max(|y|, |x|) on which [`atan2`] is accurate: there the products of its interval
/// tests (up to 2.5·max) neither overflow nor, for the larger argument, underflow (below it
/// 0.4375·5e-324 rounds to 0, and atan2(0, 5e-324) would take the wrong interval).
pub const ATAN2_RANGE: core::ops::RangeInclusive<f64> = 1e-270..=1e300;

/// atan2(y, x) by [`atan2`]`::<FUSED>` for max(|y|, |x|) in [`ATAN2_RANGE`] (NaN too, which the
/// kernel propagates), by `libm` outside (zeros, infinities, tiny and huge pairs, with libm's
/// rules for each): what `Scalar::fast_atan2` returns for `f64`.
#[inline(always)]
pub fn atan2_or_libm(y: f64, x: f64) -> f64 {
    // `max` ignores one NaN: a NaN with a number in range takes the kernel, which returns NaN
    if ATAN2_RANGE.contains(&y.abs().max(x.abs())) { atan2::<FUSED>(y, x) } else { y.atan2(x) }
}

/// (π/2)², the largest h² that [`cos_sinc_of_square`] takes.
pub const HALF_PI_SQUARED: f64 = 2.467_401_100_272_339_5;

/// Taylor coefficients (−1)ᵏ/(2k)! of cos h in u = h², k = 0..11 (the k = 12 term is below
/// 1e-19 on u ≤ (π/2)²).
const COS_U: [f64; 12] = [
    1.0,
    -0.5,
    0.041_666_666_666_666_664,
    -0.001_388_888_888_888_889,
    2.480_158_730_158_73e-5,
    -2.755_731_922_398_589e-7,
    2.087_675_698_786_81e-9,
    -1.147_074_559_772_972_5e-11,
    4.779_477_332_387_385e-14,
    -1.561_920_696_858_622_5e-16,
    4.110_317_623_312_165e-19,
    -8.896_791_392_450_574e-22,
];
/// Taylor coefficients (−1)ᵏ/(2k+1)! of sin h / h in u = h², k = 0..10 (the k = 11 term is
/// below 1e-18).
const SINC_U: [f64; 11] = [
    1.0,
    -0.166_666_666_666_666_66,
    0.008_333_333_333_333_333,
    -0.000_198_412_698_412_698_4,
    2.755_731_922_398_589_3e-6,
    -2.505_210_838_544_172e-8,
    1.605_904_383_682_161_3e-10,
    -7.647_163_731_819_816e-13,
    2.811_457_254_345_520_6e-15,
    -8.220_635_246_624_33e-18,
    1.957_294_106_339_126_3e-20,
];

/// Horner's rule for Σ cₖ uᵏ.
#[inline(always)]
fn horner<const F: bool, const N: usize>(u: f64, c: &[f64; N]) -> f64 {
    c.iter().rev().fold(0.0, |acc, &ck| madd::<F>(acc, u, ck))
}

/// (cos h, sin h / h) from u = h² ∈ [0, (π/2)²] (the caller checks): both are even in h, so
/// their Taylor series in u need no square root, no range reduction and no division, the
/// short dependency chain the batched exponential map wants. Alternating series with
/// decreasing terms: sin h / h within 2 ulps, cos h within 2ε absolute (near h = π/2, where
/// cos h → 0, that is the absolute accuracy the rounded input h allows anyway: cos′ = −sin).
#[inline(always)]
pub fn cos_sinc_of_square<const F: bool>(u: f64) -> (f64, f64) {
    (horner::<F, 12>(u, &COS_U), horner::<F, 11>(u, &SINC_U))
}

const ATAN_HI: [f64; 4] = [
    4.636_476_090_008_060_935_15e-1,
    core::f64::consts::FRAC_PI_4,
    9.827_937_232_473_290_540_82e-1,
    core::f64::consts::FRAC_PI_2,
];
const ATAN_LO: [f64; 4] = [
    2.269_877_745_296_168_709_24e-17,
    3.061_616_997_868_383_017_93e-17,
    1.390_331_103_123_099_845_16e-17,
    6.123_233_995_736_766_035_87e-17,
];
const AT: [f64; 11] = [
    3.333_333_333_333_293_180_27e-1,
    -1.999_999_999_987_648_324_76e-1,
    1.428_571_427_250_346_637_11e-1,
    -1.111_111_040_546_235_578_80e-1,
    9.090_887_133_436_506_561_96e-2,
    -7.691_876_205_044_829_994_95e-2,
    6.661_073_137_387_531_206_69e-2,
    -5.833_570_133_790_573_486_45e-2,
    4.976_877_994_615_932_360_17e-2,
    -3.653_157_274_421_691_552_70e-2,
    1.628_582_011_536_578_236_23e-2,
];
const PI: f64 = core::f64::consts::PI;
const PI_LO: f64 = 1.224_646_799_147_353_177_2e-16;

/// atan2(y, x) within 1 ulp for max(|y|, |x|) in [`ATAN2_RANGE`] (the callers check): fdlibm's
/// `s_atan.c` on p/q with p = |y|, q = |x|, its five intervals chosen by comparisons and each
/// reduced argument formed from p and q with a single division; then `e_atan2.c`'s quadrant
/// rule (π − (z − π_lo) for x < 0, including x = −0) and the sign of y. Range [−π, π].
#[inline(always)]
pub fn atan2<const F: bool>(y: f64, x: f64) -> f64 {
    let (p, q) = (y.abs(), x.abs());
    // Intervals of p/q: [0, 7/16), [7/16, 11/16), [11/16, 19/16), [19/16, 39/16), [39/16, ∞).
    let (i0, i1, i2, i3) = (p >= 0.4375 * q, p >= 0.6875 * q, p >= 1.1875 * q, p >= 2.4375 * q);
    // t = p/q, (2p − q)/(2q + p), (p − q)/(p + q), (p − 1.5q)/(q + 1.5p), −q/p.
    let (num, den) = if i3 {
        (-q, p)
    } else if i2 {
        (madd::<F>(-1.5, q, p), madd::<F>(1.5, p, q))
    } else if i1 {
        (p - q, p + q)
    } else if i0 {
        (2.0 * p - q, 2.0 * q + p)
    } else {
        (p, q)
    };
    let (hi, lo) = if i3 {
        (ATAN_HI[3], ATAN_LO[3])
    } else if i2 {
        (ATAN_HI[2], ATAN_LO[2])
    } else if i1 {
        (ATAN_HI[1], ATAN_LO[1])
    } else if i0 {
        (ATAN_HI[0], ATAN_LO[0])
    } else {
        (0.0, 0.0)
    };
    let t = num / den;
    let z = t * t;
    let w = z * z;
    let s1 = z * madd::<F>(
        w,
        madd::<F>(w, madd::<F>(w, madd::<F>(w, madd::<F>(w, AT[10], AT[8]), AT[6]), AT[4]), AT[2]),
        AT[0],
    );
    let s2 = w * madd::<F>(w, madd::<F>(w, madd::<F>(w, madd::<F>(w, AT[9], AT[7]), AT[5]), AT[3]), AT[1]);
    let a = hi - ((t * (s1 + s2) - lo) - t);
    let r = if x.is_sign_negative() { PI - (a - PI_LO) } else { a };
    r.copysign(y)
}

#[cfg(test)]
mod tests;
