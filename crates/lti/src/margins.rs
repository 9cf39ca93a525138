//! Gain and phase crossovers and stability margins, found by root finding on the exact
//! crossover equations and refined on the factored response (notes §3.6).
//!
//! Book: §16.3, (16.3.1)–(16.3.2) with the sign of (16.3.1) corrected; 16.8.10–16.8.14.

use crate::error::LtiError;
use crate::poly::Polynomial;
use crate::routh::jw_parts;
use crate::tf::TransferFunction;
use crate::zpk::Zpk;
use num_complex::Complex64;

/// Wraps an angle in degrees into (−180°, 180°].
pub fn wrap_deg(x: f64) -> f64 {
    let y = x.rem_euclid(360.0);
    if y > 180.0 { y - 360.0 } else { y }
}

/// A gain crossover |L(jω)| = 1 and its phase margin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GainCrossover {
    /// ω_mc in rad/s.
    pub omega: f64,
    /// PM = wrap₍₋₁₈₀,₁₈₀₎(180° + ∠L(jω_mc)) in degrees (the book's (16.3.1) prints
    /// 180° − ∠L, a sign error).
    pub phase_margin_deg: f64,
}

/// A phase crossover ∠L(jω) ≡ −180° and its gain margin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PhaseCrossover {
    /// ω_pc in rad/s.
    pub omega: f64,
    /// GM = −20 log₁₀|L(jω_pc)| in dB (16.3.2); negative when the loop gain must *grow* to
    /// reach −1 (an unstable open loop, 16.8.14).
    pub gain_margin_db: f64,
}

/// Every crossover of a loop L and the resulting margins.
///
/// Book: §16.3, 16.8.10–16.8.14.
#[derive(Debug, Clone, PartialEq)]
pub struct Margins {
    /// All gain crossovers, increasing ω.
    pub gain_crossovers: Vec<GainCrossover>,
    /// All phase crossovers, increasing ω.
    pub phase_crossovers: Vec<PhaseCrossover>,
}

impl Margins {
    /// The gain margin in dB: the phase crossover with the smallest |GM|, or +∞ when L never
    /// crosses −180° (16.8.10, 16.8.11i).
    pub fn gain_margin_db(&self) -> f64 {
        self.phase_crossovers
            .iter()
            .map(|c| c.gain_margin_db)
            .min_by(|a, b| a.abs().total_cmp(&b.abs()))
            .unwrap_or(f64::INFINITY)
    }

    /// The phase margin in degrees: the gain crossover with the smallest |PM|, or +∞ when
    /// |L| never equals 1.
    pub fn phase_margin_deg(&self) -> f64 {
        self.gain_crossovers
            .iter()
            .map(|c| c.phase_margin_deg)
            .min_by(|a, b| a.abs().total_cmp(&b.abs()))
            .unwrap_or(f64::INFINITY)
    }

    /// ω of the crossover giving [`Margins::phase_margin_deg`].
    pub fn gain_crossover_omega(&self) -> Option<f64> {
        self.gain_crossovers
            .iter()
            .min_by(|a, b| a.phase_margin_deg.abs().total_cmp(&b.phase_margin_deg.abs()))
            .map(|c| c.omega)
    }

    /// ω of the crossover giving [`Margins::gain_margin_db`].
    pub fn phase_crossover_omega(&self) -> Option<f64> {
        self.phase_crossovers
            .iter()
            .min_by(|a, b| a.gain_margin_db.abs().total_cmp(&b.gain_margin_db.abs()))
            .map(|c| c.omega)
    }
}

/// Positive real roots of p(ω), deduplicated.
fn positive_real_roots(p: &Polynomial) -> Result<Vec<f64>, LtiError> {
    if p.is_zero() {
        return Ok(Vec::new());
    }
    let mut out: Vec<f64> = p
        .roots()?
        .into_iter()
        .filter(|w| w.im.abs() <= 1e-6 * w.norm().max(1e-12) && w.re > 0.0)
        .map(|w| w.re)
        .collect();
    out.sort_by(f64::total_cmp);
    out.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * a.abs());
    Ok(out)
}

