//! Tight clothing: a thin layer shrink-wrapped over the body — it bridges the concavities the skin
//! dips into (between the buttocks, under the bust, the navel, the crotch's fold) and lies
//! `thickness` over the rest; the scanner sees the layer.
//!
//! The layer is the skin moved out along its smoothed normals, `x_i = p_i + d_i·n_i` (the vertex
//! normals averaged over the one-ring `normal_smoothing` times and normalised: the cloth's
//! direction at the scale of the hollows, so the walls of a cleft move out of it, not across
//! it), with `d_i` the fixed point of a taut membrane held out of the body: Gauss–Seidel sweeps of
//!
//! `d_i ← c_i · clamp((x̄_i − p_i)·n_i, t, d_max)`, `x̄_i` the mean of `x_j` over the one-ring,
//!
//! from `d = 0` (`c_i` ∈ [0, 1] how much vertex `i` is covered, `t` the thickness, `d_max` the
//! deepest bridge). Where the skin is convex the neighbours' mean lies inside it and the layer
//! stays at `t`; over a concavity it lies outside, and the membrane spans it as taut cloth does
//! (the mean of the neighbours is the discrete Laplacian's fixed point: a minimal surface over the
//! hollow). The sweeps stop when no `d_i` changes by more than [`TOLERANCE`] or after
//! `sweeps`.

use nalgebra::{Point3, Vector3};

use crate::mesh::normals::vertex_normals;
use crate::mesh::topology::vertex_neighbours;
use crate::mesh::Mesh;

/// The membrane's sweeps stop when no lift changes by more than this (m).
pub const TOLERANCE: f64 = 1e-7;

/// Settings of [`shrink_wrap`] (defaults in `ZooParams`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ClothingParams {
    /// The layer's thickness over convex skin, drawn per subject (m).
    pub thickness: (f64, f64),
    /// The deepest hollow the membrane bridges (m).
    pub max_bridge: f64,
    /// At most this many Gauss–Seidel sweeps.
    pub sweeps: usize,
    /// Rounds of one-ring averaging of the normals the layer moves along.
    pub normal_smoothing: usize,
    /// The legs' hem: the cover fades in over this height above the higher lateral malleolus
    /// (m).
    pub hem_above_ankle: f64,
}

/// Per vertex of `surface` (positions `p`, one-rings `rings`, smoothed normals `n`), how far the
/// layer lies out along `n` (m; see the module documentation); `cover[i]` ∈ [0, 1] how much
/// vertex `i` is clothed.
fn layer_lift(
    p: &[Point3<f64>],
    rings: &[Vec<u32>],
    n: &[Vector3<f64>],
    cover: &[f64],
    thickness: f64,
    params: &ClothingParams,
) -> Vec<f64> {
    let mut d = vec![0.0; p.len()];
    for _ in 0..params.sweeps {
        let mut change: f64 = 0.0;
        for i in 0..p.len() {
            if cover[i] <= 0.0 || rings[i].is_empty() {
                continue;
            }
            let mean = rings[i]
                .iter()
                .map(|&j| p[j as usize].coords + n[j as usize] * d[j as usize])
                .sum::<Vector3<f64>>()
                / rings[i].len() as f64;
            let lift = (mean - p[i].coords).dot(&n[i]);
            let new = cover[i] * lift.clamp(thickness, params.max_bridge.max(thickness));
            change = change.max((new - d[i]).abs());
            d[i] = new;
        }
        if change <= TOLERANCE {
            break;
        }
    }
    d
}

/// The vertex normals of `surface` averaged over the one-ring (`rings`) `rounds` times, unit.
pub fn smoothed_normals(surface: &Mesh, rings: &[Vec<u32>], rounds: usize) -> Vec<Vector3<f64>> {
    let mut n = vertex_normals(&surface.positions, &surface.triangles);
    for _ in 0..rounds {
        n = (0..n.len())
            .map(|i| {
                let sum = rings[i].iter().fold(n[i], |acc, &j| acc + n[j as usize]);
                sum.try_normalize(1e-12).unwrap_or(n[i])
            })
            .collect();
    }
    n
}

