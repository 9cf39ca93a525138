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
    /// A [`SceneError::Parse`] from a TOML error, located in `text` (shared by every kind of
    /// scene file: multibody here, flight in `vectrix-flight`).
    pub fn from_toml(e: &toml::de::Error, text: &str, file: &str) -> Self {
        let message = e.message().trim();
        let mut at = e.span().map_or(0, |s| s.start);
        if let (Some(key), Some(span)) = (unknown_key(message), e.span())
            && let Some(table) = text.get(span.clone())
        {
            // the parser points at the table holding the key (an inline table's `{`): find the
            // key itself in it
            at = key_offset(table, key).map_or(span.start, |k| span.start + k);
        }
        let message = if message == "duplicate key" {
            // name the key (the span is the repeated key)
            let key = e.span().and_then(|s| text.get(s)).unwrap_or("").trim();
            format!("duplicate key `{key}`; valid: each key once in its table")
        } else {
            plain_words(message)
        };
        let (line, column) = super::source::line_col(text, at);
        Self::Parse { file: file.into(), line, column, message }
    }
}

/// The key of serde's "unknown field `k`, expected …" message.
pub(crate) fn unknown_key(message: &str) -> Option<&str> {
    message.strip_prefix("unknown field `")?.split('`').next()
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

/// The variant and the valid ones of serde's "unknown variant `v`, expected one of `a`, `b`"
/// (or "expected `a` or `b`"), the valid ones as "`a`, `b`".
pub(crate) fn unknown_variant(message: &str) -> Option<(&str, String)> {
    let rest = message.strip_prefix("unknown variant `")?;
    let (variant, tail) = rest.split_once('`')?;
    let valid: Vec<String> = tail.split('`').skip(1).step_by(2).map(|v| format!("`{v}`")).collect();
    Some((variant, valid.join(", ")))
}

/// Byte offset of the bare key `key` (followed by `=`) in `text`.
fn key_offset(text: &str, key: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(k) = text[from..].find(key).map(|k| from + k) {
        let before = text[..k].chars().next_back();
        let after = text[k + key.len()..].trim_start();
        if before.is_none_or(|c| !(c.is_alphanumeric() || c == '_' || c == '-')) && after.starts_with('=') {
            return Some(k);
        }
        from = k + key.len();
    }
    None
}

/// " (did you mean `x`?)" for the candidate closest to `name` by edit distance, when it is
/// close (at most a third of the name's letters, or 2, apart); otherwise "".
pub(crate) fn did_you_mean<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> String {
    candidates
        .into_iter()
        .map(|c| (distance(name, c), c))
        .min_by_key(|(d, _)| *d)
        .filter(|(d, _)| *d <= (name.chars().count() / 3).max(2))
        .map_or_else(String::new, |(_, c)| format!(" (did you mean `{c}`?)"))
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

/// A parser message in the scene's words: serde's Rust type names become what a scene
/// writer would type, and an unknown key gets the closest valid one ("did you mean").
pub(crate) fn plain_words(message: &str) -> String {
    let mut m = message.trim().to_string();
    for (rust, plain) in [
        ("expected usize", "valid: a whole number ≥ 0 (no decimal point)"),
        ("expected u64", "valid: a whole number ≥ 0 (no decimal point)"),
        ("expected f64", "valid: a number"),
        ("expected a sequence", "valid: an array [ … ]"),
        ("expected a string", "valid: a string in quotes"),
        ("expected a boolean", "valid: true or false"),
    ] {
        if let Some(k) = m.find(rust) {
            let head = m[..k].trim_end().trim_end_matches(',');
            m = format!("{head}; {plain}{}", &m[k + rust.len()..]);
        }
    }
    if let Some(key) = m.strip_prefix("missing field `").and_then(|r| r.split('`').next()) {
        m = format!("the required key `{key}` is missing; valid: a table that gives `{key}`");
    }
    if let Some(struct_at) = m.find("expected struct ") {
        let head = m[..struct_at].trim_end().trim_end_matches(',');
        m = format!("{head}; valid: a table {{ … }}");
    }
    if let Some(key) = unknown_key(message) {
        // "unknown field `k`, expected `a`" or "…, expected one of `a`, `b`"
        let valid: Vec<&str> = message.split('`').skip(3).step_by(2).collect();
        m = format!(
            "unknown key `{key}`; valid: {}",
            valid.iter().map(|v| format!("`{v}`")).collect::<Vec<_>>().join(", ")
        );
        if valid.is_empty() {
            m = format!("unknown key `{key}`; valid: none here");
        } else if let Some(best) = valid.iter().copied().min_by_key(|v| distance(key, v))
            && valid.len() > 1
            && distance(key, best) <= (key.chars().count() / 3).max(2)
        {
            m.push_str(&format!(" (did you mean `{best}`?)"));
        }
    }
    m
}
