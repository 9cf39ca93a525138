//! Root locus of D₀(s) + kN₀(s) = 0 for k ≥ 0, with the construction rules of §15.18.3.
//!
//! Book: §15.18.3 Rules 1–7, (15.18.1)–(15.18.10); 15.20.48–15.20.50.

use crate::error::LtiError;
use crate::routh::jw_parts;
use crate::tf::TransferFunction;
use num_complex::Complex64;

/// The root locus of L = kN₀/D₀ and the data of its construction rules.
///
/// Book: §15.18.3.
#[derive(Debug, Clone, PartialEq)]
pub struct RootLocus {
    /// Gains k, increasing from 0.
    pub gains: Vec<f64>,
    /// `branches[i][j]`: root i of D₀ + k_j N₀ (branches follow continuity in k).
    pub branches: Vec<Vec<Complex64>>,
    /// Open-loop poles (roots of D₀, k = 0).
    pub poles: Vec<Complex64>,
    /// Open-loop zeros (roots of N₀).
    pub zeros: Vec<Complex64>,
    /// Asymptote centre α = (ΣP − ΣZ)/(n − m) (15.18.10); `None` when n = m.
    pub asymptote_center: Option<f64>,
    /// Asymptote angles (2i + 1)·180°/(n − m), i = 0 … n − m − 1 (Rule 7), in degrees.
    pub asymptote_angles_deg: Vec<f64>,
    /// Breakaway/break-in points: roots of N₀D₀′ − D₀N₀′ = 0 on the locus (real k ≥ 0), with k.
    pub breakaway: Vec<(Complex64, f64)>,
    /// Imaginary-axis crossings (ω ≥ 0, k > 0).
    pub jw_crossings: Vec<(f64, f64)>,
    /// Departure angles in degrees from each open-loop pole (one per pole, repeated poles
    /// give their q angles, (15.18.9)).
    pub departure_deg: Vec<(Complex64, f64)>,
}

/// The root locus of L = k·G for k from 0 to `k_max`, with adaptive gain steps so that no
/// root moves more than `max_step` between samples (relative to the size of the pole–zero
/// pattern).
///
/// # Errors
/// [`LtiError::Delay`], [`LtiError::Improper`], [`LtiError::InvalidArgument`] for
/// k_max ≤ 0; [`LtiError::NoConvergence`] when `max_step` is so small that 20000 gain steps
/// do not reach k_max (the locus used to end early without a word); root-finding errors.
pub fn root_locus(g: &TransferFunction, k_max: f64, max_step: f64) -> Result<RootLocus, LtiError> {
    g.require_rational("root locus")?;
    g.require_proper("root locus")?;
    if !(k_max.is_finite() && k_max > 0.0 && max_step.is_finite() && max_step > 0.0) {
        return Err(LtiError::InvalidArgument {
            what: "root-locus range",
            reason: format!("k_max = {k_max}, max_step = {max_step}; both must be finite and > 0"),
        });
    }
    let (n0, d0) = (g.num().clone(), g.den().clone());
    let poles = d0.roots()?;
    let zeros = if n0.is_zero() { Vec::new() } else { n0.roots()? };
    let scale = poles.iter().chain(&zeros).map(|z| z.norm()).fold(1.0, f64::max);
    let roots_at = |k: f64| d0.plus(&n0.scaled(k)).roots();
    let mut gains = vec![0.0];
    let mut current = poles.clone();
    let n = current.len();
    let mut branches: Vec<Vec<Complex64>> = current.iter().map(|&p| vec![p]).collect();
    let mut k = 0.0;
    // a first step of k_max·10⁻⁶, or k_max itself where that underflows (k_max subnormal)
    let mut dk = if k_max * 1e-6 > 0.0 { k_max * 1e-6 } else { k_max };
    let mut guard = 0;
    while k < k_max && guard < 20000 {
        guard += 1;
        let trial = (k + dk).min(k_max);
        let next = roots_at(trial)?;
        if next.len() != n {
            break;
        }
        let matched = match_roots(&current, &next);
        let jump = current.iter().zip(&matched).map(|(a, b)| (a - b).norm()).fold(0.0, f64::max);
        if jump > max_step * scale && dk > k_max * 1e-12 && k + 0.5 * dk > k {
            dk *= 0.5;
            continue;
        }
        k = trial;
        current = matched;
        gains.push(k);
        for (b, r) in branches.iter_mut().zip(&current) {
            b.push(*r);
        }
        if jump < 0.25 * max_step * scale {
            dk *= 2.0;
        }
    }
    if k < k_max {
        // the step bound (max_step tiny against the pattern) did not let k reach k_max
        return Err(LtiError::NoConvergence { what: "root locus (k_max not reached in 20000 gain steps)" });
    }
    // Rule 7 and (15.18.10): asymptotes.
    let r = poles.len() as isize - zeros.len() as isize;
    let (asymptote_center, asymptote_angles_deg) = if r > 0 {
        let sp: f64 = poles.iter().map(|p| p.re).sum();
        let sz: f64 = zeros.iter().map(|z| z.re).sum();
        (Some((sp - sz) / r as f64), (0..r).map(|i| (2 * i + 1) as f64 * 180.0 / r as f64).collect())
    } else {
        (None, Vec::new())
    };
    // Breakaway points: d/ds(D₀/N₀) = 0 ⇔ N₀D₀′ − D₀N₀′ = 0 with k = −D₀/N₀ real ≥ 0.
    let dd = n0.times(&d0.deriv()).minus(&d0.times(&n0.deriv()));
    let mut breakaway = Vec::new();
    if !dd.is_zero() && dd.degree() > 0 {
        for s in dd.roots()? {
            let kk = -d0.eval_c(s) / n0.eval_c(s);
            if kk.re.is_finite() && kk.re >= 0.0 && kk.im.abs() <= 1e-6 * kk.norm().max(1.0) {
                breakaway.push((s, kk.re));
            }
        }
    }
    // Imaginary-axis crossings: Im(D₀ conj N₀)(ω) = 0 with k = −D₀/N₀ > 0.
    let (dr, di) = jw_parts(&d0);
    let (nr, ni) = jw_parts(&n0);
    let im = di.times(&nr).minus(&dr.times(&ni));
    let mut jw_crossings = Vec::new();
    if !im.is_zero() {
        for w in im.roots()? {
            if w.im.abs() <= 1e-7 * w.norm().max(1.0) && w.re >= 0.0 {
                let s = Complex64::new(0.0, w.re);
                let kk = -d0.eval_c(s) / n0.eval_c(s);
                if kk.re > 0.0 && kk.im.abs() <= 1e-6 * kk.norm() {
                    jw_crossings.push((w.re, kk.re));
                }
            }
        }
    }
    jw_crossings.sort_by(|a, b| a.0.total_cmp(&b.0));
    jw_crossings.dedup_by(|a, b| (a.0 - b.0).abs() <= 1e-9 * a.0.max(1.0));
    Ok(RootLocus {
        gains,
        branches,
        departure_deg: departure_angles(&poles, &zeros),
        poles,
        zeros,
        asymptote_center,
        asymptote_angles_deg,
        breakaway,
        jw_crossings,
    })
}

