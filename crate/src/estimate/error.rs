//! Why a landmark estimate did not run.

use thiserror::Error;

use crate::align::AlignError;

/// The errors of [`super::estimate_landmarks`]; each message says what to do.
#[derive(Debug, Error)]
pub enum EstimateError {
    /// The scan has too few points, or they are not finite, so it has no principal axes.
    #[error("the scan has no body shape to fit (fewer than 3 distinct finite points)")]
    NoShape,
    /// The scan cannot be indexed for closest points (no triangles, bad indices, NaN).
    #[error("{0}")]
    Scan(AlignError),
    /// No frame candidate matched the scan at all.
    #[error("the template matched no part of the scan in any orientation; is this a whole body?")]
    NoMatch,
    /// The landmark-free fine alignment refused its inputs.
    #[error("fine alignment: {0}")]
    Align(AlignError),
    /// The caller cancelled.
    #[error("the landmark estimate was cancelled")]
    Cancelled,
}
