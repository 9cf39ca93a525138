//! Which parts of the right-hand side a scene's declared effects call for: the physics crate
//! evaluates only those (ABA alone for a free body; poses for gravitation; twists for dashpots
//! and aerodynamics; the multiplier system for loops, rolling and inerters).
//!
//! Book: §7.11 (ABA), ch. 6 (the declared loads).

use super::build::Built;
use super::parts::{Effect, Src};
use super::spec::{EffectSpec, SceneSpec};
use super::{SceneError, aero};

/// Which parts of the right-hand side the declared effects need.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Needs {
    /// Force elements to apply (none: ABA alone, gravity as base acceleration).
    pub loads: bool,
    /// The loads read link poses (all but rotational springs and dashpots, which read q, v).
    pub poses: bool,
    /// The loads read link twists too (dashpots, aero effects).
    pub twists: bool,
    /// Some loads are joint torques (rotational springs and dashpots); the others act as link
    /// wrenches only, and the joint torques stay zero.
    pub joint_torques: bool,
    pub inerters: bool,
    pub rolling: bool,
    pub impacts: bool,
    pub loops: bool,
    /// Every joint's coordinates are its velocities (pins, sleeves, collars, slots, welds: no
    /// ball or free joint), numbered alike: q̇ = v is a copy.
    pub qdot_is_v: bool,
    /// An aero effect's forces depend on α̇ or β̇ (solved after ABA, see `aero`).
    pub aero_rates: bool,
    /// The shortest evaluation the above allow, decided once (see `Scene::deriv_plain`).
    pub route: Route,
}

/// The shortest path through the right-hand side a scene allows.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) enum Route {
    /// ABA alone: no loads, constraints, contacts or aero rate terms.
    #[default]
    Plain,
    /// The tree with its loads (and aero rate terms), no constraints or impacts.
    Tree,
    /// Everything: the multiplier system, impacts.
    Full,
}

impl Needs {
    /// Whether accelerations need the multiplier system (inerters, rolling, loops).
    pub fn constrained(&self) -> bool {
        self.inerters || self.rolling || self.loops
    }

    /// Nothing but the tree's own dynamics: no loads, constraints, contacts or aero rate terms
    /// (see `Scene::deriv_plain`).
    pub fn plain(&self) -> bool {
        !(self.loads || self.constrained() || self.impacts || self.aero_rates)
    }
}

impl Needs {
    /// What `built`'s effects need; refuses the combinations the right-hand side does not
    /// support (an aero effect or a joint stop beside loops, rolling or inerters).
    pub fn of(spec: &SceneSpec, built: &Built, src: &Src) -> Result<Self, SceneError> {
        let mut needs = Needs::default();
        for e in &built.effects {
            use Effect as E;
            match e {
                E::Uniform { .. } => {}
                E::RotSpring { .. } | E::RotDashpot { .. } => {
                    (needs.loads, needs.joint_torques) = (true, true)
                }
                E::Inerter { .. } | E::RotInerter { .. } => needs.inerters = true,
                E::Rolling { .. } => needs.rolling = true,
                E::Spheres { .. } | E::Plane { .. } | E::JointStop { .. } => needs.impacts = true,
                E::Dashpot { .. } | E::Aero { .. } => {
                    (needs.loads, needs.poses, needs.twists) = (true, true, true)
                }
                _ => (needs.loads, needs.poses) = (true, true),
            }
        }
        needs.loops = !built.loops.is_empty();
        needs.aero_rates = built.effects.iter().any(|e| match e {
            Effect::Aero { aircraft, .. } => aero::has_rate_terms(aircraft),
            _ => false,
        });
        if needs.aero_rates && needs.constrained() {
            let k = spec.effects.iter().position(|e| matches!(e, EffectSpec::Aero { .. })).unwrap_or(0);
            return Err(src.invalid(
            format!("effects[{k}]"),
            "an aero effect with loops, rolling contacts or inerters is not supported (its α̇/β̇ solve runs on \
             the tree's forward dynamics); valid: an aircraft in a tree of bodies (a slung load on a ball \
             joint, a rotor on a pin)",
        ));
        }
        if needs.constrained()
            && let Some(k) = spec.effects.iter().position(|e| matches!(e, EffectSpec::JointStop { .. }))
        {
            return Err(src.invalid(
            format!("effects[{k}]"),
            "a joint stop in a scene with loops, rolling contacts or inerters is not supported (its impulse \
             and holding force act on the tree alone); valid: joint stops on a tree of bodies",
        ));
        }
        // only ball joints (also of free joints) have more coordinates than speeds
        needs.qdot_is_v = built.model.nq() == built.model.nv();
        needs.route = if needs.plain() {
            Route::Plain
        } else if !(needs.constrained() || needs.impacts) {
            Route::Tree
        } else {
            Route::Full
        };
        Ok(needs)
    }
}
