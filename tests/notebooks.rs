//! The notebooks in `docs/notebooks/` as tests (issue 11, item 2; issue 23, item 3).
//!
//! `tests/notebooks/generated.rs` holds one `#[test] fn notebook_<name>()` per notebook whose
//! body is that notebook's code cells in order, minus evcxr's `:dep` lines; `cargo test` thus
//! compiles and runs every notebook top to bottom. [`generated_code_is_current`] re-extracts
//! the cells from each `.ipynb` and fails when the checked-in extraction is stale; regenerate
//! it with `VECTRIX_BLESS=1 cargo test --test notebooks`.
//!
//! [`stored_outputs_are_present`] fails when a notebook's outputs are missing, so that readers of
//! the repository see results and figures without running anything (store them with
//! `scripts/notebooks.sh`).
//!
//! The `.ipynb` files are read with a small JSON reader below: only the `cells`, `cell_type`,
//! `source` and `outputs` (`output_type`, `data`) fields are used.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

include!("notebooks/generated.rs");

/// A JSON value, as far as nbformat needs it.
#[derive(Debug)]
enum Json {
    /// `true`, `false` or `null`.
    Literal,
    Number,
    Str(String),
    Array(Vec<Json>),
    Object(BTreeMap<String, Json>),
}

/// A recursive-descent reader for RFC 8259 JSON; `Err` names the byte offset of the fault.
struct Reader<'a> {
    s: &'a [u8],
    i: usize,
}

impl Reader<'_> {
    fn ws(&mut self) {
        while self.i < self.s.len() && matches!(self.s[self.i], b' ' | b'\n' | b'\r' | b'\t') {
            self.i += 1;
        }
    }

    fn eat(&mut self, b: u8) -> Result<(), String> {
        self.ws();
        if self.s.get(self.i) == Some(&b) {
            self.i += 1;
            Ok(())
        } else {
            Err(format!("expected '{}' at byte {}", b as char, self.i))
        }
    }

    fn value(&mut self) -> Result<Json, String> {
        self.ws();
        match self.s.get(self.i) {
            Some(b'{') => {
                self.i += 1;
                let mut m = BTreeMap::new();
                self.ws();
                if self.s.get(self.i) == Some(&b'}') {
                    self.i += 1;
                    return Ok(Json::Object(m));
                }
                loop {
                    self.ws();
                    let Json::Str(k) = self.value()? else {
                        return Err(format!("object key must be a string at byte {}", self.i));
                    };
                    self.eat(b':')?;
                    m.insert(k, self.value()?);
                    self.ws();
                    match self.s.get(self.i) {
                        Some(b',') => self.i += 1,
                        Some(b'}') => {
                            self.i += 1;
                            return Ok(Json::Object(m));
                        }
                        _ => return Err(format!("expected ',' or '}}' at byte {}", self.i)),
                    }
                }
            }
            Some(b'[') => {
                self.i += 1;
                let mut v = Vec::new();
                self.ws();
                if self.s.get(self.i) == Some(&b']') {
                    self.i += 1;
                    return Ok(Json::Array(v));
                }
                loop {
                    v.push(self.value()?);
                    self.ws();
                    match self.s.get(self.i) {
                        Some(b',') => self.i += 1,
                        Some(b']') => {
                            self.i += 1;
                            return Ok(Json::Array(v));
                        }
                        _ => return Err(format!("expected ',' or ']' at byte {}", self.i)),
                    }
                }
            }
            Some(b'"') => self.string().map(Json::Str),
            Some(b't') if self.s[self.i..].starts_with(b"true") => {
                self.i += 4;
                Ok(Json::Literal)
            }
            Some(b'f') if self.s[self.i..].starts_with(b"false") => {
                self.i += 5;
                Ok(Json::Literal)
            }
            Some(b'n') if self.s[self.i..].starts_with(b"null") => {
                self.i += 4;
                Ok(Json::Literal)
            }
            Some(b'-' | b'0'..=b'9') => {
                while self.i < self.s.len()
                    && matches!(self.s[self.i], b'-' | b'+' | b'.' | b'e' | b'E' | b'0'..=b'9')
                {
                    self.i += 1;
                }
                Ok(Json::Number)
            }
            _ => Err(format!("unexpected input at byte {}", self.i)),
        }
    }

    fn hex4(&mut self) -> Result<u32, String> {
        let h = self.s.get(self.i..self.i + 4).ok_or("truncated \\u escape")?;
        let h = std::str::from_utf8(h).map_err(|e| e.to_string())?;
        self.i += 4;
        u32::from_str_radix(h, 16).map_err(|e| format!("bad \\u escape {h}: {e}"))
    }

    fn string(&mut self) -> Result<String, String> {
        self.i += 1; // opening quote
        let mut out = Vec::new();
        loop {
            let b = *self.s.get(self.i).ok_or("unterminated string")?;
            self.i += 1;
            match b {
                b'"' => return String::from_utf8(out).map_err(|e| e.to_string()),
                b'\\' => {
                    let e = *self.s.get(self.i).ok_or("unterminated escape")?;
                    self.i += 1;
                    let c = match e {
                        b'"' => '"',
                        b'\\' => '\\',
                        b'/' => '/',
                        b'b' => '\u{8}',
                        b'f' => '\u{c}',
                        b'n' => '\n',
                        b'r' => '\r',
                        b't' => '\t',
                        b'u' => {
                            let mut u = self.hex4()?;
                            if (0xD800..0xDC00).contains(&u) && self.s[self.i..].starts_with(b"\\u") {
                                self.i += 2;
                                let lo = self.hex4()?;
                                u = 0x10000 + ((u - 0xD800) << 10) + (lo.wrapping_sub(0xDC00) & 0x3FF);
                            }
                            char::from_u32(u).ok_or(format!("invalid code point {u:#x}"))?
                        }
                        _ => return Err(format!("bad escape at byte {}", self.i)),
                    };
                    out.extend_from_slice(c.encode_utf8(&mut [0; 4]).as_bytes());
                }
                _ => out.push(b),
            }
        }
    }
}

