//! Flight scenes: an aircraft in a TOML scene file, trimmed, linearized, flown through
//! control inputs (doublet, step, pulse) by the nonlinear 12-state equations of motion and by
//! their linearization side by side, with the modes of the trim point.
//!
//! ```toml
//! name = "business_jet_elevator_doublet"
//! duration = 60.0
//! samples = 601
//! outputs = ["u", "alpha", "q", "theta"]
//!
//! [aircraft]
//! model = "business_jet"      # Tables 14.1–14.2; overrides: mass, inertia, area, chord, …
//!
//! [trim]
//! airspeed = 675.2            # straight flight at flight-path angle `gamma` (default 0), or
//! gamma = 0.0                 # `turn_rate` (rad/s) for a coordinated level turn
//!
//! [[inputs]]
//! control = "elevator"        # elevator | aileron | rudder | thrust
//! shape = "doublet"           # doublet | step | pulse
//! start = 1.0
//! width = 1.0
//! amplitude = 0.01            # rad (thrust: force units)
//! ```
//!
//! The nonlinear response integrates ẋ = f(x, u(t)) (11.5.3–16) with DOP853, restarted at
//! every discontinuity of the inputs; the linear response integrates δẋ = A δx + B δu of the
//! dual-number linearization with the same integrator, so the two differ only by the
//! nonlinearity. Linear outputs are trim + f(x₀, u₀) t + δx (the reference motion is straight
//! and steady); in a turn the reference positions X, Y are not linear in t, so those two
//! linear columns are left out.
//!
//! Book: §11.5 (equations of motion), §12.1 (trim), §12.6 and §14.1–14.5 (linearization and
//! decoupling), §14.2 (control inputs), §14.6–14.7 (modes).

use std::collections::BTreeMap;

use crate::{Expect, RunControl, Scene, SceneError, SceneSource, Step, Stop, StopReason};
use nalgebra::DVector;
use serde::{Deserialize, Serialize};
use vectrix_lti::Complex64;
use vectrix_ode::OdeError;
use vectrix_ode::explicit::{Adaptive, Stepper};
use vectrix_units::UnitSystem;

use vectrix_flight::{
    Aircraft, AircraftState, Airframe, Controls, FlightError, FlightMode, Linearization, Trim, TrimLimits,
    TrimSpec, business_jet, lateral_modes, linearize, longitudinal_modes, trim,
};

/// A flight scene file, as written.
///
/// Book: §12.1, §14.2 (what a flight scene declares).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FlightSceneSpec {
    /// Name of the scene (the output folder).
    pub name: String,
    /// Simulated time span [0, duration] in seconds.
    pub duration: f64,
    /// Number of output samples, including t = 0 and t = duration (≥ 2).
    #[serde(default = "default_samples")]
    pub samples: usize,
    /// Relative (and absolute) tolerance of the integrator (default 1e-9).
    #[serde(default)]
    pub accuracy: Option<f64>,
    /// Output names (see [`OUTPUT_NAMES`]); default u, alpha, q, theta.
    #[serde(default = "default_outputs")]
    pub outputs: Vec<String>,
    /// The aircraft.
    pub aircraft: AircraftSpec,
    /// The trim condition.
    pub trim: TrimSection,
    /// Control inputs added to the trim controls.
    #[serde(default)]
    pub inputs: Vec<InputSpec>,
    /// Write `view.html`, the run's self-contained 3-D view, into the output folder (`true`
    /// when omitted; `vectrix run --no-view` skips it as well).
    #[serde(default = "crate::spec::yes", skip_serializing_if = "crate::spec::is_yes")]
    pub view: bool,
}

fn default_samples() -> usize {
    601
}

fn default_outputs() -> Vec<String> {
    ["u", "alpha", "q", "theta"].map(String::from).to_vec()
}

/// The `[aircraft]` table: a catalogue model and optional overrides.
///
/// Book: Tables 14.1–14.2 (the business jet); §13.3–13.5 (coefficients).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct AircraftSpec {
    /// Catalogue model: `business_jet` (the only one with a full nonlinear aerodynamic
    /// model; the 747 of §14.7.3 is printed as a linear A only).
    pub model: String,
    /// Mass (> 0).
    pub mass: Option<f64>,
    /// [J_xx, J_yy, J_zz, J_xz] about the centre of mass, aircraft frame.
    pub inertia: Option<[f64; 4]>,
    /// Wing area S (> 0).
    pub area: Option<f64>,
    /// Mean chord c̄ (> 0).
    pub chord: Option<f64>,
    /// Span b (> 0).
    pub span: Option<f64>,
    /// Air density ρ (> 0).
    pub rho: Option<f64>,
    /// Gravitational acceleration g (> 0).
    pub g: Option<f64>,
    /// Thrust-line angle (rad).
    pub thrust_angle: Option<f64>,
    /// Overrides of individual [`vectrix_flight::Coefficients`] fields by name (`cm_alpha = -0.6`).
    #[serde(default)]
    pub coefficients: BTreeMap<String, f64>,
}

