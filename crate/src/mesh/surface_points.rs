//! Points spread over a mesh's surface: its triangles sampled on barycentric grids, everywhere
//! ([`surface_samples`]) or near a point ([`surface_near`], [`SurfaceWindows`] for several
//! points on one mesh). A coarse mesh's vertices lie too far
//! apart for a profile's bins or a prominence's cap; its surface does not.

use nalgebra::Point3;

/// Points spread over the triangles of a mesh (`positions`, `triangles`) about `spacing` (m)
/// apart: on each triangle a barycentric grid with as many steps per edge as its longest edge
/// holds `spacing`. A coarse template's vertices lie in rings too far apart for a profile's bins
/// (and more densely where the mesh is finer); its surface does not.
pub fn surface_samples(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    spacing: f64,
) -> Vec<Point3<f64>> {
    let mut out = Vec::new();
    for t in triangles {
        let [a, b, c] = corners(positions, t);
        let longest = (b - a).norm().max((c - b).norm()).max((a - c).norm());
        let n = ((longest / spacing).ceil() as usize).clamp(1, 64);
        for i in 0..n {
            for j in 0..n - i {
                // Grid cell centres (a third of a step in), so shared edges are not counted twice.
                let u = (i as f64 + 1.0 / 3.0) / n as f64;
                let v = (j as f64 + 1.0 / 3.0) / n as f64;
                out.push(a + (b - a) * u + (c - a) * v);
            }
        }
    }
    out
}

/// Points spread `spacing` apart over the triangles of a mesh (`positions`, `triangles`) that
/// lie within `radius` of `centre` (barycentric grids, as [`surface_samples`]).
pub fn surface_near(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    centre: &Point3<f64>,
    radius: f64,
    spacing: f64,
) -> Vec<Point3<f64>> {
    SurfaceWindows::new(positions, triangles).near(centre, radius, spacing)
}

/// A mesh whose surface is sampled in several windows ([`surface_near`] around several
/// centres), each triangle's longest edge measured once for all of them.
pub struct SurfaceWindows<'a> {
    positions: &'a [Point3<f64>],
    triangles: &'a [[u32; 3]],
    /// Per triangle, its longest edge (m).
    longest: Vec<f64>,
}

impl<'a> SurfaceWindows<'a> {
    pub fn new(positions: &'a [Point3<f64>], triangles: &'a [[u32; 3]]) -> Self {
        let longest = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = corners(positions, t);
                (b - a).norm().max((c - b).norm()).max((a - c).norm())
            })
            .collect();
        SurfaceWindows {
            positions,
            triangles,
            longest,
        }
    }

    /// [`surface_near`]: the points `spacing` apart over the triangles within `radius` of
    /// `centre` (those with a corner within `radius` plus their longest edge of it, sampled, then
    /// the samples within `radius` kept).
    pub fn near(&self, centre: &Point3<f64>, radius: f64, spacing: f64) -> Vec<Point3<f64>> {
        let r2 = radius * radius;
        let near: Vec<[u32; 3]> = self
            .triangles
            .iter()
            .zip(&self.longest)
            .filter(|(t, &longest)| {
                corners(self.positions, t)
                    .iter()
                    .any(|p| (p - centre).norm() <= radius + longest)
            })
            .map(|(t, _)| *t)
            .collect();
        surface_samples(self.positions, &near, spacing)
            .into_iter()
            .filter(|p| (p - centre).norm_squared() <= r2)
            .collect()
    }
}

/// The corners of triangle `t` (written out: an array's `map` is not always inlined, and this
/// runs per triangle).
fn corners(positions: &[Point3<f64>], t: &[u32; 3]) -> [Point3<f64>; 3] {
    [
        positions[t[0] as usize],
        positions[t[1] as usize],
        positions[t[2] as usize],
    ]
}
