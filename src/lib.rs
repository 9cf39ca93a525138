//! # vectrix
//!
//! Frame-free geometry, kinematics, statics and dynamics after Bernstein, Goel and Ansari,
//! *Geometry, Kinematics, Statics, and Dynamics*. This facade re-exports every layer; most
//! users need only `use vectrix::prelude::*;`.
//!
//! ```
//! use vectrix::prelude::*;
//! let a = Frame::new();
//! let x = a.vector([1.0, 2.0, 3.0]);
//! assert_eq!(x.resolve(&a), nalgebra::Vector3::new(1.0, 2.0, 3.0));
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub use nalgebra;
pub use num_dual;
#[cfg(feature = "uom")]
pub use uom;
pub use vectrix_dynamics as dynamics;
pub use vectrix_flight as flight;
pub use vectrix_frames as frames;
pub use vectrix_kinematics as kinematics;
pub use vectrix_lti as lti;
pub use vectrix_ode as ode;
pub use vectrix_plot as plot;
pub use vectrix_rotation as rotation;
#[cfg(feature = "scene")]
pub use vectrix_scene as scene;
pub use vectrix_statics as statics;
pub use vectrix_tensor as tensor;
pub mod units;

/// Everything for notebooks and applications: `use vectrix::prelude::*;`.
#[allow(unused_imports)] // layers still in progress export empty preludes
pub mod prelude {
    pub use vectrix_dynamics::prelude::*;
    pub use vectrix_flight::prelude::*;
    pub use vectrix_frames::prelude::*;
    pub use vectrix_kinematics::prelude::*;
    pub use vectrix_lti::prelude::*;
    pub use vectrix_ode::prelude::*;
    pub use vectrix_plot::prelude::*;
    pub use vectrix_rotation::prelude::*;
    #[cfg(feature = "scene")]
    pub use vectrix_scene::{Scene, SceneError};
    pub use vectrix_statics::prelude::*;
    pub use vectrix_tensor::prelude::*;
}

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The interop guide's examples (`docs/guide/interop.md`), compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../docs/guide/interop.md")]
pub struct InteropDoctests;
