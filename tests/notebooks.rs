//! The notebooks in `docs/notebooks/` as tests (issue 11, item 2).
//!
//! `tests/notebooks/generated.rs` holds one `#[test] fn notebook_<name>()` per notebook whose
//! body is that notebook's code cells in order, minus evcxr's `:dep` lines; `cargo test` thus
//! compiles and runs every notebook top to bottom. [`generated_code_is_current`] re-extracts
//! the cells from each `.ipynb` and fails when the checked-in extraction is stale; regenerate
//! it with `VECTRIX_BLESS=1 cargo test --test notebooks`.
//!
//! The `.ipynb` files are read with a small JSON reader below (the root package has no JSON
//! dependency): only the `cells`, `cell_type` and `source` fields are used.

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

/// A notebook's code cells (each `source` joined), after checking the nbformat 4 header.
fn code_cells(path: &Path) -> Vec<String> {
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
    let mut code = Vec::new();
    for cell in cells {
        let src = match field(cell, "source") {
            Some(Json::Str(s)) => s.clone(),
            Some(Json::Array(lines)) => lines
                .iter()
                .map(|l| match l {
                    Json::Str(s) => s.as_str(),
                    _ => panic!("{}: non-string source line", path.display()),
                })
                .collect(),
            _ => panic!("{}: cell without source", path.display()),
        };
        if matches!(field(cell, "cell_type"), Some(Json::Str(t)) if t == "code") {
            code.push(src);
        }
    }
    code
}

fn notebooks() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/notebooks");
    let mut v: Vec<PathBuf> = fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("readable directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "ipynb"))
        .collect();
    v.sort();
    v
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

/// Every notebook opens with the `:dep` cell the README promises and has markdown citing the book.
#[test]
fn notebooks_are_guided_tours() {
    let list = notebooks();
    assert!(list.len() >= 3, "expected one notebook per chapter, found {}", list.len());
    for nb in list {
        let cells = code_cells(&nb);
        let first = cells.first().map(String::as_str).unwrap_or("");
        assert!(
            first.contains(":dep vectrix = { path = \"../..\", default-features = false }"),
            "{}: first code cell must be the :dep",
            nb.display()
        );
        let text = fs::read_to_string(&nb).unwrap_or_default();
        assert!(text.contains('§'), "{}: markdown must cite the book's sections", nb.display());
        assert!(text.contains("EVCXR_BEGIN_CONTENT image/svg+xml"), "{}: no inline SVG figure", nb.display());
    }
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
