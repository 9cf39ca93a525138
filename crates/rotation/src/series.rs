//! Smooth functions with removable singularities, evaluated by series near them (DESIGN §1.3).
//!
//! Book: §2.14, (2.14.12–15); notes ch2b §3.4–3.5.

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

/// (sin x, cos x): [`Scalar::fast_sin_cos`]. For `f64` arguments with |x| ≤ 2·10⁵ this is the
/// branch-free fdlibm kernel (one shared argument reduction, each result within 1 ulp, inlined:
/// no call, so the caller keeps its registers); other scalars (dual numbers, `f32`) and larger
/// or non-finite arguments take `T::sin_cos`.
///
/// Public for the other layers' hot loops; [`crate::sin_cos_slices`] is the same over a slice.
///
/// Book: (2.12.17–19), (2.15.20): the elementary rotations and quaternions.
#[inline(always)]
pub fn sin_cos<T: Scalar>(x: T) -> (T, T) {
    x.fast_sin_cos()
}

/// atan2(y, x) in [−π, π]: [`Scalar::fast_atan2`], for finite `f64` arguments other than
/// (0, 0) fdlibm's kernel (within 1 ulp, inlined); other scalars and the special arguments
/// take `T::atan2` (the `libm` rules for zeros, infinities and NaN).
///
/// Book: §2.11 (θ = 2 atan2(|ε|, η)), §2.13 (Euler angles).
#[inline(always)]
pub(crate) fn atan2<T: Scalar>(y: T, x: T) -> T {
    y.fast_atan2(x)
}

/// sin x / x, with the Taylor series 1 − x²/6 + x⁴/120 below |x| = 1e-3 (the next term,
/// x⁶/5040 ≈ 2·10⁻²², is far below ε), exact for dual numbers too.
///
/// Book: (2.14.12), the coefficient of Θ^×.
#[inline]
pub(crate) fn sinc<T: Scalar>(x: T) -> T {
    if x.re().abs() < 1e-3 {
        let x2 = x * x;
        T::one() - x2 / T::lit(6.0) + x2 * x2 / T::lit(120.0)
    } else {
        x.sin() / x
    }
}

/// The angle θ ∈ [0, π] with (sin θ, cos θ) = (s, c), s ≥ 0 and s² + c² = 1, by asin of
/// whichever of s and c is well conditioned (asin is about half the cost of atan2): asin(s)
/// for c > 0.7 (θ < 45.6°), π/2 − asin(c) for |c| ≤ 0.7, π − asin(s) for c < −0.7. The
/// derivative of asin is at most 1.41 on |x| ≤ 0.72, so each branch is accurate to a few ulps,
/// like atan2(s, c). Not for unnormalised pairs (atan2 is scale-free, this is not).
///
/// Book: §2.14 (θ ∈ [0, π]); notes ch2b §3.5 (never acos of a rounded cosine).
#[inline]
pub(crate) fn angle_0_pi<T: Scalar>(s: T, c: T) -> T {
    let cr = c.re();
    if cr > 0.7 {
        s.asin()
    } else if cr >= -0.7 {
        T::lit(core::f64::consts::FRAC_PI_2) - c.asin()
    } else {
        T::pi() - s.asin()
    }
}

/// The angle β ∈ [−π/2, π/2] with (sin β, cos β) = (s, c), c ≥ 0 and s² + c² = 1: asin(s)
/// for |s| ≤ 0.7, ±(π/2 − asin(c)) beyond, as in [`angle_0_pi`].
///
/// Book: §2.13 (the middle angle of a Tait–Bryan sequence); notes ch2b §3.7.
#[inline]
pub(crate) fn angle_half_pi<T: Scalar>(s: T, c: T) -> T {
    let sr = s.re();
    if sr.abs() <= 0.7 {
        s.asin()
    } else {
        let b = T::lit(core::f64::consts::FRAC_PI_2) - c.asin();
        if sr > 0.0 { b } else { -b }
    }
}

/// Euclidean norm without underflow or overflow: components of 1e-300 keep their length.
#[inline]
pub(crate) fn norm3<T: Scalar>(v: &Vector3<T>) -> T {
    // Fast path: |v|² neither underflows nor overflows.
    let n2 = v.norm_squared();
    let r = n2.re();
    if r > 1e-290 && r < 1e290 {
        return n2.sqrt();
    }
    let m = v.x.abs().max(v.y.abs()).max(v.z.abs());
    if m == T::zero() {
        return m;
    }
    (v / m).norm() * m
}

/// Wraps an angle in (−3π, 3π] into (−π, π] with at most one shift of 2π; π stays π (DESIGN
/// §4). Unlike a floor-based wrap it is smooth for dual numbers (num-dual has no `floor`).
/// Branch-free: the shift is a multiple k ∈ {−1, 0, 1} of 2π from two comparisons, since the
/// alternate Euler solutions (α + π, γ + π) need a shift half of the time, at random.
#[inline]
pub(crate) fn wrap_near<T: Scalar>(a: T) -> T {
    let r = a.re();
    let pi = core::f64::consts::PI;
    // k = 1 above π, −1 at or below −π; a − 0 keeps a (and the sign of a zero) exactly
    let k = f64::from(u8::from(r > pi)) - f64::from(u8::from(r <= -pi));
    a - T::lit(k * core::f64::consts::TAU)
}

/// The first nonzero component positive (DESIGN §4, canonical axis at θ = π).
#[inline]
pub(crate) fn canonical_sign<T: Scalar>(v: Vector3<T>) -> Vector3<T> {
    let first = [v.x, v.y, v.z].into_iter().find(|c| *c != T::zero());
    match first {
        Some(c) if c < T::zero() => -v,
        _ => v,
    }
}

/// Maximum |component| of a residual, as `f64`.
#[inline]
pub(crate) fn max_abs<T: Scalar>(xs: impl IntoIterator<Item = T>) -> f64 {
    xs.into_iter().fold(0.0f64, |m, x| {
        let a = x.re().abs();
        if a.is_nan() || m.is_nan() { f64::NAN } else { m.max(a) }
    })
}

/// `true` when every value is finite.
#[inline]
pub(crate) fn all_finite<T: Scalar>(xs: impl IntoIterator<Item = T>) -> bool {
    xs.into_iter().all(|x| x.re().is_finite())
}