/// The `[trim]` table.
///
/// Book: §12.1 (straight-line flight, level turn).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TrimSection {
    /// Airspeed V (> 0).
    pub airspeed: f64,
    /// Flight-path angle γ (rad) of straight flight; 0 for level flight.
    #[serde(default)]
    pub gamma: f64,
    /// Turn rate Ψ̇ (rad/s) of a coordinated level turn; when given, `gamma` must be 0.
    pub turn_rate: Option<f64>,
}

/// One `[[inputs]]` entry.
///
/// Book: §14.2 (control inputs).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct InputSpec {
    /// `elevator`, `aileron`, `rudder` or `thrust`.
    pub control: String,
    /// `doublet` (+A on [t₀, t₀+w), −A on [t₀+w, t₀+2w)), `step` (+A from t₀) or `pulse`
    /// (+A on [t₀, t₀+w)).
    pub shape: String,
    /// Start time t₀ (≥ 0).
    pub start: f64,
    /// Width w (> 0) of a doublet half or a pulse.
    pub width: Option<f64>,
    /// Amplitude A (rad for surfaces, force for thrust).
    pub amplitude: f64,
}

/// Output names: the twelve states of (11.5.1), the air-relative and flight-path angles, and
/// the four controls.
///
/// Book: (11.5.1), (10.6.18), (10.6.27), (10.8.1).
pub const OUTPUT_NAMES: [&str; 20] = [
    "x", "y", "z", "u", "v", "w", "phi", "theta", "psi", "p", "q", "r", "alpha", "beta", "airspeed", "gamma",
    "elevator", "aileron", "rudder", "thrust",
];

const CONTROLS: [&str; 4] = ["elevator", "aileron", "rudder", "thrust"];

#[derive(Debug, Clone, Copy, PartialEq)]
enum Shape {
    Doublet,
    Step,
    Pulse,
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Input {
    channel: usize,
    shape: Shape,
    start: f64,
    width: f64,
    amplitude: f64,
}

impl Input {
    fn value(&self, t: f64) -> f64 {
        let (t0, w, a) = (self.start, self.width, self.amplitude);
        match self.shape {
            Shape::Doublet => vectrix_flight::doublet(t, t0, w, a),
            Shape::Step => {
                if t >= t0 {
                    a
                } else {
                    0.0
                }
            }
            Shape::Pulse => {
                if t >= t0 && t < t0 + w {
                    a
                } else {
                    0.0
                }
            }
        }
    }

    fn breakpoints(&self) -> Vec<f64> {
        match self.shape {
            Shape::Doublet => vec![self.start, self.start + self.width, self.start + 2.0 * self.width],
            Shape::Step => vec![self.start],
            Shape::Pulse => vec![self.start, self.start + self.width],
        }
    }
}

/// A validated flight scene: the aircraft, its trim and linearization (computed on loading,
/// so that an unreachable trim is reported by `vectrix check`), inputs and outputs.
///
/// Book: §12.1, §12.6, §14.2.
#[derive(Debug, Clone)]
pub struct FlightScene {
    spec: FlightSceneSpec,
    aircraft: Aircraft,
    linearization: Linearization,
    inputs: Vec<Input>,
    outputs: Vec<usize>,
    rtol: f64,
}

/// One mode of the trim point, named when the model decouples (§14.5).
///
/// Book: §14.6, Table 14.3.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModeSummary {
    /// short period, phugoid, Dutch roll, roll, spiral; or `mode k` for a coupled model.
    pub name: String,
    /// Re λ.
    pub re: f64,
    /// Im λ (≥ 0).
    pub im: f64,
    /// ωₙ = |λ|.
    pub natural_frequency: f64,
    /// ζ = −Re λ/|λ|.
    pub damping_ratio: f64,
    /// 2π/ωₙ for an oscillatory mode.
    pub period: Option<f64>,
    /// ln 2/(−Re λ) for a stable mode.
    pub time_to_half: Option<f64>,
}

impl ModeSummary {
    fn of(name: &str, m: &FlightMode) -> Self {
        let l = m.eigenvalue();
        Self {
            name: name.into(),
            re: l.re,
            im: l.im.abs(),
            natural_frequency: m.natural_frequency(),
            damping_ratio: m.damping_ratio(),
            period: m.period(),
            time_to_half: m.time_to_half(),
        }
    }
}

/// The result of a flight scene: samples of every output, nonlinear and linear.
///
/// Book: §14.2, §14.6–14.7.
#[derive(Debug, Clone, PartialEq)]
pub struct FlightRun {
    /// Scene name.
    pub scene: String,
    /// The trim point.
    pub trim: Trim,
    /// Modes of the linearization at the trim point.
    pub modes: Vec<ModeSummary>,
    /// Eigenvalues plotted in the pole map (the decoupled 4-state models, or the full A).
    pub poles: Vec<Complex64>,
    /// Sample times.
    pub t: Vec<f64>,
    /// Output names, in order.
    pub outputs: Vec<String>,
    /// Nonlinear response, one vector of samples per output.
    pub nonlinear: Vec<Vec<f64>>,
    /// Linear response (trim + reference motion + δx), `None` where undefined (X, Y in a turn).
    pub linear: Vec<Option<Vec<f64>>>,
    /// Right-hand-side evaluations of the nonlinear run.
    pub fevals: usize,
    /// Accepted steps of the nonlinear run.
    pub steps: usize,
    /// `Some` when the run was cancelled: the samples end where the nonlinear run stopped.
    pub stop: Option<Stop>,
    /// The unit of each output (`ft/s`, `rad`, `lbf`): the catalogue's (the book's imperial
    /// units) unless converted by [`FlightRun::in_units`].
    pub units: Vec<String>,
    /// The unit system of the outputs (`imperial` as flown, or `si`).
    pub unit_system: &'static str,
}

