//! Reads an STL scan (binary or ASCII) into a [`Mesh`], merging corners at identical positions.
//!
//! STL stores every triangle with its own three corners; without merging, every triangle would be
//! its own component and every edge a boundary edge. Corners are merged by exact position (bit
//! pattern, with −0 = +0), which is what the writer's shared vertices become. Binary vs ASCII is
//! decided by the size check `84 + 50·n` first, because many binary files start with `solid`.
//! Hand-written rather than `stl_io`: that crate decides by the `solid` prefix alone and its
//! errors do not name the file position.

use std::collections::hash_map::Entry;
use std::collections::HashMap;

use nalgebra::Point3;

use super::limits::{more_than, MAX_SCAN_TRIANGLES, MAX_SCAN_VERTICES};
use super::text_xyz::parse_xyz;
use super::IoError;
use crate::mesh::Mesh;

/// Whether `bytes` are a binary STL of consistent size.
pub fn is_binary_stl(bytes: &[u8]) -> bool {
    declared_triangles(bytes).is_some_and(|n| 84 + 50 * n == bytes.len() as u64)
}

/// Whether `bytes` start like an ASCII STL (`solid`).
pub fn looks_like_ascii_stl(bytes: &[u8]) -> bool {
    let start = bytes
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(0);
    bytes[start..].starts_with(b"solid")
}

fn declared_triangles(bytes: &[u8]) -> Option<u64> {
    let count: [u8; 4] = bytes.get(80..84)?.try_into().ok()?;
    Some(u32::from_le_bytes(count) as u64)
}

/// Parses an STL file (already decompressed).
pub fn read_stl(bytes: &[u8], file: &str) -> Result<Mesh, IoError> {
    if is_binary_stl(bytes) {
        read_binary(bytes, file)
    } else if looks_like_ascii_stl(bytes) {
        read_ascii(bytes, file)
    } else if let Some(declared) = declared_triangles(bytes) {
        Err(IoError::Truncated {
            file: file.to_string(),
            what: "triangles".to_string(),
            declared,
            found: (bytes.len() as u64 - 84) / 50,
        })
    } else {
        Err(IoError::malformed(
            file,
            "header",
            "too short for a binary STL (84-byte header) and does not start with `solid`",
        ))
    }
}

/// Merges corners by exact position.
struct Welder {
    mesh: Mesh,
    index: HashMap<[u64; 3], u32>,
}

impl Welder {
    fn with_capacity(triangles: usize) -> Self {
        // A closed surface has about half as many vertices as triangles.
        let vertices = triangles / 2 + 3;
        Self {
            mesh: Mesh {
                positions: Vec::with_capacity(vertices),
                triangles: Vec::with_capacity(triangles),
            },
            index: HashMap::with_capacity(vertices),
        }
    }

    /// The index of the vertex at `p`, added if new; `None` once the scan would pass
    /// [`MAX_SCAN_VERTICES`].
    fn vertex(&mut self, p: [f64; 3]) -> Option<u32> {
        // `+ 0.0` turns −0 into +0 so the two spellings of zero merge.
        let key = p.map(|c| (c + 0.0).to_bits());
        let positions = &mut self.mesh.positions;
        match self.index.entry(key) {
            Entry::Occupied(e) => Some(*e.get()),
            Entry::Vacant(e) => {
                if positions.len() as u64 >= MAX_SCAN_VERTICES {
                    return None;
                }
                positions.push(Point3::new(p[0], p[1], p[2]));
                Some(*e.insert((positions.len() - 1) as u32))
            }
        }
    }

    fn push_triangle(&mut self, t: [u32; 3], file: &str) -> Result<(), IoError> {
        if self.mesh.triangles.len() as u64 >= MAX_SCAN_TRIANGLES {
            return Err(more_than(file, "triangles", MAX_SCAN_TRIANGLES));
        }
        self.mesh.triangles.push(t);
        Ok(())
    }
}