/// `surface` clothed (`cover[i]` ∈ [0, 1] how much vertex `i` is, `thickness` in metres): every
/// vertex moved out along its smoothed normal by the membrane's lift.
pub fn shrink_wrap(surface: &Mesh, cover: &[f64], thickness: f64, params: &ClothingParams) -> Mesh {
    let p = &surface.positions;
    let rings = vertex_neighbours(p.len(), &surface.triangles);
    let n = smoothed_normals(surface, &rings, params.normal_smoothing);
    let lift = layer_lift(p, &rings, &n, cover, thickness, params);
    let positions: Vec<Point3<f64>> = p
        .iter()
        .zip(n.iter().zip(&lift))
        .map(|(p, (n, d))| p + n * *d)
        .collect();
    Mesh::new(positions, surface.triangles.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square sheet facing +z, 1 cm grid, 40 × 40 cells, with a groove along y at x = 0.2 m
    /// (2 cm wide, 1.5 cm deep) and a round dent (the navel: 1.5 cm across, 1 cm deep) at
    /// (0.3, 0.3).
    fn sheet() -> Mesh {
        let n = 41;
        let mut positions = Vec::new();
        for i in 0..n {
            for j in 0..n {
                let (x, y) = (i as f64 * 0.01, j as f64 * 0.01);
                let groove = if (x - 0.2).abs() < 0.011 { 0.015 } else { 0.0 };
                let dent = if ((x - 0.3).powi(2) + (y - 0.3).powi(2)).sqrt() < 0.0075 {
                    0.01
                } else {
                    0.0
                };
                positions.push(Point3::new(x, y, -groove - dent));
            }
        }
        let mut triangles = Vec::new();
        for i in 0..n as u32 - 1 {
            for j in 0..n as u32 - 1 {
                let a = i * n as u32 + j;
                let (b, c, d) = (a + n as u32, a + n as u32 + 1, a + 1);
                triangles.push([a, b, c]);
                triangles.push([a, c, d]);
            }
        }
        Mesh::new(positions, triangles)
    }

    #[test]
    fn the_layer_bridges_a_groove_and_a_dent_and_lies_thin_elsewhere() {
        let s = sheet();
        let params = ClothingParams {
            thickness: (0.002, 0.002),
            max_bridge: 0.05,
            sweeps: 2000,
            normal_smoothing: 10,
            hem_above_ankle: 0.03,
        };
        // The sheet's rim is not clothed (it holds the membrane like a frame).
        let cover: Vec<f64> = s
            .positions
            .iter()
            .map(|p| {
                let inner = p.x > 0.005 && p.x < 0.395 && p.y > 0.005 && p.y < 0.395;
                if inner {
                    1.0
                } else {
                    0.0
                }
            })
            .collect();
        let wrapped = shrink_wrap(&s, &cover, 0.002, &params);
        let z_at = |x: f64, y: f64| {
            let v = (x / 0.01).round() as usize * 41 + (y / 0.01).round() as usize;
            (s.positions[v].z, wrapped.positions[v].z)
        };
        // Flat skin: the layer is the thickness out (the smoothed normals are +z there).
        let (skin, layer) = z_at(0.1, 0.1);
        assert!((layer - skin - 0.002).abs() < 1e-4, "{skin} {layer}");
        // The groove's floor and the navel are bridged: the layer lies within 3 mm of the
        // surrounding skin's level (the skin is 15 and 10 mm below it).
        for (x, y) in [(0.2, 0.2), (0.2, 0.1), (0.3, 0.3)] {
            let (skin, layer) = z_at(x, y);
            assert!(skin < -0.009, "{skin}");
            assert!(layer > -0.003, "at ({x}, {y}) the layer is at {layer}");
        }
        // Never inside the skin, never further out than the bridge.
        for (a, b) in s.positions.iter().zip(&wrapped.positions) {
            assert!(b.z >= a.z - 1e-12 && b.z - a.z <= 0.05 + 1e-12);
        }
    }
}
