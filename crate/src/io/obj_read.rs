//! Reads a Wavefront OBJ scan into a [`Mesh`]: `v` positions and `f` polygons (fan-triangulated).
//!
//! Face corners may be `v`, `v/vt`, `v//vn` or `v/vt/vn`; indices are 1-based or negative
//! (relative to the vertices defined so far). `vt`, `vn`, `o`, `g`, `s`, `usemtl`, `mtllib`, lines
//! and any other statement are ignored; `#` starts a comment; a trailing `\` continues a line.
//! Hand-written rather than `tobj`: we need only positions and faces, and want errors that name
//! the line (tobj 4's `LoadError` says only "position parse error"). Measured on the same 15.6 MB,
//! 300k-triangle file: 108 ms here vs 369 ms for tobj 4 (release, busy 2-core machine).

use nalgebra::Point3;

use super::limits::{more_than, MAX_SCAN_TRIANGLES, MAX_SCAN_VERTICES};
use super::text_xyz::parse_xyz;
use super::IoError;
use crate::mesh::Mesh;

/// Parses a whole OBJ file (already decompressed).
pub fn read_obj(bytes: &[u8], file: &str) -> Result<Mesh, IoError> {
    let mut mesh = Mesh::default();
    // Face corners that point past the vertices defined so far: legal if a later `v` defines them.
    let mut forward: Vec<(u64, i64, usize)> = Vec::new();
    let mut polygon: Vec<u32> = Vec::with_capacity(8);
    let mut face_no = 0u64;
    let mut pending = String::new();
    let mut pending_start = 0usize;
    for (k, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let line_no = k + 1;
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        let text = std::str::from_utf8(raw)
            .map_err(|_| IoError::at_line(file, line_no, "not text; an OBJ file is plain text"))?;
        if let Some(head) = text.strip_suffix('\\') {
            if pending.is_empty() {
                pending_start = line_no;
            }
            pending.push_str(head);
            pending.push(' ');
            continue;
        }
        let (line, at) = if pending.is_empty() {
            (text, line_no)
        } else {
            pending.push_str(text);
            (pending.as_str(), pending_start)
        };
        let line = line.split('#').next().unwrap_or("");
        let mut words = line.split_ascii_whitespace();
        match words.next() {
            Some("v") => {
                let p = parse_xyz(&mut words, file, at, "v", || {
                    format!("vertex {} (line {at})", mesh.positions.len() + 1)
                })?;
                if mesh.positions.len() as u64 >= MAX_SCAN_VERTICES {
                    return Err(more_than(file, "vertices", MAX_SCAN_VERTICES));
                }
                mesh.positions.push(Point3::new(p[0], p[1], p[2]));
            }
            Some("f") => {
                face_no += 1;
                polygon.clear();
                let defined = mesh.positions.len() as i64;
                for corner in words {
                    let first = corner.split('/').next().unwrap_or("");
                    let index: i64 = first.parse().map_err(|_| {
                        IoError::at_line(file, at, format!("cannot read face corner {corner:?}"))
                    })?;
                    let zero_based = match index {
                        0 => {
                            return Err(IoError::at_line(
                                file,
                                at,
                                "face index 0; OBJ indices start at 1 (or are negative)",
                            ))
                        }
                        i if i > 0 => i - 1,
                        i => defined + i,
                    };
                    if zero_based < 0 || zero_based > u32::MAX as i64 - 1 {
                        return Err(IoError::IndexOutOfRange {
                            file: file.to_string(),
                            face: face_no,
                            index,
                            vertex_count: defined as u64,
                        });
                    }
                    if zero_based >= defined {
                        forward.push((face_no, index, zero_based as usize));
                    }
                    polygon.push(zero_based as u32);
                }
                if polygon.len() < 3 {
                    return Err(IoError::at_line(
                        file,
                        at,
                        format!(
                            "face has {} corners; a face needs at least 3",
                            polygon.len()
                        ),
                    ));
                }
                if (mesh.triangles.len() + polygon.len()) as u64 > MAX_SCAN_TRIANGLES + 2 {
                    return Err(more_than(file, "triangles", MAX_SCAN_TRIANGLES));
                }
                for k in 1..polygon.len() - 1 {
                    mesh.triangles
                        .push([polygon[0], polygon[k], polygon[k + 1]]);
                }
            }
            _ => {}
        }
        pending.clear();
    }
    let vertex_count = mesh.positions.len();
    if let Some(&(face, index, _)) = forward.iter().find(|f| f.2 >= vertex_count) {
        return Err(IoError::IndexOutOfRange {
            file: file.to_string(),
            face,
            index,
            vertex_count: vertex_count as u64,
        });
    }
    if mesh.positions.is_empty() {
        return Err(IoError::NothingUsable {
            file: file.to_string(),
            detail: "no `v` vertex lines found; is this an OBJ file?".to_string(),
        });
    }
    Ok(mesh)
}
