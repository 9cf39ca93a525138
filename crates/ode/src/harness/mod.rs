//! The work–precision harness: reference problems with exact solutions, every method over
//! a range of tolerances or step counts, recording (error, time, evaluations).
//!
//! Book: §4.11; HNW §II.10 (work–precision diagrams).

pub mod elliptic;
mod problems;
mod rigid;
mod run;
mod stiff;
mod suite;

pub use problems::{CHAIN_MASSES, Kepler, Oscillator, Pendulum, Reference, Separable, SpringChain};
pub use rigid::{RigidBody, euler_equations, quaternion_rate};
pub use run::{Budget, Method, Point, sweep, sweep_lie, sweep_verlet};
pub use stiff::{
    STIFF_PROBLEMS, StiffDerived, StiffProblem, derive_stiff_accuracy, robertson, robertson_jacobian, vdpol,
    vdpol_jacobian,
};
pub use suite::{Derived, FILE_STEMS, PROBLEMS, cheapest, derive_accuracy, run_all};
