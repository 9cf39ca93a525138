//! The XML side of the loaders: parsing with a node budget, positions of elements and
//! attributes, numbers read strictly, and the record of what was used, from which every
//! element and attribute left out becomes a warning.
//!
//! Book: — (file formats: URDF, MJCF).

use std::collections::HashSet;

use roxmltree::{Document, Node, NodeId, ParsingOptions};

use super::{ImportWarning, MAX_MODEL_BYTES};
use crate::SceneError;

/// Most XML nodes in one file (elements, attributes' owners, text): a little above what
/// [`super::MAX_MODEL_LINKS`] links with their inertials, visuals and joints need.
const MAX_NODES: u32 = 2_000_000;

/// A parse error at `file:line:col`.
pub(crate) fn error_at(file: &str, (line, column): (usize, usize), message: impl Into<String>) -> SceneError {
    SceneError::Parse { file: file.into(), line, column, message: message.into() }
}

/// Parses `text` (at most [`MAX_MODEL_BYTES`] bytes, no DTD, at most [`MAX_NODES`] nodes).
///
/// # Errors
/// [`SceneError::Parse`] with the position of malformed XML, or of the size refusal.
pub(crate) fn parse<'a>(text: &'a str, file: &str) -> Result<Document<'a>, SceneError> {
    if text.len() > MAX_MODEL_BYTES {
        return Err(error_at(
            file,
            (1, 1),
            format!("the file has {} bytes; valid: at most {MAX_MODEL_BYTES} bytes", text.len()),
        ));
    }
    let options = ParsingOptions { allow_dtd: false, nodes_limit: MAX_NODES, ..ParsingOptions::default() };
    Document::parse_with_options(text, options).map_err(|e| {
        let p = e.pos();
        error_at(file, (p.row as usize, p.col as usize), format!("malformed XML: {e}"))
    })
}

/// The documents of one model (a file and the files it includes) and the record of which
/// elements and attributes were mapped.
pub(crate) struct Tracked<'a, 'i> {
    docs: Vec<(&'a Document<'i>, String)>,
    /// The first document's file name.
    pub file: String,
    used: HashSet<(usize, NodeId)>,
    used_attr: HashSet<(usize, NodeId, String)>,
    /// Elements that are left out on purpose, with the reason given in their warning.
    skipped: Vec<(usize, NodeId, String)>,
}

impl<'a, 'i> Tracked<'a, 'i> {
    pub fn new(doc: &'a Document<'i>, file: &str) -> Self {
        Self {
            docs: vec![(doc, file.into())],
            file: file.into(),
            used: HashSet::new(),
            used_attr: HashSet::new(),
            skipped: Vec::new(),
        }
    }

    /// Adds an included document.
    pub fn add(&mut self, doc: &'a Document<'i>, file: &str) {
        self.docs.push((doc, file.into()));
    }

    /// Index of the document holding `n`.
    pub fn doc_of(&self, n: Node) -> usize {
        self.docs.iter().position(|(d, _)| std::ptr::eq(*d, n.document())).unwrap_or(0)
    }

    /// 1-based line and column of an element.
    pub fn pos(&self, n: Node) -> (usize, usize) {
        let p = self.docs[self.doc_of(n)].0.text_pos_at(n.range().start);
        (p.row as usize, p.col as usize)
    }

    /// A [`SceneError::Parse`] at element `n`, naming it.
    pub fn err(&self, n: Node, message: impl std::fmt::Display) -> SceneError {
        error_at(&self.docs[self.doc_of(n)].1, self.pos(n), format!("<{}>: {message}", n.tag_name().name()))
    }

    /// Marks `n` as mapped (its attributes are marked one by one by the readers).
    pub fn use_el(&mut self, n: Node) {
        self.used.insert((self.doc_of(n), n.id()));
    }

    /// Marks `n` as left out on purpose (one warning for it and everything inside).
    pub fn skip(&mut self, n: Node, why: &str) {
        let d = self.doc_of(n);
        self.used.insert((d, n.id()));
        self.skipped.push((d, n.id(), why.into()));
    }

    /// The attribute's text, marked as mapped.
    pub fn attr<'n>(&mut self, n: Node<'n, 'i>, name: &str) -> Option<&'n str> {
        let v = n.attribute(name)?;
        self.used_attr.insert((self.doc_of(n), n.id(), name.into()));
        Some(v)
    }

