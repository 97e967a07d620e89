//! Errors of reading, building and storing the generic template.

use thiserror::Error;

/// What can go wrong reading the MakeHuman model, building the template, or reading a stored
/// template file.
#[derive(Debug, Error)]
pub enum TemplateError {
    /// The MakeHuman JSON could not be parsed at all.
    #[error("MakeHuman model: not a three.js JSON model ({0})")]
    Json(String),
    /// The MakeHuman JSON parsed but its contents are inconsistent.
    #[error("MakeHuman model: {0}")]
    Model(String),
    /// The model has no faces with the body-skin material.
    #[error("MakeHuman model: no faces use the material `{0}`")]
    NoBodySkin(String),
    /// A stored template file is truncated, has the wrong magic or an inconsistent header.
    #[error("template file: {0}")]
    Format(String),
    /// A landmark search rule found no candidate vertex.
    #[error("template build: landmark `{0}` has no candidate vertex ({1})")]
    Landmark(String, String),
    /// A joint named in a rule is missing from the MakeHuman skeleton.
    #[error("template build: joint `{0}` is missing from the MakeHuman skeleton")]
    MissingJoint(String),
    /// An unknown resolution name.
    #[error("unknown template resolution `{0}` (expected `base` or `fine`)")]
    Resolution(String),
}
