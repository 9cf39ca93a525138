//! Scene output folders, written so that vectrix never deletes or replaces what it did not
//! create and never writes outside the folder the user named:
//!
//! * the folder name is a validated scene name (a plain file name: no separator, no `..`);
//! * everything is written into a fresh temporary sibling (`.<name>.tmp-<pid>-…`, created new,
//!   never reused), which carries the marker file [`MARKER`] from its creation on, naming the
//!   process that writes it;
//! * when the folder is complete, the marker lists every file written (the manifest), and the
//!   temporary folder takes the place of `<out>/<name>`: by a rename when nothing is there, by
//!   an atomic exchange when a previous vectrix output is there — a folder with the marker,
//!   holding nothing its manifest does not list — and never when anything else is there: a
//!   folder without the marker, a marker without a manifest (an earlier vectrix), or any file
//!   or folder vectrix did not write (the run is refused before it starts and names them,
//!   nothing is touched);
//! * the previous output is deleted file by file from its manifest, so a file that appeared in
//!   it meanwhile is never deleted; a failed run removes only its own temporary folder, so the
//!   previous good output stays;
//! * temporary folders that carry the marker and whose process is gone (killed, or stopped by
//!   a second Ctrl-C) are removed by the next run into the same parent folder.
//!
//! Book: — (reporting).

use std::collections::BTreeSet;
use std::io::ErrorKind;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use vectrix_scene::check_name;

use crate::sink::{Halt, Limits, Sink};

mod marker;

#[cfg(test)]
pub(crate) use marker::is_ours;
use marker::{Marker, marker_text, read_marker, remove_stale_temps};

/// The marker file in every folder vectrix writes; its first line is [`MARKER_TEXT`].
pub(crate) const MARKER: &str = ".vectrix-output";
/// The marker's first line.
pub(crate) const MARKER_TEXT: &str = "vectrix output folder: replaced by the next run of the same scene";

/// Files named in a refusal (the rest are counted).
const MAX_NAMED: usize = 8;

/// Attempts at claiming the destination against concurrent writers before giving up.
const CLAIM_ATTEMPTS: usize = 16;

pub(crate) use crate::sink::BoxError;

