//! Editing a [`Scan`]: keeping some of its vertices and triangles, and adding geometry that is not
//! the body (floor, strays). Added vertices have no noise-free body point: their `clean` is the
//! point itself and their `head` is [`NOT_BODY`].

use nalgebra::Point3;

use crate::synth::scanner::Scan;

/// `Scan::head` of a vertex that is not on the body (floor, turntable, stray points).
pub const NOT_BODY: u8 = u8::MAX;

/// The scan with only the vertices where `keep` is true and the triangles whose three vertices are
/// kept and that `keep_triangle` accepts; vertices keep their order.
pub fn keep_vertices(
    scan: &Scan,
    keep: &[bool],
    keep_triangle: impl Fn(&[u32; 3]) -> bool,
) -> Scan {
    let mut index = vec![u32::MAX; scan.mesh.positions.len()];
    let mut out = Scan::default();
    for (v, p) in scan.mesh.positions.iter().enumerate() {
        if keep[v] {
            index[v] = out.mesh.positions.len() as u32;
            out.mesh.positions.push(*p);
            out.clean.push(scan.clean[v]);
            out.head.push(scan.head[v]);
        }
    }
    out.mesh.triangles = scan
        .mesh
        .triangles
        .iter()
        .filter(|t| t.iter().all(|&v| keep[v as usize]) && keep_triangle(t))
        .map(|t| t.map(|v| index[v as usize]))
        .collect();
    out
}

/// Adds `positions` (noisy as measured) and `triangles` (indices into `positions`) to `scan` as
/// geometry that is not the body.
pub fn append(scan: &mut Scan, positions: &[Point3<f64>], triangles: &[[u32; 3]]) {
    let base = scan.mesh.positions.len() as u32;
    scan.mesh.positions.extend_from_slice(positions);
    scan.clean.extend_from_slice(positions);
    scan.head
        .extend(std::iter::repeat_n(NOT_BODY, positions.len()));
    scan.mesh
        .triangles
        .extend(triangles.iter().map(|t| t.map(|v| v + base)));
}

/// Triangles of a `rows × cols` grid of optional vertex indices: each cell whose four corners are
/// all present becomes two triangles (`a, b, c`, `a, c, d` with corners `a = (r, c)`,
/// `b = (r, c + 1)`, `c = (r + 1, c + 1)`, `d = (r + 1, c)`).
pub fn grid_triangles(rows: usize, cols: usize, at: &[Option<u32>]) -> Vec<[u32; 3]> {
    let mut out = Vec::new();
    for r in 0..rows.saturating_sub(1) {
        for c in 0..cols.saturating_sub(1) {
            let q = [
                at[r * cols + c],
                at[r * cols + c + 1],
                at[(r + 1) * cols + c + 1],
                at[(r + 1) * cols + c],
            ];
            if let [Some(a), Some(b), Some(cc), Some(d)] = q {
                out.push([a, b, cc]);
                out.push([a, cc, d]);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Mesh;

    fn square() -> Scan {
        let positions = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ];
        Scan {
            mesh: Mesh::new(positions.clone(), vec![[0, 1, 2], [0, 2, 3]]),
            clean: positions,
            head: vec![0, 1, 2, 3],
        }
    }

    #[test]
    fn kept_vertices_are_renumbered_and_their_triangles_kept() {
        let s = keep_vertices(&square(), &[true, false, true, true], |_| true);
        assert_eq!(s.mesh.positions.len(), 3);
        assert_eq!(s.mesh.triangles, vec![[0, 1, 2]]);
        assert_eq!(s.head, vec![0, 2, 3]);
        let none = keep_vertices(&square(), &[true; 4], |t| t[1] != 1);
        assert_eq!(none.mesh.triangles, vec![[0, 2, 3]]);
    }

    #[test]
    fn appended_geometry_is_marked_not_body() {
        let mut s = square();
        append(&mut s, &[Point3::new(5.0, 5.0, 5.0)], &[]);
        assert_eq!(s.head[4], NOT_BODY);
        assert_eq!(s.clean.len(), 5);
        let t = grid_triangles(2, 2, &[Some(0), Some(1), None, Some(3)]);
        assert!(t.is_empty());
        assert_eq!(
            grid_triangles(2, 2, &[Some(0), Some(1), Some(2), Some(3)]).len(),
            2
        );
    }
}
