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
//! # Layout
//! Split by verb: `search` finds every candidate frequency of the three crossover equations,
//! `select` keeps the candidates that hold and gives each crossover its margin, and the
//! [`Margins`] accessors choose the crossover that sets each margin.
//!
//! Book: §16.3, (16.3.1)–(16.3.2) with the sign of (16.3.1) corrected; 16.8.10–16.8.14.

use crate::error::LtiError;
use crate::tf::TransferFunction;
use search::Loop;

mod search;
mod select;

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
        // search: every candidate of the three crossover equations
        let lp = Loop::new(self.num().coeffs(), self.den().coeffs())?;
        let found = search::candidates(&lp, self.delay())?;
        // selection: the candidates that hold, merged, with their margins
        let at_zero = (self.num().coeff(0), self.den().coeff(0));
        Ok(select::crossovers(&lp, self.delay(), found, at_zero))
    }
}
