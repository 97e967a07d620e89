//! The one error type of every reader: each message is a single actionable line that starts with
//! the file name, so the command line and the browser can show it as is.

/// Why a scan or landmark file could not be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum IoError {
    /// The file has no bytes at all.
    #[error("{file}: the file is empty")]
    Empty { file: String },

    /// Neither the content nor the extension says which format the file is in.
    #[error("{file}: not a recognised scan format; expected PLY, OBJ or STL (optionally gzip-compressed)")]
    UnknownFormat { file: String },

    /// The gzip stream is corrupt or cut short.
    #[error(
        "{file}: the gzip data is corrupt ({detail}); re-compress or send the file uncompressed"
    )]
    Gzip { file: String, detail: String },

    /// The decompressed data would exceed [`super::limits::MAX_INFLATED_BYTES`], the largest scan
    /// accepted; refused as soon as the inflated bytes pass it.
    #[error("{file}: decompresses to more than {limit_bytes} bytes, the largest scan accepted; crop or decimate the scan (see Limits in the README)")]
    TooLarge { file: String, limit_bytes: u64 },

    /// The compressed data inflates far more than any real scan compresses
    /// ([`super::limits::MAX_INFLATE_RATIO`]): a decompression bomb or a damaged file. Refused as
    /// soon as the inflated bytes pass `limit_bytes`.
    #[error("{file}: {compressed_bytes} compressed bytes inflate to more than {limit_bytes} bytes, over {ratio} times their size, which no real scan does; this is a decompression bomb or a damaged file: decompress and check it yourself, or send it uncompressed")]
    InflatesTooMuch {
        file: String,
        compressed_bytes: u64,
        limit_bytes: u64,
        ratio: u64,
    },

    /// The header declares (or the file holds) more vertices or triangles than the largest scan
    /// accepted ([`super::limits::MAX_SCAN_VERTICES`], [`super::limits::MAX_SCAN_TRIANGLES`]);
    /// refused before memory for them is reserved.
    #[error("{file}: {found} {what}, more than the {limit} {what} of the largest scan accepted; crop or decimate the scan (see Limits in the README)")]
    TooManyElements {
        file: String,
        what: String,
        /// "the header declares 4294967295" or "the file holds more than 40000000".
        found: String,
        limit: u64,
    },

    /// The file does not follow its format; `at` names the line or record.
    #[error("{file}: {at}: {detail}")]
    Malformed {
        file: String,
        at: String,
        detail: String,
    },

    /// The header (or record count) promises more data than the file holds.
    #[error("{file}: header declares {declared} {what} but the file ends after {found}")]
    Truncated {
        file: String,
        what: String,
        declared: u64,
        found: u64,
    },

    /// A coordinate is NaN or infinite.
    #[error("{file}: {what} has a non-finite coordinate (NaN or infinity)")]
    NonFinite { file: String, what: String },

    /// A face refers to a vertex that does not exist.
    #[error(
        "{file}: face {face} refers to vertex {index} but the file has {vertex_count} vertices"
    )]
    IndexOutOfRange {
        file: String,
        face: u64,
        index: i64,
        vertex_count: u64,
    },

    /// Two entries of a landmark file name the same (canonical) landmark.
    #[error("{file}: landmark{} {} given more than once; keep one of each", plural(.names.len()), .names.join(", "))]
    DuplicateLandmarks { file: String, names: Vec<String> },

    /// The file is well formed but holds nothing usable.
    #[error("{file}: {detail}")]
    NothingUsable { file: String, detail: String },
}

fn plural(n: usize) -> &'static str {
    if n == 1 {
        ""
    } else {
        "s"
    }
}

impl IoError {
    /// A [`IoError::Malformed`] at a 1-based line number.
    pub(crate) fn at_line(file: &str, line: usize, detail: impl Into<String>) -> Self {
        IoError::Malformed {
            file: file.to_string(),
            at: format!("line {line}"),
            detail: detail.into(),
        }
    }

    /// A [`IoError::Malformed`] at a named place (a header, a record).
    pub(crate) fn malformed(file: &str, at: impl Into<String>, detail: impl Into<String>) -> Self {
        IoError::Malformed {
            file: file.to_string(),
            at: at.into(),
            detail: detail.into(),
        }
    }
}
