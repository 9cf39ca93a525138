//! Errors of the flight crate.

use thiserror::Error;

/// What was wrong with a flight-dynamics input, with what would be valid.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum FlightError {
    /// A mass, inertia, area, length or speed that must be positive (or otherwise bounded) is not.
    #[error("invalid {what} = {value}: {valid}")]
    OutOfRange {
        /// Which parameter.
        what: &'static str,
        /// The value given.
        value: f64,
        /// What would be valid.
        valid: &'static str,
    },
    /// A number (input, state, derivative or Jacobian entry) was NaN or infinite.
    #[error("non-finite value in {what}: every entry must be a finite number")]
    NonFinite {
        /// Which quantity.
        what: &'static str,
    },
    /// Euler-angle rates (10.9.9) are undefined at Θ = ±90° (det S = cos Θ).
    #[error("gimbal lock: cos Θ = {cos_theta:e} (Θ = ±90°); use quaternion attitude rates instead")]
    GimbalLock {
        /// cos Θ at the offending attitude.
        cos_theta: f64,
    },
    /// Wind-angle rates (10.9.20–22) are undefined at γ = ±90° (det = cos γ).
    #[error("flight path vertical: cos γ = {cos_gamma:e}; heading and bank rates are undefined at γ = ±90°")]
    VerticalFlightPath {
        /// cos γ.
        cos_gamma: f64,
    },
    /// A descriptor matrix (Υ of (14.1.7) or Γ of (14.3.x)) is singular.
    #[error("singular descriptor matrix in {what}: {reason}")]
    SingularDescriptor {
        /// Which model.
        what: &'static str,
        /// Why (e.g. U0 − Z_α̇ = 0).
        reason: String,
    },
    /// A trim solve did not converge: names the condition that could not be met.
    #[error("trim failed after {iterations} iterations: {condition} (residual {residual:e})")]
    TrimFailed {
        /// The residual condition that stayed largest, in words.
        condition: String,
        /// Its final value.
        residual: f64,
        /// Iterations used.
        iterations: usize,
    },
    /// The modes asked for do not exist in this model (e.g. no oscillatory pair).
    #[error("mode structure not as expected: {reason}")]
    ModeStructure {
        /// What was found.
        reason: String,
    },
    /// A figure could not be drawn.
    #[error("plot failed: {reason}")]
    Plot {
        /// The plotting layer's message.
        reason: String,
    },
    /// An error from the linear-systems layer.
    #[error(transparent)]
    Lti(#[from] vectrix_lti::LtiError),
}
