//! Wrapped angles and congruence mod 2π (book Fact 2.1.1, §2.3).

use crate::Scalar;

/// Wraps an angle into (−π, π]: π is included, −π is not (book §2.3, "wrapped angle").
///
/// Book: §2.3, Fact 2.1.1. Non-finite input is returned unchanged.
#[inline]
pub fn wrap_angle<T: Scalar>(a: T) -> T {
    let pi = T::pi();
    let two_pi = T::two_pi();
    if a > -pi && a <= pi {
        return a;
    }
    if !a.re().is_finite() {
        return a;
    }
    // r ∈ [−π, π) by subtracting k turns, then map −π to +π. The integer k is taken from the
    // real part, so dual numbers (whose `floor` is not defined) keep their derivative parts.
    let k = ((a.re() + core::f64::consts::PI) / core::f64::consts::TAU).floor();
    let mut r = a - two_pi * T::lit(k);
    if r <= -pi {
        r += two_pi;
    }
    if r > pi {
        r -= two_pi;
    }
    r
}

/// `a ≡ b`: a − b ∈ 2πℤ within the absolute tolerance `tol` on the wrapped difference.
///
/// Book: Fact 2.1.1.
#[inline]
pub fn congruent<T: Scalar>(a: T, b: T, tol: f64) -> bool {
    // The wrapped difference lies in (−π, π]; for congruent angles it is 0 up to rounding.
    wrap_angle(a - b).re().abs() <= tol
}
