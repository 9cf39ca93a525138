//! Where things are in a scene file. The document is parsed once with the TOML parser's
//! spans (`toml::de::DeTable`), and every error is located by the *path* of the offending
//! item (`bodies[2].joint.axis`) walked through that spanned tree: it points at the key or
//! the array element itself, never at a textual match (which could land in a comment or on
//! the first of two equal names).
//!
//! Book: — (file format).

use serde::de::DeserializeOwned;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use super::SceneError;

/// Largest scene file read, in bytes (a scene is a page of text; this bounds the parser's
/// work and memory on hostile input).
pub const MAX_SCENE_BYTES: usize = 4 << 20;

/// A scene file's text, its name for messages, and its spanned syntax tree.
///
/// Book: — (file format).
#[derive(Debug)]
pub struct SceneSource<'a> {
    file: &'a str,
    text: &'a str,
    doc: Spanned<DeTable<'a>>,
}

/// One step of an item path: a table key or an array index.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Seg<'p> {
    Key(&'p str),
    Index(usize),
}

/// Splits `bodies[2].joint.axis` into `bodies`, `[2]`, `joint`, `axis`.
fn segments(path: &str) -> Vec<Seg<'_>> {
    let mut out = Vec::new();
    for part in path.split('.').filter(|p| !p.is_empty()) {
        let (key, mut rest) = part.split_once('[').map_or((part, ""), |(k, r)| (k, r));
        if !key.is_empty() {
            out.push(Seg::Key(key));
        }
        while let Some((index, after)) = rest.split_once(']') {
            if let Ok(i) = index.parse() {
                out.push(Seg::Index(i));
            }
            rest = after.strip_prefix('[').unwrap_or(after);
        }
    }
    out
}

/// The string value of `key` in the table at `path` of `root`.
fn tag_at<'v>(root: &'v toml::Value, path: &str, key: &str) -> Option<&'v str> {
    let mut cur = root;
    for seg in segments(path) {
        cur = match seg {
            Seg::Key(k) => cur.get(k)?,
            Seg::Index(i) => cur.get(i)?,
        };
    }
    cur.get(key)?.as_str()
}

