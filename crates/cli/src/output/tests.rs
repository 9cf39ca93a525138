//! The ownership rules of output folders (see the module doc of `output`).

use super::marker::{FILES, WRITER, temp_pid};
use super::*;

/// A sink-free fill: one file `name` with `text`.
fn one(name: &'static str, text: &'static str) -> impl FnOnce(&Sink) -> Result<(), BoxError> {
    move |s: &Sink| s.last(name, text.as_bytes())
}

const ANY: Limits = Limits { max_bytes: 1 << 20, reserve: 0 };

fn names(d: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
    v.sort();
    v
}

#[test]
fn replaces_only_its_own_folders() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // a user's folder of the same name is refused and left as it was
    std::fs::create_dir(d.join("src")).unwrap();
    std::fs::write(d.join("src/lib.rs"), "fn main() {}").unwrap();
    let e = write_dir(d, "src", ANY, one("a", "1")).err().unwrap();
    assert!(e.to_string().contains("refusing"), "{e}");
    assert_eq!(std::fs::read_to_string(d.join("src/lib.rs")).unwrap(), "fn main() {}");
    // a folder of ours is replaced
    let p = write_dir(d, "scene", ANY, one("a", "1")).unwrap().dest;
    write_dir(d, "scene", ANY, one("b", "2")).unwrap();
    assert!(!p.join("a").exists() && p.join("b").exists() && is_ours(&p));
    // a failed run keeps the previous output and leaves no temporary folder
    let e = write_dir(d, "scene", ANY, |_| Err("boom".into())).err().unwrap();
    assert_eq!(e.to_string(), "boom");
    assert!(p.join("b").exists());
    assert_eq!(names(d), ["scene", "src"]);
    // names that are not plain file names are refused before anything is written
    for bad in ["", ".", "..", "../x", "/etc", "a/b"] {
        assert!(write_dir(d, bad, ANY, |_| Ok(())).is_err(), "{bad:?}");
    }
}

/// Issue 33 item 4: a file the user put into an output folder is named and kept, not deleted
/// by the next run (also the manifest lists every file, in sub-folders too).
#[test]
fn a_file_vectrix_did_not_write_stops_the_replacement() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    let p = write_dir(d, "s", ANY, |s| {
        s.dir("run-000")?;
        s.last("run-000/a.csv", b"1")?;
        s.last("b.svg", b"2")
    })
    .unwrap()
    .dest;
    assert!(write_dir(d, "s", ANY, one("x", "y")).is_ok(), "only listed files: replaceable");
    std::fs::write(p.join("notes.txt"), "mine").unwrap();
    std::fs::create_dir(p.join("data")).unwrap();
    let e = write_dir(d, "s", ANY, one("x", "z")).err().unwrap().to_string();
    assert!(e.contains("holds files vectrix did not write: data/, notes.txt"), "{e}");
    assert_eq!(std::fs::read_to_string(p.join("notes.txt")).unwrap(), "mine");
    assert_eq!(std::fs::read_to_string(p.join("x")).unwrap(), "y");
    assert_eq!(names(d), ["s"]);
}

#[test]
fn a_marker_without_a_manifest_is_not_enough() {
    let d = tempfile::tempdir().unwrap();
    let old = d.path().join("old");
    std::fs::create_dir(&old).unwrap();
    std::fs::write(old.join(MARKER), format!("{MARKER_TEXT}\n")).unwrap();
    std::fs::write(old.join("trajectory.csv"), "t\n").unwrap();
    let e = write_dir(d.path(), "old", ANY, one("a", "1")).err().unwrap().to_string();
    assert!(e.contains("lists no files"), "{e}");
    assert!(old.join("trajectory.csv").exists());
}

/// A hand-edited manifest cannot make vectrix delete outside the folder.
#[test]
fn a_manifest_cannot_point_outside() {
    let d = tempfile::tempdir().unwrap();
    let victim = d.path().join("victim.txt");
    std::fs::write(&victim, "keep").unwrap();
    let f = d.path().join("f");
    std::fs::create_dir(&f).unwrap();
    std::fs::write(f.join(MARKER), format!("{MARKER_TEXT}\n{FILES}\n../victim.txt\n/etc/passwd\n")).unwrap();
    write_dir(d.path(), "f", ANY, one("a", "1")).unwrap();
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep");
}

