//! Chapter 9: Lagrange's and Hamilton's equations without symbols (book §9.3–9.13), with
//! constraints and multipliers (§9.11–9.12) and Kane's equations (§9.14).
//! T, U, R are written once, generic over the scalar; vectrix differentiates them exactly with
//! dual numbers. Split by topic into `tests/ch09/*.rs`.

mod support;

#[path = "ch09/systems.rs"]
mod systems;

#[path = "ch09/examples.rs"]
mod examples;

#[path = "ch09/laws.rs"]
mod laws;

#[path = "ch09/prop.rs"]
mod prop;

#[path = "ch09/mechanisms.rs"]
mod mechanisms;

#[path = "ch09/rolling.rs"]
mod rolling;

#[path = "ch09/constraints.rs"]
mod constraints;

#[path = "ch09/nonholonomic.rs"]
mod nonholonomic;

#[path = "ch09/kane.rs"]
mod kane;

#[path = "ch09/four_bar.rs"]
mod four_bar;

#[path = "ch09/problems.rs"]
mod problems;

#[path = "ch09/sections.rs"]
mod sections;
