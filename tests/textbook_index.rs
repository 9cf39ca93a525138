//! The executable-textbook index: `docs/textbook.md` maps every section, example and problem of
//! the book to the tests that execute it. Its tables are generated from the test sources, so
//! this test checks two things: every test file and test the page names exists, and the page is
//! current.
//!
//! Regenerate after adding tests: `VECTRIX_BLESS=1 cargo test --test textbook_index`.
//!
//! # Tag grammar
//!
//! A test name carries book tags anywhere in it. A tag is a kind word followed by at least two
//! numbers, chapter and section, then optionally the item numbers:
//!
//! - kinds: `section` (or `sec`), `fact`, `eq`, `example`, `problem`, `erratum`, `definition`
//!   (or `def`), `remark`, `figure` (or `fig`); plurals (`facts`, `problems`, …) read the same.
//!   `table_14_1` is a chapter-numbered table and credits no section.
//! - `problem_6_14_8_box_inertia` → Problem 6.14.8 (and §6.14);
//!   `section_14_7_3_…` → §14.7 (item 3 of it).
//! - several items of one section: `problem_15_20_15_16_…` → 15.20.15 and 15.20.16;
//!   `eq_10_9_20_22` → (10.9.20) and (10.9.22).
//! - a run of six or nine numbers is two or three full triples: `fact_6_12_5_6_12_6_…`.
//! - `and` continues the last tag's kind: `problem_10_11_2_and_3_…` (10.11.2, 10.11.3),
//!   `problem_16_8_8_and_16_8_9_…` (16.8.8, 16.8.9); a new kind after `and` starts a new tag:
//!   `example_4_5_2_and_section_4_14_…`, `example_6_3_4_cylinder_and_erratum_6_3_15_…`.
//! - `to` gives a range: `problems_2_26_15_to_18_…` (15, 16, 17, 18),
//!   `facts_4_16_2_to_4_16_4_…` (2, 3, 4).
//!
//! Files in [`REGRESSION_GUARDS`] (the SVG snapshots) are listed but credit nothing.
//!
//! The same sources, and the notebooks' code cells, are checked for worst-error folds that
//! would pass with a NaN inside ([`nan_folds::nan_blind_folds_are_refused`]).

mod support;

#[path = "textbook_index/nan_folds.rs"]
mod nan_folds;

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

const BEGIN: &str = "<!-- BEGIN GENERATED: tests/textbook_index.rs -->";
const END: &str = "<!-- END GENERATED -->";
/// Test binaries that guard output against regressions but are not book coverage.
const REGRESSION_GUARDS: [&str; 1] = ["plot_snapshots"];
/// The chapters the coverage counts cover (chapter 1 is prose; 17–18 print solutions).
const COUNTED: std::ops::RangeInclusive<u32> = 2..=16;

/// What a tag names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Kind {
    Section,
    Fact,
    Eq,
    Example,
    Problem,
    Erratum,
    Definition,
    Remark,
    Figure,
}

/// One book reference in a test name: chapter, section and, if given, the item.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Tag {
    kind: Kind,
    ch: u32,
    sec: u32,
    item: Option<u32>,
}

fn kind_of(word: &str) -> Option<Kind> {
    Some(match word {
        "section" | "sections" | "sec" => Kind::Section,
        "fact" | "facts" => Kind::Fact,
        "eq" | "eqs" => Kind::Eq,
        "example" | "examples" => Kind::Example,
        "problem" | "problems" => Kind::Problem,
        "erratum" | "errata" => Kind::Erratum,
        "definition" | "def" => Kind::Definition,
        "remark" | "remarks" => Kind::Remark,
        "figure" | "fig" => Kind::Figure,
        _ => return None,
    })
}

