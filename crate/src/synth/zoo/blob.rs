//! A photogrammetry-like scan: a closed, smooth surface with low-frequency bumps and noise, with
//! its own triangulation (not the body mesh's, not a scanner's grid).
//!
//! 1. The body's surface is rasterised into a grid of corners `voxel` (m) apart: every corner
//!    within half a voxel of a surface sample (each triangle sampled every half voxel) is *shell*;
//!    the outside is flood-filled (6-neighbours) from the grid's corner; occupancy is 1 inside,
//!    ½ on the shell, 0 outside.
//! 2. The occupancy is blurred by a separable Gaussian of `blur` voxels (standard deviation):
//!    fingers fuse, the armpits and the crotch web over a little, as a reconstruction smooths.
//! 3. Its ½ level set is extracted by marching tetrahedra (each cube split into six tetrahedra
//!    along its main diagonal), vertices shared along grid edges, triangles facing out: a closed
//!    surface.
//! 4. Each vertex moves along its normal by `Σ_k a_k·exp(−|p − c_k|² / (2 r_k²))` (`bumps`
//!    centres `c_k` on the surface, `r_k` uniform in `bump_radius`, `a_k` uniform in
//!    ±`bump_height`) plus Gaussian noise `sigma`.

use std::collections::HashMap;

use nalgebra::{Point3, Vector3};
use rand::Rng;
use rand_distr::{Distribution, Normal};

use crate::mesh::normals::vertex_normals;
use crate::mesh::{bounding_box, Mesh};
use crate::synth::scanner::Scan;

/// Settings of [`blob_scan`] (defaults in `ZooParams`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct BlobParams {
    pub voxel: f64,
    pub blur: f64,
    pub bumps: usize,
    pub bump_radius: (f64, f64),
    pub bump_height: f64,
    pub sigma: f64,
}

/// The photogrammetry-like scan of `surface` (outward triangles, metres).
pub fn blob_scan<R: Rng>(surface: &Mesh, params: &BlobParams, rng: &mut R) -> Scan {
    let Some(grid) = Grid::rasterise(surface, params.voxel, params.blur) else {
        return Scan::default();
    };
    let mut field = grid.occupancy();
    grid.blur(&mut field, params.blur);
    let mesh = grid.march(&field, 0.5);
    let clean = mesh.positions.clone();
    let normals = vertex_normals(&mesh.positions, &mesh.triangles);
    let n = mesh.positions.len();
    if n == 0 {
        return Scan::default();
    }
    let bumps: Vec<(Point3<f64>, f64, f64)> = (0..params.bumps)
        .map(|_| {
            let c = mesh.positions[rng.gen_range(0..n)];
            let r = rng.gen_range(params.bump_radius.0..=params.bump_radius.1);
            let a = rng.gen_range(-params.bump_height..=params.bump_height);
            (c, r, a)
        })
        .collect();
    let noise = Normal::new(0.0, params.sigma.max(0.0)).unwrap_or(Normal::new(0.0, 0.0).unwrap());
    let positions = mesh
        .positions
        .iter()
        .zip(&normals)
        .map(|(p, nrm)| {
            let bump: f64 = bumps
                .iter()
                .map(|(c, r, a)| a * (-(p - c).norm_squared() / (2.0 * r * r)).exp())
                .sum();
            p + nrm * (bump + noise.sample(rng))
        })
        .collect();
    Scan {
        mesh: Mesh::new(positions, mesh.triangles),
        clean,
        head: vec![0; n],
    }
}

/// A grid of corners `h` apart from `origin`, `dims` corners per axis.
struct Grid {
    origin: Vector3<f64>,
    h: f64,
    dims: [usize; 3],
    /// 0 outside, 1 shell, 2 inside.
    state: Vec<u8>,
}

impl Grid {
    fn index(&self, i: usize, j: usize, k: usize) -> usize {
        i + self.dims[0] * (j + self.dims[1] * k)
    }

