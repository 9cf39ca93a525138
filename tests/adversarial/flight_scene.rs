//! vectrix-scene's flight scenes under hostile input (docs/robustness.md): hostile numbers at
//! every numeric key are refused at their line and column or give a finite trim; an aircraft
//! left alone stays at its trim; outputs convert by the exact foot.

use vectrix::scene::flight::{AnyScene, FlightScene, flight_schema, output_dimension};
use vectrix::scene::{RunControl, SceneError, Step};
use vectrix::units::{Dimension, UnitSystem};

use crate::harness::{err_or, finite, none_or, refused};

const EPS: f64 = f64::EPSILON;

/// A short flight scene (the business jet of Tables 14.1–14.2 at 400 kt, an elevator doublet).
fn flight_text(amplitude: &str) -> String {
    format!(
        r#"name = "jet"
duration = 4.0
samples = 41
accuracy = 1e-9
outputs = ["u", "alpha", "q", "theta", "elevator"]

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
amplitude = {amplitude}
"#
    )
}

/// A flight-scene refusal names `jet.toml:line:column`.
fn located(e: &SceneError) -> bool {
    let s = e.to_string();
    let mut p = s.splitn(4, ':');
    p.next() == Some("jet.toml")
        && p.next().is_some_and(|l| l.parse::<usize>().is_ok_and(|l| l >= 1))
        && p.next().is_some_and(|c| c.parse::<usize>().is_ok_and(|c| c >= 1))
}