/// Q(x) with Q(ω²) = p(ω)/ω^shift, from the coefficients of ω^{2k + shift}.
fn in_omega_squared(p: &Polynomial, shift: usize) -> Polynomial {
    if p.is_zero() {
        return p.clone();
    }
    let n = p.degree();
    let m = if n >= shift { (n - shift) / 2 } else { 0 };
    let asc: Vec<f64> = (0..=m).map(|k| p.coeff(2 * k + shift)).collect();
    Polynomial::from_vec(asc.into_iter().rev().collect())
}

/// Newton refinement of a scalar function root from `w`, kept only while |f| decreases.
fn refine(f: impl Fn(f64) -> f64, w: f64) -> f64 {
    let mut best = w;
    let mut fb = f(w).abs();
    for _ in 0..6 {
        let h = 1e-7 * best;
        let d = (f(best + h) - f(best - h)) / (2.0 * h);
        if d == 0.0 || !d.is_finite() {
            break;
        }
        let next = best - f(best) / d;
        let fn_ = f(next).abs();
        if next > 0.0 && fn_ < fb {
            best = next;
            fb = fn_;
        } else {
            break;
        }
    }
    best
}

impl TransferFunction {
    /// All crossovers and margins of the loop L = self.
    ///
    /// Without delay: gain crossovers are the positive roots of |N(jω)|² − |D(jω)|² and phase
    /// crossovers those of Im[N(jω)·conj D(jω)] with Re L < 0, each refined by Newton on the
    /// factored response. With a delay: a dense log grid, bracketing and the same refinement.
    ///
    /// Book: (16.3.1)–(16.3.2) (sign of (16.3.1) corrected), 16.8.10–16.8.14.
    ///
    /// # Errors
    /// Root-finding errors.
    pub fn margins(&self) -> Result<Margins, LtiError> {
        let zpk = self.to_zpk()?;
        let log_mag = |w: f64| zpk.magnitude(w).ln();
        let im_part = |w: f64| {
            let l = zpk.eval(Complex64::new(0.0, w));
            l.im / l.norm()
        };
        let (mut wg, mut wp) = if self.delay() == 0.0 {
            let (nr, ni) = jw_parts(self.num());
            let (dr, di) = jw_parts(self.den());
            // |N|² − |D|² is even in ω and Im(N conj D) is odd: with x = ω² both halve in
            // degree (cheaper and better conditioned); ω = √x for the roots x > 0.
            let gain_eq = nr.mul(&nr).add(&ni.mul(&ni)).sub(&dr.mul(&dr).add(&di.mul(&di)));
            let phase_eq = ni.mul(&dr).sub(&nr.mul(&di));
            let sqrt_all = |v: Vec<f64>| v.into_iter().map(f64::sqrt).collect::<Vec<f64>>();
            (
                sqrt_all(positive_real_roots(&in_omega_squared(&gain_eq, 0))?),
                sqrt_all(positive_real_roots(&in_omega_squared(&phase_eq, 1))?),
            )
        } else {
            grid_crossings(&zpk)
        };
        wg.iter_mut().for_each(|w| *w = refine(log_mag, *w));
        wp.iter_mut().for_each(|w| *w = refine(im_part, *w));
        let gain_crossovers = wg
            .into_iter()
            .filter(|&w| (zpk.magnitude(w) - 1.0).abs() < 1e-6)
            .map(|w| GainCrossover { omega: w, phase_margin_deg: wrap_deg(180.0 + zpk.phase_deg(w)) })
            .collect();
        let mut phase_crossovers: Vec<PhaseCrossover> = wp
            .into_iter()
            .filter(|&w| {
                let l = zpk.eval(Complex64::new(0.0, w));
                l.re < 0.0 && l.im.abs() <= 1e-6 * l.norm()
            })
            .map(|w| PhaseCrossover { omega: w, gain_margin_db: -20.0 * zpk.magnitude(w).log10() })
            .collect();
        // ω = 0 is a phase crossover when L(0) is finite, real and negative.
        let l0 = zpk.eval(Complex64::new(0.0, 0.0));
        if l0.re.is_finite() && l0.re < 0.0 && l0.im == 0.0 {
            phase_crossovers
                .insert(0, PhaseCrossover { omega: 0.0, gain_margin_db: -20.0 * l0.re.abs().log10() });
        }
        Ok(Margins { gain_crossovers, phase_crossovers })
    }
}

