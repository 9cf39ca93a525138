//! Reading a spec from a scene file's document: quantity strings converted by a schema
//! (`quantities`), then deserialized (`de`), with every shape error of the file reported in
//! one pass (`many`). These are methods of [`SceneSource`] written above the modules they
//! use, so that the source itself stays below them.
//!
//! Book: — (file format), §15.19 (quantities).

use serde::de::DeserializeOwned;

use super::SceneError;
use super::many::{MAX_ERRORS, patch_document};
use super::path::ItemPath;
use super::quantities::{Schema, convert_on};
use super::source::SceneSource;
use super::tree::Node;

impl SceneSource<'_> {
    /// The document with its quantity strings converted by `schema` (see
    /// [`super::quantities`]): the numbers a spec is read from, and a sweep sets.
    ///
    /// # Errors
    /// [`SceneError::Invalid`] at the offending character of a quantity string.
    pub fn document(&self, schema: &Schema) -> Result<Node, SceneError> {
        let mut doc = self.tree().clone();
        convert_on(self, &mut doc, self.tree(), schema)?;
        Ok(doc)
    }

    /// Deserializes the document into `T` after converting its quantity strings by `schema`.
    ///
    /// # Errors
    /// [`SceneError::Invalid`] at the item at fault: a shape error (unknown or missing keys,
    /// wrong types) or a quantity string that is wrong where it stands.
    pub fn deserialize_with<T: DeserializeOwned>(&self, schema: &Schema) -> Result<T, SceneError> {
        self.read_document(&self.document(schema)?)
    }

    /// Every shape error of the document (unknown or missing keys, wrong types) in one pass,
    /// up to [`MAX_ERRORS`]: after each, the item at fault is set aside (see
    /// `many::patch_document`) and the rest is read again. A misspelt key is reported once,
    /// not also as the missing key it suggests.
    pub(crate) fn deserialize_all<T: DeserializeOwned>(&self, schema: &Schema) -> Result<T, Vec<SceneError>> {
        let mut doc = self.document(schema).map_err(|e| vec![e])?;
        let (mut errors, mut suggested) = (Vec::new(), Vec::<ItemPath>::new());
        loop {
            match self.read::<T>(&doc) {
                Ok(t) if errors.is_empty() => return Ok(t),
                Ok(_) => return Err(errors),
                Err(b) => {
                    let (e, fault) = *b;
                    if let Some(s) = fault.suggested {
                        suggested.push(s);
                    }
                    if !(fault.missing && suggested.contains(&fault.path)) {
                        errors.push(e);
                    }
                    if errors.len() >= MAX_ERRORS || !patch_document(&mut doc, &fault.path) {
                        return Err(errors);
                    }
                }
            }
        }
    }
}
