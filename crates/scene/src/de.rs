//! The scene's own serde `Deserializer`: reads a spec from the spanned document (`tree`) and
//! tracks the item path itself, so that an error says *which* item is at fault from the data
//! serde gives (`unknown_field(field, expected)`, `missing_field`, `unknown_variant`,
//! `invalid_type`, …), never from its message text.
//!
//! The path is kept as a trail on the stack and written out only for an error. An error gets
//! the path of the innermost item whose deserialization it leaves; an unknown key is located
//! at its key. Internally tagged enums (`#[serde(tag = "type")]`) read their table whole through
//! `deserialize_any` and deserialize it afterwards from serde's own buffer, out of sight: an
//! error from there leaves with the path of the tagged table and the mark `buffered`, and
//! `fault` finds the item inside it.
//!
//! Book: — (file format).

use std::cell::Cell;
use std::fmt;

use serde::de::value::BorrowedStrDeserializer;
use serde::de::{self, DeserializeSeed, Expected, MapAccess, SeqAccess, Unexpected, Visitor};

use super::path::{ItemPath, PathSeg};
use super::tree::{Entry, Node, NodeValue};

/// What serde found at the item, for matching it in the document.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Found {
    Bool(bool),
    Signed(i64),
    Unsigned(u64),
    Float(f64),
    Str(String),
    Seq,
    Map,
    Other,
}

/// What went wrong, as serde reports it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Kind {
    UnknownField {
        field: String,
        expected: &'static [&'static str],
    },
    MissingField {
        field: &'static str,
    },
    UnknownVariant {
        variant: String,
        expected: &'static [&'static str],
    },
    /// A value of the wrong type (`value: false`) or out of range (`value: true`).
    Invalid {
        found: Found,
        shown: String,
        expected: String,
        value: bool,
    },
    InvalidLength {
        len: usize,
        expected: String,
    },
    DuplicateField {
        field: &'static str,
    },
    Custom(String),
}

/// A deserialization error with the path of the item it left (`None` until it leaves one).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct DeError {
    pub kind: Kind,
    pub path: Option<ItemPath>,
    /// Raised while reading a key (an unknown key: located at the key itself).
    pub at_key: bool,
    /// Raised out of sight, from serde's buffer of the table at `path` (a tagged enum).
    pub buffered: bool,
}

impl DeError {
    fn new(kind: Kind) -> Self {
        Self { kind, path: None, at_key: false, buffered: false }
    }

    /// The error with the path of the trail, unless an inner item already gave it one.
    fn leaving(mut self, trail: &Trail<'_>) -> Self {
        if self.path.is_none() {
            self.path = Some(trail.path());
            self.buffered = trail.buffered.get();
        }
        self
    }
}

impl fmt::Display for DeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let quoted = |names: &[&str]| names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ");
        match &self.kind {
            Kind::UnknownField { field, expected } => {
                write!(f, "unknown key `{field}`; valid: {}", quoted(expected))
            }
            Kind::MissingField { field } => write!(f, "the required key `{field}` is missing"),
            Kind::UnknownVariant { variant, expected } => {
                write!(f, "unknown variant `{variant}`; valid: {}", quoted(expected))
            }
            Kind::Invalid { shown, expected, value, .. } => {
                let what = if *value { "value" } else { "type" };
                write!(f, "invalid {what}: {shown}, expected {expected}")
            }
            Kind::InvalidLength { len, expected } => write!(f, "invalid length {len}, expected {expected}"),
            Kind::DuplicateField { field } => write!(f, "duplicate key `{field}`"),
            Kind::Custom(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for DeError {}

fn found(u: &Unexpected<'_>) -> Found {
    match *u {
        Unexpected::Bool(b) => Found::Bool(b),
        Unexpected::Signed(i) => Found::Signed(i),
        Unexpected::Unsigned(i) => Found::Unsigned(i),
        Unexpected::Float(x) => Found::Float(x),
        Unexpected::Str(s) => Found::Str(s.to_string()),
        Unexpected::Seq => Found::Seq,
        Unexpected::Map => Found::Map,
        _ => Found::Other,
    }
}

impl de::Error for DeError {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        Self::new(Kind::Custom(msg.to_string()))
    }
    fn invalid_type(unexp: Unexpected<'_>, exp: &dyn Expected) -> Self {
        let (found, shown) = (found(&unexp), unexp.to_string());
        Self::new(Kind::Invalid { found, shown, expected: exp.to_string(), value: false })
    }
    fn invalid_value(unexp: Unexpected<'_>, exp: &dyn Expected) -> Self {
        let (found, shown) = (found(&unexp), unexp.to_string());
        Self::new(Kind::Invalid { found, shown, expected: exp.to_string(), value: true })
    }
    fn invalid_length(len: usize, exp: &dyn Expected) -> Self {
        Self::new(Kind::InvalidLength { len, expected: exp.to_string() })
    }
    fn unknown_variant(variant: &str, expected: &'static [&'static str]) -> Self {
        Self::new(Kind::UnknownVariant { variant: variant.to_string(), expected })
    }
    fn unknown_field(field: &str, expected: &'static [&'static str]) -> Self {
        Self::new(Kind::UnknownField { field: field.to_string(), expected })
    }
    fn missing_field(field: &'static str) -> Self {
        Self::new(Kind::MissingField { field })
    }
    fn duplicate_field(field: &'static str) -> Self {
        Self::new(Kind::DuplicateField { field })
    }
}

