//! Real polynomials in s, coefficients in descending powers as Matlab's `num`/`den`.
//!
//! Book: §15.18, (15.18.7); Matlab `roots`/`poly` in 15.20.5.

use crate::error::{LtiError, check_finite};
use num_complex::Complex64;
use std::fmt;

mod roots;

/// A real polynomial p(s) = c₀sⁿ + c₁sⁿ⁻¹ + … + cₙ, stored in descending powers (Matlab's
/// convention, so `[1, 3, 5, −2]` is s³ + 3s² + 5s − 2 as in 15.20.5).
///
/// The leading coefficient is nonzero unless the polynomial is zero, which is stored as `[0]`.
///
/// Book: §15.18, (15.18.7).
#[derive(Debug, Clone, PartialEq)]
pub struct Polynomial {
    coeffs: Vec<f64>,
}

/// Relative tolerance for trimming leading coefficients made of round-off: 16ε.
pub const TRIM_RTOL: f64 = 16.0 * f64::EPSILON;

impl Polynomial {
    /// A polynomial from coefficients in descending powers; exact leading zeros are removed.
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] for a NaN or infinite coefficient.
    pub fn new(coeffs: &[f64]) -> Result<Self, LtiError> {
        check_finite("polynomial coefficients", coeffs)?;
        Ok(Self::from_vec(coeffs.to_vec()))
    }

    /// Internal constructor for finite coefficients.
    pub(crate) fn from_vec(mut coeffs: Vec<f64>) -> Self {
        let first = coeffs.iter().position(|&c| c != 0.0).unwrap_or(coeffs.len().saturating_sub(1));
        coeffs.drain(..first);
        if coeffs.is_empty() {
            coeffs.push(0.0);
        }
        Self { coeffs }
    }

    /// The constant polynomial c.
    pub fn constant(c: f64) -> Self {
        Self::from_vec(vec![c])
    }

    /// The polynomial s.
    pub fn s() -> Self {
        Self { coeffs: vec![1.0, 0.0] }
    }

    /// The monic polynomial ∏(s − rᵢ) with real coefficients (Matlab `poly`). Every complex
    /// root must come with its exact conjugate (as the root finders of this crate return them);
    /// each pair is multiplied in as the real quadratic s² − 2 Re r·s + |r|².
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] for a non-finite root; [`LtiError::UnpairedComplexRoot`] for a
    /// complex root whose conjugate is missing (a real polynomial cannot have it: `[1 + 1j]`
    /// alone used to give s − 1); [`LtiError::Overflow`] when a coefficient overflows.
    pub fn from_roots(roots: &[Complex64]) -> Result<Self, LtiError> {
        if roots.iter().any(|r| !(r.re.is_finite() && r.im.is_finite())) {
            return Err(LtiError::NonFinite { what: "roots" });
        }
        // pair every root of positive imaginary part with an unused exact conjugate
        let mut used = vec![false; roots.len()];
        let mut c = vec![1.0];
        for i in 0..roots.len() {
            if used[i] {
                continue;
            }
            let r = roots[i];
            used[i] = true;
            if r.im == 0.0 {
                c = Self::from_vec(c).times(&Self { coeffs: vec![1.0, -r.re] }).coeffs;
                continue;
            }
            let Some(j) = (0..roots.len()).find(|&j| !used[j] && roots[j] == r.conj()) else {
                return Err(LtiError::UnpairedComplexRoot { what: "roots", re: r.re, im: r.im });
            };
            used[j] = true;
            // (s − r)(s − r̄) = s² − 2 Re r·s + |r|²
            let quad = Self { coeffs: vec![1.0, -2.0 * r.re, r.re * r.re + r.im * r.im] };
            c = Self::from_vec(c).times(&quad).coeffs;
        }
        let p = Self::from_vec(c);
        p.checked("polynomial from roots")
    }

    /// Self, or [`LtiError::Overflow`] when a coefficient is not finite.
    pub(crate) fn checked(self, what: &'static str) -> Result<Self, LtiError> {
        if self.coeffs.iter().all(|c| c.is_finite()) { Ok(self) } else { Err(LtiError::Overflow { what }) }
    }

    /// Coefficients in descending powers.
    pub fn coeffs(&self) -> &[f64] {
        &self.coeffs
    }

    /// Degree (0 for constants, including the zero polynomial).
    pub fn degree(&self) -> usize {
        self.coeffs.len() - 1
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.coeffs.iter().all(|&c| c == 0.0)
    }

    /// Leading coefficient c₀.
    pub fn leading(&self) -> f64 {
        self.coeffs[0]
    }

    /// Coefficient of sᵏ (0 beyond the degree).
    pub fn coeff(&self, k: usize) -> f64 {
        if k > self.degree() { 0.0 } else { self.coeffs[self.degree() - k] }
    }

    /// Largest coefficient magnitude.
    pub fn norm_inf(&self) -> f64 {
        self.coeffs.iter().fold(0.0f64, |m, c| m.max(c.abs()))
    }

    /// Drops leading coefficients with |cᵢ| ≤ rtol·max|c| (round-off left by ss → tf, notes
    /// §3.3: a leading 1.1e-16 gave a spurious zero at −1.04e16 in 15.20.42).
    pub fn trim(&self, rtol: f64) -> Self {
        let tol = rtol * self.norm_inf();
        // kept unless |c| ≤ tol: with a NaN rtol nothing is dropped
        let keep = |c: &f64| c.abs() > tol || tol.is_nan() || c.is_nan();
        let first = self.coeffs.iter().position(keep).unwrap_or(self.coeffs.len() - 1);
        Self::from_vec(self.coeffs[first..].to_vec())
    }

    /// The same polynomial divided by its leading coefficient.
    ///
    /// # Errors
    /// [`LtiError::ZeroPolynomial`] for the zero polynomial; [`LtiError::Overflow`] when a
    /// quotient overflows.
    pub fn monic(&self) -> Result<Self, LtiError> {
        if self.is_zero() {
            return Err(LtiError::ZeroPolynomial { what: "monic" });
        }
        let l = self.leading();
        Self::from_vec(self.coeffs.iter().map(|x| x / l).collect()).checked("monic polynomial")
    }

    /// c·p(s).
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] for a non-finite c; [`LtiError::Overflow`].
    pub fn scale(&self, c: f64) -> Result<Self, LtiError> {
        check_finite("scale factor", [&c])?;
        self.scaled(c).checked("scaled polynomial")
    }

    /// c·p(s) (internal: the caller checks the result where it can overflow).
    pub(crate) fn scaled(&self, c: f64) -> Self {
        Self::from_vec(self.coeffs.iter().map(|x| x * c).collect())
    }

    /// p(x) at a real point: Horner's rule, on the reversed polynomial in 1/x for |x| > 1 so
    /// that intermediate powers never overflow (±∞ only when the value itself does): xⁿ·r(1/x)
    /// is formed by n multiplications of r by x, whose magnitudes only grow, so that a tiny
    /// leading coefficient (5e-324 x² + x + 1 at 10³⁰⁰) does not meet an overflowed xⁿ.
    ///
    /// # Degenerate inputs
    /// This is a plain function on the extended reals (numpy's `polyval` gives the same
    /// values); ±∞ comes out in exactly two places (docs/robustness.md, "Where ∞ is the
    /// answer"):
    /// - at x = ±∞ the value is the limit of p(x): c₀·(±∞)ⁿ, that is ±∞ with the sign of
    ///   c₀·(±1)ⁿ for n ≥ 1, the constant c₀ for n = 0, and 0 for the zero polynomial;
    /// - at a finite x where |p(x)| exceeds f64::MAX the value is ±∞ with the sign of p(x).
    ///
    /// NaN gives NaN.
    pub fn eval(&self, x: f64) -> f64 {
        if x.abs() <= 1.0 {
            return self.coeffs.iter().fold(0.0, |acc, &c| acc * x + c);
        }
        let y = 1.0 / x;
        let r = self.coeffs.iter().rev().fold(0.0, |acc, &c| acc * y + c);
        if r == 0.0 {
            return 0.0;
        }
        // p(x) = xⁿ·r(1/x), multiplied in one x at a time (|x| > 1: no premature overflow;
        // at x = ±∞, r = c₀ and the product is the limit c₀·(±∞)ⁿ; NaN stays NaN)
        (0..self.degree()).fold(r, |v, _| v * x)
    }

    /// p(s) at a complex point (Horner; on the reversed polynomial at 1/s for |s| > 1). A value
    /// beyond the f64 range is the point at infinity in its direction (never NaN).
    pub fn eval_c(&self, s: Complex64) -> Complex64 {
        if s.norm_sqr() <= 1.0 {
            return self.coeffs.iter().fold(Complex64::new(0.0, 0.0), |acc, &c| acc * s + c);
        }
        let z = crate::axis::cdiv(Complex64::new(1.0, 0.0), s);
        // the form with the smaller condition number ([`Conditions`]): s + 1e300 at −1e300 + j
        // is j in s, while 1e300·(1/s) + 1 cancels to 0
        let (direct, reversed) = (Conditions::direct(&self.coeffs, s), Conditions::reversed(&self.coeffs, z));
        if direct.better_than(&reversed) {
            return direct.value;
        }
        let r = self.coeffs.iter().rev().fold(Complex64::new(0.0, 0.0), |acc, &c| acc * z + c);
        if r.re == 0.0 && r.im == 0.0 {
            return r;
        }
        // sⁿ·r(1/s), one factor s at a time (|s| > 1: the magnitudes only grow)
        let v = (0..self.degree()).fold(r, |v, _| v * s);
        if v.re.is_finite() && v.im.is_finite() {
            v
        } else {
            let dir = r / r.norm() * (s / s.norm()).powi(self.degree() as i32);
            crate::axis::infinity_towards(dir)
        }
    }

    /// p(s) and p′(s) together at a complex point.
    pub(crate) fn eval_with_derivative(&self, s: Complex64) -> (Complex64, Complex64) {
        let mut p = Complex64::new(0.0, 0.0);
        let mut dp = Complex64::new(0.0, 0.0);
        for &c in &self.coeffs {
            dp = dp * s + p;
            p = p * s + c;
        }
        (p, dp)
    }

    /// The derivative p′(s).
    ///
    /// # Errors
    /// [`LtiError::Overflow`] when a coefficient k·cₖ overflows.
    pub fn derivative(&self) -> Result<Self, LtiError> {
        self.deriv().checked("derivative")
    }

    /// p′(s) (internal).
    pub(crate) fn deriv(&self) -> Self {
        let n = self.degree();
        if n == 0 {
            return Self::constant(0.0);
        }
        Self::from_vec(self.coeffs[..n].iter().enumerate().map(|(i, c)| c * (n - i) as f64).collect())
    }

    /// p(s) + q(s).
    ///
    /// # Errors
    /// [`LtiError::Overflow`] when a sum overflows.
    pub fn add(&self, q: &Self) -> Result<Self, LtiError> {
        self.plus(q).checked("polynomial sum")
    }

    /// p(s) − q(s).
    ///
    /// # Errors
    /// [`LtiError::Overflow`] when a difference overflows.
    pub fn sub(&self, q: &Self) -> Result<Self, LtiError> {
        self.minus(q).checked("polynomial difference")
    }

    /// p(s)·q(s).
    ///
    /// # Errors
    /// [`LtiError::Overflow`] when a coefficient of the product overflows.
    pub fn mul(&self, q: &Self) -> Result<Self, LtiError> {
        self.times(q).checked("polynomial product")
    }

    /// p + q (internal).
    pub(crate) fn plus(&self, q: &Self) -> Self {
        let n = self.coeffs.len().max(q.coeffs.len());
        let get = |p: &Self, i: usize| {
            let off = n - p.coeffs.len();
            if i < off { 0.0 } else { p.coeffs[i - off] }
        };
        Self::from_vec((0..n).map(|i| get(self, i) + get(q, i)).collect())
    }

    /// p − q (internal).
    pub(crate) fn minus(&self, q: &Self) -> Self {
        self.plus(&q.scaled(-1.0))
    }

    /// p·q (internal).
    pub(crate) fn times(&self, q: &Self) -> Self {
        let mut c = vec![0.0; self.coeffs.len() + q.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            for (j, b) in q.coeffs.iter().enumerate() {
                c[i + j] += a * b;
            }
        }
        Self::from_vec(c)
    }

    /// p(a·s): scales the variable (time scaling of a transfer function).
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] for a non-finite a; [`LtiError::Overflow`].
    pub fn scale_variable(&self, a: f64) -> Result<Self, LtiError> {
        check_finite("variable scale", [&a])?;
        self.scaled_variable(a).checked("polynomial in a scaled variable")
    }

    /// p(a·s) (internal).
    pub(crate) fn scaled_variable(&self, a: f64) -> Self {
        let n = self.degree();
        Self::from_vec(self.coeffs.iter().enumerate().map(|(i, c)| c * a.powi((n - i) as i32)).collect())
    }

    /// Number of exact roots at s = 0 (trailing zero coefficients).
    pub fn zero_roots(&self) -> usize {
        if self.is_zero() {
            return 0;
        }
        self.coeffs.iter().rev().take_while(|&&c| c == 0.0).count()
    }
}

