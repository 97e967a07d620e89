//! The triangle mesh type shared by scans, the template and fitted bodies.

use nalgebra::Point3;

/// A triangle mesh: `#V` positions and `#F` triangles indexing them (counter-clockwise seen from
/// outside). Units are whatever the source used until [`crate::mesh`] unit detection says
/// otherwise; everything downstream of loading works in metres.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// `#V` vertex positions.
    pub positions: Vec<Point3<f64>>,
    /// `#F` triangles, each three indices into `positions`.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// A mesh from positions and triangles; indices are assumed to be in range (readers check).
    pub fn new(positions: Vec<Point3<f64>>, triangles: Vec<[u32; 3]>) -> Self {
        Self {
            positions,
            triangles,
        }
    }

    /// Number of vertices `#V`.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles `#F`.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Positions as a flat `[x0, y0, z0, x1, ...]` array (three.js buffer layout).
    pub fn flat_positions_f32(&self) -> Vec<f32> {
        self.positions
            .iter()
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect()
    }

    /// Triangles as a flat `[a0, b0, c0, a1, ...]` index array.
    pub fn flat_triangles(&self) -> Vec<u32> {
        self.triangles.iter().flatten().copied().collect()
    }
}
