//! The marker file of an output folder: the folder is vectrix's, which process writes it
//! (pid and start time, so a temporary folder of a killed run can be told from one in use),
//! and, once complete, the manifest of every file written. Also the removal of the temporary
//! folders of processes that are gone.
//!
//! Book: — (reporting).

use std::path::Path;

use super::{MARKER, MARKER_TEXT};

/// The marker line naming the writing process: `writer <pid> <start>`.
pub(super) const WRITER: &str = "writer ";
/// The marker line after which the manifest lists one written file per line.
pub(super) const FILES: &str = "files:";
/// Largest marker read (a manifest of 10 000 sweep runs is a few megabytes).
const MAX_MARKER_BYTES: usize = 64 << 20;
/// Entries of a parent folder looked at for stale temporary folders.
const MAX_SCAN: usize = 100_000;

/// A marker read back: the writing process and the manifest (`None` in the marker of an
/// earlier vectrix, which listed no files).
pub(super) struct Marker {
    pub writer: Option<(u32, u64)>,
    pub files: Option<Vec<String>>,
}

/// The marker of `dir`, when `dir` is a real folder (not a link) holding one.
pub(super) fn read_marker(dir: &Path) -> Option<Marker> {
    let meta = std::fs::symlink_metadata(dir).ok()?;
    if !meta.is_dir() {
        return None;
    }
    let path = dir.join(MARKER);
    if !std::fs::symlink_metadata(&path).ok()?.is_file() {
        return None;
    }
    let file = std::fs::File::open(&path).ok()?;
    let bytes = crate::input::read_capped(file, MAX_MARKER_BYTES).ok()?.ok()?;
    let text = String::from_utf8(bytes).ok()?;
    let mut lines = text.lines();
    if lines.next() != Some(MARKER_TEXT) {
        return None;
    }
    let mut marker = Marker { writer: None, files: None };
    for line in lines.by_ref() {
        if let Some(w) = line.strip_prefix(WRITER) {
            let mut it = w.split(' ').map(str::parse::<u64>);
            if let (Some(Ok(pid)), Some(Ok(start))) = (it.next(), it.next()) {
                marker.writer = u32::try_from(pid).ok().map(|p| (p, start));
            }
        } else if line == FILES {
            // only plain relative paths: a hand-edited manifest cannot point outside the folder
            marker.files = Some(lines.by_ref().filter(|l| plain_relative(l)).map(String::from).collect());
            break;
        }
    }
    Some(marker)
}

/// `a/b.csv`: segments that are plain names (no `..`, `.`, empty segment, backslash or NUL).
fn plain_relative(path: &str) -> bool {
    !path.is_empty()
        && path.split('/').all(|s| !s.is_empty() && s != "." && s != ".." && !s.contains(['\\', '\0']))
}

/// Whether `dir` is a folder vectrix wrote (a real folder, not a link, holding the marker).
#[cfg(test)]
pub(crate) fn is_ours(dir: &Path) -> bool {
    read_marker(dir).is_some()
}

/// The marker's text: the first line, this process, and the manifest when given.
pub(super) fn marker_text(files: Option<&[String]>) -> String {
    let mut s = format!(
        "{MARKER_TEXT}\n{WRITER}{} {}\n",
        std::process::id(),
        start_time(std::process::id()).unwrap_or(0)
    );
    if let Some(files) = files {
        s.push_str(FILES);
        s.push('\n');
        for f in files {
            s.push_str(f);
            s.push('\n');
        }
    }
    s
}

/// The start time of process `pid` (clock ticks since boot, `/proc/<pid>/stat` field 22):
/// with the pid it names one process, even after the pid is reused.
#[cfg(target_os = "linux")]
fn start_time(pid: u32) -> Option<u64> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // the command name (field 2) is in parentheses and may hold spaces: count after the last `)`
    let rest = &stat[stat.rfind(')')? + 1..];
    rest.split_whitespace().nth(19)?.parse().ok()
}

#[cfg(not(target_os = "linux"))]
fn start_time(_: u32) -> Option<u64> {
    None
}

/// Whether the process that wrote a temporary folder may still be writing it: `pid` from
/// the folder's name, `writer` from its marker (pid and start time).
fn alive(pid: u32, writer: Option<(u32, u64)>) -> bool {
    if pid == std::process::id() {
        return true;
    }
    if start_time(std::process::id()).is_some() {
        // Linux with /proc: gone when its stat is gone, or when the pid now names a process
        // started at another time than the writer
        return match (start_time(pid), writer) {
            (None, _) => false,
            (Some(now), Some((w, then))) if w == pid && then != 0 => now == then,
            (Some(_), _) => true,
        };
    }
    #[cfg(unix)]
    {
        let Ok(p) = libc::pid_t::try_from(pid) else { return true };
        // SAFETY: kill with signal 0 only checks that the process exists
        let r = unsafe { libc::kill(p, 0) };
        r == 0 || std::io::Error::last_os_error().raw_os_error() != Some(libc::ESRCH)
    }
    #[cfg(not(unix))]
    {
        let _ = writer;
        true // cannot tell: never remove
    }
}

/// The pid in a temporary folder's name `.<name>.tmp-<pid>-<n>-<nanos>`.
pub(super) fn temp_pid(file_name: &str) -> Option<u32> {
    if !file_name.starts_with('.') {
        return None;
    }
    let (_, tail) = file_name.rsplit_once(".tmp-")?;
    tail.split('-').next()?.parse().ok()
}

/// Removes the temporary folders in `parent` that carry the marker and whose writing process
/// is gone (a run killed while writing, or stopped by a second Ctrl-C). Returns their names.
pub(crate) fn remove_stale_temps(parent: &Path) -> Vec<String> {
    let mut removed = Vec::new();
    let Ok(entries) = std::fs::read_dir(parent) else { return removed };
    for entry in entries.take(MAX_SCAN).flatten() {
        let name = entry.file_name();
        let Some(name) = name.to_str() else { continue };
        let Some(pid) = temp_pid(name) else { continue };
        let path = entry.path();
        // a real folder with the marker (read_marker does not follow links)
        let Some(marker) = read_marker(&path) else { continue };
        if !alive(pid, marker.writer) && std::fs::remove_dir_all(&path).is_ok() {
            removed.push(name.to_string());
        }
    }
    removed
}
