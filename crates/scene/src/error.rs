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
    /// Several errors of one file, in file order (at most [`super::MAX_ERRORS`]), each located.
    #[error("{}", .errors.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n"))]
    Many {
        /// The errors, each a located [`SceneError::Parse`] or [`SceneError::Invalid`].
        errors: Vec<SceneError>,
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
    /// A [`SceneError::Parse`] from a TOML syntax error, located in `text` (the parser's span;
    /// the start of the file when the span does not fit `text`).
    pub fn from_toml(e: &toml::de::Error, text: &str, file: &str) -> Self {
        let message = e.message().trim();
        let at = e.span().map_or(0, |s| s.start);
        let message = if message == "duplicate key" {
            // name the key (the span is the repeated key)
            let key = e.span().and_then(|s| text.get(s)).unwrap_or("").trim();
            format!("duplicate key `{key}`; valid: each key once in its table")
        } else {
            message.to_string()
        };
        let (line, column) = line_col(text, at);
        Self::Parse { file: file.into(), line, column, message }
    }
}

/// 1-based (line, column) of byte `offset` in `src` (columns count characters; an offset past
/// the end or inside a character is taken back to the character boundary before it).
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

/// A quantity-string error in the words of a scene file: the units library's byte positions
/// inside the string (`at bytes 0..1`) are left out, since a scene error is located by file,
/// line and column at the offending character already (and a command-line value names itself).
///
/// Book: §15.19 (quantities).
pub fn unit_message(e: &vectrix_units::UnitError) -> String {
    let m = e.to_string();
    let Some(k) = m.find(" at bytes ") else { return m };
    let tail = &m[k + " at bytes ".len()..];
    let end = tail.find(|c: char| !(c.is_ascii_digit() || c == '.')).unwrap_or(tail.len());
    format!("{}{}", &m[..k], &tail[end..])
}

/// " (did you mean `x`?)" for the candidate closest to `name` by edit distance, when it is
/// close (see [`closest`]); otherwise "".
pub(crate) fn did_you_mean<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> String {
    closest(name, candidates).map_or_else(String::new, |c| format!(" (did you mean `{c}`?)"))
}

/// The candidate closest to `name` by edit distance, when it is close: at most a third of the
/// name's letters, or 2, apart.
pub(crate) fn closest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .into_iter()
        .map(|c| (distance(name, c), c))
        .min_by_key(|(d, _)| *d)
        .filter(|(d, _)| *d <= (name.chars().count() / 3).max(2))
        .map(|(_, c)| c)
}

/// Edit distance (Levenshtein) between two short names.
pub(crate) fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}
