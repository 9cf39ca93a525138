//! The adversarial suite (issue 22): every public function of every crate, called with zero,
//! ±0, subnormal, 1e±300, ±∞, NaN, empty and mismatched-length inputs, must return a typed
//! error or a finite value that satisfies its defining property — never panic, hang, abort or
//! hand back NaN/∞ inside `Ok`. The policy is `docs/robustness.md`.
//!
//! One file per crate under `tests/adversarial/`, each a table of cases (`cases!`) naming the
//! functions it exercises. The coverage test (`coverage.rs`) reads each crate's public API
//! from its source and fails with the list of public functions that no case names, so a new
//! public function without a case fails CI.

mod support;

#[path = "adversarial/api.rs"]
mod api;
#[path = "adversarial/coverage.rs"]
mod coverage;
#[path = "adversarial/harness.rs"]
#[macro_use]
mod harness;
#[cfg(feature = "cli")]
#[path = "adversarial/cli.rs"]
mod cli;
/// Without the `cli` feature the command is not built and has nothing to call: coverage.rs
/// switches the crate off.
#[cfg(not(feature = "cli"))]
mod cli {
    pub const COVERED: &[&str] = &[];
}
#[path = "adversarial/aircraft_scene.rs"]
mod aircraft_scene;
#[path = "adversarial/dynamics.rs"]
mod dynamics;
#[path = "adversarial/flight.rs"]
mod flight;
#[path = "adversarial/frames.rs"]
mod frames;
#[path = "adversarial/kinematics.rs"]
mod kinematics;
#[path = "adversarial/lti.rs"]
mod lti;
#[path = "adversarial/multibody.rs"]
mod multibody;
#[path = "adversarial/ode.rs"]
mod ode;
#[path = "adversarial/plot.rs"]
mod plot;
#[path = "adversarial/rotation.rs"]
mod rotation;
#[path = "adversarial/scene.rs"]
mod scene;
#[path = "adversarial/scene_format.rs"]
mod scene_format;
#[path = "adversarial/sealed.rs"]
mod sealed;
#[path = "adversarial/statics.rs"]
mod statics;
#[path = "adversarial/tensor.rs"]
mod tensor;
