//! Every refusal of a scene file is located and worded for the writer of the file (issue 33):
//! an unknown key is named with the valid keys and the closest one, at the key itself (also
//! inside an inline table); a duplicate key is named; a parent cycle is reported at `parent`;
//! numbers past 1e150 (whose products would overflow) and profile corners closer than the time
//! resolution are refused where they stand instead of failing the run with "step size 0".
//!
//! Book: — (file format).

use vectrix::scene::{MAX_MAGNITUDE, Scene, SceneError};

const PIN: &str = r#"
name = "p"
duration = 1.0
outputs = ["energy"]

[[bodies]]
name = "b"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
mass = { shape = "particle", mass = 1.0 }
com = [1.0, 0.0, 0.0]
v = [1.0]
"#;

/// (line, column, message) of the refusal of `text`, which must be located in `p.toml`.
fn refusal(text: &str) -> (usize, usize, String) {
    match Scene::from_toml(text, "p.toml") {
        Err(SceneError::Parse { file, line, column, message }) => {
            assert_eq!(file, "p.toml");
            (line, column, message)
        }
        Err(SceneError::Invalid { file, line, column, path, message }) => {
            assert_eq!(file, "p.toml");
            (line, column, format!("{path}: {message}"))
        }
        other => panic!("expected a located refusal, got {other:?}"),
    }
}

/// 1-based (line, column) of the first occurrence of `needle` in `text`.
fn position(text: &str, needle: &str) -> (usize, usize) {
    let at = text.find(needle).expect("needle in text");
    let line = text[..at].matches('\n').count() + 1;
    let column = text[..at].rsplit('\n').next().unwrap().chars().count() + 1;
    (line, column)
}

#[test]
fn unknown_key_in_an_inline_table_is_located_at_the_key() {
    let text = PIN.replace("axis = [0.0, 0.0, 1.0] }", "axis = [0.0, 0.0, 1.0], axes = 1 }");
    let (line, column, message) = refusal(&text);
    assert_eq!((line, column), position(&text, "axes"));
    assert_eq!(message, "bodies[0].joint.axes: unknown key `axes`; valid: `axis`");
}

#[test]
fn unknown_top_level_key_suggests_the_closest() {
    let text = PIN.replace("duration = 1.0", "durration = 1.0");
    let (line, column, message) = refusal(&text);
    assert_eq!((line, column), position(&text, "durration"));
    assert!(
        message.starts_with("durration: unknown key `durration`; valid: `name`, `duration`"),
        "{message}"
    );
    assert!(message.ends_with("(did you mean `duration`?)"), "{message}");
}

#[test]
fn duplicate_key_is_named() {
    let text = PIN.replace("duration = 1.0", "duration = 1.0\nduration = 2.0");
    let (line, _, message) = refusal(&text);
    assert_eq!(line, 4);
    assert_eq!(message, "duplicate key `duration`; valid: each key once in its table");
}

#[test]
fn parser_wording_is_the_scene_writers() {
    for (value, shown) in [("-3", "integer `-3`"), ("1.5", "floating point `1.5`")] {
        let text = PIN.replace("duration = 1.0", &format!("duration = 1.0\nsamples = {value}"));
        let (line, column, message) = refusal(&text);
        assert_eq!((line, column), (4, 11));
        assert!(
            message.contains(shown) && message.ends_with("valid: a whole number ≥ 0 (no decimal point)"),
            "{message}"
        );
        assert!(!message.contains("usize"), "{message}");
    }
}

#[test]
fn parent_cycle_is_reported_at_parent() {
    let text = r#"
name = "c"
duration = 1.0
[[bodies]]
name = "a"
parent = "b"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
mass = { shape = "particle", mass = 1.0 }
[[bodies]]
name = "b"
parent = "a"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
mass = { shape = "particle", mass = 1.0 }
"#;
    let (line, _, message) = refusal(text);
    assert_eq!(line, 6, "{message}");
    assert!(message.starts_with("bodies[0].parent: body `a` is its own ancestor"), "{message}");
}

#[test]
fn numbers_past_the_magnitude_bound_are_refused_where_they_stand() {
    // the issue's cases: a mass ≥ 1e154 (energies overflow), g = −1e308 (a zero step)
    assert_eq!(MAX_MAGNITUDE, 1e150);
    let text = PIN.replace("mass = 1.0 }", "mass = 1e155 }");
    let (line, column, message) = refusal(&text);
    assert_eq!((line, column), position(&text, "mass = 1e155"));
    assert!(
        message.starts_with("bodies[0].mass.mass: 1e155; valid: finite numbers of magnitude at most 1e150")
    );
    let text = format!("{PIN}\n[[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -1e308, 0.0]\n");
    let (line, _, message) = refusal(&text);
    assert_eq!(line, position(&text, "-1e308").0);
    assert!(message.starts_with("effects[0].g[1]: -1e308;"), "{message}");
    // the bound itself is accepted
    let text = PIN.replace("com = [1.0, 0.0, 0.0]", "com = [1e150, 0.0, 0.0]");
    assert!(Scene::from_toml(&text, "p.toml").is_ok());
}

