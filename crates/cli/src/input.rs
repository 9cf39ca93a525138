//! Reading a scene file with bounded time and memory: only a regular file is read (a FIFO,
//! a device such as `/dev/zero`, a socket or a folder is refused before anything is read, and
//! the file is opened without blocking, so a FIFO put in its place cannot stall the open), and
//! the bytes actually read are counted against [`MAX_SCENE_BYTES`] — never the size the file
//! system reports, which a growing file or a `/proc` file gets wrong.
//!
//! Book: — (file format).

use std::io::Read;
use std::path::Path;

use vectrix_scene::MAX_SCENE_BYTES;
use vectrix_scene::Scene;

use crate::output::BoxError;

/// A loaded scene with the text it came from and the name its errors are reported under.
pub(crate) struct Loaded {
    /// The file's text.
    pub text: String,
    /// The path as shown in messages.
    pub file: String,
    /// The scene.
    pub scene: Scene,
}

/// What kind of file system object `t` is, for a message.
fn kind(t: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() { "a folder" } else { "not a regular file" }
}

/// Reads at most `cap` bytes from `r`; `Err(n)` with n > cap when there are more.
pub(crate) fn read_capped(r: impl Read, cap: usize) -> std::io::Result<Result<Vec<u8>, usize>> {
    let mut bytes = Vec::new();
    // one byte past the cap tells a file of exactly `cap` bytes from a longer one
    r.take(cap as u64 + 1).read_to_end(&mut bytes)?;
    Ok(if bytes.len() > cap { Err(bytes.len()) } else { Ok(bytes) })
}

/// The text of the scene file at `path`: a regular file of at most [`MAX_SCENE_BYTES`] bytes
/// of UTF-8.
///
/// # Errors
/// A message naming the path: it cannot be opened, is not a regular file, is longer than the
/// cap, or is not UTF-8.
pub(crate) fn read_scene(path: &Path) -> Result<String, BoxError> {
    let shown = path.display();
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // a FIFO without a writer would block the open itself
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path).map_err(|e| format!("{shown}: {e}"))?;
    let meta = file.metadata().map_err(|e| format!("{shown}: {e}"))?;
    if !meta.is_file() {
        return Err(format!(
            "{shown}: {}; valid: a scene file (a regular TOML file)",
            kind(meta.file_type())
        )
        .into());
    }
    let bytes = match read_capped(file, MAX_SCENE_BYTES).map_err(|e| format!("{shown}: {e}"))? {
        Ok(b) => b,
        Err(_) => {
            return Err(format!(
                "{shown}: more than {MAX_SCENE_BYTES} bytes; valid: a scene file of at most {MAX_SCENE_BYTES} bytes"
            )
            .into());
        }
    };
    String::from_utf8(bytes).map_err(|e| {
        // located like every other refusal: line and column (in characters) of the first bad byte
        let bytes = e.as_bytes();
        let at = e.utf8_error().valid_up_to();
        let line_start = bytes[..at].iter().rposition(|b| *b == b'\n').map_or(0, |k| k + 1);
        let line = 1 + bytes[..at].iter().filter(|b| **b == b'\n').count();
        let column = 1 + String::from_utf8_lossy(&bytes[line_start..at]).chars().count();
        format!(
            "{shown}:{line}:{column}: the byte {:#04x} is not UTF-8 text; valid: a TOML file in UTF-8",
            bytes[at]
        )
        .into()
    })
}

/// Reads and validates a scene file, reporting errors with line and column.
///
/// # Errors
/// As [`read_scene`], and the scene's own errors (`file:line:col`).
pub(crate) fn load(path: &Path) -> Result<Loaded, BoxError> {
    let file = path.display().to_string();
    // issue 35: a URDF or MJCF file alone is a scene of that model under gravity
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let text = match ext.as_deref() {
        Some(e @ ("urdf" | "xml")) => {
            let name = path.file_name().and_then(|n| n.to_str()).ok_or("the model file name is not UTF-8")?;
            vectrix_scene::import::model_scene_toml(name, e == "xml")
        }
        _ => read_scene(path)?,
    };
    let scene = Scene::from_toml(&text, &file)?;
    report_import(scene.import_warnings(), STRICT.with(std::cell::Cell::get))?;
    Ok(Loaded { text, file, scene })
}

thread_local! {
    /// `--strict`: unmapped model content is an error (set per command by `run_with_args`).
    static STRICT: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Sets `--strict` for the commands run next on this thread.
pub(crate) fn set_strict(strict: bool) {
    STRICT.with(|s| s.set(strict));
}

/// Most import warnings printed one by one (the rest are counted).
const MAX_WARNINGS_SHOWN: usize = 50;

/// Prints what a `[model]` file had that does not map (to stderr), or refuses it when strict.
fn report_import(w: &[vectrix_scene::import::ImportWarning], strict: bool) -> Result<(), BoxError> {
    if w.is_empty() {
        return Ok(());
    }
    let shown: Vec<String> = w.iter().take(MAX_WARNINGS_SHOWN).map(ToString::to_string).collect();
    let more = w.len().saturating_sub(MAX_WARNINGS_SHOWN);
    let tail = if more > 0 { format!("\n… and {more} more") } else { String::new() };
    if strict {
        return Err(format!(
            "{}{tail}\n--strict: {} element(s) or attribute(s) of the model do not map; valid: a model whose every \
             element maps, or drop --strict to run with them left out",
            shown.join("\n"),
            w.len()
        )
        .into());
    }
    eprintln!("{}{tail}", shown.join("\n"));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_endless_reader_is_cut_at_the_cap() {
        // io::repeat never ends, like /dev/zero: the read stops one byte past the cap
        let r = read_capped(std::io::repeat(0), 1000).unwrap();
        assert_eq!(r, Err(1001));
        let r = read_capped(&b"abc"[..], 3).unwrap();
        assert_eq!(r, Ok(b"abc".to_vec()));
    }
}
