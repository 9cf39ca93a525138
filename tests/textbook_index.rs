//! The executable-textbook index: `docs/textbook.md` maps every section of the book to the
//! tests that execute it. Its tables are generated from the test sources, so this test
//! checks two things: every test file and test the page names exists, and the page is current.
//!
//! Regenerate after adding tests: `VECTRIX_BLESS=1 cargo test --test textbook_index`.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

const BEGIN: &str = "<!-- BEGIN GENERATED: tests/textbook_index.rs -->";
const END: &str = "<!-- END GENERATED -->";
/// Test-name prefixes that carry a book tag `kind_chapter_section_...`.
const KINDS: [&str; 13] = [
    "fact",
    "example",
    "problem",
    "eq",
    "sec",
    "section",
    "definition",
    "remark",
    "table",
    "figure",
    "erratum",
    "p",
    "ex",
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The source files of one test binary: its root file and every module it loads by `mod x;` or
/// `#[path = "..."] mod x;`, recursively.
fn module_files(file: &Path, out: &mut Vec<PathBuf>) {
    let Ok(src) = fs::read_to_string(file) else { return };
    out.push(file.to_path_buf());
    let dir = file.parent().unwrap_or(Path::new("."));
    let stem = file.file_stem().and_then(|s| s.to_str()).unwrap_or("");
    let is_root = file.parent().map(|p| p.ends_with("tests")).unwrap_or(false);
    let mut pending_path: Option<String> = None;
    for line in src.lines() {
        let t = line.trim();
        if let Some(rest) = t.strip_prefix("#[path = \"") {
            pending_path = rest.split('"').next().map(str::to_owned);
            continue;
        }
        let decl = t.strip_prefix("pub ").unwrap_or(t);
        if let Some(name) = decl.strip_prefix("mod ").and_then(|r| r.strip_suffix(';')) {
            let next = match pending_path.take() {
                Some(p) => dir.join(p),
                None if is_root || stem == "mod" => dir.join(format!("{name}.rs")),
                None => dir.join(stem).join(format!("{name}.rs")),
            };
            let next = if next.exists() { next } else { next.with_extension("").join("mod.rs") };
            if !out.contains(&next) {
                module_files(&next, out);
            }
        } else if !t.starts_with("#[") {
            pending_path = None;
        }
    }
}

/// Names of the `#[test]` functions (plain and inside `proptest!`) in a source file.
fn test_names(src: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut armed = false;
    for line in src.lines() {
        let t = line.trim();
        if t.starts_with("#[test]") {
            armed = true;
        }
        if armed && let Some(pos) = t.find("fn ") {
            let rest = &t[pos + 3..];
            let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            if !name.is_empty() {
                names.push(name);
                armed = false;
            }
        }
    }
    names
}

/// Every test binary (file stem) and its test names.
fn collect() -> BTreeMap<String, Vec<String>> {
    let mut map = BTreeMap::new();
    let mut files: Vec<PathBuf> = fs::read_dir(root().join("tests"))
        .expect("tests/ exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .collect();
    files.sort();
    for f in files {
        let mut srcs = Vec::new();
        module_files(&f, &mut srcs);
        let mut names = Vec::new();
        for s in srcs {
            names.extend(test_names(&fs::read_to_string(&s).unwrap_or_default()));
        }
        let stem = f.file_stem().and_then(|s| s.to_str()).unwrap_or_default().to_owned();
        map.insert(stem, names);
    }
    map
}

/// The book section (chapter, section) a test name is tagged with, if any.
fn section_of(name: &str) -> Option<(u32, u32)> {
    let mut parts = name.split('_');
    let kind = parts.next()?;
    if !KINDS.contains(&kind) {
        return None;
    }
    let ch = parts.next()?.parse().ok()?;
    let sec = parts.next()?.parse().ok()?;
    Some((ch, sec))
}

fn titles() -> BTreeMap<(u32, u32), String> {
    include_str!("textbook/sections.txt")
        .lines()
        .filter_map(|l| {
            let (num, title) = l.split_once(' ')?;
            let (c, s) = num.split_once('.')?;
            Some(((c.parse().ok()?, s.parse().ok()?), title.trim().to_owned()))
        })
        .collect()
}

fn generate() -> String {
    let tests = collect();
    let titles = titles();
    let mut by_sec: BTreeMap<(u32, u32), BTreeMap<String, Vec<String>>> = BTreeMap::new();
    let mut untagged: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for (file, names) in &tests {
        for n in names {
            match section_of(n) {
                Some(s) => by_sec.entry(s).or_default().entry(file.clone()).or_default().push(n.clone()),
                None => untagged.entry(file.clone()).or_default().push(n.clone()),
            }
        }
    }
    let total: usize = tests.values().map(Vec::len).sum();
    let tagged: usize = by_sec.values().flat_map(|m| m.values()).map(Vec::len).sum();
    let mut out = String::new();
    out.push_str(BEGIN);
    out.push('\n');
    out.push_str(&format!(
        "\n{total} tests in {} files; {tagged} carry a book tag.\n",
        tests.values().filter(|v| !v.is_empty()).count()
    ));
    let chapters: BTreeSet<u32> = titles.keys().map(|k| k.0).chain(by_sec.keys().map(|k| k.0)).collect();
    for ch in chapters {
        let secs: Vec<_> =
            titles.keys().filter(|k| k.0 == ch).chain(by_sec.keys().filter(|k| k.0 == ch)).collect();
        let secs: BTreeSet<_> = secs.into_iter().copied().collect();
        let count: usize =
            secs.iter().filter_map(|s| by_sec.get(s)).flat_map(|m| m.values()).map(Vec::len).sum();
        out.push_str(&format!("\n### Chapter {ch} ({count} tagged tests)\n\n| § | section | tests | count |\n|---|---|---|---|\n"));
        for s in secs {
            let title = titles.get(&s).map(String::as_str).unwrap_or("(problems and examples)");
            let (cell, n) = match by_sec.get(&s) {
                Some(files) => {
                    let n = files.values().map(Vec::len).sum::<usize>();
                    let cell = files
                        .iter()
                        .map(|(f, ns)| {
                            let list: Vec<String> = ns.iter().map(|n| format!("`{n}`")).collect();
                            format!("`{f}`: {}", list.join(", "))
                        })
                        .collect::<Vec<_>>()
                        .join("; ");
                    (cell, n)
                }
                None => ("—".to_owned(), 0),
            };
            out.push_str(&format!("| {}.{} | {title} | {cell} | {n} |\n", s.0, s.1));
        }
    }
    out.push_str("\n### Property tests, hard cases and other tests, by file\n\n| file | tests | count |\n|---|---|---|\n");
    for (file, names) in &untagged {
        let list: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
        out.push_str(&format!("| `{file}` | {} | {} |\n", list.join(", "), names.len()));
    }
    out.push('\n');
    out.push_str(END);
    out
}

#[test]
fn textbook_index_is_current_and_names_only_existing_tests() {
    let path = root().join("docs/textbook.md");
    let page = fs::read_to_string(&path).expect("docs/textbook.md exists");
    let (head, rest) = page.split_once(BEGIN).expect("docs/textbook.md has the BEGIN GENERATED marker");
    let (_, tail) = rest.split_once(END).expect("docs/textbook.md has the END GENERATED marker");
    let fresh = generate();
    let want = format!("{head}{fresh}{tail}");
    if std::env::var_os("VECTRIX_BLESS").is_some() {
        fs::write(&path, &want).expect("write docs/textbook.md");
        return;
    }
    // Every `file`: `test` the page names exists in the sources.
    let tests = collect();
    for line in rest.lines().filter(|l| l.starts_with("| ")) {
        for cell in line.split("; ") {
            let ticks: Vec<&str> = cell.split('`').skip(1).step_by(2).collect();
            if let Some((file, names)) = ticks.split_first()
                && let Some(known) = tests.get(*file)
            {
                for n in names {
                    assert!(
                        known.iter().any(|k| k == n),
                        "docs/textbook.md names {file}::{n}, which does not exist"
                    );
                }
            }
        }
    }
    assert!(
        page == want,
        "docs/textbook.md is out of date with the tests: run `VECTRIX_BLESS=1 cargo test --test textbook_index`"
    );
}

#[test]
fn section_tags_parse_the_book_numbering() {
    assert_eq!(section_of("fact_2_11_5_half_turn"), Some((2, 11)));
    assert_eq!(section_of("example_4_19_2_slotted_arm"), Some((4, 19)));
    assert_eq!(section_of("problem_6_14_8_box_inertia"), Some((6, 14)));
    assert_eq!(section_of("round_trip_near_pi"), None);
    assert_eq!(
        titles().get(&(2, 11)).map(String::as_str),
        Some("Eigenaxis Rotations and Rodrigues's Formula")
    );
}
