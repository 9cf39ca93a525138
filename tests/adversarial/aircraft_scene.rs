//! Aircraft scenes under hostile input (docs/robustness.md): a free body with `aero` and
//! `thrust` effects, trimmed when it loads. Hostile numbers at every numeric key are refused
//! at their line and column or give a finite trim and initial state; an aircraft left alone
//! stays at its trim; a file in the old flight form is refused, located, whatever it holds.

use vectrix::scene::{Scene, SceneError};

use crate::harness::{finite, refused};

/// A short aircraft scene (the business jet of Tables 14.1–14.2 at 400 kt, an elevator
/// doublet of `amplitude`), trimmed in level flight.
fn jet_text(amplitude: &str) -> String {
    format!(
        r#"name = "jet"
duration = 4.0
samples = 40
method = {{ name = "dop853", rtol = 1e-9 }}
outputs = ["velocity_body:jet", "air:jet", "omega_body:jet", "euler321:jet"]
trim = {{ free = ["dq:jet.4", "effects[1].elevator", "effects[2]"] }}

[[bodies]]
name = "jet"
joint = {{ type = "free" }}
mass = {{ shape = "aircraft", model = "business_jet" }}
v = [205.778, 0.0, 0.0, 0.0, 0.0, 0.0]

[[effects]]
type = "uniform_gravity"
g = [0.0, 0.0, 9.81456]

[[effects]]
type = "aero"
body = "jet"
aircraft = "business_jet"
rho = 0.303
area = 21.4
chord = 2.0
span = 10.7
coefficients = {{ cm_alpha = -0.6 }}
elevator = {{ kind = "doublet", start = 1.0, width = 1.0, amplitude = {amplitude} }}

[[effects]]
type = "thrust"
body = "jet"
profile = {{ kind = "constant", value = 0.0 }}
angle = 0.0
"#
    )
}

/// A refusal names `jet.toml:line:column`.
fn located(e: &SceneError) -> bool {
    let s = e.to_string();
    let mut p = s.splitn(4, ':');
    p.next() == Some("jet.toml")
        && p.next().is_some_and(|l| l.parse::<usize>().is_ok_and(|l| l >= 1))
        && p.next().is_some_and(|c| c.parse::<usize>().is_ok_and(|c| c >= 1))
}

cases! {
    // Aircraft scenes (§11.1, §12.1, §14.2): hostile numbers at every numeric key of the
    // aircraft's body, aero and thrust effects are refused at their line and column or give
    // a finite trimmed state; with no input the aircraft stays at its trim (the defining
    // property of a trim: every output stays at the integrator's noise); the old flight form
    // is refused with a location whatever it holds.
    aircraft_scenes [] {
        let text = jet_text("0.01");
        let s = Scene::from_toml(&text, "jet.toml").unwrap();
        assert!(finite(s.initial_state().as_slice()));
        for x in ["0.0", "-0.0", "5e-324", "1e-300", "1e300", "-1e300", "1.7976931348623157e308", "inf", "-inf", "nan"] {
            for (from, to) in [
                ("v = [205.778", format!("v = [{x}")),
                ("g = [0.0, 0.0, 9.81456]", format!("g = [0.0, 0.0, {x}]")),
                ("rho = 0.303", format!("rho = {x}")),
                ("area = 21.4", format!("area = {x}")),
                ("chord = 2.0", format!("chord = {x}")),
                ("span = 10.7", format!("span = {x}")),
                ("cm_alpha = -0.6", format!("cm_alpha = {x}")),
                ("start = 1.0", format!("start = {x}")),
                ("width = 1.0", format!("width = {x}")),
                ("amplitude = 0.01", format!("amplitude = {x}")),
                ("angle = 0.0", format!("angle = {x}")),
                ("value = 0.0", format!("value = {x}")),
            ] {
                let t = text.replacen(from, &to, 1);
                assert!(text.contains(from), "{from}");
                match Scene::from_toml(&t, "jet.toml") {
                    Ok(s) => assert!(finite(s.initial_state().as_slice()), "{to}"),
                    Err(e) => assert!(located(&e), "{to}: {e}"),
                }
            }
        }
        // trim is a steady flight: without input the speeds, angles and rates stay
        let still = Scene::from_toml(&jet_text("0.0"), "jet.toml").unwrap().run(&mut |_| {}).unwrap();
        assert!(still.is_complete());
        for (k, c) in still.columns.iter().enumerate() {
            let first = still.rows[0][k];
            for r in &still.rows {
                assert!((r[k] - first).abs() <= 1e-6 * first.abs().max(1.0), "{c}: {} vs {first}", r[k]);
            }
        }
        // the old flight form: refused at a location, never accepted under a new meaning
        for old in [
            "[aircraft]",
            "aircraft = 1",
            "name = \"x\"\n[aircraft]\nmodel = \"glider\"\n",
            "name = \"x\"\nduration = 1.0\n[aircraft]\nmodel = \"business_jet\"\nmass = nan\n[trim]\nairspeed = -1.0\n",
            "name = \"x\"\n[aircraft]\n[trim]\nairspeed = \"400 parsecs\"\nturn_rate = \"zzz\"\n[[inputs]]\ncontrol = 3\n",
        ] {
            match Scene::from_toml(old, "jet.toml") {
                Err(e) => assert!(located(&e), "{old}: {e}"),
                Ok(_) => panic!("accepted the old form {old:?}"),
            }
        }
        refused(Scene::from_toml("\u{0}", "jet.toml"), "NUL");
    }
}
