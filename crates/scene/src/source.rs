//! Where things are in a scene file. The document is parsed once, with the TOML parser's
//! spans (`toml::de::DeTable`), into the span-carrying tree of `tree`; the spec is
//! deserialized from that tree (`de`), and every error is located by the *path* of the
//! offending item (`bodies[2].joint.axis`, an [`ItemPath`]) walked through it: it points at the
//! key or the array element itself, never at a textual match (which could land in a comment or
//! on the first of two equal names).
//!
//! Book: — (file format).

use serde::de::DeserializeOwned;

use super::SceneError;
use super::de::from_node;
use super::error::line_col;
use super::fault::{Fault, fault};
use super::path::{AsItemPath, ItemPath, PathSeg};
use super::tree::Node;

/// Largest scene file read, in bytes (a scene is a page of text; this bounds the parser's
/// work and memory on hostile input).
pub const MAX_SCENE_BYTES: usize = 4 << 20;

/// A scene file's text, its name for messages, and its document (the one parse, with spans).
///
/// Book: — (file format).
#[derive(Debug)]
pub struct SceneSource<'a> {
    file: &'a str,
    text: &'a str,
    doc: Node,
}

impl<'a> SceneSource<'a> {
    /// Parses `text` (named `file` in messages) into its spanned document.
    ///
    /// # Errors
    /// [`SceneError::Parse`] with line and column for a TOML syntax error, a number that does
    /// not fit its type (an integer beyond i64, a float literal beyond f64), or a file larger
    /// than [`MAX_SCENE_BYTES`].
    pub fn new(text: &'a str, file: &'a str) -> Result<Self, SceneError> {
        if text.len() > MAX_SCENE_BYTES {
            return Err(SceneError::Parse {
                file: file.into(),
                line: 1,
                column: 1,
                message: format!(
                    "the file has {} bytes; valid: at most {MAX_SCENE_BYTES} bytes (a scene is a page of text)",
                    text.len()
                ),
            });
        }
        let parsed = toml::de::DeTable::parse(text).map_err(|e| SceneError::from_toml(&e, text, file))?;
        let doc = Node::from_document(&parsed).map_err(|(span, message)| {
            let (line, column) = line_col(text, span.start);
            SceneError::Parse { file: file.into(), line, column, message }
        })?;
        Ok(Self { file, text, doc })
    }

    /// The source of `text` whose document is `doc` (parsed before, by [`SceneSource::new`]).
    pub(crate) fn with_tree(text: &'a str, file: &'a str, doc: Node) -> Self {
        Self { file, text, doc }
    }

    /// The file name used in messages.
    pub fn file(&self) -> &'a str {
        self.file
    }

    /// The text.
    pub fn text(&self) -> &'a str {
        self.text
    }

    /// The document as parsed (quantity strings not yet converted).
    pub fn tree(&self) -> &Node {
        &self.doc
    }

    /// Whether the document has the top-level key `key` (e.g. `aircraft`: the old flight form).
    pub fn has_key(&self, key: &str) -> bool {
        self.doc.entry(key).is_some()
    }

    /// Deserializes the whole document into `T` (quantity strings as they are); errors
    /// (unknown or missing keys, wrong types) are located at their item.
    ///
    /// # Errors
    /// [`SceneError::Invalid`] at the item at fault, [`SceneError::Parse`] for the document as
    /// a whole (a wrong target type).
    pub fn deserialize<T: DeserializeOwned>(&self) -> Result<T, SceneError> {
        self.read_document(&self.doc)
    }

    /// Deserializes `T` from `doc`, a document derived from this file (quantities converted, a
    /// sweep's numbers set): errors are located in this file.
    ///
    /// # Errors
    /// As [`SceneSource::deserialize`].
    pub fn read_document<T: DeserializeOwned>(&self, doc: &Node) -> Result<T, SceneError> {
        self.read::<T>(doc).map_err(|b| b.0)
    }

    /// [`SceneSource::read_document`] with the located fault (for reporting every error; boxed,
    /// the pair being large beside a parsed value).
    pub(crate) fn read<T: DeserializeOwned>(&self, doc: &Node) -> Result<T, Box<(SceneError, Fault)>> {
        from_node::<T>(doc).map_err(|e| {
            let f = fault(&e, doc, &|changed: &Node| from_node::<T>(changed).err());
            Box::new((self.error_of(&f), f))
        })
    }

    /// The located error of a fault: an unknown key at the key, anything else at the value (a
    /// missing key at its table), the document as a whole at its start.
    fn error_of(&self, f: &Fault) -> SceneError {
        let message = f.message.clone();
        if f.path.is_empty() {
            let (line, column) = self.locate(&f.path);
            return SceneError::Parse { file: self.file.into(), line, column, message };
        }
        let at = if f.at_key { self.span(&f.path).start } else { self.value_span(&f.path).start };
        self.invalid_at(at, &f.path, message)
    }

    /// The node at each step of `path` that exists, with the byte range of its key (or, for an
    /// array element, of the element).
    fn walk(&self, path: &ItemPath) -> Vec<(&Node, std::ops::Range<usize>)> {
        let mut out = Vec::new();
        let mut cur = &self.doc;
        for seg in path.segments() {
            let next = match seg {
                PathSeg::Key(k) => cur.entry(k).map(|e| (&e.node, e.key_span.clone())),
                PathSeg::Index(i) => cur.as_array().and_then(|a| a.get(*i)).map(|n| (n, n.span.clone())),
            };
            let Some((n, at)) = next else { break };
            out.push((n, at));
            cur = n;
        }
        out
    }

    /// Byte range of the *value* at `path` (a string literal with its quotes), or of the
    /// nearest existing ancestor.
    pub fn value_span(&self, path: impl AsItemPath) -> std::ops::Range<usize> {
        self.walk(&path.item_path()).last().map_or(0..0, |(n, _)| n.span.clone())
    }

    /// A [`SceneError::Invalid`] for the item `path`, located at byte `offset` of the file.
    pub fn invalid_at(&self, offset: usize, path: impl AsItemPath, message: impl Into<String>) -> SceneError {
        let (line, column) = line_col(self.text, offset);
        SceneError::Invalid {
            file: self.file.into(),
            line,
            column,
            path: path.item_path().to_string(),
            message: message.into(),
        }
    }

    /// Byte range of the item at `path`: the key of a table entry, the element of an array;
    /// the deepest existing ancestor when the path goes further than the file (a key left
    /// to its default), the start of the file for the empty path.
    pub fn span(&self, path: impl AsItemPath) -> std::ops::Range<usize> {
        self.walk(&path.item_path()).pop().map_or(0..0, |(_, at)| at)
    }

    /// 1-based (line, column) of the item at `path` (see [`SceneSource::span`]).
    pub fn locate(&self, path: impl AsItemPath) -> (usize, usize) {
        line_col(self.text, self.span(path).start)
    }

    /// A [`SceneError::Invalid`] at the item `path`.
    pub fn invalid(&self, path: impl AsItemPath, message: impl Into<String>) -> SceneError {
        let path = path.item_path();
        self.invalid_at(self.span(&*path).start, &*path, message)
    }
}

