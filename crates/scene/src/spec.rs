//! The scene file format (TOML, serde): what a scene declares. Every table rejects unknown
//! keys, so a misspelt key is an error with its line and column, not a silent default.
//!
//! Book: §7.11 (trees of bodies and joints), ch. 6 (force elements), §7.13 (collisions).

use serde::{Deserialize, Serialize};

pub use super::profile::Profile;

/// A whole scene: bodies joined in a tree, the effects acting on them, the run and the outputs.
///
/// Book: §7.11, ch. 6.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    /// Name of the scene (the output folder `out/<name>/`).
    pub name: String,
    /// End time of the run, t ∈ [0, duration] [s].
    pub duration: f64,
    /// Global relative accuracy asked for (picks method and tolerance, `vectrix_ode::Accuracy`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub accuracy: Option<f64>,
    /// An explicit method instead of an accuracy.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub method: Option<MethodSpec>,
    /// Number of output samples (rows of trajectory.csv after the initial one): intervals of
    /// duration/samples, taken from the integrator's dense output (they do not change the
    /// steps taken). At most 1 000 000, and samples × columns at most 5·10⁷.
    #[serde(default = "default_samples")]
    pub samples: usize,
    /// Bound on the integrator's steps (accepted + rejected); 10⁷ when omitted. A run that
    /// reaches it (or whose pace predicts it would by ten times) stops early with what it
    /// computed, marked incomplete.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_steps: Option<usize>,
    /// Bound on the wall time of the run [s]; 600 when omitted; as `max_steps`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_wall_seconds: Option<f64>,
    /// Named frames (orientations relative to the ground) that joints may be placed in.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub frames: Vec<FrameSpec>,
    /// A robot model read from a URDF or MJCF file (issue 35, `import`): its links become
    /// bodies after the scene's own `bodies`, its loops after the scene's `loops`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model: Option<ModelSpec>,
    /// The bodies, each joined to its parent (or to the ground).
    #[serde(default)]
    pub bodies: Vec<BodySpec>,
    /// The effects acting: only these are assembled.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub effects: Vec<EffectSpec>,
    /// Joints that close kinematic loops (a four-bar's coupler–rocker pin): constraints between
    /// two points of the tree, solved with Lagrange multipliers (§9.11), their drift projected
    /// away after every step.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub loops: Vec<LoopSpec>,
    /// How `vectrix linearize` treats the initial state (an equilibrium unless `steady`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub linearize: Option<LinearizeSpec>,
    /// Make the initial state steady (v̇ = 0) by solving for the named coordinates, speeds and
    /// input magnitudes before anything else (see `Scene::trim`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trim: Option<TrimSpec>,
    /// Project the initial state onto the loop constraints (assemble the mechanism) instead of
    /// refusing a start that violates them.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub assemble: bool,
    /// Quantities written to trajectory.csv and plotted.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub outputs: Vec<String>,
    /// Invariants whose drift is measured (`energy`, `momentum`, `angular_momentum`), if the
    /// declared effects imply they hold.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub checks: Vec<String>,
    /// Write `view.html`, the run's self-contained 3-D view, into the output folder (`true`
    /// when omitted; `vectrix run --no-view` skips it as well).
    #[serde(default = "yes", skip_serializing_if = "is_yes")]
    pub view: bool,
}

fn zero_profile() -> Profile {
    Profile::Constant { value: 0.0 }
}

fn default_samples() -> usize {
    200
}

/// The default of a key that is on unless turned off.
pub(crate) fn yes() -> bool {
    true
}

/// Whether a key is at its default `true` (then it is not serialized).
#[allow(clippy::trivially_copy_pass_by_ref)]
pub(crate) fn is_yes(b: &bool) -> bool {
    *b
}

/// An integration method chosen by name.
///
/// Book: §4.11.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MethodSpec {
    /// `dopri5`, `dop853`, `radau5` or `bdf` (stiff scenes).
    pub name: String,
    /// Relative (= absolute) local tolerance.
    pub rtol: f64,
}

