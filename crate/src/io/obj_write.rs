//! Writes a [`Mesh`] as a Wavefront OBJ file (`v` and 1-based `f` lines), with full `f64`
//! precision so that a round trip is exact.

use std::fmt::Write as _;

use crate::mesh::Mesh;

/// The mesh as OBJ text.
pub fn write_obj(mesh: &Mesh) -> Vec<u8> {
    let mut out = String::with_capacity(mesh.positions.len() * 40 + mesh.triangles.len() * 24);
    let _ = writeln!(out, "# written by bodyspace {}", env!("CARGO_PKG_VERSION"));
    for p in &mesh.positions {
        let _ = writeln!(out, "v {} {} {}", p.x, p.y, p.z);
    }
    for t in &mesh.triangles {
        let _ = writeln!(out, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    out.into_bytes()
}
