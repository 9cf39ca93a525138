//! Rational functions on the imaginary axis, evaluated from the coefficients.
//!
//! G(jω) = N(jω)/D(jω) is computed from the coefficients by Horner's rule on the even and odd
//! parts, p(jω) = E(−ω²) + jω·O(−ω²), which returns the exact value for coefficients perturbed
//! by at most (n + 2)ε relative each (Higham, *Accuracy and Stability of Numerical
//! Algorithms*, §5.1). So every value carries at most a small multiple of ε times its
//! condition number with respect to the coefficients, whatever the conditioning of the roots
//! (notes §3.4: the zero–pole–gain form inherits the root errors instead).
//!
//! Two scalings keep the evaluation free of overflow: the coefficients of N and D are divided by
//! a power of two (exact) so that the largest has magnitude in [1, 2), and for ω > 1 the
//! reversed polynomials are evaluated at 1/(jω): p(jω) = (jω)ⁿ·Σ cₖ(jω)^{−k}.
//!
//! At an imaginary-axis pole or zero (D or N exactly zero in floating point at jω) the value is
//! the limit from above, ω → ω₀⁺, the one-sided rule the book uses at ω = 0 (16.6.2): the
//! orders and leading Taylor coefficients of N and D at jω₀ give G ≈ c·(j(ω − ω₀))^q.
//!
//! Book: §16.2, (16.2.4); (16.6.2); notes §3.4.

use num_complex::Complex64;
use std::f64::consts::FRAC_PI_2;

/// A polynomial's coefficients (descending) divided by 2^e so that max |c| ∈ [1, 2).
#[derive(Debug, Clone)]
pub(crate) struct Scaled {
    /// c / 2^e, descending powers.
    pub c: Vec<f64>,
    /// The exponent e.
    pub e: i32,
}

impl Scaled {
    /// Scales `c` (finite, not all zero, or the zero polynomial `[0]`).
    pub(crate) fn new(c: &[f64]) -> Self {
        let m = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if m == 0.0 || !m.is_finite() {
            return Self { c: c.to_vec(), e: 0 };
        }
        let e = exponent(m);
        let f = pow2(-e);
        // two steps when 2^−e is not representable (|c| near the subnormal or overflow range)
        let c = if f.is_normal() {
            c.iter().map(|x| x * f).collect()
        } else {
            let (e1, e2) = (-e / 2, -e - (-e / 2));
            c.iter().map(|x| x * pow2(e1) * pow2(e2)).collect()
        };
        Self { c, e }
    }

    /// Degree.
    pub(crate) fn degree(&self) -> usize {
        self.c.len() - 1
    }

    /// p(jω)/2^e for ω ≤ 1, p(jω)/(2^e (jω)ⁿ) for ω > 1 (see [`at_jw`]).
    #[inline]
    pub(crate) fn at_jw(&self, w: f64) -> Complex64 {
        at_jw(&self.c, w)
    }
}

/// ⌊log₂ m⌋ for a finite m > 0.
pub(crate) fn exponent(m: f64) -> i32 {
    let bits = m.to_bits();
    let raw = ((bits >> 52) & 0x7ff) as i32;
    if raw == 0 {
        // subnormal: count from the highest set mantissa bit
        -1074 + (63 - (bits & ((1u64 << 52) - 1)).leading_zeros() as i32)
    } else {
        raw - 1023
    }
}

