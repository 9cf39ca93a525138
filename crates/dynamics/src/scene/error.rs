//! Errors of the scene layer: where in the file, what is wrong, what would be valid.

use thiserror::Error;

/// A scene that cannot be loaded, built or run.
///
/// Book: — (file format); the messages name the book's constraints where they apply.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum SceneError {
    /// TOML syntax or shape error (unknown key, wrong type, missing field).
    #[error("{file}:{line}:{column}: {message}")]
    Parse {
        /// File name (or `<scene>`).
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What is wrong and what would be valid.
        message: String,
    },
    /// A well-formed file that does not describe a valid scene.
    #[error("{file}:{line}:{column}: {path}: {message}")]
    Invalid {
        /// File name.
        file: String,
        /// 1-based line of the offending item (best effort: where its key or name appears).
        line: usize,
        /// 1-based column.
        column: usize,
        /// Path of the item (`bodies[2].joint.axis`).
        path: String,
        /// What is wrong and what would be valid.
        message: String,
    },
    /// The dynamics failed during the run (a singular mass matrix, a non-finite state, …).
    #[error("simulation failed at t = {t}: {message}")]
    Run {
        /// Time reached.
        t: f64,
        /// Cause.
        message: String,
    },
}

impl SceneError {
    /// A [`SceneError::Parse`] from a TOML error, located in `text` (shared by every kind of
    /// scene file: multibody here, flight in `vectrix-flight`).
    pub fn from_toml(e: &toml::de::Error, text: &str, file: &str) -> Self {
        let (line, column) = e.span().map_or((1, 1), |s| line_col(text, s.start));
        Self::Parse { file: file.into(), line, column, message: e.message().trim().to_string() }
    }

    /// A [`SceneError::Invalid`] located at the first occurrence of `needle` in `text` (1:1
    /// when it does not occur).
    pub fn invalid_at(
        text: &str,
        file: &str,
        needle: &str,
        path: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        let off = if needle.is_empty() { None } else { text.find(needle) };
        let (line, column) = off.map_or((1, 1), |o| line_col(text, o));
        Self::Invalid { file: file.into(), line, column, path: path.into(), message: message.into() }
    }
}

/// 1-based (line, column) of byte `offset` in `src` (columns count characters).
pub(crate) fn line_col(src: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(src.len());
    while !src.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &src[..offset];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}
