//! Smooth functions with removable singularities, evaluated by series near them (DESIGN §1.3).
//!
//! Book: §2.14, (2.14.12–15); notes ch2b §3.4–3.5.

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

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
#[inline]
pub(crate) fn wrap_near<T: Scalar>(a: T) -> T {
    let (pi, two_pi) = (T::pi(), T::two_pi());
    if a > pi {
        a - two_pi
    } else if a <= -pi {
        a + two_pi
    } else {
        a
    }
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
