//! Scene output folders, written so that vectrix never deletes or replaces what it did not
//! create and never writes outside the folder the user named:
//!
//! * the folder name is a validated scene name (a plain file name: no separator, no `..`);
//! * everything is written into a fresh temporary sibling (`.<name>.tmp-…`, created new, never
//!   reused), which carries a marker file, [`MARKER`];
//! * the temporary folder then takes the place of `<out>/<name>`: by a rename when nothing is
//!   there, by an atomic exchange when a previous vectrix output is there (it carries the
//!   marker), and never when anything else is there (the run is refused, nothing is touched);
//! * a failed run removes only its own temporary folder, so the previous good output stays.
//!
//! Book: — (reporting).

use std::io::ErrorKind;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use vectrix_scene::check_name;

/// The marker file in every folder vectrix writes; its first line is [`MARKER_TEXT`].
pub(crate) const MARKER: &str = ".vectrix-output";
/// The marker's first line.
pub(crate) const MARKER_TEXT: &str = "vectrix output folder: replaced by the next run of the same scene";

/// Attempts at claiming the destination against concurrent writers before giving up.
const CLAIM_ATTEMPTS: usize = 16;

/// Boxed error of the command line.
pub(crate) type BoxError = Box<dyn std::error::Error + Send + Sync>;

/// Whether `dir` is a folder vectrix wrote (a real folder, not a link, holding the marker).
pub(crate) fn is_ours(dir: &Path) -> bool {
    let Ok(meta) = std::fs::symlink_metadata(dir) else { return false };
    if !meta.is_dir() {
        return false;
    }
    let marker = dir.join(MARKER);
    match std::fs::symlink_metadata(&marker) {
        Ok(m) if m.is_file() => std::fs::read_to_string(&marker).is_ok_and(|t| t.starts_with(MARKER_TEXT)),
        _ => false,
    }
}

/// A fresh temporary sibling `<parent>/.<name>.tmp-<pid>-<n>`, created here (never reused).
fn fresh_temp(parent: &Path, name: &str) -> Result<PathBuf, BoxError> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    for _ in 0..CLAIM_ATTEMPTS {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.subsec_nanos());
        let tmp = parent.join(format!(".{name}.tmp-{}-{n}-{nanos}", std::process::id()));
        match std::fs::create_dir(&tmp) {
            Ok(()) => return Ok(tmp),
            Err(e) if e.kind() == ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(format!("cannot create {}: {e}", tmp.display()).into()),
        }
    }
    Err(format!("cannot create a temporary folder in {}", parent.display()).into())
}

/// Swaps two paths atomically (Linux `renameat2(RENAME_EXCHANGE)`); `Ok(false)` where the
/// system cannot.
#[cfg(target_os = "linux")]
fn exchange(a: &Path, b: &Path) -> std::io::Result<bool> {
    use std::os::unix::ffi::OsStrExt;
    let ca = std::ffi::CString::new(a.as_os_str().as_bytes())?;
    let cb = std::ffi::CString::new(b.as_os_str().as_bytes())?;
    // SAFETY: two valid NUL-terminated paths; renameat2 only reads them.
    let r = unsafe {
        libc::renameat2(libc::AT_FDCWD, ca.as_ptr(), libc::AT_FDCWD, cb.as_ptr(), libc::RENAME_EXCHANGE)
    };
    if r == 0 {
        return Ok(true);
    }
    let e = std::io::Error::last_os_error();
    match e.raw_os_error() {
        Some(libc::ENOSYS) | Some(libc::EINVAL) => Ok(false),
        _ => Err(e),
    }
}

#[cfg(not(target_os = "linux"))]
fn exchange(_: &Path, _: &Path) -> std::io::Result<bool> {
    Ok(false)
}

