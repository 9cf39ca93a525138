//! The HTML of `view.html`: one file, no external resource. The title is HTML-escaped; the
//! run's data is JSON inside `<script type="application/json">` with `<`, `>`, `&`, U+2028 and
//! U+2029 written as `\u` escapes, so no text of a scene (a name, a unit, an error message)
//! can close the script element or start markup; a Content-Security-Policy forbids every
//! network fetch and every script but the page's own. three.js is inlined as one module
//! script whose final `export { a as B, … }` is turned into `const THREE = { B: a, … }`.
//!
//! Book: — (reporting).

use std::sync::OnceLock;

use serde_json::Value;

/// three.js as published (`three@0.170.0`, `build/three.module.min.js`), MIT licence.
const THREE: &str = include_str!("../../assets/three/three.module.min.js");
/// three.js's licence, kept in the page next to the code.
const THREE_LICENSE: &str = include_str!("../../assets/three/LICENSE");
/// The pinned version of three.js.
const THREE_VERSION: &str = include_str!("../../assets/three/VERSION");
/// The viewer: scene graph, controls, hooks (`window.vectrixView`).
const VIEW_JS: &str = include_str!("../../assets/view.js");
/// The page's style and controls.
const VIEW_HTML: &str = include_str!("../../assets/view.html");

/// Bytes of the page besides the data and the title: template, three.js, licence, viewer.
fn fixed_bytes() -> u64 {
    (VIEW_HTML.len() + three_inline().len() + THREE_LICENSE.len() + VIEW_JS.len() + 64) as u64
}

/// three.js with its module exports turned into one `THREE` object, so the viewer can follow
/// it in the same inline script (in a function of its own: three.js's minified top-level
/// names are one-letter).
fn three_inline() -> &'static str {
    static INLINE: OnceLock<String> = OnceLock::new();
    INLINE.get_or_init(|| {
        let Some(at) = THREE.rfind("export{") else { return THREE.to_string() };
        let Some(end) = THREE[at..].find('}') else { return THREE.to_string() };
        let pairs: Vec<String> = THREE[at + "export{".len()..at + end]
            .split(',')
            .map(|p| match p.split_once(" as ") {
                Some((local, public)) => format!("{}:{}", public.trim(), local.trim()),
                None => p.trim().to_string(),
            })
            .collect();
        format!(
            "{}const THREE=Object.freeze({{{}}});{}",
            &THREE[..at],
            pairs.join(","),
            &THREE[at + end + 1..]
        )
    })
}

/// Text for an HTML element or attribute: `&`, `<`, `>`, `"`, `'` as character references.
pub(crate) fn escape_html(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// JSON that is safe inside a `<script>` element: `<`, `>`, `&`, U+2028, U+2029 as `\u`
/// escapes (valid JSON and valid JavaScript; no `</script>` or `<!--` can appear).
pub(crate) fn escape_json(v: &Value) -> String {
    let text = v.to_string();
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '<' => out.push_str("\\u003c"),
            '>' => out.push_str("\\u003e"),
            '&' => out.push_str("\\u0026"),
            '\u{2028}' => out.push_str("\\u2028"),
            '\u{2029}' => out.push_str("\\u2029"),
            c => out.push(c),
        }
    }
    out
}

/// The page of a run named `title` with the view data `data` (see [`super::scene_view`]).
pub(crate) fn page(title: &str, data: &Value) -> String {
    let licence = THREE_LICENSE.replace("*/", "* /");
    let script = format!(
        "/*! three.js {} (npm three, build/three.module.min.js)\n{licence}*/\n{}\n(() => {{\n{VIEW_JS}}})();\n",
        THREE_VERSION.trim(),
        three_inline()
    );
    // the template is cut at its three slots once, so no inserted text is searched again
    let mut out = String::with_capacity(VIEW_HTML.len() + script.len() + 4096);
    let mut rest = VIEW_HTML;
    for (slot, text) in
        [("{{TITLE}}", escape_html(title)), ("{{DATA}}", escape_json(data)), ("{{SCRIPT}}", script)]
    {
        let (head, tail) = rest.split_once(slot).unwrap_or((rest, ""));
        out.push_str(head);
        out.push_str(&text);
        rest = tail;
    }
    out.push_str(rest);
    out
}

/// An upper bound of the page's bytes for `poses` poses of 7 numbers, `rows` instants with
/// `hud` heads-up values each, and `text` bytes of names (bodies, outputs, units, frames,
/// loops, each escaped at worst six bytes per byte) and `items` drawn items (bodies, loops,
/// force elements, frames) of fixed size.
pub(crate) fn page_bound(poses: usize, rows: usize, hud: usize, text: usize, items: usize) -> u64 {
    let n = crate::budget::NUM;
    let m = |a: usize, b: u64| (a as u64).saturating_mul(b);
    fixed_bytes()
        .saturating_add(m(poses, 7 * n))
        .saturating_add(m(rows, (hud as u64 + 1) * n))
        .saturating_add(m(text, 6))
        .saturating_add(m(items, 40 * n))
        .saturating_add(4096)
}
