//! Units at the edges (book §15.19) and typed physical vectors (book §1.6).
//!
//! Everything of `vectrix-units` (quantity strings, [`Dimension`], [`UnitSystem`],
//! [`Measure`] and the [`kind`]s) plus, because they need the kernel, the typed physical
//! vectors [`Physical<K>`] and typed constructors and reads of mass properties.
//!
//! The kernel stays untyped SI `f64`: a typed value wraps the same `f64` or `Vector`
//! (`#[repr(transparent)]`), is built and read at the edges of a computation, and is
//! unwrapped for free ([`Physical::si`], [`Measure::si`]) before the hot path.
//!
//! ```
//! use vectrix::prelude::*;
//! use vectrix::units::kind::{Force, Length, Moment};
//! use vectrix::units::{Measure, Physical};
//! let a = Frame::new();
//! let r: Physical<Length> = Physical::parse(&a, ["2 ft", "0 ft", "0 ft"])?;
//! let f: Physical<Force> = Physical::parse(&a, ["0 lbf", "10 lbf", "0 lbf"])?;
//! let m: Physical<Moment> = r.cross(&f); // r⃗ × f⃗ is a moment (§6.3)
//! let [_, _, mz] = m.resolve_in(&a, "ft*lbf")?;
//! assert!((mz - 20.0).abs() <= 4.0 * f64::EPSILON * 20.0);
//! let mass = Measure::<vectrix::units::kind::Mass>::new(1.0, "slug")?;
//! assert_eq!(mass.si(), 14.593902937206364);
//! # Ok::<(), vectrix::units::UnitError>(())
//! ```

mod physical;

pub use physical::{
    AsPhysical, CrossKind, Physical, TypedMassProperties, mass_properties, principal_mass_properties,
};
pub use vectrix_units::*;
