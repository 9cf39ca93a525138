//! Issue 33: the command line is safe with the user's files, bounded in what it writes, and
//! honest in what it reports. Each test reproduces one finding and asserts its fix:
//!
//! * output size is bounded (`--max-output-bytes`, default 1 GiB) before the run, and a
//!   repeated output, whose figures grew with the square of the list, is refused;
//! * SIGTERM stops a run like Ctrl-C, and temporary folders of killed runs are removed;
//! * `accuracy`, `sweep` and `linearize` write only into folders vectrix created and marked;
//! * no command deletes a file it did not write, its own scene file included;
//! * a parameter given twice to `sweep` is refused (the table named values not used);
//! * a scene is read from a regular file with its bytes counted (`/dev/zero`, FIFOs);
//! * a run whose numbers mean nothing (a state near f64::MAX, energy drift ≥ 1e-3) is not
//!   `complete`.
//!
//! Book: — (the command line; scenes of §7.11).

mod support;

use std::path::Path;

use support::snapshot;

use vectrix_cli::{Outcome, run_with_args};

fn cli(args: &[&str]) -> Result<(Outcome, String), String> {
    let mut out = Vec::new();
    let r = run_with_args(std::iter::once("vectrix").chain(args.iter().copied()), &mut out);
    let text = String::from_utf8_lossy(&out).to_string();
    r.map(|o| (o, text)).map_err(|e| e.to_string())
}

/// A pendulum scene: short, with `outputs`, `samples` and `q` as given.
fn pendulum(dir: &Path, file: &str, name: &str, outputs: &str, samples: usize, q: &str) -> String {
    let text = format!(
        "name = \"{name}\"\nduration = 0.5\nsamples = {samples}\noutputs = {outputs}\nchecks = [\"energy\"]\n\n\
         [[bodies]]\nname = \"bob\"\njoint = {{ type = \"pin\", axis = [0.0, 0.0, 1.0] }}\n\
         mass = {{ shape = \"particle\", mass = 1.0 }}\ncom = [0.0, -1.0, 0.0]\nq = [{q}]\n\n\
         [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, -9.81, 0.0]\n"
    );
    let p = dir.join(file);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn simple(dir: &Path) -> String {
    pendulum(dir, "p.toml", "p", "[\"coordinates:bob\", \"energy\"]", 10, "1.0")
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Finding 2: 800 repeated outputs wrote 1 GB (every figure drew every repetition's columns).
/// A repeated output is now refused at its position, naming the one it repeats.
#[test]
fn issue_33_repeated_output_is_refused_at_its_position() {
    let dir = tempfile::tempdir().unwrap();
    let p = pendulum(dir.path(), "p.toml", "p", "[\"energy\", \"coordinates:bob\", \"energy\"]", 10, "1.0");
    let out = dir.path().join("out");
    let e = cli(&["run", &p, "--quiet", "--out", out.to_str().unwrap()]).unwrap_err();
    assert!(e.starts_with(&format!("{p}:4:")), "{e}");
    assert!(e.contains("outputs[2]: output `energy` repeats outputs[0]; valid: each output once"), "{e}");
    assert!(!out.exists(), "nothing written");
    // aircraft scenes too
    let jet = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/scenes/business_jet_doublet.toml"
    ))
    .unwrap()
    .replace("outputs = [\"velocity_body:jet\",", "outputs = [\"velocity_body:jet\", \"velocity_body:jet\",");
    let f = dir.path().join("jet.toml");
    std::fs::write(&f, jet).unwrap();
    let e = cli(&["check", f.to_str().unwrap()]).unwrap_err();
    assert!(e.contains("outputs[1]: output `velocity_body:jet` repeats outputs[0]"), "{e}");
}

/// Finding 2: the `(samples + 1) × columns` bound did not cover the figures, and nothing
/// bounded the bytes written. An output whose bound exceeds `--max-output-bytes` (default
/// 1 GiB) is refused at `samples` before the run, and nothing is written.
#[test]
fn issue_33_output_over_the_budget_is_refused_before_the_run() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    let p = simple(dir.path());
    let e = cli(&["run", &p, "--quiet", "--out", o, "--max-output-bytes", "20kB"]).unwrap_err();
    assert!(e.starts_with(&format!("{p}:3:1: samples: the output would take up to")), "{e}");
    assert!(e.contains("valid: at most max_output_bytes = 20000 bytes"), "{e}");
    assert!(!out.exists(), "nothing written");
    // the default budget: a million samples of 23 columns (CSV and figures) could take 1.1 GB
    let every = "[\"q\", \"v\", \"energy\", \"momentum\", \"angular_momentum\", \"position:bob\", \"velocity:bob\", \
                 \"omega:bob\", \"omega_body:bob\", \"coordinates:bob\", \"speeds:bob\"]";
    let big = pendulum(dir.path(), "big.toml", "big", every, 1_000_000, "1.0");
    let e = cli(&["run", &big, "--quiet", "--out", o]).unwrap_err();
    assert!(e.contains("samples: the output would take up to") && e.contains("= 1073741824 bytes"), "{e}");
    assert!(!out.exists());
    // a sweep is bounded as a whole
    let e = cli(&[
        "sweep",
        &p,
        "--quiet",
        "--out",
        o,
        "--param",
        "duration=1,2,3",
        "--max-output-bytes",
        "100kB",
    ])
    .unwrap_err();
    assert!(e.contains(":3:1: samples: 3 runs: the output would take up to"), "{e}");
    assert!(cli(&["run", &p, "--quiet", "--out", o, "--max-output-bytes", "nonsense"]).is_err());
    // within the budget: the run says what it allowed, and wrote less
    let (outcome, text) = cli(&["run", &p, "--quiet", "--out", o, "--max-output-bytes", "1MB"]).unwrap();
    assert_eq!(outcome, Outcome::Complete);
    assert!(text.contains("max_output_bytes = 1000000"), "{text}");
    let s = json(&out.join("p/summary.json"));
    assert_eq!(s["max_output_bytes"], 1_000_000);
    let written: usize = snapshot(&out.join("p")).iter().map(|(_, b)| b.len()).sum();
    assert!(written <= 1_000_000);
}

