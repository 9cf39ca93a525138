//! Real polynomials in s, coefficients in descending powers as Matlab's `num`/`den`.
//!
//! Book: §15.18, (15.18.7); Matlab `roots`/`poly` in 15.20.5.

use crate::error::{LtiError, check_finite};
use crate::linalg;
use nalgebra::DMatrix;
use num_complex::Complex64;
use std::fmt;

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

    /// The monic polynomial ∏(s − rᵢ) with real coefficients (Matlab `poly`); complex roots
    /// must come in conjugate pairs, and the imaginary round-off of the product is dropped.
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] for a non-finite root.
    pub fn from_roots(roots: &[Complex64]) -> Result<Self, LtiError> {
        if roots.iter().any(|r| !(r.re.is_finite() && r.im.is_finite())) {
            return Err(LtiError::NonFinite { what: "roots" });
        }
        let mut c = vec![Complex64::new(1.0, 0.0)];
        for r in roots {
            let mut next = vec![Complex64::new(0.0, 0.0); c.len() + 1];
            for (k, ck) in c.iter().enumerate() {
                next[k] += ck;
                next[k + 1] -= ck * r;
            }
            c = next;
        }
        Ok(Self::from_vec(c.iter().map(|z| z.re).collect()))
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
        let first = self.coeffs.iter().position(|c| c.abs() > tol).unwrap_or(self.coeffs.len() - 1);
        Self::from_vec(self.coeffs[first..].to_vec())
    }

    /// The same polynomial divided by its leading coefficient (unchanged if zero).
    pub fn monic(&self) -> Self {
        let l = self.leading();
        if l == 0.0 { self.clone() } else { self.scale(1.0 / l) }
    }

    /// c·p(s).
    pub fn scale(&self, c: f64) -> Self {
        Self::from_vec(self.coeffs.iter().map(|x| x * c).collect())
    }

    /// p(x) at a real point (Horner).
    pub fn eval(&self, x: f64) -> f64 {
        self.coeffs.iter().fold(0.0, |acc, &c| acc * x + c)
    }

    /// p(s) at a complex point (Horner).
    pub fn eval_c(&self, s: Complex64) -> Complex64 {
        self.coeffs.iter().fold(Complex64::new(0.0, 0.0), |acc, &c| acc * s + c)
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
    pub fn derivative(&self) -> Self {
        let n = self.degree();
        if n == 0 {
            return Self::constant(0.0);
        }
        Self::from_vec(self.coeffs[..n].iter().enumerate().map(|(i, c)| c * (n - i) as f64).collect())
    }

    /// p(s) + q(s).
    pub fn add(&self, q: &Self) -> Self {
        let n = self.coeffs.len().max(q.coeffs.len());
        let get = |p: &Self, i: usize| {
            let off = n - p.coeffs.len();
            if i < off { 0.0 } else { p.coeffs[i - off] }
        };
        Self::from_vec((0..n).map(|i| get(self, i) + get(q, i)).collect())
    }

    /// p(s) − q(s).
    pub fn sub(&self, q: &Self) -> Self {
        self.add(&q.scale(-1.0))
    }

    /// p(s)·q(s).
    pub fn mul(&self, q: &Self) -> Self {
        let mut c = vec![0.0; self.coeffs.len() + q.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            for (j, b) in q.coeffs.iter().enumerate() {
                c[i + j] += a * b;
            }
        }
        Self::from_vec(c)
    }

    /// p(a·s): scales the variable (time scaling of a transfer function).
    pub fn scale_variable(&self, a: f64) -> Self {
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

    /// The roots, from the eigenvalues of the balanced companion matrix (faer) followed by
    /// Newton polishing on p itself; exact roots at 0 are returned exactly, real roots have
    /// zero imaginary part and complex roots come in exact conjugate pairs.
    ///
    /// # Conventions
    /// Repeated roots are found to about ε^{1/q} relative accuracy for multiplicity q (a
    /// property of the problem, not of the method): (s+1)² gives −1 ± ~1e-8j.
    ///
    /// Book: 15.20.5 (`roots(p)` equals `eig` of the companion matrix).
    ///
    /// # Errors
    /// [`LtiError::NoConvergence`] if the eigenvalue iteration fails.
    pub fn roots(&self) -> Result<Vec<Complex64>, LtiError> {
        let z = self.zero_roots();
        let core = Self::from_vec(self.coeffs[..self.coeffs.len() - z].to_vec());
        let n = core.degree();
        let mut roots = vec![Complex64::new(0.0, 0.0); z];
        if n == 0 {
            return Ok(roots);
        }
        if n == 1 {
            roots.push(Complex64::new(-core.coeffs[1] / core.coeffs[0], 0.0));
            return Ok(linalg::tidy_conjugates(roots, 1.0));
        }
        // Companion matrix (15.7.3) of the monic polynomial: top row −c₁/c₀ … −cₙ/c₀.
        let c0 = core.coeffs[0];
        let comp = DMatrix::from_fn(n, n, |i, j| {
            if i == 0 {
                -core.coeffs[j + 1] / c0
            } else if i == j + 1 {
                1.0
            } else {
                0.0
            }
        });
        let raw = linalg::eigenvalues_hessenberg(&comp)?;
        // Newton polishing helps simple roots; inside a cluster (a multiple root split by
        // roundoff into ~ε^{1/k}) it moves the members unevenly and spoils their mean, which
        // the QR iteration gets right to O(ε) (the trace), so clusters are left as computed.
        for (i, &r) in raw.iter().enumerate() {
            let near = raw
                .iter()
                .enumerate()
                .any(|(j, &o)| j != i && (o - r).norm_sqr() <= 1e-6 * r.norm_sqr().max(1.0));
            roots.push(if near { r } else { core.polish(r) });
        }
        Ok(linalg::tidy_conjugates(roots, core.norm_inf() / c0.abs()))
    }

    /// A few Newton steps on p from `r`, kept only while |p| decreases.
    fn polish(&self, r: Complex64) -> Complex64 {
        let mut best = r;
        let (mut pb, mut db) = self.eval_with_derivative(r);
        for _ in 0..4 {
            if db.norm_sqr() == 0.0 || pb.norm_sqr() == 0.0 {
                break;
            }
            let next = best - pb / db;
            let (pn, dn) = self.eval_with_derivative(next);
            // |·|² orders like |·| without hypot (an under- or overflowed square stops early)
            if pn.norm_sqr() < pb.norm_sqr() {
                (best, pb, db) = (next, pn, dn);
            } else {
                break;
            }
        }
        best
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
