//! Writes a [`Mesh`] as PLY: binary little-endian (compact, what scanners and three.js read
//! fastest) or ASCII (for people and diffs). Positions are written as `float` (32-bit), the
//! precision of every scanner's output (6·10⁻⁸ m at 1 m).

use std::fmt::Write as _;

use crate::mesh::Mesh;

fn header(mesh: &Mesh, format: &str) -> String {
    format!(
        "ply\nformat {format} 1.0\ncomment written by bodyspace {}\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\nelement face {}\nproperty list uchar int vertex_indices\nend_header\n",
        env!("CARGO_PKG_VERSION"),
        mesh.positions.len(),
        mesh.triangles.len()
    )
}

/// The mesh as a binary little-endian PLY file.
pub fn write_ply(mesh: &Mesh) -> Vec<u8> {
    let head = header(mesh, "binary_little_endian");
    let mut out =
        Vec::with_capacity(head.len() + mesh.positions.len() * 12 + mesh.triangles.len() * 13);
    out.extend_from_slice(head.as_bytes());
    for p in &mesh.positions {
        for c in [p.x, p.y, p.z] {
            out.extend_from_slice(&(c as f32).to_le_bytes());
        }
    }
    for t in &mesh.triangles {
        out.push(3);
        for &i in t {
            // Indices above i32::MAX cannot occur: a mesh that large does not fit in memory.
            out.extend_from_slice(&(i as i32).to_le_bytes());
        }
    }
    out
}

/// The mesh as an ASCII PLY file.
pub fn write_ply_ascii(mesh: &Mesh) -> Vec<u8> {
    let mut out = header(mesh, "ascii");
    for p in &mesh.positions {
        let _ = writeln!(out, "{} {} {}", p.x as f32, p.y as f32, p.z as f32);
    }
    for t in &mesh.triangles {
        let _ = writeln!(out, "3 {} {} {}", t[0], t[1], t[2]);
    }
    out.into_bytes()
}
