//! # vectrix-ode: integrators and the evidence of what accuracy costs
//!
//! * explicit Runge–Kutta from Butcher tableaux ([`EULER`], [`HEUN`], [`RK4`]) and the
//!   adaptive Dormand–Prince pairs ([`Adaptive::dopri5`], [`Adaptive::dop853`]) with error
//!   control, dense output and event location;
//! * Gauss–Legendre collocation ([`GaussLegendre`]: implicit midpoint, 2 and 3 stages, Newton
//!   with faer) and Störmer–Verlet ([`stormer_verlet`]);
//! * Lie-group methods for attitude ([`LieMethod`]: exponential Euler, RKMK4,
//!   Crouch–Grossman) over a small [`LieGroup`] trait, and the exact quaternion step
//!   [`quaternion_exact_step`] (4.11.17);
//! * a work–precision [`harness`] on reference problems with exact solutions, and the
//!   [`Accuracy`] choice derived from it.
//!
//! Every run reports its [`Work`]. Bad input returns an [`OdeError`] that says where.
//!
//! Book: §4.11 (integration of the attitude rate equations); HNW = Hairer, Nørsett &
//! Wanner, *Solving Ordinary Differential Equations I*; HLW = Hairer, Lubich & Wanner,
//! *Geometric Numerical Integration*.
#![warn(missing_docs)]

mod accuracy;
mod error;
pub mod explicit;
pub mod harness;
pub mod implicit;
pub mod lie;
mod state;
mod work;

pub use accuracy::{ACCURACY_TABLE, Accuracy, AccuracyRow};
pub use error::OdeError;
pub use explicit::{
    Adaptive, DOP853, DOPRI5, Direction, EULER, Event, EventHit, HEUN, Pair, RK4, Solution, Tableau,
};
pub use implicit::{GaussLegendre, stormer_verlet};
pub use lie::{LieGroup, LieMethod, integrate_lie, quaternion_exact_step};
pub use state::State;
pub use work::Work;

/// `use vectrix_ode::prelude::*;`
pub mod prelude {
    pub use crate::{
        Accuracy, Adaptive, Direction, Event, GaussLegendre, LieGroup, LieMethod, OdeError, Pair, Solution,
        State, Work, integrate_lie, stormer_verlet,
    };
}