/// Finding 2: a run killed while writing (SIGTERM, or a second Ctrl-C) left a hidden
/// `.NAME.tmp-*` folder that no later run removed. The next run into the same `--out`
/// removes temporary folders that carry vectrix's marker and whose process is gone.
#[test]
fn issue_33_temporary_folders_of_killed_runs_are_removed() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let mut child = std::process::Command::new("true").spawn().unwrap();
    let dead = child.id();
    child.wait().unwrap();
    let stale = out.join(format!(".p.tmp-{dead}-0-0"));
    std::fs::create_dir(&stale).unwrap();
    std::fs::write(
        stale.join(".vectrix-output"),
        format!("vectrix output folder: replaced by the next run of the same scene\nwriter {dead} 1\n"),
    )
    .unwrap();
    std::fs::write(stale.join("trajectory.csv"), "t [s]\n").unwrap();
    // a hidden folder of the user's, named alike but without the marker, stays
    let user = out.join(format!(".q.tmp-{dead}-0-0"));
    std::fs::create_dir(&user).unwrap();
    std::fs::write(user.join("mine.txt"), "mine").unwrap();
    let p = simple(dir.path());
    cli(&["run", &p, "--quiet", "--out", out.to_str().unwrap()]).unwrap();
    assert!(!stale.exists());
    assert_eq!(std::fs::read_to_string(user.join("mine.txt")).unwrap(), "mine");
}

/// Finding 2: SIGTERM is honoured like Ctrl-C: the run stops, what it computed is written
/// and marked incomplete, no temporary folder stays, and the exit code is 130.
#[cfg(target_os = "linux")]
#[test]
fn issue_33_sigterm_stops_a_run_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    // a run that would take days: only the signal ends it
    let text = std::fs::read_to_string(simple(dir.path())).unwrap().replace(
        "duration = 0.5",
        "duration = 1e9\nmax_wall_seconds = 1e9\nmax_steps = 1000000000000\naccuracy = 1e-11",
    );
    let p = dir.path().join("long.toml");
    std::fs::write(&p, text).unwrap();
    let out = dir.path().join("out");
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_vectrix"))
        .args(["run", p.to_str().unwrap(), "--quiet", "--out", out.to_str().unwrap()])
        .stdout(std::process::Stdio::null())
        .spawn()
        .unwrap();
    // wait until the process catches SIGTERM (bit 15 of SigCgt in /proc/PID/status), so
    // the signal cannot arrive before the handler
    let caught = |pid: u32| -> bool {
        let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
        status
            .lines()
            .find_map(|l| l.strip_prefix("SigCgt:"))
            .and_then(|m| u64::from_str_radix(m.trim(), 16).ok())
            .is_some_and(|m| m & (1 << (15 - 1)) != 0)
    };
    let mut polls = 0;
    while !caught(child.id()) {
        polls += 1;
        assert!(polls < 60_000, "the handler was never installed");
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
    let killed =
        std::process::Command::new("kill").args(["-TERM", &child.id().to_string()]).status().unwrap();
    assert!(killed.success());
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130));
    let s = json(&out.join("p/summary.json"));
    assert_eq!(s["complete"], false);
    assert_eq!(s["stop"]["reason"], "interrupted");
    let hidden: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().starts_with('.'))
        .collect();
    assert!(hidden.is_empty(), "temporary folders left: {hidden:?}");
}

