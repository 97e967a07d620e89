//! Errors of model building, reconstruction and model files.

use thiserror::Error;

/// Everything that can go wrong when building, using, saving or loading a shape model.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum PcaError {
    /// Fewer than two subjects: no variation to model.
    #[error("a shape model needs at least 2 subjects, got {0}")]
    TooFewSubjects(usize),
    /// A subject does not have the template's vertex count.
    #[error("subject {subject} has {got} vertices but the template has {expected}; fits must be in template vertex order")]
    VertexCountMismatch {
        subject: String,
        got: usize,
        expected: usize,
    },
    /// A subject contains NaN or infinite coordinates.
    #[error("subject {0} has a non-finite coordinate")]
    NonFinite(String),
    /// Segment blend weights are not one `[f32; 6]` per template vertex, or a weight is negative/NaN.
    #[error("segment weights: {0}")]
    BadSegmentWeights(String),
    /// A parameter is out of its range.
    #[error("invalid parameter: {0}")]
    BadParameter(String),
    /// Coefficient vector longer than the model's mode count, or a flat buffer of the wrong length.
    #[error("{what}: expected at most {expected} values, got {got}")]
    BadLength {
        what: String,
        expected: usize,
        got: usize,
    },
    /// The file does not start with the model magic bytes.
    #[error("not a BodySpace model file (magic bytes are not BSPCAMDL)")]
    BadMagic,
    /// The file's format version is not one this build reads.
    #[error(
        "model file format version {found} is not supported (this build reads version {supported})"
    )]
    UnsupportedVersion { found: u32, supported: u32 },
    /// The file is larger than `model_file::file::MAX_MODEL_BYTES`, the largest model accepted.
    #[error("model file is {bytes} bytes, more than the {limit} bytes of the largest model accepted (see Limits in the README)")]
    TooLarge { bytes: u64, limit: u64 },
    /// The file ends before the header or an array it declares.
    #[error("model file is truncated: {0}")]
    Truncated(String),
    /// The header or the data section is inconsistent or fails its checksum.
    #[error("model file is corrupted: {0}")]
    Corrupted(String),
    /// The model was built for a different template than the one it is used with.
    #[error("model was built for template {model} but the loaded template is {expected}; rebuild the model from fits of this template")]
    TemplateMismatch { model: String, expected: String },
    /// A statismo HDF5 model whose datasets do not fit together, or that is not on the template.
    #[error("statismo model: {0}")]
    Statismo(String),
}
