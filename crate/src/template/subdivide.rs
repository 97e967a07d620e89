//! Interpolating subdivision as a linear operator: `fine = S · base`.
//!
//! One level splits every triangle into four at its edge midpoints. Original vertices keep their
//! positions and indices (so landmarks and provenance carry over exactly); each new edge vertex
//! takes Loop's edge stencil `3/8 (a + b) + 1/8 (c + d)` (a, b the edge ends, c, d the opposite
//! vertices of the two triangles), or the midpoint `1/2 (a + b)` on a boundary or non-manifold
//! edge. Levels compose, so every fine vertex is a sparse weighted sum of base vertices — the
//! stencils — and any base-resolution body maps to the fine resolution exactly by
//! [`Subdivision::apply`].

use std::collections::HashMap;

use nalgebra::Point3;

/// The sparse linear map from base-resolution vertices to fine-resolution vertices.
#[derive(Debug, Clone, PartialEq)]
pub struct Subdivision {
    /// Base vertex count `#Vb`; the first `#Vb` fine vertices are the base vertices.
    pub base_vertex_count: usize,
    /// Per fine vertex (`#Vf`), the base vertices and weights (summing to 1) it is made from.
    pub stencils: Vec<Vec<(u32, f64)>>,
    /// Fine triangles (`#Ff = 4^levels · #Fb`), counter-clockwise like the base.
    pub triangles: Vec<[u32; 3]>,
}

impl Subdivision {
    /// `levels` rounds of 1→4 subdivision of a mesh with `base_vertex_count` vertices.
    pub fn new(base_vertex_count: usize, triangles: &[[u32; 3]], levels: usize) -> Self {
        let mut stencils: Vec<Vec<(u32, f64)>> = (0..base_vertex_count as u32)
            .map(|v| vec![(v, 1.0)])
            .collect();
        let mut tris = triangles.to_vec();
        for _ in 0..levels {
            let (new_stencils, new_tris) = one_level(&stencils, &tris);
            stencils = new_stencils;
            tris = new_tris;
        }
        Self {
            base_vertex_count,
            stencils,
            triangles: tris,
        }
    }

    /// Fine positions from base positions (`#Vb` in, `#Vf` out).
    pub fn apply(&self, base: &[Point3<f64>]) -> Vec<Point3<f64>> {
        self.stencils
            .iter()
            .map(|s| {
                Point3::from(s.iter().fold(nalgebra::Vector3::zeros(), |acc, &(v, w)| {
                    acc + base[v as usize].coords * w
                }))
            })
            .collect()
    }

    /// Fine per-vertex values from base values, `K` numbers per vertex (e.g. segment weights).
    pub fn apply_values<const K: usize>(&self, base: &[[f32; K]]) -> Vec<[f32; K]> {
        self.stencils
            .iter()
            .map(|s| {
                let mut out = [0f64; K];
                for &(v, w) in s {
                    for (o, x) in out.iter_mut().zip(base[v as usize]) {
                        *o += w * x as f64;
                    }
                }
                out.map(|x| x as f32)
            })
            .collect()
    }
}

type Stencils = Vec<Vec<(u32, f64)>>;

fn one_level(stencils: &[Vec<(u32, f64)>], tris: &[[u32; 3]]) -> (Stencils, Vec<[u32; 3]>) {
    // Edge → opposite vertices of the triangles that share it.
    let mut opposite: HashMap<(u32, u32), Vec<u32>> = HashMap::with_capacity(tris.len() * 2);
    for t in tris {
        for k in 0..3 {
            let (a, b, c) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
            opposite.entry((a.min(b), a.max(b))).or_default().push(c);
        }
    }
    let mut out = stencils.to_vec();
    let mut edge_vertex: HashMap<(u32, u32), u32> = HashMap::with_capacity(opposite.len());
    let mut midpoint = |a: u32, b: u32, out: &mut Stencils| -> u32 {
        let key = (a.min(b), a.max(b));
        if let Some(&v) = edge_vertex.get(&key) {
            return v;
        }
        let weights: Vec<(u32, f64)> = match opposite.get(&key).map(Vec::as_slice) {
            Some(&[c, d]) => vec![(a, 0.375), (b, 0.375), (c, 0.125), (d, 0.125)],
            _ => vec![(a, 0.5), (b, 0.5)],
        };
        let mut combined: HashMap<u32, f64> = HashMap::new();
        for (v, w) in weights {
            for &(bv, bw) in &stencils[v as usize] {
                *combined.entry(bv).or_default() += w * bw;
            }
        }
        let mut s: Vec<(u32, f64)> = combined.into_iter().collect();
        s.sort_by_key(|&(v, _)| v);
        let id = out.len() as u32;
        out.push(s);
        edge_vertex.insert(key, id);
        id
    };
    let mut new_tris = Vec::with_capacity(tris.len() * 4);
    for &[a, b, c] in tris {
        let ab = midpoint(a, b, &mut out);
        let bc = midpoint(b, c, &mut out);
        let ca = midpoint(c, a, &mut out);
        new_tris.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
    }
    (out, new_tris)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_levels_of_a_tetrahedron() {
        let p = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.0, 0.0, 1.0),
        ];
        let t = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        let s = Subdivision::new(4, &t, 2);
        assert_eq!(s.triangles.len(), 64);
        // V - E + F = 2 on a closed genus-0 surface.
        assert_eq!(s.stencils.len(), 34);
        let fine = s.apply(&p);
        assert_eq!(&fine[..4], &p[..]);
        for st in &s.stencils {
            assert!((st.iter().map(|x| x.1).sum::<f64>() - 1.0).abs() < 1e-12);
        }
        // Edge vertex of (0,1) in level 1 uses Loop's 3/8, 3/8, 1/8, 1/8.
        let e = &s.stencils[4];
        assert_eq!(e.len(), 4);
        let v = s.apply_values(&[[1.0f32], [1.0], [1.0], [1.0]]);
        assert!(v.iter().all(|x| (x[0] - 1.0).abs() < 1e-6));
    }
}
