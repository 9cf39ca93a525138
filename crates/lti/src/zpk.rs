//! Zero–pole–gain form G(s) = k∏(s − zᵢ)/∏(s − pᵢ)·e^{−τs}, the form in which frequency
//! responses are evaluated (no overflow at large ω, continuous phase factor by factor).
//!
//! Book: (15.18.1)–(15.18.6), 16.8.3; notes §3.4–3.5.

use crate::error::LtiError;
use num_complex::Complex64;

/// Zero–pole–gain form G(s) = k∏(s − zᵢ)/∏(s − pᵢ)·e^{−τs}.
///
/// Book: (15.18.1)–(15.18.6).
#[derive(Debug, Clone, PartialEq)]
pub struct Zpk {
    zeros: Vec<Complex64>,
    poles: Vec<Complex64>,
    gain: f64,
    delay: f64,
}

fn finite(z: &[Complex64]) -> bool {
    z.iter().all(|c| c.re.is_finite() && c.im.is_finite())
}

/// The first complex root without an exact conjugate partner, if any.
fn unpaired(z: &[Complex64]) -> Option<Complex64> {
    let mut used = vec![false; z.len()];
    for i in 0..z.len() {
        if used[i] || z[i].im == 0.0 {
            continue;
        }
        used[i] = true;
        match (0..z.len()).find(|&j| !used[j] && z[j] == z[i].conj()) {
            Some(j) => used[j] = true,
            None => return Some(z[i]),
        }
    }
    None
}

