//! The fast frequency sweep: G(jω) over a whole grid from the zero–pole–gain factors, one
//! factor at a time across all frequencies (structure of arrays, so the inner loops
//! vectorise), with the continuous phase obtained from one atan2 per frequency by counting
//! the turns of the running product.
//!
//! Book: §16.2–16.3; notes §3.4–3.5.

use crate::axis::infinity_towards;
use crate::zpk::Zpk;
use num_complex::Complex64;

/// G(jω) and the continuous phase in radians (the branch of [`Zpk::phase_deg`]).
///
/// A factor jω − r that is exactly zero (ω on an imaginary-axis root) contributes its limit
/// direction j(ω − ω₀)/|ω − ω₀| = j as ω → ω₀⁺ and counts in the order of the pole or zero, so
/// that the value is the point at infinity (or 0) in the limiting direction and the phase the
/// limit from above, never NaN.
pub(crate) fn sweep(zpk: &Zpk, omega: &[f64], with_phase: bool) -> (Vec<Complex64>, Vec<f64>) {
    let n = omega.len();
    let mut re = vec![1.0; n];
    let mut im = vec![0.0; n];
    let mut turns = vec![0i32; n];
    let mut order = vec![0i32; n];
    // Interleave zeros and poles so that the running product stays moderate (no overflow).
    let (z, p) = (zpk.zeros(), zpk.poles());
    for i in 0..z.len().max(p.len()) {
        if let Some(r) = z.get(i) {
            mul_factor(&mut re, &mut im, &mut turns, &mut order, omega, r, false, with_phase);
        }
        if let Some(r) = p.get(i) {
            mul_factor(&mut re, &mut im, &mut turns, &mut order, omega, r, true, with_phase);
        }
    }
    let k = zpk.gain();
    let tau = zpk.delay();
    let mut response: Vec<Complex64> = (0..n)
        .map(|i| {
            let mut g = Complex64::new(k * re[i], k * im[i]);
            if tau != 0.0 {
                g *= Complex64::from_polar(1.0, -omega[i] * tau);
            }
            match order[i].cmp(&0) {
                std::cmp::Ordering::Less => infinity_towards(g),
                std::cmp::Ordering::Greater => Complex64::new(0.0, 0.0),
                std::cmp::Ordering::Equal => g,
            }
        })
        .collect();
    let mut phase: Vec<f64> = if with_phase {
        let off = zpk.branch_offset();
        (0..n)
            .map(|i| im[i].atan2(re[i]) + std::f64::consts::TAU * turns[i] as f64 + off - omega[i] * tau)
            .collect()
    } else {
        Vec::new()
    };
    // A running product that overflowed to ∞·0 = NaN (a double pole at 0 at ω = 5e-324): the
    // point by the factor-wise evaluation, which returns the point at infinity and the phase of
    // the factors, never NaN.
    for i in 0..n {
        if response[i].re.is_nan() || response[i].im.is_nan() {
            response[i] = zpk.eval(Complex64::new(0.0, omega[i]));
        }
        if with_phase && phase[i].is_nan() {
            phase[i] = zpk.phase_deg(omega[i]).to_radians();
        }
    }
    (response, phase)
}

/// P ← P·(jω − r) for a zero, P ← P/(jω − r) for a pole, counting the 2π turns that the
/// principal argument of P loses, plus the [0, 2π) branch of right-half-plane roots.
#[allow(clippy::too_many_arguments)] // the structure-of-arrays state of the sweep
fn mul_factor(
    re: &mut [f64],
    im: &mut [f64],
    turns: &mut [i32],
    order: &mut [i32],
    omega: &[f64],
    r: &Complex64,
    pole: bool,
    with_phase: bool,
) {
    let rhp = r.re > 0.0;
    for i in 0..omega.len() {
        // f = jω − r = a + jb, or its reciprocal conj(f)/|f|² for a pole.
        let a = -r.re;
        let b = omega[i] - r.im;
        let (fa, fb) = if a == 0.0 && b == 0.0 {
            // ω on an axis root: the direction j of jω − r as ω → ω₀⁺ (−j for 1/(jω − r))
            order[i] += if pole { -1 } else { 1 };
            (0.0, if pole { -1.0 } else { 1.0 })
        } else if pole {
            // 1/(a + jb) = (a − jb)/(a² + b²), one division; Smith's algorithm only where
            // a² + b² over- or underflows (huge ω or roots)
            let d = a * a + b * b;
            if d.is_normal() {
                let inv = 1.0 / d;
                (a * inv, -b * inv)
            } else if a.abs() >= b.abs() {
                let (r, d) = (b / a, a + b * (b / a));
                (1.0 / d, -r / d)
            } else {
                let (r, d) = (a / b, b + a * (a / b));
                (r / d, -1.0 / d)
            }
        } else {
            (a, b)
        };
        // `+ 0.0` turns −0.0 into +0.0, so that Im ≥ 0 ⇔ arg ∈ [0, π] also for atan2.
        let fb = fb + 0.0;
        let (pa, pb) = (re[i], im[i]);
        let qa = pa * fa - pb * fb;
        let qb = pa * fb + pb * fa + 0.0;
        re[i] = qa;
        im[i] = qb;
        if with_phase {
            // arg P + arg f = arg Q + 2πk: both in [0, π] and Q below the axis ⇒ k = 1; both in
            // (−π, 0) and Q on or above it ⇒ k = −1. Pole factors: arg f = −arg(jω − r),
            // except that f on the negative real axis has arg π instead of −π.
            let up_p = pb >= 0.0;
            let up_f = fb >= 0.0;
            let up_q = qb >= 0.0;
            // Edge: arg P = arg f = π gives arg P + arg f = 2π with Q on the positive real axis.
            let both_pi = up_p && up_f && qb == 0.0 && qa > 0.0 && pa < 0.0;
            let mut k = (up_p && up_f && (!up_q || both_pi)) as i32 - (!up_p && !up_f && up_q) as i32;
            // Correct a pole factor on the negative real axis: we want −π, not π.
            if pole && fb == 0.0 && fa < 0.0 {
                k -= 1;
            }
            // Branch [0, 2π) for right-half-plane roots: arg(jω − r) gets +2π when b < 0.
            if rhp && b < 0.0 {
                k += if pole { -1 } else { 1 };
            }
            turns[i] += k;
        }
    }
}

