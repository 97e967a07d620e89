//! Edges, neighbours, normals and volume of a triangle mesh: what the template build and the
//! smoothness term need.

use std::collections::HashMap;

use nalgebra::{Point3, Vector3};

/// Unique undirected edges `(a, b)` with `a < b`, in first-seen order.
pub fn unique_edges(triangles: &[[u32; 3]]) -> Vec<[u32; 2]> {
    let mut seen = HashMap::with_capacity(triangles.len() * 2);
    let mut edges = Vec::with_capacity(triangles.len() * 3 / 2);
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let e = [a.min(b), a.max(b)];
            if seen.insert(e, ()).is_none() {
                edges.push(e);
            }
        }
    }
    edges
}

/// Per-vertex neighbour lists (`#V` lists) from the triangles.
pub fn vertex_neighbours(vertex_count: usize, triangles: &[[u32; 3]]) -> Vec<Vec<u32>> {
    let mut nb = vec![Vec::new(); vertex_count];
    for [a, b] in unique_edges(triangles) {
        nb[a as usize].push(b);
        nb[b as usize].push(a);
    }
    nb
}

/// Area-weighted vertex normals (unit length; zero for isolated vertices).
pub fn vertex_normals(positions: &[Point3<f64>], triangles: &[[u32; 3]]) -> Vec<Vector3<f64>> {
    let mut n = vec![Vector3::zeros(); positions.len()];
    for t in triangles {
        let [a, b, c] = t.map(|i| positions[i as usize]);
        let f = (b - a).cross(&(c - a));
        for &i in t {
            n[i as usize] += f;
        }
    }
    n.iter()
        .map(|v| v.try_normalize(1e-30).unwrap_or_else(Vector3::zeros))
        .collect()
}

/// Signed volume `Σ (a · (b × c)) / 6` over the triangles: positive when a closed surface is
/// oriented with outward normals.
pub fn signed_volume(positions: &[Point3<f64>], triangles: &[[u32; 3]]) -> f64 {
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| positions[i as usize].coords);
            a.dot(&b.cross(&c)) / 6.0
        })
        .sum()
}

/// Edge-length geodesic distance (Dijkstra) from every vertex to the nearest seed; `f64::INFINITY`
/// where unreachable. `#V` neighbour lists in, `#V` distances out.
pub fn edge_distance(
    positions: &[Point3<f64>],
    neighbours: &[Vec<u32>],
    seeds: impl IntoIterator<Item = u32>,
) -> Vec<f64> {
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;
    let mut dist = vec![f64::INFINITY; positions.len()];
    let mut heap = BinaryHeap::new();
    for s in seeds {
        dist[s as usize] = 0.0;
        heap.push(Reverse((OrdF64(0.0), s)));
    }
    while let Some(Reverse((OrdF64(d), v))) = heap.pop() {
        if d > dist[v as usize] {
            continue;
        }
        for &w in &neighbours[v as usize] {
            let nd = d + (positions[v as usize] - positions[w as usize]).norm();
            if nd < dist[w as usize] {
                dist[w as usize] = nd;
                heap.push(Reverse((OrdF64(nd), w)));
            }
        }
    }
    dist
}

#[derive(Clone, Copy)]
struct OrdF64(f64);
impl PartialEq for OrdF64 {
    fn eq(&self, other: &Self) -> bool {
        self.0.total_cmp(&other.0).is_eq()
    }
}
impl Eq for OrdF64 {}
impl PartialOrd for OrdF64 {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for OrdF64 {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetra() -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
        let p = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.0, 0.0, 1.0),
        ];
        (p, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    }

    #[test]
    fn tetra_volume_edges_distance() {
        let (p, t) = tetra();
        assert!((signed_volume(&p, &t) - 1.0 / 6.0).abs() < 1e-12);
        assert_eq!(unique_edges(&t).len(), 6);
        let nb = vertex_neighbours(4, &t);
        let d = edge_distance(&p, &nb, [1]);
        assert!((d[2] - 2f64.sqrt()).abs() < 1e-12 && d[1] == 0.0);
        let n = vertex_normals(&p, &t);
        assert!(n[1].x > 0.0);
    }
}