    fn rasterise(surface: &Mesh, h: f64, blur: f64) -> Option<Grid> {
        let (lo, hi) = bounding_box(&surface.positions)?;
        if h <= 0.0 {
            return None;
        }
        let pad = h * (3.0 + 3.0 * blur);
        let origin = lo.coords.add_scalar(-pad);
        let size = hi.coords.add_scalar(pad) - origin;
        let dims = [0, 1, 2].map(|a| (size[a] / h).ceil() as usize + 1);
        let mut grid = Grid {
            origin,
            h,
            dims,
            state: vec![0; dims[0] * dims[1] * dims[2]],
        };
        let p = &surface.positions;
        for t in &surface.triangles {
            let [a, b, c] = t.map(|v| p[v as usize]);
            let longest = (b - a).norm().max((c - b).norm()).max((a - c).norm());
            let n = (longest / (0.5 * h)).ceil().max(1.0) as usize;
            for u in 0..=n {
                for v in 0..=n - u {
                    let (fu, fv) = (u as f64 / n as f64, v as f64 / n as f64);
                    let q = a + (b - a) * fu + (c - a) * fv;
                    let g = (q.coords - origin) / h;
                    let at = [0, 1, 2].map(|k| g[k].round() as usize);
                    let i = grid.index(at[0], at[1], at[2]);
                    grid.state[i] = 1;
                }
            }
        }
        // Flood the outside from corner (0, 0, 0); what it does not reach is inside.
        let mut outside = vec![false; grid.state.len()];
        let mut stack = vec![0usize];
        outside[0] = true;
        let [nx, ny, nz] = dims;
        while let Some(i) = stack.pop() {
            let (x, y, z) = (i % nx, (i / nx) % ny, i / (nx * ny));
            let mut push = |x: usize, y: usize, z: usize| {
                let j = x + nx * (y + ny * z);
                if !outside[j] && grid.state[j] == 0 {
                    outside[j] = true;
                    stack.push(j);
                }
            };
            if x > 0 {
                push(x - 1, y, z);
            }
            if x + 1 < nx {
                push(x + 1, y, z);
            }
            if y > 0 {
                push(x, y - 1, z);
            }
            if y + 1 < ny {
                push(x, y + 1, z);
            }
            if z > 0 {
                push(x, y, z - 1);
            }
            if z + 1 < nz {
                push(x, y, z + 1);
            }
        }
        for (s, out) in grid.state.iter_mut().zip(&outside) {
            if *s == 0 && !out {
                *s = 2;
            }
        }
        Some(grid)
    }

    fn occupancy(&self) -> Vec<f32> {
        self.state.iter().map(|&s| s as f32 / 2.0).collect()
    }

    /// Separable Gaussian blur of `field`, standard deviation `sigma` voxels (radius 2σ).
    fn blur(&self, field: &mut [f32], sigma: f64) {
        if sigma <= 0.0 {
            return;
        }
        let radius = (2.0 * sigma).ceil() as isize;
        let kernel: Vec<f32> = (-radius..=radius)
            .map(|d| (-(d * d) as f64 / (2.0 * sigma * sigma)).exp() as f32)
            .collect();
        let total: f32 = kernel.iter().sum();
        let kernel: Vec<f32> = kernel.iter().map(|w| w / total).collect();
        let [nx, ny, nz] = self.dims;
        let strides = [1, nx, nx * ny];
        let mut line = Vec::new();
        for axis in 0..3 {
            let len = self.dims[axis];
            let stride = strides[axis];
            for start in 0..field.len() {
                let (x, y, z) = (start % nx, (start / nx) % ny, start / (nx * ny));
                if [x, y, z][axis] != 0 {
                    continue;
                }
                line.clear();
                line.extend((0..len).map(|s| field[start + s * stride]));
                for s in 0..len {
                    let mut acc = 0.0;
                    for (w, d) in kernel.iter().zip(-radius..=radius) {
                        let t = (s as isize + d).clamp(0, len as isize - 1) as usize;
                        acc += w * line[t];
                    }
                    field[start + s * stride] = acc;
                }
            }
            let _ = nz;
        }
    }

