//! A closed box as the integration tests write it: 8 corners `size` apart from the origin, 12
//! triangles wound counter-clockwise seen from outside (two per face).

/// The corners (corner `i` at `size` where bit 0, 1, 2 of `i` is set for x, y, z) and triangles.
pub fn cube(size: [f64; 3]) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let corners = (0..8)
        .map(|i| [0, 1, 2].map(|k| ((i >> k) & 1) as f64 * size[k]))
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
    (corners, triangles)
}
