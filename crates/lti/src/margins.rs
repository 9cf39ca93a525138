//! Stability margins exactly as python-control 0.10 (`stability_margins`) defines them, every
//! crossover found by root finding on the exact crossover polynomials and refined by Newton's
//! method on the coefficient form of L(jω) (notes §3.6).
//!
//! # Definitions (python-control 0.10.2, `margins.py`, continuous time, `epsw = 0`)
//!
//! For the loop L = N/D (no delay):
//! - **Phase crossovers** ω_pc ≥ 0: Im L(jω) = 0 with L(jω) ≤ 0 real and D(jω) ≠ 0. ω = 0
//!   belongs to the list exactly when N(0)/D(0) ≤ 0 with D(0) ≠ 0, decided from the signs of the
//!   two coefficients (exact; a pole at 0 excludes ω = 0, a zero at 0 includes it with GM = ∞).
//!   Gain margin GM = 1/|L(jω_pc)| (a ratio, +∞ where L = 0), in dB −20 log₁₀|L| (16.3.2).
//! - **Gain crossovers** ω_gc > 0: |L(jω)| = 1. Phase margin
//!   PM = mod(∠L(jω_gc) in degrees, 360°) − 180° ∈ [−180°, 180°) with ∠ the principal angle
//!   (the book's (16.3.1) prints 180° − ∠L, a sign error).
//! - **Stability points** ω_s > 0: the stationary points of |1 + L(jω)| that are minima
//!   (second-derivative test), with the distance |1 + L(jω_s)| from −1. The stability margin is the
//!   smallest such distance; a minimum at ω = 0 or at ω → ∞ is not a stationary point and does
//!   not count (python-control's definition).
//! - **Selection**: the gain margin is the crossover with the smallest |ln GM| among finite
//!   GMs; the phase margin the crossover with the smallest |PM|; the stability margin the
//!   smallest distance; ties go to the lowest frequency. Absent margins are `None`
//!   (python-control returns ∞ with frequency NaN).
//!
//! Differences from python-control's floating-point implementation: python-control keeps a
//! root of the crossover polynomials only if `numpy.roots` returns it with an imaginary part of
//! exactly 0, and lists ω = 0 once per multiplicity; here a root is a candidate if it is real to
//! 10⁻⁶ relative, is refined on L itself and kept if the crossover equation then holds to its
//! evaluation error (so touching double crossovers are kept once), and every frequency appears
//! once.
//!
//! # Accuracy
//! N(jω) and D(jω) come from the coefficients (see the `axis` module): each crossover frequency
//! and margin is within a small multiple of ε times its condition number with respect to
//! relative perturbations of the coefficients, however ill-conditioned the roots of N and D.
//!
//! Book: §16.3, (16.3.1)–(16.3.2) with the sign of (16.3.1) corrected; 16.8.10–16.8.14.

use crate::axis::{AxisRational, AxisValue, Scaled, wrap_pi};
use crate::error::LtiError;
use crate::poly::Polynomial;
use crate::tf::TransferFunction;
use num_complex::Complex64;

/// Wraps an angle in degrees into (−180°, 180°].
pub fn wrap_deg(x: f64) -> f64 {
    let y = x.rem_euclid(360.0);
    if y > 180.0 { y - 360.0 } else { y }
}

/// python-control's phase margin of an angle in degrees: mod(∠, 360°) − 180° ∈ [−180°, 180°).
fn phase_margin_of(angle_deg: f64) -> f64 {
    angle_deg.rem_euclid(360.0) - 180.0
}

/// A gain crossover |L(jω)| = 1 and its phase margin.
///
/// Book: (16.3.1), sign corrected.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GainCrossover {
    /// ω_gc > 0 in rad/s.
    pub omega: f64,
    /// PM = mod(∠L(jω_gc), 360°) − 180° in degrees, in [−180°, 180°).
    pub phase_margin_deg: f64,
}

