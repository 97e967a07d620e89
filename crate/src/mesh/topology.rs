//! Mesh connectivity: unique edges, vertex neighbours, boundary edges, boundary vertices,
//! boundary loops (holes) and connected components. A boundary edge is an edge used by exactly
//! one triangle; edges used by three or more (non-manifold) are not boundary edges. Degenerate
//! edges (a triangle naming one vertex twice) are ignored throughout.

use super::Mesh;

/// Each undirected edge once, as `[i, j]` with `i < j`, sorted: the pairs summed over in the
/// smoothness term E_s (paper eq. 7). `triangles`: `#F`.
pub fn unique_edges(triangles: &[[u32; 3]]) -> Vec<[u32; 2]> {
    let mut edges: Vec<[u32; 2]> = triangles
        .iter()
        .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
        .filter(|[a, b]| a != b)
        .map(|[a, b]| [a.min(b), a.max(b)])
        .collect();
    edges.sort_unstable();
    edges.dedup();
    edges
}

/// Per-vertex neighbour lists (`#V` lists, each ascending) from the triangles.
pub fn vertex_neighbours(vertex_count: usize, triangles: &[[u32; 3]]) -> Vec<Vec<u32>> {
    let mut nb = vec![Vec::new(); vertex_count];
    for [a, b] in unique_edges(triangles) {
        nb[a as usize].push(b);
        nb[b as usize].push(a);
    }
    nb
}

