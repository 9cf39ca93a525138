//! Frequency response (Bode data) evaluated from zero–pole–gain factors, and Nyquist data.
//!
//! Book: §16.2–16.6, (16.2.1)–(16.2.5), (16.6.2); 16.8.6, 16.8.14 (Z = N + P); notes §3.4–3.5.

use crate::axis::{AxisRational, AxisValue, Scaled, infinity_towards, pow2, rotate};
use crate::error::LtiError;
use crate::routh::routh;
use crate::ss::StateSpace;
use crate::tf::TransferFunction;
use crate::zpk::Zpk;
use num_complex::Complex64;
use std::f64::consts::TAU;
use vectrix_simd::{FUSED_LOOPS, madd};

/// `n` logarithmically spaced frequencies from 10^a to 10^b (Matlab `logspace`): the exponents
/// a + (b − a)·k/(n − 1), the last one exactly b (as Matlab and numpy set it).
///
/// # Degenerate inputs
/// An exponent below log₁₀ of the smallest subnormal (≈ −323.3) gives the correctly rounded
/// frequency 0.
///
/// # Errors
/// [`LtiError::InvalidArgument`] unless a < b are finite and n ≥ 2, and when 10^b exceeds the
/// largest finite f64 (b ≥ log₁₀ f64::MAX ≈ 308.2547: the valid range of b is below that);
/// [`LtiError::TooLarge`] for n > [`crate::MAX_VALUES`].
pub fn logspace(a: f64, b: f64, n: usize) -> Result<Vec<f64>, LtiError> {
    if !(a.is_finite() && b.is_finite() && a < b && n >= 2) {
        return Err(LtiError::InvalidArgument {
            what: "logspace",
            reason: format!("10^{a} … 10^{b} with {n} points; need finite a < b and n ≥ 2"),
        });
    }
    // every frequency is at most 10^b, which must be a finite f64 (issue 33: `logspace(0, 400,
    // 5)` returned ∞ inside `Ok`)
    if !10f64.powf(b).is_finite() {
        return Err(LtiError::InvalidArgument {
            what: "logspace",
            reason: format!(
                "10^{b} exceeds the largest finite f64 (≈ 1.8e308); the upper exponent b must be below log₁₀(f64::MAX) ≈ {:.4}",
                f64::MAX.log10()
            ),
        });
    }
    if n > crate::MAX_VALUES {
        return Err(LtiError::TooLarge { what: "logspace", requested: n as u128, limit: crate::MAX_VALUES });
    }
    let (span, last) = (b - a, (n - 1) as f64);
    // a + (b − a)·k/(n − 1), never above b; for a near −f64::MAX the product (b − a)·k would
    // overflow, so the fraction k/(n − 1) is formed first there
    let wide = !(span * last).is_finite();
    let exponent = |k: usize| {
        if k == n - 1 {
            b
        } else if wide {
            (a + span * (k as f64 / last)).min(b)
        } else {
            (a + span * k as f64 / last).min(b)
        }
    };
    Ok((0..n).map(|k| 10f64.powf(exponent(k))).collect())
}

/// G(jω) on a frequency grid with magnitude in dB and continuous phase in degrees.
///
/// Book: (16.2.1)–(16.2.5), §16.3 (Bode).
#[derive(Debug, Clone, PartialEq)]
pub struct FrequencyResponse {
    /// Frequencies ω in rad/s.
    pub omega: Vec<f64>,
    /// G(jω).
    pub response: Vec<Complex64>,
    /// 20 log₁₀|G(jω)| (−∞ at an imaginary-axis zero, +∞ at a pole).
    pub magnitude_db: Vec<f64>,
    /// ∠G(jω) in degrees on the continuous branch of [`Zpk::phase_deg`].
    pub phase_deg: Vec<f64>,
}

fn check_omega(omega: &[f64]) -> Result<(), LtiError> {
    // 0 ≤ ω < ∞ (NaN fails both), folded without short-circuit so that it vectorises
    if !omega.iter().fold(true, |ok, &w| ok & (0.0..f64::INFINITY).contains(&w)) {
        return Err(LtiError::InvalidArgument {
            what: "frequency grid",
            reason: "every ω must be finite and ≥ 0".into(),
        });
    }
    Ok(())
}

