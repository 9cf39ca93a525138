//! The scene document: the TOML parser's spanned tree (`toml::de::DeTable`, the one parse of
//! the file) turned into values that carry their byte spans (and, in tables, their keys'
//! spans). Quantity strings are converted on it, a sweep sets numbers in it, and the spec is
//! deserialized from it (`de`), so every error is located in the file without a second parse.
//!
//! Book: — (file format).

use std::ops::Range;

use toml::Spanned;
use toml::de::{DeTable, DeValue};

use super::path::{ItemPath, PathSeg};

/// A value of the document with the byte range of its text (a string with its quotes, a
/// table from its header or brace).
///
/// Book: — (file format).
#[derive(Debug, Clone, PartialEq)]
pub struct Node {
    /// The value.
    pub value: NodeValue,
    /// Byte range of the value in the file.
    pub span: Range<usize>,
}

/// The value of a [`Node`]: TOML's kinds of value, numbers already read.
///
/// Book: — (file format).
#[derive(Debug, Clone, PartialEq)]
pub enum NodeValue {
    /// A string.
    String(String),
    /// An integer.
    Integer(i64),
    /// A float (a quantity string, once converted, is one).
    Float(f64),
    /// A boolean.
    Boolean(bool),
    /// A date-time (no scene key takes one).
    Datetime(toml::value::Datetime),
    /// An array.
    Array(Vec<Node>),
    /// A table, its entries in the parser's order.
    Table(Vec<Entry>),
}

/// One entry of a table: its key, the key's byte range, and the value.
///
/// Book: — (file format).
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// The key.
    pub key: String,
    /// Byte range of the key in the file.
    pub key_span: Range<usize>,
    /// The value.
    pub node: Node,
}

/// A number the parser accepted but that does not fit (an integer beyond i64, a float literal
/// beyond f64): byte range and message.
pub(crate) type Overflow = (Range<usize>, String);

impl Node {
    /// The document of a parsed file.
    ///
    /// # Errors
    /// A number that does not fit its type, with its byte range.
    pub(crate) fn from_document(doc: &Spanned<DeTable<'_>>) -> Result<Self, Overflow> {
        Ok(Self { value: NodeValue::Table(table(doc.get_ref())?), span: doc.span() })
    }

    fn from_value(v: &Spanned<DeValue<'_>>) -> Result<Self, Overflow> {
        let span = v.span();
        let value = match v.get_ref() {
            DeValue::String(s) => NodeValue::String(s.to_string()),
            DeValue::Integer(i) => match i64::from_str_radix(i.as_str(), i.radix()) {
                Ok(x) => NodeValue::Integer(x),
                Err(_) => {
                    return Err((
                        span,
                        format!(
                            "the integer {i} does not fit; valid: a whole number from {} to {}",
                            i64::MIN,
                            i64::MAX
                        ),
                    ));
                }
            },
            DeValue::Float(f) => match f.as_str().parse::<f64>() {
                // `1e400` reads as ∞: only `inf` may be infinite (`nan` is a number of TOML's,
                // refused later where it stands)
                Ok(x) if !x.is_infinite() || f.as_str().contains("inf") => NodeValue::Float(x),
                _ => {
                    return Err((
                        span,
                        format!(
                            "the number {f} does not fit; valid: magnitudes up to {:e} (or inf)",
                            f64::MAX
                        ),
                    ));
                }
            },
            DeValue::Boolean(b) => NodeValue::Boolean(*b),
            DeValue::Datetime(d) => NodeValue::Datetime(*d),
            DeValue::Array(a) => NodeValue::Array(a.iter().map(Self::from_value).collect::<Result<_, _>>()?),
            DeValue::Table(t) => NodeValue::Table(table(t)?),
        };
        Ok(Self { value, span })
    }

    /// A node with the given value and span.
    pub(crate) fn new(value: NodeValue, span: Range<usize>) -> Self {
        Self { value, span }
    }

    /// The entries of a table (`None` for any other value).
    pub fn as_table(&self) -> Option<&[Entry]> {
        if let NodeValue::Table(t) = &self.value { Some(t) } else { None }
    }

    /// The elements of an array (`None` for any other value).
    pub fn as_array(&self) -> Option<&[Node]> {
        if let NodeValue::Array(a) = &self.value { Some(a) } else { None }
    }

    /// The string of a string value.
    pub fn as_str(&self) -> Option<&str> {
        if let NodeValue::String(s) = &self.value { Some(s) } else { None }
    }

    /// The entry `key` of a table.
    pub fn entry(&self, key: &str) -> Option<&Entry> {
        self.as_table()?.iter().find(|e| e.key == key)
    }

    /// The value of `key` in a table.
    pub fn get(&self, key: &str) -> Option<&Node> {
        self.entry(key).map(|e| &e.node)
    }

    /// The item at `path` below this node.
    pub fn at(&self, path: &ItemPath) -> Option<&Node> {
        path.segments().iter().try_fold(self, |cur, seg| match seg {
            PathSeg::Key(k) => cur.get(k),
            PathSeg::Index(i) => cur.as_array()?.get(*i),
        })
    }

    /// The item at `path` below this node, to change it.
    pub fn at_mut(&mut self, path: &ItemPath) -> Option<&mut Node> {
        path.segments().iter().try_fold(self, |cur, seg| match (seg, &mut cur.value) {
            (PathSeg::Key(k), NodeValue::Table(t)) => t.iter_mut().find(|e| e.key == *k).map(|e| &mut e.node),
            (PathSeg::Index(i), NodeValue::Array(a)) => a.get_mut(*i),
            _ => None,
        })
    }

    /// Sets the number at `path` to `x` (a sweep's parameter): a float takes any finite `x`,
    /// an integer a whole `x` (it stays an integer).
    ///
    /// # Errors
    /// A message when there is no item at `path`, when it is not a number, or when `x` is not
    /// whole for an integer.
    pub fn set_number(&mut self, path: &ItemPath, x: f64) -> Result<(), String> {
        let node = self.at_mut(path).ok_or_else(|| format!("`{path}`: no such item in the scene file"))?;
        node.value = match node.value {
            // 2⁵³: every whole f64 below it is exactly an i64
            NodeValue::Integer(_) if x.fract() == 0.0 && x.abs() < 9.0e15 => NodeValue::Integer(x as i64),
            NodeValue::Integer(_) => return Err(format!("`{path}` is an integer; {x} is not")),
            NodeValue::Float(_) => NodeValue::Float(x),
            _ => return Err(format!("`{path}` is not a number")),
        };
        Ok(())
    }

    /// The document as a TOML value (spans dropped), for code that reads plain values (the
    /// old-form translation of `migrate`).
    pub fn to_toml(&self) -> toml::Value {
        match &self.value {
            NodeValue::String(s) => toml::Value::String(s.clone()),
            NodeValue::Integer(i) => toml::Value::Integer(*i),
            NodeValue::Float(x) => toml::Value::Float(*x),
            NodeValue::Boolean(b) => toml::Value::Boolean(*b),
            NodeValue::Datetime(d) => toml::Value::Datetime(*d),
            NodeValue::Array(a) => toml::Value::Array(a.iter().map(Self::to_toml).collect()),
            NodeValue::Table(t) => {
                toml::Value::Table(t.iter().map(|e| (e.key.clone(), e.node.to_toml())).collect())
            }
        }
    }
}

fn table(t: &DeTable<'_>) -> Result<Vec<Entry>, Overflow> {
    t.iter()
        .map(|(k, v)| {
            Ok(Entry { key: k.get_ref().to_string(), key_span: k.span(), node: Node::from_value(v)? })
        })
        .collect()
}