/// Finding 3: `vectrix accuracy --out DIR` overwrote files it did not write (a user's
/// `oscillator.svg`). It now writes DIR like a scene's output folder: a folder without the
/// marker is refused before the harness runs, and nothing in it changes.
#[test]
fn issue_33_accuracy_does_not_overwrite_a_users_files() {
    let dir = tempfile::tempdir().unwrap();
    let figures = dir.path().join("figures");
    std::fs::create_dir(&figures).unwrap();
    std::fs::write(figures.join("oscillator.svg"), "my drawing").unwrap();
    let before = snapshot(dir.path());
    let e = cli(&["accuracy", "--quick", "--out", figures.to_str().unwrap()]).unwrap_err();
    assert!(
        e.contains("refusing to replace") && e.contains("figures") && e.contains("no .vectrix-output marker"),
        "{e}"
    );
    assert_eq!(snapshot(dir.path()), before);
    // an `--out` that is no folder name
    assert!(cli(&["accuracy", "--quick", "--out", "/"]).is_err());
    // a folder of its own: written, replaced, and refused once a user's file is in it
    let own = dir.path().join("own");
    let o = own.to_str().unwrap();
    let (_, text) = cli(&["accuracy", "--quick", "--out", o]).unwrap();
    assert!(text.contains(&format!("wrote {}", own.join("oscillator.svg").display())), "{text}");
    cli(&["accuracy", "--quick", "--out", o]).unwrap();
    std::fs::write(own.join("notes.txt"), "mine").unwrap();
    let e = cli(&["accuracy", "--quick", "--out", o]).unwrap_err();
    assert!(e.contains("holds files vectrix did not write: notes.txt"), "{e}");
    assert_eq!(std::fs::read_to_string(own.join("notes.txt")).unwrap(), "mine");
}

/// Finding 3: `sweep` and `linearize` follow the rule of `run`: a folder vectrix did not
/// write is refused, and so is a folder of vectrix's that holds a file it did not write.
#[test]
fn issue_33_sweep_and_linearize_write_only_into_their_own_folders() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    let p = simple(dir.path());
    std::fs::create_dir_all(out.join("p-sweep")).unwrap();
    std::fs::write(out.join("p-sweep/sweep.csv"), "mine").unwrap();
    std::fs::create_dir_all(out.join("p")).unwrap();
    std::fs::write(out.join("p/poles.svg"), "mine").unwrap();
    let before = snapshot(dir.path());
    let e = cli(&["sweep", &p, "--quiet", "--out", o, "--param", "duration=0.1,0.2"]).unwrap_err();
    assert!(e.contains("refusing to replace") && e.contains("p-sweep"), "{e}");
    let e = cli(&["linearize", &p, "--out", o]).unwrap_err();
    assert!(e.contains("refusing to replace") && e.contains("no .vectrix-output marker"), "{e}");
    assert_eq!(snapshot(dir.path()), before);
    // into a run's folder, linearize adds its files; a user's file there stops it
    std::fs::remove_dir_all(out.join("p")).unwrap();
    cli(&["run", &p, "--quiet", "--out", o]).unwrap();
    cli(&["linearize", &p, "--out", o]).unwrap();
    assert!(out.join("p/linearization.json").is_file() && out.join("p/trajectory.csv").is_file());
    std::fs::write(out.join("p/notes.md"), "mine").unwrap();
    let e = cli(&["linearize", &p, "--out", o]).unwrap_err();
    assert!(e.contains("holds files vectrix did not write: notes.md"), "{e}");
    let e = cli(&["run", &p, "--quiet", "--out", o]).unwrap_err();
    assert!(e.contains("holds files vectrix did not write: notes.md"), "{e}");
    assert_eq!(std::fs::read_to_string(out.join("p/notes.md")).unwrap(), "mine");
}