/// One step of the path being read, on the stack.
enum Step<'t> {
    Root,
    Key(&'t str),
    Index(usize),
}

/// The path being read, as a chain of stack frames; `buffered` marks a table read whole by
/// `deserialize_any` (and so deserialized afterwards out of sight).
struct Trail<'t> {
    parent: Option<&'t Trail<'t>>,
    step: Step<'t>,
    buffered: Cell<bool>,
}

impl<'t> Trail<'t> {
    fn new(parent: Option<&'t Trail<'t>>, step: Step<'t>) -> Self {
        Self { parent, step, buffered: Cell::new(false) }
    }

    fn path(&self) -> ItemPath {
        let mut steps = Vec::new();
        let mut cur = Some(self);
        while let Some(t) = cur {
            match t.step {
                Step::Root => {}
                Step::Key(k) => steps.push(PathSeg::Key(k.to_string())),
                Step::Index(i) => steps.push(PathSeg::Index(i)),
            }
            cur = t.parent;
        }
        steps.reverse();
        ItemPath::from(steps)
    }
}

/// Deserializes `T` from the document `root`; an error carries the path of its item.
pub(crate) fn from_node<'de, T: serde::Deserialize<'de>>(root: &'de Node) -> Result<T, DeError> {
    let trail = Trail::new(None, Step::Root);
    T::deserialize(NodeDe { node: root, trail: &trail }).map_err(|e| e.leaving(&trail))
}

/// A deserializer of one node.
struct NodeDe<'de, 't> {
    node: &'de Node,
    trail: &'t Trail<'t>,
}

/// What a node is, in serde's words (for a type error raised here).
fn unexpected(node: &Node) -> Unexpected<'_> {
    match &node.value {
        NodeValue::String(s) => Unexpected::Str(s),
        NodeValue::Integer(i) => Unexpected::Signed(*i),
        NodeValue::Float(x) => Unexpected::Float(*x),
        NodeValue::Boolean(b) => Unexpected::Bool(*b),
        NodeValue::Datetime(_) => Unexpected::Other("a date-time"),
        NodeValue::Array(_) => Unexpected::Seq,
        NodeValue::Table(_) => Unexpected::Map,
    }
}

impl<'de> de::Deserializer<'de> for NodeDe<'de, '_> {
    type Error = DeError;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        match &self.node.value {
            NodeValue::String(s) => visitor.visit_borrowed_str(s),
            NodeValue::Integer(i) => visitor.visit_i64(*i),
            NodeValue::Float(x) => visitor.visit_f64(*x),
            NodeValue::Boolean(b) => visitor.visit_bool(*b),
            // TOML's own convention, so that `toml::Value` reads a date-time back as one
            NodeValue::Datetime(d) => visitor.visit_map(DatetimeAccess(Some(d.to_string()))),
            NodeValue::Array(a) => {
                let mut seq = Seq { items: a.iter().enumerate(), trail: self.trail };
                let v = visitor.visit_seq(&mut seq)?;
                // a fixed-size target (`[f64; 3]`) stops reading early: the rest is an error,
                // never dropped
                match seq.items.len() {
                    0 => Ok(v),
                    left => Err(de::Error::invalid_length(
                        a.len(),
                        &format!("an array of {} elements", a.len() - left).as_str(),
                    )),
                }
            }
            NodeValue::Table(t) => {
                self.trail.buffered.set(true);
                visitor.visit_map(Map { entries: t.iter(), current: None, trail: self.trail })
            }
        }
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        // TOML has no null: a key that is there is `Some`
        visitor.visit_some(self)
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, DeError> {
        match &self.node.value {
            NodeValue::Table(t) => {
                visitor.visit_map(Map { entries: t.iter(), current: None, trail: self.trail })
            }
            _ => Err(de::Error::invalid_type(unexpected(self.node), &visitor)),
        }
    }