/// A named frame: the ground frame rotated by `angle` [rad] about `axis` (ground components).
///
/// Book: §2.10 (frames rotated about an axis).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrameSpec {
    /// Name used by `BodySpec::frame`.
    pub name: String,
    /// Rotation axis, ground components (nonzero).
    pub axis: [f64; 3],
    /// Rotation angle [rad] (right-hand rule).
    pub angle: f64,
}

/// One body: mass properties, the joint to its parent and its initial joint state.
///
/// # Conventions
/// `offset` is the joint point relative to the parent's link origin, parent components; the
/// link frame coincides with the joint frame at q = 0; `com` is in link components.
///
/// Book: §7.11, §6.1–6.2.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Unique name (`ground` is reserved).
    pub name: String,
    /// Parent body name, `ground` when omitted.
    #[serde(default = "ground", skip_serializing_if = "is_ground")]
    pub parent: String,
    /// The joint into the parent.
    pub joint: JointSpec,
    /// Joint point relative to the parent link origin (parent components).
    #[serde(default)]
    pub offset: [f64; 3],
    /// Orientation of the joint frame: a frame of `frames` (relative to the ground, and only
    /// for bodies on the ground), identity when omitted.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub frame: Option<String>,
    /// Orientation of the joint frame relative to the parent link frame, as the rows of the
    /// rotation matrix whose columns are the joint frame's axes in parent components (URDF's
    /// `rpy`, MJCF's `quat`); identity when omitted; not together with `frame`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub orientation: Option<[[f64; 3]; 3]>,
    /// Mass properties.
    pub mass: MassSpec,
    /// Centre of mass relative to the link origin (link components).
    #[serde(default)]
    pub com: [f64; 3],
    /// Initial joint coordinates (length nq of the joint; neutral when omitted).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q: Option<Vec<f64>>,
    /// Initial joint velocities (length nv of the joint; zero when omitted).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub v: Option<Vec<f64>>,
}

/// The `[model]` table: a URDF or MJCF file whose links and joints become bodies.
///
/// Book: §7.11 (trees of bodies and joints); URDF (ROS `urdf/XML`), MJCF (MuJoCo XML reference).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelSpec {
    /// A URDF file, relative to the scene file and inside its folder tree.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub urdf: Option<String>,
    /// An MJCF file, relative to the scene file and inside its folder tree.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mjcf: Option<String>,
    /// Refuse the model when any element or attribute does not map (instead of a warning).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub strict: bool,
    /// Add uniform gravity: MJCF's `<option gravity>`, else (0, 0, −9.81) m/s².
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub gravity: bool,
    /// Initial joint coordinates of the model's bodies, by body name (as `bodies[].q`).
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub q: std::collections::BTreeMap<String, Vec<f64>>,
    /// Initial joint velocities of the model's bodies, by body name (as `bodies[].v`).
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub v: std::collections::BTreeMap<String, Vec<f64>>,
}

fn ground() -> String {
    "ground".into()
}

fn is_ground(s: &String) -> bool {
    s == "ground"
}

/// The book's joints (§1.5) plus weld and free; axes in the joint frame.
///
/// Book: §1.5, Table 1.3.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum JointSpec {
    /// Rotation about `axis`: q = [θ].
    Pin {
        /// Axis.
        axis: [f64; 3],
    },
    /// Translation along `axis`: q = [s].
    Sleeve {
        /// Axis.
        axis: [f64; 3],
    },
    /// Translation along and rotation about `axis`: q = [s, θ].
    Collar {
        /// Axis.
        axis: [f64; 3],
    },
    /// Translation along `direction`, rotation about `axis` ⊥ direction: q = [s, θ].
    Slot {
        /// Pin axis.
        axis: [f64; 3],
        /// Groove direction.
        direction: [f64; 3],
    },
    /// Spherical: q = quaternion (η, ε₁, ε₂, ε₃), v = ω in the link frame. (Written `{}` so
    /// that an unknown key in its table is an error, as in every other table.)
    Ball {},
    /// Rigid attachment.
    Weld {},
    /// Six degrees of freedom: q = (x, y, z, η, ε₁, ε₂, ε₃), v = (ẋ, ẏ, ż, ω in the link).
    Free {},
}

