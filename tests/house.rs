//! House rules on the source of the library crates (issue 38, item 3), so that the house stays
//! clean once it is clean:
//!
//! - **no import circle**: within a crate, the modules form no cycle of references;
//! - **no file over 500 lines** under `crates/` (generated coefficient tables aside);
//! - **no function over 100 lines** (from the line of `fn` to its closing brace).
//!
//! A module is one file (`src/a/b.rs` and `src/a/b/mod.rs` are `a::b`). Module m references
//! module c when m's code (comments, literals and `#[cfg(test)]` items aside) names a path
//! `crate::c::…` or `super::…` that resolves into c (the longest prefix that is a module; `use`
//! groups expanded, `super` taken from the inline `mod x { … }` the path sits in). A reference
//! to m itself or to one of its ancestors is not an edge, and neither are the relative paths
//! down into m's own children (`self::x`, `child::x`): a parent declares and re-exports its
//! children, so only references across branches can close a cycle, and a re-exporting parent
//! (`explicit` for `crate::explicit::Solution`) is where such a path ends. The circles are the strongly
//! connected sets of that graph (Tarjan).
//!
//! The checker is plain Rust over the source text (the small lexer in `tests/house/lexer.rs`),
//! so `cargo test` needs no Python; its own behaviour is pinned by the synthetic crates in the
//! `checker_*` tests.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

#[path = "house/lexer.rs"]
mod lexer;
use lexer::{Tok, Token, lex};

/// Generated coefficient tables may be long (file length only): a file whose name ends so.
const GENERATED_TABLE_SUFFIX: &str = "_coefficients.rs";
/// Longest file, in lines (`wc -l`).
const MAX_FILE_LINES: usize = 500;
/// Longest function, in lines from `fn` to its closing brace.
const MAX_FN_LINES: usize = 100;

#[test]
fn crates_have_no_import_circles() {
    let mut found = Vec::new();
    for krate in checked_crates() {
        let src = root().join("crates").join(&krate).join("src");
        let mut files = Vec::new();
        rs_files(&src, &mut files);
        let modules: Vec<(String, String)> =
            files.iter().map(|f| (module_name(&src, f), fs::read_to_string(f).unwrap_or_default())).collect();
        for circle in circles(&modules) {
            found.push(format!("{krate}: {}", circle.join(" ↔ ")));
        }
    }
    assert!(
        found.is_empty(),
        "import circles (move the shared item to a module below both, or a new small module both use):\n{}",
        found.join("\n")
    );
}

#[test]
fn crates_have_no_long_files_or_functions() {
    let mut found = Vec::new();
    for krate in checked_crates() {
        let mut files = Vec::new();
        rs_files(&root().join("crates").join(&krate), &mut files);
        files.sort();
        for f in files {
            let rel = f.strip_prefix(root()).unwrap_or(&f).to_string_lossy().replace('\\', "/");
            let text = fs::read_to_string(&f).unwrap_or_default();
            let lines = text.matches('\n').count();
            if lines > MAX_FILE_LINES && !rel.ends_with(GENERATED_TABLE_SUFFIX) {
                found.push(format!("{rel}: {lines} lines (> {MAX_FILE_LINES}): split it by verb"));
            }
            for (name, line, len) in long_functions(&text) {
                found.push(format!("{rel}:{line}: fn {name} is {len} lines (> {MAX_FN_LINES})"));
            }
        }
    }
    assert!(found.is_empty(), "too long:\n{}", found.join("\n"));
}

/// The checker finds a circle through `crate::`, `super::` (from an inline module too) and
/// `use` groups, and none where the references sit in comments, literals or test modules.
#[test]
fn checker_finds_circles_and_only_circles() {
    let m = |name: &str, src: &str| (name.to_string(), src.to_string());
    // a → b (use group), b → c::d (super:: from an inline module), c::d → a (crate::)
    let cyclic = [
        m("", "mod a; mod b; mod c;"),
        m("a", "use crate::{b::Thing, x};\nfn f() {}"),
        m("b", "pub struct Thing;\nmod inner { fn g() { super::super::c::d::h(); } }"),
        m("c", "mod d;"),
        m("c::d", "pub fn h() { let _ = crate::a::f; }"),
    ];
    assert_eq!(circles(&cyclic), [vec!["a".to_string(), "b".into(), "c::d".into()]]);
    // a parent naming its child and the child naming its parent is no circle; neither are
    // references in comments, strings, char literals or #[cfg(test)] items
    let acyclic = [
        m("", "mod a; mod b;"),
        m(
            "a",
            "mod kid;\nuse kid::K;\n// crate::b::x\nconst S: &str = \"crate::b::x\";\nconst C: char = '\"';",
        ),
        m("a::kid", "pub struct K;\nuse super::super::a::f;"),
        m("b", "use crate::a::kid::K;\n#[cfg(test)]\nmod tests { use crate::a::x; }\n/* crate::a */"),
    ];
    assert_eq!(circles(&acyclic), Vec::<Vec<String>>::new());
    // and the same graph with b → a and a → b closes one
    let two = [m("a", "fn f() { crate::b::g(); }"), m("b", "use super::a::f;")];
    assert_eq!(circles(&two), [vec!["a".to_string(), "b".into()]]);
}