/// Departure angles (15.18.9): for a q-fold pole p,
/// φ = (1/q)[Σ∠(p − zᵢ) − Σ∠(p − pⱼ) + 180° + 360°ℓ], ℓ = 0 … q − 1, other poles pⱼ only.
pub fn departure_angles(poles: &[Complex64], zeros: &[Complex64]) -> Vec<(Complex64, f64)> {
    let groups = crate::laplace::cluster_roots(poles, crate::laplace::CLUSTER_RTOL);
    let mut out = Vec::new();
    for &(p, q) in &groups {
        let sz: f64 = zeros.iter().map(|z| (p - z).arg().to_degrees()).sum();
        let sp: f64 = groups
            .iter()
            .filter(|(pj, _)| (pj - p).norm() > 0.0)
            .map(|(pj, m)| *m as f64 * (p - pj).arg().to_degrees())
            .sum();
        for l in 0..q {
            let phi = (sz - sp + 180.0 + 360.0 * l as f64) / q as f64;
            out.push((p, crate::margins::wrap_deg(phi)));
        }
    }
    out
}

/// Reorders `next` to follow `prev` by greedy nearest matching.
fn match_roots(prev: &[Complex64], next: &[Complex64]) -> Vec<Complex64> {
    let mut pairs: Vec<(f64, usize, usize)> = Vec::with_capacity(prev.len() * next.len());
    for (i, a) in prev.iter().enumerate() {
        for (j, b) in next.iter().enumerate() {
            pairs.push(((a - b).norm(), i, j));
        }
    }
    pairs.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)).then(x.2.cmp(&y.2)));
    let mut out = vec![Complex64::new(0.0, 0.0); prev.len()];
    let (mut ui, mut uj) = (vec![false; prev.len()], vec![false; next.len()]);
    for (_, i, j) in pairs {
        if !ui[i] && !uj[j] {
            ui[i] = true;
            uj[j] = true;
            out[i] = next[j];
        }
    }
    out
}

impl RootLocus {
    /// Every crossing of the locus (upper half plane) with the damping line of ratio ζ,
    /// s = ωn(−ζ + j√(1 − ζ²)), as (k, s) with increasing k: bracketed on the sampled locus,
    /// then refined by bisection on k with fresh roots.
    ///
    /// Book: (15.15.6) ζ = sin θ; 15.20.50, 16.8.11(iv).
    ///
    /// # Degenerate inputs
    /// A NaN ζ defines no line: no crossings (it used to report every sampled segment).
    pub fn zeta_crossings(&self, g: &TransferFunction, zeta: f64) -> Vec<(f64, Complex64)> {
        if zeta.is_nan() {
            return Vec::new();
        }
        let th = zeta.clamp(-1.0, 1.0).asin();
        // Signed distance to the ray at angle 90° + θ from the positive real axis.
        let dir = Complex64::from_polar(1.0, std::f64::consts::FRAC_PI_2 + th);
        let side = |s: Complex64| (dir.conj() * s).im;
        let char_roots = |k: f64| g.den().plus(&g.num().scaled(k)).roots().ok();
        let mut out: Vec<(f64, Complex64)> = Vec::new();
        for b in &self.branches {
            for j in 1..b.len() {
                let (a, c) = (b[j - 1], b[j]);
                if a.im <= 0.0 || c.im <= 0.0 || side(a).signum() == side(c).signum() {
                    continue;
                }
                let (mut ka, mut kb) = (self.gains[j - 1], self.gains[j]);
                let (mut sa, mut s) = (a, c);
                for _ in 0..60 {
                    let km = 0.5 * (ka + kb);
                    let Some(r) = char_roots(km) else { break };
                    let Some(sm) = r.into_iter().min_by(|x, y| (x - sa).norm().total_cmp(&(y - sa).norm()))
                    else {
                        break;
                    };
                    if side(sm).signum() == side(sa).signum() {
                        ka = km;
                        sa = sm;
                    } else {
                        kb = km;
                        s = sm;
                    }
                }
                out.push((0.5 * (ka + kb), s));
            }
        }
        out.sort_by(|x, y| x.0.total_cmp(&y.0));
        out
    }
}
