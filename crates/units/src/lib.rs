//! # vectrix-units: dimensions, units and quantity strings
//!
//! vectrix computes in SI with bare `f64` (DESIGN §7: units live at the edges). This crate is
//! the edge: it parses quantity strings such as `"2.2046226218487757 lb"`, `"-32.174 ft/s^2"`,
//! `"30 deg"` or `"1200 slug*ft^2"`, checks their [`Dimension`] against the one a caller
//! expects, and converts them to SI **exactly**: the number is kept as the decimal written and
//! every unit factor as an exact rational (ft = 0.3048 m, lb = 0.45359237 kg,
//! g₀ = 9.80665 m/s², π to 59 decimals for angles), so each converted value is rounded once.
//! It also writes SI values in a chosen [`UnitSystem`] with labels (`rad/s`, `ft/s^2`), and
//! offers typed scalars ([`Measure`] of a [`kind`]) for compile-time kinds.
//!
//! Book: §15.19 (dimensions and units; (15.19.1) 1 lb = 1 slug·ft/s² ≈ 4.4 N, (15.19.2)
//! 1 slug ≈ 14.59 kg; the book rounds, this crate uses the exact definitions), §1.6 (kinds of
//! physical vectors).
//!
//! ```
//! use vectrix_units::{Dimension, Quantity, UnitSystem};
//! let g = Quantity::parse("-32.174 ft/s^2")?;
//! assert_eq!(g.to_si(Dimension::ACCELERATION)?, -32.174 * 0.3048);
//! // the pound-force and the slug are their exact definitions, rounded once
//! assert_eq!(Quantity::parse("1 lbf")?.to_si(Dimension::FORCE)?, 4.4482216152605);
//! assert_eq!(Quantity::parse("1 slug")?.to_si(Dimension::MASS)?, 14.593902937206364);
//! // a wrong dimension is an error that names both
//! let e = Quantity::parse("3 ft")?.to_si(Dimension::VELOCITY).unwrap_err();
//! assert!(e.to_string().contains("expected velocity (m/s), given length (m)"));
//! assert_eq!(UnitSystem::Imperial.label(Dimension::MOMENT_OF_INERTIA), "slug*ft^2");
//! # Ok::<(), vectrix_units::UnitError>(())
//! ```
//!
//! # Grammar
//! ```text
//! quantity  = ws* number (ws* unit)? ws*                       at most 256 bytes
//! number    = [+-]? (digits ["." digits?] | "." digits) ([eE] [+-]? digits)?
//! unit      = power (ws* ("*" | "·" | "/") ws* power)*         left-associative: m/s/s = m/s^2
//! power     = primary ("^" [+-]? digits | superscript digits)?    |n| ≤ 16: m^2, s^-2, m², s⁻²
//! primary   = symbol | "1" | "(" ws* unit ws* ")"               1/s, kg/(m*s^2); depth ≤ 8
//! symbol    = exact symbol or alias | SI prefix + prefixable symbol
//! ```
//! An exact symbol wins over a prefix split, which settles every ambiguity: `min` is the
//! minute (not milli-inch), `mi` the mile, `nmi` the nautical mile (not nano-mile), `Pa` the
//! pascal (not peta-annum), `kn` the knot (the kilonewton is `kN`), `h` the hour, `g` the gram
//! (standard gravity is `g0`), `lb` the pound-*mass* (the book's force pound is `lbf`).
//! Prefixes (`E P T G M k h da d c m µ u μ n p f a`) apply to the SI symbols `m g s rad Hz N
//! Pa J W` only, once: `km`, `kg`, `ms`, `kN`, `MPa`, `mrad`; never `kft` or `kkg`. A space is
//! not a product: `kg m` is an error that says to write `kg*m`. The full table with exact
//! definitions is in `docs/units.md`.
//!
//! # Dimensions
//! Mass, length, time and plane angle. The angle is its own base dimension so that `rad/s`
//! and `1/s` (or `Hz`) are told apart; torque and angular momentum keep their SI form without
//! the radian (`N*m`, `kg*m^2/s`): see [`Dimension`].
//!
//! # Rounding
//! [`Quantity::to_si`], [`Quantity::to_unit`], [`Unit::convert`] and [`Unit::factor`] round
//! once (exact decimal or binary input × exact factor ratio, round to nearest even). π enters
//! with a relative error below 10⁻⁵⁹, so angle conversions are correctly rounded except for
//! values within 10⁻⁵⁹ (relative) of a rounding boundary. [`Measure`] arithmetic is plain
//! `f64` arithmetic. Results outside the normal `f64` range are [`UnitError::Overflow`] or
//! [`UnitError::Underflow`], never ∞, 0 or a subnormal.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod converter;
mod dimension;
mod error;
mod exact;
pub mod kind;
mod number;
mod parse;
mod quantity;
mod system;
mod table;
mod unit;
#[cfg(feature = "uom")]
mod uom_interop;

pub use converter::Converter;
pub use dimension::{Dimension, MAX_EXPONENT};
pub use error::{UnitError, valid_units};
pub use kind::{Kind, Measure};
pub use number::Number;
pub use parse::{MAX_DEPTH, MAX_LEN};
pub use quantity::Quantity;
pub use system::UnitSystem;
pub use unit::Unit;

/// `use vectrix_units::prelude::*;`
pub mod prelude {
    pub use crate::{Converter, Dimension, Measure, Number, Quantity, Unit, UnitError, UnitSystem};
}