/// Finding 4: `vectrix run out/p/scene.toml --out out` deleted its own scene file, and any
/// file dropped into `out/<name>/` was deleted by the next run. Both are refused now, naming
/// the files, and nothing changes.
#[test]
fn issue_33_a_run_never_deletes_its_input_or_a_users_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    let p = simple(dir.path());
    cli(&["run", &p, "--quiet", "--out", o]).unwrap();
    let inside = out.join("p/scene.toml");
    std::fs::copy(&p, &inside).unwrap();
    let before = snapshot(dir.path());
    for cmd in [vec!["run", inside.to_str().unwrap()], vec!["linearize", inside.to_str().unwrap()]] {
        let e = cli(&[cmd.as_slice(), &["--out", o]].concat()).unwrap_err();
        assert!(e.contains("the scene file") && e.contains("is inside it"), "{cmd:?}: {e}");
    }
    // the same scene from elsewhere: the folder holds a file vectrix did not write
    let e = cli(&["run", &p, "--quiet", "--out", o]).unwrap_err();
    assert!(e.contains("holds files vectrix did not write: scene.toml"), "{e}");
    assert_eq!(snapshot(dir.path()), before);
}

/// Finding 5: `--param duration=1,2 --param duration=3` ran both runs with 3 while sweep.csv
/// said 1 and 2. A parameter given twice (in any spelling of its path) is refused.
#[test]
fn issue_33_repeated_sweep_parameter_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    let text = std::fs::read_to_string(simple(dir.path())).unwrap().replace("name = \"p\"", "name = \"s\"")
        + "\n[[effects]]\ntype = \"rotational_dashpot\"\nbody = \"bob\"\nxi = 0.5\n";
    let p = dir.path().join("s.toml");
    std::fs::write(&p, text).unwrap();
    let p = p.to_str().unwrap();
    for (a, b) in [("duration=1,2", "duration=3"), ("effects.1.xi=1", "effects.01.xi=2")] {
        let e = cli(&["sweep", p, "--quiet", "--out", o, "--param", a, "--param", b]).unwrap_err();
        assert!(e.contains(&format!("--param `{b}` repeats the parameter of --param `{a}`")), "{e}");
    }
    assert!(!out.exists());
    // distinct parameters still combine, and the table holds the values used
    cli(&["sweep", p, "--quiet", "--out", o, "--param", "duration=0.2,0.3", "--param", "effects.1.xi=1"])
        .unwrap();
    let csv = std::fs::read_to_string(out.join("s-sweep/sweep.csv")).unwrap();
    assert!(csv.starts_with("run,duration,effects.1.xi,complete"), "{csv}");
    let summary = json(&out.join("s-sweep/run-001/summary.json"));
    assert_eq!(summary["duration"], 0.3);
    assert!(csv.lines().nth(2).unwrap().starts_with("001,3e-1,1e0,"), "{csv}");
}

/// Finding 6: `vectrix check /dev/zero` grew without bound (the 4 MiB cap trusted the size
/// the file system reports). Only regular files are read, and the bytes read are counted.
#[test]
fn issue_33_scene_input_is_bounded() {
    let dir = tempfile::tempdir().unwrap();
    let o = dir.path().join("out");
    let o = o.to_str().unwrap();
    #[cfg(unix)]
    {
        for args in [
            vec!["check", "/dev/zero"],
            vec!["run", "/dev/zero", "--out", o],
            vec!["linearize", "/dev/zero", "--out", o],
        ] {
            let e = cli(&args).unwrap_err();
            assert!(e.contains("/dev/zero: a character device; valid: a scene file"), "{args:?}: {e}");
        }
        let e = cli(&["sweep", "/dev/zero", "--param", "duration=1", "--out", o]).unwrap_err();
        assert!(e.contains("/dev/zero: a character device"), "{e}");
        // a FIFO with no writer: refused at once, the open does not block
        let fifo = dir.path().join("fifo.toml");
        assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
        let e = cli(&["check", fifo.to_str().unwrap()]).unwrap_err();
        assert!(e.contains("fifo.toml: a FIFO (named pipe)"), "{e}");
    }
    let big = dir.path().join("big.toml");
    std::fs::write(&big, format!("name = \"x\"\n#{}\n", "x".repeat(4 << 20))).unwrap();
    let e = cli(&["check", big.to_str().unwrap()]).unwrap_err();
    assert!(
        e.contains("big.toml: more than 4194304 bytes; valid: a scene file of at most 4194304 bytes"),
        "{e}"
    );
    let e = cli(&["check", dir.path().to_str().unwrap()]).unwrap_err();
    assert!(e.contains("a folder"), "{e}");
}