fn parse(text: &str) -> Result<Json, String> {
    let mut r = Reader { s: text.as_bytes(), i: 0 };
    let v = r.value()?;
    r.ws();
    if r.i != r.s.len() {
        return Err(format!("trailing input at byte {}", r.i));
    }
    Ok(v)
}

fn field<'a>(j: &'a Json, k: &str) -> Option<&'a Json> {
    match j {
        Json::Object(m) => m.get(k),
        _ => None,
    }
}

/// One stored output of a code cell: its `output_type` and, for `display_data` and
/// `execute_result`, the MIME types of its `data`.
#[derive(Debug)]
struct Output {
    kind: String,
    mimes: Vec<String>,
}

/// A code cell: its `source` joined, and its stored outputs.
struct CodeCell {
    source: String,
    outputs: Vec<Output>,
}

/// The text of a `source` field (a string or an array of lines).
fn joined(j: Option<&Json>, what: &str) -> String {
    match j {
        Some(Json::Str(s)) => s.clone(),
        Some(Json::Array(lines)) => lines
            .iter()
            .map(|l| match l {
                Json::Str(s) => s.as_str(),
                _ => panic!("{what}: non-string source line"),
            })
            .collect(),
        _ => panic!("{what}: cell without source"),
    }
}

/// A notebook's code cells with their outputs, after checking the nbformat 4 header.
fn code_cells_with_outputs(path: &Path) -> Vec<CodeCell> {
    let text = fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let nb = parse(&text).unwrap_or_else(|e| panic!("{}: invalid JSON: {e}", path.display()));
    assert!(matches!(field(&nb, "nbformat"), Some(Json::Number)), "{}: nbformat", path.display());
    let kernel = field(&nb, "metadata").and_then(|m| field(m, "kernelspec")).and_then(|k| field(k, "name"));
    assert!(
        matches!(kernel, Some(Json::Str(n)) if n == "rust"),
        "{}: kernelspec must be evcxr's `rust`",
        path.display()
    );
    let Some(Json::Array(cells)) = field(&nb, "cells") else { panic!("{}: no cells", path.display()) };
    let what = path.display().to_string();
    let mut code = Vec::new();
    for cell in cells {
        let source = joined(field(cell, "source"), &what);
        if !matches!(field(cell, "cell_type"), Some(Json::Str(t)) if t == "code") {
            continue;
        }
        let outputs = match field(cell, "outputs") {
            Some(Json::Array(outs)) => outs
                .iter()
                .map(|o| Output {
                    kind: match field(o, "output_type") {
                        Some(Json::Str(k)) => k.clone(),
                        _ => panic!("{what}: output without output_type"),
                    },
                    mimes: match field(o, "data") {
                        Some(Json::Object(m)) => m.keys().cloned().collect(),
                        _ => Vec::new(),
                    },
                })
                .collect(),
            _ => Vec::new(),
        };
        code.push(CodeCell { source, outputs });
    }
    code
}

