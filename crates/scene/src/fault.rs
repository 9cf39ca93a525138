//! From a deserialization error (`de`) to the item at fault and the words for the writer of
//! the file. Most errors already carry their item's path. One raised out of sight inside a
//! tagged table (see `de`) carries the table's path: the item is found inside that table from
//! the data serde gave, in the order serde reads a table (entries in order, inner tables
//! when reached):
//!
//! - an unknown key: the first table there holding that key among keys the struct knows;
//! - a missing key: the table whose deserialization changes when the key is given (each
//!   table lacking it is tried in serde's order, by deserializing the document again with the
//!   key added: a table without that field rejects it as unknown or ignores it);
//! - an unknown variant: the tag (`type`, `kind`, `shape`) holding that name;
//! - a wrong value or length: the first value there that is what serde found.
//!
//! Book: — (file format).

use super::de::{DeError, Found, Kind};
use super::error::closest;
use super::path::ItemPath;
use super::tree::{Entry, Node, NodeValue};

/// The keys that tag a table's kind (`#[serde(tag = …)]` of the spec's enums).
const TAGS: [&str; 3] = ["type", "kind", "shape"];

/// Most tables tried for a missing key (see `missing_at`).
const MAX_PROBES: usize = 8;

/// A deserialization error, located and worded.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Fault {
    /// The item at fault (for a missing key: where it would be).
    pub path: ItemPath,
    /// Located at the key (an unknown key) rather than at the value.
    pub at_key: bool,
    /// What is wrong and what would be valid.
    pub message: String,
    /// The key a "did you mean" names, with its table's path (a misspelt key explains the
    /// missing one it suggests).
    pub suggested: Option<ItemPath>,
    /// A required key is missing.
    pub missing: bool,
}

/// Locates and words `e`, raised deserializing `doc`; `probe` deserializes a changed copy of
/// the document again (the same target type) and returns its error.
pub(crate) fn fault(e: &DeError, doc: &Node, probe: &dyn Fn(&Node) -> Option<DeError>) -> Fault {
    let at = e.path.clone().unwrap_or_default();
    let path = if e.buffered { inside(e, doc, &at, probe).unwrap_or(at) } else { at };
    let mut f = Fault { path, at_key: e.at_key, message: String::new(), suggested: None, missing: false };
    f.message = match &e.kind {
        Kind::UnknownField { field, expected } => {
            f.at_key = true;
            if e.buffered || f.path.last_key() != Some(field.as_str()) {
                f.path = f.path.key(field);
            }
            let hint = if expected.len() > 1 { closest(field, expected.iter().copied()) } else { None };
            if let (Some(best), Some(table)) = (hint, f.path.parent()) {
                f.suggested = Some(table.key(best));
            }
            let valid = if expected.is_empty() { "none here".to_string() } else { quoted(expected) };
            let tail = hint.map(|b| format!(" (did you mean `{b}`?)")).unwrap_or_default();
            format!("unknown key `{field}`; valid: {valid}{tail}")
        }
        Kind::MissingField { field } => {
            f.path = f.path.key(field);
            f.missing = true;
            format!("the required key `{field}` is missing; valid: a table that gives `{field}`")
        }
        Kind::UnknownVariant { variant, expected } => {
            let tag = f.path.last_key().unwrap_or("variant").to_string();
            let valid = if expected.is_empty() { "none".to_string() } else { quoted(expected) };
            format!("unknown {tag} `{variant}`; valid: {valid}")
        }
        Kind::Invalid { shown, expected, value, .. } => {
            // a date-time reaches serde as TOML's one-entry map: name it as written
            let dated = matches!(doc.at(&f.path).map(|n| &n.value), Some(NodeValue::Datetime(_)));
            let shown = if dated { "a date-time" } else { shown.as_str() };
            let head = format!("invalid {}: {shown}", if *value { "value" } else { "type" });
            match expected_words(expected) {
                Some(words) => format!("{head}; valid: {words}"),
                None => format!("{head}, expected {expected}"),
            }
        }
        Kind::InvalidLength { len, expected } => format!("invalid length {len}, expected {expected}"),
        Kind::DuplicateField { field } => {
            format!("duplicate key `{field}`; valid: each key once in its table")
        }
        Kind::Custom(m) => m.clone(),
    };
    f
}

fn quoted(names: &[&str]) -> String {
    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}

/// serde's name of an expected type in a scene writer's words (`None`: serde's own words).
fn expected_words(expected: &str) -> Option<&'static str> {
    match expected {
        "usize" | "u64" | "u32" | "u16" | "u8" => Some("a whole number ≥ 0 (no decimal point)"),
        "i64" | "i32" => Some("a whole number (no decimal point)"),
        "f64" | "f32" => Some("a number"),
        "a sequence" => Some("an array [ … ]"),
        "a string" => Some("a string in quotes"),
        "a boolean" => Some("true or false"),
        "a map" => Some("a table { … }"),
        e if e.starts_with("struct ") || e.starts_with("internally tagged enum ") => Some("a table { … }"),
        _ => None,
    }
}