impl Zpk {
    /// Bode data on `omega` (each ω ≥ 0).
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] for a negative or non-finite ω.
    pub fn bode(&self, omega: &[f64]) -> Result<FrequencyResponse, LtiError> {
        check_omega(omega)?;
        let (response, phase) = crate::sweep::sweep(self, omega, true);
        // 10 log₁₀|G|² skips hypot; where |G|² would under- or overflow, 20 log₁₀|G|
        let magnitude_db = response
            .iter()
            .map(|g| {
                let n2 = g.norm_sqr();
                if n2.is_normal() { 10.0 * n2.log10() } else { 20.0 * g.norm().log10() }
            })
            .collect();
        let phase_deg = phase.into_iter().map(f64::to_degrees).collect();
        Ok(FrequencyResponse { omega: omega.to_vec(), response, magnitude_db, phase_deg })
    }

    /// G(jω) only (no magnitude or phase), the cheapest sweep (python-control's
    /// `frequency_response` data).
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] for a negative or non-finite ω.
    pub fn freqresp(&self, omega: &[f64]) -> Result<Vec<Complex64>, LtiError> {
        check_omega(omega)?;
        Ok(crate::sweep::response(self, omega))
    }
}

/// Points per block of the vectorised evaluation.
const CHUNK: usize = 32;

/// G(jω)·2^{−e}… for one block of frequencies (≤ [`CHUNK`]), all at most `w_max` so that the
/// direct Horner sums cannot overflow: N(jω) = E_N(−ω²) + jω·O_N(−ω²) and D likewise, one
/// coefficient at a time across the block (the inner loops vectorise), then N·conj(D)/|D|²
/// times `gain`. A point where |D|² is not a normal number (an axis pole, or under- or
/// overflow) is left as NaN for the caller's exact path; returns whether there was one.
#[inline(always)]
fn block<const FMA: bool>(num: &[f64], den: &[f64], w: &[f64], gain: f64, out: &mut [Complex64]) -> bool {
    let m = w.len();
    let mut x = [0.0f64; CHUNK];
    for (xi, wi) in x.iter_mut().zip(w) {
        *xi = -wi * wi;
    }
    // E and O of N and D: a coefficient of sᵏ joins E when k is even, O when odd
    let eo = |c: &[f64], e: &mut [f64; CHUNK], o: &mut [f64; CHUNK]| {
        let n = c.len() - 1;
        for (i, &ci) in c.iter().enumerate() {
            let v = if (n - i).is_multiple_of(2) { &mut *e } else { &mut *o };
            for (vl, xl) in v[..m].iter_mut().zip(&x[..m]) {
                *vl = madd::<FMA>(*vl, *xl, ci);
            }
        }
    };
    let (mut en, mut on, mut ed, mut od) = ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
    eo(num, &mut en, &mut on);
    eo(den, &mut ed, &mut od);
    // N·conj(D)/|D|² with branch-free checks (comparisons and selects, so the loop vectorises);
    // the results are interleaved into `out` afterwards
    let (mut re, mut im) = ([0.0f64; CHUNK], [0.0f64; CHUNK]);
    let mut bad = 0u32;
    for l in 0..m {
        let (nr, ni) = (en[l], w[l] * on[l]);
        let (dr, di) = (ed[l], w[l] * od[l]);
        let d2 = madd::<FMA>(dr, dr, di * di);
        let inv = gain / d2;
        let r = madd::<FMA>(nr, dr, ni * di) * inv;
        let i = madd::<FMA>(ni, dr, -(nr * di)) * inv;
        // d2 normal (not 0, subnormal, ∞ or NaN) and both parts finite
        let ok = (f64::MIN_POSITIVE..f64::INFINITY).contains(&d2)
            & (r.abs() < f64::INFINITY)
            & (i.abs() < f64::INFINITY);
        bad += u32::from(!ok);
        re[l] = if ok { r } else { f64::NAN };
        im[l] = if ok { i } else { f64::NAN };
    }
    for (o, (r, i)) in out[..m].iter_mut().zip(re.iter().zip(&im)) {
        *o = Complex64::new(*r, *i);
    }
    bad > 0
}

/// The data of one grid evaluation: scaled coefficients, frequencies, the largest frequency
/// for the direct sums, and the power of two between the scalings of N and D.
struct Grid<'a> {
    num: &'a [f64],
    den: &'a [f64],
    omega: &'a [f64],
    w_max: f64,
    gain: f64,
}

