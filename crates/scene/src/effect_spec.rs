//! The `[[effects]]` of a scene file, as written (see [`super::spec`]).
//!
//! Book: ch. 6 (force elements), §7.13 (collisions), §11.1 and §13.3–13.5 (aircraft).

use serde::{Deserialize, Serialize};

use super::profile::Profile;

/// One effect. Only declared effects are assembled.
///
/// Book: ch. 6 (force elements §6.7–6.13), §7.13 (collisions), §7.x rolling.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum EffectSpec {
    /// Uniform gravity g (ground components) on every body (6.11).
    UniformGravity {
        /// g [m/s²].
        g: [f64; 3],
    },
    /// Central gravity toward a fixed point: f = −μ m r̂/|r|² (6.12.1).
    CentralGravity {
        /// μ = G M [m³/s²].
        mu: f64,
        /// The attracting point (ground components).
        #[serde(default)]
        centre: [f64; 3],
    },
    /// Mutual gravitation between every pair of bodies (centres of mass), constant G.
    MutualGravitation {
        /// Gravitational constant.
        g: f64,
    },
    /// Translational spring f = −k(|r| − d) r̂ between two points (6.7.1).
    Spring {
        /// One end.
        a: Attach,
        /// Other end.
        b: Attach,
        /// Stiffness k [N/m].
        k: f64,
        /// Relaxed length d [m].
        #[serde(default)]
        length: f64,
    },
    /// Dashpot f = −c (d|r|/dt) r̂ between two points (6.8.1).
    Dashpot {
        /// One end.
        a: Attach,
        /// Other end.
        b: Attach,
        /// Damping c [N s/m].
        c: f64,
    },
    /// Inerter f = −b (d²|r|/dt²) r̂ between two points (6.8); enters the mass matrix.
    Inerter {
        /// One end.
        a: Attach,
        /// Other end.
        b: Attach,
        /// Inertance b [kg].
        inertance: f64,
    },
    /// Rotational spring on a one-angle joint: τ = −κ(θ − θ₀).
    RotationalSpring {
        /// The body whose joint it acts on (pin, collar or slot: the angle).
        body: String,
        /// κ [N m/rad].
        kappa: f64,
        /// θ₀ [rad].
        #[serde(default)]
        angle: f64,
    },
    /// Rotational dashpot on a one-angle joint: τ = −ξ θ̇.
    RotationalDashpot {
        /// The body.
        body: String,
        /// ξ [N m s/rad].
        xi: f64,
    },
    /// Rotational inerter on a one-angle joint: τ = −β θ̈ (adds β to the joint's mass).
    RotationalInerter {
        /// The body.
        body: String,
        /// β [kg m²].
        beta: f64,
    },
    /// Magnetic dipoles fixed in bodies, interacting pairwise (6.13.11), (6.13.18).
    Dipoles {
        /// The dipoles.
        dipoles: Vec<DipoleSpec>,
    },
    /// Applied force along a fixed ground direction, magnitude a function of time.
    Force {
        /// Where it acts.
        at: Attach,
        /// Direction (ground components; scaled by the profile).
        direction: [f64; 3],
        /// Magnitude profile.
        profile: Profile,
    },
    /// Applied torque about a fixed ground direction, magnitude a function of time.
    Torque {
        /// The body.
        body: String,
        /// Direction (ground components).
        direction: [f64; 3],
        /// Magnitude profile.
        profile: Profile,
    },
    /// Impacts of two spheres (free bodies) with restitution e and Coulomb friction μ.
    ContactSpheres {
        /// First sphere.
        a: String,
        /// Second sphere.
        b: String,
        /// Radius of a.
        radius_a: f64,
        /// Radius of b.
        radius_b: f64,
        /// Coefficient of restitution e ∈ [0, 1].
        restitution: f64,
        /// Coulomb friction μ ≥ 0.
        #[serde(default)]
        friction: f64,
    },
    /// Impacts of a sphere (free body) on a fixed plane.
    ContactPlane {
        /// The sphere.
        body: String,
        /// Its radius.
        radius: f64,
        /// A point of the plane (ground components).
        #[serde(default)]
        point: [f64; 3],
        /// Plane normal (ground components, toward the allowed side).
        normal: [f64; 3],
        /// e ∈ [0, 1].
        restitution: f64,
        /// μ ≥ 0.
        #[serde(default)]
        friction: f64,
    },
    /// The aerodynamic forces and moments of an aircraft on a free body (§11.1, §13.3–13.5):
    /// lift, drag and side force from the body's airspeed, angle of attack α and sideslip β,
    /// its angular velocity, α̇ and β̇, and the control deflections, with the aircraft's
    /// coefficient model. The body's link axes are the aircraft's (x forward, y right wing,
    /// z down); the air is at rest in the ground frame. α̇ and β̇ depend on the body's own
    /// acceleration, so the right-hand side solves for them exactly (the accelerations are
    /// affine in them).
    Aero {
        /// The aircraft body: on a free joint to the ground.
        body: String,
        /// The coefficient model from the catalogue: `business_jet` (Tables 14.1–14.2,
        /// converted exactly to SI).
        aircraft: String,
        /// Air density ρ [kg/m³] (default: the catalogue's, 0.000588 slug/ft³ at 40,000 ft).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rho: Option<f64>,
        /// Wing area S [m²] (default: the catalogue's).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        area: Option<f64>,
        /// Mean aerodynamic chord c̄ [m] (default: the catalogue's).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        chord: Option<f64>,
        /// Wing span b [m] (default: the catalogue's).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        span: Option<f64>,
        /// Overrides of the catalogue's nondimensional coefficients by name (`cm_alpha = -0.6`;
        /// `u_ref` is a speed [m/s]); names as in `vectrix_flight::Coefficients` (§13.3–13.5).
        #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
        coefficients: std::collections::BTreeMap<String, f64>,
        /// Elevator δe [rad] (trailing edge down positive).
        #[serde(default = "zero_profile")]
        elevator: Profile,
        /// Aileron δa [rad] (right aileron up positive).
        #[serde(default = "zero_profile")]
        aileron: Profile,
        /// Rudder δr [rad] (trailing edge left positive).
        #[serde(default = "zero_profile")]
        rudder: Profile,
    },
    /// Engine thrust F_T on a body along a line tilted up by `angle` from the link x axis,
    /// F_T [cos Φ_T, 0, −sin Φ_T] in link components (11.2.11), at the centre of mass.
    Thrust {
        /// The body.
        body: String,
        /// F_T(t) [N].
        profile: Profile,
        /// Thrust-line angle Φ_T [rad] above the link x axis (default 0).
        #[serde(default)]
        angle: f64,
    },
    /// Stops of a one-coordinate joint (pin or sleeve) at `lower` ≤ q ≤ `upper`: unilateral
    /// constraints with restitution e, through the same touch events, impacts and resting
    /// contact as a sphere on a plane (URDF `<limit>`, MJCF `range`, with `[model] limits =
    /// "contact"`). An impact sends the joint's speed from q̇ to −e q̇ by a generalized impulse
    /// on its coordinate (§7.14); a stop held (bounces accumulated, or e = 0) pushes with the
    /// generalized force that keeps q̈ = 0 until that force would have to pull.
    JointStop {
        /// The body whose joint is stopped.
        body: String,
        /// The lower stop [rad or m] (none: no lower stop).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        lower: Option<f64>,
        /// The upper stop [rad or m] (none: no upper stop).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        upper: Option<f64>,
        /// e ∈ [0, 1].
        #[serde(default)]
        restitution: f64,
    },
    /// Rolling without slip of a sphere or a disk (a free body, centre at its link origin)
    /// on a fixed plane.
    Rolling {
        /// The body.
        body: String,
        /// `sphere` or `disk` (disk normal = link z axis).
        shape: String,
        /// Radius.
        radius: f64,
        /// A point of the plane.
        #[serde(default)]
        point: [f64; 3],
        /// Plane normal (toward the body).
        normal: [f64; 3],
    },
}

