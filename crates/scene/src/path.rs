//! Item paths: where an item sits in a scene file, as errors name it (`bodies[2].joint.axis`).
//! One type for every path of the scene layer: the deserializer tracks it, the quantity schema
//! reads it, the locator walks it through the spanned document, and errors print it.
//!
//! # Conventions
//! The text form joins table keys with `.` and writes array indices in brackets:
//! `bodies[2].q[0]`, `[3]` (an index at the root), `""` (the document itself). A key that is
//! empty or holds `.`, `[`, `]`, `"`, whitespace or a control character is written in double
//! quotes with `\"` and `\\` escaped (`trim.hold."air:jet.beta"`), so display and parse are
//! inverse: `p.to_string().parse() == Ok(p)` for every path.
//!
//! Book: — (file format).

use std::borrow::Cow;
use std::fmt;
use std::str::FromStr;

/// One step of an item path: a table key or an array index.
///
/// Book: — (file format).
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum PathSeg {
    /// A table key.
    Key(String),
    /// An array index.
    Index(usize),
}

impl PathSeg {
    /// The key of a key step (`None` for an index).
    pub fn key(&self) -> Option<&str> {
        if let Self::Key(k) = self { Some(k) } else { None }
    }

    /// The index of an index step (`None` for a key).
    pub fn index(&self) -> Option<usize> {
        if let Self::Index(i) = self { Some(*i) } else { None }
    }
}

/// The path of an item in a scene file: keys and indices from the document's root.
///
/// Book: — (file format).
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ItemPath(Vec<PathSeg>);

/// A path text that is not an item path: where it goes wrong and why.
///
/// Book: — (file format).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "item path `{text}`: {problem} at byte {at}; valid: keys joined by `.` and indices in brackets \
     (`bodies[2].joint.axis`), a key with `.`, `[`, `]`, `\"` or spaces in double quotes"
)]
pub struct PathError {
    /// The text given.
    pub text: String,
    /// Byte offset of the first character that does not fit.
    pub at: usize,
    /// What does not fit.
    pub problem: String,
}

impl ItemPath {
    /// The empty path (the document itself).
    pub fn root() -> Self {
        Self(Vec::new())
    }

    /// The steps, from the root.
    pub fn segments(&self) -> &[PathSeg] {
        &self.0
    }

    /// Whether this is the root (no steps).
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Appends a step.
    pub fn push(&mut self, seg: PathSeg) {
        self.0.push(seg);
    }

    /// Removes and returns the last step.
    pub fn pop(&mut self) -> Option<PathSeg> {
        self.0.pop()
    }

    /// This path with the key `key` appended.
    pub fn key(&self, key: &str) -> Self {
        let mut p = self.clone();
        p.push(PathSeg::Key(key.to_string()));
        p
    }

    /// This path with the index `i` appended.
    pub fn index(&self, i: usize) -> Self {
        let mut p = self.clone();
        p.push(PathSeg::Index(i));
        p
    }

    /// The path of the item holding this one (`None` for the root).
    pub fn parent(&self) -> Option<Self> {
        let (_, init) = self.0.split_last()?;
        Some(Self(init.to_vec()))
    }

    /// The first key and the index right after it: `effects[3].k` → (`effects`, Some(3)),
    /// `duration` → (`duration`, None); `None` when the path does not start with a key.
    pub fn head(&self) -> Option<(&str, Option<usize>)> {
        let key = self.0.first()?.key()?;
        Some((key, self.0.get(1).and_then(PathSeg::index)))
    }

    /// The last key of the path, if its last step is a key.
    pub fn last_key(&self) -> Option<&str> {
        self.0.last().and_then(PathSeg::key)
    }

    /// Reads a path in its text form (see the module's conventions).
    ///
    /// # Errors
    /// [`PathError`] at the first character that does not fit: an empty key (`a..b`), an
    /// unclosed bracket or quote, an index that is not a whole number or exceeds `usize`.
    pub fn parse(text: &str) -> Result<Self, PathError> {
        let (segs, fault) = scan(text);
        match fault {
            None => Ok(Self(segs)),
            Some((at, problem)) => Err(PathError { text: text.to_string(), at, problem }),
        }
    }

    /// Reads as much of `text` as is a path: the steps before the first character that does
    /// not fit (the locator uses it, so that a malformed path still finds its nearest item).
    pub fn parse_prefix(text: &str) -> Self {
        Self(scan(text).0)
    }
}

impl From<Vec<PathSeg>> for ItemPath {
    fn from(segs: Vec<PathSeg>) -> Self {
        Self(segs)
    }
}

impl FromStr for ItemPath {
    type Err = PathError;
    fn from_str(s: &str) -> Result<Self, PathError> {
        Self::parse(s)
    }
}

/// Whether a key is written bare (without quotes).
fn bare(key: &str) -> bool {
    !key.is_empty() && key.chars().all(bare_char)
}

fn bare_char(c: char) -> bool {
    !(matches!(c, '.' | '[' | ']' | '"') || c.is_whitespace() || c.is_control())
}

