//! Every error of a file in one pass: after an error, the item at fault is set aside (replaced
//! by a harmless stand-in, or removed and the later items renumbered back to the file's own
//! indices) and the file is checked again, up to [`MAX_ERRORS`]. Errors are reported in file
//! order. Bodies are the foundation of everything else: after an error inside a body (its
//! shape or its values) no later stage is run, so that no error is reported that only follows
//! from an earlier one.
//!
//! Book: — (file format).

use super::SceneError;
use super::path::{AsItemPath, ItemPath, PathSeg};
use super::source::SceneSource;
use super::spec::{EffectSpec, SceneSpec};
use super::tree::{Entry, Node, NodeValue};

/// At most this many errors are reported for one file.
pub const MAX_ERRORS: usize = 20;

/// The errors found, in file order: one error as itself, several as [`SceneError::Many`].
pub(crate) fn report(mut errors: Vec<SceneError>) -> SceneError {
    errors.sort_by_key(|e| match e {
        SceneError::Parse { line, column, .. } | SceneError::Invalid { line, column, .. } => (*line, *column),
        _ => (usize::MAX, usize::MAX),
    });
    errors.dedup();
    if errors.len() == 1 { errors.remove(0) } else { SceneError::Many { errors } }
}

/// The item path of a located error.
fn path_of(e: &SceneError) -> Option<ItemPath> {
    match e {
        SceneError::Invalid { path, .. } => Some(path.item_path().into_owned()),
        _ => None,
    }
}

/// A value for the stand-ins, located at `span` (where the item it stands in for was).
fn node(value: NodeValue, span: &std::ops::Range<usize>) -> Node {
    Node::new(value, span.clone())
}

/// A table of `entries`, located at `span`.
fn table(entries: Vec<(&str, Node)>, span: &std::ops::Range<usize>) -> Node {
    let entries = entries
        .into_iter()
        .map(|(key, node)| Entry { key: key.to_string(), key_span: span.clone(), node })
        .collect();
    Node::new(NodeValue::Table(entries), span.clone())
}

/// A harmless stand-in for element `i` of the list `key` (`None`: the list has none), keeping
/// the old element's name: a weld of no mass, zero gravity, the identity frame, a loop of the
/// ground with itself.
fn stand_in(key: &str, i: usize, old: &Node) -> Option<Node> {
    let at = &old.span;
    let s = |x: &str| node(NodeValue::String(x.to_string()), at);
    let f = |x: f64| node(NodeValue::Float(x), at);
    let mut entries = match key {
        "bodies" => vec![
            ("joint", table(vec![("type", s("weld"))], at)),
            ("mass", table(vec![("shape", s("massless"))], at)),
        ],
        "effects" => {
            let g = node(NodeValue::Array(vec![f(0.0), f(0.0), f(0.0)]), at);
            return Some(table(vec![("type", s("uniform_gravity")), ("g", g)], at));
        }
        "frames" => {
            vec![("axis", node(NodeValue::Array(vec![f(0.0), f(0.0), f(1.0)]), at)), ("angle", f(0.0))]
        }
        "loops" => {
            let ground = || table(vec![("body", s("ground"))], at);
            vec![("type", s("ball")), ("a", ground()), ("b", ground())]
        }
        _ => return None,
    };
    let name = old.get("name").cloned().unwrap_or_else(|| s(&format!("_{i}")));
    entries.push(("name", name));
    Some(table(entries, at))
}

/// Sets aside the item at `path` of a document that failed to deserialize, so that the next
/// attempt finds the next error; `false` when nothing can be set aside (stop).
pub(crate) fn patch_document(doc: &mut Node, path: &ItemPath) -> bool {
    let Some((key, index)) = path.head() else { return false };
    let key = key.to_string();
    let NodeValue::Table(root) = &mut doc.value else { return false };
    let at = doc.span.clone();
    let entry = root.iter().position(|e| e.key == key);
    match (index, entry) {
        (Some(i), Some(k)) => {
            let NodeValue::Array(a) = &mut root[k].node.value else { return false };
            let Some(old) = a.get(i) else { return false };
            let replacement = match &old.value {
                NodeValue::String(_) => Some(node(NodeValue::String(format!("_{i}")), &old.span)),
                _ => stand_in(&key, i, old),
            };
            match replacement {
                Some(r) if a[i] != r => {
                    a[i] = r;
                    true
                }
                _ => false,
            }
        }
        (None, Some(k)) => {
            // a top-level value or table: its default (required keys) or nothing
            let default = match key.as_str() {
                "name" => Some(NodeValue::String("x".into())),
                "duration" => Some(NodeValue::Float(1.0)),
                "bodies" => return false,
                _ => None,
            };
            match default {
                Some(d) if root[k].node.value != d => {
                    root[k].node.value = d;
                    true
                }
                Some(_) => false,
                None => {
                    root.remove(k);
                    true
                }
            }
        }
        (Some(_), None) => false,
        // an unknown or missing top-level key
        (None, None) => {
            let value = match key.as_str() {
                "name" => NodeValue::String("x".into()),
                "duration" => NodeValue::Float(1.0),
                _ => return false,
            };
            root.push(Entry { key, key_span: at.start..at.start, node: node(value, &(at.start..at.start)) });
            true
        }
    }
}

