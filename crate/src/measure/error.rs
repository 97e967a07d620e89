//! Errors of taking measurements.

use thiserror::Error;

/// What can stop a body from being measured. A girth whose plane finds no section is not an
/// error: that measurement is `None`.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum MeasureError {
    /// The template has no landmark of this canonical name.
    #[error("the template has no landmark {0:?}, which the measurements are anchored on")]
    MissingLandmark(String),
    /// A landmark or triangle indexes a vertex the body does not have.
    #[error("{what} indexes vertex {vertex}, but the body has {vertex_count} vertices")]
    VertexOutOfRange {
        what: String,
        vertex: u32,
        vertex_count: usize,
    },
    /// Positions are not `#V·3` finite numbers for the template's `#V`.
    #[error("positions: {0}")]
    BadPositions(String),
    /// The segment weights are not one entry per vertex.
    #[error("segment weights: {got} entries for {expected} vertices")]
    BadSegmentWeights { got: usize, expected: usize },
    /// A parameter is out of its range.
    #[error("invalid parameter: {0}")]
    BadParameter(String),
}