/// The dimension of a flight output (by its name in [`OUTPUT_NAMES`]).
///
/// Book: (11.5.1), (10.6.18), (10.8.1).
pub fn output_dimension(name: &str) -> vectrix_units::Dimension {
    use vectrix_units::Dimension as D;
    match name {
        "x" | "y" | "z" => D::LENGTH,
        "u" | "v" | "w" | "airspeed" => D::VELOCITY,
        "p" | "q" | "r" => D::ANGULAR_VELOCITY,
        "thrust" => D::FORCE,
        _ => D::ANGLE,
    }
}

/// Samples and work of one integration.
struct Integrated {
    samples: Vec<[f64; 12]>,
    fevals: usize,
    steps: usize,
    stopped: Option<f64>,
}

/// A scene file of either kind, read by the one loader: an `[aircraft]` table makes it a
/// flight scene, otherwise it declares bodies. Errors are located by the same spanned parse.
///
/// Book: §7.11 (bodies), §12.1 and §14.2 (aircraft).
#[derive(Debug)]
pub enum AnyScene {
    /// Bodies, joints and effects (`vectrix_scene`).
    Bodies(Box<Scene>),
    /// An aircraft, its trim and control inputs.
    Flight(Box<FlightScene>),
}

impl AnyScene {
    /// Parses and validates a scene file of either kind; `file` names it in messages.
    ///
    /// # Errors
    /// [`SceneError::Parse`] and [`SceneError::Invalid`] with line and column.
    pub fn from_toml(text: &str, file: &str) -> Result<Self, SceneError> {
        let src = SceneSource::new(text, file)?;
        Ok(if src.has_key("aircraft") {
            Self::Flight(Box::new(FlightScene::from_source(&src)?))
        } else {
            Self::Bodies(Box::new(Scene::from_source(&src)?))
        })
    }

    /// The scene's name (its output folder).
    pub fn name(&self) -> &str {
        match self {
            Self::Bodies(s) => &s.spec().name,
            Self::Flight(f) => &f.spec().name,
        }
    }
}

#[derive(Serialize)]
struct Summary<'a> {
    scene: &'a str,
    /// The unit system of the outputs; each output's unit is in `outputs`.
    units: &'static str,
    /// `false` when the run was cancelled (see `stop`).
    complete: bool,
    stop: &'a Option<Stop>,
    /// Rows written to trajectory.csv (t = 0 included).
    rows: usize,
    trim: TrimSummary,
    modes: &'a [ModeSummary],
    outputs: Vec<OutputSummary<'a>>,
    fevals: usize,
    steps: usize,
}

#[derive(Serialize)]
struct TrimSummary {
    alpha: f64,
    theta: f64,
    phi: f64,
    elevator: f64,
    aileron: f64,
    rudder: f64,
    thrust: f64,
    residual: f64,
    iterations: usize,
}

#[derive(Serialize)]
struct OutputSummary<'a> {
    name: &'a str,
    unit: &'a str,
    /// max |nonlinear − trim value| over the run
    max_excursion: f64,
    /// max |nonlinear − linear| (None where the linear column is undefined)
    max_linear_error: Option<f64>,
}

/// The expected dimensions of a flight scene's numbers. Bare numbers are in the units of the
/// aircraft catalogue — the book's (ft, slug, s, lbf, rad) for the business jet — and quantity
/// strings are converted exactly into them: `airspeed = "400 kt"`, `mass = "17.8 t"`.
///
/// Book: §15.19; Tables 14.1–14.2.
pub fn flight_schema(path: &[Step], root: &toml::Value) -> Option<Expect> {
    use vectrix_units::Dimension as D;
    const fn imp(dims: &'static [D]) -> Option<Expect> {
        Some(Expect { dims, system: UnitSystem::Imperial })
    }
    let keys: Vec<Option<&str>> = path.iter().map(crate::key_of).collect();
    match keys.as_slice() {
        [Some("duration")] | [Some("inputs"), None, Some("start" | "width")] => imp(&[D::TIME]),
        [Some("accuracy")] => imp(&[D::DIMENSIONLESS]),
        [Some("aircraft"), Some("mass")] => imp(&[D::MASS]),
        [Some("aircraft"), Some("inertia"), None] => imp(&[D::MOMENT_OF_INERTIA]),
        [Some("aircraft"), Some("area")] => imp(&[D::AREA]),
        [Some("aircraft"), Some("chord" | "span")] => imp(&[D::LENGTH]),
        [Some("aircraft"), Some("rho")] => imp(&[D::DENSITY]),
        [Some("aircraft"), Some("g")] => imp(&[D::ACCELERATION]),
        [Some("aircraft"), Some("thrust_angle")] | [Some("trim"), Some("gamma")] => imp(&[D::ANGLE]),
        [Some("aircraft"), Some("coefficients"), Some("u_ref")] | [Some("trim"), Some("airspeed")] => {
            imp(&[D::VELOCITY])
        }
        [Some("aircraft"), Some("coefficients"), Some(_)] => imp(&[D::DIMENSIONLESS]),
        [Some("trim"), Some("turn_rate")] => imp(&[D::ANGULAR_VELOCITY, D::FREQUENCY]),
        [Some("inputs"), None, Some("amplitude")] => {
            let Step::Index(i) = path[1] else { return None };
            let control = crate::tag(root, &[Step::Key("inputs".into()), Step::Index(i)], "control");
            if control == Some("thrust") { imp(&[D::FORCE]) } else { imp(&[D::ANGLE]) }
        }
        _ => None,
    }
}

