//! The page is one file that fetches nothing, and no text of a scene can break out of it
//! (issue 36: "a hostile scene name in the page title, or non-finite samples must not produce
//! a broken or script-injectable page").

use serde_json::{Value, json};

use super::page::{escape_html, escape_json};
use super::*;

const HOSTILE: &str = "</script><script>alert(1)</script>";

/// The JSON between `<script type="application/json" id="vectrix-data">` and its end tag.
fn data_of(page: &str) -> Value {
    let open = "<script type=\"application/json\" id=\"vectrix-data\">";
    let at = page.find(open).expect("data script") + open.len();
    let end = page[at..].find("</script>").expect("end of the data script");
    serde_json::from_str(&page[at..at + end]).expect("the data is JSON")
}

/// A name with `</script>`, `<!--`, `&`, quotes and the JavaScript line terminators U+2028 and
/// U+2029 in the title, a body name, an output name and a note: the page keeps exactly its two
/// script elements, the title shows the text escaped, and the data reads back unchanged.
#[test]
fn hostile_text_is_escaped_everywhere() {
    let name = format!("{HOSTILE}<!--&\"'\u{2028}\u{2029}");
    let mut data = no_poses(&name, &name);
    data["bodies"] = json!([{ "name": name, "shape": { "kind": "particle" }, "com": [0, 0, 0], "parent": -1,
        "offset": [0, 0, 0] }]);
    data["hud"] = json!({ "names": [name], "units": [name], "values": [] });
    let page = page(&name, &data);
    assert_eq!(page.matches("<script").count(), 2, "only the page's own two script elements");
    assert_eq!(page.matches("</script>").count(), 2);
    assert!(!page.contains("<script>alert"));
    assert!(!page.contains("<!--"));
    // JavaScript line terminators: harmless in the title, escaped in the scripts
    let scripts = &page[page.find("<script").unwrap()..];
    assert!(!scripts.contains('\u{2028}') && !scripts.contains('\u{2029}'));
    let title = format!("<title>{} · vectrix view</title>", escape_html(&name));
    assert!(page.contains(&title), "escaped title");
    assert!(title.contains("&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt;&lt;!--&amp;&quot;&#39;"));
    assert_eq!(data_of(&page), data, "the data survives its escaping unchanged");
    assert_eq!(data_of(&page)["note"], format!("no poses to show: {name}"));
}