/// A point fixed in a body (link components) or in the ground (`body = "ground"`).
///
/// Book: §6.7.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Attach {
    /// Body name or `ground`.
    pub body: String,
    /// The point relative to the link origin, link components.
    #[serde(default)]
    pub point: [f64; 3],
}

pub(crate) fn zero_profile() -> Profile {
    Profile::Constant { value: 0.0 }
}

/// A magnetic dipole m (link components) at the body's centre of mass.
///
/// Book: §6.13.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DipoleSpec {
    /// The body.
    pub body: String,
    /// Moment m (link components), in units where μ₀/4π = 1.
    pub moment: [f64; 3],
}

impl EffectSpec {
    /// The effect's profiles with their keys (`profile`, or an aircraft's `elevator`,
    /// `aileron`, `rudder`), in input order: each is one input of a linearization or trim.
    pub(crate) fn profiles(&self) -> Vec<(&'static str, &Profile)> {
        use EffectSpec as E;
        match self {
            E::Force { profile, .. } | E::Torque { profile, .. } | E::Thrust { profile, .. } => {
                vec![("profile", profile)]
            }
            E::Aero { elevator, aileron, rudder, .. } => {
                vec![("elevator", elevator), ("aileron", aileron), ("rudder", rudder)]
            }
            _ => vec![],
        }
    }

    /// [`Self::profiles`], mutable.
    pub(crate) fn profiles_mut(&mut self) -> Vec<&mut Profile> {
        use EffectSpec as E;
        match self {
            E::Force { profile, .. } | E::Torque { profile, .. } | E::Thrust { profile, .. } => vec![profile],
            E::Aero { elevator, aileron, rudder, .. } => vec![elevator, aileron, rudder],
            _ => vec![],
        }
    }
}
