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
        /// 1-based line of the offending item (its key, or its element in an array).
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
        let (line, column) = e.span().map_or((1, 1), |s| super::source::line_col(text, s.start));
        Self::Parse { file: file.into(), line, column, message: e.message().trim().to_string() }
    }
}
