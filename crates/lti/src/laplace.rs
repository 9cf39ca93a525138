//! Partial fractions, inverse Laplace transforms in real form, and the initial- and
//! final-value theorems, done on the polynomials rather than by taking limits numerically.
//!
//! Book: §15.10–15.13, Fact 15.12.1–15.12.2, Fact 15.13.1, Ex 15.11.4, 15.20.17–31;
//! notes §3.9.

use crate::error::LtiError;
use crate::poly::Polynomial;
use crate::tf::TransferFunction;
use num_complex::Complex64;

/// Default relative tolerance for treating computed roots as one repeated root: repeated
/// roots of multiplicity q split by about ε^{1/q} (notes §3.2), so 1e-5 covers q ≤ 3.
pub const CLUSTER_RTOL: f64 = 1e-5;

/// One term r/(s − p)ᵏ of a partial-fraction expansion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PfTerm {
    /// The pole p.
    pub pole: Complex64,
    /// The power k ≥ 1.
    pub power: usize,
    /// The residue r.
    pub residue: Complex64,
}

/// G(s) = Q(s) + Σ rᵢ/(s − pᵢ)^{kᵢ} (Matlab `residue`), poles grouped by multiplicity.
///
/// Book: §15.11, Ex 15.11.4, 15.20.17–26.
#[derive(Debug, Clone, PartialEq)]
pub struct PartialFractions {
    /// The polynomial part Q (zero for strictly proper G).
    pub direct: Polynomial,
    /// Terms, one per (pole, power).
    pub terms: Vec<PfTerm>,
}

/// Groups roots whose distance is within `rtol·max(1, |r|)` and returns (mean, multiplicity).
pub fn cluster_roots(roots: &[Complex64], rtol: f64) -> Vec<(Complex64, usize)> {
    let mut groups: Vec<(Complex64, usize)> = Vec::new();
    let mut members: Vec<Vec<Complex64>> = Vec::new();
    for r in roots {
        let found = groups.iter().position(|(c, _)| (c - r).norm() <= rtol * r.norm().max(1.0));
        match found {
            Some(i) => {
                members[i].push(*r);
                let m = &members[i];
                // the mean as Σ(r/q): no overflow for members near f64::MAX
                groups[i] = (m.iter().map(|z| z / m.len() as f64).sum::<Complex64>(), m.len());
            }
            None => {
                groups.push((*r, 1));
                members.push(vec![*r]);
            }
        }
    }
    for g in groups.iter_mut() {
        if g.0.im.abs() <= rtol * g.0.norm().max(1.0) * 1e-3 {
            g.0.im = 0.0;
        }
    }
    groups
}

/// Truncated power series in e (coefficients ascending), complex.
fn series_mul(a: &[Complex64], b: &[Complex64], order: usize) -> Vec<Complex64> {
    let mut c = vec![Complex64::new(0.0, 0.0); order];
    for (i, ai) in a.iter().enumerate().take(order) {
        for (j, bj) in b.iter().enumerate().take(order - i) {
            c[i + j] += ai * bj;
        }
    }
    c
}

impl TransferFunction {
    /// Partial fractions with repeated poles: for a pole p of multiplicity q,
    /// r_k = (1/(q−k)!) d^{q−k}/ds^{q−k}[(s − p)^q G(s)] at s = p, computed by Taylor series
    /// about p. Poles closer than `rtol` (relative) are one repeated pole.
    ///
    /// Book: §15.11, Ex 15.11.4.
    ///
    /// # Errors
    /// [`LtiError::Delay`] for a delayed G; [`LtiError::InvalidArgument`] unless `rtol` is
    /// finite and ≥ 0; root-finding errors.
    pub fn partial_fractions(&self, rtol: f64) -> Result<PartialFractions, LtiError> {
        self.require_rational("partial fractions")?;
        crate::error::check_tolerance("pole clustering tolerance", rtol)?;
        let (q, r) = divide(self.num(), self.den());
        let lead = self.den().leading();
        let groups = cluster_roots(&self.den().roots()?, rtol);
        let mut terms = Vec::new();
        for (gi, &(p, mult)) in groups.iter().enumerate() {
            // Taylor series of R(p + e)/lead about e = 0, to order mult.
            let mut rs = taylor(&r, p, mult);
            rs.iter_mut().for_each(|c| *c /= lead);
            for (gj, &(pj, mj)) in groups.iter().enumerate() {
                if gi == gj {
                    continue;
                }
                // 1/(p − pj + e) = Σ (−1)ᵏ eᵏ/a^{k+1}, a = p − pj; raised to the power mj.
                let a = p - pj;
                let inv: Vec<Complex64> =
                    (0..mult).map(|k| (if k % 2 == 0 { 1.0 } else { -1.0 }) / a.powu(k as u32 + 1)).collect();
                for _ in 0..mj {
                    rs = series_mul(&rs, &inv, mult);
                }
            }
            for k in 1..=mult {
                terms.push(PfTerm { pole: p, power: k, residue: rs[mult - k] });
            }
        }
        Ok(PartialFractions { direct: q, terms })
    }

