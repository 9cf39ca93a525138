//! The `[[loops]]` tables of a scene file: joints that close kinematic loops and couplings of
//! joint coordinates (re-exported as `spec::LoopSpec`).
//!
//! Book: §9.11 (holonomic constraints), §6.10 (reactions of joints), §1.5 (joints).

use serde::{Deserialize, Serialize};

use crate::spec::Attach;

/// A loop-closing joint between a point of body `a` and a point of body `b` (or the ground).
///
/// Book: §9.11 (holonomic constraints), §6.10 (reactions of joints), §1.5 (joints).
///
/// # Conventions
/// Points are link components of their body (ground components for `ground`); `axis` is in
/// `a`'s link frame, `direction` and `normal` in `b`'s. The reaction reported as
/// `reaction:NAME` is the force (and moment) the loop joint exerts on body `a`, ground
/// components.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum LoopSpec {
    /// The two points coincide (a spherical joint): 3 constraints.
    Ball {
        /// Name (outputs `reaction:NAME`).
        name: String,
        /// Point of the first body.
        a: Attach,
        /// Point of the second body.
        b: Attach,
    },
    /// The two points coincide and the bodies turn relative to each other only about `axis`
    /// (a revolute joint): 3 + 2 constraints (in a planar mechanism some are redundant, and
    /// are dropped: their reactions are indeterminate and reported as 0).
    Pin {
        /// Name.
        name: String,
        /// Point of the first body.
        a: Attach,
        /// Point of the second body.
        b: Attach,
        /// The pin axis, `a`'s link components.
        axis: [f64; 3],
    },
    /// Point `a` stays on the line through point `b` along `direction` (a slider): 2
    /// constraints.
    PointOnLine {
        /// Name.
        name: String,
        /// The sliding point.
        a: Attach,
        /// A point of the line.
        b: Attach,
        /// The line's direction, `b`'s link components.
        direction: [f64; 3],
    },
    /// Point `a` stays on the plane through point `b` with `normal`: 1 constraint.
    PointOnPlane {
        /// Name.
        name: String,
        /// The point.
        a: Attach,
        /// A point of the plane.
        b: Attach,
        /// The plane's normal, `b`'s link components.
        normal: [f64; 3],
    },
    /// The two bodies keep the relative pose they have at the initial state (a weld, MJCF
    /// `<equality><weld>`): the points coincide (3 constraints) and the relative orientation
    /// is fixed (3 constraints). The reaction is a force and a couple on `a`.
    Weld {
        /// Name.
        name: String,
        /// Point of the first body.
        a: Attach,
        /// Point of the second body (the same point as `a` at the initial state).
        b: Attach,
    },
    /// A linear coupling of two joint coordinates (a gear; URDF `<mimic>`, MJCF `<equality>
    /// <joint polycoef>` with a linear polynomial): q_body = ratio · q_leader + offset, one
    /// holonomic constraint. Both joints have one coordinate (pin or sleeve); without
    /// `leader` the joint is locked at q_body = offset. The reaction is the generalized force
    /// (N m for a pin, N for a sleeve) the coupling applies to `body`'s joint; the leader's
    /// joint receives −ratio times it.
    Coupler {
        /// Name.
        name: String,
        /// The body whose joint follows.
        body: String,
        /// The body whose joint leads (none: the joint is locked).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        leader: Option<String>,
        /// The gear ratio m in q_body = m q_leader + offset.
        #[serde(default = "one")]
        ratio: f64,
        /// The offset [rad or m].
        #[serde(default)]
        offset: f64,
    },
}

impl LoopSpec {
    /// The loop's name.
    pub fn name(&self) -> &str {
        match self {
            Self::Ball { name, .. }
            | Self::Pin { name, .. }
            | Self::PointOnLine { name, .. }
            | Self::PointOnPlane { name, .. }
            | Self::Weld { name, .. }
            | Self::Coupler { name, .. } => name,
        }
    }
}

fn one() -> f64 {
    1.0
}
