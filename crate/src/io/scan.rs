//! `read_scan`: bytes of any supported scan file → [`Mesh`], deciding gzip and the format from the
//! content first and the extension second (downloads and browsers rename files).

use super::gzip::{inner_name, maybe_gunzip};
use super::obj_read::read_obj;
use super::ply_header::is_ply;
use super::ply_read::read_ply;
use super::stl_read::{is_binary_stl, looks_like_ascii_stl, read_stl};
use super::IoError;
use crate::mesh::Mesh;

/// A scan file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScanFormat {
    Ply,
    Obj,
    Stl,
}

/// Reads a scan: PLY (ASCII / binary LE / binary BE), OBJ or STL (binary / ASCII), optionally
/// gzip-compressed (detected by magic bytes). Positions are in the file's own units; see
/// [`crate::mesh::summary::summarise`] for the detected units. `file_name` is used for format
/// detection and starts every error message.
pub fn read_scan(bytes: &[u8], file_name: &str) -> Result<Mesh, IoError> {
    if bytes.is_empty() {
        return Err(IoError::Empty {
            file: file_name.to_string(),
        });
    }
    let data = maybe_gunzip(bytes, file_name)?;
    if data.is_empty() {
        return Err(IoError::Empty {
            file: file_name.to_string(),
        });
    }
    let format = detect_format(&data, file_name).ok_or_else(|| IoError::UnknownFormat {
        file: file_name.to_string(),
    })?;
    match format {
        ScanFormat::Ply => read_ply(&data, file_name),
        ScanFormat::Obj => read_obj(&data, file_name),
        ScanFormat::Stl => read_stl(&data, file_name),
    }
}

/// The format of (decompressed) `data`: magic bytes first (`ply`, a binary STL's consistent size,
/// `solid`), then a look at the text for OBJ statements, then the extension.
pub fn detect_format(data: &[u8], file_name: &str) -> Option<ScanFormat> {
    if is_ply(data) {
        return Some(ScanFormat::Ply);
    }
    if is_binary_stl(data) || looks_like_ascii_stl(data) {
        return Some(ScanFormat::Stl);
    }
    if looks_like_obj(data) {
        return Some(ScanFormat::Obj);
    }
    // The content is no clean example of any format: let the extension pick the reader, whose
    // error then says what is wrong in that format's terms.
    match inner_name(file_name).rsplit('.').next() {
        Some("ply") => Some(ScanFormat::Ply),
        Some("obj") => Some(ScanFormat::Obj),
        Some("stl") => Some(ScanFormat::Stl),
        _ => None,
    }
}

/// Whether the first lines of `data` are OBJ statements (`v `, `f `, `#`, `o `, ...).
fn looks_like_obj(data: &[u8]) -> bool {
    let head = &data[..data.len().min(4096)];
    let Ok(text) =
        std::str::from_utf8(head).or_else(|e| std::str::from_utf8(&head[..e.valid_up_to()]))
    else {
        return false;
    };
    let mut saw_vertex = false;
    for line in text.lines().take(50) {
        let word = line.split_ascii_whitespace().next().unwrap_or("");
        match word {
            "" => {}
            w if w.starts_with('#') => {}
            "v" => saw_vertex = true,
            "vt" | "vn" | "f" | "o" | "g" | "s" | "usemtl" | "mtllib" => {}
            _ => return false,
        }
    }
    saw_vertex
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn content_beats_the_extension() {
        let mut binary_stl = vec![b's'; 80];
        binary_stl.extend_from_slice(&1u32.to_le_bytes());
        binary_stl.extend_from_slice(&[0u8; 50]);
        let cases: [(&[u8], &str, ScanFormat); 4] = [
            (b"ply\nformat ascii 1.0\n", "x.obj", ScanFormat::Ply),
            (b"solid x\nfacet\n", "x.ply", ScanFormat::Stl),
            (b"# hi\nv 1 2 3\n", "x.ply", ScanFormat::Obj),
            (&binary_stl, "x", ScanFormat::Stl),
        ];
        for (bytes, name, format) in cases {
            assert_eq!(detect_format(bytes, name), Some(format), "{name}");
        }
    }

    #[test]
    fn extension_decides_unclear_content_and_nothing_decides_noise() {
        let cases = [
            ("x.PLY", Some(ScanFormat::Ply)),
            ("x.obj.gz", Some(ScanFormat::Obj)),
            ("x.stl", Some(ScanFormat::Stl)),
            ("x.bin", None),
        ];
        for (name, format) in cases {
            assert_eq!(detect_format(b"\x00\x01junk", name), format, "{name}");
        }
        assert_eq!(detect_format(b"hello world\n", "notes.txt"), None);
    }
}
