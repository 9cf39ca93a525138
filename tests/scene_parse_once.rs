//! Parse once, locate exactly (issue 32, item 6): a scene file is parsed once into a
//! span-carrying document, the spec is deserialized from it by the scene's own deserializer,
//! and every error names its item by one path type and points at it (file:line:col): an
//! unknown key at the key, also deep inside the inline table of a tagged effect, with "did you
//! mean"; a missing key at its table; a wrong value at the value; an unknown `type`, `shape` or
//! `kind` at the tag. The independent reference of each location is the position of the
//! offending text in the file, found here by searching the test's own text.
//!
//! Book: — (file format).

use vectrix::scene::{ItemPath, PathSeg, Scene, SceneError};

/// A pendulum on a pin: the base that each case changes.
const PIN: &str = r#"name = "p"
duration = 1.0

[[bodies]]
name = "b"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
mass = { shape = "particle", mass = 1.0 }
com = [1.0, 0.0, 0.0]

[[effects]]
type = "uniform_gravity"
g = [0.0, -9.81, 0.0]
"#;

/// (line, column, path, message) of the one refusal of `text`.
fn refusal(text: &str) -> (usize, usize, String, String) {
    match Scene::from_toml(text, "p.toml") {
        Err(SceneError::Invalid { file, line, column, path, message }) => {
            assert_eq!(file, "p.toml");
            (line, column, path, message)
        }
        other => panic!("expected one located refusal, got {other:?}"),
    }
}

/// 1-based (line, column) of the `nth` occurrence (from 0) of `needle` in `text`.
fn position(text: &str, needle: &str, nth: usize) -> (usize, usize) {
    let at = text.match_indices(needle).nth(nth).expect("needle in text").0;
    let line = text[..at].matches('\n').count() + 1;
    let column = text[..at].rsplit('\n').next().unwrap().chars().count() + 1;
    (line, column)
}

/// `PIN` with one more effect.
fn with_effect(effect: &str) -> String {
    format!("{PIN}\n[[effects]]\n{effect}\n")
}

#[test]
fn unknown_key_deep_in_a_tagged_effects_inline_table_is_located_at_the_key() {
    let text = with_effect(
        "type = \"torque\"\nbody = \"b\"\ndirection = [0.0, 0.0, 1.0]\n\
         profile = { kind = \"sine\", amplitud = 1.0, omega = 2.0 }",
    );
    let (line, column, path, message) = refusal(&text);
    assert_eq!(path, "effects[1].profile.amplitud");
    assert_eq!((line, column), position(&text, "amplitud", 0));
    assert!(message.starts_with("unknown key `amplitud`; valid: `amplitude`, `omega`"), "{message}");
    assert!(message.ends_with("(did you mean `amplitude`?)"), "{message}");
}

#[test]
fn missing_key_inside_a_tagged_joint_is_named_by_its_path_at_the_joint() {
    let text = PIN.replace("{ type = \"pin\", axis", "{ type = \"slot\", axis");
    let (line, column, path, message) = refusal(&text);
    assert_eq!(path, "bodies[0].joint.direction");
    assert_eq!((line, column), position(&text, "{ type = \"slot\"", 0));
    assert_eq!(message, "the required key `direction` is missing; valid: a table that gives `direction`");
}

#[test]
fn missing_key_of_a_tagged_effect_is_its_own_not_its_inner_tables() {
    // the torque lacks `body`; its profile (which has no `body`) is not at fault
    let text = with_effect(
        "type = \"torque\"\ndirection = [0.0, 0.0, 1.0]\nprofile = { kind = \"constant\", value = 1.0 }",
    );
    let (line, column, path, _) = refusal(&text);
    assert_eq!(path, "effects[1].body");
    // at its table: the `[[effects]]` header of the second effect
    assert_eq!((line, column), position(&text, "[[effects]]", 1));
    // the force's point of application lacks `body`; the force itself has none to give
    let text = with_effect(
        "type = \"force\"\nat = { point = [1.0, 0.0, 0.0] }\ndirection = [0.0, 1.0, 0.0]\nprofile = { kind = \"constant\", value = 1.0 }",
    );
    let (line, column, path, _) = refusal(&text);
    assert_eq!(path, "effects[1].at.body");
    assert_eq!((line, column), position(&text, "{ point", 0));
}

#[test]
fn wrong_type_in_an_array_element_is_located_at_the_element() {
    // in a body (read directly) and in a tagged effect (read from serde's buffer)
    for (from, to, path) in [
        ("com = [1.0, 0.0, 0.0]", "com = [1.0, true, 0.0]", "bodies[0].com[1]"),
        ("g = [0.0, -9.81, 0.0]", "g = [0.0, true, 0.0]", "effects[0].g[1]"),
    ] {
        let text = PIN.replace(from, to);
        let (line, column, got, message) = refusal(&text);
        assert_eq!(got, path);
        assert_eq!((line, column), position(&text, "true", 0));
        assert_eq!(message, "invalid type: boolean `true`; valid: a number");
    }
    // an array of the wrong length, at the array
    let text = PIN.replace("com = [1.0, 0.0, 0.0]", "com = [1.0, 0.0]");
    let (line, column, path, message) = refusal(&text);
    assert_eq!((path.as_str(), (line, column)), ("bodies[0].com", position(&text, "[1.0, 0.0]", 0)));
    assert!(message.starts_with("invalid length 2"), "{message}");
    // one element too many is refused too, never dropped
    let text = PIN.replace("com = [1.0, 0.0, 0.0]", "com = [1.0, 0.0, 0.0, 4.0]");
    let (line, column, path, message) = refusal(&text);
    assert_eq!(
        (path.as_str(), (line, column)),
        ("bodies[0].com", position(&text, "[1.0, 0.0, 0.0, 4.0]", 0))
    );
    assert!(message.starts_with("invalid length 4"), "{message}");
    // a date-time where a number goes is named as written
    let text = PIN.replace("duration = 1.0", "duration = 1979-05-27");
    let (line, column, path, message) = refusal(&text);
    assert_eq!((path.as_str(), (line, column)), ("duration", position(&text, "1979", 0)));
    assert_eq!(message, "invalid type: a date-time; valid: a number");
}

