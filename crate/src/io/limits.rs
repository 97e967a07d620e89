//! The largest input the readers accept, so that a file can only cost memory in proportion to what
//! it really contains. Natively and in the browser (wasm32, at most 4 GiB of memory) alike, a small
//! gzip file that inflates to gigabytes, or a header that declares billions of elements, is refused
//! with a message naming the file and the limit before that memory is taken. README.md ("Limits")
//! lists them for users.
//!
//! Sizing: a CAESAR scan has about 300 thousand points; today's high-resolution whole-body scanners
//! write 1–5 million vertices (about twice as many triangles). A binary PLY of 5 million vertices
//! and 10 million triangles is about 190 MB, the same as ASCII PLY or OBJ about 500 MB. The limits
//! leave four times that headroom and still fit a browser tab: 20 million vertices (480 MB as
//! `f64` positions) and 40 million triangles (480 MB), from at most 1 GiB of inflated bytes.

use super::error::IoError;

/// Largest decompressed (inflated) size of a gzip-compressed scan or landmark file: 1 GiB.
pub const MAX_INFLATED_BYTES: u64 = 1 << 30;

/// Largest inflation ratio accepted once the inflated data passes [`RATIO_FREE_BYTES`]. Scan files
/// compress 1.1–2.5× (binary PLY, binary STL) or 2.5–4× (ASCII PLY, OBJ); ASCII STL, which writes
/// each shared corner six times, reaches about 12×. Deflate itself tops out near 1032×, which only
/// long runs of one byte reach (a decompression bomb). 40× leaves three times the headroom over
/// ASCII STL and refuses a 5 MB bomb after about 200 MB of output instead of gigabytes.
pub const MAX_INFLATE_RATIO: u64 = 40;

/// Inflated size up to which any ratio is accepted (small, very regular files such as a synthetic
/// test shape or a landmark list).
pub const RATIO_FREE_BYTES: u64 = 16 << 20;

/// Most vertices in one scan: 20 million.
pub const MAX_SCAN_VERTICES: u64 = 20_000_000;

/// Most triangles in one scan (after fan triangulation of polygons): 40 million.
pub const MAX_SCAN_TRIANGLES: u64 = 40_000_000;

/// The error for a scan that holds more `what` than `limit`; `found` says how many it holds
/// (or that it holds more).
pub fn too_many(file: &str, what: &str, found: String, limit: u64) -> IoError {
    IoError::TooManyElements {
        file: file.to_string(),
        what: what.to_string(),
        found,
        limit,
    }
}

/// The error for a file found, while reading, to hold more `what` than `limit`.
pub fn more_than(file: &str, what: &str, limit: u64) -> IoError {
    too_many(
        file,
        what,
        format!("the file holds more than {limit}"),
        limit,
    )
}

/// The error for polygon faces that triangulate to more than [`MAX_SCAN_TRIANGLES`].
pub fn too_many_triangles(file: &str) -> IoError {
    let found = format!("the faces make more than {MAX_SCAN_TRIANGLES}");
    too_many(file, "triangles", found, MAX_SCAN_TRIANGLES)
}

/// Largest number of bytes `compressed_len` compressed bytes may inflate to.
pub fn inflated_limit(compressed_len: u64) -> u64 {
    compressed_len
        .saturating_mul(MAX_INFLATE_RATIO)
        .clamp(RATIO_FREE_BYTES, MAX_INFLATED_BYTES)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_limit_grows_with_the_file_between_the_floor_and_the_cap() {
        assert_eq!(inflated_limit(0), RATIO_FREE_BYTES);
        assert_eq!(inflated_limit(1 << 20), 40 << 20);
        assert_eq!(inflated_limit(100 << 20), MAX_INFLATED_BYTES);
        assert_eq!(inflated_limit(u64::MAX), MAX_INFLATED_BYTES);
    }
}
