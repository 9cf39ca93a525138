//! SISO transfer functions G(s) = N(s)/D(s)·e^{−τs}, and their interconnections.
//!
//! Book: §15.11 (zeros and poles, Def 15.11.2), §15.14, (15.14.7); delay (15.10.2);
//! feedback (15.18.4).

use crate::error::LtiError;
use crate::poly::{Conditions, Polynomial};
use num_complex::Complex64;
use std::fmt;

/// A single-input single-output transfer function G(s) = N(s)/D(s)·e^{−τs}.
///
/// # Conventions
/// Coefficients in descending powers (Matlab `tf(num, den)`); the delay τ ≥ 0 multiplies by
/// e^{−τs} (15.10.2). Common factors are *not* cancelled automatically: use
/// [`TransferFunction::minreal`] (15.14.15, 15.20.37).
///
/// Book: §15.11, §15.14, (15.14.7), (15.10.2).
#[derive(Debug, Clone, PartialEq)]
pub struct TransferFunction {
    num: Polynomial,
    den: Polynomial,
    delay: f64,
    roots: RootCache,
}

/// Zeros and poles, computed once per transfer function on first use (they depend on N and D
/// only, never on the delay); ignored by `==`.
#[derive(Debug, Clone, Default)]
struct RootCache(std::sync::OnceLock<(Vec<Complex64>, Vec<Complex64>)>);

impl PartialEq for RootCache {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl TransferFunction {
    /// G = num/den from coefficient slices in descending powers.
    ///
    /// # Errors
    /// [`LtiError::NonFinite`], or [`LtiError::ZeroDenominator`] when `den` is zero.
    pub fn new(num: &[f64], den: &[f64]) -> Result<Self, LtiError> {
        Self::from_polynomials(Polynomial::new(num)?, Polynomial::new(den)?)
    }

    /// G = N/D from polynomials.
    ///
    /// # Errors
    /// [`LtiError::ZeroDenominator`] when D = 0; [`LtiError::Overflow`] when a coefficient is
    /// not finite (an interconnection whose coefficients overflowed).
    pub fn from_polynomials(num: Polynomial, den: Polynomial) -> Result<Self, LtiError> {
        let num = num.checked("transfer-function numerator")?;
        let den = den.checked("transfer-function denominator")?;
        if den.is_zero() {
            return Err(LtiError::ZeroDenominator);
        }
        Ok(Self { num, den, delay: 0.0, roots: RootCache::default() })
    }

    /// The same N/D with another delay (internal: τ already valid).
    pub(crate) fn with_delay_unchecked(mut self, tau: f64) -> Self {
        self.delay = tau;
        self
    }

    /// The same transfer function times e^{−τs}.
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] unless τ is finite and ≥ 0.
    pub fn with_delay(mut self, tau: f64) -> Result<Self, LtiError> {
        if !(tau.is_finite() && tau >= 0.0) {
            return Err(LtiError::InvalidArgument {
                what: "delay",
                reason: format!("τ = {tau}; a delay must be finite and ≥ 0"),
            });
        }
        self.delay = tau;
        Ok(self)
    }

