//! A bounding-volume hierarchy over a triangle mesh for ray casting: the virtual scanner's rays
//! (`crate::synth::scanner`), and the rays that tell which side of a piece of a scan is seen from
//! outside ([`super::winding`]).
//!
//! Its own tree rather than `parry3d-f64`'s (which the aligner's closest-point index uses): the
//! scanner needs only the first hit of a ray with its triangle and barycentrics. Median split on
//! the longest centroid axis, leaves of ≤ 4 triangles; the ray/triangle test is
//! [`crate::mesh::ray`]'s Möller–Trumbore.

use nalgebra::{Point3, Vector3};

use crate::mesh::ray::ray_triangle;
use crate::mesh::Mesh;

const LEAF_SIZE: usize = 4;

#[derive(Debug, Clone)]
struct Node {
    min: Point3<f64>,
    max: Point3<f64>,
    /// Leaf: `start..start + count` into `order`; inner: children at `start` and `start + 1`
    /// when `count == 0`.
    start: usize,
    count: usize,
}

/// The first surface a ray meets.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RayHit {
    /// Distance along the (unit) ray direction.
    pub t: f64,
    /// Index of the triangle hit.
    pub triangle: usize,
    /// Barycentric weights of the triangle's three corners at the hit.
    pub barycentric: [f64; 3],
}

/// A BVH over a mesh's triangles (it borrows nothing: positions are copied in).
#[derive(Debug, Clone)]
pub struct TriangleBvh {
    positions: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
    order: Vec<usize>,
    nodes: Vec<Node>,
}

impl TriangleBvh {
    /// Builds the hierarchy over `mesh` (indices must be in range).
    pub fn new(mesh: &Mesh) -> Self {
        let mut bvh = Self {
            positions: mesh.positions.clone(),
            triangles: mesh.triangles.clone(),
            order: (0..mesh.triangles.len()).collect(),
            nodes: Vec::with_capacity(2 * mesh.triangles.len() / LEAF_SIZE + 1),
        };
        let centroids: Vec<Point3<f64>> = bvh
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| bvh.positions[i as usize].coords);
                Point3::from((a + b + c) / 3.0)
            })
            .collect();
        bvh.nodes.push(Node {
            min: Point3::origin(),
            max: Point3::origin(),
            start: 0,
            count: 0,
        });
        bvh.build(0, 0, bvh.order.len(), &centroids);
        bvh
    }

    fn build(&mut self, node: usize, start: usize, end: usize, centroids: &[Point3<f64>]) {
        let (mut min, mut max) = (
            Point3::from([f64::INFINITY; 3]),
            Point3::from([f64::NEG_INFINITY; 3]),
        );
        let (mut cmin, mut cmax) = (min, max);
        for &t in &self.order[start..end] {
            for &i in &self.triangles[t] {
                let p = self.positions[i as usize];
                min = min.inf(&p);
                max = max.sup(&p);
            }
            cmin = cmin.inf(&centroids[t]);
            cmax = cmax.sup(&centroids[t]);
        }
        self.nodes[node].min = min;
        self.nodes[node].max = max;
        if end - start <= LEAF_SIZE {
            self.nodes[node].start = start;
            self.nodes[node].count = end - start;
            return;
        }
        let extent = cmax - cmin;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        let mid = (start + end) / 2;
        self.order[start..end].select_nth_unstable_by(mid - start, |&a, &b| {
            centroids[a][axis].total_cmp(&centroids[b][axis])
        });
        let left = self.nodes.len();
        for _ in 0..2 {
            self.nodes.push(Node {
                min,
                max,
                start: 0,
                count: 0,
            });
        }
        self.nodes[node].start = left;
        self.nodes[node].count = 0;
        self.build(left, start, mid, centroids);
        self.build(left + 1, mid, end, centroids);
    }

    /// The nearest hit of the ray `origin + t·dir`, `0 < t < t_max` (`dir` need not be unit; `t`
    /// is then in units of `|dir|`).
    pub fn cast(&self, origin: &Point3<f64>, dir: &Vector3<f64>, t_max: f64) -> Option<RayHit> {
        let inv = Vector3::new(1.0 / dir.x, 1.0 / dir.y, 1.0 / dir.z);
        let mut best: Option<RayHit> = None;
        let mut t_best = t_max;
        let mut stack = [0usize; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top]];
            if !slab(origin, &inv, &node.min, &node.max, t_best) {
                continue;
            }
            if node.count > 0 {
                for &t in &self.order[node.start..node.start + node.count] {
                    if let Some((d, b)) = self.hit_triangle(t, origin, dir) {
                        if d < t_best {
                            t_best = d;
                            best = Some(RayHit {
                                t: d,
                                triangle: t,
                                barycentric: b,
                            });
                        }
                    }
                }
            } else if top + 2 <= stack.len() {
                stack[top] = node.start;
                stack[top + 1] = node.start + 1;
                top += 2;
            }
        }
        best
    }

    fn hit_triangle(&self, t: usize, o: &Point3<f64>, d: &Vector3<f64>) -> Option<(f64, [f64; 3])> {
        let [a, b, c] = self.triangles[t].map(|i| &self.positions[i as usize]);
        let (dist, u, v) = ray_triangle(o, d, [a, b, c], 1e-18)?;
        (dist > 1e-12).then_some((dist, [1.0 - u - v, u, v]))
    }
}

