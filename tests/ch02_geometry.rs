//! Chapter 2: geometry (book §2.1–2.24). The executable textbook for vectors, frames,
//! rotations and nonstandard frames. Split by topic into `tests/ch02/*.rs`.

mod support;

#[path = "ch02/geometry.rs"]
mod geometry;

#[path = "ch02/matrices.rs"]
mod matrices;

#[path = "ch02/nonstandard.rs"]
mod nonstandard;

#[path = "ch02/problems.rs"]
mod problems;

#[path = "ch02/rotations.rs"]
mod rotations;
