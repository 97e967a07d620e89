//! What a scanner sees besides the body at the feet (template frame, y up, floor at y = 0):
//!
//! * **floor remnants** — the floor's plane where it shows around the feet: grid points at the
//!   scanner's step on y = 0, kept where they lie horizontally within `margin` of a foot vertex
//!   (a body vertex lower than `foot_height`) but no nearer than `under` to one (the floor under
//!   the sole is hidden), triangulated; separate patches, not joined to the body;
//! * **a turntable** — a disc of radius `radius` on y = 0 (hidden under the feet in the same way)
//!   with its rim, a band of height `rim` below the disc's edge.
//!
//! Both get Gaussian noise `sigma` along y (the disc) or radially (the rim).

use nalgebra::Point3;
use rand::Rng;
use rand_distr::{Distribution, Normal};

use super::edit::{append, grid_triangles};
use crate::synth::scanner::Scan;

/// Vertices of the body up to this height (m) are the feet.
pub const FOOT_HEIGHT: f64 = 0.03;

/// The floor under the sole is hidden up to this horizontal distance (m) from a foot vertex.
pub const UNDER_SOLE: f64 = 0.01;

/// Horizontal (x, z) positions of the feet: the body vertices of `scan` below [`FOOT_HEIGHT`].
fn feet(scan: &Scan) -> Vec<[f64; 2]> {
    scan.clean
        .iter()
        .filter(|p| p.y < FOOT_HEIGHT)
        .map(|p| [p.x, p.z])
        .collect()
}

/// The nearest horizontal distance from `(x, z)` to any of `feet` (brute force on a coarse
/// bucket grid of cell `cell`).
struct FootIndex {
    cell: f64,
    buckets: std::collections::HashMap<(i64, i64), Vec<[f64; 2]>>,
}

impl FootIndex {
    fn new(feet: &[[f64; 2]], cell: f64) -> Self {
        let mut buckets: std::collections::HashMap<(i64, i64), Vec<[f64; 2]>> = Default::default();
        for f in feet {
            let key = ((f[0] / cell).floor() as i64, (f[1] / cell).floor() as i64);
            buckets.entry(key).or_default().push(*f);
        }
        Self { cell, buckets }
    }

    /// The distance to the nearest foot point, if any lies within one cell.
    fn distance(&self, x: f64, z: f64) -> f64 {
        let (i, k) = (
            (x / self.cell).floor() as i64,
            (z / self.cell).floor() as i64,
        );
        let mut best = f64::INFINITY;
        for di in -1..=1 {
            for dk in -1..=1 {
                for f in self.buckets.get(&(i + di, k + dk)).into_iter().flatten() {
                    best = best.min(((f[0] - x).powi(2) + (f[1] - z).powi(2)).sqrt());
                }
            }
        }
        best
    }
}

/// Adds floor patches around the feet: on y = 0, within `margin` (m) of a foot but not under it,
/// sampled every `step` (m), noise `sigma` (m) along y.
pub fn add_floor<R: Rng>(scan: &mut Scan, margin: f64, step: f64, sigma: f64, rng: &mut R) {
    let feet = feet(scan);
    if feet.is_empty() || step <= 0.0 {
        return;
    }
    let index = FootIndex::new(&feet, margin.max(UNDER_SOLE));
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for f in &feet {
        for k in 0..2 {
            lo[k] = lo[k].min(f[k] - margin);
            hi[k] = hi[k].max(f[k] + margin);
        }
    }
    let cols = ((hi[0] - lo[0]) / step).ceil() as usize + 1;
    let rows = ((hi[1] - lo[1]) / step).ceil() as usize + 1;
    let noise = Normal::new(0.0, sigma.max(0.0)).unwrap_or(Normal::new(0.0, 0.0).unwrap());
    let mut positions = Vec::new();
    let mut at = vec![None; rows * cols];
    for r in 0..rows {
        for c in 0..cols {
            let (x, z) = (lo[0] + c as f64 * step, lo[1] + r as f64 * step);
            let d = index.distance(x, z);
            if d > UNDER_SOLE && d <= margin {
                at[r * cols + c] = Some(positions.len() as u32);
                positions.push(Point3::new(x, noise.sample(rng), z));
            }
        }
    }
    let triangles = grid_triangles(rows, cols, &at);
    append(scan, &positions, &triangles);
}