/// Longest name (scene, body, frame), in characters.
pub const MAX_NAME_CHARS: usize = 64;

/// Checks a name that becomes part of a file or folder name or of a CSV column: 1 to
/// [`MAX_NAME_CHARS`] ASCII letters, digits, `_`, `-` (and `.` inside a scene name, never
/// first); so no separator, no `..`, no hidden name, nothing a shell or CSV reader misreads.
///
/// # Errors
/// A message saying what is wrong and what is valid.
pub fn check_name(name: &str, what: &str, allow_dot: bool) -> Result<(), String> {
    let valid = if allow_dot {
        "1 to 64 ASCII letters, digits, `_`, `-` or `.`, not starting with `.`"
    } else {
        "1 to 64 ASCII letters, digits, `_` or `-`"
    };
    let ok_char = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-' || (allow_dot && c == '.');
    let problem = if name.is_empty() {
        Some("is empty".to_string())
    } else if name.chars().count() > MAX_NAME_CHARS {
        Some(format!("has {} characters", name.chars().count()))
    } else if name.starts_with('.') {
        Some("starts with `.`".to_string())
    } else {
        name.chars().find(|c| !ok_char(*c)).map(|c| format!("contains {c:?}"))
    };
    match problem {
        Some(p) => Err(format!("{what} {name:?} {p}; valid: {valid}")),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_point_at_the_key_not_at_a_comment_or_the_first_equal_name() {
        let text = "# the body b with mass is here\nname = \"x\"\n[[bodies]]\nname = \"b\"\n[[bodies]]\nname = \"b\"\nmass = { shape = \"particle\", mass = -1 }\n";
        let s = SceneSource::new(text, "f.toml").unwrap();
        assert_eq!(s.locate("bodies[1].name"), (6, 1));
        assert_eq!(s.locate("bodies[0].name"), (4, 1));
        assert_eq!(s.locate("bodies[1].mass.mass"), (7, 30));
        // a key left to its default: its table
        assert_eq!(s.locate("bodies[1].joint"), (5, 1));
    }

    #[test]
    fn names_are_plain_file_names() {
        for bad in ["", ".", "..", "../x", "/abs", "a/b", "a\\b", ".hidden", "a b", "é", "a:b", "a,b"] {
            assert!(check_name(bad, "scene name", true).is_err(), "{bad:?}");
        }
        assert!(check_name(&"x".repeat(65), "scene name", true).is_err());
        for good in ["tennis_racket", "kepler-0.9", "a", &"x".repeat(64)] {
            assert!(check_name(good, "scene name", true).is_ok(), "{good:?}");
        }
        assert!(check_name("a.b", "body name", false).is_err());
    }
}