impl Zpk {
    /// A zero–pole–gain system (no delay) with real coefficients: every complex zero or pole
    /// must come with its exact conjugate.
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] for a non-finite zero, pole or gain;
    /// [`LtiError::UnpairedComplexRoot`] for a complex zero or pole without its conjugate
    /// (`[−1 + 1j]` alone used to become 1/(s + 1)).
    pub fn new(zeros: Vec<Complex64>, poles: Vec<Complex64>, gain: f64) -> Result<Self, LtiError> {
        if !(finite(&zeros) && finite(&poles)) {
            return Err(LtiError::NonFinite { what: "zeros or poles" });
        }
        for (what, v) in [("zeros", &zeros), ("poles", &poles)] {
            if let Some(r) = unpaired(v) {
                return Err(LtiError::UnpairedComplexRoot { what, re: r.re, im: r.im });
            }
        }
        if !gain.is_finite() {
            return Err(LtiError::NonFinite { what: "gain" });
        }
        Ok(Self { zeros, poles, gain, delay: 0.0 })
    }

    /// The same system times e^{−τs}.
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] unless τ is finite and ≥ 0.
    pub fn with_delay(mut self, tau: f64) -> Result<Self, LtiError> {
        if !(tau.is_finite() && tau >= 0.0) {
            return Err(LtiError::InvalidArgument {
                what: "delay",
                reason: format!("τ = {tau}; need τ ≥ 0"),
            });
        }
        self.delay = tau;
        Ok(self)
    }

    /// Zeros.
    pub fn zeros(&self) -> &[Complex64] {
        &self.zeros
    }

    /// Poles.
    pub fn poles(&self) -> &[Complex64] {
        &self.poles
    }

    /// Gain k (ratio of leading coefficients).
    pub fn gain(&self) -> f64 {
        self.gain
    }

    /// Delay τ.
    pub fn delay(&self) -> f64 {
        self.delay
    }

    /// G(s) = k∏(s − zᵢ)/∏(s − pᵢ)·e^{−τs}, products interleaved to avoid overflow.
    ///
    /// # Degenerate inputs
    /// At a pole (a factor s − pᵢ exactly zero) the value is the point at infinity in the
    /// direction of the limit s₀ + h, h → 0⁺ real (components ±∞ or 0, never NaN); at a zero it
    /// is 0; where zeros and poles coincide they cancel.
    pub fn eval(&self, s: Complex64) -> Complex64 {
        let mut g = Complex64::new(self.gain, 0.0);
        let mut order = 0i32;
        let n = self.zeros.len().max(self.poles.len());
        for i in 0..n {
            if let Some(z) = self.zeros.get(i) {
                let f = s - z;
                // an exact root: direction 1 of s − z = h, counted in the order
                if f.re == 0.0 && f.im == 0.0 { order += 1 } else { g *= f }
            }
            if let Some(p) = self.poles.get(i) {
                let f = s - p;
                if f.re == 0.0 && f.im == 0.0 { order -= 1 } else { g = crate::axis::cdiv(g, f) }
            }
        }
        let d = if self.delay == 0.0 { Complex64::new(1.0, 0.0) } else { (-self.delay * s).exp() };
        match order.cmp(&0) {
            std::cmp::Ordering::Less => {
                crate::axis::infinity_towards(g * Complex64::from_polar(1.0, d.arg()))
            }
            std::cmp::Ordering::Greater => Complex64::new(0.0, 0.0),
            std::cmp::Ordering::Equal => {
                let v = g * d;
                if v.re.is_nan() || v.im.is_nan() {
                    crate::axis::infinity_towards(g * Complex64::from_polar(1.0, d.arg()))
                } else {
                    v
                }
            }
        }
    }

    /// |G(jω)| for ω ≥ 0 (∞ at an imaginary-axis pole, 0 at an imaginary-axis zero).
    pub fn magnitude(&self, omega: f64) -> f64 {
        self.eval(Complex64::new(0.0, omega)).norm()
    }

    /// ∠G(jω) in degrees on the continuous branch (notes §3.5): ∠k + Σ∠(jω − zᵢ) − Σ∠(jω − pᵢ)
    /// − ωτ, each factor continuous in ω > 0, shifted by a multiple of 360° so that the
    /// low-frequency phase follows the book's rule (16.6.2): 0° or −180° by the sign of the
    /// low-frequency gain, plus 90° per zero and −90° per pole at s = 0.
    ///
    /// Book: (16.6.2), §16.3; notes §3.5.
    pub fn phase_deg(&self, omega: f64) -> f64 {
        let raw = self.zeros.iter().map(|z| branch_arg(z, omega)).sum::<f64>()
            - self.poles.iter().map(|p| branch_arg(p, omega)).sum::<f64>();
        (self.branch_offset() + raw - omega * self.delay).to_degrees()
    }

    /// ∠k plus the multiple of 2π that puts the factor-wise phase on the book's
    /// low-frequency branch (16.6.2), in radians.
    pub(crate) fn branch_offset(&self) -> f64 {
        use std::f64::consts::{FRAC_PI_2, PI, TAU};
        let at_origin = |r: &Complex64| r.re == 0.0 && r.im == 0.0;
        // Low-frequency limit of the factor sum, ω → 0⁺ (a root at 0 contributes 90°).
        let limit = |r: &Complex64| if at_origin(r) { FRAC_PI_2 } else { branch_arg(r, 0.0) };
        let raw0 = self.zeros.iter().map(limit).sum::<f64>() - self.poles.iter().map(limit).sum::<f64>();
        // Book's low-frequency phase: sign of k∏(−zᵢ)/∏(−pᵢ) over the nonzero roots, ±90° per
        // root at the origin.
        let origin = |v: &[Complex64]| v.iter().filter(|r| at_origin(r)).count() as f64;
        let k0 = self
            .zeros
            .iter()
            .filter(|r| !at_origin(r))
            .fold(Complex64::new(self.gain, 0.0), |acc, z| acc * (-z));
        let k0 = self.poles.iter().filter(|r| !at_origin(r)).fold(k0, |acc, p| acc / (-p));
        let book0 =
            if k0.re < 0.0 { -PI } else { 0.0 } + FRAC_PI_2 * (origin(&self.zeros) - origin(&self.poles));
        let gain_angle = if self.gain < 0.0 { PI } else { 0.0 };
        gain_angle + ((book0 - raw0 - gain_angle) / TAU).round() * TAU
    }

    /// Cancels zero–pole pairs closer than `tol·max(1, |p|)`, nearest first. A complex pole
    /// cancels only against a complex zero on the same side of the real axis, and its conjugate
    /// against that zero's conjugate, so the result keeps real coefficients.
    pub fn minreal(&self, tol: f64) -> Self {
        let mut zeros = self.zeros.clone();
        let mut poles = Vec::new();
        let mut skip = vec![false; self.poles.len()];
        for (pi, p) in self.poles.iter().enumerate() {
            if skip[pi] {
                continue;
            }
            let best = zeros
                .iter()
                .enumerate()
                .filter(|(_, z)| (z.im == 0.0) == (p.im == 0.0) && z.im.signum() == p.im.signum())
                .map(|(i, z)| (i, (z - p).norm()))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .filter(|&(_, d)| d <= tol * p.norm().max(1.0));
            match best {
                Some((i, _)) => {
                    let z = zeros.remove(i);
                    if p.im != 0.0 {
                        // the conjugate pole cancels the conjugate zero
                        if let Some(j) = zeros.iter().position(|x| *x == z.conj()) {
                            zeros.remove(j);
                        }
                        if let Some(q) =
                            (0..self.poles.len()).find(|&q| !skip[q] && q != pi && self.poles[q] == p.conj())
                        {
                            skip[q] = true;
                        }
                    }
                }
                None => poles.push(*p),
            }
        }
        Self { zeros, poles, gain: self.gain, delay: self.delay }
    }
}

/// arg(jω − r) = atan2(ω − Im r, −Re r), continuous in ω: for Re r > 0 the branch [0, 2π) so
/// that the angle does not jump when ω passes Im r.
pub(crate) fn branch_arg(r: &Complex64, w: f64) -> f64 {
    if r.re == 0.0 && w == r.im {
        // ω on an axis root: the limit ω → ω₀⁺ of arg(j(ω − ω₀)) (16.6.2's rule at ω = 0)
        return std::f64::consts::FRAC_PI_2;
    }
    let a = (w - r.im).atan2(-r.re);
    if r.re > 0.0 && a < 0.0 { a + std::f64::consts::TAU } else { a }
}