vectrix_simd::dispatch! {
    /// [`block`] over a whole grid, compiled for AVX2 when the CPU has it (detected when the
    /// program runs; the same bits either way) and portable otherwise, fused multiply–add where
    /// the build says so ([`FUSED_LOOPS`]); points above `w_max` are left as NaN. Returns whether
    /// any point was left.
    fn blocks(grid: &Grid<'_>, out: &mut [Complex64]) -> bool = blocks_all::<FUSED_LOOPS>;
}

/// The body of [`blocks`].
#[inline(always)]
fn blocks_all<const FMA: bool>(g: &Grid<'_>, out: &mut [Complex64]) -> bool {
    let mut bad = false;
    for (w, o) in g.omega.chunks(CHUNK).zip(out.chunks_mut(CHUNK)) {
        if w.iter().fold(true, |ok, &wi| ok & (wi <= g.w_max)) {
            bad |= block::<FMA>(g.num, g.den, w, g.gain, o);
        } else {
            o.fill(Complex64::new(f64::NAN, f64::NAN));
            bad = true;
        }
    }
    bad
}

impl TransferFunction {
    /// G(jω) on `omega`, evaluated from the coefficients: N(jω) and D(jω) by Horner's rule on
    /// their even and odd parts, p(jω) = E(−ω²) + jω·O(−ω²), vectorised across blocks of the grid
    /// (AVX2 when the CPU has it, the same bits either way); frequencies so high that the powers could overflow
    /// use the reversed polynomials in 1/(jω). The result is the exact response of coefficients
    /// perturbed by at most (n + 2)ε relative each (Higham, *Accuracy and Stability of Numerical
    /// Algorithms*, §5.1): its relative error is at most a small multiple of ε times the
    /// condition number Σ|cₖωᵏ|/|N| + Σ|dₖωᵏ|/|D|, whatever the conditioning of the roots. No
    /// root finding.
    ///
    /// # Degenerate inputs
    /// `Ok` holds ±∞ components in exactly two places (docs/robustness.md, "Where ∞ is the
    /// answer"): at an imaginary-axis pole jω₀ on the grid, where the value is the point at
    /// infinity in the direction of the limit ω → ω₀⁺ (components ±∞, or 0 where the
    /// direction has none; never NaN), and where |G(jω)| exceeds the f64 range. ∞ is the
    /// book's value there (|G(j0)| = +∞ for 1/(ms), §16.4), and a grid that meets a pole keeps
    /// its other points (python-control and Matlab return ∞ at such a point as well). At an
    /// imaginary-axis zero the value is 0, and a common factor of N and D at jω₀ gives the
    /// limit (16.6.2 takes the same one-sided limit at ω = 0). [`TransferFunction::bode`]
    /// gives the exact limiting phase.
    ///
    /// Book: §16.2 (frequency response G(jω)), (16.2.4).
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] for a negative or non-finite ω.
    pub fn freqresp(&self, omega: &[f64]) -> Result<Vec<Complex64>, LtiError> {
        check_omega(omega)?;
        let num = Scaled::new(self.num().coeffs());
        let den = Scaled::new(self.den().coeffs());
        let gain = pow2(num.e - den.e);
        // |E|, |O| ≤ (n + 1)·2·ω^n with max|c| < 2, and |D|² squares that: the direct sums and
        // |D|² stay finite while ω^n ≤ 2^450
        let n = num.degree().max(den.degree()).max(1);
        let w_max = 2f64.powf(450.0 / n as f64);
        let mut out = vec![Complex64::new(0.0, 0.0); omega.len()];
        let tau = self.delay();
        let grid = Grid { num: &num.c, den: &den.c, omega, w_max, gain };
        let slow = blocks(&grid, &mut out);
        if !slow && tau == 0.0 {
            return Ok(out);
        }
        let ax = slow.then(|| AxisRational::new(self.num().coeffs(), self.den().coeffs()));
        for (g, &w) in out.iter_mut().zip(omega) {
            if g.re.is_nan() {
                // an axis pole or zero, or a frequency beyond the direct range: the exact path
                let v = ax.as_ref().expect("slow points imply the exact path").at(w);
                let value = v.value(w);
                *g = if tau == 0.0 { value } else { delayed(value, direction(&v), -w * tau) };
            } else if tau != 0.0 {
                *g *= Complex64::from_polar(1.0, -w * tau);
            }
        }
        Ok(out)
    }

    /// Bode data on `omega`: G(jω) and its magnitude from the coefficients as in
    /// [`TransferFunction::freqresp`] (20 log₁₀|G| in logarithms, exact in range), the phase as the
    /// principal argument from the coefficients moved by the multiple of 360° that puts it on the
    /// continuous branch of the zero–pole–gain factors ([`Zpk::phase_deg`], the book's branch
    /// (16.6.2)). So magnitude and phase carry the coefficient conditioning only; the roots
    /// decide the branch alone.
    ///
    /// # Degenerate inputs
    /// `Ok` holds ∞ only at an imaginary-axis pole jω₀ on the grid (docs/robustness.md, "Where
    /// ∞ is the answer"): there the magnitude is +∞ dB (the book's value, §16.4), the response
    /// is infinite as in [`TransferFunction::freqresp`], and the phase is the finite limit
    /// ω → ω₀⁺; the other points of the grid are unaffected. At a zero the magnitude is −∞ dB
    /// with the same phase rule. Where |G(jω)| merely exceeds the f64 range the magnitude in
    /// dB stays finite (it is computed in logarithms) while the response is infinite.
    ///
    /// Book: §16.3, (16.6.2), 16.8.3–16.8.7.
    ///
    /// # Errors
    /// Root-finding errors; [`LtiError::InvalidArgument`] for a bad grid.
    pub fn bode(&self, omega: &[f64]) -> Result<FrequencyResponse, LtiError> {
        check_omega(omega)?;
        let ax = AxisRational::new(self.num().coeffs(), self.den().coeffs());
        let (_, branch) = crate::sweep::sweep(&self.to_zpk()?, omega, true);
        let tau = self.delay();
        let mut response = Vec::with_capacity(omega.len());
        let mut magnitude_db = Vec::with_capacity(omega.len());
        let mut phase_deg = Vec::with_capacity(omega.len());
        for (&w, &b) in omega.iter().zip(&branch) {
            let v = ax.at(w);
            let g = v.value(w);
            response.push(if tau == 0.0 { g } else { delayed(g, direction(&v), -w * tau) });
            magnitude_db.push(v.ln_abs(w) * (20.0 / std::f64::consts::LN_10));
            // principal argument from the coefficients, on the branch of the factors
            let a = v.arg() - w * tau;
            phase_deg.push((a + TAU * ((b - a) / TAU).round()).to_degrees());
        }
        Ok(FrequencyResponse { omega: omega.to_vec(), response, magnitude_db, phase_deg })
    }
}

