//! The old flight-scene form (an `[aircraft]` table; bare numbers in ft, slug, lbf) is refused
//! with the same scene written in the new form (issue 32, item 4): a free body with `aero` and
//! `thrust` effects. These tests take the rewritten text from the error, load it, and check
//! that it trims to what `vectrix-flight`'s trim (§12.1–12.3, the library's reference model)
//! gives for the old file's aircraft and condition in the book's units: nothing the user wrote
//! is lost or reinterpreted.

mod support;

use support::{assert_abs, assert_rel};
use vectrix::scene::{Scene, SceneError};
use vectrix_flight::{Aircraft, Airframe, Trim, TrimLimits, TrimSpec, business_jet, trim};

/// Newtons per pound-force (exact: 0.45359237 kg × 9.80665 m/s²).
const LBF: f64 = 0.45359237 * 9.80665;

/// The refusal of an old-form file: (line, path, message).
fn refusal(text: &str) -> (usize, String, String) {
    match Scene::from_toml(text, "old.toml") {
        Err(SceneError::Invalid { line, path, message, .. }) => (line, path, message),
        Err(e) => panic!("not a located refusal: {e}"),
        Ok(_) => panic!("the old flight form was accepted"),
    }
}

/// The scene in the new form that the refusal of `old` writes out.
fn rewritten(old: &str) -> String {
    let (line, path, message) = refusal(old);
    let at = old.lines().position(|l| l.trim() == "[aircraft]").unwrap() + 1;
    assert_eq!((line, path.as_str()), (at, "aircraft"), "{message}");
    assert!(message.contains("old flight-scene form") && message.contains("SI"), "{message}");
    message.split_once("\n\n").expect("the message holds the file").1.to_string()
}

fn load(text: &str) -> Scene {
    Scene::from_toml(text, "new.toml").unwrap_or_else(|e| panic!("{e}\n{text}"))
}

/// The flight trim of `ac` (book units) for `spec`.
fn flight_trim(ac: &Aircraft, spec: TrimSpec) -> Trim {
    trim(ac, spec, TrimLimits::default()).unwrap()
}

const DOUBLET: &str = r#"name = "business_jet_doublet"
duration = 20.0
samples = 201
accuracy = 1e-10
outputs = ["u", "alpha", "q", "theta", "z", "elevator"]

[aircraft]
model = "business_jet"

[trim]
airspeed = 675.124
gamma = 0.0

[[inputs]]
control = "elevator"
shape = "doublet"
start = 1.0
width = 1.0
amplitude = 0.01
"#;

#[test]
fn old_level_flight_file_is_refused_with_its_new_form_which_trims_as_before() {
    let new = rewritten(DOUBLET);
    // the doublet became the aero effect's elevator profile; rows became intervals
    assert!(
        new.contains("elevator = { kind = \"doublet\", start = 1.0, width = 1.0, amplitude = 0.01 }"),
        "{new}"
    );
    assert!(new.contains("samples = 200"), "{new}");
    assert!(new.contains("\"675.124 ft/s\""), "{new}");
    let scene = load(&new);
    let t = scene.trim_report().unwrap();
    assert_eq!(t.free, ["dq:aircraft.4", "effects[1].elevator", "effects[2]"]);
    let want = flight_trim(&business_jet(), TrimSpec::Straight { airspeed: 675.124, gamma: 0.0 });
    // angles [rad]: absolute 1e-10; thrust: the flight trim's lbf in N, relative 1e-9
    assert_abs(t.change[0], want.state.attitude.theta, 1e-10);
    assert_abs(t.change[1], want.controls.elevator, 1e-10);
    assert_rel(t.change[2], want.controls.thrust * LBF, 1e-9);
    // every old output maps to a body output, except the two with no column, which are noted
    assert_eq!(
        scene.spec().outputs,
        [
            "velocity_body:aircraft",
            "air:aircraft",
            "omega_body:aircraft",
            "euler321:aircraft",
            "position:aircraft"
        ]
    );
    assert!(new.contains("# note: `elevator` has no column"), "{new}");
}