    /// A required attribute.
    pub fn req<'n>(&mut self, n: Node<'n, 'i>, name: &str) -> Result<&'n str, SceneError> {
        self.attr(n, name).ok_or_else(|| self.err(n, format!("missing attribute `{name}`")))
    }

    /// Numbers of an attribute (whitespace separated), each finite, exactly `len` of them
    /// when `len` is given.
    pub fn nums(
        &mut self,
        n: Node<'_, 'i>,
        name: &str,
        len: Option<usize>,
    ) -> Result<Option<Vec<f64>>, SceneError> {
        let Some(text) = self.attr(n, name) else { return Ok(None) };
        let v = numbers(text).map_err(|m| self.err(n, format!("attribute `{name}`: {m}")))?;
        if let Some(k) = len
            && v.len() != k
        {
            return Err(self.err(n, format!("attribute `{name}` has {} numbers; valid: {k}", v.len())));
        }
        Ok(Some(v))
    }

    /// A 3-vector attribute, `default` when absent.
    pub fn vec3(&mut self, n: Node<'_, 'i>, name: &str, default: [f64; 3]) -> Result<[f64; 3], SceneError> {
        Ok(self.nums(n, name, Some(3))?.map_or(default, |v| [v[0], v[1], v[2]]))
    }

    /// A scalar attribute, `default` when absent.
    pub fn num(&mut self, n: Node<'_, 'i>, name: &str, default: f64) -> Result<f64, SceneError> {
        Ok(self.nums(n, name, Some(1))?.map_or(default, |v| v[0]))
    }

    /// Warnings for every element not mapped (one per unmapped subtree) and every attribute
    /// of a mapped element not read, in document order, over every document.
    pub fn all_warnings(&self) -> Vec<ImportWarning> {
        self.docs.iter().flat_map(|(d, _)| self.warnings(d.root_element())).collect()
    }

    /// As [`Tracked::all_warnings`], for the tree under `root`.
    pub fn warnings(&self, root: Node) -> Vec<ImportWarning> {
        let mut out = Vec::new();
        let warn = |n: Node, message: String, out: &mut Vec<ImportWarning>| {
            let (line, column) = self.pos(n);
            out.push(ImportWarning { file: self.docs[self.doc_of(n)].1.clone(), line, column, message });
        };
        let mut stack = vec![root];
        while let Some(n) = stack.pop() {
            let tag = n.tag_name().name();
            let d = self.doc_of(n);
            if let Some((_, _, why)) = self.skipped.iter().find(|(k, id, _)| *k == d && *id == n.id()) {
                warn(n, format!("<{tag}> not used: {why}"), &mut out);
                continue;
            }
            if !self.used.contains(&(d, n.id())) {
                warn(
                    n,
                    format!("<{tag}> does not map onto the scene and is left out (with its contents)"),
                    &mut out,
                );
                continue;
            }
            let left: Vec<&str> = n
                .attributes()
                .map(|a| a.name())
                .filter(|a| !self.used_attr.contains(&(d, n.id(), (*a).to_string())))
                .collect();
            if !left.is_empty() {
                warn(
                    n,
                    format!(
                        "<{tag}>: attribute(s) {} do not map onto the scene and are left out",
                        left.join(", ")
                    ),
                    &mut out,
                );
            }
            let kids: Vec<Node> = n.children().filter(Node::is_element).collect();
            stack.extend(kids.into_iter().rev());
        }
        out
    }
}

/// Whitespace-separated finite numbers.
pub(crate) fn numbers(text: &str) -> Result<Vec<f64>, String> {
    text.split_whitespace()
        .map(|t| match t.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            Ok(_) => Err(format!("`{t}` is not finite; valid: finite numbers")),
            Err(_) => Err(format!("`{t}` is not a number; valid: decimal numbers")),
        })
        .collect()
}

/// Counts `needle` in `text` up to `cap + 1` (a cheap pre-scan that refuses a huge model
/// before the parser builds its tree).
pub(crate) fn count_capped(text: &str, needle: &str, cap: usize) -> usize {
    text.match_indices(needle).take(cap + 1).count()
}