    /// y(0⁺), ẏ(0⁺), … (the first `count` initial values) of y with Laplace transform G, from
    /// the expansion G = Σ mᵢ s^{−i} at s = ∞: y⁽ᵏ⁾(0⁺) = m_{k+1}. This is the initial-value
    /// theorem y(0⁺) = lim s·ŷ (Fact 15.12.1) and its derivative form
    /// ẏ(0⁺) = lim s[sŷ − y(0⁺)] (Fact 15.12.2 as corrected in the notes: the book prints
    /// s[ŷ − y(0)]). A delay τ > 0 makes every value 0.
    ///
    /// Book: Fact 15.12.1–15.12.2, 15.20.15–16, 15.20.28.
    ///
    /// # Errors
    /// [`LtiError::Improper`] unless strictly proper (y would contain δ at t = 0);
    /// [`LtiError::TooLarge`] for `count` > [`crate::MAX_VALUES`] (it used to abort on
    /// allocation); [`LtiError::Overflow`] when a value exceeds the f64 range.
    pub fn initial_values(&self, count: usize) -> Result<Vec<f64>, LtiError> {
        if count > crate::MAX_VALUES {
            return Err(LtiError::TooLarge {
                what: "initial values",
                requested: count as u128,
                limit: crate::MAX_VALUES,
            });
        }
        if !self.is_strictly_proper() {
            return Err(LtiError::Improper {
                num_degree: self.num().degree(),
                den_degree: self.den().degree(),
                what: "the initial-value theorem (a strictly proper ŷ)",
            });
        }
        if self.delay() > 0.0 {
            return Ok(vec![0.0; count]);
        }
        let n = self.den().degree();
        let d = |k: usize| if k <= n { self.den().coeffs()[k] } else { 0.0 };
        // c_j: coefficient of s^{n−j} in N.
        let c = |j: usize| if j <= n { self.num().coeff(n - j) } else { 0.0 };
        let mut m = Vec::with_capacity(count);
        for j in 1..=count {
            // only d(0) … d(n) are nonzero: i ≥ j − n (linear, not quadratic, in `count`)
            let acc = (j.saturating_sub(n).max(1)..j).fold(c(j), |acc, i| acc - m[i - 1] * d(j - i));
            m.push(acc / d(0));
        }
        if m.iter().all(|v| v.is_finite()) {
            Ok(m)
        } else {
            Err(LtiError::Overflow { what: "initial values" })
        }
    }

    /// The final value lim_{t→∞} y(t) of the signal y whose Laplace transform is ŷ = self.
    ///
    /// Book: Fact 15.13.1, Ex 15.13.2, 15.20.29–31.
    ///
    /// # Errors
    /// As [`final_value`]; illegal cases are [`FinalValue::Illegal`].
    pub fn final_value(&self, tol: f64) -> Result<FinalValue, LtiError> {
        final_value(self, tol)
    }

    /// The inverse Laplace transform in real form (Ex 15.11.4, 15.20.19).
    ///
    /// # Errors
    /// As [`TransferFunction::partial_fractions`].
    pub fn inverse_laplace(&self, rtol: f64) -> Result<TimeFunction, LtiError> {
        let pf = self.partial_fractions(rtol)?;
        let mut terms = Vec::new();
        for t in &pf.terms {
            let fact: f64 = (1..t.power).map(|i| i as f64).product();
            let k = t.power - 1;
            if t.pole.im == 0.0 {
                terms.push(RealTerm {
                    power: k,
                    sigma: t.pole.re,
                    omega: 0.0,
                    a: t.residue.re / fact,
                    b: 0.0,
                });
            } else if t.pole.im > 0.0 {
                // r e^{pt} + r̄ e^{p̄t} = 2e^{σt}(Re r cos ωt − Im r sin ωt).
                terms.push(RealTerm {
                    power: k,
                    sigma: t.pole.re,
                    omega: t.pole.im,
                    a: 2.0 * t.residue.re / fact,
                    b: -2.0 * t.residue.im / fact,
                });
            }
        }
        let mut impulses: Vec<f64> = pf.direct.coeffs().iter().rev().copied().collect();
        if impulses.iter().all(|&c| c == 0.0) {
            impulses.clear();
        }
        Ok(TimeFunction { terms, impulses, delay: self.delay() })
    }
}

/// Polynomial long division N = QD + R.
pub(crate) fn divide(n: &Polynomial, d: &Polynomial) -> (Polynomial, Polynomial) {
    let (nn, dn) = (n.degree(), d.degree());
    if n.is_zero() || nn < dn {
        return (Polynomial::constant(0.0), n.clone());
    }
    let mut rem = n.coeffs().to_vec();
    let mut q = vec![0.0; nn - dn + 1];
    for i in 0..=nn - dn {
        let f = rem[i] / d.leading();
        q[i] = f;
        for (j, dc) in d.coeffs().iter().enumerate() {
            rem[i + j] -= f * dc;
        }
    }
    (Polynomial::from_vec(q), Polynomial::from_vec(rem[nn - dn + 1..].to_vec()))
}