/// The item inside the tagged table at `at` that `e` is about.
fn inside(
    e: &DeError,
    doc: &Node,
    at: &ItemPath,
    probe: &dyn Fn(&Node) -> Option<DeError>,
) -> Option<ItemPath> {
    let top = doc.at(at)?;
    let mut pre = Vec::new();
    preorder(top, at.clone(), None, &mut pre);
    match &e.kind {
        Kind::UnknownField { field, expected } => {
            let known = |k: &str| expected.iter().chain(&TAGS).any(|x| *x == k);
            let holding: Vec<&(ItemPath, &Node, Option<&str>)> =
                pre.iter().filter(|(_, n, _)| n.get(field).is_some()).collect();
            // the table whose keys before this one are all the struct's own
            let fits = |n: &Node| {
                n.as_table().is_some_and(|t| t.iter().take_while(|x| x.key != *field).all(|x| known(&x.key)))
            };
            let best = holding.iter().find(|(_, n, _)| fits(n)).or(holding.first());
            best.map(|(p, _, _)| p.clone())
        }
        Kind::MissingField { field } => missing_at(field, doc, top, at, probe),
        Kind::UnknownVariant { variant, .. } => {
            let named = |(_, n, k): &&(ItemPath, &Node, Option<&str>)| {
                n.as_str() == Some(variant.as_str()) && k.is_some()
            };
            let tagged = pre.iter().filter(named).find(|(_, _, k)| k.is_some_and(|k| TAGS.contains(&k)));
            tagged.or_else(|| pre.iter().find(named)).map(|(p, _, _)| p.clone())
        }
        Kind::Invalid { found, .. } => {
            // the tagged table itself is a table by right: a found table is one inside it
            let is = |n: &Node| matches_found(n, found);
            pre.iter()
                .skip(usize::from(*found == Found::Map))
                .find(|(_, n, _)| is(n))
                .map(|(p, _, _)| p.clone())
        }
        Kind::InvalidLength { len, .. } => pre
            .iter()
            .find(|(_, n, _)| {
                n.as_array().map(<[Node]>::len).or(n.as_table().map(<[Entry]>::len)) == Some(*len)
            })
            .map(|(p, _, _)| p.clone()),
        Kind::DuplicateField { .. } | Kind::Custom(_) => None,
    }
}

/// The table inside `top` (at `at`) whose struct lacks the required key `field`: each table
/// lacking it, inner tables first as serde finishes them, is given `field = 0.0` in a copy of
/// the document; the one whose error changes (other than to `field` being unknown) is it.
fn missing_at(
    field: &str,
    doc: &Node,
    top: &Node,
    at: &ItemPath,
    probe: &dyn Fn(&Node) -> Option<DeError>,
) -> Option<ItemPath> {
    let mut post = Vec::new();
    postorder(top, at.clone(), &mut post);
    let lacking: Vec<ItemPath> =
        post.into_iter().filter(|(_, n)| n.get(field).is_none()).map(|(p, _)| p).collect();
    if lacking.len() <= 1 {
        return lacking.into_iter().next();
    }
    let same = |e: &Option<DeError>| match e.as_ref().map(|e| &e.kind) {
        Some(Kind::MissingField { field: f }) => *f == field,
        Some(Kind::UnknownField { field: f, .. }) => f == field,
        _ => false,
    };
    // each try reads the whole document again: a bounded number, in serde's order (a hostile
    // file of many inner tables falls back to the tagged table itself)
    lacking.into_iter().take(MAX_PROBES).find(|table| {
        let mut copy = doc.clone();
        let Some(Node { value: NodeValue::Table(t), span }) = copy.at_mut(table) else { return false };
        let here = span.start..span.start;
        t.push(Entry {
            key: field.to_string(),
            key_span: here.clone(),
            node: Node::new(NodeValue::Float(0.0), here),
        });
        !same(&probe(&copy))
    })
}

/// Whether `n` is the value serde found.
fn matches_found(n: &Node, found: &Found) -> bool {
    match (&n.value, found) {
        (NodeValue::Boolean(a), Found::Bool(b)) => a == b,
        (NodeValue::Integer(a), Found::Signed(b)) => a == b,
        (NodeValue::Integer(a), Found::Unsigned(b)) => u64::try_from(*a).is_ok_and(|a| a == *b),
        (NodeValue::Float(a), Found::Float(b)) => a == b || (a.is_nan() && b.is_nan()),
        (NodeValue::String(a), Found::Str(b)) => a == b,
        (NodeValue::Array(_), Found::Seq) | (NodeValue::Table(_), Found::Map) => true,
        (NodeValue::Datetime(_), Found::Other) => true,
        _ => false,
    }
}

/// Every node of `node`'s subtree in serde's reading order (a table, then its entries in
/// order), with its path and the key it stands under.
fn preorder<'a>(
    node: &'a Node,
    path: ItemPath,
    key: Option<&'a str>,
    out: &mut Vec<(ItemPath, &'a Node, Option<&'a str>)>,
) {
    out.push((path.clone(), node, key));
    match &node.value {
        NodeValue::Table(t) => t.iter().for_each(|e| preorder(&e.node, path.key(&e.key), Some(&e.key), out)),
        NodeValue::Array(a) => a.iter().enumerate().for_each(|(i, n)| preorder(n, path.index(i), None, out)),
        _ => {}
    }
}

/// The tables of `node`'s subtree in the order serde finishes them (inner tables first).
fn postorder<'a>(node: &'a Node, path: ItemPath, out: &mut Vec<(ItemPath, &'a Node)>) {
    match &node.value {
        NodeValue::Table(t) => {
            t.iter().for_each(|e| postorder(&e.node, path.key(&e.key), out));
            out.push((path, node));
        }
        NodeValue::Array(a) => a.iter().enumerate().for_each(|(i, n)| postorder(n, path.index(i), out)),
        _ => {}
    }
}