/// The function-length scan counts from `fn` to the closing brace, skips declarations without
/// a body and is not fooled by braces in literals and comments.
#[test]
fn checker_measures_functions() {
    let body = "    let x = 1;\n".repeat(MAX_FN_LINES - 2);
    let long = format!("fn long() {{\n{body}}}\n");
    assert_eq!(long_functions(&long), Vec::<(String, usize, usize)>::new());
    let too_long = format!(
        "// {{\ntrait T {{ fn decl(&self); }}\npub(crate) fn long() {{\n    let s = \"}}\";\n{body}}}\n"
    );
    assert_eq!(long_functions(&too_long), [("long".to_string(), 3, MAX_FN_LINES + 1)]);
}

/// The crates under `crates/` (every one: the house rules have no exemptions).
fn checked_crates() -> Vec<String> {
    let mut out: Vec<String> = fs::read_dir(root().join("crates"))
        .expect("crates/ exists")
        .filter_map(|e| e.ok())
        .filter(|e| e.path().join("src").is_dir())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    out.sort();
    assert!(out.len() >= 5, "expected the library crates under crates/, found {out:?}");
    out
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn rs_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            rs_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// `src/a/b.rs` and `src/a/b/mod.rs` → `a::b`; `src/lib.rs` → `` (the crate root).
fn module_name(src: &Path, file: &Path) -> String {
    let rel = file.strip_prefix(src).unwrap_or(file).with_extension("");
    let mut parts: Vec<String> =
        rel.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
    if parts.last().is_some_and(|l| l == "mod" || l == "lib" || l == "main") {
        parts.pop();
    }
    parts.join("::")
}

/// The import circles of one crate given as (module name, source) pairs: each strongly
/// connected set of two or more modules, sorted, in a sorted list.
fn circles(modules: &[(String, String)]) -> Vec<Vec<String>> {
    let names: BTreeSet<String> = modules.iter().map(|(m, _)| m.clone()).collect();
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (m, src) in modules {
        let targets = references(m, &lex(src), &names);
        edges.insert(m.clone(), targets);
    }
    let mut out = lexer::strongly_connected(&edges);
    out.retain(|c| c.len() > 1);
    out.sort();
    out
}

/// The modules that module `m` references (see the file's documentation).
fn references(m: &str, toks: &[Token], names: &BTreeSet<String>) -> BTreeSet<String> {
    let toks = lexer::without_test_items(toks);
    let split = |s: &str| -> Vec<String> {
        if s.is_empty() { Vec::new() } else { s.split("::").map(str::to_string).collect() }
    };
    let here = split(m);
    // the module each token is in: the file's module plus the inline `mod x { … }` around it
    let scopes = lexer::inline_scopes(&toks, &here);
    let mut out = BTreeSet::new();
    let mut i = 0;
    while i < toks.len() {
        let at_path_start =
            i < 2 || !(toks[i - 1].tok == Tok::Punct(':') && toks[i - 2].tok == Tok::Punct(':'));
        if at_path_start && let Tok::Ident(first) = &toks[i].tok {
            let base: Option<Vec<String>> = match first.as_str() {
                "crate" => Some(Vec::new()),
                "super" => Some(scopes[i].clone()),
                _ => None,
            };
            if let Some(base) = base
                && lexer::is_path_sep(&toks, i + 1)
            {
                let (paths, next) = lexer::path_tree(&toks, i, base);
                for p in paths {
                    if let Some(target) = resolve(&p, names)
                        && target != m
                        && !m.starts_with(&format!("{target}::"))
                    {
                        out.insert(target);
                    }
                }
                i = next;
                continue;
            }
        }
        i += 1;
    }
    out
}

/// The longest prefix of an absolute path that is a module (never the crate root).
fn resolve(path: &[String], names: &BTreeSet<String>) -> Option<String> {
    (1..=path.len()).rev().map(|k| path[..k].join("::")).find(|c| names.contains(c))
}

/// Functions longer than [`MAX_FN_LINES`]: (name, line of `fn`, lines).
fn long_functions(src: &str) -> Vec<(String, usize, usize)> {
    let toks = lex(src);
    let mut out = Vec::new();
    for (i, t) in toks.iter().enumerate() {
        if t.tok != Tok::Ident("fn".into()) {
            continue;
        }
        let Some(Token { tok: Tok::Ident(name), .. }) = toks.get(i + 1) else { continue };
        // the body: the first `{` before any `;` (a declaration has none)
        let Some(open) = toks[i..].iter().position(|t| t.tok == Tok::Punct('{') || t.tok == Tok::Punct(';'))
        else {
            continue;
        };
        if toks[i + open].tok == Tok::Punct(';') {
            continue;
        }
        let Some(close) = lexer::matching(&toks, i + open) else { continue };
        let len = toks[close].line - t.line + 1;
        if len > MAX_FN_LINES {
            out.push((name.clone(), t.line, len));
        }
    }
    out
}
