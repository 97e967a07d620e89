//! Transparent gzip: CAESAR and other archives ship `.ply.gz`; we detect gzip by its magic bytes
//! (1f 8b), not by the name, because browsers and downloads rename files freely.

use std::borrow::Cow;
use std::io::Read;

use super::limits::{inflated_limit, MAX_INFLATED_BYTES, MAX_INFLATE_RATIO};
use super::IoError;

/// Whether `bytes` start with the gzip magic number.
pub fn is_gzip(bytes: &[u8]) -> bool {
    bytes.len() >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b
}

/// `bytes` decompressed if they are gzip (all members), else borrowed unchanged. The inflated size
/// is capped by [`inflated_limit`]: at most [`MAX_INFLATE_RATIO`] times the compressed size (above
/// a small floor) and never more than [`MAX_INFLATED_BYTES`], so a decompression bomb is refused
/// after a bounded amount of output rather than after it has filled memory.
pub fn maybe_gunzip<'a>(bytes: &'a [u8], file: &str) -> Result<Cow<'a, [u8]>, IoError> {
    if !is_gzip(bytes) {
        return Ok(Cow::Borrowed(bytes));
    }
    gunzip_limited(bytes, file, inflated_limit(bytes.len() as u64)).map(Cow::Owned)
}

/// Decompresses a gzip stream, failing as soon as more than `limit` bytes come out.
pub fn gunzip_limited(bytes: &[u8], file: &str, limit: u64) -> Result<Vec<u8>, IoError> {
    let decoder = flate2::read::MultiGzDecoder::new(bytes);
    let mut out = Vec::new();
    decoder
        .take(limit.saturating_add(1))
        .read_to_end(&mut out)
        .map_err(|e| IoError::Gzip {
            file: file.to_string(),
            detail: e.to_string(),
        })?;
    if out.len() as u64 > limit {
        return Err(if limit >= MAX_INFLATED_BYTES {
            IoError::TooLarge {
                file: file.to_string(),
                limit_bytes: limit,
            }
        } else {
            IoError::InflatesTooMuch {
                file: file.to_string(),
                compressed_bytes: bytes.len() as u64,
                limit_bytes: limit,
                ratio: MAX_INFLATE_RATIO,
            }
        });
    }
    Ok(out)
}

/// The file name without a trailing `.gz`, lower-cased, for extension checks.
pub fn inner_name(file: &str) -> String {
    let lower = file.to_ascii_lowercase();
    match lower.strip_suffix(".gz") {
        Some(stem) => stem.to_string(),
        None => lower,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn gz(data: &[u8]) -> Vec<u8> {
        let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        enc.write_all(data).unwrap();
        enc.finish().unwrap()
    }

    #[test]
    fn round_trips_and_passes_plain_bytes_through() {
        let packed = gz(b"hello body");
        assert!(is_gzip(&packed));
        assert_eq!(&*maybe_gunzip(&packed, "a.gz").unwrap(), b"hello body");
        assert!(matches!(
            maybe_gunzip(b"plain", "a").unwrap(),
            Cow::Borrowed(b"plain")
        ));
    }

    #[test]
    fn caps_the_decompressed_size() {
        let packed = gz(&vec![0u8; 10_000]);
        let err = gunzip_limited(&packed, "bomb.ply.gz", 1000).unwrap_err();
        assert!(matches!(err, IoError::InflatesTooMuch { .. }));
        assert!(err.to_string().starts_with("bomb.ply.gz: "));
    }

    #[test]
    fn corrupt_gzip_is_an_error() {
        let mut packed = gz(b"some text that is long enough to matter");
        packed.truncate(packed.len() / 2);
        let err = maybe_gunzip(&packed, "x.ply.gz").unwrap_err();
        assert!(matches!(err, IoError::Gzip { .. }), "{err}");
    }

    #[test]
    fn inner_name_strips_gz() {
        assert_eq!(inner_name("Scan.PLY.gz"), "scan.ply");
        assert_eq!(inner_name("scan.obj"), "scan.obj");
    }
}