    /// The constant (static gain) transfer function k.
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] for a non-finite k.
    pub fn gain(k: f64) -> Result<Self, LtiError> {
        Self::new(&[k], &[1.0])
    }

    /// Numerator N(s).
    pub fn num(&self) -> &Polynomial {
        &self.num
    }

    /// Denominator D(s).
    pub fn den(&self) -> &Polynomial {
        &self.den
    }

    /// Delay τ (0 when none).
    pub fn delay(&self) -> f64 {
        self.delay
    }

    /// deg D − deg N (negative for an improper G). For the zero transfer function, deg D + 1.
    pub fn relative_degree(&self) -> isize {
        if self.num.is_zero() {
            return self.den.degree() as isize + 1;
        }
        self.den.degree() as isize - self.num.degree() as isize
    }

    /// True when deg N ≤ deg D.
    pub fn is_proper(&self) -> bool {
        self.relative_degree() >= 0
    }

    /// True when deg N < deg D.
    pub fn is_strictly_proper(&self) -> bool {
        self.relative_degree() > 0
    }

    /// Errors with [`LtiError::Improper`] unless proper.
    pub(crate) fn require_proper(&self, what: &'static str) -> Result<(), LtiError> {
        if self.is_proper() {
            Ok(())
        } else {
            Err(LtiError::Improper { num_degree: self.num.degree(), den_degree: self.den.degree(), what })
        }
    }

    /// Errors with [`LtiError::Delay`] if τ ≠ 0.
    pub(crate) fn require_rational(&self, what: &'static str) -> Result<(), LtiError> {
        if self.delay == 0.0 { Ok(()) } else { Err(LtiError::Delay { what, delay: self.delay }) }
    }

    /// Poles: roots of D (Def 15.11.2).
    ///
    /// # Errors
    /// [`LtiError::NoConvergence`] if the eigenvalue iteration fails.
    pub fn poles(&self) -> Result<Vec<Complex64>, LtiError> {
        Ok(self.roots()?.1.clone())
    }

    /// (zeros, poles), from the cache or computed (and cached) now.
    fn roots(&self) -> Result<&(Vec<Complex64>, Vec<Complex64>), LtiError> {
        if let Some(r) = self.roots.0.get() {
            return Ok(r);
        }
        let zeros = if self.num.is_zero() { Vec::new() } else { self.num.roots()? };
        let poles = self.den.roots()?;
        Ok(self.roots.0.get_or_init(|| (zeros, poles)))
    }

    /// Zeros: roots of N (Def 15.11.2); none for the zero transfer function.
    ///
    /// # Errors
    /// [`LtiError::NoConvergence`] if the eigenvalue iteration fails.
    pub fn zeros(&self) -> Result<Vec<Complex64>, LtiError> {
        Ok(self.roots()?.0.clone())
    }

    /// G(s) at a complex point from the coefficients: Horner's rule on N and D, times e^{−τs}.
    /// For |s| > 1 the form is chosen by conditioning: the polynomials in s, or the reversed
    /// polynomials in 1/s (where nothing overflows), whichever has the smaller condition number
    /// Σ|cᵢ||w|ⁱ/|p(w)|, so the value is accurate to a small multiple of ε times the better one
    /// (1/(s + 10³⁰⁰) at s = −10³⁰⁰ + j is −j, where 1/s would cancel to a false pole).
    ///
    /// # Degenerate inputs
    /// A plain function whose value at a pole is ∞, the exact value of a rational function
    /// there (python-control's `G(s)` and Matlab's `evalfr` return ∞ too, with NaN parts).
    /// At a finite s, ±∞ components come out in exactly two places (docs/robustness.md,
    /// "Where ∞ is the answer"):
    /// - at a pole (D(s) = 0 exactly in floating point) the value is the point at infinity in
    ///   the direction of the limit G(s + h), h → 0⁺ real (components ±∞, or 0 where the
    ///   direction has none; never NaN): 1/(s + 1) at s = −1 is +∞ + 0j;
    /// - where |G(s)| exceeds the f64 range, the point at infinity in the direction of G(s).
    ///
    /// Where N and D vanish together the limit is taken (a removable singularity gives its
    /// finite value). For G(jω) see [`TransferFunction::freqresp`].
    pub fn eval(&self, s: Complex64) -> Complex64 {
        use crate::axis::{cdiv, infinity_towards, taylor_leading};
        let (nc, dc) = (self.num.coeffs(), self.den.coeffs());
        let big = s.norm() > 1.0 && reversed_is_better(nc, dc, s);
        // z = s, or z = 1/s with p(s) = s^deg·Σ cᵢzⁱ
        let z = if big { cdiv(Complex64::new(1.0, 0.0), s) } else { s };
        let poly =
            |c: &[f64]| -> Vec<f64> { if big { c.iter().rev().copied().collect() } else { c.to_vec() } };
        let (pn, pd) = (poly(nc), poly(dc));
        let horner = |c: &[f64]| c.iter().fold(Complex64::new(0.0, 0.0), |acc, &x| acc * z + x);
        let k = if big { self.num.degree() as i32 - self.den.degree() as i32 } else { 0 };
        // v/|v| for v ≠ 0, scaled by the larger component first so that |v| neither overflows
        // nor underflows; an infinite component counts as the whole direction
        let unit = |v: Complex64| {
            let sat = |x: f64| if x.is_infinite() { x.signum() } else { 0.0 };
            let w = if v.re.is_infinite() || v.im.is_infinite() {
                Complex64::new(sat(v.re), sat(v.im))
            } else {
                v / v.re.abs().max(v.im.abs())
            };
            w / w.norm()
        };
        let (nv, dv) = (horner(&pn), horner(&pd));
        let zero = Complex64::new(0.0, 0.0);
        // q = a/b with its order at z, and the direction of q from a and b (q itself may
        // overflow: 1e300/(s + 1e-300) at 0 is 1e600, whose direction is still +1)
        let (q, q_dir, order) = if dv != zero || self.num.is_zero() {
            if self.num.is_zero() { (zero, zero, 0) } else { (cdiv(nv, dv), unit(nv) * unit(dv).conj(), 0) }
        } else {
            // D(s) = 0: orders and leading Taylor coefficients at z
            let (a, ta) = taylor_leading(&pn, z).unwrap_or((0, zero));
            let (b, tb) = taylor_leading(&pd, z).unwrap_or((0, Complex64::new(1.0, 0.0)));
            (cdiv(ta, tb), unit(ta) * unit(tb).conj(), a as i32 - b as i32)
        };
        // s + h ↦ z: z − z₀ ≈ −h/s² for the reversed variable
        let approach = if big { unit(-(z * z)) } else { Complex64::new(1.0, 0.0) };
        let delay = if self.delay == 0.0 { Complex64::new(1.0, 0.0) } else { (-self.delay * s).exp() };
        if order > 0 || q == zero {
            return zero;
        }
        let dir = || q_dir * approach.powi(order) * unit(s).powi(k) * Complex64::from_polar(1.0, delay.arg());
        if order < 0 {
            return infinity_towards(dir());
        }
        // q·sᵏ one factor at a time (s for k > 0, z = 1/s for k < 0), so that neither sᵏ
        // overflows nor s⁻ᵏ underflows before the product is formed
        let v = (0..k.unsigned_abs()).fold(q, |v, _| if k > 0 { v * s } else { v * z }) * delay;
        if v.re.is_finite() && v.im.is_finite() { v } else { infinity_towards(dir()) }
    }

    /// The DC gain G(0), `None` when G has a pole at 0 (and N(0) ≠ 0), or when |N(0)/D(0)|
    /// exceeds the f64 range ((s + 1e300)/(s + 1e-300) used to give `Some(∞)`).
    pub fn dc_gain(&self) -> Option<f64> {
        let (n0, d0) = (self.num.eval(0.0), self.den.eval(0.0));
        if d0 == 0.0 {
            if n0 == 0.0 { self.minreal(1e-9).ok()?.dc_gain() } else { None }
        } else {
            Some(n0 / d0).filter(|g| g.is_finite())
        }
    }

    /// −G.
    pub fn neg(&self) -> Self {
        Self {
            num: self.num.scaled(-1.0),
            den: self.den.clone(),
            delay: self.delay,
            roots: RootCache::default(),
        }
    }

    /// c·G.
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] for a NaN or infinite c; [`LtiError::Overflow`] when a
    /// coefficient of c·N overflows.
    pub fn scale(&self, c: f64) -> Result<Self, LtiError> {
        Ok(Self::from_polynomials(self.num.scale(c)?, self.den.clone())?.with_delay_unchecked(self.delay))
    }

    /// Series connection G₂G₁ (delays add).
    ///
    /// # Errors
    /// [`LtiError::Overflow`] when a coefficient of N₁N₂ or D₁D₂ overflows.
    pub fn series(&self, g2: &Self) -> Result<Self, LtiError> {
        let g = Self::from_polynomials(self.num.times(&g2.num), self.den.times(&g2.den))?;
        Ok(g.with_delay_unchecked(self.delay + g2.delay))
    }

    /// Parallel connection G₁ + G₂.
    ///
    /// # Errors
    /// [`LtiError::Delay`] when the delays differ (the sum is not rational times one delay);
    /// [`LtiError::Overflow`] when a coefficient overflows.
    pub fn parallel(&self, g2: &Self) -> Result<Self, LtiError> {
        if self.delay != g2.delay {
            return Err(LtiError::Delay { what: "parallel connection", delay: self.delay.max(g2.delay) });
        }
        let num = self.num.times(&g2.den).plus(&g2.num.times(&self.den));
        Ok(Self::from_polynomials(num, self.den.times(&g2.den))?.with_delay_unchecked(self.delay))
    }

    /// Negative feedback G/(1 + GH) (H in the return path); with H = 1 this is the closed
    /// loop T = L/(1 + L), and S = 1/(1 + L) of (15.18.4) is `one.feedback(&l)`.
    ///
    /// Book: (15.18.4).
    ///
    /// # Errors
    /// [`LtiError::Delay`] with a delay in the loop; [`LtiError::ZeroDenominator`] when
    /// 1 + GH ≡ 0; [`LtiError::Overflow`] when a coefficient overflows.
    pub fn feedback(&self, h: &Self) -> Result<Self, LtiError> {
        self.require_rational("feedback")?;
        h.require_rational("feedback")?;
        // G/(1+GH) = N_g D_h / (D_g D_h + N_g N_h)
        let num = self.num.times(&h.den);
        let den = self.den.times(&h.den).plus(&self.num.times(&h.num));
        Self::from_polynomials(num, den)
    }

    /// Sensitivity S = 1/(1 + L) of the loop L = self.
    ///
    /// Book: (15.18.4), (15.18.8).
    ///
    /// # Errors
    /// As [`TransferFunction::feedback`].
    pub fn sensitivity(&self) -> Result<Self, LtiError> {
        Self::gain(1.0)?.feedback(self)
    }

    /// G(s/a) with numerator and denominator scaled so that time runs a times faster
    /// (ω ↦ aω in the frequency response; the delay τ becomes τ/a).
    ///
    /// The coefficients cₖa⁻ᵏ are formed as mantissa times a power of two and both N and D are
    /// multiplied by the one power of two that makes the largest coefficient of D about 1
    /// (the ratio is unchanged), so that a leading coefficient such as a⁻² = 10⁻⁶⁰⁰ for
    /// a = 10³⁰⁰ does not underflow to zero and drop the degree. Where that power of two
    /// overflows a coefficient of N or underflows one to 0, the largest coefficient of N and D
    /// is put just below the overflow threshold instead.
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] unless a is finite and > 0; [`LtiError::Overflow`] when the
    /// coefficients cₖa⁻ᵏ of N and D together span more than the f64 exponent range (no common
    /// power of two keeps every nonzero one finite and nonzero: the degree would change), or
    /// the delay τ/a exceeds the f64 range.
    pub fn time_scaled(&self, a: f64) -> Result<Self, LtiError> {
        if !(a.is_finite() && a > 0.0) {
            return Err(LtiError::InvalidArgument {
                what: "time scale",
                reason: format!("a = {a}; need a > 0"),
            });
        }
        // a = m·2ᵉ with m ∈ [1, 2): cₖa⁻ᵏ = (cₖm⁻ᵏ)·2^{−ke}
        let e = crate::axis::exponent(a);
        let m = crate::axis::mul_pow2(a, -e);
        let parts = |p: &Polynomial| -> Vec<(f64, i32)> {
            let n = p.degree();
            p.coeffs()
                .iter()
                .enumerate()
                .map(|(i, &c)| {
                    // c = c̃·2^{e_c} with |c̃| ∈ [1, 2) first, so that a subnormal c does not
                    // underflow to 0 when multiplied by m⁻ᵏ
                    let ec = if c == 0.0 { 0 } else { crate::axis::exponent(c) };
                    let k = (n - i) as i32;
                    (crate::axis::mul_pow2(c, -ec) * m.powi(-k), ec - k * e)
                })
                .collect()
        };
        let (pn, pd) = (parts(&self.num), parts(&self.den));
        // the binary exponent of each nonzero coefficient cₖa⁻ᵏ
        let exps = |v: &[(f64, i32)]| -> Vec<i32> {
            v.iter().filter(|(c, _)| *c != 0.0).map(|&(c, k)| crate::axis::exponent(c) + k).collect()
        };
        let (en, ed) = (exps(&pn), exps(&pd));
        // N and D multiplied by 2^shift; None where a nonzero coefficient would underflow to 0
        // or overflow (the ratio N/D is kept, but not the polynomial)
        let build = |v: &[(f64, i32)], shift: i32| -> Option<Polynomial> {
            let c: Vec<f64> = v.iter().map(|&(c, k)| crate::axis::mul_pow2(c, k + shift)).collect();
            let exact = c.iter().zip(v).all(|(x, (c0, _))| x.is_finite() && (*x != 0.0 || *c0 == 0.0));
            exact.then(|| Polynomial::from_vec(c))
        };
        // first choice: the largest coefficient of D near 1; else the largest coefficient of
        // N or D just below the overflow threshold, which keeps the most of the small ones
        let shift_d = -ed.iter().copied().max().unwrap_or(0);
        let shift_top = 1022 - en.iter().chain(&ed).copied().max().unwrap_or(0);
        let (num, den) = [shift_d, shift_top]
            .into_iter()
            .find_map(|sh| Some((build(&pn, sh)?, build(&pd, sh)?)))
            .ok_or(LtiError::Overflow {
                what: "time-scaled coefficients (cₖa⁻ᵏ span more than the f64 exponent range)",
            })?;
        let tau = self.delay / a;
        if !tau.is_finite() {
            return Err(LtiError::Overflow { what: "time-scaled delay" });
        }
        Ok(Self::from_polynomials(num, den)?.with_delay_unchecked(tau))
    }
}

