//! Implicit and symplectic methods: Gauss–Legendre collocation (implicit midpoint, 2 and
//! 3 stages), Störmer–Verlet, and the adaptive stiff integrators Radau IIA 5 (RADAU5) and
//! variable-order BDF.
//!
//! Book: §4.11; HLW ch. II, IV, VI; HW §IV.8.

mod bdf;
mod bdf_stepper;
mod gauss;
mod lu;
mod radau5;
mod radau_core;
mod radau_stepper;
mod solve;
mod verlet;

pub use bdf::{Bdf, BdfFormula};
pub use bdf_stepper::BdfStepper;
pub use gauss::GaussLegendre;
pub use lu::{DenseLu, LuError, LuScalar};
pub use radau_core::NoJacobian;
pub use radau_stepper::RadauStepper;
pub use radau5::{Radau5, RadauIIA};
pub use solve::Implicit;
pub use verlet::stormer_verlet;

/// (c₁ − 1, c₂ − 1) of Radau IIA 5, for its dense output.
pub(crate) fn radau_nodes_minus_one() -> (f64, f64) {
    (radau_core::C1 - 1.0, radau_core::C2 - 1.0)
}
