//! Every error of a file in one pass: after an error, the item at fault is set aside (replaced
//! by a harmless stand-in, or removed and the later items renumbered back to the file's own
//! indices) and the file is checked again, up to [`MAX_ERRORS`]. Errors are reported in file
//! order. Bodies are the foundation of everything else: after an error inside a body (its
//! shape or its values) no later stage is run, so that no error is reported that only follows
//! from an earlier one.
//!
//! Book: — (file format).

use toml::Value;

use super::SceneError;
use super::source::SceneSource;
use super::spec::{EffectSpec, SceneSpec};

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
fn path_of(e: &SceneError) -> Option<&str> {
    match e {
        SceneError::Invalid { path, .. } => Some(path),
        _ => None,
    }
}

/// The first key and index of a path: `effects[3].k` → (`effects`, Some(3)).
fn head(path: &str) -> (&str, Option<usize>) {
    let first = path.split('.').next().unwrap_or("");
    match first.split_once('[') {
        Some((key, rest)) => (key, rest.split(']').next().and_then(|i| i.parse().ok())),
        None => (first, None),
    }
}

/// Sets aside the item at `path` of a document that failed to deserialize, so that the next
/// attempt finds the next error; `false` when nothing can be set aside (stop).
pub(crate) fn patch_document(doc: &mut Value, path: &str) -> bool {
    let Some(root) = doc.as_table_mut() else { return false };
    let (key, index) = head(path);
    if key.is_empty() {
        return false;
    }
    let stand_in = |i: usize, old: Option<&Value>| -> Option<Value> {
        let name = old.and_then(|o| o.get("name")).cloned().unwrap_or_else(|| Value::String(format!("_{i}")));
        let text = match key {
            "bodies" => "joint = { type = \"weld\" }\nmass = { shape = \"massless\" }",
            "effects" => "type = \"uniform_gravity\"\ng = [0.0, 0.0, 0.0]",
            "frames" => "axis = [0.0, 0.0, 1.0]\nangle = 0.0",
            "loops" => "type = \"ball\"\na = { body = \"ground\" }\nb = { body = \"ground\" }",
            _ => return None,
        };
        let mut t: toml::Table = toml::from_str(text).ok()?;
        if key != "effects" {
            t.insert("name".into(), name);
        }
        Some(Value::Table(t))
    };
    match (index, root.get_mut(key)) {
        (Some(i), Some(Value::Array(a))) if i < a.len() => {
            let replacement = match &a[i] {
                Value::String(_) => Some(Value::String(format!("_{i}"))),
                old => stand_in(i, Some(old)),
            };
            match replacement {
                Some(r) if a[i] != r => {
                    a[i] = r;
                    true
                }
                _ => false,
            }
        }
        (_, Some(_)) => {
            // a top-level value or table: its default (required keys) or nothing
            let default = match key {
                "name" => Some(Value::String("x".into())),
                "duration" => Some(Value::Float(1.0)),
                "bodies" => return false,
                _ => None,
            };
            match default {
                Some(d) if root.get(key) != Some(&d) => {
                    root.insert(key.into(), d);
                    true
                }
                Some(_) => false,
                None => root.remove(key).is_some(),
            }
        }
        // an unknown or missing top-level key
        (_, None) => match key {
            "name" => root.insert("name".into(), Value::String("x".into())).is_none(),
            "duration" => root.insert("duration".into(), Value::Float(1.0)).is_none(),
            _ => false,
        },
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
        let Some(path) = path_of(&e).map(str::to_string) else { return e };
        let (key, Some(i)) = head(&path) else { return e };
        let j = self.original(key, i);
        if i == j {
            return e;
        }
        let SceneError::Invalid { message, .. } = e else { return e };
        let rest = path.split_once(']').map_or("", |(_, r)| r);
        src.invalid(format!("{key}[{j}]{rest}"), message)
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
pub(crate) fn patch_spec(spec: &mut SceneSpec, path: &str, removed: &mut Removed) -> bool {
    let (key, index) = head(path);
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
