//! Chapter 4: kinematics (book §4.1–4.21). The executable textbook for frame derivatives,
//! angular velocity and acceleration, transport theorems, attitude rate equations, chains,
//! instantaneous centres and rolling. Split by topic into `tests/ch04/*.rs`.
//!
//! Oracles: exact time derivatives from num-dual (`Dual2_64` carries value, first and second
//! derivative of every path), finite differences only where a third derivative is needed.

mod support;

#[path = "ch04/paths.rs"]
mod paths;

#[path = "ch04/frames.rs"]
mod frames;

#[path = "ch04/transport.rs"]
mod transport;

#[path = "ch04/chains.rs"]
mod chains;

#[path = "ch04/centres.rs"]
mod centres;

#[path = "ch04/examples.rs"]
mod examples;

#[path = "ch04/problems.rs"]
mod problems;

#[path = "ch04/attitude.rs"]
mod attitude;