/// Adds a turntable: a disc of `radius` (m) on y = 0 around the body's vertical axis (the middle
/// of the feet), hidden under the feet, and its rim, `rim` (m) high below the edge; sampled every
/// `step` (m), noise `sigma` (m).
pub fn add_turntable<R: Rng>(
    scan: &mut Scan,
    radius: f64,
    rim: f64,
    step: f64,
    sigma: f64,
    rng: &mut R,
) {
    let feet = feet(scan);
    if feet.is_empty() || step <= 0.0 || radius <= 0.0 {
        return;
    }
    let n = feet.len() as f64;
    let centre = [
        feet.iter().map(|f| f[0]).sum::<f64>() / n,
        feet.iter().map(|f| f[1]).sum::<f64>() / n,
    ];
    let index = FootIndex::new(&feet, 0.05);
    let noise = Normal::new(0.0, sigma.max(0.0)).unwrap_or(Normal::new(0.0, 0.0).unwrap());
    let cells = (2.0 * radius / step).ceil() as usize + 1;
    let mut positions = Vec::new();
    let mut at = vec![None; cells * cells];
    for r in 0..cells {
        for c in 0..cells {
            let (x, z) = (
                centre[0] - radius + c as f64 * step,
                centre[1] - radius + r as f64 * step,
            );
            let inside = (x - centre[0]).powi(2) + (z - centre[1]).powi(2) <= radius * radius;
            if inside && index.distance(x, z) > UNDER_SOLE {
                at[r * cells + c] = Some(positions.len() as u32);
                positions.push(Point3::new(x, noise.sample(rng), z));
            }
        }
    }
    let mut triangles = grid_triangles(cells, cells, &at);
    // The rim: a band of `rows` × `around` points on the disc's edge, facing out.
    let around = (2.0 * std::f64::consts::PI * radius / step).ceil() as usize;
    let rows = (rim / step).ceil() as usize + 1;
    let first = positions.len() as u32;
    for r in 0..rows {
        let y = -(r as f64) * step;
        for k in 0..around {
            let a = 2.0 * std::f64::consts::PI * k as f64 / around as f64;
            let e = radius + noise.sample(rng);
            positions.push(Point3::new(
                centre[0] + e * a.cos(),
                y,
                centre[1] + e * a.sin(),
            ));
        }
    }
    let id = |r: usize, k: usize| first + (r * around + k % around) as u32;
    for r in 0..rows.saturating_sub(1) {
        for k in 0..around {
            triangles.push([id(r, k), id(r, k + 1), id(r + 1, k + 1)]);
            triangles.push([id(r, k), id(r + 1, k + 1), id(r + 1, k)]);
        }
    }
    append(scan, &positions, &triangles);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Mesh;
    use crate::synth::zoo::edit::NOT_BODY;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    /// Two "feet": 3 × 10 cm patches of points 5 mm above the floor.
    fn two_feet() -> Scan {
        let mut positions = Vec::new();
        for x0 in [-0.1, 0.1] {
            for i in 0..6 {
                for k in 0..20 {
                    positions.push(Point3::new(x0 + i as f64 * 0.005, 0.005, k as f64 * 0.005));
                }
            }
        }
        Scan {
            mesh: Mesh::new(positions.clone(), Vec::new()),
            clean: positions.clone(),
            head: vec![0; positions.len()],
        }
    }

    #[test]
    fn floor_patches_surround_the_feet_and_stay_on_the_floor() {
        let mut s = two_feet();
        let body = s.mesh.positions.len();
        add_floor(&mut s, 0.05, 0.005, 0.0, &mut ChaCha8Rng::seed_from_u64(3));
        assert!(s.mesh.positions.len() > body + 100);
        assert!(!s.mesh.triangles.is_empty());
        for (p, h) in s.mesh.positions[body..].iter().zip(&s.head[body..]) {
            assert_eq!(*h, NOT_BODY);
            assert_eq!(p.y, 0.0);
            assert!(p.x.abs() < 0.2 && p.z > -0.06 && p.z < 0.16, "{p}");
        }
    }

    #[test]
    fn a_turntable_is_a_disc_with_a_rim_below() {
        let mut s = two_feet();
        let body = s.mesh.positions.len();
        add_turntable(
            &mut s,
            0.4,
            0.03,
            0.01,
            0.0,
            &mut ChaCha8Rng::seed_from_u64(3),
        );
        let added = &s.mesh.positions[body..];
        assert!(added.len() > 4000, "{}", added.len());
        assert!(added.iter().all(|p| p.y <= 0.0 && p.y >= -0.031));
        assert!(added.iter().any(|p| p.y < -0.02));
    }
}
