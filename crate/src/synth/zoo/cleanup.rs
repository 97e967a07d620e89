//! Scanner-export effects on the scan itself (template frame, metres, y up, feet on y = 0):
//!
//! * [`cut_field_of_view`] — the crown or the feet cut off: every vertex whose noise-free height
//!   lies above `top` or below `bottom` is dropped with its triangles;
//! * [`decimate`] — a decimated export by vertex clustering: vertices in one cube of side `cell`
//!   become one (their mean), triangles are renumbered, and those that collapse are dropped;
//! * [`add_strays`] — stray points: `points` lone vertices and `clusters` small triangulated
//!   blobs of 4–9 vertices floating within `margin` (m) of the body's bounding box (not on it).

use std::collections::HashMap;

use nalgebra::{Point3, Vector3};
use rand::Rng;

use super::edit::{append, keep_vertices};
use crate::mesh::bounding_box;
use crate::synth::scanner::Scan;

/// `scan` without the vertices whose noise-free height (`clean.y`) is above `top` or below
/// `bottom`, nor their triangles.
pub fn cut_field_of_view(scan: &Scan, bottom: f64, top: f64) -> Scan {
    let keep: Vec<bool> = scan
        .clean
        .iter()
        .map(|p| p.y >= bottom && p.y <= top)
        .collect();
    keep_vertices(scan, &keep, |_| true)
}

/// `scan` decimated by vertex clustering on a grid of cubes of side `cell` (m): one vertex per
/// occupied cube at the mean of its vertices (noisy and noise-free alike); triangles with two
/// corners in one cube, and repeated triangles, are dropped.
pub fn decimate(scan: &Scan, cell: f64) -> Scan {
    if cell <= 0.0 {
        return scan.clone();
    }
    let key = |p: &Point3<f64>| {
        (
            (p.x / cell).floor() as i64,
            (p.y / cell).floor() as i64,
            (p.z / cell).floor() as i64,
        )
    };
    let mut cluster: HashMap<(i64, i64, i64), u32> = HashMap::new();
    let mut sums: Vec<(Vector3<f64>, Vector3<f64>, f64, u8)> = Vec::new();
    let mut of_vertex = Vec::with_capacity(scan.mesh.positions.len());
    for (v, p) in scan.mesh.positions.iter().enumerate() {
        let next = sums.len() as u32;
        let c = *cluster.entry(key(p)).or_insert(next);
        if c == next {
            sums.push((Vector3::zeros(), Vector3::zeros(), 0.0, scan.head[v]));
        }
        let s = &mut sums[c as usize];
        s.0 += p.coords;
        s.1 += scan.clean[v].coords;
        s.2 += 1.0;
        of_vertex.push(c);
    }
    let mut out = Scan::default();
    for (p, q, n, head) in &sums {
        out.mesh.positions.push(Point3::from(p / *n));
        out.clean.push(Point3::from(q / *n));
        out.head.push(*head);
    }
    let mut seen = std::collections::HashSet::new();
    for t in &scan.mesh.triangles {
        let [a, b, c] = t.map(|v| of_vertex[v as usize]);
        if a == b || b == c || c == a {
            continue;
        }
        let mut sorted = [a, b, c];
        sorted.sort_unstable();
        if seen.insert(sorted) {
            out.mesh.triangles.push([a, b, c]);
        }
    }
    out
}

/// The cube side (m) that decimates `scan` to about `target` vertices: `√(area / target)` with
/// the scan's triangle area (one vertex per cube the surface passes through, roughly).
pub fn cell_for(scan: &Scan, target: usize) -> f64 {
    let p = &scan.mesh.positions;
    let area: f64 = scan
        .mesh
        .triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| p[v as usize]);
            0.5 * (b - a).cross(&(c - a)).norm()
        })
        .sum();
    (area / target.max(1) as f64).sqrt()
}