/// Finding 7: `q = [1e308]` completed with an energy drift of 1.0 (relative) and no warning.
/// A state beyond √f64::MAX, or a checked invariant drifting by 1e-3 or more, makes the run
/// incomplete with the reason; the exit code is 1.
#[test]
fn issue_33_meaningless_numbers_are_not_complete() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    // the issue's q = [1e308] is refused where it stands (numbers beyond 1e150 mean nothing)
    let p = pendulum(dir.path(), "huge.toml", "huge", "[\"energy\"]", 10, "1e308");
    let e = cli(&["run", &p, "--quiet", "--out", o]).unwrap_err();
    assert!(e.contains("huge.toml:") && e.contains("bodies[0].q[0]: 1e308; valid:"), "{e}");
    // a state that grows beyond 1e154 during the run: a slider at 1e150 m/s for 1e5 s
    let slider = "name = \"far\"\nduration = 1e5\nsamples = 10\noutputs = [\"q\"]\n\n[[bodies]]\nname = \"s\"\n\
                  joint = { type = \"sleeve\", axis = [1.0, 0.0, 0.0] }\nmass = { shape = \"particle\", mass = 1.0 }\n\
                  v = [1e150]\n";
    std::fs::write(dir.path().join("far.toml"), slider).unwrap();
    let p = dir.path().join("far.toml");
    let (outcome, text) = cli(&["run", p.to_str().unwrap(), "--quiet", "--out", o]).unwrap();
    assert_eq!(outcome, Outcome::Unreliable);
    assert!(text.contains("INCOMPLETE") && text.contains("q[0] reached"), "{text}");
    let s = json(&out.join("far/summary.json"));
    assert_eq!(s["complete"], false);
    assert_eq!(s["stop"]["reason"], "state_out_of_range");
    // a loose method on a conservative pendulum: the energy drifts by far more than 1e-3
    let text = std::fs::read_to_string(simple(dir.path()))
        .unwrap()
        .replace("duration = 0.5", "duration = 50.0\nmethod = { name = \"dopri5\", rtol = 0.3 }");
    std::fs::write(dir.path().join("p.toml"), text).unwrap();
    let p = dir.path().join("p.toml");
    let (outcome, _) = cli(&["run", p.to_str().unwrap(), "--quiet", "--out", o]).unwrap();
    assert_eq!(outcome, Outcome::Unreliable);
    let s = json(&out.join("p/summary.json"));
    assert_eq!(s["complete"], false);
    assert_eq!(s["stop"]["reason"], "invariant_drift");
    assert!(s["drift"][0]["max_rel"].as_f64().unwrap() >= 1e-3);
}

/// An `--out` that is a file, a device or a symbolic-link loop is refused with its path and
/// why, in the user's words (issue 33: "File exists" with no path), and nothing is written.
#[test]
fn out_that_is_not_a_folder_is_refused_with_its_path() {
    let dir = tempfile::tempdir().unwrap();
    let scene = pendulum(dir.path(), "p.toml", "p", "[\"q\"]", 10, "0.3");
    let file = dir.path().join("afile");
    std::fs::write(&file, "mine").unwrap();
    // the loop lives in a folder of its own (a snapshot cannot read through it)
    let links = tempfile::tempdir().unwrap();
    let (a, b) = (links.path().join("loop_a"), links.path().join("loop_b"));
    std::os::unix::fs::symlink(&b, &a).unwrap();
    std::os::unix::fs::symlink(&a, &b).unwrap();
    let before = snapshot(dir.path());
    for (out, why) in [
        (file.display().to_string(), "is not a folder"),
        ("/dev/null".to_string(), "is not a folder"),
        (a.display().to_string(), "symbolic link"),
    ] {
        let e = cli(&["run", &scene, "--out", &out]).unwrap_err();
        assert!(e.contains(&format!("--out {out}")) && e.contains(why) && !e.contains("os error"), "{e}");
    }
    assert_eq!(snapshot(dir.path()), before);
}