#[test]
fn a_file_or_link_in_the_way_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    std::fs::write(d.join("f"), "user data").unwrap();
    assert!(write_dir(d, "f", ANY, |_| Ok(())).is_err());
    assert_eq!(std::fs::read_to_string(d.join("f")).unwrap(), "user data");
    #[cfg(unix)]
    {
        let target = d.join("target");
        std::fs::create_dir(&target).unwrap();
        std::fs::write(target.join(MARKER), format!("{MARKER_TEXT}\n{FILES}\n")).unwrap();
        std::os::unix::fs::symlink(&target, d.join("l")).unwrap();
        assert!(write_dir(d, "l", ANY, |_| Ok(())).is_err());
        assert!(target.join(MARKER).exists());
    }
}

#[test]
fn concurrent_writers_never_collide() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    std::thread::scope(|s| {
        for k in 0..8 {
            s.spawn(move || {
                write_dir(d, "same", ANY, |s| s.last("k", k.to_string().as_bytes())).unwrap();
            });
        }
    });
    assert!(is_ours(&d.join("same")));
    assert_eq!(names(d), ["same"], "temporary folders left behind");
}

/// Issue 33 item 2: a temporary folder left by a killed run (marker, dead writer) is removed
/// by the next run into the same folder; one of a live process, or without the marker, stays.
#[test]
fn stale_temporary_folders_of_dead_processes_are_removed() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    // a process that is gone: a child that has exited and been reaped
    let mut child = std::process::Command::new("true").spawn().unwrap();
    let dead = child.id();
    child.wait().unwrap();
    let stale = d.join(format!(".x.tmp-{dead}-0-0"));
    std::fs::create_dir(&stale).unwrap();
    std::fs::write(stale.join(MARKER), format!("{MARKER_TEXT}\n{WRITER}{dead} 1\n")).unwrap();
    std::fs::write(stale.join("trajectory.csv"), "big").unwrap();
    // our own (live) temporary folder, and a user's hidden folder without the marker
    let live = d.join(format!(".y.tmp-{}-0-0", std::process::id()));
    std::fs::create_dir(&live).unwrap();
    std::fs::write(live.join(MARKER), marker_text(None)).unwrap();
    let user = d.join(format!(".z.tmp-{dead}-0-0"));
    std::fs::create_dir(&user).unwrap();
    std::fs::write(user.join("keep"), "mine").unwrap();
    write_dir(d, "other", ANY, one("a", "1")).unwrap();
    assert!(!stale.exists(), "stale folder of a dead process kept");
    assert!(live.exists() && user.join("keep").exists());
    assert_eq!(temp_pid(".a.b.tmp-123-4-5"), Some(123));
    assert_eq!(temp_pid("a.tmp-123-4-5"), None);
}

#[test]
fn in_place_files_join_the_manifest() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    write_dir(d, "s", ANY, one("trajectory.csv", "t")).unwrap();
    write_files(d, "s", ANY, &[("linearization.json", "{}".to_string())]).unwrap();
    let m = read_marker(&d.join("s")).unwrap().files.unwrap();
    assert_eq!(m, ["trajectory.csv", "linearization.json"]);
    // both are ours: the next run replaces the folder
    write_dir(d, "s", ANY, one("trajectory.csv", "u")).unwrap();
    assert!(!d.join("s/linearization.json").exists());
    // over the budget: refused before anything is written
    let e =
        write_files(d, "s", Limits { max_bytes: 3, reserve: 0 }, &[("a", "1234".to_string())]).unwrap_err();
    assert!(e.to_string().contains("max_output_bytes = 3"), "{e}");
}

#[test]
fn file_stems_are_unique() {
    let mut taken = vec![];
    assert_eq!(file_stem("position:a.b", &mut taken), "position_a_b");
    assert_eq!(file_stem("position:a_b", &mut taken), "position_a_b_2");
}
