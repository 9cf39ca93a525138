//! # vectrix-scene: the scene file and its pipeline
//!
//! A TOML file declares bodies, joints, effects, the run and the outputs; the simulator
//! assembles exactly the declared effects, computes exactly the requested outputs, and checks
//! the invariants that the declared effects imply. This crate holds the format (spec, source,
//! quantities, errors), the loader, the run loop, contacts, outputs and linearization; the
//! physics below it (`vectrix-dynamics`, `vectrix-flight`) carries no file format. The facade
//! re-exports it as `vectrix::scene`.
//!
//! ```
//! use vectrix_scene::{DEFAULT_SCENE, Scene};
//! let scene = Scene::from_toml(DEFAULT_SCENE, "default.toml").unwrap();
//! assert_eq!(scene.spec().name, "tennis_racket");
//! ```
//!
//! Book: §7.11 (trees), ch. 6 (force elements), §7.13 (impacts), §8.3 (energy).

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod aero;
mod build;
mod contacts;
mod de;
mod effect_spec;
mod error;
mod fault;
mod forces;
mod impacts;
pub mod import;
mod invariants;
mod jacobian;
mod kin;
mod limits;
mod linearize;
mod load;
mod loop_spec;
mod loops;
mod many;
mod mass;
mod migrate;
mod needs;
mod outcome;
mod outputs;
mod parts;
mod path;
mod profile;
mod project;
mod quantities;
mod query;
mod resolve;
mod resting;
mod rhs;
mod run;
mod sampling;
mod source;
pub mod spec;
mod stiff;
mod stops;
mod tree;
mod trim;

pub use aero::AIRCRAFT;
pub use build::MAX_MAGNITUDE;
pub use contacts::{ContactEvent, ContactEventKind, MAX_CONTACT_EVENTS, REST_TIME_REL};
pub use error::{SceneError, unit_message};
pub use invariants::Invariant;
pub use limits::{DEFAULT_MAX_STEPS, MAX_SAMPLE_VALUES, MAX_SAMPLES};
pub use linearize::{EQUILIBRIUM_TOL, EquilibriumResidual, LinearMode, LinearModel, MARGINAL_REL};
pub use many::MAX_ERRORS;
pub use outcome::{Drift, InvariantValue, Run, RunControl, RunWork, Stop, StopReason};
pub use path::{AsItemPath, ItemPath, PathError, PathSeg};
pub use project::{ASSEMBLY_TOL, CONSTRAINT_TOL, ConstraintViolation};
pub use quantities::{Expect, Schema, body_schema, convert as convert_quantities, tag};
pub use query::StateQuery;
pub use rhs::SceneRhs;
pub use run::DEFAULT_MAX_WALL_SECONDS;
pub use sampling::{MAX_TRUSTED_DRIFT, MAX_TRUSTED_STATE};
pub use source::{MAX_NAME_CHARS, MAX_SCENE_BYTES, SceneSource, check_name};
pub use spec::SceneSpec;
pub use stiff::{MethodChoice, RADAU5_TOL_FACTOR, STIFF_RATIO, STIFF_RHO_DURATION};
pub use tree::{Entry, Node, NodeValue};
pub use trim::{TRIM_TOL, TrimReport};

use build::{Built, build};
use forces::Ground;
use needs::Needs;
use outputs::Output;
use parts::Src;
use vectrix_ode::Method;

use vectrix_dynamics::Model;

/// The embedded default scene: a free rigid body spinning near its intermediate axis (the
/// tennis-racket flip, Dzhanibekov effect).
///
/// Book: §7.8 (Euler's equation), §8.x (torque-free motion, energy and |H| conserved).
pub const DEFAULT_SCENE: &str = include_str!("default.toml");