/// Most output samples of a flight scene (rows of trajectory.csv; bounds memory and time).
pub const MAX_FLIGHT_SAMPLES: usize = 1_000_000;

/// Errors are located by item path in the spanned document (one locator for every kind of
/// scene file).
type Src<'a> = SceneSource<'a>;

/// Sets coefficient `name` of `c`; `false` for an unknown name.
fn set_coefficient(c: &mut vectrix_flight::Coefficients, name: &str, v: f64) -> bool {
    macro_rules! fields {
        ($($f:ident)*) => {
            match name {
                $(stringify!($f) => c.$f = v,)*
                _ => return false,
            }
        };
    }
    fields!(u_ref cl0 cl_u cl_alpha cl_q cl_alpha_dot cl_de cd_par k_induced cd_u cm0 cm_u cm_alpha cm_q
        cm_alpha_dot cm_de ce_beta ce_beta_dot ce_p ce_r ce_da ce_dr croll_beta croll_beta_dot croll_p
        croll_r croll_da croll_dr cn_beta cn_beta_dot cn_p cn_r cn_da cn_dr);
    true
}

fn positive(src: &Src, key: &str, path: &str, v: Option<f64>) -> Result<Option<f64>, SceneError> {
    match v {
        Some(x) if !(x.is_finite() && x > 0.0) => {
            Err(src.invalid(path, format!("{key} = {x}; valid: a finite number > 0")))
        }
        _ => Ok(v),
    }
}

fn build_aircraft(spec: &AircraftSpec, src: &Src) -> Result<Aircraft, SceneError> {
    let mut ac = match spec.model.as_str() {
        "business_jet" => business_jet(),
        m => {
            return Err(src.invalid("aircraft.model",
                format!(
                    "unknown aircraft model `{m}`; valid: business_jet (the 747 of §14.7.3 is a linear A only, \
                     see boeing_747_longitudinal_a)"
                ),
            ));
        }
    };
    let (jxx0, jyy0, jzz0, jxz0) = ac.airframe.inertia();
    let mass = positive(src, "mass", "aircraft.mass", spec.mass)?.unwrap_or(ac.airframe.mass());
    let [jxx, jyy, jzz, jxz] = spec.inertia.unwrap_or([jxx0, jyy0, jzz0, jxz0]);
    ac.airframe = Airframe::new(mass, jxx, jyy, jzz, jxz).map_err(|e| {
        src.invalid(if spec.inertia.is_some() { "aircraft.inertia" } else { "aircraft.mass" }, e.to_string())
    })?;
    ac.geometry.area = positive(src, "area", "aircraft.area", spec.area)?.unwrap_or(ac.geometry.area);
    ac.geometry.chord = positive(src, "chord", "aircraft.chord", spec.chord)?.unwrap_or(ac.geometry.chord);
    ac.geometry.span = positive(src, "span", "aircraft.span", spec.span)?.unwrap_or(ac.geometry.span);
    ac.rho = positive(src, "rho", "aircraft.rho", spec.rho)?.unwrap_or(ac.rho);
    ac.g = positive(src, "g", "aircraft.g", spec.g)?.unwrap_or(ac.g);
    if let Some(a) = spec.thrust_angle {
        if !a.is_finite() {
            return Err(src.invalid("aircraft.thrust_angle", "thrust_angle must be finite"));
        }
        ac.thrust_angle = a;
    }
    for (name, &v) in &spec.coefficients {
        let path = format!("aircraft.coefficients.{name}");
        if !v.is_finite() {
            return Err(src.invalid(&*path, format!("{name} = {v}; valid: a finite number")));
        }
        if !set_coefficient(&mut ac.coefficients, name, v) {
            return Err(src.invalid(&*path,
                format!(
                    "unknown coefficient `{name}`; valid: u_ref, cl0, cl_u, cl_alpha, cl_q, cl_alpha_dot, cl_de, \
                     cd_par, k_induced, cd_u, cm0, cm_u, cm_alpha, cm_q, cm_alpha_dot, cm_de, ce_beta, \
                     ce_beta_dot, ce_p, ce_r, ce_da, ce_dr, croll_beta, croll_beta_dot, croll_p, croll_r, \
                     croll_da, croll_dr, cn_beta, cn_beta_dot, cn_p, cn_r, cn_da, cn_dr"
                ),
            ));
        }
    }
    ac.check().map_err(|e| src.invalid("aircraft", e.to_string()))?;
    Ok(ac)
}