/// A finite nonzero complex number with the direction of G(jω) (for a delayed infinity).
fn direction(v: &AxisValue) -> Complex64 {
    match *v {
        AxisValue::Regular { q, k, .. } => rotate(q, k),
        AxisValue::Limit { c, order, k, .. } => rotate(rotate(c, k), order),
    }
}

/// g·e^{jφ} for the delay factor, keeping an infinite g infinite in the rotated direction.
fn delayed(g: Complex64, dir: Complex64, phi: f64) -> Complex64 {
    let r = Complex64::from_polar(1.0, phi);
    if g.re.is_finite() && g.im.is_finite() { g * r } else { infinity_towards(dir * r) }
}

impl StateSpace {
    /// Bode data of one channel, through its transfer function in zero–pole–gain form.
    ///
    /// # Errors
    /// Index, root-finding and grid errors.
    pub fn bode(&self, output: usize, input: usize, omega: &[f64]) -> Result<FrequencyResponse, LtiError> {
        self.to_tf(output, input)?.bode(omega)
    }
}

/// Nyquist data of a loop L = kN/D: the image of the Nyquist contour (with small
/// semicircular indentations to the right of imaginary-axis poles) and the encirclement
/// count of −1.
///
/// Book: 16.8.6, 16.8.13–16.8.14, Z = N + P.
#[derive(Debug, Clone, PartialEq)]
pub struct Nyquist {
    /// Contour points s on the upper half (ω from 0⁺ to ∞, indentations included).
    pub contour: Vec<Complex64>,
    /// L(s) on the upper half; the lower half is its mirror image (complex conjugate).
    pub positive: Vec<Complex64>,
    /// Clockwise encirclements N of −1 by the whole image, N = Z − P.
    pub encirclements: isize,
    /// P: open-loop poles in the ORHP.
    pub open_loop_rhp: usize,
    /// Z: closed-loop poles (roots of D + N) in the ORHP.
    pub closed_loop_rhp: usize,
}

