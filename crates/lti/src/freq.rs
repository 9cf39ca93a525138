//! Frequency response (Bode data) evaluated from zero–pole–gain factors, and Nyquist data.
//!
//! Book: §16.2–16.6, (16.2.1)–(16.2.5), (16.6.2); 16.8.6, 16.8.14 (Z = N + P); notes §3.4–3.5.

use crate::error::LtiError;
use crate::routh::routh;
use crate::ss::StateSpace;
use crate::tf::TransferFunction;
use crate::zpk::Zpk;
use num_complex::Complex64;

/// `n` logarithmically spaced frequencies from 10^a to 10^b (Matlab `logspace`).
///
/// # Errors
/// [`LtiError::InvalidArgument`] unless a < b are finite and n ≥ 2.
pub fn logspace(a: f64, b: f64, n: usize) -> Result<Vec<f64>, LtiError> {
    if !(a.is_finite() && b.is_finite() && a < b && n >= 2) {
        return Err(LtiError::InvalidArgument {
            what: "logspace",
            reason: format!("10^{a} … 10^{b} with {n} points; need finite a < b and n ≥ 2"),
        });
    }
    Ok((0..n).map(|k| 10f64.powf(a + (b - a) * k as f64 / (n - 1) as f64)).collect())
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
    if omega.iter().any(|w| !(w.is_finite() && *w >= 0.0)) {
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

/// Relative error bound (guaranteed, from Horner's a-priori bound) up to which
/// [`TransferFunction::freqresp`] accepts the evaluation from the coefficients; points beyond
/// it are evaluated from the zero–pole–gain factors.
pub const FREQRESP_RTOL: f64 = 1e-11;

/// p(jω) on a grid for real coefficients `c` (highest power first), as E(−ω²) + jω·O(−ω²)
/// by Horner's rule over the even and odd powers, one pass per coefficient across the whole
/// grid (vectorisable), with the bounds Σ|c_k|ω^k.
fn horner_jw(c: &[f64], omega: &[f64]) -> (Vec<Complex64>, Vec<f64>) {
    let m = omega.len();
    let n = c.len() - 1;
    let sq: Vec<f64> = omega.iter().map(|w| w * w).collect();
    let (mut e, mut o, mut eb, mut ob) = (vec![0.0; m], vec![0.0; m], vec![0.0; m], vec![0.0; m]);
    for (k, &ck) in c.iter().enumerate() {
        let (v, b) = if (n - k).is_multiple_of(2) { (&mut e, &mut eb) } else { (&mut o, &mut ob) };
        let ak = ck.abs();
        for ((vi, bi), s) in v.iter_mut().zip(b.iter_mut()).zip(&sq) {
            *vi = ck - *vi * s;
            *bi = ak + *bi * s;
        }
    }
    let values = e.iter().zip(&o).zip(omega).map(|((e, o), w)| Complex64::new(*e, w * o)).collect();
    let bounds = eb.iter().zip(&ob).zip(omega).map(|((e, o), w)| e + w * o).collect();
    (values, bounds)
}

impl TransferFunction {
    /// G(jω) on `omega`. Numerator and denominator are evaluated as real polynomials in −ω²
    /// (even and odd powers: p(jω) = E(−ω²) + jω·O(−ω²)), by Horner's rule vectorised across
    /// the grid, with the a-priori bound |p̂ − p| ≤ (n + 2)ε·Σ|c_k|ω^k at every point (Higham,
    /// *Accuracy and Stability of Numerical Algorithms*, §5.1). A value whose bound exceeds
    /// [`FREQRESP_RTOL`] relative (near a zero or a lightly damped pole, or at ω so large that
    /// the powers overflow) is recomputed from the zero–pole–gain factors (roots found once
    /// per transfer function and cached). No root finding at all when every point passes,
    /// which is the common case.
    ///
    /// Book: §16.2 (frequency response G(jω)), (16.2.4).
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] for a negative or non-finite ω; root-finding errors when
    /// some point needs the factored form.
    pub fn freqresp(&self, omega: &[f64]) -> Result<Vec<Complex64>, LtiError> {
        check_omega(omega)?;
        let (num, den) = (self.num().coeffs(), self.den().coeffs());
        let (vn, bn) = horner_jw(num, omega);
        let (vd, bd) = horner_jw(den, omega);
        let (kn, kd) = ((num.len() + 1) as f64 * f64::EPSILON, (den.len() + 1) as f64 * f64::EPSILON);
        let tau = self.delay();
        let mut out = Vec::with_capacity(omega.len());
        let mut redo = Vec::new();
        // a point passes when each of N, D is guaranteed to ½·FREQRESP_RTOL relative:
        // (k·bound)² ≤ (tol/2)²·|p̂|², no square root or division; a square that under- or
        // overflows only sends the point to the factored form
        let t2 = 0.25 * FREQRESP_RTOL * FREQRESP_RTOL;
        for i in 0..omega.len() {
            let (n2, d2) = (vn[i].norm_sqr(), vd[i].norm_sqr());
            let (en, ed) = (kn * bn[i], kd * bd[i]);
            let g = vn[i] * vd[i].conj() * (1.0 / d2);
            if en * en <= t2 * n2 && ed * ed <= t2 * d2 && g.re.is_finite() && g.im.is_finite() {
                out.push(if tau == 0.0 { g } else { g * Complex64::from_polar(1.0, -omega[i] * tau) });
            } else {
                out.push(Complex64::new(f64::NAN, f64::NAN));
                redo.push(i);
            }
        }
        if !redo.is_empty() {
            let w: Vec<f64> = redo.iter().map(|&i| omega[i]).collect();
            let exact = self.to_zpk()?.freqresp(&w)?;
            for (&i, g) in redo.iter().zip(exact) {
                out[i] = g;
            }
        }
        Ok(out)
    }

    /// Bode data on `omega`, evaluated from the zero–pole–gain factors (no overflow at large
    /// ω, notes §3.4).
    ///
    /// Book: §16.3, 16.8.3–16.8.7.
    ///
    /// # Errors
    /// Root-finding errors; [`LtiError::InvalidArgument`] for a bad grid.
    pub fn bode(&self, omega: &[f64]) -> Result<FrequencyResponse, LtiError> {
        self.to_zpk()?.bode(omega)
    }
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
        let cl = self.den().add(self.num());
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