/// 2^k, exact for every k (0 or ∞ beyond the range).
pub(crate) fn pow2(k: i32) -> f64 {
    if (-1022..=1023).contains(&k) {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else if k > 1023 {
        f64::INFINITY
    } else if k >= -1074 {
        f64::from_bits(1u64 << (k + 1074))
    } else {
        0.0
    }
}

/// x·2ᵏ exactly (0 or ±∞ beyond the range), in two steps so that 2ᵏ itself never overflows
/// before the product is formed.
pub(crate) fn mul_pow2(x: f64, k: i32) -> f64 {
    let h = k / 2;
    x * pow2(h) * pow2(k - h)
}

/// p(jω) for descending real coefficients `c`: for ω ≤ 1 the value itself, for ω > 1 the value
/// divided by (jω)ⁿ, i.e. the reversed polynomial Σ cₖ zᵏ (k from the leading coefficient) at
/// z = 1/(jω). Horner's rule on the even and odd parts in x = −ω² (or x = −1/ω²).
#[inline]
pub(crate) fn at_jw(c: &[f64], w: f64) -> Complex64 {
    let n = c.len() - 1;
    let (mut e, mut o) = (0.0, 0.0);
    if w <= 1.0 {
        // p(jω) = Σ c_i (jω)^{n−i}: even powers into e, odd into o, both in x = −ω²
        let x = -w * w;
        for (i, &ci) in c.iter().enumerate() {
            if (n - i).is_multiple_of(2) {
                e = e * x + ci;
            } else {
                o = o * x + ci;
            }
        }
        Complex64::new(e, w * o)
    } else {
        // r(z) = Σ c_i z^i at z = −j/ω: even powers i in e, odd in o, both in y = −1/ω²
        let u = 1.0 / w;
        let y = -u * u;
        for (i, &ci) in c.iter().enumerate().rev() {
            if i.is_multiple_of(2) {
                e = e * y + ci;
            } else {
                o = o * y + ci;
            }
        }
        // r = E(y) + z·O(y) with z = −j u
        Complex64::new(e, -u * o)
    }
}

/// a/b without spurious overflow or NaN for finite a and nonzero finite b (Smith's algorithm;
/// the plain formula where |b|² is a normal number).
#[inline]
pub(crate) fn cdiv(a: Complex64, b: Complex64) -> Complex64 {
    let d = b.norm_sqr();
    if d.is_normal() && d < 1e300 {
        let inv = 1.0 / d;
        return Complex64::new((a.re * b.re + a.im * b.im) * inv, (a.im * b.re - a.re * b.im) * inv);
    }
    if b.re.abs() >= b.im.abs() {
        let r = b.im / b.re;
        let den = b.re + b.im * r;
        Complex64::new((a.re + a.im * r) / den, (a.im - a.re * r) / den)
    } else {
        let r = b.re / b.im;
        let den = b.re * r + b.im;
        Complex64::new((a.re * r + a.im) / den, (a.im * r - a.re) / den)
    }
}

/// The point at infinity in the direction of `dir` (≠ 0): each component ±∞ by its sign, or 0
/// where the direction has none (never NaN). Its `norm()` is +∞.
pub(crate) fn infinity_towards(dir: Complex64) -> Complex64 {
    let inf = |x: f64| if x == 0.0 { 0.0 } else { f64::INFINITY.copysign(x) };
    Complex64::new(inf(dir.re), inf(dir.im))
}

/// Order q ≥ 0 and leading Taylor coefficient t_q ≠ 0 of p at z₀: p(z) = t_q (z − z₀)^q + …,
/// by repeated synthetic division (exact zeros decided in floating point). `None` for the zero
/// polynomial.
pub(crate) fn taylor_leading(c: &[f64], z0: Complex64) -> Option<(usize, Complex64)> {
    let mut q: Vec<Complex64> = c.iter().map(|&x| Complex64::new(x, 0.0)).collect();
    let mut order = 0;
    while !q.is_empty() {
        // one step of synthetic division: q(z) = (z − z₀)·q₁(z) + q(z₀)
        let mut acc = Complex64::new(0.0, 0.0);
        let mut next = Vec::with_capacity(q.len().saturating_sub(1));
        for (i, &x) in q.iter().enumerate() {
            acc = acc * z0 + x;
            if i + 1 < q.len() {
                next.push(acc);
            }
        }
        if acc != Complex64::new(0.0, 0.0) {
            return Some((order, acc));
        }
        order += 1;
        q = next;
    }
    None
}

/// G(jω) = N(jω)/D(jω) in a form that keeps magnitude and phase exact in range:
/// G = q·(jω)^k·2^e, or the limit c·(j(ω − ω₀))^order at an axis pole or zero.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum AxisValue {
    /// G = q·(jω)^k·2^e with q finite and nonzero, or q = 0 for N ≡ 0.
    Regular { q: Complex64, k: i32, e: i32 },
    /// As ω → ω₀⁺: G ≈ c·(jω₀)^k·2^e·(j(ω − ω₀))^order (order ≠ 0: a pole for order < 0).
    Limit { c: Complex64, order: i32, k: i32, e: i32 },
}

/// The rational function N/D on the imaginary axis (scaled coefficients).
#[derive(Debug, Clone)]
pub(crate) struct AxisRational {
    pub num: Scaled,
    pub den: Scaled,
}

impl AxisRational {
    /// From descending coefficients (finite; D not the zero polynomial).
    pub(crate) fn new(num: &[f64], den: &[f64]) -> Self {
        Self { num: Scaled::new(num), den: Scaled::new(den) }
    }

    /// G(jω) for ω ≥ 0 as an [`AxisValue`].
    pub(crate) fn at(&self, w: f64) -> AxisValue {
        let (m, n) = (self.num.degree() as i32, self.den.degree() as i32);
        let e = self.num.e - self.den.e;
        let big = w > 1.0;
        let k = if big { m - n } else { 0 };
        let nv = self.num.at_jw(w);
        let dv = self.den.at_jw(w);
        let zero = Complex64::new(0.0, 0.0);
        if dv != zero && (nv != zero || self.num.c.iter().all(|&c| c == 0.0)) {
            return AxisValue::Regular { q: cdiv(nv, dv), k, e };
        }
        // an exact zero of N or D at jω₀: orders and Taylor coefficients in the variable of
        // the evaluation (s for ω ≤ 1, z = 1/s for ω > 1; z − z₀ ≈ j(ω − ω₀)/ω₀², the same
        // direction as s − s₀)
        let z0 = if big { Complex64::new(0.0, -1.0 / w) } else { Complex64::new(0.0, w) };
        let rev = |c: &[f64]| -> Vec<f64> { c.iter().rev().copied().collect() };
        let (nc, dc) =
            if big { (rev(&self.num.c), rev(&self.den.c)) } else { (self.num.c.clone(), self.den.c.clone()) };
        let Some((a, ta)) = taylor_leading(&nc, z0) else {
            return AxisValue::Regular { q: zero, k, e };
        };
        let (b, tb) = taylor_leading(&dc, z0).unwrap_or((0, Complex64::new(1.0, 0.0)));
        let order = a as i32 - b as i32;
        if order == 0 {
            return AxisValue::Regular { q: cdiv(ta, tb), k, e };
        }
        // in z, (z − z₀)^order = (j(ω − ω₀)/ω₀²)^order: the factor ω₀^{−2·order} is positive
        // and only scales the approach, not its direction
        AxisValue::Limit { c: cdiv(ta, tb), order, k, e }
    }
}