fn build_inputs(spec: &FlightSceneSpec, src: &Src) -> Result<Vec<Input>, SceneError> {
    let mut out = Vec::new();
    for (i, inp) in spec.inputs.iter().enumerate() {
        let path = |f: &str| format!("inputs[{i}].{f}");
        let Some(channel) = CONTROLS.iter().position(|c| *c == inp.control) else {
            return Err(src.invalid(
                path("control"),
                format!("unknown control `{}`; valid: elevator, aileron, rudder, thrust", inp.control),
            ));
        };
        let shape = match inp.shape.as_str() {
            "doublet" => Shape::Doublet,
            "step" => Shape::Step,
            "pulse" => Shape::Pulse,
            s => {
                return Err(
                    src.invalid(path("shape"), format!("unknown shape `{s}`; valid: doublet, step, pulse"))
                );
            }
        };
        if !(inp.start.is_finite() && inp.start >= 0.0) {
            return Err(src.invalid(path("start"), format!("start = {}; valid: finite, ≥ 0", inp.start)));
        }
        if !inp.amplitude.is_finite() {
            return Err(src.invalid(path("amplitude"), "amplitude must be a finite number"));
        }
        let width = match (shape, inp.width) {
            (Shape::Step, _) => 0.0,
            (_, Some(w)) if w.is_finite() && w > 0.0 => w,
            (_, Some(w)) => {
                return Err(src.invalid(path("width"), format!("width = {w}; valid: finite, > 0")));
            }
            (_, None) => {
                return Err(
                    src.invalid(path("width"), format!("a {} needs `width` (seconds, > 0)", inp.shape))
                );
            }
        };
        out.push(Input { channel, shape, start: inp.start, width, amplitude: inp.amplitude });
    }
    Ok(out)
}

impl FlightScene {
    /// Parses, validates, trims and linearizes a flight scene.
    ///
    /// Book: §12.1, §12.6.
    ///
    /// # Errors
    /// [`SceneError::Parse`] (TOML syntax, unknown keys, wrong types) and
    /// [`SceneError::Invalid`] (bad values, unknown names, a trim that cannot be reached — the
    /// message names the condition that could not be met), each with line and column.
    pub fn from_toml(text: &str, file: &str) -> Result<Self, SceneError> {
        let src = SceneSource::new(text, file)?;
        Self::from_source(&src)
    }

    /// Validates the flight scene of a parsed source (errors located in it).
    ///
    /// # Errors
    /// As [`FlightScene::from_toml`].
    pub fn from_source(src: &SceneSource) -> Result<Self, SceneError> {
        let spec: FlightSceneSpec = src.deserialize_with(&flight_schema)?;
        crate::check_name(&spec.name, "scene name", true).map_err(|m| src.invalid("name", m))?;
        if !(spec.duration.is_finite() && spec.duration > 0.0) {
            return Err(src.invalid("duration", format!("duration = {}; valid: finite, > 0", spec.duration)));
        }
        if !(2..=MAX_FLIGHT_SAMPLES).contains(&spec.samples) {
            return Err(src.invalid(
                "samples",
                format!("samples = {}; valid: 2 ..= {MAX_FLIGHT_SAMPLES}", spec.samples),
            ));
        }
        let rtol = spec.accuracy.unwrap_or(1e-9);
        if !(rtol.is_finite() && rtol > 0.0 && rtol < 1.0) {
            return Err(src.invalid("accuracy", format!("accuracy = {rtol}; valid: 0 < accuracy < 1")));
        }
        let mut outputs = Vec::new();
        for (i, o) in spec.outputs.iter().enumerate() {
            if let Some(j) = spec.outputs[..i].iter().position(|p| p == o) {
                return Err(src.invalid(
                    format!("outputs[{i}]"),
                    format!("output `{o}` repeats outputs[{j}]; valid: each output once"),
                ));
            }
            match OUTPUT_NAMES.iter().position(|n| n == o) {
                Some(k) => outputs.push(k),
                None => {
                    return Err(src.invalid(
                        format!("outputs[{i}]"),
                        format!("unknown output `{o}`; valid: {}", OUTPUT_NAMES.join(", ")),
                    ));
                }
            }
        }
        let aircraft = build_aircraft(&spec.aircraft, src)?;
        let inputs = build_inputs(&spec, src)?;
        let t = &spec.trim;
        let trim_spec = match t.turn_rate {
            Some(_) if t.gamma != 0.0 => {
                return Err(src.invalid(
                    "trim.turn_rate",
                    "give either `gamma` (straight flight) or `turn_rate` (level turn), not both",
                ));
            }
            Some(r) => TrimSpec::LevelTurn { airspeed: t.airspeed, turn_rate: r },
            None => TrimSpec::Straight { airspeed: t.airspeed, gamma: t.gamma },
        };
        let trimmed = trim(&aircraft, trim_spec, TrimLimits::default())
            .map_err(|e| src.invalid("trim", format!("cannot trim: {e}")))?;
        let linearization = linearize(&aircraft, &trimmed)
            .map_err(|e| src.invalid("trim", format!("cannot linearize: {e}")))?;
        Ok(Self { spec, aircraft, linearization, inputs, outputs, rtol })
    }