#[test]
fn mutual_gravitation_whose_g_m_m_overflows_is_refused_at_g_naming_the_pair() {
    // each number is inside the bound, their product G m₁ m₂ = 1e350 is not: refused at `g`,
    // naming both bodies, instead of failing every evaluation of the run
    let two = format!(
        "{PIN}\n[[bodies]]\nname = \"c\"\njoint = {{ type = \"free\" }}\nmass = {{ shape = \"particle\", mass = 1e100 }}\n\
         q = [5.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]\n\n[[effects]]\ntype = \"mutual_gravitation\"\ng = 1e150\n"
    )
    .replace("mass = 1.0 }", "mass = 1e100 }");
    let (line, _, message) = refusal(&two);
    assert_eq!(line, position(&two, "g = 1e150").0);
    assert!(message.starts_with("effects[0].g: bodies `b` and `c`:"), "{message}");
    assert!(message.contains("overflow") || message.contains("largest"), "{message}");
    // G = 1 with the same masses is a valid scene
    assert!(Scene::from_toml(&two.replace("g = 1e150", "g = 1.0"), "p.toml").is_ok());
}

#[test]
fn profile_corner_closer_than_the_time_resolution_is_refused_where_it_stands() {
    let torque = |at: &str| {
        format!(
            "{PIN}\n[[effects]]\ntype = \"torque\"\nbody = \"b\"\ndirection = [0.0, 0.0, 1.0]\n\
             profile = {{ kind = \"step\", at = {at}, after = 1.0 }}\n"
        )
    };
    for at in ["1e-300", "1e-15", "0.9999999999999999"] {
        let text = torque(at);
        let (line, _, message) = refusal(&text);
        assert_eq!(line, position(&text, "profile").0);
        assert!(message.starts_with("effects[0].profile.at: a profile corner"), "{at}: {message}");
    }
    // at the start, at the end and well apart they run
    for at in ["0.0", "1.0", "1e-13", "0.5"] {
        let scene = Scene::from_toml(&torque(at), "p.toml").unwrap_or_else(|e| panic!("{at}: {e}"));
        let run = scene.run(&mut |_| {}).unwrap();
        assert!(run.is_complete(), "{at}: {:?}", run.stop);
    }
}

/// Issue 33 item 5: every error of a file in one pass, in file order, each located, without
/// the errors that would only follow from an earlier one.
#[test]
fn every_error_of_a_file_in_one_pass_in_file_order() {
    let text = r#"name = "multi"
duration = -1.0
outputs = ["q", "qq", "energy", "position:nobody"]
checks = ["energy", "momentum2"]

[[bodies]]
name = "rod"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
mass = { shape = "rod", mass = 1.0, length = 1.0 }

[[effects]]
type = "spring"
a = { body = "rod", point = [1.0, 0.0, 0.0] }
b = { body = "nobody" }
k = 3.0

[[effects]]
type = "torque"
body = "rod"
direction = [0.0, 0.0, 1.0]
profile = { kind = "ramp", t0 = 1.0, t1 = 0.5, to = 1.0 }
"#;
    let Err(SceneError::Many { errors }) = Scene::from_toml(text, "multi.toml") else {
        panic!("expected several errors")
    };
    let got: Vec<(usize, String)> = errors
        .iter()
        .map(|e| match e {
            SceneError::Invalid { line, path, .. } => (*line, path.clone()),
            other => panic!("{other}"),
        })
        .collect();
    let want = [
        (2, "duration"),
        (3, "outputs[1]"),
        (3, "outputs[3]"),
        (4, "checks[1]"),
        (14, "effects[0].b.body"),
        (21, "effects[1].profile.t1"),
    ];
    assert_eq!(got, want.map(|(l, p)| (l, p.to_string())));
    // the shape errors of a file, likewise (a misspelt key, a wrong type, unknown tags)
    let shape = "name = \"s\"\ndurration = 1.0\nsamples = \"x\"\n\n[[bodies]]\nname = \"rod\"\n\
        joint = { type = \"hinge\" }\nmass = { shape = \"particle\", mass = 1.0 }\n\n[[effects]]\ntype = \"wind\"\n";
    let Err(SceneError::Many { errors }) = Scene::from_toml(shape, "shape.toml") else {
        panic!("expected several errors")
    };
    let paths: Vec<String> = errors
        .iter()
        .filter_map(|e| match e {
            SceneError::Invalid { path, .. } => Some(path.clone()),
            _ => None,
        })
        .collect();
    // (the misspelt `durration` is not also reported as a missing `duration`: it suggests it)
    assert_eq!(paths, ["durration", "samples", "bodies[0].joint.type", "effects[0].type"]);
}
