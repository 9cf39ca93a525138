//! Exact rational arithmetic for conversion factors, rounded to `f64` once.
//!
//! A conversion multiplies a decimal number (or an `f64`, itself an exact binary fraction) by
//! a product of exact unit factors (0.3048, 0.45359237, 9.80665, …, and π for angles). All of
//! these are rationals, except π, which enters as a 60-digit rational (relative error below
//! 10⁻⁵⁹, far under the 2⁻⁵³ of an `f64`). [`Ratio`] keeps the numerator and the denominator
//! as exact unsigned integers; [`Ratio::to_f64`] divides them with round-to-nearest-even. So a
//! converted value carries one rounding, however composite its unit.
//!
//! The integers are small vectors of `u32` limbs: the sizes met here (a few hundred digits)
//! need nothing faster than schoolbook multiplication and binary long division.

use core::cmp::Ordering;

/// An unsigned integer of any size, little-endian base-2³² limbs, no trailing zero limbs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Big {
    limbs: Vec<u32>,
}

impl Big {
    pub(crate) fn zero() -> Self {
        Self { limbs: Vec::new() }
    }

    pub(crate) fn from_u64(x: u64) -> Self {
        let mut b = Self { limbs: vec![x as u32, (x >> 32) as u32] };
        b.trim();
        b
    }

    fn trim(&mut self) {
        while self.limbs.last() == Some(&0) {
            self.limbs.pop();
        }
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.limbs.is_empty()
    }

    /// Number of significant bits (0 for zero).
    pub(crate) fn bits(&self) -> u64 {
        match self.limbs.last() {
            None => 0,
            Some(top) => 32 * (self.limbs.len() as u64 - 1) + u64::from(32 - top.leading_zeros()),
        }
    }

    /// self · k + c for small k and c.
    pub(crate) fn mul_small_add(&mut self, k: u32, c: u32) {
        let mut carry = u64::from(c);
        for limb in &mut self.limbs {
            let t = u64::from(*limb) * u64::from(k) + carry;
            *limb = t as u32;
            carry = t >> 32;
        }
        if carry != 0 {
            self.limbs.push(carry as u32);
        }
        self.trim();
    }

    pub(crate) fn mul(&self, other: &Big) -> Big {
        if self.is_zero() || other.is_zero() {
            return Big::zero();
        }
        let mut out = vec![0u32; self.limbs.len() + other.limbs.len()];
        for (i, &a) in self.limbs.iter().enumerate() {
            let mut carry = 0u64;
            for (j, &b) in other.limbs.iter().enumerate() {
                let t = u64::from(out[i + j]) + u64::from(a) * u64::from(b) + carry;
                out[i + j] = t as u32;
                carry = t >> 32;
            }
            let mut k = i + other.limbs.len();
            while carry != 0 {
                let t = u64::from(out[k]) + carry;
                out[k] = t as u32;
                carry = t >> 32;
                k += 1;
            }
        }
        let mut b = Big { limbs: out };
        b.trim();
        b
    }

    /// self^e by repeated squaring.
    pub(crate) fn pow(&self, mut e: u32) -> Big {
        let mut base = self.clone();
        let mut acc = Big::from_u64(1);
        while e > 0 {
            if e & 1 == 1 {
                acc = acc.mul(&base);
            }
            e >>= 1;
            if e > 0 {
                base = base.mul(&base);
            }
        }
        acc
    }

    pub(crate) fn shl(&self, n: u64) -> Big {
        if self.is_zero() {
            return Big::zero();
        }
        let (words, bits) = ((n / 32) as usize, (n % 32) as u32);
        let mut out = vec![0u32; words];
        if bits == 0 {
            out.extend_from_slice(&self.limbs);
        } else {
            let mut carry = 0u32;
            for &l in &self.limbs {
                out.push((l << bits) | carry);
                carry = l >> (32 - bits);
            }
            out.push(carry);
        }
        let mut b = Big { limbs: out };
        b.trim();
        b
    }