impl fmt::Display for TransferFunction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}) / ({})", self.num, self.den)?;
        if self.delay != 0.0 {
            write!(f, " · exp(-{} s)", self.delay)?;
        }
        Ok(())
    }
}

/// For |s| > 1: whether N/D is better evaluated in z = 1/s (reversed coefficients) than in s:
/// the form with the smaller summed condition number of N and D ([`Conditions`]), the direct
/// one when it finds D exactly zero (a pole) and the reversed one has no correct digit in D.
/// Large s near a root of large coefficients (1/(s + 1e300) at s = −1e300 + j) needs the
/// direct form, large s far from the roots of small ones the reversed form.
fn reversed_is_better(nc: &[f64], dc: &[f64], s: Complex64) -> bool {
    let z = crate::axis::cdiv(Complex64::new(1.0, 0.0), s);
    let (dd, dr) = (Conditions::direct(dc, s), Conditions::reversed(dc, z));
    let (nd, nr) = if nc.iter().all(|&x| x == 0.0) {
        (0.0, 0.0)
    } else {
        (Conditions::direct(nc, s).cond, Conditions::reversed(nc, z).cond)
    };
    let pole = dd.value == Complex64::new(0.0, 0.0) && dd.better_than(&dr);
    !pole && nd + dd.cond >= nr + dr.cond
}