impl TransferFunction {
    /// Nyquist data with `n` contour points per frequency decade-range (≥ 16).
    ///
    /// # Errors
    /// [`LtiError::Delay`] with a delay (the closed-loop count needs a rational L);
    /// [`LtiError::Improper`] for an improper L; [`LtiError::InvalidArgument`] if −1 lies on
    /// the image (a closed-loop pole on the imaginary axis: N is undefined).
    pub fn nyquist(&self, n: usize) -> Result<Nyquist, LtiError> {
        self.require_rational("Nyquist encirclement count")?;
        self.require_proper("Nyquist plot")?;
        let zpk = self.to_zpk()?;
        let poles = zpk.poles().to_vec();
        let cl = self.den().plus(self.num());
        let ra = routh(&cl)?;
        if ra.imaginary > 0 {
            return Err(LtiError::InvalidArgument {
                what: "loop",
                reason: "−1 lies on the Nyquist plot (closed-loop pole on the imaginary axis)".into(),
            });
        }
        let p = routh(self.den())?;
        let open_loop_rhp = p.rhp;
        let closed_loop_rhp = ra.rhp;
        // Frequency range from the pole/zero magnitudes.
        let mags: Vec<f64> = poles.iter().chain(zpk.zeros()).map(|z| z.norm()).filter(|m| *m > 0.0).collect();
        let lo = mags.iter().copied().fold(f64::INFINITY, f64::min).min(1.0) / 100.0;
        let hi = mags.iter().copied().fold(0.0, f64::max).max(1.0) * 100.0;
        let n = n.max(16);
        let omega = logspace(lo.log10(), hi.log10(), n)?;
        // Imaginary-axis poles at jb (b ≥ 0) with an indentation radius r.
        let axis: Vec<f64> = poles
            .iter()
            .filter(|p| p.re.abs() <= 1e-9 * p.norm().max(1.0) && p.im >= 0.0)
            .map(|p| p.im)
            .collect();
        let r = 1e-3 * lo.max(1e-6);
        let mut contour = Vec::new();
        let semicircle = |b: f64, from: f64, to: f64, out: &mut Vec<Complex64>| {
            for i in 0..=16 {
                let th = from + (to - from) * i as f64 / 16.0;
                out.push(Complex64::new(0.0, b) + r * Complex64::from_polar(1.0, th));
            }
        };
        if axis.contains(&0.0) {
            semicircle(0.0, 0.0, std::f64::consts::FRAC_PI_2, &mut contour);
        } else {
            contour.push(Complex64::new(0.0, 0.0));
        }
        for &w in &omega {
            if let Some(&b) = axis.iter().find(|&&b| b > 0.0 && (w - b).abs() < r) {
                let _ = b;
                continue;
            }
            // Insert an indentation when passing a pole at jb.
            if let Some(&b) =
                axis.iter().find(|&&b| b > 0.0 && contour.last().is_some_and(|c| c.im < b - r) && w > b + r)
            {
                semicircle(b, -std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2, &mut contour);
            }
            contour.push(Complex64::new(0.0, w));
        }
        let positive = contour.iter().map(|&s| zpk.eval(s)).collect();
        Ok(Nyquist {
            contour,
            positive,
            encirclements: closed_loop_rhp as isize - open_loop_rhp as isize,
            open_loop_rhp,
            closed_loop_rhp,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The dispatched grid evaluation (AVX2 here when the CPU has it) gives the bits of the
    /// portable body of the build's choice, on a logarithmic grid plus zero, subnormal and
    /// huge frequencies (one beyond `w_max`, left as NaN for the exact path); and the fused and
    /// plain bodies agree to 64ε relative (this rational function has no pole near the axis).
    #[test]
    fn dispatched_grid_is_the_portable_body_bitwise() {
        let num = Scaled::new(&[1.0, 0.5, 2.0]);
        let den = Scaled::new(&[1.0, 0.4, 0.0, 4.0]);
        let mut omega: Vec<f64> = (0..500).map(|k| 1e-3 * 1.03f64.powi(k)).collect();
        omega.extend([0.0, 2.0, 5e-324, 1e-300, 1e150]);
        let grid = Grid { num: &num.c, den: &den.c, omega: &omega, w_max: 1e100, gain: pow2(num.e - den.e) };
        let zero = Complex64::new(0.0, 0.0);
        let (mut dispatched, mut portable, mut other) =
            (vec![zero; omega.len()], vec![zero; omega.len()], vec![zero; omega.len()]);
        let bad = blocks(&grid, &mut dispatched);
        assert_eq!(bad, blocks_all::<FUSED_LOOPS>(&grid, &mut portable));
        blocks_all::<{ !FUSED_LOOPS }>(&grid, &mut other);
        for (k, (d, p)) in dispatched.iter().zip(&portable).enumerate() {
            let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
            assert!(same(d.re, p.re) && same(d.im, p.im), "ω = {:e}: {d} vs {p}", omega[k]);
            let o = other[k];
            if p.re.is_finite() && o.re.is_finite() {
                assert!((p - o).norm() <= 64.0 * f64::EPSILON * p.norm(), "ω = {:e}: {p} vs {o}", omega[k]);
            }
        }
    }
}
