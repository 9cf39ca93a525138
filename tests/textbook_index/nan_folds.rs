//! Worst-error folds that fail on NaN (issue 38, item 6): the NaN-aware helpers of
//! `tests/support`, and a source scan that refuses the NaN-blind forms in the test sources and
//! in the code cells of the notebooks (`docs/notebooks/NN-*.ipynb`).

use std::fs;
use std::path::{Path, PathBuf};

use super::root;

/// The NaN-aware folds of `tests/support` give NaN wherever a NaN enters, first, middle or last,
/// while the forms they replace drop it (which is why [`nan_blind_folds_are_refused`] exists).
#[test]
fn nan_folds_fail_on_nan() {
    use crate::support::{NanAmax, nan_max, nan_min};
    use vectrix::nalgebra::{DVector, Vector3};
    let nan = f64::NAN;
    for v in [[nan, 1.0, 2.0], [1.0, nan, 2.0], [1.0, 2.0, nan]] {
        assert!(v.iter().copied().fold(0.0, nan_max).is_nan(), "{v:?}");
        assert!(v.iter().copied().fold(f64::INFINITY, nan_min).is_nan(), "{v:?}");
        assert!(Vector3::from(v).nan_amax().is_nan(), "{v:?}");
    }
    // the NaN-blind forms: f64::max drops a NaN anywhere, amax all but a last one
    assert_eq!([nan, 1.0, 2.0].iter().copied().fold(0.0, f64::max), 2.0);
    assert_eq!(Vector3::new(nan, 1.0, 2.0).amax(), 2.0);
    // otherwise the same values: the largest |entry|, 0 for an empty vector
    assert_eq!(Vector3::new(-3.0, 1.0, 2.0).nan_amax(), 3.0);
    assert_eq!(DVector::<f64>::zeros(0).nan_amax(), 0.0);
    assert_eq!([1.0, -4.0].iter().copied().fold(f64::NEG_INFINITY, nan_max), 1.0);
}

/// The marker that allows a NaN-blind fold on its line or the line below, followed by the
/// reason: `// nan-blind-ok: <why a NaN cannot reach this fold or should be ignored>`.
const NAN_BLIND_OK: &str = "nan-blind-ok:";

/// Every test source under `dir` (recursively).
fn rs_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    for e in entries.filter_map(Result::ok) {
        let p = e.path();
        if p.is_dir() {
            rs_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The arguments of a call whose opening parenthesis has just been read: the text up to the
/// matching `)` (parentheses counted, strings not parsed).
fn call_args(rest: &str) -> &str {
    let mut depth = 1;
    for (i, c) in rest.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            _ => {}
        }
        if depth == 0 {
            return &rest[..i];
        }
    }
    rest
}

/// True if `text` contains `word` not followed by an identifier character (`f64::max` but not
/// `f64::max_value`).
fn has_path(text: &str, word: &str) -> bool {
    text.match_indices(word)
        .any(|(i, _)| !text[i + word.len()..].starts_with(|c: char| c.is_alphanumeric() || c == '_'))
}

/// True for an accumulator `x = x.max(…)` or `x = x.min(…)` (also `*x = x.max(…)`).
fn is_accumulator(line: &str) -> bool {
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    [".max(", ".min("].iter().any(|call| {
        line.match_indices(call).any(|(i, _)| {
            let before = &line[..i];
            let name = &before[before.trim_end_matches(ident).len()..];
            let Some(lhs) = before[..before.len() - name.len()].trim_end().strip_suffix('=') else {
                return false;
            };
            // a plain assignment, not a comparison or a compound operator
            let lhs = lhs.trim_end();
            !name.is_empty()
                && !lhs.ends_with(['=', '<', '>', '!', '+', '-', '*', '/', '%', '&', '|', '^'])
                && lhs.strip_suffix(name).is_some_and(|l| !l.ends_with(ident))
        })
    })
}

/// The NaN-blind folds of one source, as (1-based line, what to use instead); comments are
/// not code, and a line carrying [`NAN_BLIND_OK`] (or below one that does) is allowed.
fn nan_blind_folds(src: &str) -> Vec<(usize, &'static str)> {
    let raw: Vec<&str> = src.lines().collect();
    let code: Vec<&str> = raw.iter().map(|l| l.split("//").next().unwrap_or("")).collect();
    let mut found = Vec::new();
    for (i, l) in code.iter().enumerate() {
        if l.contains(".amax()") {
            found.push((i, "nalgebra's `amax` drops NaN unless it is last: use `nan_amax()`"));
        }
        if has_path(l, "f64::max") || has_path(l, "f64::min") {
            found.push((i, "`f64::max`/`f64::min` drop NaN: use `nan_max`/`nan_min`"));
        }
        if is_accumulator(l) {
            found.push((i, "`x = x.max(e)` drops a NaN e: use `x = nan_max(x, e)`"));
        }
    }
    // `.fold(…)` whose arguments call `.max(` or `.min(`, over as many lines as the call takes
    let text = code.join("\n");
    for (pos, call) in text.match_indices(".fold(") {
        let args = call_args(&text[pos + call.len()..]);
        if args.contains(".max(") || args.contains(".min(") {
            let line = text[..pos].matches('\n').count();
            found.push((line, "a fold with `.max(`/`.min(` drops NaN: use `nan_max`/`nan_min`"));
        }
    }
    let allowed = |i: usize| raw[i].contains(NAN_BLIND_OK) || (i > 0 && raw[i - 1].contains(NAN_BLIND_OK));
    found.retain(|&(i, _)| !allowed(i));
    found.sort();
    found.into_iter().map(|(i, what)| (i + 1, what)).collect()
}