/// Sign changes of log|L| and of the wrapped phase + 180° on a dense grid (delayed loops).
fn grid_crossings(zpk: &Zpk) -> (Vec<f64>, Vec<f64>) {
    let mags: Vec<f64> =
        zpk.poles().iter().chain(zpk.zeros()).map(|z| z.norm()).filter(|m| *m > 0.0).collect();
    let lo = mags.iter().copied().fold(1.0f64, f64::min) / 1e3;
    let hi = mags.iter().copied().fold(1.0f64, f64::max).max(1.0 / zpk.delay().clamp(1e-300, 1e300)) * 1e3;
    let n = 4000;
    let w: Vec<f64> = (0..n).map(|k| lo * (hi / lo).powf(k as f64 / (n - 1) as f64)).collect();
    let mut wg = Vec::new();
    let mut wp = Vec::new();
    for pair in w.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        if zpk.magnitude(a).ln().signum() != zpk.magnitude(b).ln().signum() {
            wg.push(0.5 * (a + b));
        }
        let pa = wrap_deg(zpk.phase_deg(a) + 180.0);
        let pb = wrap_deg(zpk.phase_deg(b) + 180.0);
        if pa.signum() != pb.signum() && (pa - pb).abs() < 90.0 {
            wp.push(0.5 * (a + b));
        }
    }
    (wg, wp)
}

/// Bode's sensitivity integral ∫₀^∞ ln|S(jω)| dω for S = 1/(1 + L), computed with ω = tan θ
/// and adaptive Simpson quadrature on θ ∈ (0, π/2). Bode's theorem gives π·Σ Re pᵢ over the
/// ORHP poles of L for a stable closed loop and relative degree ≥ 2.
///
/// Book: (16.8.8)–(16.8.9) (the book's Riemann sum to 10⁴ gave 0.0021 and 3.1412; the exact
/// values are 0 and π); notes §3.11.
///
/// # Errors
/// [`LtiError::InvalidArgument`] for relative degree < 2 (the integral diverges or the
/// theorem has an extra term); [`LtiError::Delay`].
pub fn sensitivity_integral(l: &TransferFunction) -> Result<f64, LtiError> {
    l.require_rational("the sensitivity integral")?;
    if l.relative_degree() < 2 {
        return Err(LtiError::InvalidArgument {
            what: "loop",
            reason: format!(
                "relative degree {} < 2; Bode's integral needs deg D − deg N ≥ 2",
                l.relative_degree()
            ),
        });
    }
    let zpk = l.to_zpk()?;
    let f = |th: f64| {
        // At θ = π/2 take the limit, approximated at ω = 10⁶ (error O(ω⁻²) relative).
        let th = th.min(std::f64::consts::FRAC_PI_2 - 1e-6);
        let w = th.tan();
        let l = zpk.eval(Complex64::new(0.0, w));
        let c = th.cos();
        // ln|1 + L| = ½ ln(1 + 2 Re L + |L|²), with ln_1p for accuracy when |L| ≪ 1.
        -0.5 * (2.0 * l.re + l.norm_sqr()).ln_1p() / (c * c)
    };
    Ok(adaptive_simpson(&f, 0.0, std::f64::consts::FRAC_PI_2, 1e-11, 40))
}

fn adaptive_simpson(f: &impl Fn(f64) -> f64, a: f64, b: f64, tol: f64, depth: u32) -> f64 {
    let m = 0.5 * (a + b);
    let (fa, fm, fb) = (f(a), f(m), f(b));
    let whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    simpson_rec(f, a, b, fa, fm, fb, whole, tol, depth)
}

#[allow(clippy::too_many_arguments)] // the recursion carries the reused samples
fn simpson_rec(
    f: &impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    fa: f64,
    fm: f64,
    fb: f64,
    whole: f64,
    tol: f64,
    depth: u32,
) -> f64 {
    let m = 0.5 * (a + b);
    let (lm, rm) = (0.5 * (a + m), 0.5 * (m + b));
    let (flm, frm) = (f(lm), f(rm));
    let left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    let right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    let delta = left + right - whole;
    if depth == 0 || delta.abs() <= 15.0 * tol {
        return left + right + delta / 15.0;
    }
    simpson_rec(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1)
        + simpson_rec(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1)
}