/// Taylor coefficients of p(x + e) in e, ascending, up to order `count`.
fn taylor(p: &Polynomial, x: Complex64, count: usize) -> Vec<Complex64> {
    let mut out = Vec::with_capacity(count);
    let mut d = p.clone();
    let mut fact = 1.0;
    for k in 0..count {
        if k > 0 {
            fact *= k as f64;
        }
        out.push(d.eval_c(x) / fact);
        d = d.deriv();
    }
    out
}

/// One real term tᵏe^{σt}(a cos ωt + b sin ωt).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RealTerm {
    /// Power k of t.
    pub power: usize,
    /// Decay rate σ (the real part of the pole).
    pub sigma: f64,
    /// Frequency ω ≥ 0.
    pub omega: f64,
    /// Cosine coefficient a.
    pub a: f64,
    /// Sine coefficient b.
    pub b: f64,
}

/// y(t) = Σ tᵏe^{σt}(a cos ωt + b sin ωt) + Σ cᵢδ⁽ⁱ⁾(t), all delayed by τ.
///
/// Book: §15.10–15.11, Ex 15.11.4.
#[derive(Debug, Clone, PartialEq)]
pub struct TimeFunction {
    /// Smooth terms.
    pub terms: Vec<RealTerm>,
    /// Weights cᵢ of δ⁽ⁱ⁾(t − τ) (from a non-strictly-proper ŷ); not sampled by `eval`.
    pub impulses: Vec<f64>,
    /// Delay τ.
    pub delay: f64,
}

impl TimeFunction {
    /// The smooth part y(t) (0 before the delay).
    pub fn eval(&self, t: f64) -> f64 {
        let s = t - self.delay;
        if s < 0.0 {
            return 0.0;
        }
        self.terms
            .iter()
            .map(|r| {
                s.powi(r.power as i32)
                    * (r.sigma * s).exp()
                    * (r.a * (r.omega * s).cos() + r.b * (r.omega * s).sin())
            })
            .sum()
    }
}

/// Why the final-value theorem does not apply.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Illegal {
    /// ŷ has a pole in the open right half plane (e^{t} would give a wrong 0, Ex 15.13.2).
    RightHalfPlanePole(Complex64),
    /// ŷ has a pole on the imaginary axis other than 0 (y oscillates forever).
    ImaginaryAxisPole(Complex64),
}

/// Outcome of the final-value theorem (Fact 15.13.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FinalValue {
    /// y(t) → the value.
    Finite(f64),
    /// y(t) → ±∞ (a repeated pole at 0; the sign is that of sŷ as s → 0⁺): +1.0 or −1.0.
    Infinite(f64),
    /// The theorem does not apply.
    Illegal(Illegal),
}

/// The final-value theorem, decided on the polynomials (notes §3.9): powers of s are
/// cancelled exactly, the remaining poles are classified with relative tolerance `tol` on
/// their real parts, and lim sŷ at 0⁺ is the ratio of the lowest-order coefficients.
///
/// Book: Fact 15.13.1, Ex 15.13.2–15.13.3, 15.20.29–31.
///
/// # Errors
/// [`LtiError::InvalidArgument`] unless `tol` is finite and ≥ 0 (a NaN tolerance used to let
/// right-half-plane poles through); [`LtiError::Overflow`] when the finite limit exceeds the
/// f64 range (1/(s(s + 5e-324)) → 1/5e-324); root-finding errors.
pub fn final_value(y: &TransferFunction, tol: f64) -> Result<FinalValue, LtiError> {
    crate::error::check_tolerance("imaginary-axis tolerance", tol)?;
    if y.num().is_zero() {
        return Ok(FinalValue::Finite(0.0));
    }
    let (zn, zd) = (y.num().zero_roots(), y.den().zero_roots());
    let strip = |p: &Polynomial, k: usize| Polynomial::from_vec(p.coeffs()[..p.coeffs().len() - k].to_vec());
    let (n, d) = (strip(y.num(), zn), strip(y.den(), zd));
    for p in d.roots()? {
        let scale = p.norm().max(1.0);
        if p.re > tol * scale {
            return Ok(FinalValue::Illegal(Illegal::RightHalfPlanePole(p)));
        }
        if p.re.abs() <= tol * scale {
            return Ok(FinalValue::Illegal(Illegal::ImaginaryAxisPole(p)));
        }
    }
    // s·ŷ = s^{1 + zn − zd}·n/d.
    let power = 1 + zn as isize - zd as isize;
    let ratio = n.eval(0.0) / d.eval(0.0);
    Ok(match power {
        p if p > 0 => FinalValue::Finite(0.0),
        0 if !ratio.is_finite() => return Err(LtiError::Overflow { what: "final value" }),
        0 => FinalValue::Finite(ratio),
        _ => FinalValue::Infinite(ratio.signum()),
    })
}