impl fmt::Display for ItemPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, seg) in self.0.iter().enumerate() {
            match seg {
                PathSeg::Index(i) => write!(f, "[{i}]")?,
                PathSeg::Key(key) => {
                    if k > 0 {
                        f.write_str(".")?;
                    }
                    if bare(key) {
                        f.write_str(key)?;
                    } else {
                        f.write_str("\"")?;
                        for c in key.chars() {
                            if matches!(c, '"' | '\\') {
                                f.write_str("\\")?;
                            }
                            write!(f, "{c}")?;
                        }
                        f.write_str("\"")?;
                    }
                }
            }
        }
        Ok(())
    }
}

/// The steps of `text` up to the first fault, and the fault (byte offset, what).
fn scan(text: &str) -> (Vec<PathSeg>, Option<(usize, String)>) {
    let mut segs = Vec::new();
    let mut chars = text.char_indices().peekable();
    // a key is expected at the start and after each `.`
    let mut want_key = true;
    while let Some(&(at, c)) = chars.peek() {
        let fault = |problem: &str| Some((at, problem.to_string()));
        match c {
            '[' if want_key && !segs.is_empty() => return (segs, fault("a key is missing")),
            '[' => {
                chars.next();
                let start = at + 1;
                let mut end = start;
                while let Some(&(k, d)) = chars.peek() {
                    if !d.is_ascii_digit() {
                        break;
                    }
                    end = k + 1;
                    chars.next();
                }
                match (chars.next(), text[start..end].parse::<usize>()) {
                    (Some((_, ']')), Ok(i)) => segs.push(PathSeg::Index(i)),
                    (_, Err(_)) if end > start => return (segs, fault("an index larger than usize")),
                    _ => return (segs, fault("an index is not `[` digits `]`")),
                }
                want_key = false;
            }
            '.' if !want_key => {
                chars.next();
                want_key = true;
                if chars.peek().is_none() {
                    return (segs, Some((text.len(), "a key is missing after `.`".into())));
                }
            }
            '"' if want_key => {
                chars.next();
                let mut key = String::new();
                loop {
                    match chars.next() {
                        Some((_, '"')) => break,
                        Some((_, '\\')) => match chars.next() {
                            Some((_, e @ ('"' | '\\'))) => key.push(e),
                            _ => {
                                return (
                                    segs,
                                    fault("a quoted key has an escape other than `\\\"` or `\\\\`"),
                                );
                            }
                        },
                        Some((_, d)) => key.push(d),
                        None => return (segs, fault("a quoted key is not closed")),
                    }
                }
                segs.push(PathSeg::Key(key));
                want_key = false;
            }
            c if want_key && bare_char(c) => {
                let mut key = String::new();
                while let Some(&(_, d)) = chars.peek() {
                    if !bare_char(d) {
                        break;
                    }
                    key.push(d);
                    chars.next();
                }
                segs.push(PathSeg::Key(key));
                want_key = false;
            }
            _ if want_key => return (segs, fault("a key is missing")),
            _ => return (segs, fault("`.` or `[` is missing before this")),
        }
    }
    (segs, None)
}

/// Anything that names an item: an [`ItemPath`], or its text (read with
/// [`ItemPath::parse_prefix`], so that a malformed text still finds its nearest item).
///
/// Book: — (file format).
pub trait AsItemPath {
    /// The path.
    fn item_path(&self) -> Cow<'_, ItemPath>;
}

impl AsItemPath for ItemPath {
    fn item_path(&self) -> Cow<'_, ItemPath> {
        Cow::Borrowed(self)
    }
}

impl AsItemPath for str {
    fn item_path(&self) -> Cow<'_, ItemPath> {
        Cow::Owned(ItemPath::parse_prefix(self))
    }
}

impl AsItemPath for String {
    fn item_path(&self) -> Cow<'_, ItemPath> {
        Cow::Owned(ItemPath::parse_prefix(self))
    }
}

impl<T: AsItemPath + ?Sized> AsItemPath for &T {
    fn item_path(&self) -> Cow<'_, ItemPath> {
        (**self).item_path()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_split_into_keys_and_indices() {
        let p = ItemPath::parse("bodies[2].joint.axis").unwrap();
        let want = [
            PathSeg::Key("bodies".into()),
            PathSeg::Index(2),
            PathSeg::Key("joint".into()),
            PathSeg::Key("axis".into()),
        ];
        assert_eq!(p.segments(), want);
        assert_eq!(ItemPath::parse("a[1][0]").unwrap().to_string(), "a[1][0]");
        assert_eq!(ItemPath::parse("").unwrap(), ItemPath::root());
        assert_eq!(p.head(), Some(("bodies", Some(2))));
        assert_eq!(p.parent().unwrap().to_string(), "bodies[2].joint");
        assert_eq!(ItemPath::parse("trim.hold.\"air:jet.beta\"").unwrap().last_key(), Some("air:jet.beta"));
    }

    #[test]
    fn malformed_paths_say_where() {
        for (text, at) in [("a..b", 2), ("[", 0), ("a[x]", 1), ("a.", 2), ("a[0]b", 4), ("\"a", 0), (".a", 0)]
        {
            let e = ItemPath::parse(text).unwrap_err();
            assert_eq!(e.at, at, "{text}: {e}");
        }
        assert_eq!(ItemPath::parse_prefix("bodies[1].q..x").to_string(), "bodies[1].q");
        assert!(ItemPath::parse("a[18446744073709551616]").is_err());
    }
}
