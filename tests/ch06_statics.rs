//! Chapter 6: statics (book §6.1–6.15), with §7.10.8 (spatial inertia) and §7.12 (inerters).
//! The executable textbook for mass properties, inertia, wrenches, free-body analysis and
//! force elements. Split by topic into `tests/ch06/*.rs`.

mod support;

#[path = "ch06/common.rs"]
mod common;

#[path = "ch06/mass.rs"]
mod mass;

#[path = "ch06/inertia.rs"]
mod inertia;

#[path = "ch06/wrench.rs"]
mod wrench;

#[path = "ch06/elements.rs"]
mod elements;

#[path = "ch06/problems.rs"]
mod problems;

#[path = "ch06/prop.rs"]
mod prop;