    /// The scene as written.
    pub fn spec(&self) -> &FlightSceneSpec {
        &self.spec
    }

    /// The aircraft after overrides.
    pub fn aircraft(&self) -> &Aircraft {
        &self.aircraft
    }

    /// The linearization at the trim point (holds the trim).
    pub fn linearization(&self) -> &Linearization {
        &self.linearization
    }

    fn controls_at(&self, t: f64) -> [f64; 4] {
        let mut u = self.linearization.trim.controls.to_array();
        for i in &self.inputs {
            u[i.channel] += i.value(t);
        }
        u
    }

    /// Integration segments: [0, duration] cut at every input discontinuity.
    fn segments(&self) -> Vec<(f64, f64)> {
        let end = self.spec.duration;
        let mut cuts: Vec<f64> =
            self.inputs.iter().flat_map(Input::breakpoints).filter(|&b| b > 0.0 && b < end).collect();
        cuts.push(0.0);
        cuts.push(end);
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        cuts.windows(2).map(|w| (w[0], w[1])).collect()
    }

    /// Integrates ẋ = rhs(t, x, u(t)) segment by segment from x0 (one integration per segment
    /// between input discontinuities) and samples it at `times` from the dense output, up to
    /// `t_limit`. Reports progress as `base + span·t/duration`; stops early when cancelled
    /// and returns the time reached.
    #[allow(clippy::too_many_arguments)]
    fn integrate(
        &self,
        x0: [f64; 12],
        times: &[f64],
        mut rhs: impl FnMut(&[f64; 12], &[f64; 4]) -> Result<[f64; 12], FlightError>,
        ctl: &mut RunControl<'_>,
        (base, span): (f64, f64),
        t_limit: f64,
    ) -> Result<Integrated, SceneError> {
        let solver = Adaptive::dop853().rtol(self.rtol).atol(self.rtol);
        let end = self.spec.duration;
        let mut out = Integrated { samples: vec![x0], fevals: 0, steps: 0, stopped: None };
        let mut x = x0;
        let mut k = 1;
        for (a, b) in self.segments() {
            if a >= t_limit {
                break;
            }
            let b = b.min(t_limit);
            // controls are constant on [a, b): evaluate them just inside the segment
            let u = self.controls_at(a + 0.5 * (b - a));
            let failure = std::cell::RefCell::new(None::<FlightError>);
            let f = |_t: f64, y: &[f64; 12]| match rhs(y, &u) {
                Ok(d) => d,
                Err(e) => {
                    failure.borrow_mut().get_or_insert(e);
                    [f64::NAN; 12]
                }
            };
            let fail = |t: f64, e: OdeError| {
                let message = match failure.borrow_mut().take() {
                    Some(fe) => fe.to_string(),
                    None => e.to_string(),
                };
                SceneError::Run { t, message }
            };
            let mut st = Stepper::new(&solver, f, a, x, b).map_err(|e| fail(a, e))?;
            while !st.done() {
                st.step().map_err(|e| fail(st.t(), e))?;
                let t = st.t();
                while k < times.len() && times[k] <= t {
                    let y = if times[k] == t {
                        *st.y()
                    } else {
                        st.dense().map_err(|e| fail(t, e))?.eval(times[k])
                    };
                    out.samples.push(y);
                    k += 1;
                }
                (ctl.progress)(base + span * t / end);
                if ctl.cancel.is_some_and(|c| c.load(std::sync::atomic::Ordering::Relaxed)) {
                    out.stopped = Some(t);
                    break;
                }
            }
            let w = st.work();
            out.fevals += w.fevals;
            out.steps += w.accepted;
            x = *st.y();
            if out.stopped.is_some() {
                break;
            }
        }
        Ok(out)
    }

    /// Runs the scene: nonlinear and linear responses to the inputs, and the modes.
    ///
    /// Book: §11.5, §12.6, §14.2, §14.6.
    ///
    /// # Errors
    /// [`SceneError::Run`] if the nonlinear equations fail (zero airspeed, a non-finite state)
    /// or the integrator does.
    pub fn run(&self) -> Result<FlightRun, SceneError> {
        self.run_with(RunControl { progress: &mut |_| {}, cancel: None })
    }

