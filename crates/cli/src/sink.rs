//! Where a command writes its files: a temporary folder (see [`crate::output`]), with a byte
//! budget counted as the bytes go out and a watch on Ctrl-C (and SIGTERM).
//!
//! Data files (the trajectory, the figures) go through [`Sink::data`]: once the budget would
//! be exceeded or an interrupt arrives, the file in progress is removed and every later data
//! file is skipped, so what was written is whole. Summaries (summary.json, sweep.csv, the
//! marker) go through [`Sink::last`]: they are small, the budget keeps room for them
//! ([`Limits::reserve`]), and they are always written, so that a summary says what is missing
//! and that the run is not complete.
//!
//! Book: — (reporting).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Boxed error of the command line.
pub(crate) type BoxError = Box<dyn std::error::Error + Send + Sync>;

/// Default bound on the bytes one command writes (`--max-output-bytes`): 1 GiB.
pub const DEFAULT_MAX_OUTPUT_BYTES: u64 = 1 << 30;

/// Bytes written between two looks at the interrupt flag inside one file.
const CHUNK: usize = 1 << 20;

/// The byte budget of one command's output.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Limits {
    /// Most bytes written in all (every file, the marker included).
    pub max_bytes: u64,
    /// Bytes kept for the summaries: data files stop at `max_bytes − reserve`.
    pub reserve: u64,
}

/// Why a sink stopped writing data files.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Halt {
    /// Ctrl-C or SIGTERM while writing.
    Interrupted,
    /// The next file would have exceeded the byte budget.
    Budget,
}

impl Halt {
    /// The reason as written in summaries.
    pub fn name(self) -> &'static str {
        match self {
            Halt::Interrupted => "interrupted",
            Halt::Budget => "max_output_bytes",
        }
    }
}

/// A temporary folder being filled (shared between threads: a sweep writes its runs in
/// parallel).
pub(crate) struct Sink {
    root: PathBuf,
    limits: Limits,
    written: AtomicU64,
    files: Mutex<Vec<String>>,
    halt: Mutex<Option<Halt>>,
    /// The interrupt flag, watched only when it was clear as writing began (a run that Ctrl-C
    /// stopped still writes what it computed; a second Ctrl-C ends the process).
    cancel: Option<&'static AtomicBool>,
}

impl Sink {
    /// A sink writing below `root`, watching the process's interrupt flag.
    pub fn new(root: &Path, limits: Limits) -> Self {
        let flag = crate::interrupt::interrupted();
        let cancel = (!flag.load(Ordering::SeqCst)).then_some(flag);
        Self::with_cancel(root, limits, cancel)
    }

    /// A sink watching `cancel` (tests give their own flag).
    pub fn with_cancel(root: &Path, limits: Limits, cancel: Option<&'static AtomicBool>) -> Self {
        Self {
            root: root.to_path_buf(),
            limits,
            written: AtomicU64::new(0),
            files: Mutex::new(Vec::new()),
            halt: Mutex::new(None),
            cancel,
        }
    }

    /// Why data files stopped being written, if they did.
    pub fn halt(&self) -> Option<Halt> {
        self.halt.lock().map_or(Some(Halt::Interrupted), |h| *h)
    }

    fn set_halt(&self, h: Halt) {
        if let Ok(mut g) = self.halt.lock() {
            g.get_or_insert(h);
        }
    }

    fn interrupted(&self) -> bool {
        self.cancel.is_some_and(|c| c.load(Ordering::SeqCst))
    }

    /// The whole budget.
    pub fn max_bytes(&self) -> u64 {
        self.limits.max_bytes
    }

    /// Bytes written so far.
    pub fn bytes(&self) -> u64 {
        self.written.load(Ordering::SeqCst)
    }

    /// Every file written, relative to the root (`run-000/trajectory.csv`), in order.
    pub fn files(&self) -> Vec<String> {
        self.files.lock().map(|f| f.clone()).unwrap_or_default()
    }

    /// Counts `n` more bytes for `path` against the whole budget.
    ///
    /// # Errors
    /// When they do not fit.
    pub fn account(&self, path: &Path, n: u64) -> Result<(), BoxError> {
        let before = self.written.fetch_add(n, Ordering::SeqCst);
        if before.saturating_add(n) > self.limits.max_bytes {
            self.written.fetch_sub(n, Ordering::SeqCst);
            return Err(format!(
                "writing {} would exceed max_output_bytes = {} ({before} bytes written); valid: a larger \
                 --max-output-bytes, or fewer samples or outputs",
                path.display(),
                self.limits.max_bytes
            )
            .into());
        }
        Ok(())
    }

    /// Creates the folder `rel` below the root.
    ///
    /// # Errors
    /// I/O errors.
    pub fn dir(&self, rel: &str) -> Result<(), BoxError> {
        let p = self.root.join(rel);
        std::fs::create_dir(&p).map_err(|e| format!("cannot create {}: {e}", p.display()).into())
    }