fn slab(
    o: &Point3<f64>,
    inv: &Vector3<f64>,
    min: &Point3<f64>,
    max: &Point3<f64>,
    t_max: f64,
) -> bool {
    let (mut t0, mut t1) = (0.0f64, t_max);
    for k in 0..3 {
        let a = (min[k] - o[k]) * inv[k];
        let b = (max[k] - o[k]) * inv[k];
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        // NaN (ray parallel and on the slab plane) compares false and keeps the box: conservative.
        if lo > t0 {
            t0 = lo;
        }
        if hi < t1 {
            t1 = hi;
        }
        if t0 > t1 {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(n: usize) -> Mesh {
        let mut positions = Vec::new();
        let mut triangles = Vec::new();
        for j in 0..=n {
            for i in 0..=n {
                positions.push(Point3::new(i as f64 / n as f64, j as f64 / n as f64, 0.0));
            }
        }
        let w = (n + 1) as u32;
        for j in 0..n as u32 {
            for i in 0..n as u32 {
                let a = j * w + i;
                triangles.push([a, a + 1, a + w + 1]);
                triangles.push([a, a + w + 1, a + w]);
            }
        }
        Mesh::new(positions, triangles)
    }

    #[test]
    fn matches_brute_force() {
        let mut mesh = grid(20);
        // A second, nearer layer over part of the grid.
        let offset = mesh.positions.len() as u32;
        let copy: Vec<_> = mesh
            .positions
            .iter()
            .map(|p| Point3::new(p.x * 0.5, p.y * 0.5, 0.3))
            .collect();
        let tris: Vec<_> = mesh
            .triangles
            .iter()
            .map(|t| t.map(|i| i + offset))
            .collect();
        mesh.positions.extend(copy);
        mesh.triangles.extend(tris);
        let bvh = TriangleBvh::new(&mesh);
        for k in 0..200 {
            let x = (k as f64 * 0.618).fract();
            let y = (k as f64 * 0.377).fract();
            let o = Point3::new(x, y, 1.0);
            let d = Vector3::new(0.01, -0.02, -1.0);
            let hit = bvh.cast(&o, &d, 10.0);
            let brute = (0..mesh.triangles.len())
                .filter_map(|t| bvh.hit_triangle(t, &o, &d).map(|(dist, _)| dist))
                .fold(f64::INFINITY, f64::min);
            match hit {
                Some(h) => assert!((h.t - brute).abs() < 1e-12),
                None => assert!(brute.is_infinite()),
            }
        }
        let h = bvh
            .cast(
                &Point3::new(0.2137, 0.1931, 1.0),
                &Vector3::new(0.0, 0.0, -1.0),
                10.0,
            )
            .unwrap();
        assert!((h.t - 0.7).abs() < 1e-12);
    }
}