cases! {
    // Flight scenes (§12.1, §14.2): hostile numbers at every numeric key are refused at
    // their line and column or give a finite trim; with no input the aircraft stays at its
    // trim (the defining property of a trim: every output's excursion is at the
    // integrator's noise); the outputs convert to SI by the exact foot; a cancelled run is
    // marked; the either-kind loader reads both kinds.
    flight_scenes ["FlightScene::from_toml", "FlightScene::from_source", "FlightScene::spec", "FlightScene::aircraft",
        "FlightScene::linearization", "FlightScene::run", "FlightScene::run_with", "FlightRun::to_csv",
        "FlightRun::max_linear_error", "FlightRun::max_excursion", "FlightRun::in_units", "FlightRun::summary_json",
        "FlightRun::response_svg", "FlightRun::modes_svg", "AnyScene::from_toml", "AnyScene::name",
        "flight::output_dimension", "flight::flight_schema"] {
        let text = flight_text("0.01");
        let s = FlightScene::from_toml(&text, "jet.toml").unwrap();
        assert!(s.spec().name == "jet" && finite(&s.linearization().trim.state.to_array()));
        assert!(format!("{:?}", s.aircraft()).contains("Aircraft"));
        let src = vectrix::scene::SceneSource::new(&text, "jet.toml").unwrap();
        assert_eq!(FlightScene::from_source(&src).unwrap().spec(), s.spec());
        for x in ["0.0", "-0.0", "5e-324", "1e-300", "1e300", "-1e300", "1.7976931348623157e308", "inf", "-inf", "nan"] {
            for (from, to) in [
                ("airspeed = 675.124", format!("airspeed = {x}")),
                ("gamma = 0.0", format!("gamma = {x}")),
                ("duration = 4.0", format!("duration = {x}")),
                ("accuracy = 1e-9", format!("accuracy = {x}")),
                ("start = 1.0", format!("start = {x}")),
                ("width = 1.0", format!("width = {x}")),
                ("amplitude = 0.01", format!("amplitude = {x}")),
                ("model = \"business_jet\"", format!("model = \"business_jet\"\nmass = {x}")),
            ] {
                let t = text.replacen(from, &to, 1);
                match FlightScene::from_toml(&t, "jet.toml") {
                    Ok(f) => assert!(finite(&f.linearization().trim.state.to_array()), "{to}"),
                    Err(e) => assert!(located(&e), "{to}: {e}"),
                }
            }
        }
        for n in ["0", "1", "-1", "18446744073709551615", "1e9"] {
            let t = text.replacen("samples = 41", &format!("samples = {n}"), 1);
            if let Err(e) = FlightScene::from_toml(&t, "jet.toml") {
                assert!(located(&e), "samples = {n}: {e}");
            }
        }
        for name in ["", "..", "a/b", "\u{202e}x"] {
            refused(FlightScene::from_toml(&text.replacen("name = \"jet\"", &format!("name = {name:?}"), 1), "jet.toml"), "flight scene name");
        }
        // trim is an equilibrium: without input nothing moves
        let still = FlightScene::from_toml(&flight_text("0.0"), "jet.toml").unwrap().run().unwrap();
        for k in 0..still.outputs.len() {
            let v0 = still.nonlinear[k][0].abs().max(1.0);
            assert!(still.max_excursion(k) <= 1e-6 * v0, "{}: {}", still.outputs[k], still.max_excursion(k));
        }
        let run = s.run().unwrap();
        assert!(run.stop.is_none() && run.t.len() == 41);
        assert_eq!(run.to_csv().lines().count(), 42);
        for k in 0..run.outputs.len() {
            assert!(run.max_excursion(k).is_finite() && run.max_excursion(k) >= 0.0);
            none_or(run.max_linear_error(k), "max_linear_error", |e| e.is_finite() && *e >= 0.0);
            assert!(run.response_svg(k).is_ok_and(|s| !s.contains("NaN")));
        }
        assert!(run.max_linear_error(usize::MAX).is_none() && run.max_linear_error(run.outputs.len()).is_none());
        refused(run.response_svg(run.outputs.len()), "response_svg(out of range)");
        refused(run.response_svg(usize::MAX), "response_svg(usize::MAX)");
        assert!(run.modes_svg().is_ok_and(|s| s.starts_with("<svg") && !s.contains("NaN")));
        let json: serde_json::Value = serde_json::from_str(&run.summary_json()).unwrap();
        assert_eq!(json["scene"], "jet");
        let si = run.clone().in_units(UnitSystem::Si).unwrap();
        assert!(si.nonlinear[0].iter().zip(&run.nonlinear[0]).all(|(a, b)| (a - b * 0.3048).abs() <= 4.0 * EPS * a.abs()));
        assert_eq!(si.nonlinear[1], run.nonlinear[1]);
        let mut huge = run.clone();
        huge.nonlinear[0] = vec![f64::MAX; huge.t.len()];
        err_or(huge.in_units(UnitSystem::Si), "in_units(f64::MAX ft/s)", |r| r.nonlinear.iter().flatten().all(|x| x.is_finite()));
        let cancel = std::sync::atomic::AtomicBool::new(true);
        let stopped = s.run_with(RunControl { progress: &mut |_| {}, cancel: Some(&cancel) }).unwrap();
        assert!(stopped.stop.is_some() && stopped.nonlinear.iter().flatten().all(|x| x.is_finite()));
        // output dimensions: total on any name
        assert_eq!((output_dimension("u"), output_dimension("x"), output_dimension("q")), (Dimension::VELOCITY, Dimension::LENGTH, Dimension::ANGULAR_VELOCITY));
        for name in ["", "\u{202e}", "thrust", &"z".repeat(10_000)] {
            let _ = output_dimension(name);
        }
        let doc: toml::Value = toml::from_str(&text).unwrap();
        let key = |k: &str| Step::Key(k.into());
        assert!(flight_schema(&[key("trim"), key("airspeed")], &doc).is_some());
        assert!(flight_schema(&[key("inputs"), Step::Index(0), key("amplitude")], &doc).is_some());
        assert!(flight_schema(&[key("inputs"), Step::Index(usize::MAX), key("amplitude")], &doc).is_some_and(|e| !e.dims.is_empty()));
        assert!(flight_schema(&[], &doc).is_none() && flight_schema(&[Step::Index(0)], &doc).is_none());
        // either kind through one loader
        let any = AnyScene::from_toml(&text, "jet.toml").unwrap();
        assert_eq!(any.name(), "jet");
        let bodies = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/scenes/simple_pendulum.toml")).unwrap();
        assert!(AnyScene::from_toml(&bodies, "p.toml").is_ok_and(|a| a.name() == "simple_pendulum"));
        for bad in ["", "[aircraft]", "aircraft = 1", "\u{0}"] {
            refused(AnyScene::from_toml(bad, "jet.toml"), "AnyScene(bad)");
        }
    }
}