#[test]
fn old_climb_with_overrides_keeps_every_override_in_its_units() {
    // every override of the old `[aircraft]` table, in the old form's units (slug, ft, …)
    let old = r#"name = "climb"
duration = 5.0

[aircraft]
model = "business_jet"
mass = 700.0
inertia = [120000.0, 140000.0, 250000.0, 3000.0]
area = 260.0
chord = 7.5
span = 36.0
rho = 0.0007
g = 32.174
thrust_angle = 0.02
coefficients = { cm_alpha = -0.65, cl_alpha = 5.2, u_ref = 675.124 }

[trim]
airspeed = 600.0
gamma = 0.05

[[inputs]]
control = "thrust"
shape = "step"
start = 2.0
amplitude = 100.0
"#;
    let new = rewritten(old);
    assert!(new.contains("profile = { kind = \"step\", at = 2.0, after = \"100.0 lbf\" }"), "{new}");
    let scene = load(&new);
    let t = scene.trim_report().unwrap();
    let mut ac = business_jet();
    ac.airframe = Airframe::new(700.0, 120000.0, 140000.0, 250000.0, 3000.0).unwrap();
    (ac.geometry.area, ac.geometry.chord, ac.geometry.span) = (260.0, 7.5, 36.0);
    (ac.rho, ac.g, ac.thrust_angle) = (0.0007, 32.174, 0.02);
    (ac.coefficients.cm_alpha, ac.coefficients.cl_alpha, ac.coefficients.u_ref) = (-0.65, 5.2, 675.124);
    let want = flight_trim(&ac, TrimSpec::Straight { airspeed: 600.0, gamma: 0.05 });
    // the pitch is γ + α; the unit conversions (ft, slug, lbf → SI) are exact to rounding
    assert_abs(t.change[0], want.state.attitude.theta, 1e-10);
    assert_abs(t.change[1], want.controls.elevator, 1e-10);
    assert_rel(t.change[2], want.controls.thrust * LBF, 1e-9);
}

#[test]
fn old_turn_file_is_refused_with_a_turn_trim_that_banks_as_before() {
    let old = r#"name = "turn"
duration = 5.0
samples = 51
outputs = ["r", "beta", "phi"]

[aircraft]
model = "business_jet"

[trim]
airspeed = 675.124
turn_rate = 0.0523599

[[inputs]]
control = "rudder"
shape = "pulse"
start = 2.0
width = 1.0
amplitude = 0.02
"#;
    let new = rewritten(old);
    let scene = load(&new);
    let t = scene.trim_report().unwrap();
    let want = flight_trim(&business_jet(), TrimSpec::LevelTurn { airspeed: 675.124, turn_rate: 0.0523599 });
    // the controls the turn needs [rad]: absolute 1e-10; thrust relative 1e-9
    let c = want.controls;
    for (k, w) in [(6, c.elevator), (7, c.aileron), (8, c.rudder)] {
        assert_abs(t.change[k], w, 1e-10);
    }
    assert_rel(t.change[9], c.thrust * LBF, 1e-9);
    // the bank and the body rates of the run's first row
    let run = scene.run(&mut |_| {}).unwrap();
    assert_abs(run.column("euler321:aircraft.phi").unwrap()[0], want.state.attitude.phi, 1e-10);
    let r = run.column("omega_body:aircraft.z").unwrap()[0];
    assert_abs(r, want.state.omega[2], 1e-12);
}

#[test]
fn what_the_new_form_cannot_say_is_written_as_a_note_not_dropped() {
    let old = r#"name = "two"
duration = 5.0
outputs = ["gamma", "aileron"]
[aircraft]
model = "business_jet"
[trim]
airspeed = "400 kt"
[[inputs]]
control = "aileron"
shape = "pulse"
start = 1.0
width = 1.0
amplitude = 0.01
[[inputs]]
control = "aileron"
shape = "step"
start = 3.0
amplitude = 0.01
[[inputs]]
control = "flaps"
shape = "wiggle"
start = 3.0
amplitude = 0.01
"#;
    let new = rewritten(old);
    for note in ["`gamma` has no column", "second `aileron` input", "shape `wiggle`"] {
        assert!(new.contains(note), "{note}\n{new}");
    }
    // a quantity string stays as written
    assert!(new.contains("v = [\"400 kt\""), "{new}");
    load(&new);
}

#[test]
fn aero_overrides_are_checked_and_located() {
    let new = rewritten(DOUBLET);
    let bad = |from: &str, to: &str| {
        let text = new.replacen(from, to, 1);
        assert_ne!(text, new);
        match Scene::from_toml(&text, "new.toml") {
            Err(SceneError::Invalid { path, message, .. }) => (path, message),
            other => panic!("{other:?}"),
        }
    };
    let with = "aircraft = \"business_jet\"";
    let (path, msg) = bad(with, "aircraft = \"business_jet\"\ncoefficients = { cm_alfa = -1.0 }");
    assert_eq!(path, "effects[1].coefficients.cm_alfa");
    assert!(msg.contains("did you mean `cm_alpha`"), "{msg}");
    let (path, msg) = bad(with, "aircraft = \"business_jet\"\narea = -3.0");
    assert_eq!(path, "effects[1].area");
    assert!(msg.contains("> 0"), "{msg}");
    let (path, _) = bad(with, "aircraft = \"business_jet\"\nspan = \"2 s\"");
    assert_eq!(path, "effects[1].span");
}
