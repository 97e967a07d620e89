//! The triangle mesh type shared by scans, the template and fitted bodies.

use nalgebra::{Point3, Vector3};

use super::normals::vertex_normals;

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

    /// The mesh with every position multiplied by `factor` (e.g. `Units::scale_to_metres()`).
    pub fn scaled(&self, factor: f64) -> Mesh {
        Mesh {
            positions: self.positions.iter().map(|p| p * factor).collect(),
            triangles: self.triangles.clone(),
        }
    }

    /// The mesh with only the vertices whose `keep` flag is set (`#V` flags), in their order, and
    /// the triangles all of whose corners are kept, re-indexed.
    pub fn with_vertices(&self, keep: &[bool]) -> Mesh {
        let mut index = vec![u32::MAX; self.positions.len()];
        let mut positions = Vec::with_capacity(self.positions.len());
        for (v, p) in self.positions.iter().enumerate() {
            if keep[v] {
                index[v] = positions.len() as u32;
                positions.push(*p);
            }
        }
        let triangles = self
            .triangles
            .iter()
            .filter(|t| t.iter().all(|&v| keep[v as usize]))
            .map(|t| t.map(|v| index[v as usize]))
            .collect();
        Mesh {
            positions,
            triangles,
        }
    }

    /// Area-weighted unit vertex normals, `#V` ([`crate::mesh::normals::vertex_normals`]).
    pub fn vertex_normals(&self) -> Vec<Vector3<f64>> {
        vertex_normals(&self.positions, &self.triangles)
    }

    /// [`Mesh::vertex_normals`] as a flat `[x0, y0, z0, x1, ...]` f32 array (three.js layout).
    pub fn flat_vertex_normals_f32(&self) -> Vec<f32> {
        self.vertex_normals()
            .iter()
            .flat_map(|n| [n.x as f32, n.y as f32, n.z as f32])
            .collect()
    }

    /// Triangles as a flat `[a0, b0, c0, a1, ...]` index array.
    pub fn flat_triangles(&self) -> Vec<u32> {
        self.triangles.iter().flatten().copied().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn with_vertices_keeps_the_triangles_of_kept_corners_reindexed() {
        let p = |x: f64| Point3::new(x, 0.0, 0.0);
        let mesh = Mesh::new(
            vec![p(0.0), p(1.0), p(2.0), p(3.0)],
            vec![[0, 1, 3], [1, 2, 3]],
        );
        let kept = mesh.with_vertices(&[false, true, true, true]);
        assert_eq!(kept.positions, vec![p(1.0), p(2.0), p(3.0)]);
        assert_eq!(kept.triangles, vec![[0, 1, 2]]);
    }

    #[test]
    fn scaled_multiplies_positions_and_keeps_triangles() {
        let mesh = Mesh::new(vec![Point3::new(1000.0, -500.0, 2.0)], vec![[0, 0, 0]]);
        let m = mesh.scaled(1e-3);
        assert_eq!(m.positions[0], Point3::new(1.0, -0.5, 0.002));
        assert_eq!(m.triangles, mesh.triangles);
    }
}