impl fmt::Display for Polynomial {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.degree();
        let mut first = true;
        for (i, &c) in self.coeffs.iter().enumerate() {
            let k = n - i;
            if c == 0.0 && !(first && k == 0) {
                continue;
            }
            let sign = if c < 0.0 { "-" } else { "+" };
            if first {
                if c < 0.0 {
                    write!(f, "-")?;
                }
            } else {
                write!(f, " {sign} ")?;
            }
            let a = c.abs();
            match k {
                0 => write!(f, "{a}")?,
                _ if a == 1.0 => {}
                _ => write!(f, "{a}")?,
            }
            match k {
                0 => {}
                1 => write!(f, "s")?,
                _ => write!(f, "s^{k}")?,
            }
            first = false;
        }
        Ok(())
    }
}

/// Horner's value of a polynomial at w and its condition number Σ|cᵢ||w|ⁱ/|p(w)| (Higham,
/// *Accuracy and Stability of Numerical Algorithms*, §5.1: the relative error of the value is a
/// small multiple of ε times it), for choosing between the polynomial in s and the reversed one
/// in z = 1/s when |s| > 1.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Conditions {
    /// The Horner value (of the reversed polynomial for the reversed form).
    pub value: Complex64,
    /// The condition number, +∞ when the value is 0 or a sum overflowed (never NaN).
    pub cond: f64,
}