/// A fresh temporary sibling `<parent>/.<name>.tmp-<pid>-<n>-<nanos>`, created here (never
/// reused), holding the marker with this process as its writer.
fn fresh_temp(parent: &Path, name: &str) -> Result<PathBuf, BoxError> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    for _ in 0..CLAIM_ATTEMPTS {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.subsec_nanos());
        let tmp = parent.join(format!(".{name}.tmp-{}-{n}-{nanos}", std::process::id()));
        match std::fs::create_dir(&tmp) {
            Ok(()) => {
                if let Err(e) = std::fs::write(tmp.join(MARKER), marker_text(None)) {
                    let _ = std::fs::remove_dir_all(&tmp);
                    return Err(format!("cannot write {}: {e}", tmp.join(MARKER).display()).into());
                }
                return Ok(tmp);
            }
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

/// What a finished [`write_dir`] wrote.
pub(crate) struct Written {
    /// `<parent>/<name>`.
    pub dest: PathBuf,
    /// Why writing stopped before every file was written (Ctrl-C, the byte budget).
    pub halt: Option<Halt>,
    /// Bytes written, the marker included.
    pub bytes: u64,
    /// The files written (relative paths), the marker aside.
    pub files: Vec<String>,
}

/// The `--out` folder that cannot be made says why in the user's words, with its path.
fn out_folder_error(parent: &Path, e: &std::io::Error) -> String {
    let shown = parent.display();
    let why = match std::fs::symlink_metadata(parent) {
        Ok(m) if m.file_type().is_symlink() && std::fs::metadata(parent).is_err() => {
            "is a symbolic link that leads nowhere (or in a loop)".to_string()
        }
        Ok(m) if !m.is_dir() => "is not a folder (a file or a device is there)".to_string(),
        _ => match e.kind() {
            std::io::ErrorKind::PermissionDenied => "cannot be created: permission denied".to_string(),
            _ => format!("cannot be created ({e})"),
        },
    };
    format!("--out {shown} {why}; valid: a folder, or a path where one can be created")
}

/// Creates `<parent>/<name>/` (see the module doc): `fill` writes through a [`Sink`] into a
/// fresh temporary folder that takes the place of the destination only when it succeeded.
///
/// # Errors
/// An invalid name, a destination that vectrix may not replace, I/O errors, a manifest over
/// the byte budget; in every case nothing outside this run's temporary folder was changed.
pub(crate) fn write_dir(
    parent: &Path,
    name: &str,
    limits: Limits,
    fill: impl FnOnce(&Sink) -> Result<(), BoxError>,
) -> Result<Written, BoxError> {
    preflight(parent, name)?;
    let dest = parent.join(name);
    std::fs::create_dir_all(parent).map_err(|e| out_folder_error(parent, &e))?;
    remove_stale_temps(parent);
    let tmp = fresh_temp(parent, name)?;
    let sink = Sink::new(&tmp, limits);
    let filled = fill(&sink).and_then(|()| {
        let text = marker_text(Some(&sink.files()));
        sink.account(&tmp.join(MARKER), text.len() as u64)?;
        std::fs::write(tmp.join(MARKER), text)?;
        Ok(())
    });
    if let Err(e) = filled {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    match claim(&tmp, &dest) {
        Ok(()) => Ok(Written { dest, halt: sink.halt(), bytes: sink.bytes(), files: sink.files() }),
        Err(e) => {
            let _ = std::fs::remove_dir_all(&tmp);
            Err(e)
        }
    }
}

/// Checks before a run that its output could be written: a valid name, and nothing at
/// `<parent>/<name>` that vectrix may not replace (so a long run is not wasted).
///
/// # Errors
/// As [`write_dir`].
pub(crate) fn preflight(parent: &Path, name: &str) -> Result<(), BoxError> {
    check_name(name, "output folder name", true)?;
    replaceable(&parent.join(name)).map_err(Into::into)
}

/// Refuses to write where the scene file itself lies inside the folder the run would replace
/// (a run never deletes its own input).
///
/// # Errors
/// A message naming both paths.
pub(crate) fn not_inside(input: &Path, parent: &Path, name: &str) -> Result<(), BoxError> {
    let dest = parent.join(name);
    let (Ok(i), Ok(d)) = (input.canonicalize(), dest.canonicalize()) else { return Ok(()) };
    if i.starts_with(&d) {
        return Err(format!(
            "refusing to write {}: the scene file {} is inside it, and the run would replace that folder; valid: \
             keep scene files outside the output folder (move it, or use another --out)",
            dest.display(),
            input.display()
        )
        .into());
    }
    Ok(())
}

/// `Ok` when nothing is at `dest`, or a folder vectrix wrote that holds only the files its
/// manifest lists; otherwise the refusal, naming what vectrix did not write.
fn replaceable(dest: &Path) -> Result<(), String> {
    if std::fs::symlink_metadata(dest).is_err() {
        return Ok(());
    }
    let Some(marker) = read_marker(dest) else {
        return Err(format!(
            "refusing to replace {}: it exists and vectrix did not write it (no {MARKER} marker); valid: another \
             --out folder or another scene name",
            dest.display()
        ));
    };
    let Some(files) = marker.files else {
        return Err(format!(
            "refusing to replace {}: its {MARKER} marker lists no files (an output of an earlier vectrix), so its \
             files cannot be told from yours; valid: delete that folder yourself, or another --out folder",
            dest.display()
        ));
    };
    let foreign = foreign(dest, &files).map_err(|e| format!("cannot inspect {}: {e}", dest.display()))?;
    if foreign.is_empty() {
        return Ok(());
    }
    let mut named: Vec<&str> = foreign.iter().take(MAX_NAMED).map(String::as_str).collect();
    let more = if foreign.len() > MAX_NAMED { " and more" } else { "" };
    named.sort_unstable();
    Err(format!(
        "refusing to replace {}: it holds files vectrix did not write: {}{more}; valid: move them out of that \
         folder, or another --out folder or scene name",
        dest.display(),
        named.join(", ")
    ))
}

/// The entries of `dir` (relative paths, folders with a trailing `/`) that its manifest
/// `files` does not list, at most [`MAX_NAMED`] + 1; links and special files always count.
fn foreign(dir: &Path, files: &[String]) -> std::io::Result<Vec<String>> {
    let listed: BTreeSet<&str> = files.iter().map(String::as_str).collect();
    let mut folders: BTreeSet<String> = BTreeSet::new();
    for f in files {
        let mut p = f.as_str();
        while let Some((head, _)) = p.rsplit_once('/') {
            folders.insert(head.to_string());
            p = head;
        }
    }
    let mut out = Vec::new();
    let mut stack = vec![(String::new(), dir.to_path_buf())];
    while let Some((prefix, path)) = stack.pop() {
        for entry in std::fs::read_dir(&path)? {
            let entry = entry?;
            let name = entry.file_name().to_string_lossy().into_owned();
            let rel = format!("{prefix}{name}");
            if rel == MARKER {
                continue;
            }
            let t = entry.file_type()?;
            if t.is_dir() && folders.contains(&rel) {
                stack.push((format!("{rel}/"), entry.path()));
            } else if t.is_dir() {
                out.push(format!("{rel}/"));
            } else if !(t.is_file() && listed.contains(rel.as_str())) {
                out.push(rel);
            }
            if out.len() > MAX_NAMED {
                return Ok(out);
            }
        }
    }
    Ok(out)
}

/// Deletes a previous output (moved to `old`) file by file from its manifest, then its
/// folders and marker; a folder that is not empty then (something appeared in it) is kept
/// and renamed visibly next to `dest`.
fn remove_listed(old: &Path, dest: &Path) {
    let Some(Marker { files: Some(files), .. }) = read_marker(old) else { return };
    let mut folders: BTreeSet<&str> = BTreeSet::new();
    for f in &files {
        let _ = std::fs::remove_file(old.join(f));
        let mut p = f.as_str();
        while let Some((head, _)) = p.rsplit_once('/') {
            folders.insert(head);
            p = head;
        }
    }
    // deepest first
    let mut folders: Vec<&str> = folders.into_iter().collect();
    folders.sort_by_key(|f| std::cmp::Reverse(f.matches('/').count()));
    for f in folders {
        let _ = std::fs::remove_dir(old.join(f));
    }
    let _ = std::fs::remove_file(old.join(MARKER));
    if std::fs::remove_dir(old).is_err() {
        let name = dest.file_name().and_then(|n| n.to_str()).unwrap_or("output");
        let kept = dest.with_file_name(format!("{name}.kept-{}", std::process::id()));
        let _ = std::fs::rename(old, kept);
    }
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
            Ok(_) => {
                replaceable(dest)?;
                if exchange(tmp, dest)? {
                    // tmp now holds the previous output: a file that appeared in it since the
                    // check above puts it back, and the run is refused
                    if let Err(e) = replaceable(tmp) {
                        exchange(tmp, dest)?;
                        return Err(e
                            .replace(&tmp.display().to_string(), &dest.display().to_string())
                            .into());
                    }
                    remove_listed(tmp, dest);
                    return Ok(());
                }
                // no atomic exchange here: move the old output aside, then ours in
                let parent = dest.parent().unwrap_or(Path::new("."));
                let name = dest.file_name().and_then(|n| n.to_str()).unwrap_or("output");
                let old = fresh_temp(parent, &format!("{name}.old"))?;
                std::fs::remove_dir_all(&old)?;
                match std::fs::rename(dest, &old) {
                    Ok(()) => {}
                    Err(e) if e.kind() == ErrorKind::NotFound => continue,
                    Err(e) => return Err(e.into()),
                }
                if let Err(e) = replaceable(&old) {
                    std::fs::rename(&old, dest)?;
                    return Err(e.replace(&old.display().to_string(), &dest.display().to_string()).into());
                }
                let placed = std::fs::rename(tmp, dest);
                remove_listed(&old, dest);
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

/// Writes `files` into `<parent>/<name>/`: into the folder of an earlier vectrix run (which
/// then holds both) replacing only these files, else into a new folder as [`write_dir`] does.
/// The manifest lists the new files before they are written, so that an interrupted update
/// leaves nothing unlisted.
///
/// # Errors
/// As [`write_dir`]; a total over `limits.max_bytes` before anything is written.
pub(crate) fn write_files(
    parent: &Path,
    name: &str,
    limits: Limits,
    files: &[(&str, String)],
) -> Result<PathBuf, BoxError> {
    let total: u64 = files.iter().map(|(_, t)| t.len() as u64).sum();
    if total > limits.max_bytes {
        let list: Vec<String> = files.iter().map(|(f, t)| format!("{f} {} bytes", t.len())).collect();
        return Err(format!(
            "{} would take {total} bytes ({}); valid: at most max_output_bytes = {} (--max-output-bytes)",
            parent.join(name).display(),
            list.join(", "),
            limits.max_bytes
        )
        .into());
    }
    preflight(parent, name)?;
    let dest = parent.join(name);
    let Some(Marker { files: Some(mut listed), .. }) = read_marker(&dest) else {
        let w = write_dir(parent, name, limits, |sink| {
            for (file, text) in files {
                sink.last(file, text.as_bytes())?;
            }
            Ok(())
        })?;
        return Ok(w.dest);
    };
    for (file, _) in files {
        if !listed.iter().any(|l| l == file) {
            listed.push((*file).to_string());
        }
    }
    replace_file(&dest, MARKER, &marker_text(Some(&listed)))?;
    for (file, text) in files {
        replace_file(&dest, file, text)?;
    }
    Ok(dest)
}

/// Replaces `dir/file` by a rename from a fresh sibling, so a reader sees the old or the new
/// file (created new: never a file or link that was already there).
fn replace_file(dir: &Path, file: &str, text: &str) -> Result<(), BoxError> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let tmp = dir.join(format!(".{file}.partial-{}-{n}", std::process::id()));
    let mut f = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&tmp)
        .map_err(|e| format!("cannot create {}: {e}", tmp.display()))?;
    let written = std::io::Write::write_all(&mut f, text.as_bytes());
    drop(f);
    if let Err(e) = written.and_then(|()| std::fs::rename(&tmp, dir.join(file))) {
        let _ = std::fs::remove_file(&tmp);
        return Err(format!("cannot write {}: {e}", dir.join(file).display()).into());
    }
    Ok(())
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
mod tests;
