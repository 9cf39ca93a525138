//! # vectrix-flight: aircraft flight dynamics
//!
//! Aircraft frames and angles, the nonlinear 12-state equations of motion built on the
//! rigid-body equations of `vectrix-dynamics`, aerodynamic models from stability and control
//! derivatives, trim, linearization with dual numbers (including the descriptor forms with
//! α̇ and β̇ terms), longitudinal and lateral models through `vectrix-lti`, and flight modes,
//! after Bernstein, Goel and Ansari, ch. 10–14, with the errata of the chapter notes
//! corrected.
//!
//! # Conventions
//! Earth frame F_E with k̂_E down; aircraft frame F_AC with î through the nose, ĵ along the
//! right wing, k̂ down; 3-2-1 Euler angles (Ψ, Θ, Φ); α = atan2(W, U),
//! β = atan2(V, √(U²+W²)); state x = [X Y Z U V W Φ Θ Ψ P Q R] (11.5.1).
//!
//! Bad input: every public function returns a correct value or a typed error (never a panic,
//! hang, NaN or ∞ inside `Ok`); the contract — which functions return `Result`, how overflow
//! and tolerances are reported — is `docs/robustness.md` in the repository.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod aero;
mod angles;
mod catalog;
mod derivatives;
mod eom;
mod error;
mod linearize;
mod modes;
mod plots;
mod rates;
mod table;
mod trim;

pub use aero::{
    Aircraft, Coefficients, Controls, Geometry, aero_angle_rates, cm_alpha_from_static_margin,
    induced_drag_factor, static_margin,
};
pub use angles::{AeroAngles, Euler321, FlightPathAngles, o_s_ac, o_w_ac, o_w_s, o1, o2, o3};
pub use catalog::{
    BUSINESS_JET_U0, BUSINESS_JET_WEIGHT, boeing_747_longitudinal_a, business_jet, business_jet_in,
    business_jet_lateral, business_jet_lateral_in, business_jet_longitudinal, business_jet_longitudinal_in,
};
pub use derivatives::{Descriptor, LateralDerivatives, LongitudinalDerivatives};
pub use eom::{AircraftState, Airframe, ForcesMoments, state_derivative};
pub use error::FlightError;
pub use linearize::{Linearization, linearize};
pub use modes::{
    FlightMode, LateralModes, LongitudinalModes, characteristic_polynomial, eigenflight, eigenvector,
    lateral_modes, longitudinal_modes,
};
pub use plots::{doublet, doublet_response, doublet_response_svg, modes_svg};
pub use rates::{
    GIMBAL_LOCK_TOL, body_rates, body_rates_from_wind_angle_rates, euler_rate_matrix, euler_rates,
    orientation_from_quaternion, quaternion_from_euler321, quaternion_rates, wind_angle_rate_matrix,
    wind_angle_rates,
};
pub use trim::{Trim, TrimLimits, TrimSpec, trim};

/// `use vectrix_flight::prelude::*;`
pub mod prelude {
    pub use crate::{
        AeroAngles, Euler321, FlightError, FlightPathAngles, LateralDerivatives, LongitudinalDerivatives,
    };
}