    /// [`FlightScene::run`] with a progress callback (fraction done: the nonlinear run is the
    /// first half, the linear one the second) and a cancellation flag: a cancelled run keeps
    /// the samples up to the time the nonlinear run reached (both responses), with
    /// [`FlightRun::stop`] set.
    ///
    /// # Errors
    /// As [`FlightScene::run`].
    pub fn run_with(&self, mut ctl: RunControl<'_>) -> Result<FlightRun, SceneError> {
        let n = self.spec.samples;
        let end = self.spec.duration;
        let times: Vec<f64> = (0..n).map(|k| end * k as f64 / (n - 1) as f64).collect();
        let trim = self.linearization.trim;
        let x0 = trim.state.to_array();
        let ac = &self.aircraft;
        let nl = self.integrate(
            x0,
            &times,
            |x, u| {
                let d = ac.dynamics(&AircraftState::from_array(*x), &Controls::from_array(*u))?;
                Ok(d.to_array())
            },
            &mut ctl,
            (0.0, 0.5),
            end,
        )?;
        let t_limit = nl.stopped.unwrap_or(end);
        // linear: δẋ = A δx + B δu, from δx = 0 (not cancelled again: it stops where the
        // nonlinear run stopped)
        let ss = &self.linearization.state_space;
        let (a, b) = (ss.a().clone(), ss.b().clone());
        let u0 = trim.controls.to_array();
        let lin = self.integrate(
            [0.0; 12],
            &times,
            |dx, u| {
                let du = DVector::from_iterator(4, (0..4).map(|i| u[i] - u0[i]));
                let d = &a * DVector::from_column_slice(dx) + &b * du;
                Ok(std::array::from_fn(|i| d[i]))
            },
            &mut RunControl { progress: &mut |f| (ctl.progress)(f), cancel: None },
            (0.5, 0.5),
            t_limit,
        )?;
        let rows = nl.samples.len().min(lin.samples.len());
        let (times, xs, dxs) = (&times[..rows], &nl.samples[..rows], &lin.samples[..rows]);
        // reference motion: ẋ at trim (nonzero only in X, Y, Z and, in a turn, Ψ)
        let f0 = ac
            .dynamics(&trim.state, &trim.controls)
            .map_err(|e| SceneError::Run { t: 0.0, message: e.to_string() })?
            .to_array();
        let turning = matches!(self.spec.trim.turn_rate, Some(r) if r != 0.0);
        let mut nonlinear = Vec::new();
        let mut linear = Vec::new();
        for &o in &self.outputs {
            nonlinear.push(times.iter().zip(xs).map(|(&t, x)| self.output(o, x, t)).collect());
            if turning && o < 2 {
                linear.push(None);
                continue;
            }
            linear.push(Some(
                times
                    .iter()
                    .zip(dxs)
                    .map(|(&t, dx)| {
                        let x: [f64; 12] = std::array::from_fn(|i| x0[i] + f0[i] * t + dx[i]);
                        self.output(o, &x, t)
                    })
                    .collect(),
            ));
        }
        let (modes, poles) = self.modes();
        let stop = nl.stopped.map(|t| Stop {
            reason: StopReason::Interrupted,
            t,
            message: format!("interrupted at t = {t} s of {end} s"),
        });
        Ok(FlightRun {
            scene: self.spec.name.clone(),
            trim,
            modes,
            poles,
            t: times.to_vec(),
            outputs: self.outputs.iter().map(|&o| OUTPUT_NAMES[o].to_string()).collect(),
            nonlinear,
            linear,
            fevals: nl.fevals,
            steps: nl.steps,
            stop,
            units: self
                .outputs
                .iter()
                .map(|&o| UnitSystem::Imperial.label(output_dimension(OUTPUT_NAMES[o])))
                .collect(),
            unit_system: UnitSystem::Imperial.name(),
        })
    }

    fn output(&self, o: usize, x: &[f64; 12], t: f64) -> f64 {
        let s = AircraftState::from_array(*x);
        match o {
            0..12 => x[o],
            12 => s.aero_angles().alpha,
            13 => s.aero_angles().beta,
            14 => s.aero_angles().airspeed,
            15 => {
                let a = s.aero_angles();
                vectrix_flight::FlightPathAngles::from_attitude(&s.attitude, a.alpha, a.beta).gamma
            }
            _ => self.controls_at(t)[o - 16],
        }
    }

    /// Named modes of the decoupled 4-state models when the trim decouples (14.5.1), else the
    /// eigenvalues of the full A (upper half plane, zero roots of X, Y, Z, Ψ left out).
    fn modes(&self) -> (Vec<ModeSummary>, Vec<Complex64>) {
        let lin = &self.linearization;
        let scale = lin.state_space.a().amax().max(1.0);
        if lin.coupling() <= 1e-9 * scale
            && let (Ok(lon), Ok(lat)) = (lin.longitudinal(), lin.lateral())
            && let (Ok(l), Ok(d)) = (longitudinal_modes(lon.a()), lateral_modes(lat.a()))
        {
            let modes = vec![
                ModeSummary::of("short period", &l.short_period),
                ModeSummary::of("phugoid", &l.phugoid),
                ModeSummary::of("Dutch roll", &d.dutch_roll),
                ModeSummary::of("roll", &d.roll),
                ModeSummary::of("spiral", &d.spiral),
            ];
            let mut poles: Vec<Complex64> = lon.poles().unwrap_or_default();
            poles.extend(lat.poles().unwrap_or_default());
            return (modes, poles);
        }
        let eig = vectrix_lti::modes(lin.state_space.a()).unwrap_or_default();
        let mut modes = Vec::new();
        let mut poles = Vec::new();
        for m in eig {
            let l = m.eigenvalue;
            if l.norm() <= 1e-12 * scale {
                continue;
            }
            poles.push(l);
            if l.im < 0.0 {
                continue;
            }
            let fm = FlightMode { mode: m };
            modes.push(ModeSummary::of(&format!("mode {}", modes.len() + 1), &fm));
        }
        (modes, poles)
    }
}

