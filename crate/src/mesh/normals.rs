//! Smooth per-vertex normals.

use nalgebra::Vector3;

use super::Mesh;

/// Area-weighted vertex normals: n_v = normalise(Σ_{t ∋ v} (b − a) × (c − a)), the sum of the
/// incident triangles' unnormalised face normals (each is twice the triangle's area times its
/// unit normal). Returns `#V` unit vectors; a vertex with no incident triangle of non-zero area
/// (or whose incident normals cancel) gets the zero vector rather than NaN.
pub fn vertex_normals(mesh: &Mesh) -> Vec<Vector3<f64>> {
    let mut normals = vec![Vector3::zeros(); mesh.positions.len()];
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let n = (b - a).cross(&(c - a));
        for &i in t {
            normals[i as usize] += n;
        }
    }
    for n in &mut normals {
        let len = n.norm();
        *n = if len > 0.0 && len.is_finite() {
            *n / len
        } else {
            Vector3::zeros()
        };
    }
    normals
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point3;

    #[test]
    fn flat_square_points_up_and_isolated_vertex_is_zero() {
        let mesh = Mesh::new(
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
                Point3::new(5.0, 5.0, 5.0),
            ],
            vec![[0, 1, 2], [0, 2, 3], [0, 0, 1]],
        );
        let n = vertex_normals(&mesh);
        for (v, normal) in n.iter().enumerate().take(4) {
            assert!((normal - Vector3::z()).norm() < 1e-12, "{v}: {normal:?}");
        }
        assert_eq!(n[4], Vector3::zeros());
    }

    #[test]
    fn weights_by_area() {
        // Vertex 0 is shared by a big triangle facing +z and a small one facing +x.
        let mesh = Mesh::new(
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(10.0, 0.0, 0.0),
                Point3::new(0.0, 10.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
                Point3::new(0.0, 0.0, 1.0),
            ],
            vec![[0, 1, 2], [0, 3, 4]],
        );
        let n = vertex_normals(&mesh)[0];
        let expected = Vector3::new(1.0, 0.0, 100.0).normalize();
        assert!((n - expected).norm() < 1e-12);
    }
}