impl Conditions {
    fn of<'a>(c: impl Iterator<Item = &'a f64>, w: Complex64, weight: f64) -> Self {
        let aw = w.norm();
        let (value, m) = c.fold((Complex64::new(0.0, 0.0), 0.0), |(v, m), &x| (v * w + x, m * aw + x.abs()));
        let k = weight * m / value.norm();
        Self { value, cond: if k.is_finite() { k } else { f64::INFINITY } }
    }

    /// The polynomial (descending `c`) in s.
    pub(crate) fn direct(c: &[f64], s: Complex64) -> Self {
        Self::of(c.iter(), s, 1.0)
    }

    /// The reversed polynomial in z = 1/s; the rounding of 1/s is counted as half the
    /// condition number again.
    pub(crate) fn reversed(c: &[f64], z: Complex64) -> Self {
        Self::of(c.iter().rev(), z, 1.5)
    }

    /// Whether this (direct) form is to be used rather than `reversed`: the smaller condition
    /// number, ties to the reversed form (where nothing overflows); and an exact zero of the
    /// direct form is believed when the reversed form has no correct digit (condition number
    /// ≥ 1/ε): direct sums of exact coefficients at an exact point cancel exactly (Sterbenz),
    /// while 1/s is already rounded.
    pub(crate) fn better_than(&self, reversed: &Self) -> bool {
        let exact_zero = self.value == Complex64::new(0.0, 0.0);
        (exact_zero && reversed.cond * f64::EPSILON >= 1.5) || self.cond < reversed.cond
    }
}