/// A rolling body must start touching its plane: |(c − p)·n − r| small (for a disk, the
/// lowest rim point).
fn check_rolling_start(b: &Built, src: &Src) -> Result<(), SceneError> {
    let Ok(poses) = b.model.poses(&b.q0) else { return Ok(()) };
    for e in &b.effects {
        if let parts::Effect::Rolling { body, disk, r, point, n } = e {
            let (el, rl) = poses[*body];
            let c = rl + el.transpose() * b.bodies[*body].com;
            let reach = if *disk {
                let k = el.transpose() * nalgebra::Vector3::z();
                r * (1.0 - k.dot(n).powi(2)).max(0.0).sqrt()
            } else {
                *r
            };
            let gap = (c - point).dot(n) - reach;
            if gap.abs() > 1e-9 * (1.0 + r) {
                let name = &b.bodies[*body].name;
                let k = b.effects.iter().position(|x| std::ptr::eq(x, e)).unwrap_or(0);
                return Err(src.invalid(
                    format!("effects[{k}].body"),
                    format!(
                        "body `{name}` starts {gap:e} m off its rolling plane; valid: touching it (gap 0)"
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// A validated scene, ready to run.
///
/// Book: §7.11; ch. 6.
pub struct Scene {
    spec: SceneSpec,
    pub(crate) built: Built,
    pub(crate) ground: Ground,
    pub(crate) needs: Needs,
    /// The model's v ↦ q̇ map, compiled once (the joints' own definition, see `rhs`).
    pub(crate) qdot: vectrix_dynamics::multibody::QdotPlan,
    pub(crate) solver: Method,
    /// The integrator chosen and why (named, accuracy table, or the stiffness test).
    pub(crate) choice: MethodChoice,
    pub(crate) outputs: Vec<Output>,
    invariants: Vec<Invariant>,
    /// The length scale of the constraint tolerances (see [`CONSTRAINT_TOL`]).
    pub(crate) loop_scale: f64,
    /// The contact effects' indices in `built.effects`, in declaration order.
    pub(crate) contacts: Vec<usize>,
    /// The file name, text and document the scene was read from, to locate refusals after
    /// loading ([`Scene::invalid`]) without parsing the file again.
    source: (String, String, Node),
    /// What `[trim]` found, when the file declares it.
    trim: Option<TrimReport>,
    /// What the `[model]` file had that does not map (issue 35).
    import_warnings: Vec<import::ImportWarning>,
}

impl std::fmt::Debug for Scene {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Scene").field("spec", &self.spec).finish_non_exhaustive()
    }
}

impl Scene {
    /// Parses and validates a scene file; `file` names it in error messages.
    ///
    /// Book: — (file format).
    ///
    /// # Errors
    /// [`SceneError::Parse`] (syntax, unknown keys, wrong types) and [`SceneError::Invalid`]
    /// (unknown names, joints that do not form a tree, non-finite or out-of-range numbers),
    /// both with line and column.
    pub fn from_toml(text: &str, file: &str) -> Result<Self, SceneError> {
        let src = SceneSource::new(text, file)?;
        Self::from_source(&src)
    }

    /// Validates the scene of a parsed source (errors located in it).
    ///
    /// # Errors
    /// As [`Scene::from_toml`].
    pub fn from_source(src: &SceneSource) -> Result<Self, SceneError> {
        if src.has_key("aircraft") {
            // the old flight-scene form: refused with the file written in the new form
            return Err(src.invalid("aircraft", migrate::message(&src.tree().to_toml())));
        }
        let spec: SceneSpec = src.deserialize_all(&body_schema).map_err(many::report)?;
        Self::build_reporting_all(spec, src)
    }

    /// [`Scene::build`], reporting every error of the file in one pass (see [`many`]): after
    /// an error the item at fault is set aside and the scene is checked again.
    fn build_reporting_all(spec: SceneSpec, src: &Src) -> Result<Self, SceneError> {
        let first = match Self::build(spec.clone(), src) {
            Ok(scene) => return Ok(scene),
            Err(e) => e,
        };
        let (mut spec, mut removed) = (spec, many::Removed::default());
        let mut errors = vec![first.clone()];
        let mut last = first;
        while errors.len() < MAX_ERRORS {
            let SceneError::Invalid { path, .. } = &last else { break };
            if !many::patch_spec(&mut spec, &ItemPath::parse_prefix(path), &mut removed) {
                break;
            }
            match Self::build(spec.clone(), src) {
                Ok(_) => break,
                Err(e) => {
                    errors.push(removed.renumber(e.clone(), src));
                    last = e;
                }
            }
        }
        Err(many::report(errors))
    }

    /// Validates `spec` with errors located in `src`, the file it was derived from (a sweep
    /// changes numbers of the user's file: its errors point into that file).
    ///
    /// # Errors
    /// As [`Scene::from_toml`].
    pub fn from_spec_in(spec: SceneSpec, src: &SceneSource) -> Result<Self, SceneError> {
        Self::build(spec, src)
    }

    /// Validates a scene given as a value (errors are located in its TOML form).
    ///
    /// # Errors
    /// As [`Scene::from_toml`].
    pub fn from_spec(spec: SceneSpec) -> Result<Self, SceneError> {
        let text = toml::to_string(&spec).unwrap_or_default();
        let src = SceneSource::new(&text, "<scene>")?;
        Self::build(spec, &src)
    }

    /// Validates `spec`; with a `[trim]` table, trims its initial state and validates the
    /// trimmed scene (whose [`Scene::trim_report`] says what was found).
    fn build(spec: SceneSpec, src: &Src) -> Result<Self, SceneError> {
        // issue 35: a `[model]` file's links become bodies first
        let (spec, warnings) = import::expand(spec, src)?;
        let mut scene = Self::build_plain(spec, src)?;
        if let Some(t) = scene.spec.trim.clone() {
            let (trimmed, report) = scene.trimmed_holding(&t.free, &t.hold)?;
            scene = Self::build_plain(trimmed, src)?;
            scene.trim = Some(report);
        }
        scene.import_warnings = warnings;
        Ok(scene)
    }

    /// What the `[model]` file (URDF, MJCF) had that does not map onto the scene, each with
    /// its file and line (empty without `[model]`).
    ///
    /// Book: — (issue 35: nothing dropped silently).
    pub fn import_warnings(&self) -> &[import::ImportWarning] {
        &self.import_warnings
    }

    /// What `[trim]` found (`None` without a `[trim]` table): the unknowns, their change, the
    /// residual |v̇|∞ and the Newton iterations. The scene's initial state is the trimmed one.
    ///
    /// Book: §12.3.
    pub fn trim_report(&self) -> Option<&TrimReport> {
        self.trim.as_ref()
    }

    fn build_plain(spec: SceneSpec, src: &Src) -> Result<Self, SceneError> {
        let built = build(&spec, src)?;
        let (solver, named) = limits::solver(&spec, src)?;
        let outputs = outputs::parse(&spec, &built, src)?;
        limits::check_bounds(&spec, &built, &outputs, src)?;
        let invariants = invariants::derive(&built);
        let needs = Needs::of(&spec, &built, src)?;
        check_rolling_start(&built, src)?;
        for (k, c) in spec.checks.iter().enumerate() {
            if !["energy", "momentum", "angular_momentum"].contains(&c.as_str()) {
                return Err(src.invalid(
                    format!("checks[{k}]"),
                    format!("unknown check `{c}`; valid: energy, momentum, angular_momentum"),
                ));
            }
        }
        let qdot = built.model.qdot_plan();
        let mut scene = Self {
            spec,
            built,
            ground: Ground::new(),
            qdot,
            needs,
            solver,
            choice: MethodChoice {
                name: solver.name(),
                rtol: solver.tolerances().0,
                jacobian: "none",
                reason: String::new(),
            },
            outputs,
            invariants,
            loop_scale: 1.0,
            contacts: Vec::new(),
            source: (src.file().to_string(), src.text().to_string(), src.tree().clone()),
            trim: None,
            import_warnings: Vec::new(),
        };
        scene.contacts = scene.contact_effects();
        scene.loop_scale = scene.constraint_scale();
        scene.assemble(src)?;
        scene.check_start(src)?;
        scene.check_contacts_start(src)?;
        match named {
            Some(reason) => {
                if scene.needs.impacts && !scene.solver.has_interpolant() {
                    return Err(src.invalid(
                        "method.name",
                        format!(
                            "`{}` keeps no interpolant, and this scene's contacts or joint stops are located on \
                             one; valid: dopri5, dop853, radau5, bdf",
                            scene.solver.name()
                        ),
                    ));
                }
                scene.choice.reason = reason;
                if scene.solver.is_implicit() {
                    scene.choice.jacobian =
                        if scene.tree_only() { "exact (dual numbers)" } else { "finite differences" };
                }
            }
            None => scene.choose_method(),
        }
        Ok(scene)
    }

    /// The dynamics must be defined at t = 0: `check` reports a mechanism that cannot start
    /// (a singular joint inertia, coincident points, an overflowing load) where the scene is
    /// declared, instead of the run failing at its first step.
    fn check_start(&self, src: &SceneSource) -> Result<(), SceneError> {
        let y0 = self.initial_state();
        let started = self.deriv(0.0, &y0).and_then(|d| match d.iter().position(|x| !x.is_finite()) {
            None => Ok(()),
            Some(k) => Err(format!("the right-hand side is not finite at t = 0 (component {k}: {})", d[k])),
        });
        started.map_err(|m| {
            src.invalid(
                "bodies",
                format!(
                    "the dynamics cannot start: {m}; valid: bodies with inertia about every free direction of their \
                     joints (a particle needs a joint that leaves it no free rotation about itself), and finite \
                     loads and velocities"
                ),
            )
        })
    }

    /// No sphere may start inside its plane or another sphere (beyond a rounding of its size).
    fn check_contacts_start(&self, src: &SceneSource) -> Result<(), SceneError> {
        let gaps = self.gaps(&self.initial_state()).map_err(|m| src.invalid("bodies", m))?;
        for (g, &k) in gaps.iter().zip(&self.contacts) {
            if g.gap < -1e-9 * g.size {
                return Err(src.invalid(
                    format!("effects[{k}]"),
                    format!(
                        "the contact starts penetrating by {:e} m; valid: spheres that start apart or touching \
                         (gap ≥ 0)",
                        -g.gap
                    ),
                ));
            }
        }
        Ok(())
    }

    /// A refusal after loading (a run, a linearization), located at the item `path` of the
    /// file the scene was read from, as a load-time refusal is.
    pub(crate) fn invalid(&self, path: &str, message: impl Into<String>) -> SceneError {
        let (file, text, tree) = &self.source;
        SceneSource::with_tree(text, file, tree.clone()).invalid(path, message)
    }

    /// The scene as declared.
    pub fn spec(&self) -> &SceneSpec {
        &self.spec
    }

    /// The scene file text (TOML) of [`Scene::spec`]: load → save → load gives the same scene.
    ///
    /// # Errors
    /// [`SceneError::Invalid`] if serialization fails (it does not for validated scenes).
    pub fn to_toml(&self) -> Result<String, SceneError> {
        toml::to_string(&self.spec).map_err(|e| SceneError::Invalid {
            file: "<scene>".into(),
            line: 1,
            column: 1,
            path: "scene".into(),
            message: e.to_string(),
        })
    }

    /// The assembled multibody model (its `gravity` is nonzero only if gravity is declared).
    pub fn model(&self) -> &Model {
        &self.built.model
    }

    /// The invariants that the declared effects imply (whether or not they are checked).
    pub fn invariants(&self) -> &[Invariant] {
        &self.invariants
    }

    /// The integrator the scene runs and why: named by `method`, or picked from `accuracy` by
    /// the accuracy table and the stiffness test of the Jacobian at t = 0 (RADAU5 when stiff).
    ///
    /// Book: §4.11; HW §IV.1.
    pub fn method_choice(&self) -> &MethodChoice {
        &self.choice
    }

    /// The initial state y₀ = (q₀, v₀).
    pub fn initial_state(&self) -> Vec<f64> {
        [self.built.q0.as_slice(), self.built.v0.as_slice()].concat()
    }

    /// The right-hand side y′ = f(t, y) with exactly the declared effects.
    ///
    /// # Errors
    /// [`SceneError::Run`] for a state of the wrong length, a non-finite t or y, a
    /// non-finite y′, or when the dynamics fail (singular mass matrix, coincident points).
    pub fn derivative(&self, t: f64, y: &[f64]) -> Result<Vec<f64>, SceneError> {
        if y.len() != self.built.model.nq() + self.built.model.nv() {
            return Err(SceneError::Run {
                t,
                message: format!(
                    "state of length {}, expected {}",
                    y.len(),
                    self.built.model.nq() + self.built.model.nv()
                ),
            });
        }
        rhs::finite_state(t, y).map_err(|message| SceneError::Run { t, message })?;
        let d = self.deriv(t, y).map_err(|message| SceneError::Run { t, message })?;
        rhs::finite_derivative(&d).map_err(|message| SceneError::Run { t, message })?;
        Ok(d)
    }
}