fn read_binary(bytes: &[u8], file: &str) -> Result<Mesh, IoError> {
    let n = (bytes.len() - 84) / 50;
    if n as u64 > MAX_SCAN_TRIANGLES {
        return Err(IoError::TooManyElements {
            file: file.to_string(),
            what: "triangles".to_string(),
            found: format!("the header declares {n}"),
            limit: MAX_SCAN_TRIANGLES,
        });
    }
    let mut welder = Welder::with_capacity(n);
    for (t, record) in bytes[84..].chunks_exact(50).enumerate() {
        let mut corners = [0u32; 3];
        for (k, corner) in corners.iter_mut().enumerate() {
            let base = 12 + 12 * k;
            let mut p = [0.0f64; 3];
            for (a, c) in p.iter_mut().enumerate() {
                let o = base + 4 * a;
                let b = [record[o], record[o + 1], record[o + 2], record[o + 3]];
                *c = f32::from_le_bytes(b) as f64;
            }
            if !p.iter().all(|c| c.is_finite()) {
                return Err(IoError::NonFinite {
                    file: file.to_string(),
                    what: format!("triangle {t} corner {k}"),
                });
            }
            *corner = welder
                .vertex(p)
                .ok_or_else(|| more_than(file, "vertices", MAX_SCAN_VERTICES))?;
        }
        welder.push_triangle(corners, file)?;
    }
    Ok(welder.mesh)
}

fn read_ascii(bytes: &[u8], file: &str) -> Result<Mesh, IoError> {
    let text = std::str::from_utf8(bytes).map_err(|_| {
        IoError::malformed(
            file,
            "content",
            "starts with `solid` but is neither text nor a binary STL of consistent size",
        )
    })?;
    let mut welder = Welder::with_capacity(bytes.len() / 250);
    let mut polygon: Vec<u32> = Vec::with_capacity(4);
    let mut facet = 0usize;
    for (k, line) in text.lines().enumerate() {
        let line_no = k + 1;
        let mut words = line.split_ascii_whitespace();
        match words.next() {
            Some("vertex") => {
                let p = parse_xyz(&mut words, file, line_no, "vertex", || {
                    format!("facet {facet} (line {line_no})")
                })?;
                let v = welder
                    .vertex(p)
                    .ok_or_else(|| more_than(file, "vertices", MAX_SCAN_VERTICES))?;
                polygon.push(v);
            }
            Some("endloop") => {
                if polygon.len() < 3 {
                    return Err(IoError::at_line(
                        file,
                        line_no,
                        format!("facet {facet} has {} vertices; it needs 3", polygon.len()),
                    ));
                }
                for k in 1..polygon.len() - 1 {
                    welder.push_triangle([polygon[0], polygon[k], polygon[k + 1]], file)?;
                }
                polygon.clear();
                facet += 1;
            }
            _ => {}
        }
    }
    if welder.mesh.triangles.is_empty() {
        return Err(IoError::NothingUsable {
            file: file.to_string(),
            detail: "the ASCII STL holds no facets".to_string(),
        });
    }
    Ok(welder.mesh)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn binary(corners: &[[f32; 3]]) -> Vec<u8> {
        let mut out = vec![0u8; 80];
        out.extend_from_slice(&((corners.len() / 3) as u32).to_le_bytes());
        for t in corners.chunks(3) {
            out.extend_from_slice(&[0u8; 12]);
            for c in t.iter().flatten() {
                out.extend_from_slice(&c.to_le_bytes());
            }
            out.extend_from_slice(&[0u8; 2]);
        }
        out
    }

    #[test]
    fn shared_corners_merge_including_signed_zero() {
        let bytes = binary(&[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [-0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
        ]);
        let mesh = read_stl(&bytes, "t.stl").unwrap();
        assert_eq!(mesh.positions.len(), 3);
        assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 1]]);
    }

    #[test]
    fn non_finite_corner_is_named() {
        let bytes = binary(&[[0.0, 0.0, 0.0], [f32::NAN, 0.0, 0.0], [0.0, 1.0, 0.0]]);
        let err = read_stl(&bytes, "t.stl").unwrap_err();
        assert_eq!(
            err.to_string(),
            "t.stl: triangle 0 corner 1 has a non-finite coordinate (NaN or infinity)"
        );
    }

    #[test]
    fn short_files_and_empty_ascii_are_errors() {
        assert!(read_stl(b"abc", "t.stl").is_err());
        let err = read_stl(b"solid empty\nendsolid empty\n", "t.stl").unwrap_err();
        assert_eq!(err.to_string(), "t.stl: the ASCII STL holds no facets");
    }
}