/// A notebook's code cells (each `source` joined).
fn code_cells(path: &Path) -> Vec<String> {
    code_cells_with_outputs(path).into_iter().map(|c| c.source).collect()
}

/// What a cell must have stored, by the rule of [`stored_outputs_are_present`]: `(prints, draws,
/// returns)`.
///
/// - *prints*: outside item definitions (a line at column 0 starting `fn`, `struct`, `impl`,
///   `enum` or `trait` opens one, the next line at column 0 starting with `}` closes it), a line
///   calls `println!`, `print!`, `eprintln!` or the notebooks' `show(` helper;
/// - *draws*: such a line calls `show(` or prints `EVCXR_BEGIN_CONTENT` (an SVG figure);
/// - *returns*: the cell's last line that is neither blank nor a `//` comment ends in neither
///   `;` nor `}` — evcxr displays the value of that trailing expression.
fn expectations(source: &str) -> (bool, bool, bool) {
    let (mut in_item, mut prints, mut draws) = (false, false, false);
    for line in source.lines() {
        let top = !line.starts_with([' ', '\t']);
        let word = line.trim_start_matches("pub ");
        if top && ["fn ", "struct ", "impl ", "impl<", "enum ", "trait "].iter().any(|k| word.starts_with(k))
        {
            in_item = !line.trim_end().ends_with('}') && !line.trim_end().ends_with(';');
            continue;
        }
        if in_item {
            if top && line.starts_with('}') {
                in_item = false;
            }
            continue;
        }
        let code = line.split("//").next().unwrap_or("");
        if ["println!", "print!", "eprintln!", "show("].iter().any(|m| code.contains(m)) {
            prints = true;
        }
        if code.contains("show(") || code.contains("EVCXR_BEGIN_CONTENT") {
            draws = true;
        }
    }
    let last = source
        .lines()
        .map(str::trim)
        .rfind(|l| !l.is_empty() && !l.starts_with("//") && !l.starts_with(':'))
        .unwrap_or("");
    let returns = !last.is_empty() && !last.ends_with(';') && !last.ends_with('}');
    (prints, draws, returns)
}

fn notebooks() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/notebooks");
    let mut v: Vec<PathBuf> = fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("readable directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "ipynb"))
        // the evcxr notebooks are `NN-topic.ipynb`; `python-tour.ipynb` runs on the Python
        // kernel and has its own test below
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.as_bytes()[..2].iter().all(u8::is_ascii_digit))
        })
        .collect();
    v.sort();
    v
}

/// `docs/notebooks/python-tour.ipynb` (issue 37), executed by the IPython kernel: every code
/// cell has stored outputs, none is an error, and the three figures (scene run, Bode plot,
/// sweep) are stored as PNG.
#[test]
fn python_tour_has_stored_outputs() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/notebooks/python-tour.ipynb");
    let text = fs::read_to_string(&path).expect("python-tour.ipynb");
    let nb = parse(&text).expect("valid JSON");
    let kernel = field(&nb, "metadata").and_then(|m| field(m, "kernelspec")).and_then(|k| field(k, "name"));
    assert!(matches!(kernel, Some(Json::Str(n)) if n == "python3"), "kernelspec must be python3");
    let Some(Json::Array(cells)) = field(&nb, "cells") else { panic!("no cells") };
    let mut pngs = 0;
    for (k, cell) in cells.iter().enumerate() {
        if !matches!(field(cell, "cell_type"), Some(Json::Str(t)) if t == "code") {
            continue;
        }
        let Some(Json::Array(outs)) = field(cell, "outputs") else { panic!("cell {k}: no outputs") };
        assert!(!outs.is_empty(), "cell {k}: no stored output");
        for o in outs {
            assert!(
                !matches!(field(o, "output_type"), Some(Json::Str(t)) if t == "error"),
                "cell {k}: error output"
            );
            if let Some(Json::Object(m)) = field(o, "data") {
                pngs += usize::from(m.contains_key("image/png"));
            }
        }
    }
    assert!(pngs >= 3, "{pngs} PNG figures; want the scene run, the Bode plot and the sweep");
}

