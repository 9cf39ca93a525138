//! Model files on disk: confined to the scene's folder tree, bounded in size, UTF-8.
//!
//! Book: — (file format).

use std::io::Read;
use std::path::{Component, Path, PathBuf};

use super::MAX_MODEL_BYTES;

/// Resolves `rel` against `dir`: relative, without `..`, and (symlinks followed) inside `dir`.
///
/// # Errors
/// A message saying what was wrong and what is valid.
pub(crate) fn confined(dir: &Path, rel: &str) -> Result<PathBuf, String> {
    let p = Path::new(rel);
    if rel.is_empty() || !p.components().all(|c| matches!(c, Component::Normal(_) | Component::CurDir)) {
        return Err(format!(
            "`{rel}` leaves the folder; valid: a relative path inside the scene's folder tree (no `..`, not absolute)"
        ));
    }
    let full = dir.join(p);
    let (Ok(real), Ok(base)) = (full.canonicalize(), dir.canonicalize()) else {
        return Err(format!("`{}` cannot be opened (missing file?)", full.display()));
    };
    if !real.starts_with(&base) {
        return Err(format!(
            "`{rel}` resolves (through a link) outside the scene's folder tree; valid: a file inside it"
        ));
    }
    Ok(real)
}

/// The text of a model file: a regular file of at most [`MAX_MODEL_BYTES`] bytes of UTF-8.
///
/// # Errors
/// A message naming the problem.
pub(crate) fn read_model(path: &Path) -> Result<String, String> {
    let meta = std::fs::metadata(path).map_err(|e| format!("{}: {e}", path.display()))?;
    if !meta.is_file() {
        return Err(format!("{}: not a regular file; valid: a URDF or MJCF file", path.display()));
    }
    let f = std::fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut bytes = Vec::new();
    f.take(MAX_MODEL_BYTES as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    if bytes.len() > MAX_MODEL_BYTES {
        return Err(format!("{}: more than {MAX_MODEL_BYTES} bytes; valid: a smaller model", path.display()));
    }
    String::from_utf8(bytes)
        .map_err(|_| format!("{}: not UTF-8 text; valid: an XML file in UTF-8", path.display()))
}