impl<'a> SceneSource<'a> {
    /// Parses `text` (named `file` in messages) into its spanned tree.
    ///
    /// # Errors
    /// [`SceneError::Parse`] with line and column for a TOML syntax error or a file larger
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
        let doc = DeTable::parse(text).map_err(|e| SceneError::from_toml(&e, text, file))?;
        Ok(Self { file, text, doc })
    }

    /// The file name used in messages.
    pub fn file(&self) -> &'a str {
        self.file
    }

    /// The text.
    pub fn text(&self) -> &'a str {
        self.text
    }

    /// Whether the document has the top-level key `key` (e.g. `aircraft`: the old flight form).
    pub fn has_key(&self, key: &str) -> bool {
        self.doc.get_ref().iter().any(|(k, _)| k.get_ref() == key)
    }

    /// Deserializes the whole document into `T`; errors (unknown or missing keys, wrong
    /// types) are located by the parser.
    ///
    /// # Errors
    /// [`SceneError::Parse`].
    pub fn deserialize<T: DeserializeOwned>(&self) -> Result<T, SceneError> {
        toml::from_str(self.text).map_err(|e| SceneError::from_toml(&e, self.text, self.file))
    }

    /// Deserializes the document into `T` after converting its quantity strings by `schema`
    /// (see [`super::quantities`]). Without quantity strings the TOML parser locates serde's
    /// errors; with them, errors are located by the item path serde reports.
    ///
    /// # Errors
    /// [`SceneError::Parse`] (shape: unknown or missing keys, wrong types) and
    /// [`SceneError::Invalid`] (a quantity string that is wrong where it stands).
    pub fn deserialize_with<T: DeserializeOwned>(
        &self,
        schema: &super::quantities::Schema,
    ) -> Result<T, SceneError> {
        self.read_document(self.document(schema)?)
    }

    /// Every shape error of the document (unknown or missing keys, wrong types) in one pass,
    /// up to [`super::MAX_ERRORS`]: after each, the item at fault is set aside (see
    /// `many::patch_document`) and the rest is read again.
    pub(crate) fn deserialize_all<T: DeserializeOwned>(
        &self,
        schema: &super::quantities::Schema,
    ) -> Result<T, Vec<SceneError>> {
        let mut doc = self.document(schema).map_err(|e| vec![e])?;
        let (mut errors, mut suggested) = (Vec::new(), Vec::<String>::new());
        loop {
            match self.read_document::<T>(doc.clone()) {
                Ok(t) if errors.is_empty() => return Ok(t),
                Ok(_) => return Err(errors),
                Err(e) => {
                    let (path, message) = match &e {
                        SceneError::Invalid { path, message, .. } => (path.clone(), message.clone()),
                        _ => (String::new(), String::new()),
                    };
                    // a misspelt key explains the missing one it suggests: report it once
                    let parent = path.rsplit_once('.').map_or("", |(p, _)| p);
                    if let Some(meant) =
                        message.split("(did you mean `").nth(1).and_then(|r| r.split('`').next())
                    {
                        suggested.push(if parent.is_empty() {
                            meant.to_string()
                        } else {
                            format!("{parent}.{meant}")
                        });
                    }
                    if !(message.starts_with("the required key") && suggested.contains(&path)) {
                        errors.push(e);
                    }
                    if errors.len() >= super::many::MAX_ERRORS
                        || !super::many::patch_document(&mut doc, &path)
                    {
                        return Err(errors);
                    }
                }
            }
        }
    }

    /// The document as a TOML value with its quantity strings converted by `schema`.
    fn document(&self, schema: &super::quantities::Schema) -> Result<toml::Value, SceneError> {
        let mut doc: toml::Value =
            toml::from_str(self.text).map_err(|e| SceneError::from_toml(&e, self.text, self.file))?;
        super::quantities::convert(self, &mut doc, schema)?;
        Ok(doc)
    }

    /// Deserializes a converted document; a shape error names its item path and is located at
    /// the key (unknown keys) or the value (wrong values).
    fn read_document<T: DeserializeOwned>(&self, doc: toml::Value) -> Result<T, SceneError> {
        let root = doc.clone();
        serde_path_to_error::deserialize(doc).map_err(|e| {
            let mut path = String::new();
            for seg in e.path().iter() {
                match seg {
                    serde_path_to_error::Segment::Seq { index } => path.push_str(&format!("[{index}]")),
                    serde_path_to_error::Segment::Map { key } => {
                        if !path.is_empty() {
                            path.push('.');
                        }
                        path.push_str(key);
                    }
                    _ => {}
                }
            }
            let join = |path: &str, key: &str| {
                if path.is_empty() { key.to_string() } else { format!("{path}.{key}") }
            };
            let full = e.inner().to_string();
            // the TOML value deserializer appends a line "in `a.b`": the path says that better
            let message = full.split("\nin `").next().unwrap_or(&full).trim().to_string();
            let mut plain = super::error::plain_words(&message);
            let last = path.rsplit('.').next().unwrap_or("").to_string();
            if let Some(key) = super::error::unknown_key(&message) {
                // an unknown key: point at it
                if last != key {
                    path = join(&path, key);
                }
            } else if let Some(key) =
                message.strip_prefix("missing field `").and_then(|r| r.split('`').next())
            {
                // a missing key: named by its path, located at its table
                path = join(&path, key);
            } else if let Some((variant, valid)) = super::error::unknown_variant(&message) {
                // an unknown `type`, `shape` or `kind` of a tagged table: point at the tag
                let tag = if ["type", "shape", "kind"].contains(&last.as_str()) {
                    last.clone()
                } else {
                    let tag = ["type", "shape", "kind"]
                        .into_iter()
                        .find(|t| tag_at(&root, &path, t) == Some(variant));
                    let tag = tag.unwrap_or("type").to_string();
                    path = join(&path, &tag);
                    tag
                };
                plain = format!("unknown {tag} `{variant}`; valid: {valid}");
            }
            // an unknown key at the key; a wrong value (type, range, tag) at the value
            let (line, column) = if super::error::unknown_key(&message).is_some() || path.is_empty() {
                self.locate(&path)
            } else {
                line_col(self.text, self.value_span(&path).start)
            };
            if path.is_empty() {
                SceneError::Parse { file: self.file.into(), line, column, message: plain }
            } else {
                SceneError::Invalid { file: self.file.into(), line, column, path, message: plain }
            }
        })
    }

    /// Byte range of the *value* at `path` (a string literal with its quotes), or of the
    /// nearest existing ancestor.
    pub fn value_span(&self, path: &str) -> std::ops::Range<usize> {
        let mut best = 0..0;
        let mut table: Option<&DeTable<'a>> = Some(self.doc.get_ref());
        let mut array: Option<&[Spanned<DeValue<'a>>]> = None;
        for seg in segments(path) {
            let next = match (seg, table, array) {
                (Seg::Key(k), Some(t), _) => t.iter().find(|(key, _)| key.get_ref() == k).map(|(_, v)| v),
                (Seg::Index(i), _, Some(a)) => a.get(i),
                _ => None,
            };
            let Some(v) = next else { break };
            best = v.span();
            table = v.get_ref().as_table();
            array = v.get_ref().as_array().map(|a| &a[..]);
        }
        best
    }

    /// A [`SceneError::Invalid`] for the item `path`, located at byte `offset` of the file.
    pub fn invalid_at(
        &self,
        offset: usize,
        path: impl Into<String>,
        message: impl Into<String>,
    ) -> SceneError {
        let (line, column) = line_col(self.text, offset);
        SceneError::Invalid {
            file: self.file.into(),
            line,
            column,
            path: path.into(),
            message: message.into(),
        }
    }

    /// Byte range of the item at `path`: the key of a table entry, the element of an array;
    /// the deepest existing ancestor when the path goes further than the file (a key left
    /// to its default), the start of the file for the empty path.
    pub fn span(&self, path: &str) -> std::ops::Range<usize> {
        let mut best = 0..0;
        let mut cur: &DeValue<'a>;
        let mut table: Option<&DeTable<'a>> = Some(self.doc.get_ref());
        let mut array: Option<&[Spanned<DeValue<'a>>]> = None;
        for seg in segments(path) {
            let next: Option<(&Spanned<DeValue<'a>>, std::ops::Range<usize>)> = match (seg, table, array) {
                (Seg::Key(k), Some(t), _) => {
                    t.iter().find(|(key, _)| key.get_ref() == k).map(|(key, v)| (v, key.span()))
                }
                (Seg::Index(i), _, Some(a)) => a.get(i).map(|v| (v, v.span())),
                _ => None,
            };
            let Some((v, at)) = next else { break };
            best = at;
            cur = v.get_ref();
            table = cur.as_table();
            array = cur.as_array().map(|a| &a[..]);
        }
        best
    }

    /// 1-based (line, column) of the item at `path` (see [`SceneSource::span`]).
    pub fn locate(&self, path: &str) -> (usize, usize) {
        line_col(self.text, self.span(path).start)
    }

    /// A [`SceneError::Invalid`] at the item `path`.
    pub fn invalid(&self, path: impl Into<String>, message: impl Into<String>) -> SceneError {
        let path = path.into();
        let (line, column) = self.locate(&path);
        SceneError::Invalid { file: self.file.into(), line, column, path, message: message.into() }
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
    fn paths_split_into_keys_and_indices() {
        assert_eq!(
            segments("bodies[2].joint.axis"),
            vec![Seg::Key("bodies"), Seg::Index(2), Seg::Key("joint"), Seg::Key("axis")]
        );
        assert_eq!(segments("a[1][0]"), vec![Seg::Key("a"), Seg::Index(1), Seg::Index(0)]);
        assert_eq!(segments(""), vec![]);
    }

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