/// A phase crossover (L(jω) real and ≤ 0) and its gain margin.
///
/// Book: (16.3.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PhaseCrossover {
    /// ω_pc ≥ 0 in rad/s.
    pub omega: f64,
    /// GM = 1/|L(jω_pc)| (python-control's `gm`), +∞ where L(jω_pc) = 0 or where 1/|L| exceeds
    /// the f64 range (then `gain_margin_db` still holds the finite value in dB).
    pub gain_margin: f64,
    /// GM in dB, −20 log₁₀|L(jω_pc)|; negative when the loop gain must *shrink* to reach −1
    /// (16.8.14: an unstable open loop stable only above a gain), +∞ where L = 0.
    pub gain_margin_db: f64,
}

/// A local minimum of |1 + L(jω)| at ω > 0: the distance of the Nyquist plot from −1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StabilityPoint {
    /// ω_s > 0 in rad/s.
    pub omega: f64,
    /// |1 + L(jω_s)| (0 when the closed loop has a pole at jω_s).
    pub distance: f64,
}

/// Every crossover of a loop L and the margins python-control reports.
///
/// Book: §16.3, 16.8.10–16.8.14.
#[derive(Debug, Clone, PartialEq)]
pub struct Margins {
    /// All phase crossovers, increasing ω (ω = 0 first when it is one).
    pub phase_crossovers: Vec<PhaseCrossover>,
    /// All gain crossovers, increasing ω.
    pub gain_crossovers: Vec<GainCrossover>,
    /// All stationary minima of |1 + L(jω)| at ω > 0, increasing ω.
    pub stability_points: Vec<StabilityPoint>,
}

impl Margins {
    /// The phase crossover that sets the gain margin: smallest |ln GM| among finite GMs
    /// (lowest ω on ties); `None` when there is none (python-control: GM = ∞, ω = NaN).
    pub fn gain_margin(&self) -> Option<&PhaseCrossover> {
        self.phase_crossovers
            .iter()
            .filter(|c| c.gain_margin.is_finite())
            .min_by(|a, b| a.gain_margin.ln().abs().total_cmp(&b.gain_margin.ln().abs()))
    }

    /// The gain crossover that sets the phase margin: smallest |PM| (lowest ω on ties).
    pub fn phase_margin(&self) -> Option<&GainCrossover> {
        self.gain_crossovers
            .iter()
            .min_by(|a, b| a.phase_margin_deg.abs().total_cmp(&b.phase_margin_deg.abs()))
    }

    /// The stability margin: the smallest distance from −1 (lowest ω on ties).
    pub fn stability_margin(&self) -> Option<&StabilityPoint> {
        self.stability_points.iter().min_by(|a, b| a.distance.total_cmp(&b.distance))
    }

    /// The gain margin in dB (16.3.2), `None` when L never crosses −180° at a finite GM
    /// (16.8.10, 16.8.11i).
    pub fn gain_margin_db(&self) -> Option<f64> {
        self.gain_margin().map(|c| c.gain_margin_db)
    }

    /// The gain margin as a ratio 1/|L(jω_pc)| (python-control's `gm`).
    pub fn gain_margin_ratio(&self) -> Option<f64> {
        self.gain_margin().map(|c| c.gain_margin)
    }

    /// The phase margin in degrees, `None` when |L| never equals 1.
    pub fn phase_margin_deg(&self) -> Option<f64> {
        self.phase_margin().map(|c| c.phase_margin_deg)
    }

    /// ω of the gain crossover that sets the phase margin (python-control's `wgc`).
    pub fn gain_crossover_omega(&self) -> Option<f64> {
        self.phase_margin().map(|c| c.omega)
    }

    /// ω of the phase crossover that sets the gain margin (python-control's `wpc`).
    pub fn phase_crossover_omega(&self) -> Option<f64> {
        self.gain_margin().map(|c| c.omega)
    }