/// The factors of a root list: a conjugate pair (stored adjacently and exactly conjugate, as
/// the root finders return them) as one real quadratic, any other root alone.
enum Factor {
    /// (jω − r)(jω − r̄) for r = a + jb, b > 0.
    Pair(f64, f64),
    /// jω − r.
    Single(Complex64),
}

fn factors(roots: &[Complex64]) -> Vec<Factor> {
    let mut out = Vec::with_capacity(roots.len());
    let mut i = 0;
    while i < roots.len() {
        let r = roots[i];
        if r.im != 0.0 && roots.get(i + 1).is_some_and(|q| *q == r.conj()) {
            out.push(Factor::Pair(r.re, r.im.abs()));
            i += 2;
        } else {
            out.push(Factor::Single(r));
            i += 1;
        }
    }
    out
}

/// P ← P·f(jω) over the grid (structure of arrays, vectorisable).
fn mul_by(re: &mut [f64], im: &mut [f64], omega: &[f64], f: &Factor) {
    for i in 0..omega.len() {
        let w = omega[i];
        let (fa, fb) = match *f {
            // (jω − r)(jω − r̄) = a² − (ω − b)(ω + b) − 2jaω: the product of the two
            // differences keeps the real part accurate near ω = b, and where it cancels
            // against a² the imaginary part 2|a|ω dominates, so the factor is good to a few ε
            Factor::Pair(a, b) => (a * a - (w - b) * (w + b), -2.0 * a * w),
            Factor::Single(r) => (-r.re, w - r.im),
        };
        let (pa, pb) = (re[i], im[i]);
        re[i] = pa * fa - pb * fb;
        im[i] = pa * fb + pb * fa;
    }
}

/// G(jω) without phase: numerator and denominator products over conjugate-pair quadratics,
/// one division per ω. Falls back to the interleaved [`sweep`] when a product over- or
/// underflows (huge ω or roots).
pub(crate) fn response(zpk: &Zpk, omega: &[f64]) -> Vec<Complex64> {
    let n = omega.len();
    let (mut nr, mut ni, mut dr, mut di) = (vec![1.0; n], vec![0.0; n], vec![1.0; n], vec![0.0; n]);
    for f in factors(zpk.zeros()) {
        mul_by(&mut nr, &mut ni, omega, &f);
    }
    for f in factors(zpk.poles()) {
        mul_by(&mut dr, &mut di, omega, &f);
    }
    let (k, tau) = (zpk.gain(), zpk.delay());
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let (num, den) = (Complex64::new(nr[i], ni[i]), Complex64::new(dr[i], di[i]));
        let (an, ad) = (num.norm_sqr(), den.norm_sqr());
        // an exact zero of a factor (an axis root at this ω): the one-sided limit of `sweep`
        if (ad == 0.0 && den.re == 0.0 && den.im == 0.0) || (num.re == 0.0 && num.im == 0.0) {
            return sweep(zpk, omega, false).0;
        }
        // a product left the range where |·|² is representable: redo everything interleaved
        let safe = |x: f64| x == 0.0 || (x.is_finite() && x > 1e-280 && x < 1e280);
        if !(safe(an) && ad.is_finite() && ad > 1e-280 && ad < 1e280) {
            return sweep(zpk, omega, false).0;
        }
        let g = num * den.conj() * (k / ad);
        out.push(if tau == 0.0 { g } else { g * Complex64::from_polar(1.0, -omega[i] * tau) });
    }
    out
}