    fn deserialize_map<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
        match &self.node.value {
            NodeValue::Table(t) => {
                visitor.visit_map(Map { entries: t.iter(), current: None, trail: self.trail })
            }
            _ => Err(de::Error::invalid_type(unexpected(self.node), &visitor)),
        }
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _variants: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, DeError> {
        match &self.node.value {
            // a unit variant by its name (`limits = "contact"`)
            NodeValue::String(s) => visitor.visit_enum(BorrowedStrDeserializer::new(s)),
            _ => Err(de::Error::invalid_type(unexpected(self.node), &visitor)),
        }
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value, DeError> {
        visitor.visit_newtype_struct(self)
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf unit
        unit_struct seq tuple tuple_struct identifier ignored_any
    }
}

/// The entries of a table; each value is read with its key on the trail.
struct Map<'de, 't> {
    entries: std::slice::Iter<'de, Entry>,
    current: Option<&'de Entry>,
    trail: &'t Trail<'t>,
}

impl<'de> MapAccess<'de> for Map<'de, '_> {
    type Error = DeError;

    fn next_key_seed<K: DeserializeSeed<'de>>(&mut self, seed: K) -> Result<Option<K::Value>, DeError> {
        let Some(entry) = self.entries.next() else { return Ok(None) };
        self.current = Some(entry);
        seed.deserialize(BorrowedStrDeserializer::new(&entry.key)).map(Some).map_err(|mut e: DeError| {
            // an unknown key: at the key itself
            if e.path.is_none() {
                e.path = Some(self.trail.path().key(&entry.key));
                e.at_key = true;
            }
            e
        })
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, DeError> {
        let entry =
            self.current.take().ok_or_else(|| de::Error::custom("a value was read before its key"))?;
        let trail = Trail::new(Some(self.trail), Step::Key(&entry.key));
        seed.deserialize(NodeDe { node: &entry.node, trail: &trail }).map_err(|e| e.leaving(&trail))
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.entries.len())
    }
}

/// The elements of an array; each is read with its index on the trail.
struct Seq<'de, 't> {
    items: std::iter::Enumerate<std::slice::Iter<'de, Node>>,
    trail: &'t Trail<'t>,
}

impl<'de> SeqAccess<'de> for Seq<'de, '_> {
    type Error = DeError;

    fn next_element_seed<T: DeserializeSeed<'de>>(&mut self, seed: T) -> Result<Option<T::Value>, DeError> {
        let Some((i, node)) = self.items.next() else { return Ok(None) };
        let trail = Trail::new(Some(self.trail), Step::Index(i));
        seed.deserialize(NodeDe { node, trail: &trail }).map(Some).map_err(|e| e.leaving(&trail))
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.items.len())
    }
}

/// A date-time as TOML's deserializer hands it to `toml::Value`: a one-entry map.
struct DatetimeAccess(Option<String>);

/// The key TOML's `Datetime` deserializes from (toml's `datetime::FIELD`).
const DATETIME_FIELD: &str = "$__toml_private_datetime";

impl<'de> MapAccess<'de> for DatetimeAccess {
    type Error = DeError;

    fn next_key_seed<K: DeserializeSeed<'de>>(&mut self, seed: K) -> Result<Option<K::Value>, DeError> {
        if self.0.is_none() {
            return Ok(None);
        }
        seed.deserialize(BorrowedStrDeserializer::new(DATETIME_FIELD)).map(Some)
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, DeError> {
        let text = self.0.take().ok_or_else(|| de::Error::custom("a date-time was read twice"))?;
        seed.deserialize(de::value::StringDeserializer::new(text))
    }
}