/// The test function name for `docs/notebooks/03-rotations.ipynb`: `notebook_03_rotations`.
fn test_name(path: &Path) -> String {
    let stem = path.file_stem().and_then(|s| s.to_str()).expect("UTF-8 notebook name");
    let s: String =
        stem.chars().map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_lowercase() } else { '_' }).collect();
    format!("notebook_{s}")
}

/// The whole of `generated.rs` as extracted from the notebooks now.
fn generate() -> String {
    let mut out = String::from(
        "// @generated by tests/notebooks.rs from docs/notebooks/*.ipynb: do not edit.\n\
         // Regenerate with `VECTRIX_BLESS=1 cargo test --test notebooks`.\n",
    );
    for nb in notebooks() {
        out.push_str(&format!(
            "\n/// `docs/notebooks/{}`\n",
            nb.file_name().and_then(|s| s.to_str()).unwrap_or("?")
        ));
        out.push_str(&format!("#[test]\nfn {}() {{\n", test_name(&nb)));
        for (k, cell) in code_cells(&nb).iter().enumerate() {
            out.push_str(&format!("    // cell {}\n", k + 1));
            for line in cell.lines().filter(|l| !l.trim_start().starts_with(':')) {
                if line.is_empty() {
                    out.push('\n');
                } else {
                    out.push_str(&format!("    {line}\n"));
                }
            }
        }
        out.push_str("}\n");
    }
    out
}

/// The checked-in extraction matches the notebooks; bless with `VECTRIX_BLESS=1`.
#[test]
fn generated_code_is_current() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/notebooks/generated.rs");
    let want = generate();
    if std::env::var_os("VECTRIX_BLESS").is_some() {
        fs::write(&path, &want).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        return;
    }
    let got = fs::read_to_string(&path).unwrap_or_default();
    assert!(
        got == want,
        "tests/notebooks/generated.rs is stale: run `VECTRIX_BLESS=1 cargo test --test notebooks`"
    );
}

/// At least one notebook per chapter 2–16 (`02-…` to `16-…`, a chapter may have a second one
/// such as `15-units`), and no other; each opening with the lean `:dep` cell the
/// README promises (plus the `scene` feature in the notebooks that run scene files), with markdown citing the book's sections and at least one SVG figure.
#[test]
fn notebooks_are_guided_tours() {
    let list = notebooks();
    let chapters: Vec<String> = list
        .iter()
        .map(|p| p.file_name().and_then(|s| s.to_str()).unwrap_or("").chars().take(3).collect())
        .collect();
    let mut chapters = chapters;
    chapters.dedup();
    let want: Vec<String> = (2..=16).map(|c| format!("{c:02}-")).collect();
    assert_eq!(chapters, want, "at least one notebook per chapter 2–16, named NN-topic.ipynb, and no other");
    for nb in list {
        let cells = code_cells(&nb);
        let first = cells.first().map(String::as_str).unwrap_or("");
        // the lean dependency, or the lean one with scene files when the notebook runs a scene
        let lean = ":dep vectrix = { path = \"../..\", default-features = false }";
        let with_scenes =
            ":dep vectrix = { path = \"../..\", default-features = false, features = [\"scene\"] }";
        let runs_scenes = cells.iter().any(|c| c.contains("vectrix::scene") || c.contains("Scene::"));
        assert!(
            first.contains(if runs_scenes { with_scenes } else { lean }),
            "{}: first code cell must be the lean :dep (with `features = [\"scene\"]` exactly when a cell runs a scene)",
            nb.display()
        );
        let text = fs::read_to_string(&nb).unwrap_or_default();
        assert!(text.contains('§'), "{}: markdown must cite the book's sections", nb.display());
        assert!(cells.iter().any(|c| expectations(c).1), "{}: no SVG figure", nb.display());
    }
}

