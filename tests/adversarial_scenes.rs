//! Issue 33 item 8: the project's own hostile scene files (tests/adversarial/scenes/, written
//! once by scripts/adversarial_scenes.py and committed), across the classes hostile numbers,
//! quantity strings, structure, output safety, loops, aircraft and trim, sweep, linearize and
//! contacts. Each file's header says what must happen; for every file this test asserts the
//! exit code, the location (`file:line:col`, on the line of the key at fault, with the item
//! path named), that nothing is written outside `--out`, and that no file vectrix did not
//! create changes (the scene file itself and a file of the user's beside it).
//!
//! Book: — (the command line; scenes of §7.11, §7.13, §9.11, §11–14).

#![cfg(feature = "cli")]

mod support;

use std::path::{Path, PathBuf};

use support::snapshot;
use vectrix_cli::{Outcome, run_with_args};

/// What a file's `# expect:` header promises.
#[derive(Debug, PartialEq)]
enum Expect {
    /// Exit 0.
    Ok,
    /// Exit 1 with the rows written and `"complete": false`.
    Stopped,
    /// Exit 1 with a located message; naming this item path when given.
    Refused(Option<String>),
    /// Exit 1 with a message naming this command-line argument (no file location applies).
    RefusedArg(String),
}

struct Case {
    path: PathBuf,
    command: String,
    args: Vec<String>,
    expect: Expect,
}

fn header(path: &Path) -> Case {
    let text = String::from_utf8_lossy(&std::fs::read(path).unwrap()).to_string();
    let field = |key: &str| {
        text.lines()
            .take_while(|l| l.starts_with('#'))
            .find_map(|l| l.strip_prefix(&format!("# {key}: ")).map(str::to_string))
    };
    let expect = match field("expect").unwrap_or_else(|| panic!("{}: no `# expect:`", path.display())) {
        e if e == "ok" => Expect::Ok,
        e if e == "stopped" => Expect::Stopped,
        e if e == "refused" => Expect::Refused(None),
        e if e.starts_with("refused by ") => Expect::RefusedArg(e["refused by ".len()..].to_string()),
        e => {
            Expect::Refused(Some(e.strip_prefix("refused at ").expect("expect: refused at PATH").to_string()))
        }
    };
    Case {
        path: path.to_path_buf(),
        command: field("command").unwrap_or_else(|| "run".into()),
        args: field("args").map(|a| a.split_whitespace().map(str::to_string).collect()).unwrap_or_default(),
        expect,
    }
}

fn files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            out.extend(files(&p));
        } else if p.extension().is_some_and(|x| x == "toml") {
            out.push(p);
        }
    }
    out.sort();
    out
}

/// The last key of an item path (`bodies[0].q[0]` → `q`; `trim.hold` → `hold`).
fn last_key(path: &str) -> &str {
    let key = path.rsplit('.').next().unwrap_or(path);
    key.split('[').next().unwrap_or(key)
}