/// Adds `points` lone vertices and `clusters` small triangulated blobs (a fan of 3–8 triangles,
/// 1–3 cm across) at uniform places within `margin` (m) of the bounding box of the scan, none
/// nearer than `margin / 4` to the box (so outside the body).
pub fn add_strays<R: Rng>(
    scan: &mut Scan,
    points: usize,
    clusters: usize,
    margin: f64,
    rng: &mut R,
) {
    let Some((lo, hi)) = bounding_box(&scan.mesh.positions) else {
        return;
    };
    let (lo, hi) = (lo.coords.add_scalar(-margin), hi.coords.add_scalar(margin));
    let inner = margin / 4.0;
    let (box_lo, box_hi) = (lo.add_scalar(margin - inner), hi.add_scalar(inner - margin));
    let place = |rng: &mut R| loop {
        let p = Vector3::new(
            rng.gen_range(lo.x..hi.x),
            rng.gen_range(lo.y..hi.y),
            rng.gen_range(lo.z..hi.z),
        );
        let inside = (0..3).all(|k| p[k] > box_lo[k] && p[k] < box_hi[k]);
        if !inside {
            return Point3::from(p);
        }
    };
    let mut positions: Vec<Point3<f64>> = (0..points).map(|_| place(rng)).collect();
    let mut triangles = Vec::new();
    for _ in 0..clusters {
        let centre = place(rng);
        let k = rng.gen_range(3..=8usize);
        let radius = rng.gen_range(0.005..0.015);
        let hub = positions.len() as u32;
        positions.push(centre);
        for j in 0..k {
            let a = 2.0 * std::f64::consts::PI * j as f64 / k as f64;
            let wobble = Vector3::new(rng.gen_range(-1.0..1.0), 0.0, rng.gen_range(-1.0..1.0));
            positions.push(
                centre
                    + Vector3::new(a.cos(), rng.gen_range(-0.3..0.3), a.sin()) * radius
                    + wobble * 0.002,
            );
            triangles.push([hub, hub + 1 + j as u32, hub + 1 + ((j + 1) % k) as u32]);
        }
    }
    append(scan, &positions, &triangles);
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    /// A vertical 1 × 2 m sheet sampled every 5 mm, triangulated.
    fn sheet() -> Scan {
        let (cols, rows) = (200, 400);
        let mut positions = Vec::new();
        for r in 0..rows {
            for c in 0..cols {
                positions.push(Point3::new(c as f64 * 0.005, r as f64 * 0.005, 0.0));
            }
        }
        let at: Vec<Option<u32>> = (0..rows * cols).map(|v| Some(v as u32)).collect();
        let triangles = super::super::edit::grid_triangles(rows, cols, &at);
        Scan::exact(positions, triangles)
    }

    #[test]
    fn no_vertex_is_left_beyond_the_cut() {
        let s = cut_field_of_view(&sheet(), 0.04, 1.9);
        assert!(s.mesh.positions.iter().all(|p| p.y >= 0.04 && p.y <= 1.9));
        assert!(s.mesh.positions.iter().any(|p| p.y > 1.89));
        assert!(s.mesh.triangles.len() > 100_000);
    }

    #[test]
    fn decimation_reaches_about_the_target_count() {
        let s = sheet();
        let cell = cell_for(&s, 10_000);
        let d = decimate(&s, cell);
        let n = d.mesh.positions.len();
        assert!((7_000..=14_000).contains(&n), "{n} vertices (cell {cell})");
        assert!(d.mesh.triangles.len() > n);
        assert!(d
            .mesh
            .triangles
            .iter()
            .all(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]));
    }

    #[test]
    fn strays_float_off_the_body() {
        let mut s = sheet();
        let body = s.mesh.positions.len();
        add_strays(&mut s, 50, 10, 0.4, &mut ChaCha8Rng::seed_from_u64(5));
        let added = &s.mesh.positions[body..];
        assert!(added.len() >= 50 + 10 * 4);
        // Outside the sheet's box grown by a quarter of the margin (10 cm) less a blob's reach.
        for p in added {
            let outside =
                p.x < -0.08 || p.x > 1.08 || p.y < -0.08 || p.y > 2.08 || p.z.abs() > 0.08;
            assert!(outside, "{p}");
        }
    }
}
