//! Vertex and face normals of a triangle mesh: the area-weighted vertex normal in f64 (with an
//! allocation-free `_into` form) and in f32 over flat three.js-style buffers, and unit face normals.

use nalgebra::{Point3, Vector3};

/// Area-weighted vertex normals: n_v = normalise(Σ_{t ∋ v} (b − a) × (c − a)), the sum of the
/// incident triangles' unnormalised face normals (each is twice the triangle's area times its
/// unit normal). `positions`: `#V`; `triangles`: `#F`, counter-clockwise seen from outside.
/// Returns `#V` unit vectors; a vertex with no incident triangle of non-zero area (or whose
/// incident normals cancel) gets the zero vector rather than NaN.
pub fn vertex_normals(positions: &[Point3<f64>], triangles: &[[u32; 3]]) -> Vec<Vector3<f64>> {
    let mut normals = vec![Vector3::zeros(); positions.len()];
    vertex_normals_into(positions, triangles, &mut normals);
    normals
}

/// [`vertex_normals`] written into a caller-owned buffer of `#V` vectors (no allocation, for
/// loops that recompute normals every round). Panics if `normals` is shorter than `#V` or a
/// triangle indexes past `positions`.
pub fn vertex_normals_into(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    normals: &mut [Vector3<f64>],
) {
    normals.iter_mut().for_each(|n| *n = Vector3::zeros());
    for t in triangles {
        let [a, b, c] = t.map(|i| i as usize);
        let n = (positions[b] - positions[a]).cross(&(positions[c] - positions[a]));
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for n in normals.iter_mut() {
        *n = unit_or_zero(*n);
    }
}

/// Unit face normals (b − a) × (c − a) / ‖·‖, `#F` of them; zero for degenerate triangles.
pub fn face_normals(positions: &[Point3<f64>], triangles: &[[u32; 3]]) -> Vec<Vector3<f64>> {
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| positions[i as usize]);
            unit_or_zero((b - a).cross(&(c - a)))
        })
        .collect()
}

/// `n / ‖n‖`, or zero when the length is zero or not finite.
fn unit_or_zero(n: Vector3<f64>) -> Vector3<f64> {
    let len = n.norm();
    if len > 0.0 && len.is_finite() {
        n / len
    } else {
        Vector3::zeros()
    }
}

/// A mesh's triangles checked once against its vertex count, to compute [`vertex_normals`] in
/// f32 for many sets of positions (a body that morphs): `#F` triangles over `#V` vertices.
#[derive(Debug, Clone)]
pub struct NormalTopology {
    triangles: Vec<[u32; 3]>,
    vertex_count: usize,
}

impl NormalTopology {
    /// `None` if a triangle indexes a vertex ≥ `vertex_count`.
    pub fn new(triangles: &[[u32; 3]], vertex_count: usize) -> Option<Self> {
        triangles
            .iter()
            .flatten()
            .all(|&i| (i as usize) < vertex_count)
            .then(|| Self {
                triangles: triangles.to_vec(),
                vertex_count,
            })
    }

    pub fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    /// Unit vertex normals of flat `positions` (`#V·3`, xyz interleaved) written into `out`
    /// (`#V·3`; zero where undefined), as [`vertex_normals`] defines them but summed in f32.
    /// Panics if either length is not `3·#V`.
    pub fn vertex_normals_into(&self, positions: &[f32], out: &mut [f32]) {
        let n = 3 * self.vertex_count;
        assert!(
            positions.len() == n && out.len() == n,
            "positions and normals must hold 3·{} values",
            self.vertex_count
        );
        out.iter_mut().for_each(|x| *x = 0.0);
        let p = positions.as_ptr();
        let o = out.as_mut_ptr();
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| 3 * i as usize);
            // SAFETY: every index was checked < #V in `new`, and both slices hold 3·#V values
            // (asserted above), so a..a+2, b..b+2 and c..c+2 are in bounds. Unchecked access
            // matters here: this runs on every slider move of a 214K-vertex body, and the bounds
            // checks made it about 1.5× (native) to 2× (WASM) slower.
            unsafe {
                let (ax, ay, az) = (*p.add(a), *p.add(a + 1), *p.add(a + 2));
                let (ux, uy, uz) = (*p.add(b) - ax, *p.add(b + 1) - ay, *p.add(b + 2) - az);
                let (vx, vy, vz) = (*p.add(c) - ax, *p.add(c + 1) - ay, *p.add(c + 2) - az);
                let (nx, ny, nz) = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
                for i in [a, b, c] {
                    *o.add(i) += nx;
                    *o.add(i + 1) += ny;
                    *o.add(i + 2) += nz;
                }
            }
        }
        for v in out.chunks_exact_mut(3) {
            let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            let inv = if len > 0.0 && len.is_finite() {
                1.0 / len
            } else {
                0.0
            };
            v.iter_mut().for_each(|x| *x *= inv);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(xyz: &[[f64; 3]]) -> Vec<Point3<f64>> {
        xyz.iter().map(|&p| Point3::from(p)).collect()
    }

    /// Vertex 0 is shared by a big triangle facing +z and a small one facing +x; vertex 5 is
    /// isolated.
    fn two_facings() -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
        let p = points(&[
            [0.0, 0.0, 0.0],
            [10.0, 0.0, 0.0],
            [0.0, 10.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [5.0, 5.0, 5.0],
        ]);
        (p, vec![[0, 1, 2], [0, 3, 4], [1, 3, 2]])
    }

    #[test]
    fn flat_square_points_up_and_isolated_vertex_is_zero() {
        #[rustfmt::skip]
        let square = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        let p = points(&[square.as_slice(), &[[5.0, 5.0, 5.0]]].concat());
        let t = [[0, 1, 2], [0, 2, 3], [0, 0, 1]];
        let n = vertex_normals(&p, &t);
        for (v, normal) in n.iter().enumerate().take(4) {
            assert!((normal - Vector3::z()).norm() < 1e-12, "{v}: {normal:?}");
        }
        assert_eq!(n[4], Vector3::zeros());
        let f = face_normals(&p, &t);
        assert!((f[0] - Vector3::z()).norm() < 1e-12);
        assert_eq!(f[2], Vector3::zeros());
    }

    #[test]
    fn weights_by_area() {
        let (p, t) = two_facings();
        let n = vertex_normals(&p, &t[..2])[0];
        let expected = Vector3::new(1.0, 0.0, 100.0).normalize();
        assert!((n - expected).norm() < 1e-12);
    }

    #[test]
    fn into_form_overwrites_the_buffer() {
        let (p, t) = two_facings();
        let mut out = vec![Vector3::new(7.0, 7.0, 7.0); p.len()];
        vertex_normals_into(&p, &t, &mut out);
        assert_eq!(out, vertex_normals(&p, &t));
        assert_eq!(out[5], Vector3::zeros());
    }

    #[test]
    fn flat_f32_normals_match_the_f64_ones() {
        let (p, t) = two_facings();
        let flat: Vec<f32> = p
            .iter()
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect();
        let mut out = vec![1.0f32; flat.len()];
        let topology = NormalTopology::new(&t, 6).unwrap();
        topology.vertex_normals_into(&flat, &mut out);
        for (n, m) in vertex_normals(&p, &t).iter().zip(out.chunks_exact(3)) {
            for a in 0..3 {
                assert!((n[a] as f32 - m[a]).abs() < 1e-6, "{n:?} vs {m:?}");
            }
        }
        assert_eq!(&out[15..18], &[0.0, 0.0, 0.0]);
        assert!(NormalTopology::new(&t, 5).is_some());
        assert!(NormalTopology::new(&t, 4).is_none());
    }
}
