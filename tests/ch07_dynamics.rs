//! Chapter 7: Newton–Euler dynamics (book §7.1–7.18): particles and rigid bodies, Euler's
//! equation (rank-aware), the eigenaxis and 6D forms, spring–dashpot networks, multibody
//! trees (RNEA, ABA, CRBA with joint reactions), collisions and impulses, and the worked
//! examples and solved problems. Split by topic into `tests/ch07/*.rs`.

mod support;

#[path = "ch07/rigid.rs"]
mod rigid;

#[path = "ch07/network.rs"]
mod network;

#[path = "ch07/multibody.rs"]
mod multibody;

#[path = "ch07/examples.rs"]
mod examples;

#[path = "ch07/problems.rs"]
mod problems;

#[path = "ch07/theory.rs"]
mod theory;

#[path = "ch07/link.rs"]
mod link;

#[path = "ch07/collision.rs"]
mod collision;

#[path = "ch07/prop.rs"]
mod prop;
