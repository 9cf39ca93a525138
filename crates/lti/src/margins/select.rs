//! The selection half of the margins: of the candidates `search` found, keep those whose
//! crossover equation holds to its evaluation error, merge duplicates, and give each crossover
//! its margin (the gain margin of a phase crossover, the phase margin of a gain crossover, the
//! distance from −1 of a stability point). Which crossover sets each margin is chosen by the
//! [`Margins`] accessors.
//!
//! Book: §16.3, (16.3.1)–(16.3.2) (sign of (16.3.1) corrected), 16.8.10–16.8.14.

use super::search::{Candidates, Kind, Loop};
use super::{GainCrossover, Margins, PhaseCrossover, StabilityPoint, phase_margin_of, wrap_deg};
use crate::axis::{AxisValue, wrap_pi};
use num_complex::Complex64;

/// The crossovers of the loop `lp` delayed by `tau` from its candidates; `(n0, d0)` are the
/// constant coefficients N(0), D(0), which decide the crossover at ω = 0 exactly.
pub(super) fn crossovers(lp: &Loop, tau: f64, c: Candidates, (n0, d0): (f64, f64)) -> Margins {
    let gain_crossovers = dedup(c.gain.into_iter().filter(|&w| holds(lp, tau, Kind::Gain, w)).collect())
        .into_iter()
        .map(|w| {
            let angle = (lp.l.at(w).arg() + delay_turn(w, tau)).to_degrees();
            GainCrossover { omega: w, phase_margin_deg: phase_margin_of(wrap_deg(angle)) }
        })
        .collect();
    let mut phase_crossovers = phase_crossovers(lp, tau, c.phase, c.axis_zeros, (n0, d0));
    let stability_points = dedup(c.stability)
        .into_iter()
        .map(|w| {
            let distance = if tau == 0.0 {
                lp.s.at(w).ln_abs(w).exp()
            } else {
                (Complex64::new(1.0, 0.0)
                    + lp.l.at(w).value(w) * Complex64::from_polar(1.0, delay_turn(w, tau)))
                .norm()
            };
            StabilityPoint { omega: w, distance }
        })
        .collect();
    phase_crossovers.sort_by(|a, b| a.omega.total_cmp(&b.omega));
    Margins { phase_crossovers, gain_crossovers, stability_points }
}

/// The phase turn −ωτ of the delay e^{−jωτ}.
fn delay_turn(w: f64, tau: f64) -> f64 {
    -w * tau
}

/// Whether a gain or phase candidate's equation holds at ω to 64 times its evaluation error.
fn holds(lp: &Loop, tau: f64, kind: Kind, w: f64) -> bool {
    let (f, _) = if tau == 0.0 || kind == Kind::Gain {
        lp.equation(kind, w)
    } else {
        (wrap_pi(lp.l.at(w).arg() + delay_turn(w, tau) - std::f64::consts::PI), 0.0)
    };
    f.abs() <= 64.0 * lp.evaluation_error(w) + 1e-300
}

/// The phase crossovers, unsorted: ω = 0 when L(0) ≤ 0, the axis zeros of N (GM = ∞), and the
/// candidates that hold with L(jω) ≤ 0 and D(jω) ≠ 0.
fn phase_crossovers(
    lp: &Loop,
    tau: f64,
    phase: Vec<f64>,
    axis_zeros: Vec<f64>,
    (n0, d0): (f64, f64),
) -> Vec<PhaseCrossover> {
    let mut out: Vec<PhaseCrossover> = Vec::new();
    // ω = 0: N(0)/D(0) ≤ 0 with D(0) ≠ 0, from the signs of the two coefficients (exact)
    if d0 != 0.0 && (n0 == 0.0 || (n0 < 0.0) != (d0 < 0.0)) {
        out.push(at_zero(n0, d0));
    }
    for w in dedup(axis_zeros) {
        out.push(PhaseCrossover { omega: w, gain_margin: f64::INFINITY, gain_margin_db: f64::INFINITY });
    }
    for w in dedup(phase.into_iter().filter(|&w| holds(lp, tau, Kind::Phase, w)).collect()) {
        let v = lp.l.at(w);
        let re = v.value(w).re;
        // L(jω) ≤ 0 and D(jω) ≠ 0 (an axis pole makes Im L = 0 trivially but L infinite)
        if matches!(v, AxisValue::Limit { order, .. } if order < 0) || re > 0.0 {
            continue;
        }
        let ln = v.ln_abs(w);
        out.push(PhaseCrossover {
            omega: w,
            gain_margin: (-ln).exp(),
            gain_margin_db: -ln * (20.0 / std::f64::consts::LN_10),
        });
    }
    out
}

/// Sorted, with crossovers closer than 10⁻¹² relative merged (two starting points that
/// converged to one crossover).
fn dedup(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * a.abs().max(b.abs()));
    v
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
