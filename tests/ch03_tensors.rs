//! Chapter 3: tensors (book §3.1–3.10). The executable textbook for tensors of type (p, q),
//! contraction, elasticity, alternating tensors and the wedge product, multivectors of
//! Cl(3,0) and rotors. Split by topic into `tests/ch03/*.rs`; each topic file ends with its
//! property tests under `mod prop`. Errata follow `book/notes/ch3.md` and are tested in their
//! corrected form, with a comment at the point of use.

mod support;

#[path = "ch03/common.rs"]
mod common;

#[path = "ch03/tensors.rs"]
mod tensors;

#[path = "ch03/elasticity.rs"]
mod elasticity;

#[path = "ch03/wedge.rs"]
mod wedge;

#[path = "ch03/multivector.rs"]
mod multivector;

#[path = "ch03/rotors.rs"]
mod rotors;