/// Worst-error folds fail on NaN (issue 38 item 6): no test source under `tests/` (this file
/// aside) and no code cell of the evcxr notebooks `docs/notebooks/NN-*.ipynb` folds a worst
/// error, a scale or an extreme with a form that drops NaN, so that `worst <= tol` cannot pass
/// with a NaN inside.
///
/// The check is by pattern, line by line with comments removed; it refuses
/// - `.amax()` (nalgebra keeps a NaN only when it is the last entry): use `.nan_amax()`;
/// - the paths `f64::max` and `f64::min` (`.fold(0.0, f64::max)`): use `nan_max`, `nan_min`;
/// - `.fold(…)` whose arguments call `.max(` or `.min(` (`|m, x| m.max(x)`): use `nan_max`;
/// - an accumulator `worst = worst.max(err)`: use `worst = nan_max(worst, err)`.
///
/// A `.max(` outside a fold (`tol * scale.max(1.0)`) is not a worst-error fold and is not
/// checked. A justified NaN-blind use carries `// nan-blind-ok: <reason>` on its line or the
/// line above. The notebooks have no test helpers: each defines its own `fn nan_max` where it
/// needs one, or checks `m.iter().all(|e| e.abs() < tol)`, which fails on NaN. They are read
/// from the `.ipynb` files themselves (cells numbered as `tests/notebooks.rs` numbers them), so
/// their extraction `tests/notebooks/generated.rs` is not scanned twice.
#[test]
fn nan_blind_folds_are_refused() {
    // the scanner itself: each refused form, and the marker
    let sample = "let w = v.iter().fold(0.0, f64::max);\nlet e = (a - b).amax();\n\
                  let s = x.iter().fold(0.0f64, |m, c| {\n    m.max(c.abs())\n});\n\
                  worst = worst.max(e);\nok = tol * s.max(1.0) <= worst.max_abs;\n\
                  // nan-blind-ok: a comment that names .amax() and f64::max is not code\n\
                  let t = u.iter().fold(0.0, f64::max); // nan-blind-ok: u is finite by construction\n\
                  let m = nan_max(worst, e.nan_amax()) <= scale.max(tol);";
    let lines: Vec<usize> = nan_blind_folds(sample).iter().map(|&(l, _)| l).collect();
    assert_eq!(lines, [1, 2, 3, 6], "{:?}", nan_blind_folds(sample));
    let mut found = Vec::new();
    let mut files = Vec::new();
    rs_files(&root().join("tests"), &mut files);
    files.sort();
    for f in files {
        let rel = f.strip_prefix(root()).unwrap_or(&f).to_string_lossy().replace('\\', "/");
        let skipped =
            ["tests/textbook_index.rs", "tests/textbook_index/nan_folds.rs", "tests/notebooks/generated.rs"];
        if skipped.contains(&rel.as_str()) {
            continue;
        }
        let src = fs::read_to_string(&f).unwrap_or_default();
        found.extend(nan_blind_folds(&src).into_iter().map(|(line, what)| format!("{rel}:{line}: {what}")));
    }
    let cells = notebook_code_cells();
    assert!(cells.len() > 100, "only {} notebook code cells found: is docs/notebooks there?", cells.len());
    for (cell, src) in cells {
        found.extend(
            nan_blind_folds(&src).into_iter().map(|(line, what)| format!("{cell}, line {line}: {what}")),
        );
    }
    assert!(
        found.is_empty(),
        "NaN-blind worst-error folds (see tests/support: nan_max, nan_min, NanAmax):\n{}",
        found.join("\n")
    );
}

/// The code cells of the evcxr notebooks `docs/notebooks/NN-*.ipynb` (the Python tour aside),
/// each as ("docs/notebooks/<file> code cell <k>", its source), k counted from 1 over the code
/// cells as in `tests/notebooks.rs`.
fn notebook_code_cells() -> Vec<(String, String)> {
    let dir = root().join("docs/notebooks");
    let mut books: Vec<PathBuf> = fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ipynb"))
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with(|c: char| c.is_ascii_digit()))
        })
        .collect();
    books.sort();
    let mut out = Vec::new();
    for nb in books {
        let name = nb.file_name().and_then(|n| n.to_str()).unwrap_or("?").to_string();
        let text = fs::read_to_string(&nb).unwrap_or_else(|e| panic!("{name}: {e}"));
        let json: serde_json::Value =
            serde_json::from_str(&text).unwrap_or_else(|e| panic!("{name}: invalid JSON: {e}"));
        let cells = json["cells"].as_array().unwrap_or_else(|| panic!("{name}: no cells"));
        for (k, cell) in cells.iter().filter(|c| c["cell_type"] == "code").enumerate() {
            let source = match &cell["source"] {
                serde_json::Value::String(s) => s.clone(),
                serde_json::Value::Array(lines) => lines.iter().filter_map(|l| l.as_str()).collect(),
                _ => panic!("{name} code cell {}: no source", k + 1),
            };
            out.push((format!("docs/notebooks/{name} code cell {}", k + 1), source));
        }
    }
    out
}
