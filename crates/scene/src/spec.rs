//! The scene file format (TOML, serde): what a scene declares. Every table rejects unknown
//! keys, so a misspelt key is an error with its line and column, not a silent default.
//!
//! Book: §7.11 (trees of bodies and joints), ch. 6 (force elements), §7.13 (collisions).

use serde::{Deserialize, Serialize};

pub use super::effect_spec::{Attach, DipoleSpec, EffectSpec};
pub use crate::loop_spec::LoopSpec;

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
    /// The joint names of the `model` that stand for their bodies (joint → body), filled when
    /// the model is read and used for "did you mean" hints; never read from or written to a
    /// file.
    #[serde(skip)]
    pub joint_aliases: std::collections::BTreeMap<String, String>,
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
    /// `dopri5`, `dop853`, `gbs` (extrapolation: tight tolerances on smooth scenes, no
    /// interpolant), `radau5` or `bdf` (stiff scenes).
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
    /// What the model's joint limits do: `"data"` (kept in the import report, the default, as
    /// Pinocchio) or `"contact"` (each becomes a `joint_stop` effect, as MuJoCo's limits).
    #[serde(default, skip_serializing_if = "LimitsMode::is_data")]
    pub limits: LimitsMode,
    /// The restitution e ∈ [0, 1] of the stops made from the limits (`limits = "contact"`).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub limit_restitution: f64,
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
    /// Solid circular cylinder with its axis along the link z axis: J_z = m r²/2,
    /// J_x = J_y = m (3 r² + h²)/12.
    Cylinder {
        /// Mass [kg].
        mass: f64,
        /// Radius [m].
        radius: f64,
        /// Length h along the link z axis [m].
        length: f64,
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

/// What a model's joint limits do (see [`ModelSpec::limits`]).
///
/// Book: §7.13 (impacts).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LimitsMode {
    /// Kept as data only.
    #[default]
    Data,
    /// Joint stops (`joint_stop` effects).
    Contact,
}

impl LimitsMode {
    fn is_data(&self) -> bool {
        *self == Self::Data
    }
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}
