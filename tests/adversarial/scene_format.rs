//! The scene format's paths and document under hostile input (issue 32, item 6): item paths
//! parse back what they print and refuse malformed text at its byte; the document's lookups
//! take hostile paths without panicking; numbers are set only where numbers are; quantity
//! strings convert on the document and are refused where they stand.

use vectrix::scene::{
    AsItemPath, ItemPath, Node, NodeValue, PathSeg, SceneError, SceneSource, SceneSpec, body_schema,
    convert_quantities, tag,
};

use crate::harness::refused;
use crate::scene::{double_pendulum, located};

/// Hostile path texts: empty, lone punctuation, unclosed brackets and quotes, an index past
/// usize::MAX, a right-to-left override, an escape that is not `\"` or `\\`.
const HOSTILE_PATHS: [&str; 14] = [
    "",
    ".",
    "[",
    "]",
    "[]",
    "bodies[",
    "bodies[99]",
    "bodies[18446744073709551616]",
    "bodies[1].q[7]",
    "bodies..name",
    "bodies[0][0][0]",
    "\u{202e}",
    "\"a",
    "\"a\\x\"",
];

cases! {
    // Item paths: display and parse are inverse; malformed text is refused with its byte (at
    // most the text's length), and its longest valid prefix is what the locator walks.
    scene_paths ["ItemPath::root", "ItemPath::segments", "ItemPath::is_empty", "ItemPath::push", "ItemPath::pop",
        "ItemPath::key", "ItemPath::index", "ItemPath::parent", "ItemPath::head", "ItemPath::last_key",
        "ItemPath::parse", "ItemPath::parse_prefix", "PathSeg::key", "PathSeg::index", "AsItemPath::item_path"] {
        let root = ItemPath::root();
        assert!(root.is_empty() && root.parent().is_none() && root.head().is_none() && root.last_key().is_none());
        let p = root.key("bodies").index(usize::MAX).key("a.b").key("");
        assert_eq!(p.to_string(), format!("bodies[{}].\"a.b\".\"\"", usize::MAX));
        assert_eq!(ItemPath::parse(&p.to_string()), Ok(p.clone()));
        assert_eq!(p.head(), Some(("bodies", Some(usize::MAX))));
        assert_eq!((p.segments()[0].key(), p.segments()[1].index()), (Some("bodies"), Some(usize::MAX)));
        assert_eq!((p.segments()[0].index(), p.segments()[1].key()), (None, None));
        let mut q = p.clone();
        assert_eq!(q.pop(), Some(PathSeg::Key(String::new())));
        q.push(PathSeg::Index(0));
        assert_eq!(q.to_string(), format!("bodies[{}].\"a.b\"[0]", usize::MAX));
        assert_eq!(ItemPath::root().index(3).to_string(), "[3]");
        for text in HOSTILE_PATHS {
            match ItemPath::parse(text) {
                Ok(p) => assert_eq!(ItemPath::parse(&p.to_string()), Ok(p), "{text:?}"),
                Err(e) => {
                    assert!(e.at <= text.len() && e.to_string().contains("valid:"), "{text:?}: {e}");
                    let prefix = ItemPath::parse_prefix(text);
                    assert_eq!(ItemPath::parse(&prefix.to_string()), Ok(prefix.clone()), "{text:?}");
                    assert_eq!(*text.item_path(), prefix, "{text:?}");
                }
            }
        }
        assert_eq!(*p.item_path(), p);
        assert_eq!(*p.to_string().item_path(), p);
    }

    // The document: lookups at hostile paths find nothing rather than panic, numbers are set
    // only on numbers (integers only to whole values), the plain TOML value keeps every key,
    // and a changed document is read back with errors located in the file.
    scene_document ["Node::as_table", "Node::as_array", "Node::as_str", "Node::entry", "Node::get", "Node::at",
        "Node::at_mut", "Node::set_number", "Node::to_toml", "SceneSource::tree", "SceneSource::read_document",
        "SceneSource::document"] {
        let text = double_pendulum([0.4, -0.3], "");
        let src = SceneSource::new(&text, "dp.toml").unwrap();
        let tree = src.tree();
        assert_eq!(tree.as_table().map(<[_]>::len), Some(tree.to_toml().as_table().unwrap().len()));
        assert!(tree.as_array().is_none() && tree.as_str().is_none() && tree.entry("").is_none());
        assert_eq!(tree.get("name").and_then(Node::as_str), Some("dp"));
        let q0 = ItemPath::root().key("bodies").index(0).key("q").index(0);
        assert_eq!(tree.at(&q0).map(|n| &n.value), Some(&NodeValue::Float(0.4)));
        assert_eq!(&text[tree.at(&q0).unwrap().span.clone()], "0.4");
        for path in HOSTILE_PATHS {
            let _ = tree.at(&path.item_path());
        }
        let mut doc = src.document(&body_schema).unwrap();
        assert!(doc.at_mut(&ItemPath::root().key("bodies").index(99)).is_none());
        for x in crate::harness::hostile() {
            let mut d = doc.clone();
            // a float takes any number; the spec read back refuses non-finite ones later
            assert!(d.set_number(&q0, x).is_ok());
            assert!(matches!(d.at(&q0).map(|n| &n.value), Some(NodeValue::Float(y)) if y.to_bits() == x.to_bits()));
            let samples = ItemPath::root().key("samples");
            match d.set_number(&samples, x) {
                Ok(()) => assert!(x.fract() == 0.0 && x.abs() < 9.0e15, "{x}"),
                Err(m) => assert!(m.contains("integer"), "{m}"),
            }
            refused(d.set_number(&ItemPath::root().key("name"), x), "a number for a string");
            refused(d.set_number(&ItemPath::root().key("nothing"), x), "a number for a missing key");
            match src.read_document::<SceneSpec>(&d) {
                Ok(spec) => assert_eq!(spec.bodies.len(), 2),
                Err(e) => assert!(located(&e), "{x}: {e}"),
            }
        }
        assert!(doc.set_number(&q0, 0.25).is_ok());
        let spec: SceneSpec = src.read_document(&doc).unwrap();
        assert_eq!(spec.bodies[0].q.as_deref(), Some(&[0.25][..]));
        // a wrong type set by hand is refused at its item
        if let Some(n) = doc.at_mut(&q0) {
            n.value = NodeValue::Boolean(true);
        }
        match src.read_document::<SceneSpec>(&doc) {
            Err(SceneError::Invalid { path, .. }) => assert_eq!(path, "bodies[0].q[0]"),
            other => panic!("{other:?}"),
        }
    }

    // Quantity strings (§15.19): tags are read from hostile paths without panicking, and
    // conversion turns "30 deg" into π/6 and refuses strings of another dimension at their
    // location.
    scene_quantities ["tag", "convert", "body_schema"] {
        let text = double_pendulum([0.4, -0.3], "");
        let src = SceneSource::new(&text, "dp.toml").unwrap();
        let doc = src.tree();
        let joint = ItemPath::root().key("bodies").index(0).key("joint");
        assert_eq!(tag(doc, &joint, "type"), Some("pin"));
        assert_eq!(tag(doc, &ItemPath::root().key("bodies").index(usize::MAX), "type"), None);
        assert_eq!(tag(doc, &ItemPath::root().index(0), "type"), None);
        assert_eq!(tag(doc, &ItemPath::root(), "name"), Some("dp"));
        let q0 = ItemPath::root().key("bodies").index(0).key("q").index(0);
        assert!(body_schema(&q0, doc).is_some());
        assert!(body_schema(&ItemPath::root(), doc).is_none() && body_schema(&ItemPath::root().index(3), doc).is_none());
        for path in HOSTILE_PATHS {
            let _ = body_schema(&path.item_path(), doc);
        }
        let mut plain = doc.clone();
        assert_eq!(convert_quantities(&src, &mut plain, &body_schema).unwrap(), 0);
        let with_units = text.replacen("q = [0.4]", "q = [\"30 deg\"]", 1).replacen("mass = 1.0", "mass = \"1000 g\"", 1);
        let src = SceneSource::new(&with_units, "dp.toml").unwrap();
        let mut doc = src.tree().clone();
        assert_eq!(convert_quantities(&src, &mut doc, &body_schema).unwrap(), 2);
        let q = doc.to_toml()["bodies"][0]["q"][0].as_float().unwrap();
        assert!((q - std::f64::consts::FRAC_PI_6).abs() <= f64::EPSILON);
        assert_eq!(doc.to_toml()["bodies"][0]["mass"]["mass"].as_float(), Some(1.0));
        for bad in ["1 m", "1e400 deg", "NaN deg", "", "1 deg deg", "1 deg/0"] {
            let t = text.replacen("q = [0.4]", &format!("q = [{bad:?}]"), 1);
            let src = SceneSource::new(&t, "dp.toml").unwrap();
            let mut doc = src.tree().clone();
            match convert_quantities(&src, &mut doc, &body_schema) {
                Ok(_) => assert!(doc.to_toml()["bodies"][0]["q"][0].as_float().is_some_and(f64::is_finite), "{bad}"),
                Err(e) => assert!(located(&e), "{bad}: {e}"),
            }
        }
    }
}