#[test]
fn unknown_variant_of_each_tag_is_located_at_the_tag() {
    let loop_scene = format!(
        "{PIN}\n[[loops]]\nname = \"l\"\ntype = \"zzz\"\na = {{ body = \"b\" }}\nb = {{ body = \"ground\" }}\n"
    );
    let cases = [
        (
            PIN.replace("type = \"pin\"", "type = \"zzz\""),
            "bodies[0].joint.type",
            "unknown type `zzz`",
            "`pin`",
        ),
        (
            PIN.replace("shape = \"particle\"", "shape = \"zzz\""),
            "bodies[0].mass.shape",
            "unknown shape `zzz`",
            "`sphere`",
        ),
        (
            PIN.replace("type = \"uniform_gravity\"", "type = \"zzz\""),
            "effects[0].type",
            "unknown type `zzz`",
            "`spring`",
        ),
        (loop_scene, "loops[0].type", "unknown type `zzz`", "`coupler`"),
        (
            with_effect(
                "type = \"torque\"\nbody = \"b\"\ndirection = [0.0, 0.0, 1.0]\nprofile = { kind = \"zzz\" }",
            ),
            "effects[1].profile.kind",
            "unknown kind `zzz`",
            "`doublet`",
        ),
    ];
    for (text, want, head, valid) in cases {
        let (line, column, path, message) = refusal(&text);
        assert_eq!(path, want);
        assert_eq!((line, column), position(&text, "\"zzz\"", 0), "{want}");
        assert!(message.starts_with(&format!("{head}; valid: ")) && message.contains(valid), "{message}");
    }
}

#[test]
fn a_sweep_path_and_an_error_path_are_one_type() {
    // the path of an error parses back into the item it names
    let text = PIN.replace("mass = 1.0 }", "mass = -1.0 }");
    let (_, _, path, _) = refusal(&text);
    let p: ItemPath = path.parse().unwrap();
    let want = ["bodies", "0", "mass", "mass"];
    let got: Vec<String> = p
        .segments()
        .iter()
        .map(|s| match s {
            PathSeg::Key(k) => k.clone(),
            PathSeg::Index(i) => i.to_string(),
        })
        .collect();
    assert_eq!(got, want);
}

/// The load path parses the user's text once: `toml::from_str` appears nowhere in the scene
/// crate's or the command's sources (outside test modules), the parser is called in one place,
/// and serde's message text is not read.
#[test]
fn the_load_path_contains_no_second_parse() {
    let root = env!("CARGO_MANIFEST_DIR");
    let mut files = Vec::new();
    for dir in ["crates/scene/src", "crates/cli/src"] {
        rs_files(&std::path::Path::new(root).join(dir), &mut files);
    }
    assert!(files.len() > 20, "{} files: the scan found the sources", files.len());
    let mut parses = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        // code before the test module, comments dropped
        let code = text.split("#[cfg(test)]").next().unwrap_or("");
        let code: String =
            code.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n");
        let name = f.display().to_string();
        for banned in [
            "toml::from_str",
            "serde_path_to_error",
            "unknown field `",
            "missing field `",
            "(\"(did you mean",
        ] {
            assert!(!code.contains(banned), "{name} contains `{banned}`");
        }
        parses.extend(std::iter::repeat_n(name, code.matches("DeTable::parse").count()));
    }
    assert_eq!(parses.len(), 1, "{parses:?}");
    assert!(parses[0].ends_with("source.rs"), "{parses:?}");
}

fn rs_files(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            rs_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

mod prop {
    use proptest::prelude::*;
    use vectrix::scene::{ItemPath, PathSeg};

    fn seg() -> impl Strategy<Value = PathSeg> {
        prop_oneof![
            // bare names, names that need quotes (dots, brackets, quotes, spaces, empty), any text
            "[a-z_][a-z0-9_]{0,8}".prop_map(PathSeg::Key),
            "[a-z.\\[\\]\" \\\\]{0,6}".prop_map(PathSeg::Key),
            any::<String>().prop_map(PathSeg::Key),
            any::<usize>().prop_map(PathSeg::Index),
        ]
    }

    proptest! {
        /// Display and parse are inverse: the text of a path reads back as the same path.
        #[test]
        fn item_path_display_parse_round_trip(segs in proptest::collection::vec(seg(), 0..6)) {
            let p = ItemPath::from(segs);
            let text = p.to_string();
            prop_assert_eq!(ItemPath::parse(&text), Ok(p.clone()), "{}", text);
            prop_assert_eq!(ItemPath::parse_prefix(&text), p);
        }
    }
}