/// Every tag in a test name (see the module doc for the grammar).
fn tags_of(name: &str) -> Vec<Tag> {
    let words: Vec<&str> = name.split('_').collect();
    let number_run = |from: usize| -> Vec<u32> {
        words[from.min(words.len())..].iter().map_while(|w| w.parse::<u32>().ok()).collect()
    };
    let mut tags = Vec::new();
    // the last tag: its kind, section and item, which `and` and `to` continue
    let mut last: Option<Tag> = None;
    let mut i = 0;
    while i < words.len() {
        let run = number_run(i + 1);
        let connective = words[i] == "and" || words[i] == "to";
        if let Some(kind) = kind_of(words[i]).filter(|_| run.len() >= 2) {
            last = push_run(&mut tags, kind, &run);
            i += 1 + run.len();
        } else if let (true, Some(prev)) = (connective, last)
            && !run.is_empty()
        {
            let range = words[i] == "to";
            let (ch, sec, items) = match run.len() {
                1 => (prev.ch, prev.sec, run.clone()),
                2 => (run[0], run[1], Vec::new()),
                _ if run.len() >= 6 && run.len().is_multiple_of(3) => {
                    last = push_run(&mut tags, prev.kind, &run);
                    i += 1 + run.len();
                    continue;
                }
                _ => (run[0], run[1], run[2..].to_vec()),
            };
            match (range, prev.item, items.first()) {
                // `to`: every item after the last one up to this one, in the same section
                (true, Some(from), Some(&to)) if (ch, sec) == (prev.ch, prev.sec) => {
                    for item in from + 1..=to {
                        tags.push(Tag { kind: prev.kind, ch, sec, item: Some(item) });
                    }
                }
                _ if items.is_empty() => tags.push(Tag { kind: prev.kind, ch, sec, item: None }),
                _ => tags.extend(items.iter().map(|&n| Tag { kind: prev.kind, ch, sec, item: Some(n) })),
            }
            last = tags.last().copied();
            i += 1 + run.len();
        } else {
            i += 1;
        }
    }
    tags.sort();
    tags.dedup();
    tags
}

/// The tags of one run of numbers after a kind word; returns the last.
fn push_run(tags: &mut Vec<Tag>, kind: Kind, run: &[u32]) -> Option<Tag> {
    if run.len() >= 6 && run.len().is_multiple_of(3) {
        for t in run.chunks(3) {
            tags.push(Tag { kind, ch: t[0], sec: t[1], item: Some(t[2]) });
        }
    } else if run.len() == 2 {
        tags.push(Tag { kind, ch: run[0], sec: run[1], item: None });
    } else {
        for &n in &run[2..] {
            tags.push(Tag { kind, ch: run[0], sec: run[1], item: Some(n) });
        }
    }
    tags.last().copied()
}

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

/// A list of numbered items (problems.txt, examples.txt): number → note ("" if none).
fn items(list: &str) -> BTreeMap<(u32, u32, u32), String> {
    list.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .filter_map(|l| {
            let (num, note) = l.split_once(" | ").unwrap_or((l, ""));
            let n: Vec<u32> = num.trim().split('.').filter_map(|x| x.parse().ok()).collect();
            (n.len() == 3).then(|| ((n[0], n[1], n[2]), note.trim().to_owned()))
        })
        .collect()
}

/// Tests by file, rendered as a table cell: "`file`: `a`, `b`; `file2`: `c`".
fn cell(files: &BTreeMap<String, Vec<String>>) -> String {
    files
        .iter()
        .map(|(f, ns)| {
            let list: Vec<String> = ns.iter().map(|n| format!("`{n}`")).collect();
            format!("`{f}`: {}", list.join(", "))
        })
        .collect::<Vec<_>>()
        .join("; ")
}

type ByFile = BTreeMap<String, Vec<String>>;

/// What the tests credit: sections, and items (examples, problems) by kind.
#[derive(Default)]
struct Credit {
    sections: BTreeMap<(u32, u32), ByFile>,
    items: BTreeMap<(Kind, u32, u32, u32), ByFile>,
    untagged: ByFile,
    guards: ByFile,
}

fn credit(tests: &BTreeMap<String, Vec<String>>) -> Credit {
    let mut c = Credit::default();
    for (file, names) in tests {
        for n in names {
            if REGRESSION_GUARDS.contains(&file.as_str()) {
                c.guards.entry(file.clone()).or_default().push(n.clone());
                continue;
            }
            let tags = tags_of(n);
            if tags.is_empty() {
                c.untagged.entry(file.clone()).or_default().push(n.clone());
            }
            let mut secs: Vec<(u32, u32)> = tags.iter().map(|t| (t.ch, t.sec)).collect();
            secs.dedup();
            for s in secs {
                c.sections.entry(s).or_default().entry(file.clone()).or_default().push(n.clone());
            }
            for t in &tags {
                if let Some(item) = t.item {
                    let list = c.items.entry((t.kind, t.ch, t.sec, item)).or_default();
                    list.entry(file.clone()).or_default().push(n.clone());
                }
            }
        }
    }
    c
}