/// Mass properties by shape or by value (about the centre of mass, link components).
///
/// Book: §6.1–6.2, Table of shapes (§6.14 problems).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "shape", rename_all = "snake_case", deny_unknown_fields)]
pub enum MassSpec {
    /// A particle (zero inertia; needs a parent joint that leaves no rotation free about it).
    Particle {
        /// Mass [kg].
        mass: f64,
    },
    /// No mass and no inertia: an ideal intermediate link (a gimbal ring, a massless arm) that
    /// carries other bodies; a massless body with nothing attached is refused.
    Massless {},
    /// Solid sphere: J = (2/5) m r² I.
    Sphere {
        /// Mass [kg].
        mass: f64,
        /// Radius [m].
        radius: f64,
    },
    /// Solid box with sides along the link axes: J_x = m(b² + c²)/12, ….
    Box {
        /// Mass [kg].
        mass: f64,
        /// Side lengths along x, y, z [m].
        sides: [f64; 3],
    },
    /// Thin rod along the link x axis: J = m l²/12 about y and z.
    Rod {
        /// Mass [kg].
        mass: f64,
        /// Length [m].
        length: f64,
    },
    /// Uniform disk with normal along the link z axis: J_z = m r²/2, J_x = J_y = m r²/4.
    Disk {
        /// Mass [kg].
        mass: f64,
        /// Radius [m].
        radius: f64,
    },
    /// The airframe of a catalogue aircraft: its mass and inertia (11.3.6) in SI, about the
    /// centre of mass, in the aircraft axes (x forward, y right, z down).
    Aircraft {
        /// `business_jet`.
        model: String,
    },
    /// Given values: mass and the inertia matrix J_{B/c} (principal moments, or full rows).
    Value {
        /// Mass [kg].
        mass: f64,
        /// Principal moments [J_x, J_y, J_z] about the link axes.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        principal: Option<[f64; 3]>,
        /// Full matrix rows (entries, so products of inertia enter as −J_xy).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        matrix: Option<[[f64; 3]; 3]>,
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

/// How `vectrix linearize` treats the initial state.
///
/// Book: §12.6 (linearization about a reference motion).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinearizeSpec {
    /// The initial state is a steady motion (the speeds are constant, the coordinates that
    /// change are cyclic: a spinning top in precession) rather than an equilibrium: only
    /// v̇ = 0 is checked, and A is taken at the initial state.
    #[serde(default)]
    pub steady: bool,
}

/// The `[trim]` table: which unknowns make the initial state steady.
///
/// Book: §12.3 (trim), §12.6.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrimSpec {
    /// The unknowns, by the names of a linearization's states and inputs: `dq:BODY.k` (the k-th
    /// displacement of a body's joint, in its tangent space), `v:BODY.k` (a joint speed) and
    /// `effects[k]` (the magnitude added to a `force` or `torque` effect).
    pub free: Vec<String>,
    /// Output columns held at given values while the state is made steady (`"air:jet.beta" =
    /// 0.0`, `"omega:jet.z" = 0.05`): one more equation each (names as in trajectory.csv; the
    /// output must be declared). SI values.
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub hold: std::collections::BTreeMap<String, f64>,
}

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
}

impl LoopSpec {
    /// The loop's name.
    pub fn name(&self) -> &str {
        match self {
            Self::Ball { name, .. }
            | Self::Pin { name, .. }
            | Self::PointOnLine { name, .. }
            | Self::PointOnPlane { name, .. } => name,
        }
    }
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