/// Creates `<parent>/<name>/` (see the module doc): `fill` writes into a fresh temporary
/// folder that takes the place of the destination only when it succeeded. Returns the path.
///
/// # Errors
/// An invalid name, a destination that vectrix did not write, I/O errors; in every case
/// nothing outside this run's temporary folder was changed.
pub(crate) fn write_dir(
    parent: &Path,
    name: &str,
    fill: impl FnOnce(&Path) -> Result<(), BoxError>,
) -> Result<PathBuf, BoxError> {
    preflight(parent, name)?;
    let dest = parent.join(name);
    std::fs::create_dir_all(parent).map_err(|e| format!("cannot create {}: {e}", parent.display()))?;
    let tmp = fresh_temp(parent, name)?;
    let filled = fill(&tmp).and_then(|()| {
        std::fs::write(tmp.join(MARKER), format!("{MARKER_TEXT}\n"))?;
        Ok(())
    });
    if let Err(e) = filled {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    match claim(&tmp, &dest) {
        Ok(()) => Ok(dest),
        Err(e) => {
            let _ = std::fs::remove_dir_all(&tmp);
            Err(e)
        }
    }
}

/// Checks before a run that its output could be written: a valid name, and nothing at
/// `<parent>/<name>` that vectrix did not write (so a long run is not wasted).
///
/// # Errors
/// As [`write_dir`].
pub(crate) fn preflight(parent: &Path, name: &str) -> Result<(), BoxError> {
    check_name(name, "output folder name", true)?;
    let dest = parent.join(name);
    if std::fs::symlink_metadata(&dest).is_ok() && !is_ours(&dest) {
        return Err(refusal(&dest).into());
    }
    Ok(())
}

fn refusal(dest: &Path) -> String {
    format!(
        "refusing to replace {}: it exists and vectrix did not write it (no {MARKER} marker); valid: another \
         --out folder or another scene name",
        dest.display()
    )
}

/// Puts the finished temporary folder in the destination's place.
fn claim(tmp: &Path, dest: &Path) -> Result<(), BoxError> {
    for _ in 0..CLAIM_ATTEMPTS {
        match std::fs::symlink_metadata(dest) {
            Err(e) if e.kind() == ErrorKind::NotFound => match std::fs::rename(tmp, dest) {
                Ok(()) => return Ok(()),
                // a concurrent run created it meanwhile: look again
                Err(e) if matches!(e.kind(), ErrorKind::AlreadyExists | ErrorKind::DirectoryNotEmpty) => {
                    continue;
                }
                Err(e) => {
                    return Err(format!("cannot rename {} to {}: {e}", tmp.display(), dest.display()).into());
                }
            },
            Err(e) => return Err(format!("cannot inspect {}: {e}", dest.display()).into()),
            Ok(_) if !is_ours(dest) => return Err(refusal(dest).into()),
            Ok(_) => {
                if exchange(tmp, dest)? {
                    // tmp now holds the previous output: remove it only if it is ours
                    if is_ours(tmp) {
                        let _ = std::fs::remove_dir_all(tmp);
                    }
                    return Ok(());
                }
                // no atomic exchange here: move the old output aside, then ours in
                let parent = dest.parent().unwrap_or(Path::new("."));
                let name = dest.file_name().and_then(|n| n.to_str()).unwrap_or("output");
                let old = fresh_temp(parent, &format!("{name}.old"))?;
                std::fs::remove_dir(&old)?;
                match std::fs::rename(dest, &old) {
                    Ok(()) => {}
                    Err(e) if e.kind() == ErrorKind::NotFound => continue,
                    Err(e) => return Err(e.into()),
                }
                let placed = std::fs::rename(tmp, dest);
                if is_ours(&old) {
                    let _ = std::fs::remove_dir_all(&old);
                }
                match placed {
                    Ok(()) => return Ok(()),
                    Err(e) if matches!(e.kind(), ErrorKind::AlreadyExists | ErrorKind::DirectoryNotEmpty) => {
                        continue;
                    }
                    Err(e) => return Err(e.into()),
                }
            }
        }
    }
    Err(format!("{} kept changing while this run tried to write it (concurrent runs)", dest.display()).into())
}

/// File-name form of an output name (`position:a` → `position_a`), unique among `taken`.
pub(crate) fn file_stem(o: &str, taken: &mut Vec<String>) -> String {
    let base: String =
        o.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' || c == '-' { c } else { '_' }).collect();
    let mut stem = base.clone();
    let mut k = 2;
    while taken.contains(&stem) {
        stem = format!("{base}_{k}");
        k += 1;
    }
    taken.push(stem.clone());
    stem
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(tag: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("vectrix-output-test-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn replaces_only_its_own_folders() {
        let d = scratch("own");
        // a user's folder of the same name is refused and left as it was
        std::fs::create_dir(d.join("src")).unwrap();
        std::fs::write(d.join("src/lib.rs"), "fn main() {}").unwrap();
        let e = write_dir(&d, "src", |t| Ok(std::fs::write(t.join("a"), "1")?)).unwrap_err();
        assert!(e.to_string().contains("refusing"), "{e}");
        assert_eq!(std::fs::read_to_string(d.join("src/lib.rs")).unwrap(), "fn main() {}");
        // a folder of ours is replaced
        let p = write_dir(&d, "scene", |t| Ok(std::fs::write(t.join("a"), "1")?)).unwrap();
        write_dir(&d, "scene", |t| Ok(std::fs::write(t.join("b"), "2")?)).unwrap();
        assert!(!p.join("a").exists() && p.join("b").exists() && is_ours(&p));
        // a failed run keeps the previous output and leaves no temporary folder
        let e = write_dir(&d, "scene", |_| Err("boom".into())).unwrap_err();
        assert_eq!(e.to_string(), "boom");
        assert!(p.join("b").exists());
        let names: Vec<String> =
            std::fs::read_dir(&d).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
        assert_eq!(names.len(), 2, "{names:?}");
        // names that are not plain file names are refused before anything is written
        for bad in ["", ".", "..", "../x", "/etc", "a/b"] {
            assert!(write_dir(&d, bad, |_| Ok(())).is_err(), "{bad:?}");
        }
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_file_or_link_in_the_way_is_refused() {
        let d = scratch("link");
        std::fs::write(d.join("f"), "user data").unwrap();
        assert!(write_dir(&d, "f", |_| Ok(())).is_err());
        assert_eq!(std::fs::read_to_string(d.join("f")).unwrap(), "user data");
        #[cfg(unix)]
        {
            let target = d.join("target");
            std::fs::create_dir(&target).unwrap();
            std::fs::write(target.join(MARKER), MARKER_TEXT).unwrap();
            std::os::unix::fs::symlink(&target, d.join("l")).unwrap();
            assert!(write_dir(&d, "l", |_| Ok(())).is_err());
            assert!(target.join(MARKER).exists());
        }
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn concurrent_writers_never_collide() {
        let d = scratch("race");
        std::thread::scope(|s| {
            for k in 0..8 {
                let d = &d;
                s.spawn(move || {
                    write_dir(d, "same", |t| Ok(std::fs::write(t.join("k"), k.to_string())?)).unwrap();
                });
            }
        });
        assert!(is_ours(&d.join("same")));
        let names: Vec<String> =
            std::fs::read_dir(&d).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
        assert_eq!(names, vec!["same".to_string()], "temporary folders left behind");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn file_stems_are_unique() {
        let mut taken = vec![];
        assert_eq!(file_stem("position:a.b", &mut taken), "position_a_b");
        assert_eq!(file_stem("position:a_b", &mut taken), "position_a_b_2");
    }
}