/// Runs one case in a fresh folder; returns what went wrong, if anything.
fn check(case: &Case, n: usize) -> Result<(), String> {
    let root = std::env::temp_dir().join(format!("vectrix-adversarial-{}-{n}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let input = root.join("in");
    std::fs::create_dir_all(&input).unwrap();
    let name = case.path.file_name().unwrap().to_string_lossy().to_string();
    let scene = input.join(&name);
    std::fs::copy(&case.path, &scene).unwrap();
    std::fs::write(input.join("notes.txt"), "the user's own file").unwrap();
    let before = snapshot(&input);
    let out = root.join("out");
    let mut args: Vec<String> = vec!["vectrix".into(), case.command.clone(), scene.display().to_string()];
    if case.command != "check" {
        args.extend(["--out".to_string(), out.display().to_string()]);
    }
    args.extend(case.args.iter().cloned());
    let mut stdout = Vec::new();
    let result = run_with_args(args.iter(), &mut stdout);
    let (code, message) = match &result {
        Ok(Outcome::Complete) => (0, String::new()),
        Ok(Outcome::Budget | Outcome::Unreliable) => (1, String::new()),
        Ok(Outcome::Interrupted) => (130, String::new()),
        Err(e) => (1, e.to_string()),
    };
    let fail = |why: String| Err(format!("{}: {why}\n  message: {message}", case.path.display()));
    // nothing the user owns changed, and nothing was written beside `in` and `out`
    if snapshot(&input) != before {
        return fail("a file vectrix did not create changed".into());
    }
    let mut entries: Vec<String> = std::fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
        .collect();
    entries.sort();
    if entries.iter().any(|e| e != "in" && e != "out") {
        return fail(format!("wrote outside --out: {entries:?}"));
    }
    let result = match &case.expect {
        Expect::Ok if code == 0 => Ok(()),
        Expect::Stopped if code == 1 && message.is_empty() => {
            let summary =
                std::fs::read_to_string(out.join("pendulum").join("summary.json")).unwrap_or_default();
            if summary.contains("\"complete\": false") {
                Ok(())
            } else {
                fail("stopped, but the summary does not say `complete: false`".into())
            }
        }
        Expect::Refused(path) if code == 1 && !message.is_empty() => {
            located(case, &scene, &message, path.as_deref())
        }
        Expect::RefusedArg(arg) if code == 1 && message.contains(arg.as_str()) => Ok(()),
        e => fail(format!("expected {e:?}, got exit {code}")),
    };
    // a refusal writes nothing at all
    if matches!(case.expect, Expect::Refused(_) | Expect::RefusedArg(_))
        && out.exists()
        && !snapshot(&out).is_empty()
    {
        return fail("a refused run wrote files".into());
    }
    let _ = std::fs::remove_dir_all(&root);
    result.map_err(|e| format!("{}: {e}\n  message: {message}", case.path.display()))
}

/// The message names `file:line:col` inside the file, on the line of the item's key, and
/// names the item path.
fn located(case: &Case, scene: &Path, message: &str, path: Option<&str>) -> Result<(), String> {
    let file = scene.display().to_string();
    // a file may have several errors (one per line, in file order): the one at `path`, or the first
    let lines: Vec<&str> = message.lines().filter(|l| l.contains(&format!("{file}:"))).collect();
    let chosen = match path {
        Some(p) => lines.iter().find(|l| l.contains(&format!(": {p}: "))).or(lines.first()),
        None => lines.first(),
    };
    let Some(rest) = chosen.and_then(|l| l.find(&format!("{file}:")).map(|i| &l[i + file.len() + 1..]))
    else {
        return Err("no file:line:col location".into());
    };
    let mut parts = rest.splitn(3, ':');
    let (Some(Ok(line)), Some(Ok(col))) =
        (parts.next().map(str::parse::<usize>), parts.next().map(str::parse::<usize>))
    else {
        return Err("no line and column after the file name".into());
    };
    let bytes = std::fs::read(&case.path).unwrap();
    let text = String::from_utf8_lossy(&bytes);
    let Some(at) = text.lines().nth(line.wrapping_sub(1)) else {
        return Err(format!("line {line} is not in the file"));
    };
    if col == 0 || col > at.chars().count() + 1 {
        return Err(format!("column {col} is not on line {line}"));
    }
    if let Some(p) = path {
        if !message.contains(p) {
            return Err(format!("the message does not name `{p}`"));
        }
        let key = last_key(p);
        if !at.contains(key) {
            return Err(format!("line {line} (`{at}`) does not hold the key `{key}`"));
        }
    }
    Ok(())
}

#[test]
fn every_hostile_scene_file_ends_as_its_header_says() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/adversarial/scenes");
    let all = files(&dir);
    assert!(all.len() >= 100, "{} files; issue 33 asks for at least 100", all.len());
    let failures: Vec<String> =
        all.iter().enumerate().filter_map(|(n, p)| check(&header(p), n).err()).collect();
    assert!(failures.is_empty(), "{} of {} files:\n{}", failures.len(), all.len(), failures.join("\n"));
}