/// The outputs are stored, so that a reader sees them without running anything
/// (`scripts/notebooks.sh` executes the notebooks with the evcxr kernel and stores them). The
/// rule, per code cell (see [`expectations`]): a cell that prints has at least one `stream`,
/// `display_data` or `execute_result` output; a cell that draws has a `display_data` or
/// `execute_result` output with `image/svg+xml` (evcxr's form for printed content); a
/// cell that ends in an expression has an `execute_result` or a `display_data`; no cell has an
/// `error` output. A stored output that no longer matches an edited cell is not detected here:
/// re-run `scripts/notebooks.sh` after editing a notebook.
#[test]
fn stored_outputs_are_present() {
    let mut missing = Vec::new();
    for nb in notebooks() {
        for (k, cell) in code_cells_with_outputs(&nb).iter().enumerate() {
            let (prints, draws, returns) = expectations(&cell.source);
            let has = |kinds: &[&str]| cell.outputs.iter().any(|o| kinds.contains(&o.kind.as_str()));
            // evcxr turns printed EVCXR_BEGIN_CONTENT blocks into an `execute_result` (or a
            // `display_data`) carrying the SVG
            let svg = cell.outputs.iter().any(|o| {
                matches!(o.kind.as_str(), "display_data" | "execute_result")
                    && o.mimes.iter().any(|m| m == "image/svg+xml")
            });
            let name = format!("{} code cell {}", nb.display(), k + 1);
            if cell.outputs.iter().any(|o| o.kind == "error") {
                missing.push(format!("{name}: stored error output"));
            }
            if prints && !has(&["stream", "display_data", "execute_result"]) {
                missing.push(format!("{name}: prints but has no stored output"));
            }
            if draws && !svg {
                missing.push(format!("{name}: draws but has no stored image/svg+xml"));
            }
            if returns && !has(&["execute_result", "display_data"]) {
                missing.push(format!("{name}: ends in an expression but has no stored result"));
            }
        }
    }
    assert!(missing.is_empty(), "run scripts/notebooks.sh:\n{}", missing.join("\n"));
}

/// Issue 36: the chapter 7, 9 and 14 notebooks show a run's 3-D view inline — a code cell that
/// opens the run's `view.html` with `vectrix_cli::View` and displays it, with the HTML stored
/// (evcxr's `text/html` result), so that a reader sees the view without running anything.
#[test]
fn chapters_7_9_14_show_a_view_inline() {
    for name in ["07-dynamics", "09-lagrange", "14-flight-modes"] {
        let nb = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("docs/notebooks/{name}.ipynb"));
        let cells = code_cells_with_outputs(&nb);
        let view = cells
            .iter()
            .find(|c| c.source.contains("View::open") && c.source.contains("evcxr_display()"))
            .unwrap_or_else(|| panic!("{name}: no cell shows a view"));
        assert!(
            view.outputs.iter().any(|o| o.mimes.iter().any(|m| m == "text/html")),
            "{name}: the view cell has no stored text/html"
        );
    }
}

/// The rule of [`stored_outputs_are_present`] on small cells.
#[test]
fn output_expectations_rule() {
    assert_eq!(expectations("let x = 1;\nprintln!(\"{x}\");"), (true, false, false));
    assert_eq!(
        expectations("fn show(svg: String) {\n    println!(\"EVCXR_BEGIN_CONTENT {svg}\");\n}"),
        (false, false, false)
    );
    assert_eq!(expectations("fn f() {}\nshow(svg);"), (true, true, false));
    assert_eq!(expectations("for k in 0..3 {\n    println!(\"{k}\");\n}"), (true, false, false));
    assert_eq!(expectations("let x = 2;\nx + 1"), (false, false, true));
    assert_eq!(expectations("use a::b;\n// println!(\"no\")"), (false, false, false));
    assert_eq!(expectations(":dep vectrix = { path = \"../..\" }"), (false, false, false));
}

/// The JSON reader itself, on the escapes nbformat writers emit.
#[test]
fn json_reader_handles_escapes() {
    let j = parse(r#"{"a": ["x\n", "\u00a7 \ud835\udc9e \"q\""], "b": [1, -2.5e3, true, null, {}]}"#)
        .expect("valid JSON");
    let Some(Json::Array(a)) = field(&j, "a") else { panic!("array") };
    assert!(matches!(&a[1], Json::Str(s) if s == "§ 𝒞 \"q\""));
    assert!(parse("[1, 2").is_err() && parse("{\"a\" 1}").is_err() && parse("[] x").is_err());
}