    /// The `level` set of `field` by marching tetrahedra, triangles facing from above `level`
    /// (inside) to below.
    fn march(&self, field: &[f32], level: f32) -> Mesh {
        // Kuhn's six tetrahedra of a cube (corner bits x = 1, y = 2, z = 4), all on 0 → 7.
        const TETS: [[usize; 4]; 6] = [
            [0, 1, 3, 7],
            [0, 1, 5, 7],
            [0, 2, 3, 7],
            [0, 2, 6, 7],
            [0, 4, 5, 7],
            [0, 4, 6, 7],
        ];
        let [nx, ny, nz] = self.dims;
        let mut vertex_of: HashMap<(usize, usize), u32> = HashMap::new();
        let mut positions: Vec<Point3<f64>> = Vec::new();
        let mut triangles = Vec::new();
        let corner_point = |i: usize| {
            let (x, y, z) = (i % nx, (i / nx) % ny, i / (nx * ny));
            Point3::from(self.origin + Vector3::new(x as f64, y as f64, z as f64) * self.h)
        };
        for z in 0..nz - 1 {
            for y in 0..ny - 1 {
                for x in 0..nx - 1 {
                    let corners: [usize; 8] = std::array::from_fn(|b| {
                        self.index(x + (b & 1), y + ((b >> 1) & 1), z + ((b >> 2) & 1))
                    });
                    let above = corners.iter().filter(|&&c| field[c] > level).count();
                    if above == 0 || above == 8 {
                        continue;
                    }
                    for tet in TETS {
                        let c = tet.map(|b| corners[b]);
                        let (inn, out): (Vec<usize>, Vec<usize>) =
                            c.iter().partition(|&&i| field[i] > level);
                        if inn.is_empty() || out.is_empty() {
                            continue;
                        }
                        let mut on_edge = |a: usize, b: usize| -> u32 {
                            let key = (a.min(b), a.max(b));
                            *vertex_of.entry(key).or_insert_with(|| {
                                let (fa, fb) = (field[a] as f64, field[b] as f64);
                                let t = ((level as f64 - fa) / (fb - fa)).clamp(0.0, 1.0);
                                let (pa, pb) = (corner_point(a), corner_point(b));
                                positions.push(pa + (pb - pa) * t);
                                positions.len() as u32 - 1
                            })
                        };
                        let tris: Vec<[u32; 3]> = match (inn.len(), out.len()) {
                            (1, 3) => vec![[
                                on_edge(inn[0], out[0]),
                                on_edge(inn[0], out[1]),
                                on_edge(inn[0], out[2]),
                            ]],
                            (3, 1) => vec![[
                                on_edge(out[0], inn[0]),
                                on_edge(out[0], inn[1]),
                                on_edge(out[0], inn[2]),
                            ]],
                            _ => {
                                let (ac, ad) = (on_edge(inn[0], out[0]), on_edge(inn[0], out[1]));
                                let (bd, bc) = (on_edge(inn[1], out[1]), on_edge(inn[1], out[0]));
                                vec![[ac, ad, bd], [ac, bd, bc]]
                            }
                        };
                        let centroid = |s: &[usize]| {
                            s.iter()
                                .map(|&i| corner_point(i).coords)
                                .sum::<Vector3<f64>>()
                                / s.len() as f64
                        };
                        let outward = centroid(&out) - centroid(&inn);
                        for t in tris {
                            let [a, b, cc] = t.map(|v| positions[v as usize]);
                            if (b - a).cross(&(cc - a)).dot(&outward) >= 0.0 {
                                triangles.push(t);
                            } else {
                                triangles.push([t[0], t[2], t[1]]);
                            }
                        }
                    }
                }
            }
        }
        // Triangles that collapsed to a segment (a level set through a corner) are dropped.
        triangles.retain(|t: &[u32; 3]| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
        Mesh::new(positions, triangles)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::topology::{boundary_edges, components};
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn a_cube_becomes_one_closed_rounded_outward_surface() {
        let params = BlobParams {
            voxel: 0.01,
            blur: 1.0,
            bumps: 0,
            bump_radius: (0.05, 0.1),
            bump_height: 0.0,
            sigma: 0.0,
        };
        let cube = crate::mesh::topology::tests::cube().scaled(0.3);
        let s = blob_scan(&cube, &params, &mut ChaCha8Rng::seed_from_u64(1));
        let m = &s.mesh;
        assert!(m.positions.len() > 2000, "{}", m.positions.len());
        assert_eq!(components(m), 1);
        assert!(boundary_edges(m.positions.len(), &m.triangles).is_empty());
        // Near the cube's faces (within 1.5 voxels), and facing out (positive signed volume).
        let centre = Point3::new(0.15, 0.15, 0.15);
        for p in &m.positions {
            let d = (p - centre).abs().max();
            assert!((d - 0.15).abs() < 0.015, "{p}: {d}");
        }
        let volume: f64 = m
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|v| m.positions[v as usize].coords);
                a.dot(&b.cross(&c)) / 6.0
            })
            .sum();
        assert!((volume - 0.027).abs() < 0.004, "{volume}");
    }
}