/// Calls `each(uses)` once per undirected edge with every use of it: `(triangle, [a, b])`, the
/// edge directed as in that triangle (one use: a boundary edge; two: a manifold edge; more:
/// non-manifold). `triangles`: `#F` indexing `vertex_count` vertices. Degenerate edges are left
/// out.
pub fn for_each_edge(
    vertex_count: usize,
    triangles: &[[u32; 3]],
    mut each: impl FnMut(&[(u32, u32, [u32; 2])]),
) {
    // Bucket each undirected edge under its smaller vertex (counting sort, O(E)), then group the
    // uses of each edge within its small bucket: far faster than sorting all 3·#F edges. A use is
    // (the larger vertex, the triangle, the directed edge).
    let n = vertex_count;
    let mut start = vec![0u32; n + 1];
    let directed = || {
        triangles.iter().enumerate().flat_map(|(t, v)| {
            [[v[0], v[1]], [v[1], v[2]], [v[2], v[0]]]
                .into_iter()
                .filter(|[a, b]| a != b)
                .map(move |e| (t as u32, e))
        })
    };
    for (_, [a, b]) in directed() {
        start[a.min(b) as usize + 1] += 1;
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut bucket = vec![(0u32, 0u32, [0u32; 2]); start[n] as usize];
    for (t, [a, b]) in directed() {
        let slot = &mut fill[a.min(b) as usize];
        bucket[*slot as usize] = (a.max(b), t, [a, b]);
        *slot += 1;
    }
    for v in 0..n {
        let edges = &mut bucket[start[v] as usize..start[v + 1] as usize];
        edges.sort_unstable_by_key(|e| e.0);
        for uses in edges.chunk_by(|x, y| x.0 == y.0) {
            each(uses);
        }
    }
}

/// Boundary edges `[a, b]`, directed as in their triangle (so loops run consistently), sorted.
/// `triangles`: `#F` indexing `vertex_count` vertices.
pub fn boundary_edges(vertex_count: usize, triangles: &[[u32; 3]]) -> Vec<[u32; 2]> {
    boundary_edges_and_disagreement(vertex_count, triangles).0
}

/// [`boundary_edges`], and whether any edge's two triangles run it the same way (they disagree
/// on which of their sides is the surface's outside: [`super::orientation`]), from one pass over
/// the edges: the scan summary needs both, and the pass is most of either's cost.
pub fn boundary_edges_and_disagreement(
    vertex_count: usize,
    triangles: &[[u32; 3]],
) -> (Vec<[u32; 2]>, bool) {
    let mut out = Vec::new();
    let mut disagree = false;
    for_each_edge(vertex_count, triangles, |uses| match uses {
        [(_, _, edge)] => out.push(*edge),
        [(_, _, [a, _]), (_, _, [c, _])] => disagree |= a == c,
        _ => {}
    });
    out.sort_unstable();
    (out, disagree)
}

/// `#V` flags: whether each vertex lies on a boundary edge (a hole rim or an open border).
pub fn boundary_vertices(vertex_count: usize, triangles: &[[u32; 3]]) -> Vec<bool> {
    let mut is_boundary = vec![false; vertex_count];
    for [a, b] in boundary_edges(vertex_count, triangles) {
        is_boundary[a as usize] = true;
        is_boundary[b as usize] = true;
    }
    is_boundary
}

/// The boundary loops (holes and open borders), each as the vertex indices along it. Edges are
/// chained head to tail; where a boundary vertex is pinched (two loops touch), each loop is still
/// traced separately, and a chain that cannot close is returned as it is.
pub fn boundary_loops(mesh: &Mesh) -> Vec<Vec<u32>> {
    loops_of(&boundary_edges(mesh.positions.len(), &mesh.triangles))
}

/// [`boundary_loops`] of the boundary edges `edges` as [`boundary_edges`] gives them (sorted).
pub fn loops_of(edges: &[[u32; 2]]) -> Vec<Vec<u32>> {
    let mut used = vec![false; edges.len()];
    let mut loops = Vec::new();
    // `edges` is sorted by start vertex, so the edges leaving `v` are one contiguous run.
    let leaving = |v: u32| {
        let start = edges.partition_point(|e| e[0] < v);
        let end = edges.partition_point(|e| e[0] <= v);
        start..end
    };
    for first in 0..edges.len() {
        if used[first] {
            continue;
        }
        used[first] = true;
        let [start, mut current] = edges[first];
        let mut chain = vec![start];
        while current != start {
            let Some(next) = leaving(current).find(|&e| !used[e]) else {
                break;
            };
            used[next] = true;
            chain.push(current);
            current = edges[next][1];
        }
        loops.push(chain);
    }
    loops
}

/// Per triangle, the label its vertices carry (`labels` as [`component_labels`] gives them).
pub fn triangle_labels(mesh: &Mesh, labels: &[u32]) -> Vec<u32> {
    mesh.triangles
        .iter()
        .map(|t| labels[t[0] as usize])
        .collect()
}

/// Connected-component labels of the vertices used by triangles (two vertices are connected when
/// a triangle holds both): `#V` labels `0..count`, and `u32::MAX` for vertices no triangle uses.
pub fn component_labels(mesh: &Mesh) -> (Vec<u32>, usize) {
    let n = mesh.positions.len();
    let mut parent: Vec<u32> = (0..n as u32).collect();
    fn root(parent: &mut [u32], mut v: u32) -> u32 {
        while parent[v as usize] != v {
            let grand = parent[parent[v as usize] as usize];
            parent[v as usize] = grand;
            v = grand;
        }
        v
    }
    let mut used = vec![false; n];
    for t in &mesh.triangles {
        for &v in t {
            used[v as usize] = true;
        }
        let r0 = root(&mut parent, t[0]);
        for &v in &t[1..] {
            let r = root(&mut parent, v);
            if r != r0 {
                parent[r as usize] = r0;
            }
        }
    }
    let mut labels = vec![u32::MAX; n];
    let mut label_of_root = vec![u32::MAX; n];
    let mut count = 0usize;
    for v in 0..n {
        if !used[v] {
            continue;
        }
        let r = root(&mut parent, v as u32) as usize;
        if label_of_root[r] == u32::MAX {
            label_of_root[r] = count as u32;
            count += 1;
        }
        labels[v] = label_of_root[r];
    }
    (labels, count)
}

/// The number of connected components (vertices no triangle uses are not counted).
pub fn components(mesh: &Mesh) -> usize {
    component_labels(mesh).1
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use nalgebra::Point3;

    /// A unit cube of 8 vertices and 12 outward-facing triangles.
    pub(crate) fn cube() -> Mesh {
        let positions = (0..8)
            .map(|i| Point3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64))
            .collect();
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let triangles = quads
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect();
        Mesh::new(positions, triangles)
    }

    fn tetrahedron(offset: f64, first: u32) -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
        let p = vec![
            Point3::new(offset, 0.0, 0.0),
            Point3::new(offset + 1.0, 0.0, 0.0),
            Point3::new(offset, 1.0, 0.0),
            Point3::new(offset, 0.0, 1.0),
        ];
        let f = first;
        let t = vec![
            [f, f + 2, f + 1],
            [f, f + 1, f + 3],
            [f, f + 3, f + 2],
            [f + 1, f + 2, f + 3],
        ];
        (p, t)
    }

    #[test]
    fn closed_cube_has_no_loops_and_one_component() {
        let mesh = cube();
        assert!(boundary_edges(mesh.positions.len(), &mesh.triangles).is_empty());
        assert!(boundary_loops(&mesh).is_empty());
        assert_eq!(components(&mesh), 1);
        assert!(boundary_vertices(mesh.positions.len(), &mesh.triangles)
            .iter()
            .all(|b| !b));
    }

    #[test]
    fn cube_without_a_face_has_one_four_vertex_loop() {
        let mut mesh = cube();
        mesh.triangles.truncate(10);
        let loops = boundary_loops(&mesh);
        assert_eq!(loops.len(), 1);
        let mut hole = loops[0].clone();
        hole.sort_unstable();
        assert_eq!(hole, [1, 3, 5, 7]);
        assert_eq!(components(&mesh), 1);
        let flags = boundary_vertices(mesh.positions.len(), &mesh.triangles);
        assert_eq!(flags.iter().filter(|b| **b).count(), 4);
        assert!(flags[1] && flags[3] && flags[5] && flags[7]);
    }

    #[test]
    fn one_pass_says_the_boundary_and_whether_triangles_disagree() {
        let census =
            |mesh: &Mesh| boundary_edges_and_disagreement(mesh.positions.len(), &mesh.triangles);
        assert_eq!(census(&cube()), (vec![], false));
        let mut open = cube();
        open.triangles.truncate(10);
        let (edges, disagree) = census(&open);
        assert_eq!(edges, boundary_edges(open.positions.len(), &open.triangles));
        assert_eq!((edges.len(), disagree), (4, false));
        // One triangle turned: its three edges are run the same way by it and its neighbours.
        let turned = crate::mesh::winding::tests::flipped(&open, |t| t == 3);
        assert!(census(&turned).1);
    }

    #[test]
    fn two_disjoint_tetrahedra_are_two_components() {
        let (mut p, mut t) = tetrahedron(0.0, 0);
        let (p2, t2) = tetrahedron(5.0, 4);
        p.extend(p2);
        t.extend(t2);
        p.push(Point3::new(9.0, 9.0, 9.0)); // unused: not a component
        let mesh = Mesh::new(p, t);
        let (labels, count) = component_labels(&mesh);
        assert_eq!(count, 2);
        assert_eq!(labels[0], labels[3]);
        assert_ne!(labels[0], labels[4]);
        assert_eq!(labels[8], u32::MAX);
        assert!(boundary_loops(&mesh).is_empty());
    }

    #[test]
    fn cube_with_two_opposite_faces_removed_has_two_loops() {
        let mut mesh = cube();
        mesh.triangles.drain(0..4); // the z = 0 and z = 1 faces
        let loops = boundary_loops(&mesh);
        assert_eq!(loops.len(), 2);
        assert!(loops.iter().all(|l| l.len() == 4));
        assert_eq!(components(&mesh), 1);
    }

    /// A mesh from corner coordinates and triangles.
    fn mesh(xyz: &[[f64; 3]], triangles: &[[u32; 3]]) -> Mesh {
        Mesh::new(
            xyz.iter().map(|&p| Point3::from(p)).collect(),
            triangles.to_vec(),
        )
    }

    #[test]
    fn an_edge_shared_by_three_triangles_is_not_a_boundary_edge() {
        #[rustfmt::skip]
        let corners = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0]];
        let mesh = mesh(
            &[corners.as_slice(), &[[0.0, 0.0, 1.0]]].concat(),
            &[[0, 1, 2], [1, 0, 3], [0, 1, 4]],
        );
        let edges = boundary_edges(mesh.positions.len(), &mesh.triangles);
        assert!(!edges
            .iter()
            .any(|e| (e[0].min(e[1]), e[0].max(e[1])) == (0, 1)));
        assert_eq!(edges.len(), 6);
    }

    #[test]
    fn quad_has_five_unique_edges_and_every_vertex_on_the_boundary() {
        let t = [[0, 1, 2], [0, 2, 3], [3, 3, 0]];
        assert_eq!(
            unique_edges(&t),
            vec![[0, 1], [0, 2], [0, 3], [1, 2], [2, 3]]
        );
        assert!(boundary_vertices(4, &t).iter().all(|&b| b));
        assert_eq!(
            vertex_neighbours(4, &t),
            vec![vec![1, 2, 3], vec![0, 2], vec![0, 1, 3], vec![0, 2]]
        );
    }

    #[test]
    fn single_triangle_is_one_loop_of_three() {
        let mesh = mesh(
            &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            &[[0, 1, 2]],
        );
        assert_eq!(boundary_loops(&mesh), vec![vec![0, 1, 2]]);
    }
}
