//! The search half of the margins: every candidate frequency of the three crossover
//! equations (gain, phase, stability point), from the roots x = ω² > 0 of exact polynomials in
//! x, each refined by Newton's method on L(jω) evaluated from the coefficients; on a grid for a
//! delayed loop. Which candidates hold, and the margins they give, are chosen in `select`.
//!
//! Book: §16.3, (16.3.1)–(16.3.2); notes §3.6.

use crate::axis::{AxisRational, AxisValue, Scaled, wrap_pi};
use crate::error::LtiError;
use crate::poly::Polynomial;
use num_complex::Complex64;

/// The candidate frequencies of a loop, before selection.
pub(super) struct Candidates {
    /// Roots of |L(jω)| = 1, refined.
    pub(super) gain: Vec<f64>,
    /// Crossings of the negative real axis, refined (not yet checked to hold).
    pub(super) phase: Vec<f64>,
    /// Minima of |1 + L(jω)|, refined (or exact zeros of 1 + L on the axis).
    pub(super) stability: Vec<f64>,
    /// Imaginary-axis zeros of N (L = 0 there: phase crossovers with GM = ∞).
    pub(super) axis_zeros: Vec<f64>,
}

/// Every candidate crossover of the loop `lp` delayed by `tau` (see
/// [`TransferFunction::margins`](crate::TransferFunction::margins)).
///
/// # Errors
/// [`LtiError::Overflow`] when a crossover polynomial overflows; root-finding errors.
pub(super) fn candidates(lp: &Loop, tau: f64) -> Result<Candidates, LtiError> {
    let (en, on) = even_odd(&lp.num);
    let (ed, od) = even_odd(&lp.den);
    let gx = abs_squared(&ed, &od);
    // gain crossovers: |N|² − |D|² = 0 (a delay does not change |L|)
    let gain_eq = abs_squared(&en, &on).minus(&gx);
    finite(&gain_eq)?;
    let mut gain = Vec::new();
    if !gain_eq.is_zero() {
        for x in positive_roots(&gain_eq)? {
            gain.push(lp.refine(Kind::Gain, x.sqrt()));
        }
    }
    if tau != 0.0 {
        let (phase, stability) = delayed_candidates(lp, tau);
        return Ok(Candidates { gain, phase, stability, axis_zeros: Vec::new() });
    }
    // phase crossovers: Im(N conj D) = ω(O_N E_D − E_N O_D) = 0
    let phase_eq = on.times(&ed).minus(&en.times(&od));
    // stability points: (F/G)′ = 0 with F = |N + D|², G = |D|² in x; minima where the
    // derivative of H = F′G − G′F is positive
    let (es, os) = even_odd(&lp.sum);
    let fx = abs_squared(&es, &os);
    let h = fx.deriv().times(&gx).minus(&gx.deriv().times(&fx));
    finite(&phase_eq)?;
    finite(&h)?;
    let (phase, axis_zeros) = phase_candidates(lp, &phase_eq)?;
    let stability = stability_candidates(lp, &h)?;
    Ok(Candidates { gain, phase, stability, axis_zeros })
}

/// [`LtiError::Overflow`] unless every coefficient of a crossover polynomial is finite.
fn finite(p: &Polynomial) -> Result<(), LtiError> {
    if p.coeffs().iter().all(|c| c.is_finite()) {
        Ok(())
    } else {
        Err(LtiError::Overflow { what: "margins (crossover polynomials)" })
    }
}

/// The phase crossover candidates from the roots of O_N E_D − E_N O_D, and the imaginary-axis
/// zeros of N among them.
fn phase_candidates(lp: &Loop, phase_eq: &Polynomial) -> Result<(Vec<f64>, Vec<f64>), LtiError> {
    let (mut wp, mut axis_zeros) = (Vec::new(), Vec::new());
    if phase_eq.is_zero() {
        return Ok((wp, axis_zeros));
    }
    for x in positive_roots(phase_eq)? {
        let w = x.sqrt();
        // an imaginary-axis zero of N (Im L = 0 trivially, L = 0: GM = ∞): the
        // crossing is the zero itself, refined on N; a zero of D there too is a
        // common factor, not a crossing
        if near_zero(&lp.num, w) {
            let w = refine_axis_root(&lp.num, w);
            if !near_zero(&lp.den, w) {
                axis_zeros.push(w);
            }
            continue;
        }
        // only crossings of the negative real axis, away from axis poles of L
        let v = lp.l.at(w);
        if matches!(v, AxisValue::Limit { order, .. } if order < 0) || v.value(w).re > 0.0 {
            continue;
        }
        wp.push(lp.refine(Kind::Phase, w));
    }
    Ok((wp, axis_zeros))
}

