//! Explicit Runge–Kutta methods from Butcher tableaux: fixed-step Euler, Heun, RK4 and
//! DOP853's 8th-order tableau; adaptive DOPRI5 and DOP853 with dense output and events;
//! Gragg–Bulirsch–Stoer extrapolation ([`Extrapolation`]) for tight tolerances.
//!
//! Book: §4.11 (the rate equations are integrated numerically); HNW ch. II.

mod adaptive;
mod dense;
mod dop853;
mod dop853_coefficients;
mod dopri5;
mod drive;
mod events;
mod extrapolation;
mod fixed;
mod gbs_lanes;
mod gbs_stepper;
mod pair;
mod root;
mod stepper;
mod tableau;
mod vern9;
mod vern9_coefficients;

pub use dense::DenseStep;
pub(crate) use dense::Form;
pub use drive::Solution;
pub(crate) use drive::{Steps, drive};
pub use events::{Direction, Event, EventHit, bracket_zero};
pub use extrapolation::{Extrapolation, GBS_MAX_COLUMNS, Gbs};
pub use fixed::integrate_fixed;
pub use gbs_stepper::GbsStepper;
pub(crate) use pair::initial_step;
pub use pair::{Adaptive, Pair};
pub use stepper::Stepper;
pub use tableau::{DOP853, DOPRI5, EULER, HEUN, RK4, Tableau, VERN9};