/// The escapes are the JSON \u forms (which JavaScript reads the same): the escaped text of a
/// value parses back to the value.
#[test]
fn escaped_json_parses_back() {
    let v = json!({ "a": "<>&\u{2028}\u{2029}", "b": [1.5, -2e-300] });
    let e = escape_json(&v);
    assert_eq!(e, r#"{"a":"\u003c\u003e\u0026\u2028\u2029","b":[1.5,-2e-300]}"#);
    assert_eq!(serde_json::from_str::<Value>(&e).unwrap(), v);
}

/// Self-contained: no element loads anything (no `src`/`href` attribute, no `<link>`), a
/// Content-Security-Policy forbids fetching, and the only `://` in the file are XML namespace
/// names inside three.js (`http://www.w3.org/…`, identifiers that are never fetched).
#[test]
fn the_page_fetches_nothing() {
    let page = page("p", &no_poses("p", "test"));
    for tag in ["<link", "<img", "<iframe", "<object", "<embed", " src=", " href=", "<base"] {
        assert!(!page.contains(tag), "{tag}");
    }
    assert!(page.contains("content=\"default-src 'none'; script-src 'unsafe-inline';"));
    let mut n = 0;
    for (at, _) in page.match_indices("://") {
        assert!(
            page[..at].ends_with("http") && page[at..].starts_with("://www.w3.org/"),
            "{}",
            &page[at - 8..at + 30]
        );
        n += 1;
    }
    assert!(n <= 4, "{n} namespace names");
    // three.js is inline, with its licence, its exports gathered in one object
    assert!(page.contains("Copyright © 2010-2024 three.js authors"));
    assert!(page.contains("const THREE=Object.freeze({"));
    assert!(page.contains("WebGLRenderer:") && page.contains("Quaternion:"));
    assert!(!page.contains("export{"), "no module export left for the viewer that follows");
}

/// The size bound: at most 1001 instants, and at most 40 000 poses, whatever the samples.
#[test]
fn frames_are_bounded() {
    assert_eq!(frames(3, 1), 3);
    assert_eq!(frames(801, 1), 801);
    assert_eq!(frames(1_000_001, 1), MAX_FRAMES);
    assert_eq!(frames(1_000_001, 30), MAX_FRAMES);
    assert_eq!(frames(1_000_001, 100), 400);
    assert_eq!(frames(1_000_001, 1_000_000), 2);
}

/// A sample with a NaN or an infinity (in its time, its pose or another value) is dropped and
/// counted, never written into the page (where JSON would turn it into `null`).
#[test]
fn non_finite_samples_are_dropped() {
    let ok = vec![0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0];
    let mut nan = ok.clone();
    nan[2] = f64::NAN;
    let samples = vec![
        (0.0, Some(ok.clone())),
        (0.5, Some(nan)),
        (1.0, None),
        (f64::INFINITY, Some(ok.clone())),
        (2.0, Some(ok)),
    ];
    let (t, pose, keep) = finite_samples(samples.into_iter());
    assert_eq!(keep, [true, false, false, false, true]);
    assert_eq!(t, [json!(0.0), json!(2.0)]);
    assert_eq!(pose.len(), 14);
    assert!(pose.iter().all(Value::is_number));
}

/// A body given by its inertia is drawn as the uniform box with the same principal moments:
/// J = [1, 2, 3], m = 1 gives sides √(6·4), √(6·2), √(6·0) (§6.1: J₁ = m(b² + c²)/12).
#[test]
fn inertia_values_draw_the_equivalent_box() {
    let s = shape(&MassSpec::Value { mass: 1.0, principal: Some([1.0, 2.0, 3.0]), matrix: None });
    let mut sides: Vec<f64> = s["sides"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    // the eigen-solver may order the principal axes differently (the box turns with them)
    sides.sort_by(|a, b| b.total_cmp(a));
    let want = [24f64.sqrt(), 12f64.sqrt(), 0.0];
    for (a, b) in sides.iter().zip(want) {
        // 7 significant digits are kept
        assert!((a - b).abs() <= 1e-6 * b.max(1.0), "{sides:?}");
    }
    // the moments back from the sides: J₁ = m(b² + c²)/12 = 1
    assert!(((sides[1].powi(2) + sides[2].powi(2)) / 12.0 - 1.0).abs() < 1e-6);
}

/// A notebook cell shows the page in a sandboxed iframe: evcxr's HTML markers around it, the
/// page HTML-escaped in `srcdoc` (so no `<script` and no `"` of the page is read as the
/// notebook's markup), and the page back unchanged after unescaping.
#[test]
fn a_notebook_view_is_an_escaped_iframe() {
    let d = tempfile::tempdir().unwrap();
    let page = page("p", &no_poses("p", "test"));
    std::fs::write(d.path().join("view.html"), &page).unwrap();
    let text = View::open(d.path()).unwrap().display_text();
    assert!(text.starts_with("EVCXR_BEGIN_CONTENT text/html\n<iframe sandbox=\"allow-scripts\""));
    assert!(text.ends_with("></iframe>\nEVCXR_END_CONTENT\n"));
    let at = text.find("srcdoc=\"").unwrap() + 8;
    let end = text[at..].find('"').unwrap();
    let doc = &text[at..at + end];
    assert!(!doc.contains('<') && !doc.contains('>'));
    let back = doc
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&#39;", "'")
        .replace("&amp;", "&");
    assert_eq!(back, page);
    assert!(View::open(d.path().join("missing")).unwrap_err().to_string().contains("view.html"));
}