/// The stability point candidates: the roots of H = F′G − G′F where H′ > 0 (minima of |1 + L|).
fn stability_candidates(lp: &Loop, h: &Polynomial) -> Result<Vec<f64>, LtiError> {
    let mut ws = Vec::new();
    if h.is_zero() {
        return Ok(ws);
    }
    let hd = h.deriv();
    for x in positive_roots(h)? {
        if hd.eval(x) <= 0.0 {
            continue;
        }
        // 1 + L(jω) = 0 (a closed-loop pole on the axis): |1 + L| has a kink there,
        // the minimum is 0 and ω is a root of N + D; no refinement on the derivative
        let w = x.sqrt();
        let (pv, pb) = horner_bound(&lp.sum, w);
        if pv <= 1e3 * (lp.sum.len() as f64) * f64::EPSILON * pb {
            ws.push(w);
        } else {
            ws.push(lp.refine(Kind::Stability, w));
        }
    }
    Ok(ws)
}

/// E(x), O(x) with p(jω) = E(ω²) + jω·O(ω²): E = Σ c_{2m}(−1)^m x^m, O = Σ c_{2m+1}(−1)^m x^m.
fn even_odd(c: &[f64]) -> (Polynomial, Polynomial) {
    let n = c.len() - 1;
    let (mut e, mut o) = (vec![0.0; n / 2 + 1], vec![0.0; n.div_ceil(2).max(1)]);
    for (i, &ci) in c.iter().enumerate() {
        let k = n - i;
        let m = k / 2;
        let v = if m % 2 == 1 { -ci } else { ci };
        if k.is_multiple_of(2) {
            let len = e.len();
            e[len - 1 - m] = v;
        } else {
            let len = o.len();
            o[len - 1 - m] = v;
        }
    }
    (Polynomial::from_vec(e), Polynomial::from_vec(o))
}

/// |p(jω)|² as a polynomial in x = ω²: E² + x·O².
fn abs_squared(e: &Polynomial, o: &Polynomial) -> Polynomial {
    e.times(e).plus(&Polynomial::s().times(&o.times(o)))
}

/// Roots x > 0 of p (the candidates, refined later on L): by certified Descartes subdivision
/// ([`crate::realroots`]), or, when that cannot decide (a double root, a root at a split
/// point), the eigenvalues of the companion matrix that are real to 10⁻⁶ relative.
fn positive_roots(p: &Polynomial) -> Result<Vec<f64>, LtiError> {
    if p.degree() == 0 {
        return Ok(Vec::new());
    }
    if let Some(r) = crate::realroots::positive_roots(p.coeffs()) {
        return Ok(r);
    }
    Ok(p.roots()?.into_iter().filter(|x| x.re > 0.0 && x.im.abs() <= 1e-6 * x.re).map(|x| x.re).collect())
}

/// p(s)/sⁿ-scaled value and the logarithmic derivatives p′/p, p″/p at s = jω, by complex
/// Horner (on the reversed polynomial at 1/s for ω > 1, so nothing overflows).
struct LogDerivatives {
    d1: Complex64,
    d2: Complex64,
}

fn log_derivatives(c: &[f64], w: f64) -> LogDerivatives {
    let n = c.len() - 1;
    let zero = Complex64::new(0.0, 0.0);
    let horner = |coeffs: &mut dyn Iterator<Item = f64>, z: Complex64| {
        let (mut p, mut d1, mut d2) = (zero, zero, zero);
        for ci in coeffs {
            d2 = d2 * z + d1;
            d1 = d1 * z + p;
            p = p * z + ci;
        }
        (p, d1, 2.0 * d2)
    };
    if w <= 1.0 {
        let s = Complex64::new(0.0, w);
        let (p, d1, d2) = horner(&mut c.iter().copied(), s);
        LogDerivatives { d1: d1 / p, d2: d2 / p }
    } else {
        // p(s) = sⁿ r(z), z = 1/s: p′/p = z(n − z r′/r), p″/p = z²[n(n−1) − 2(n−1) z r′/r + z² r″/r]
        let z = Complex64::new(0.0, -1.0 / w);
        let (r, r1, r2) = horner(&mut c.iter().rev().copied(), z);
        let (q1, q2) = (r1 / r, r2 / r);
        let nf = n as f64;
        LogDerivatives {
            d1: z * (nf - z * q1),
            d2: z * z * (nf * (nf - 1.0) - 2.0 * (nf - 1.0) * z * q1 + z * z * q2),
        }
    }
}

