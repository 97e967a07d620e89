//! Edge-length geodesic distance over a triangle mesh: what the template build measures (edges,
//! neighbours, normals and the signed volume are in [`crate::mesh`]).

use nalgebra::Point3;

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
    fn tetra_edge_distance() {
        let (p, t) = tetra();
        let nb = crate::mesh::topology::vertex_neighbours(4, &t);
        let d = edge_distance(&p, &nb, [1]);
        assert!((d[2] - 2f64.sqrt()).abs() < 1e-12 && d[1] == 0.0);
    }
}
