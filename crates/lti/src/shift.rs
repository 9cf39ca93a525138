//! Phase shift and time shift of harmonic signals of one frequency.
//!
//! Book: §16.1, (16.1.1)–(16.1.8).

use crate::error::LtiError;

/// The time shift Δt = −φ/ω of g(t) = sin(ωt + φ) relative to f(t) = sin ωt, so that
/// g(t) = f(t − Δt) (16.1.5): Δt < 0 (g advanced) for φ > 0, Δt > 0 (g delayed) for φ < 0.
///
/// Book: (16.1.4).
///
/// # Errors
/// [`LtiError::InvalidArgument`] unless φ is finite and ω > 0 is finite;
/// [`LtiError::Overflow`] when −φ/ω exceeds the f64 range.
pub fn time_shift(phase_rad: f64, omega: f64) -> Result<f64, LtiError> {
    if !(phase_rad.is_finite() && omega.is_finite() && omega > 0.0) {
        return Err(LtiError::InvalidArgument {
            what: "time shift",
            reason: format!("φ = {phase_rad}, ω = {omega}; need a finite φ and a finite ω > 0"),
        });
    }
    let dt = -phase_rad / omega;
    // φ/ω beyond the f64 range (φ = 10³⁰⁰, ω = 5·10⁻³²⁴): a typed error, not −∞
    if dt.is_finite() { Ok(dt) } else { Err(LtiError::Overflow { what: "time shift −φ/ω" }) }
}

/// True when g(t) = sin(ωt + φ̂) leads f(t) = sin(ωt + φ): 0 < φ̂ − φ ≤ 180° modulo 360°
/// (leading by more than 180° is lagging by less than 180°). Angles in degrees.
///
/// Book: §16.1, after (16.1.7).
///
/// # Errors
/// [`LtiError::NonFinite`] for a non-finite angle.
pub fn leads(phi_hat_deg: f64, phi_deg: f64) -> Result<bool, LtiError> {
    crate::error::check_finite("phase angles", [&phi_hat_deg, &phi_deg])?;
    // fmod is exact: the difference of the two remainders in (−720°, 720°) neither overflows
    // (φ̂ − φ did for ±f64::MAX) nor loses the angles' low bits to their size
    let d = (phi_hat_deg % 360.0 - phi_deg % 360.0).rem_euclid(360.0);
    Ok(d > 0.0 && d <= 180.0)
}