    /// self >>= 1.
    fn shr1(&mut self) {
        let mut carry = 0u32;
        for limb in self.limbs.iter_mut().rev() {
            let next = *limb & 1;
            *limb = (*limb >> 1) | (carry << 31);
            carry = next;
        }
        self.trim();
    }

    fn cmp_big(&self, other: &Big) -> Ordering {
        self.limbs
            .len()
            .cmp(&other.limbs.len())
            .then_with(|| self.limbs.iter().rev().cmp(other.limbs.iter().rev()))
    }

    /// self −= other, for self ≥ other.
    fn sub_assign(&mut self, other: &Big) {
        let mut borrow = 0i64;
        for i in 0..self.limbs.len() {
            let b = i64::from(other.limbs.get(i).copied().unwrap_or(0));
            let t = i64::from(self.limbs[i]) - b - borrow;
            if t < 0 {
                self.limbs[i] = (t + (1i64 << 32)) as u32;
                borrow = 1;
            } else {
                self.limbs[i] = t as u32;
                borrow = 0;
            }
        }
        debug_assert_eq!(borrow, 0, "sub_assign needs self ≥ other");
        self.trim();
    }
}

/// The result of rounding an exact positive ratio to `f64`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Rounded {
    /// A finite normal `f64` (or zero for a zero ratio).
    Value(f64),
    /// The ratio rounds above `f64::MAX`.
    Overflow,
    /// The ratio is nonzero but below `f64::MIN_POSITIVE` (subnormal or smaller).
    Underflow,
}

/// An exact nonnegative rational p/q, q > 0.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ratio {
    pub(crate) num: Big,
    pub(crate) den: Big,
}

impl Ratio {
    pub(crate) fn one() -> Self {
        Self { num: Big::from_u64(1), den: Big::from_u64(1) }
    }

    /// Multiplies by n/d.
    pub(crate) fn scale(&mut self, n: &Big, d: &Big) {
        self.num = self.num.mul(n);
        self.den = self.den.mul(d);
    }

    /// Multiplies by 2^e (e of either sign).
    pub(crate) fn scale_pow2(&mut self, e: i64) {
        if e >= 0 {
            self.num = self.num.shl(e.unsigned_abs());
        } else {
            self.den = self.den.shl(e.unsigned_abs());
        }
    }

    /// Multiplies by 10^e (e of either sign).
    pub(crate) fn scale_pow10(&mut self, e: i64) {
        let p = Big::from_u64(10).pow(e.unsigned_abs() as u32);
        if e >= 0 {
            self.num = self.num.mul(&p);
        } else {
            self.den = self.den.mul(&p);
        }
    }

    /// p/q rounded to the nearest `f64`, ties to even: one rounding.
    ///
    /// # Degenerate inputs
    /// p = 0 gives 0. A result below the smallest normal `f64` is [`Rounded::Underflow`]
    /// (subnormals are refused rather than rounded with lost precision); one that rounds past
    /// `f64::MAX` is [`Rounded::Overflow`].
    pub(crate) fn to_f64(&self) -> Rounded {
        if self.num.is_zero() {
            return Rounded::Value(0.0);
        }
        let (n, d) = (self.num.bits() as i64, self.den.bits() as i64);
        // scale so that A/B lies in [2⁵⁴, 2⁵⁶): 55 or 56 quotient bits, 2 or 3 beyond the 53 kept
        let s = 55 - (n - d);
        let (mut a, b) = if s >= 0 {
            (self.num.shl(s as u64), self.den.clone())
        } else {
            (self.num.clone(), self.den.shl((-s) as u64))
        };
        // binary long division: q = ⌊A/B⌋ < 2⁵⁷, remainder left in a; t = B·2^i, halved
        // in place from i = 56 down to 0
        let mut q: u64 = 0;
        let mut t = b.shl(56);
        for i in (0..57u64).rev() {
            if a.cmp_big(&t) != Ordering::Less {
                a.sub_assign(&t);
                q |= 1 << i;
            }
            t.shr1();
        }
        let sticky = !a.is_zero();
        // keep 53 bits, round half to even with the dropped bits and the sticky remainder
        let qb = 64 - i64::from(q.leading_zeros());
        let r = qb - 53;
        let mut mant = q >> r;
        let dropped = q & ((1u64 << r) - 1);
        let half = 1u64 << (r - 1);
        if dropped > half || (dropped == half && (sticky || mant & 1 == 1)) {
            mant += 1;
        }
        let mut e2 = r - s; // value = mant · 2^e2
        if mant == 1 << 53 {
            mant >>= 1;
            e2 += 1;
        }
        // mant ∈ [2⁵², 2⁵³): the value's binary exponent is e2 + 52
        let exponent = e2 + 52;
        if exponent > 1023 {
            return Rounded::Overflow;
        }
        if exponent < -1022 {
            return Rounded::Underflow;
        }
        let bits = (((exponent + 1023) as u64) << 52) | (mant & ((1u64 << 52) - 1));
        Rounded::Value(f64::from_bits(bits))
    }
}