    /// The stability margin min |1 + L(jω)| over the stationary points (python-control's `sm`).
    pub fn stability_margin_distance(&self) -> Option<f64> {
        self.stability_margin().map(|c| c.distance)
    }
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
enum Kind {
    /// ln|L(jω)| = 0.
    Gain,
    /// arg(−L(jω)) = 0.
    Phase,
    /// d/dω ln|1 + L(jω)| = 0.
    Stability,
}

/// The loop on the imaginary axis: L = N/D and 1 + L = P/D with P = N + D.
struct Loop {
    l: AxisRational,
    s: AxisRational,
    /// N/P = L/(1 + L).
    np: AxisRational,
    num: Vec<f64>,
    den: Vec<f64>,
    sum: Vec<f64>,
}

impl Loop {
    /// f(ω) and f′(ω) of the crossover equation.
    fn equation(&self, kind: Kind, w: f64) -> (f64, f64) {
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
    fn evaluation_error(&self, w: f64) -> f64 {
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

/// Sorted, with crossovers closer than 10⁻¹² relative merged (two starting points that
/// converged to one crossover).
fn dedup(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * a.abs().max(b.abs()));
    v
}

impl TransferFunction {
    /// All crossovers and the margins of the loop L = self, as python-control 0.10's
    /// `stability_margins(L, returnall=True)` defines them (see the module documentation and
    /// [`Margins`]).
    ///
    /// Without delay: phase crossovers are the roots x > 0 of O_N E_D − E_N O_D (with
    /// p(jω) = E(ω²) + jω O(ω²)), gain crossovers those of |N|² − |D|², stability points those of
    /// F′G − G′F with F = |N + D|², G = |D|² and (F′G − G′F)′ > 0, all in x = ω²; each candidate is
    /// refined by Newton's method on L(jω) evaluated from the coefficients and kept if its
    /// equation holds to the evaluation error. With a delay τ (beyond python-control, which has
    /// none): gain crossovers as without (|e^{−jωτ}| = 1); phase crossovers and stability points
    /// are bracketed on a logarithmic grid of 4000 points over the pole–zero frequency range
    /// widened by 10³ and 1/τ, then refined.
    ///
    /// Book: (16.3.1)–(16.3.2) (sign of (16.3.1) corrected), 16.8.10–16.8.14.
    ///
    /// # Errors
    /// [`LtiError::NoConvergence`] from the root finder; [`LtiError::Overflow`] when the
    /// crossover polynomials overflow (coefficients beyond ~10¹⁵⁰).
    pub fn margins(&self) -> Result<Margins, LtiError> {
        let num = Scaled::new(self.num().coeffs());
        let den = Scaled::new(self.den().coeffs());
        // L = 2^{e}·N̂/D̂: fold the power of two into N̂ for the crossover polynomials
        let shift = crate::axis::pow2(num.e - den.e);
        let num_c: Vec<f64> = num.c.iter().map(|c| c * shift).collect();
        if num_c.iter().any(|c| !c.is_finite()) {
            return Err(LtiError::Overflow { what: "margins (loop gain)" });
        }
        let sum = Polynomial::from_vec(num_c.clone()).plus(&Polynomial::from_vec(den.c.clone()));
        let lp = Loop {
            l: AxisRational::new(&num_c, &den.c),
            s: AxisRational::new(sum.coeffs(), &den.c),
            np: AxisRational::new(&num_c, sum.coeffs()),
            num: num_c.clone(),
            den: den.c.clone(),
            sum: sum.coeffs().to_vec(),
        };
        let (en, on) = even_odd(&num_c);
        let (ed, od) = even_odd(&den.c);
        let (es, os) = even_odd(sum.coeffs());
        let fx = abs_squared(&es, &os);
        let gx = abs_squared(&ed, &od);
        let check = |p: &Polynomial| {
            if p.coeffs().iter().all(|c| c.is_finite()) {
                Ok(())
            } else {
                Err(LtiError::Overflow { what: "margins (crossover polynomials)" })
            }
        };
        // gain crossovers: |N|² − |D|² = 0 (a delay does not change |L|)
        let gain_eq = abs_squared(&en, &on).minus(&gx);
        check(&gain_eq)?;
        let mut wg: Vec<f64> = Vec::new();
        if !gain_eq.is_zero() {
            for x in positive_roots(&gain_eq)? {
                wg.push(lp.refine(Kind::Gain, x.sqrt()));
            }
        }
        let tau = self.delay();
        let mut axis_zeros: Vec<f64> = Vec::new();
        let (wp, ws) = if tau == 0.0 {
            // phase crossovers: Im(N conj D) = ω(O_N E_D − E_N O_D) = 0
            let phase_eq = on.times(&ed).minus(&en.times(&od));
            // stability points: (F/G)′ = 0 with F = |N + D|², G = |D|² in x; minima where the
            // derivative of H = F′G − G′F is positive
            let h = fx.deriv().times(&gx).minus(&gx.deriv().times(&fx));
            check(&phase_eq)?;
            check(&h)?;
            let mut wp = Vec::new();
            if !phase_eq.is_zero() {
                for x in positive_roots(&phase_eq)? {
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
            }
            let mut ws = Vec::new();
            if !h.is_zero() {
                let hd = h.deriv();
                for x in positive_roots(&h)? {
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
            }
            (wp, ws)
        } else {
            delayed_candidates(&lp, tau)
        };
        let delay_turn = |w: f64| -w * tau;
        // keep a gain or phase candidate where its equation holds to the evaluation error
        let holds = |kind: Kind, w: f64| {
            let (f, _) = if tau == 0.0 || kind == Kind::Gain {
                lp.equation(kind, w)
            } else {
                (wrap_pi(lp.l.at(w).arg() + delay_turn(w) - std::f64::consts::PI), 0.0)
            };
            f.abs() <= 64.0 * lp.evaluation_error(w) + 1e-300
        };
        let gain_crossovers = dedup(wg.into_iter().filter(|&w| holds(Kind::Gain, w)).collect())
            .into_iter()
            .map(|w| {
                let angle = (lp.l.at(w).arg() + delay_turn(w)).to_degrees();
                GainCrossover { omega: w, phase_margin_deg: phase_margin_of(wrap_deg(angle)) }
            })
            .collect();
        let mut phase_crossovers: Vec<PhaseCrossover> = Vec::new();
        // ω = 0: N(0)/D(0) ≤ 0 with D(0) ≠ 0, from the signs of the two coefficients (exact)
        let (n0, d0) = (self.num().coeff(0), self.den().coeff(0));
        if d0 != 0.0 && (n0 == 0.0 || (n0 < 0.0) != (d0 < 0.0)) {
            phase_crossovers.push(at_zero(n0, d0));
        }
        for w in dedup(axis_zeros) {
            phase_crossovers.push(PhaseCrossover {
                omega: w,
                gain_margin: f64::INFINITY,
                gain_margin_db: f64::INFINITY,
            });
        }
        for w in dedup(wp.into_iter().filter(|&w| holds(Kind::Phase, w)).collect()) {
            let v = lp.l.at(w);
            let re = v.value(w).re;
            // L(jω) ≤ 0 and D(jω) ≠ 0 (an axis pole makes Im L = 0 trivially but L infinite)
            if matches!(v, AxisValue::Limit { order, .. } if order < 0) || re > 0.0 {
                continue;
            }
            let ln = v.ln_abs(w);
            phase_crossovers.push(PhaseCrossover {
                omega: w,
                gain_margin: (-ln).exp(),
                gain_margin_db: -ln * (20.0 / std::f64::consts::LN_10),
            });
        }
        let stability_points = dedup(ws)
            .into_iter()
            .map(|w| {
                let distance = if tau == 0.0 {
                    lp.s.at(w).ln_abs(w).exp()
                } else {
                    (Complex64::new(1.0, 0.0)
                        + lp.l.at(w).value(w) * Complex64::from_polar(1.0, delay_turn(w)))
                    .norm()
                };
                StabilityPoint { omega: w, distance }
            })
            .collect();
        phase_crossovers.sort_by(|a, b| a.omega.total_cmp(&b.omega));
        Ok(Margins { phase_crossovers, gain_crossovers, stability_points })
    }
}

/// The phase crossover at ω = 0 for L(0) = n₀/d₀ ≤ 0, d₀ ≠ 0.
fn at_zero(n0: f64, d0: f64) -> PhaseCrossover {
    if n0 == 0.0 {
        return PhaseCrossover { omega: 0.0, gain_margin: f64::INFINITY, gain_margin_db: f64::INFINITY };
    }
    let gm = (d0 / n0).abs();
    // the ratio of the logarithms where |d₀/n₀| leaves the normal range
    let db = if gm.is_normal() { 20.0 * gm.log10() } else { 20.0 * (d0.abs().log10() - n0.abs().log10()) };
    PhaseCrossover { omega: 0.0, gain_margin: gm, gain_margin_db: db }
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
