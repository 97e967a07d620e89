//! The body delivered in separate parts, as segmenting scanners export it: torso (with the head,
//! or the head split off at the neck), two arms split at the armpits, two legs split at the
//! crotch — separate connected components written as one mesh.
//!
//! Each scan vertex takes the part of the body-surface vertex nearest to its noise-free point
//! (`Scan::clean`); a triangle whose vertices lie in different parts is dropped, and so is every
//! vertex within `gap` (metres) of a vertex of another part (among its 24 nearest), so the parts
//! do not touch.

use std::num::NonZeroUsize;

use kiddo::{ImmutableKdTree, SquaredEuclidean};
use nalgebra::Point3;

use super::edit::keep_vertices;
use crate::synth::scanner::Scan;

/// How many nearest vertices [`split_parts`] looks at for another part's within the gap.
const GAP_NEIGHBOURS: NonZeroUsize = match NonZeroUsize::new(24) {
    Some(k) => k,
    None => unreachable!(),
};

/// The part of every scan vertex: the label of the `surface` vertex nearest to its noise-free
/// point (`labels[i]` is the part of `surface[i]`). Vertices that are not on the body keep
/// `u8::MAX`.
pub fn scan_labels(scan: &Scan, surface: &[Point3<f64>], labels: &[u8]) -> Vec<u8> {
    let coords: Vec<[f64; 3]> = surface.iter().map(|p| [p.x, p.y, p.z]).collect();
    let Ok(tree) = ImmutableKdTree::<f64, 3>::new_from_slice(&coords) else {
        return vec![u8::MAX; scan.clean.len()];
    };
    scan.clean
        .iter()
        .map(|p| {
            let hit = tree
                .query(&[p.x, p.y, p.z])
                .nearest_one::<SquaredEuclidean<f64>>()
                .execute();
            labels[hit.item as usize]
        })
        .collect()
}

/// `scan` split into parts by the per-vertex `part` labels: no triangle joins two parts, and
/// no vertex has a vertex of another part within `gap` (m) among its [`GAP_NEIGHBOURS`] nearest.
pub fn split_parts(scan: &Scan, part: &[u8], gap: f64) -> Scan {
    let coords: Vec<[f64; 3]> = scan.clean.iter().map(|p| [p.x, p.y, p.z]).collect();
    let mut keep = vec![true; coords.len()];
    if gap > 0.0 {
        if let Ok(tree) = ImmutableKdTree::<f64, 3>::new_from_slice(&coords) {
            for (v, q) in coords.iter().enumerate() {
                keep[v] = tree
                    .query(q)
                    .nearest_n::<SquaredEuclidean<f64>>(GAP_NEIGHBOURS)
                    .execute()
                    .iter()
                    .all(|n| n.distance > gap * gap || part[n.item as usize] == part[v]);
            }
        }
    }
    keep_vertices(scan, &keep, |t| {
        part[t[0] as usize] == part[t[1] as usize] && part[t[1] as usize] == part[t[2] as usize]
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::topology::components;

    /// A strip of `n` × 2 vertices along x, 1 cm apart, triangulated.
    fn strip(n: usize) -> Scan {
        let mut positions = Vec::new();
        for i in 0..n {
            for j in 0..2 {
                positions.push(Point3::new(i as f64 * 0.01, j as f64 * 0.01, 0.0));
            }
        }
        let mut triangles = Vec::new();
        for i in 0..n as u32 - 1 {
            triangles.push([2 * i, 2 * i + 2, 2 * i + 3]);
            triangles.push([2 * i, 2 * i + 3, 2 * i + 1]);
        }
        Scan::exact(positions, triangles)
    }

    #[test]
    fn a_strip_labelled_in_three_splits_into_three_components_with_gaps() {
        let s = strip(30);
        assert_eq!(components(&s.mesh), 1);
        // The "surface": three points along the strip, labelled 0, 1, 2.
        let surface = [
            Point3::new(0.05, 0.0, 0.0),
            Point3::new(0.15, 0.0, 0.0),
            Point3::new(0.25, 0.0, 0.0),
        ];
        let labels = scan_labels(&s, &surface, &[0, 1, 2]);
        let split = split_parts(&s, &labels, 0.012);
        assert_eq!(components(&split.mesh), 3);
        // Every vertex of one part lies more than the gap from every vertex of another.
        let kept_labels = scan_labels(&split, &surface, &[0, 1, 2]);
        for (a, pa) in split.clean.iter().enumerate() {
            for (b, pb) in split.clean.iter().enumerate() {
                if kept_labels[a] != kept_labels[b] {
                    assert!((pa - pb).norm() > 0.012);
                }
            }
        }
    }
}