impl FlightRun {
    /// CSV: `t`, then for each output its nonlinear column and `<name>_linear` (where defined).
    pub fn to_csv(&self) -> String {
        let mut s = String::from("t [s]");
        for ((name, lin), unit) in self.outputs.iter().zip(&self.linear).zip(&self.units) {
            s.push_str(&format!(",{name} [{unit}]"));
            if lin.is_some() {
                s.push_str(&format!(",{name}_linear [{unit}]"));
            }
        }
        s.push('\n');
        for (k, t) in self.t.iter().enumerate() {
            s.push_str(&format!("{t}"));
            for (nl, lin) in self.nonlinear.iter().zip(&self.linear) {
                s.push_str(&format!(",{}", nl[k]));
                if let Some(l) = lin {
                    s.push_str(&format!(",{}", l[k]));
                }
            }
            s.push('\n');
        }
        s
    }

    /// Largest |nonlinear − linear| of output `k` over the run (`None` where the linear column
    /// is undefined).
    pub fn max_linear_error(&self, k: usize) -> Option<f64> {
        let lin = self.linear.get(k)?.as_ref()?;
        Some(self.nonlinear[k].iter().zip(lin).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max))
    }

    /// Largest |nonlinear − initial value| of output `k` over the run.
    pub fn max_excursion(&self, k: usize) -> f64 {
        let v = &self.nonlinear[k];
        v.iter().map(|x| (x - v[0]).abs()).fold(0.0, f64::max)
    }

    /// The run with every output written in `system` (flight scenes fly in the catalogue's
    /// units, the book's imperial ones), converted exactly.
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// [`SceneError::Run`] when a value overflows in the new unit.
    pub fn in_units(mut self, system: UnitSystem) -> Result<Self, SceneError> {
        let fail = |e: vectrix_units::UnitError| SceneError::Run { t: 0.0, message: e.to_string() };
        for (k, name) in self.outputs.iter().enumerate() {
            let d = output_dimension(name);
            let (from, to) =
                (UnitSystem::Imperial.converter(d).map_err(fail)?, system.converter(d).map_err(fail)?);
            let conv = |x: &mut f64| -> Result<(), SceneError> {
                *x = to.from_si(from.to_si(*x).map_err(fail)?).map_err(fail)?;
                Ok(())
            };
            for x in &mut self.nonlinear[k] {
                conv(x)?;
            }
            if let Some(l) = &mut self.linear[k] {
                for x in l {
                    conv(x)?;
                }
            }
            self.units[k] = system.label(d);
        }
        self.unit_system = system.name();
        Ok(self)
    }

    /// summary.json: trim, modes, and per output the excursion and the linear model's error.
    pub fn summary_json(&self) -> String {
        let (s, c) = (&self.trim.state, &self.trim.controls);
        let summary = Summary {
            scene: &self.scene,
            units: self.unit_system,
            complete: self.stop.is_none(),
            stop: &self.stop,
            rows: self.t.len(),
            trim: TrimSummary {
                alpha: s.aero_angles().alpha,
                theta: s.attitude.theta,
                phi: s.attitude.phi,
                elevator: c.elevator,
                aileron: c.aileron,
                rudder: c.rudder,
                thrust: c.thrust,
                residual: self.trim.residual,
                iterations: self.trim.iterations,
            },
            modes: &self.modes,
            outputs: (0..self.outputs.len())
                .map(|k| OutputSummary {
                    name: &self.outputs[k],
                    unit: &self.units[k],
                    max_excursion: self.max_excursion(k),
                    max_linear_error: self.max_linear_error(k),
                })
                .collect(),
            fevals: self.fevals,
            steps: self.steps,
        };
        serde_json::to_string_pretty(&summary).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// SVG of output `k`: nonlinear and linear responses.
    ///
    /// # Errors
    /// [`FlightError::Plot`] for an output index out of range or a figure that cannot be drawn.
    pub fn response_svg(&self, k: usize) -> Result<String, FlightError> {
        let name = self.outputs.get(k).ok_or_else(|| FlightError::Plot {
            reason: format!("output index {k} out of range (0..{})", self.outputs.len()),
        })?;
        let pts = |v: &[f64]| self.t.iter().copied().zip(v.iter().copied()).collect::<Vec<_>>();
        let mut chart = vectrix_plot::LineChart::new(
            format!("{}: {name}", self.scene),
            "t [s]",
            format!("{name} [{}]", self.units[k]),
        )
        .with_series("nonlinear", pts(&self.nonlinear[k]));
        if let Some(l) = &self.linear[k] {
            chart = chart.with_series("linear", pts(l));
        }
        chart.to_svg().map_err(|e| FlightError::Plot { reason: e.to_string() })
    }

    /// SVG pole map of the modes.
    ///
    /// # Errors
    /// [`FlightError::Plot`] if there are no poles or the figure cannot be drawn.
    pub fn modes_svg(&self) -> Result<String, FlightError> {
        vectrix_flight::modes_svg(&format!("{}: modes", self.scene), &self.poles)
    }
}