/// Which crossover equation.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// ln|L(jω)| = 0.
    Gain,
    /// arg(−L(jω)) = 0.
    Phase,
    /// d/dω ln|1 + L(jω)| = 0.
    Stability,
}

/// The loop on the imaginary axis: L = N/D and 1 + L = P/D with P = N + D.
pub(super) struct Loop {
    /// L = N/D.
    pub(super) l: AxisRational,
    /// 1 + L = P/D.
    pub(super) s: AxisRational,
    /// N/P = L/(1 + L).
    np: AxisRational,
    num: Vec<f64>,
    den: Vec<f64>,
    sum: Vec<f64>,
}

impl Loop {
    /// The loop L = N/D on the imaginary axis, the power of two of its coefficient scaling
    /// folded into N̂ (L = 2^{e}·N̂/D̂).
    ///
    /// # Errors
    /// [`LtiError::Overflow`] when the folded gain overflows.
    pub(super) fn new(num: &[f64], den: &[f64]) -> Result<Self, LtiError> {
        let num = Scaled::new(num);
        let den = Scaled::new(den);
        let shift = crate::axis::pow2(num.e - den.e);
        let num_c: Vec<f64> = num.c.iter().map(|c| c * shift).collect();
        if num_c.iter().any(|c| !c.is_finite()) {
            return Err(LtiError::Overflow { what: "margins (loop gain)" });
        }
        let sum = Polynomial::from_vec(num_c.clone()).plus(&Polynomial::from_vec(den.c.clone()));
        Ok(Self {
            l: AxisRational::new(&num_c, &den.c),
            s: AxisRational::new(sum.coeffs(), &den.c),
            np: AxisRational::new(&num_c, sum.coeffs()),
            num: num_c,
            den: den.c,
            sum: sum.coeffs().to_vec(),
        })
    }

    /// f(ω) and f′(ω) of the crossover equation.
    pub(super) fn equation(&self, kind: Kind, w: f64) -> (f64, f64) {
        match kind {
            Kind::Gain => {
                let (n1, d1) = (log_derivatives(&self.num, w).d1, log_derivatives(&self.den, w).d1);
                // d/dω ln|p(jω)| = Re(j p′/p) = −Im(p′/p)
                (self.l.at(w).ln_abs(w), -n1.im + d1.im)
            }
            Kind::Phase => {
                let (n1, d1) = (log_derivatives(&self.num, w).d1, log_derivatives(&self.den, w).d1);
                // d/dω arg p(jω) = Im(j p′/p) = Re(p′/p)
                (wrap_pi(self.l.at(w).arg() - std::f64::consts::PI), n1.re - d1.re)
            }
            Kind::Stability => {
                let (n, p, d) = (
                    log_derivatives(&self.num, w),
                    log_derivatives(&self.sum, w),
                    log_derivatives(&self.den, w),
                );
                // d/dω ln|1 + L(jω)| = −Im(L′/(1 + L)) with L′/(1 + L) = (N/P)(N′/N − D′/D): formed
                // this way it stays accurate relative to |L| when |L| ≪ 1 (the form
                // −Im(P′/P) + Im(D′/D) cancels there: P ≈ D)
                let ratio = self.np.at(w).value(w);
                let f = -(ratio * (n.d1 - d.d1)).im;
                // f′ only steers Newton: d/dω of −Im(p′/p) at s = jω is −Re(p″/p − (p′/p)²)
                let fp = -(p.d2 - p.d1 * p.d1).re + (d.d2 - d.d1 * d.d1).re;
                (f, fp)
            }
        }
    }

    /// Newton's method from ω₀ with step halving, at most 60 evaluations.
    fn refine(&self, kind: Kind, w0: f64) -> f64 {
        let mut w = w0;
        let (mut f, mut fp) = self.equation(kind, w);
        for _ in 0..30 {
            if f == 0.0 || !fp.is_finite() || fp == 0.0 {
                break;
            }
            let step = f / fp;
            let mut t = 1.0;
            let mut moved = false;
            for _ in 0..6 {
                let next = w - t * step;
                if next > 0.0 && next.is_finite() {
                    let (fn_, fpn) = self.equation(kind, next);
                    if fn_.abs() < f.abs() {
                        (w, f, fp) = (next, fn_, fpn);
                        moved = true;
                        break;
                    }
                }
                t *= 0.5;
            }
            if !moved || (t * step).abs() <= 2.0 * f64::EPSILON * w {
                break;
            }
        }
        w
    }

