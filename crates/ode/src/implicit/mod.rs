//! Implicit and symplectic methods: Gauss–Legendre collocation (implicit midpoint, 2 and
//! 3 stages) and Störmer–Verlet.
//!
//! Book: §4.11; HLW ch. II, IV, VI.

mod gauss;
mod verlet;

pub use gauss::GaussLegendre;
pub use verlet::stormer_verlet;
