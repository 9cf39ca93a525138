//! Bode's sensitivity integral ∫₀^∞ ln|S(jω)| dω of a loop, by adaptive Gauss–Kronrod
//! quadrature on ω = a·tan θ.
//!
//! Book: (16.8.8)–(16.8.9); notes §3.11.

use crate::axis::AxisRational;
use crate::error::LtiError;
use crate::tf::TransferFunction;

/// Bode's sensitivity integral ∫₀^∞ ln|S(jω)| dω for S = 1/(1 + L), computed with ω = a·tan θ
/// (a the geometric centre of the moduli of the poles of L and of the closed loop) by globally
/// adaptive 15-point Gauss–Kronrod quadrature on θ ∈ (0, π/2) (the nodes never
/// touch π/2, where the integrand tends to a finite limit for relative degree ≥ 2). Where
/// |L| < ½ the integrand is ½·ln_1p(2 Re L + |L|²) (tail values of 10⁻³⁰ would round to 0 as
/// ln|1 + L|); elsewhere ln|N + D| − ln|D| from the scaled coefficients, so |L| up to the f64
/// range does not overflow. Bode's theorem gives π·Σ Re pᵢ over the ORHP poles of L for a
/// stable closed loop and relative degree ≥ 2.
///
/// Book: (16.8.8)–(16.8.9) (the book's Riemann sum to 10⁴ gave 0.0021 and 3.1412; the exact
/// values are 0 and π); notes §3.11.
///
/// # Errors
/// [`LtiError::InvalidArgument`] for relative degree < 2 (the integral diverges or the
/// theorem has an extra term); [`LtiError::Delay`]; [`LtiError::NoConvergence`] when the
/// estimated error is not below 10⁻¹¹·max(1, ∫₀^∞ |ln|S|| dω) within
/// [`QUADRATURE_INTERVALS`] subintervals, when the integrand is not finite (1 + L(jω) = 0, or
/// |L| beyond the f64 range on the axis), or when the poles of L and of the closed loop span
/// more than 12 decades (the substitution ω = a·tan θ, a their geometric centre, cannot
/// resolve them); root-finding errors of D or N + D are passed on.
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
    let closed = l.num().plus(l.den());
    // ω = a·tan θ centres the substitution on the roots of D and N + D (where ln|S| varies);
    // θ in f64 resolves ω/a from about 10⁻¹⁵ to 10¹⁵, so their moduli may span 12 decades
    let mut moduli: Vec<f64> =
        l.den().roots()?.into_iter().chain(closed.roots()?).map(|z| z.norm()).collect();
    moduli.retain(|m| *m > 0.0);
    let (lo, hi) = moduli.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &m| (lo.min(m), hi.max(m)));
    let a = if moduli.is_empty() { 1.0 } else { lo.sqrt() * hi.sqrt() };
    let resolvable = moduli.is_empty() || (hi / lo <= 1e12 && a.is_normal());
    if !resolvable {
        return Err(LtiError::NoConvergence {
            what: "sensitivity integral: the poles of L and of the closed loop span more than 12 decades (ω = a·tan θ cannot resolve them in f64)",
        });
    }
    let sum = AxisRational::new(closed.coeffs(), l.den().coeffs());
    let loop_ = AxisRational::new(l.num().coeffs(), l.den().coeffs());
    let f = |th: f64| {
        let (w, c) = (a * th.tan(), th.cos());
        let lv = loop_.at(w).value(w);
        // ln|1 + L| = ½ ln(1 + 2 Re L + |L|²)
        let ln =
            if lv.norm() < 0.5 { 0.5 * (2.0 * lv.re + lv.norm_sqr()).ln_1p() } else { sum.at(w).ln_abs(w) };
        // ln|S| = −ln|1 + L|, dω = a·dθ/cos²θ
        -ln * a / (c * c)
    };
    let no_convergence = LtiError::NoConvergence {
        what: "sensitivity integral (adaptive Gauss–Kronrod: error estimate above 10⁻¹¹·max(1, ∫|ln|S||) after 2000 subintervals, or a non-finite integrand)",
    };
    let v = gauss_kronrod(&f, 0.0, std::f64::consts::FRAC_PI_2, 1e-11, QUADRATURE_INTERVALS)
        .ok_or(no_convergence.clone())?;
    if v.is_finite() { Ok(v) } else { Err(no_convergence) }
}

/// At most this many subintervals in [`sensitivity_integral`]'s quadrature (30 015 integrand
/// evaluations): a loop whose integrand never meets the tolerance (a NaN integrand, or
/// |L| ≈ 10³⁰⁰) ends in a typed error instead of a hang.
pub const QUADRATURE_INTERVALS: usize = 2000;

/// Kronrod nodes on [−1, 1] (non-negative half, QUADPACK `qk15`); the odd-indexed ones are
/// the 7-point Gauss nodes.
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights for [`XGK`].
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// 7-point Gauss weights for XGK[1], XGK[3], XGK[5], XGK[7].
const WG: [f64; 4] =
    [0.129_484_966_168_869_7, 0.279_705_391_489_276_7, 0.381_830_050_505_118_9, 0.417_959_183_673_469_4];

/// The 15-point Kronrod estimate of ∫ₐᵇ f, |Kronrod − Gauss| as its error estimate, and the
/// Kronrod estimate of ∫ₐᵇ |f| (the scale against which cancellation is judged).
fn kronrod15(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> [f64; 3] {
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    let fc = f(c);
    let (mut k, mut g, mut m) = (WGK[7] * fc, WG[3] * fc, WGK[7] * fc.abs());
    for i in 0..7 {
        let (fl, fr) = (f(c - h * XGK[i]), f(c + h * XGK[i]));
        k += WGK[i] * (fl + fr);
        m += WGK[i] * (fl.abs() + fr.abs());
        if i % 2 == 1 {
            g += WG[i / 2] * (fl + fr);
        }
    }
    [k * h, ((k - g) * h).abs(), m * h]
}

/// ∫ₐᵇ f by globally adaptive Gauss–Kronrod: the subinterval with the largest error estimate
/// is halved until the summed estimate is ≤ tol·max(1, ∫|f|) (an absolute tolerance for
/// integrals of order one, relative to the size of the integrand where its parts cancel);
/// `None` after `max_intervals` subintervals, or for a non-finite integrand.
fn gauss_kronrod(f: &impl Fn(f64) -> f64, a: f64, b: f64, tol: f64, max_intervals: usize) -> Option<f64> {
    let mut parts = vec![(a, b, kronrod15(f, a, b))];
    loop {
        let [total, err, size] =
            parts.iter().fold([0.0; 3], |[t, e, m], (_, _, [v, r, s])| [t + v, e + r, m + s]);
        if !(total.is_finite() && err.is_finite() && size.is_finite()) {
            return None;
        }
        if err <= tol * size.max(1.0) {
            return Some(total);
        }
        if parts.len() >= max_intervals {
            return None;
        }
        let worst = (0..parts.len()).max_by(|&i, &j| parts[i].2[1].total_cmp(&parts[j].2[1]))?;
        let (lo, hi, _) = parts[worst];
        let mid = 0.5 * (lo + hi);
        parts[worst] = (lo, mid, kronrod15(f, lo, mid));
        parts.push((mid, hi, kronrod15(f, mid, hi)));
    }
}