fn generate() -> String {
    let tests = collect();
    let titles = titles();
    let problems = items(include_str!("textbook/problems.txt"));
    let examples = items(include_str!("textbook/examples.txt"));
    let c = credit(&tests);
    let named = |kind: Kind, (ch, sec, n): (u32, u32, u32)| c.items.get(&(kind, ch, sec, n));
    let total: usize = tests.values().map(Vec::len).sum();
    let tagged = total
        - c.untagged.values().map(Vec::len).sum::<usize>()
        - c.guards.values().map(Vec::len).sum::<usize>();

    let mut out = String::new();
    out.push_str(BEGIN);
    out.push('\n');
    out.push_str(&format!(
        "\n{total} tests in {} files; {tagged} carry a book tag.\n",
        tests.values().filter(|v| !v.is_empty()).count()
    ));

    // Coverage summary over the counted chapters.
    out.push_str("\n## Coverage, chapters 2–16\n\n| chapter | sections with a test | examples named | problems named |\n|---|---|---|---|\n");
    let (mut s_all, mut e_all, mut p_all) = ((0, 0), (0, 0), (0, 0));
    let mut untested_sections = Vec::new();
    for ch in COUNTED {
        let secs: Vec<_> = titles.keys().filter(|k| k.0 == ch).collect();
        let s_hit = secs.iter().filter(|s| c.sections.contains_key(s)).count();
        untested_sections.extend(secs.iter().filter(|s| !c.sections.contains_key(s)).map(|s| **s));
        let ex: Vec<_> = examples.keys().filter(|k| k.0 == ch).collect();
        let e_hit = ex.iter().filter(|&&&k| named(Kind::Example, k).is_some()).count();
        let pr: Vec<_> = problems.keys().filter(|k| k.0 == ch).collect();
        let p_hit = pr.iter().filter(|&&&k| named(Kind::Problem, k).is_some()).count();
        out.push_str(&format!(
            "| {ch} | {s_hit}/{} | {e_hit}/{} | {p_hit}/{} |\n",
            secs.len(),
            ex.len(),
            pr.len()
        ));
        s_all = (s_all.0 + s_hit, s_all.1 + secs.len());
        e_all = (e_all.0 + e_hit, e_all.1 + ex.len());
        p_all = (p_all.0 + p_hit, p_all.1 + pr.len());
    }
    out.push_str(&format!(
        "| **2–16** | **{}/{}** | **{}/{}** | **{}/{}** |\n",
        s_all.0, s_all.1, e_all.0, e_all.1, p_all.0, p_all.1
    ));
    let list: Vec<String> = untested_sections
        .iter()
        .map(|s| format!("{}.{} {}", s.0, s.1, titles.get(s).map(String::as_str).unwrap_or("")))
        .collect();
    out.push_str(&format!(
        "\nSections of chapters 2–16 without a test ({}): {}.\n",
        list.len(),
        if list.is_empty() { "none".to_owned() } else { list.join("; ") }
    ));

    let chapters: BTreeSet<u32> = titles.keys().map(|k| k.0).chain(c.sections.keys().map(|k| k.0)).collect();
    for ch in chapters {
        let secs: BTreeSet<(u32, u32)> =
            titles.keys().chain(c.sections.keys()).filter(|k| k.0 == ch).copied().collect();
        let count: BTreeSet<&String> =
            secs.iter().filter_map(|s| c.sections.get(s)).flat_map(|m| m.values().flatten()).collect();
        out.push_str(&format!(
            "\n### Chapter {ch} ({} tagged tests)\n\n| § | section | tests | count |\n|---|---|---|---|\n",
            count.len()
        ));
        for s in secs {
            let title = titles.get(&s).map(String::as_str).unwrap_or("(not a section of the book)");
            let (text, n) = match c.sections.get(&s) {
                Some(files) => (cell(files), files.values().map(Vec::len).sum::<usize>()),
                None => ("—".to_owned(), 0),
            };
            out.push_str(&format!("| {}.{} | {title} | {text} | {n} |\n", s.0, s.1));
        }
        for (kind, label, list) in
            [(Kind::Example, "Example", &examples), (Kind::Problem, "Problem", &problems)]
        {
            let mine: Vec<_> = list.iter().filter(|(k, _)| k.0 == ch).collect();
            if mine.is_empty() {
                continue;
            }
            out.push_str(&format!("\n| {label} | tests |\n|---|---|\n"));
            for (&k, note) in mine {
                let text = match named(kind, k) {
                    Some(files) => cell(files),
                    None if note.is_empty() => "—".to_owned(),
                    None => format!("— {note}"),
                };
                out.push_str(&format!("| {}.{}.{} | {text} |\n", k.0, k.1, k.2));
            }
        }
    }
    out.push_str("\n### Property tests, hard cases and other tests, by file\n\n| file | tests | count |\n|---|---|---|\n");
    for (file, names) in &c.untagged {
        let list: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
        out.push_str(&format!("| `{file}` | {} | {} |\n", list.join(", "), names.len()));
    }
    out.push_str(
        "\n### Regression guards (not counted as book coverage)\n\nSVG snapshots compare figure bytes; the \
         problems they draw are tested numerically elsewhere.\n\n| file | tests | count |\n|---|---|---|\n",
    );
    for (file, names) in &c.guards {
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

/// A test name says which book item it executes, so within one test binary no two tests share a
/// name (two `problem_2_26_9_quarter_turn` in different modules were credited twice, issue 38
/// item 6).
#[test]
fn test_names_are_unique_within_each_binary() {
    let mut twice = Vec::new();
    for (file, names) in collect() {
        let mut seen = BTreeSet::new();
        twice.extend(names.iter().filter(|n| !seen.insert(n.as_str())).map(|n| format!("{file}::{n}")));
    }
    assert!(twice.is_empty(), "test names defined twice in one binary: {}", twice.join(", "));
}

/// The lists of problems and examples are the book's: 208 problems and 42 examples, numbered
/// without gaps inside each problem section.
#[test]
fn book_lists_are_complete() {
    let problems = items(include_str!("textbook/problems.txt"));
    let examples = items(include_str!("textbook/examples.txt"));
    assert_eq!(problems.len(), 208);
    assert_eq!(examples.len(), 42);
    let mut by_section: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
    for &(c, s, n) in problems.keys() {
        by_section.entry((c, s)).or_default().push(n);
    }
    for (s, ns) in by_section {
        assert_eq!(ns, (1..=ns.len() as u32).collect::<Vec<_>>(), "problems of §{}.{} have a gap", s.0, s.1);
    }
}

#[test]
fn section_tags_parse_the_book_numbering() {
    let t = |kind, ch, sec, item| Tag { kind, ch, sec, item };
    use Kind::*;
    assert_eq!(tags_of("fact_2_11_5_half_turn"), [t(Fact, 2, 11, Some(5))]);
    assert_eq!(tags_of("example_4_19_2_slotted_arm"), [t(Example, 4, 19, Some(2))]);
    assert_eq!(tags_of("section_6_5_laws_of_statics"), [t(Section, 6, 5, None)]);
    assert_eq!(tags_of("sec_2_3_wrapped_angle_interval"), [t(Section, 2, 3, None)]);
    assert_eq!(tags_of("section_14_7_3_boeing_747_modes_and_table_14_3"), [t(Section, 14, 7, Some(3))]);
    assert_eq!(
        tags_of("problem_10_11_2_and_3_body_velocity"),
        [t(Problem, 10, 11, Some(2)), t(Problem, 10, 11, Some(3))]
    );
    assert_eq!(
        tags_of("problem_16_8_8_and_16_8_9_sensitivity_integral"),
        [t(Problem, 16, 8, Some(8)), t(Problem, 16, 8, Some(9))]
    );
    assert_eq!(
        tags_of("problem_15_20_15_16_initial_values"),
        [t(Problem, 15, 20, Some(15)), t(Problem, 15, 20, Some(16))]
    );
    assert_eq!(tags_of("fact_6_12_5_6_12_6_centre"), [t(Fact, 6, 12, Some(5)), t(Fact, 6, 12, Some(6))]);
    assert_eq!(
        tags_of("example_6_3_4_cylinder_and_erratum_6_3_15_isotropic_length"),
        [t(Example, 6, 3, Some(4)), t(Erratum, 6, 3, Some(15))]
    );
    assert_eq!(
        tags_of("eq_4_13_36_and_4_14_6_chain_velocity"),
        [t(Eq, 4, 13, Some(36)), t(Eq, 4, 14, Some(6))]
    );
    assert_eq!(
        tags_of("fact_4_18_1_and_example_4_18_4_rolling_disk"),
        [t(Fact, 4, 18, Some(1)), t(Example, 4, 18, Some(4))]
    );
    assert_eq!(
        tags_of("eq_10_9_18_determinant_is_cos_gamma_and_10_9_20_22_invert_it"),
        [t(Eq, 10, 9, Some(18)), t(Eq, 10, 9, Some(20)), t(Eq, 10, 9, Some(22))]
    );
    assert_eq!(
        tags_of("problems_2_26_15_to_18_trace_identities"),
        (15..=18).map(|n| t(Problem, 2, 26, Some(n))).collect::<Vec<_>>()
    );
    assert_eq!(
        tags_of("facts_4_16_2_to_4_16_4_iacr_lines"),
        (2..=4).map(|n| t(Fact, 4, 16, Some(n))).collect::<Vec<_>>()
    );
    assert_eq!(tags_of("figure_6_2_1_shapes"), [t(Figure, 6, 2, Some(1))]);
    assert!(tags_of("table_14_1_definitions_round_trip").is_empty());
    assert!(tags_of("round_trip_near_pi").is_empty());
    assert!(tags_of("example_simple_pendulum_period_is_elliptic").is_empty());
    assert!(tags_of("erratum_l603_counterclockwise_is_positive").is_empty());
    assert!(tags_of("snapshot_bode_16_8_11").is_empty());
    assert_eq!(
        titles().get(&(2, 11)).map(String::as_str),
        Some("Eigenaxis Rotations and Rodrigues's Formula")
    );
}

/// The assertions of `tests/support` mean what their names say: a printed value is checked to
/// half a unit of its last digit (never scaled by the value), a relative tolerance scales with
/// |want|, an absolute one does not.
#[test]
fn support_assertions_have_the_semantics_their_names_say() {
    use support::*;
    let fails = |f: fn()| std::panic::catch_unwind(f).is_err();
    assert_eq!(parse_printed("985"), (985.0, 1.0));
    assert_eq!(parse_printed("-0.0042"), (-0.0042, 1e-4));
    assert_eq!(parse_printed("1.5e-3"), (1.5e-3, 1e-4));
    // "985" is ±0.5, not ±985 (the old scaled helper's failure, issue 20)
    assert_printed(985.49, "985");
    assert!(fails(|| assert_printed(985.51, "985")));
    assert!(fails(|| assert_printed(1.0, "985")));
    assert_printed(-0.00424, "-0.0042");
    assert!(fails(|| assert_printed(-0.00426, "-0.0042")));
    // truncation: 6.297 prints as 6.29 when chopped, but not 6.30
    assert_truncated(6.297, "6.29");
    assert_truncated(-99.485, "-99.48");
    assert!(fails(|| assert_truncated(6.289, "6.29")));
    assert!(fails(|| assert_truncated(6.297, "6.30")));
    // relative scales with |want|, absolute does not
    assert_rel(1000.0 + 1e-10, 1000.0, 1e-12);
    assert!(fails(|| assert_abs(1000.0 + 1e-10, 1000.0, 1e-12)));
    assert!(fails(|| assert_rel(1e-13, 0.0, 1.0)));
    // slices: abs per entry; rel against the largest |want|; NaN always fails
    assert_rel_slice(&[100.0, 1e-13], &[100.0, 0.0], 1e-15);
    assert!(fails(|| assert_abs_slice(&[100.0, 1e-13], &[100.0, 0.0], 1e-15)));
    assert!(fails(|| assert_abs_slice(&[f64::NAN], &[0.0], 1.0)));
    assert!(fails(|| assert_rel(f64::NAN, 1.0, 1.0)));
}
