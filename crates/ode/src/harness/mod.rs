//! The work–precision harness: reference problems with exact solutions.
//!
//! Book: §4.11; HNW §II.10 (work–precision diagrams).

pub mod elliptic;