/// Items removed from the spec's arrays, by their index in the file.
#[derive(Debug, Default)]
pub(crate) struct Removed {
    lists: Vec<(&'static str, Vec<usize>)>,
}

impl Removed {
    /// The file's index of element `i` of the list `key` after the removals.
    fn original(&self, key: &str, i: usize) -> usize {
        let Some((_, gone)) = self.lists.iter().find(|(k, _)| *k == key) else { return i };
        (0..).filter(|j| !gone.contains(j)).nth(i).unwrap_or(i)
    }

    /// The error with its path's first index renumbered to the file's, and located there.
    pub fn renumber(&self, e: SceneError, src: &SceneSource) -> SceneError {
        let Some(path) = path_of(&e) else { return e };
        let Some((key, Some(i))) = path.head() else { return e };
        let j = self.original(key, i);
        if i == j {
            return e;
        }
        let SceneError::Invalid { message, .. } = e else { return e };
        let mut segs = path.segments().to_vec();
        segs[1] = PathSeg::Index(j);
        src.invalid(ItemPath::from(segs), message)
    }

    fn remove(&mut self, key: &'static str, i: usize) {
        let j = self.original(key, i);
        match self.lists.iter_mut().find(|(k, _)| *k == key) {
            Some((_, gone)) => gone.push(j),
            None => self.lists.push((key, vec![j])),
        }
    }
}

/// Sets aside the item at `path` of a spec that failed to validate; `false` when nothing can
/// be set aside (an error inside a body, or one that is not an item's).
pub(crate) fn patch_spec(spec: &mut SceneSpec, path: &ItemPath, removed: &mut Removed) -> bool {
    let Some((key, index)) = path.head() else { return false };
    let take = |len: usize| index.filter(|i| *i < len);
    match key {
        "effects" => match take(spec.effects.len()) {
            // a harmless stand-in keeps the later effects' indices; trim names the effects'
            // inputs, so it is not checked against a stand-in
            Some(i) => {
                spec.effects[i] = EffectSpec::UniformGravity { g: [0.0; 3] };
                spec.trim = None;
                true
            }
            None => false,
        },
        "loops" => take(spec.loops.len()).is_some_and(|i| {
            // with the loop go the outputs of its reaction (they would only repeat the error)
            let reaction = format!("reaction:{}", spec.loops.remove(i).name());
            removed.remove("loops", i);
            while let Some(k) = spec.outputs.iter().position(|o| *o == reaction) {
                spec.outputs.remove(k);
                removed.remove("outputs", k);
            }
            true
        }),
        "outputs" => take(spec.outputs.len()).is_some_and(|i| {
            spec.outputs.remove(i);
            removed.remove("outputs", i);
            true
        }),
        "checks" => take(spec.checks.len()).is_some_and(|i| {
            spec.checks.remove(i);
            removed.remove("checks", i);
            true
        }),
        "trim" => spec.trim.take().is_some(),
        "linearize" => spec.linearize.take().is_some(),
        "accuracy" => spec.accuracy.take().is_some(),
        "method" => spec.method.take().is_some(),
        "max_steps" => spec.max_steps.take().is_some(),
        "max_wall_seconds" => spec.max_wall_seconds.take().is_some(),
        "duration" if spec.duration != 1.0 => {
            spec.duration = 1.0;
            true
        }
        "samples" if spec.samples != 200 => {
            spec.samples = 200;
            true
        }
        _ => false,
    }
}