/// An `f64` as an exact ratio: |x| = m·2^e. Returns the ratio of |x| and its sign.
///
/// # Degenerate inputs
/// Only finite x are meaningful; callers check finiteness first.
pub(crate) fn ratio_of_f64(x: f64) -> (Ratio, bool) {
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let exp_field = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    // normal: (2⁵² + f)·2^(E−1075); subnormal: f·2^(−1074)
    let (m, e) = if exp_field == 0 { (frac, -1074) } else { (frac | (1u64 << 52), exp_field - 1075) };
    let mut r = Ratio { num: Big::from_u64(m), den: Big::from_u64(1) };
    r.scale_pow2(e);
    (r, negative)
}

/// Decimal digits of π after "3.", enough for 59 decimals: π ≈ PI_DIGITS · 10⁻⁵⁹.
pub(crate) const PI_DIGITS: &str = "314159265358979323846264338327950288419716939937510582097494";
/// Decimal exponent of [`PI_DIGITS`].
pub(crate) const PI_EXP10: i64 = -59;

/// Parses a string of ASCII decimal digits into a [`Big`].
pub(crate) fn big_from_digits(digits: &str) -> Big {
    let mut b = Big::zero();
    for c in digits.bytes() {
        b.mul_small_add(10, u32::from(c - b'0'));
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ratio(n: u64, d: u64) -> Ratio {
        Ratio { num: Big::from_u64(n), den: Big::from_u64(d) }
    }

    // One rounding: the correctly rounded quotient equals the hardware division of two
    // integers below 2⁵³ (IEEE 754 division is correctly rounded).
    #[test]
    fn small_ratios_match_ieee_division() {
        for (n, d) in
            [(1, 3), (2, 3), (3048, 10000), (45_359_237, 100_000_000), (1, 7), (22, 7), (1 << 52, 3)]
        {
            assert_eq!(ratio(n, d).to_f64(), Rounded::Value(n as f64 / d as f64), "{n}/{d}");
        }
    }

    // A tie: 2⁵³ + 1 is exactly halfway between two f64 and rounds to the even neighbour 2⁵³.
    #[test]
    fn ties_round_to_even() {
        assert_eq!(ratio((1 << 53) + 1, 1).to_f64(), Rounded::Value(9_007_199_254_740_992.0));
        assert_eq!(ratio((1 << 53) + 3, 1).to_f64(), Rounded::Value(9_007_199_254_740_996.0));
    }

    #[test]
    fn f64_round_trips_through_ratio() {
        for x in [1.0, 0.3048, 1e308, f64::MIN_POSITIVE, 123.456e-200, f64::MAX] {
            let (r, neg) = ratio_of_f64(x);
            assert!(!neg);
            assert_eq!(r.to_f64(), Rounded::Value(x));
        }
    }

    #[test]
    fn overflow_and_underflow_are_reported() {
        let (mut r, _) = ratio_of_f64(f64::MAX);
        r.scale_pow2(1);
        assert_eq!(r.to_f64(), Rounded::Overflow);
        let (mut r, _) = ratio_of_f64(f64::MIN_POSITIVE);
        r.scale_pow2(-1);
        assert_eq!(r.to_f64(), Rounded::Underflow);
    }
}