    /// Writes the data file `rel`, unless writing has halted or halts now (Ctrl-C, the
    /// budget): then nothing of it stays and `Ok(false)` says it was skipped.
    ///
    /// # Errors
    /// I/O errors.
    pub fn data(&self, rel: &str, bytes: &[u8]) -> Result<bool, BoxError> {
        if self.halt().is_some() {
            return Ok(false);
        }
        if self.interrupted() {
            self.set_halt(Halt::Interrupted);
            return Ok(false);
        }
        let n = bytes.len() as u64;
        let room = self.limits.max_bytes.saturating_sub(self.limits.reserve);
        let before = self.written.fetch_add(n, Ordering::SeqCst);
        if before.saturating_add(n) > room {
            self.written.fetch_sub(n, Ordering::SeqCst);
            self.set_halt(Halt::Budget);
            return Ok(false);
        }
        let path = self.root.join(rel);
        let mut f = create_new(&path)?;
        for chunk in bytes.chunks(CHUNK) {
            if self.interrupted() {
                drop(f);
                let _ = std::fs::remove_file(&path);
                self.written.fetch_sub(n, Ordering::SeqCst);
                self.set_halt(Halt::Interrupted);
                return Ok(false);
            }
            f.write_all(chunk).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
        self.push(rel);
        Ok(true)
    }

    /// Writes the summary file `rel` whatever has halted, within the whole budget.
    ///
    /// # Errors
    /// I/O errors; a file that does not fit in the budget.
    pub fn last(&self, rel: &str, bytes: &[u8]) -> Result<(), BoxError> {
        let path = self.root.join(rel);
        self.account(&path, bytes.len() as u64)?;
        let mut f = create_new(&path)?;
        f.write_all(bytes).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        self.push(rel);
        Ok(())
    }

    fn push(&self, rel: &str) {
        if let Ok(mut f) = self.files.lock() {
            f.push(rel.to_string());
        }
    }
}

/// A new file (never one that was already there, never through a link).
fn create_new(path: &Path) -> Result<std::fs::File, BoxError> {
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
        .map_err(|e| format!("cannot create {}: {e}", path.display()).into())
}

/// Parses a byte count: `1073741824`, or a number with a unit, `500MB`, `2GiB`, `1.5 GB`
/// (kB, MB, GB, TB are powers of 1000; KiB, MiB, GiB, TiB powers of 1024).
///
/// # Errors
/// A message saying what is valid.
pub fn parse_bytes(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let split = t.find(|c: char| !(c.is_ascii_digit() || c == '.')).unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let scale: f64 = match unit.trim() {
        "" | "B" => 1.0,
        "kB" | "KB" => 1e3,
        "MB" => 1e6,
        "GB" => 1e9,
        "TB" => 1e12,
        "KiB" => 1024.0,
        "MiB" => 1024.0 * 1024.0,
        "GiB" => 1024.0 * 1024.0 * 1024.0,
        "TiB" => 1024.0 * 1024.0 * 1024.0 * 1024.0,
        _ => f64::NAN,
    };
    let x = num.parse::<f64>().map(|x| (x * scale).round()).unwrap_or(f64::NAN);
    // 2^64 is the first integer past u64::MAX that f64 holds
    if (1.0..18_446_744_073_709_551_616.0).contains(&x) {
        Ok(x as u64)
    } else {
        Err(format!(
            "`{s}` is not a byte count; valid: a whole number of bytes ≥ 1, or a number with kB, MB, GB, TB \
             (powers of 1000) or KiB, MiB, GiB, TiB (powers of 1024), e.g. 500MB or 2GiB"
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch() -> tempfile::TempDir {
        tempfile::tempdir().unwrap()
    }

    #[test]
    fn byte_counts_with_units() {
        assert_eq!(parse_bytes("1073741824"), Ok(1 << 30));
        assert_eq!(parse_bytes("2GiB"), Ok(2 << 30));
        assert_eq!(parse_bytes("1.5 GB"), Ok(1_500_000_000));
        assert_eq!(parse_bytes("500MB"), Ok(500_000_000));
        for bad in ["", "0", "-1", "1e3", "2 parsecs", "nan", "99999999999999999999999"] {
            assert!(parse_bytes(bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn the_budget_stops_data_files_and_keeps_room_for_the_summary() {
        let d = scratch();
        let sink = Sink::with_cancel(d.path(), Limits { max_bytes: 100, reserve: 30 }, None);
        assert!(sink.data("a", &[b'a'; 60]).unwrap());
        // 60 + 20 > 100 − 30: skipped, and so is everything after it, however small
        assert!(!sink.data("b", &[b'b'; 20]).unwrap());
        assert!(!sink.data("c", b"c").unwrap());
        assert_eq!(sink.halt(), Some(Halt::Budget));
        sink.last("summary", &[b's'; 30]).unwrap();
        assert!(sink.last("more", &[b'x'; 11]).is_err());
        assert_eq!(sink.files(), ["a", "summary"]);
        assert_eq!(sink.bytes(), 90);
        assert!(!d.path().join("b").exists() && !d.path().join("c").exists());
    }

    /// Ctrl-C while writing: the files written before it stay whole, nothing after it is
    /// written, and the summary is still written (to say so).
    #[test]
    fn an_interrupt_while_writing_stops_at_a_whole_file() {
        static FLAG: AtomicBool = AtomicBool::new(false);
        let d = scratch();
        let sink = Sink::with_cancel(d.path(), Limits { max_bytes: 1 << 30, reserve: 0 }, Some(&FLAG));
        assert!(sink.data("first", b"1").unwrap());
        FLAG.store(true, Ordering::SeqCst);
        assert!(!sink.data("second", b"2").unwrap());
        assert_eq!(sink.halt(), Some(Halt::Interrupted));
        sink.last("summary", b"{}").unwrap();
        assert_eq!(sink.files(), ["first", "summary"]);
        assert!(!d.path().join("second").exists());
    }

    #[test]
    fn files_are_created_new() {
        let d = scratch();
        std::fs::write(d.path().join("x"), "user").unwrap();
        let sink = Sink::with_cancel(d.path(), Limits { max_bytes: 100, reserve: 0 }, None);
        assert!(sink.data("x", b"ours").is_err());
        assert_eq!(std::fs::read_to_string(d.path().join("x")).unwrap(), "user");
    }
}