    /// A bound on the evaluation error of ln|L| and arg L at ω: (n + 2)ε·Σ|cₖ|ωᵏ/|p| over N, D.
    pub(super) fn evaluation_error(&self, w: f64) -> f64 {
        let rel = |c: &[f64]| {
            let (v, b) = horner_bound(c, w);
            let n = c.len() as f64 + 1.0;
            if v == 0.0 { f64::INFINITY } else { n * f64::EPSILON * b / v }
        };
        rel(&self.num) + rel(&self.den)
    }
}

/// |p(jω)| and Σ|cₖ|ωᵏ, both scaled by ω⁻ⁿ for ω > 1.
fn horner_bound(c: &[f64], w: f64) -> (f64, f64) {
    let v = crate::axis::at_jw(c, w).norm();
    let b = if w <= 1.0 {
        c.iter().fold(0.0, |acc, ci| acc * w + ci.abs())
    } else {
        c.iter().rev().fold(0.0, |acc, ci| acc / w + ci.abs())
    };
    (v, b)
}

/// True when |p(jω)| is within 10³·(n + 1)ε of its Horner bound Σ|cₖ|ωᵏ: ω is (to rounding) a
/// root of p on the imaginary axis.
fn near_zero(c: &[f64], w: f64) -> bool {
    let (v, b) = horner_bound(c, w);
    v <= 1e3 * (c.len() as f64) * f64::EPSILON * b
}

/// Newton's method for a root jω of p on the imaginary axis from ω₀: ω ← ω − Re(p/(j p′)),
/// at most 30 steps, kept while |p(jω)| decreases.
fn refine_axis_root(c: &[f64], w0: f64) -> f64 {
    // ln|p(jω)| (at_jw divides by (jω)ⁿ above ω = 1)
    let ln_abs = |w: f64| {
        let v = crate::axis::at_jw(c, w).norm().ln();
        if w > 1.0 { v + (c.len() - 1) as f64 * w.ln() } else { v }
    };
    let mut w = w0;
    let mut best = ln_abs(w);
    for _ in 0..30 {
        if best == f64::NEG_INFINITY {
            break;
        }
        // p′/p at jω; the step −p/(j p′) = j/(p′/p) is real for a root on the axis
        let step = (Complex64::new(0.0, 1.0) / log_derivatives(c, w).d1).re;
        let next = w + step;
        if !(next > 0.0 && next.is_finite()) {
            break;
        }
        let v = ln_abs(next);
        if v < best {
            (w, best) = (next, v);
        } else {
            break;
        }
    }
    w
}

/// Phase crossovers and stability points of a delayed loop L₀e^{−jωτ}: sign changes of
/// arg(−L) and of d/dω|1 + L|² on a logarithmic grid, refined by bisection.
fn delayed_candidates(lp: &Loop, tau: f64) -> (Vec<f64>, Vec<f64>) {
    let mut mags: Vec<f64> = Vec::new();
    for c in [&lp.num, &lp.den] {
        // root magnitudes from the Cauchy-like ratio of consecutive nonzero coefficients
        let nz: Vec<f64> = c.iter().copied().filter(|x| *x != 0.0).collect();
        for pair in nz.windows(2) {
            mags.push((pair[1] / pair[0]).abs());
        }
    }
    let lo = mags.iter().copied().filter(|m| *m > 0.0).fold(1.0f64, f64::min).min(1.0 / tau) / 1e3;
    let hi = mags.iter().copied().fold(1.0f64, f64::max).max(1.0 / tau) * 1e3;
    let n = 4000;
    let w: Vec<f64> = (0..n).map(|k| lo * (hi / lo).powf(k as f64 / (n - 1) as f64)).collect();
    let l = |x: f64| lp.l.at(x).value(x) * Complex64::from_polar(1.0, -x * tau);
    let phase = |x: f64| wrap_pi((-l(x)).arg());
    let dist = |x: f64| (Complex64::new(1.0, 0.0) + l(x)).norm_sqr();
    let slope = |x: f64| dist(x * (1.0 + 1e-7)) - dist(x * (1.0 - 1e-7));
    let bisect = |f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64| {
        let fa = f(a);
        for _ in 0..80 {
            let m = 0.5 * (a + b);
            if f(m).signum() == fa.signum() {
                a = m;
            } else {
                b = m;
            }
        }
        0.5 * (a + b)
    };
    let mut wp = Vec::new();
    let mut ws = Vec::new();
    for pair in w.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let (pa, pb) = (phase(a), phase(b));
        if pa.signum() != pb.signum() && (pa - pb).abs() < std::f64::consts::FRAC_PI_2 {
            wp.push(bisect(&phase, a, b));
        }
        if slope(a) < 0.0 && slope(b) > 0.0 {
            ws.push(bisect(&slope, a, b));
        }
    }
    (wp, ws)
}
