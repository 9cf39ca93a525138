//! # vectrix-ode: integrators and the evidence of what accuracy costs
//!
//! * explicit Runge–Kutta from Butcher tableaux ([`EULER`], [`HEUN`], [`RK4`]) and the
//!   adaptive Dormand–Prince pairs ([`Adaptive::dopri5`], [`Adaptive::dop853`]) with error
//!   control, dense output and event location; for smooth problems at tight tolerances,
//!   Verner's 9(8) pair ([`Adaptive::vern9`], no interpolant) and Gragg–Bulirsch–Stoer
//!   extrapolation ([`Extrapolation::gbs`]: order and step control);
//! * the stiff integrator RADAU5 ([`Radau5`]: Radau IIA 5 with Hairer–Wanner's control,
//!   exact or finite-difference Jacobians, dense output and events), the variable-order BDF
//!   ([`Bdf`], orders 1–5, the same Jacobians, dense output and events), and [`AnyStepper`]
//!   to drive any of them step by step; [`Solver`] holds the settings all adaptive methods
//!   share and [`Progress`] where a step-by-step run stands; the steppers take f returning a
//!   new state or written in place ([`InPlace`]: in the explicit pairs no allocation per
//!   evaluation for `Vec` or `DVector` states; the same bits), both a [`Rhs`];
//! * Gauss–Legendre collocation ([`GaussLegendre`]: implicit midpoint, 2 and 3 stages, Newton
//!   with the dense LU of [`implicit::DenseLu`]) and Störmer–Verlet ([`stormer_verlet`]);
//! * Taylor series integration ([`Taylor`]: order 10–20 series of a smooth right-hand side
//!   written over [`taylor::Var`], by automatic differentiation, Jorba & Zou's order and step
//!   size; dense output from the series);
//! * Lie-group methods for attitude ([`LieMethod`]: exponential Euler, RKMK4,
//!   Crouch–Grossman) over a small [`LieGroup`] trait, and the exact quaternion step
//!   [`quaternion_exact_step`] (4.11.17);
//! * a work–precision `harness` on reference problems with exact solutions (cargo feature
//!   `harness`, off by default: the command line, tests and benches turn it on), and the
//!   [`Accuracy`] choice derived from it.
//!
//! Every run reports its [`Work`]. Bad input returns an [`OdeError`] that says where.
//!
//! ```
//! use nalgebra::Vector2;
//! use vectrix_ode::{Accuracy, Adaptive, Direction, Event};
//! // ẍ = −x from x = 1 at rest: x = cos t; stop where x crosses 0 downwards (t = π/2)
//! let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], -y[0]);
//! let mut stop = [Event::new(|_, y: &Vector2<f64>| y[0]).direction(Direction::Falling).terminal(true)];
//! let sol = Adaptive::dop853().rtol(1e-12).atol(1e-12)
//!     .solve_with_events(f, 0.0, &Vector2::new(1.0, 0.0), 10.0, &mut stop)?;
//! assert!((sol.t.last().unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-10);
//! // or state the accuracy and let the harness table choose the method
//! let sol = Accuracy::RelTol(1e-9).solve(f, 0.0, &Vector2::new(1.0, 0.0), 10.0)?;
//! assert!((sol.last()[0] - 10f64.cos()).abs() < 1e-9);
//! println!("{}", sol.work); // f-evals, accepted/rejected steps, Jacobians, wall time
//! # Ok::<(), vectrix_ode::OdeError>(())
//! ```
//!
//! Book: §4.11 (integration of the attitude rate equations); HNW = Hairer, Nørsett &
//! Wanner, *Solving Ordinary Differential Equations I*; HLW = Hairer, Lubich & Wanner,
//! *Geometric Numerical Integration*.
//!
//! Bad input: every public function returns a correct value or a typed error (never a panic,
//! hang, NaN or ∞ inside `Ok`); the contract — which functions return `Result`, how overflow
//! and tolerances are reported — is `docs/robustness.md` in the repository.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod accuracy;
mod error;
pub mod explicit;
#[cfg(feature = "harness")]
pub mod harness;
pub mod implicit;
pub mod lie;
mod method;
mod progress;
mod rhs;
mod solver;
mod state;
mod stiffness;
pub mod taylor;
mod work;

pub use accuracy::{ACCURACY_TABLE, Accuracy, AccuracyRow, STIFF_ACCURACY_TABLE, StiffRow};
pub use error::OdeError;
pub use explicit::{
    Adaptive, DOP853, DOPRI5, Direction, EULER, Event, EventHit, Extrapolation, GBS_MAX_COLUMNS, Gbs, HEUN,
    Pair, RK4, Solution, Tableau, VERN9,
};
pub use implicit::{
    Bdf, BdfFormula, BdfStepper, GaussLegendre, Implicit, Radau5, RadauIIA, RadauStepper, stormer_verlet,
};
pub use lie::{LieGroup, LieMethod, integrate_lie, quaternion_exact_step};
pub use method::{AnyStepper, Method};
pub use progress::Progress;
pub use rhs::{InPlace, Rhs};
pub use solver::Solver;
pub use state::State;
pub use stiffness::{Choice, STIFF_CHECK_EVERY, STIFF_H_RHO, STIFF_MIN_STEPS};
pub use taylor::{Taylor, TaylorRhs};
pub use work::Work;

/// `use vectrix_ode::prelude::*;`
pub mod prelude {
    pub use crate::{
        Accuracy, Adaptive, Direction, Event, Extrapolation, GaussLegendre, LieGroup, LieMethod, OdeError,
        Pair, Solution, State, Work, integrate_lie, stormer_verlet,
    };
}
