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

/// [`vertex_normals`] on flat f32 arrays, as the viewer's buffers are: `positions` `#V·3`
/// (xyz interleaved), `triangles` `#F`, unit normals written into `out` (`#V·3`; zero where
/// undefined). Summed in f32: this runs on every slider move of a reconstructed body.
pub fn vertex_normals_flat(positions: &[f32], triangles: &[[u32; 3]], out: &mut [f32]) {
    out.iter_mut().for_each(|x| *x = 0.0);
    let p = |i: u32| {
        let o = 3 * i as usize;
        [positions[o], positions[o + 1], positions[o + 2]]
    };
    for t in triangles {
        let [a, b, c] = t.map(p);
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let n = [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ];
        for &i in t {
            let o = 3 * i as usize;
            out[o] += n[0];
            out[o + 1] += n[1];
            out[o + 2] += n[2];
        }
    }
    for n in out.chunks_exact_mut(3) {
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let inv = if len > 0.0 && len.is_finite() {
            1.0 / len
        } else {
            0.0
        };
        n.iter_mut().for_each(|x| *x *= inv);
    }
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

    #[test]
    fn flat_f32_normals_match_the_f64_ones() {
        let mesh = Mesh::new(
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(10.0, 0.0, 0.0),
                Point3::new(0.0, 10.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
                Point3::new(0.0, 0.0, 1.0),
                Point3::new(5.0, 5.0, 5.0),
            ],
            vec![[0, 1, 2], [0, 3, 4], [1, 3, 2]],
        );
        let flat: Vec<f32> = mesh
            .positions
            .iter()
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect();
        let mut out = vec![1.0f32; flat.len()];
        vertex_normals_flat(&flat, &mesh.triangles, &mut out);
        for (n, m) in vertex_normals(&mesh).iter().zip(out.chunks_exact(3)) {
            for a in 0..3 {
                assert!((n[a] as f32 - m[a]).abs() < 1e-6, "{n:?} vs {m:?}");
            }
        }
        assert_eq!(&out[15..18], &[0.0, 0.0, 0.0]);
    }
}
