//! Why a subject could not be fitted; each message names the file or step and what to do.

use thiserror::Error;

use crate::align::PipelineError;
use crate::io::IoError;

#[derive(Debug, Error)]
pub enum SubjectError {
    /// A file could not be read (the reader's message names the file and the problem).
    #[error("{0}")]
    Read(#[from] IoError),
    /// The landmark estimate failed or was cancelled.
    #[error("{scan}: landmark estimate: {message}")]
    Estimate { scan: String, message: String },
    /// The warp or the fine alignment refused or failed.
    #[error("{scan}: {source}")]
    Align {
        scan: String,
        #[source]
        source: PipelineError,
    },
}