impl AxisValue {
    /// G(jω) as a complex number: finite, 0, or the point at infinity in the limit direction.
    pub(crate) fn value(&self, w: f64) -> Complex64 {
        match *self {
            AxisValue::Regular { q, k, e } => {
                // q·(jω)^k·2^e: jᵏ rotates, ωᵏ·2^e scales (in two factors to delay overflow)
                let r = rotate(q, k);
                let s = w.powi(k);
                let s2 = pow2(e);
                let out = if s.is_finite() && s2.is_finite() && (s * s2).is_normal() {
                    r * (s * s2)
                } else {
                    r * s * s2
                };
                if out.re.is_nan() || out.im.is_nan() { infinity_towards(r) } else { out }
            }
            AxisValue::Limit { c, order, k, .. } => {
                let dir = rotate(rotate(c, k), order);
                if order < 0 { infinity_towards(dir) } else { Complex64::new(0.0, 0.0) }
            }
        }
    }

    /// ln|G(jω)| (+∞ at a pole, −∞ at a zero).
    pub(crate) fn ln_abs(&self, w: f64) -> f64 {
        match *self {
            AxisValue::Regular { q, k, e } => {
                if q.re == 0.0 && q.im == 0.0 {
                    return f64::NEG_INFINITY;
                }
                ln_norm(q) + if k == 0 { 0.0 } else { k as f64 * w.ln() } + e as f64 * std::f64::consts::LN_2
            }
            AxisValue::Limit { order, .. } => {
                if order < 0 {
                    f64::INFINITY
                } else {
                    f64::NEG_INFINITY
                }
            }
        }
    }

    /// The principal argument of G(jω) in (−π, π] (the limit from above at a pole or zero).
    pub(crate) fn arg(&self) -> f64 {
        let (c, quarter) = match *self {
            AxisValue::Regular { q, k, .. } => (q, k),
            AxisValue::Limit { c, order, k, .. } => (c, k + order),
        };
        wrap_pi(c.arg() + quarter as f64 * FRAC_PI_2)
    }
}

/// ln|z| without overflow or underflow of |z|².
pub(crate) fn ln_norm(z: Complex64) -> f64 {
    let n2 = z.norm_sqr();
    if n2.is_normal() && n2 < 1e300 { 0.5 * n2.ln() } else { z.norm().ln() }
}

/// z·jᵏ exactly (a quarter-turn rotation).
pub(crate) fn rotate(z: Complex64, k: i32) -> Complex64 {
    match k.rem_euclid(4) {
        0 => z,
        1 => Complex64::new(-z.im, z.re),
        2 => Complex64::new(-z.re, -z.im),
        _ => Complex64::new(z.im, -z.re),
    }
}

/// An angle in radians wrapped into (−π, π].
pub(crate) fn wrap_pi(x: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    let y = x.rem_euclid(TAU);
    if y > PI { y - TAU } else { y }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pow2_and_exponent_cover_the_range() {
        for k in [-1074, -1060, -1022, -1, 0, 1, 52, 1023] {
            assert_eq!(pow2(k), 2f64.powf(k as f64), "2^{k}");
            assert_eq!(exponent(pow2(k)), k);
        }
        assert_eq!(exponent(3.0), 1);
        assert_eq!(pow2(1024), f64::INFINITY);
        assert_eq!(pow2(-1075), 0.0);
    }

    #[test]
    fn reversed_and_direct_agree_at_one() {
        // p = 2s³ − s + 5 at ω = 1: direct value, and (j)³·r(−j) from the reversed branch
        let c = [2.0, 0.0, -1.0, 5.0];
        let direct = at_jw(&c, 1.0);
        let z = Complex64::new(0.0, 1.0);
        let want = 2.0 * z * z * z - z + 5.0;
        assert_eq!(direct, want);
        let w = 1.0 + 1e-12;
        let rev = rotate(at_jw(&c, w), 3) * w.powi(3);
        let s = Complex64::new(0.0, w);
        let want = 2.0 * s * s * s - s + 5.0;
        assert!((rev - want).norm() <= 8.0 * f64::EPSILON * 8.0);
    }
}
