//! Points spread over a mesh's surface: its triangles sampled on barycentric grids, everywhere
//! ([`surface_samples`]) or near a point ([`surface_near`], [`SurfaceWindows`] for several
//! points on one mesh). A coarse mesh's vertices lie too far
//! apart for a profile's bins or a prominence's cap; its surface does not.

use nalgebra::Point3;

/// A point on a surface and the area it stands for (m²; any one constant where the points are
/// spread evenly).
pub type SurfacePoint = (Point3<f64>, f64);

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
        let c = corners(positions, t);
        grid(&c, steps(longest_edge(&c), spacing), &mut out);
    }
    out
}

/// Per triangle of a mesh, the steps per edge of its grid `spacing` apart ([`surface_samples`]):
/// laid once on one mesh (a template at rest) and held on the meshes of the same triangles
/// ([`SurfaceWindows::held`]), the points move with the surface instead of being laid anew where
/// an edge's length crosses a multiple of `spacing`.
pub fn grid_steps(positions: &[Point3<f64>], triangles: &[[u32; 3]], spacing: f64) -> Vec<u32> {
    triangles
        .iter()
        .map(|t| steps(longest_edge(&corners(positions, t)), spacing))
        .collect()
}

/// As many steps as the longest edge holds `spacing`, 1 to 64.
fn steps(longest: f64, spacing: f64) -> u32 {
    ((longest / spacing).ceil() as u32).clamp(1, 64)
}

fn longest_edge([a, b, c]: &[Point3<f64>; 3]) -> f64 {
    (b - a).norm().max((c - b).norm()).max((a - c).norm())
}

/// The barycentric grid of `n` steps per edge on triangle `[a, b, c]`, appended to `out`: the
/// grid cells' centres (a third of a step in), so shared edges are not counted twice.
fn grid([a, b, c]: &[Point3<f64>; 3], n: u32, out: &mut Vec<Point3<f64>>) {
    let n = n as usize;
    for i in 0..n {
        for j in 0..n - i {
            let u = (i as f64 + 1.0 / 3.0) / n as f64;
            let v = (j as f64 + 1.0 / 3.0) / n as f64;
            out.push(a + (b - a) * u + (c - a) * v);
        }
    }
}

/// One of `points` per cube of side `cell` (m) in a grid from the origin, the first in it: the
/// points of a dense mesh's [`surface_samples`] (one per triangle at least) no denser than
/// `cell` apart, in their order.
pub fn thinned<'a>(
    points: impl IntoIterator<Item = &'a Point3<f64>>,
    cell: f64,
) -> Vec<Point3<f64>> {
    let mut seen = std::collections::HashSet::new();
    points
        .into_iter()
        .filter(|p| seen.insert((p.coords / cell).map(|c| c.floor() as i64)))
        .copied()
        .collect()
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
/// centres), each triangle's longest edge measured once for all of them; its grids laid for the
/// spacing asked, or held ([`SurfaceWindows::held`]).
pub struct SurfaceWindows<'a> {
    positions: &'a [Point3<f64>],
    triangles: &'a [[u32; 3]],
    /// Per triangle, its longest edge (m).
    longest: Vec<f64>,
    /// Per triangle, its grid's steps per edge, where they are held ([`grid_steps`]).
    steps: Option<&'a [u32]>,
}

impl<'a> SurfaceWindows<'a> {
    pub fn new(positions: &'a [Point3<f64>], triangles: &'a [[u32; 3]]) -> Self {
        let longest = triangles
            .iter()
            .map(|t| longest_edge(&corners(positions, t)))
            .collect();
        SurfaceWindows {
            positions,
            triangles,
            longest,
            steps: None,
        }
    }

    /// The windows with each triangle's grid held at `steps` (one per triangle, [`grid_steps`]
    /// on another mesh of the same triangles): `near`'s spacing is then not used.
    pub fn held(positions: &'a [Point3<f64>], triangles: &'a [[u32; 3]], steps: &'a [u32]) -> Self {
        assert_eq!(steps.len(), triangles.len(), "one grid per triangle");
        SurfaceWindows {
            steps: Some(steps),
            ..SurfaceWindows::new(positions, triangles)
        }
    }

    /// [`surface_near`]: the points `spacing` apart (or on the held grids) over the triangles
    /// within `radius` of `centre` (those with a corner within `radius` plus their longest edge
    /// of it, sampled, then the samples within `radius` kept).
    pub fn near(&self, centre: &Point3<f64>, radius: f64, spacing: f64) -> Vec<Point3<f64>> {
        let mut out = Vec::new();
        self.each_grid(centre, radius, spacing, |_, _, kept| {
            out.extend_from_slice(kept)
        });
        out
    }

    /// [`SurfaceWindows::near`], each point with the area it stands for (its triangle's area
    /// over its grid's points): a sum over the points weighted so is an integral over the
    /// surface, however the grids' density varies from triangle to triangle.
    pub fn near_with_areas(
        &self,
        centre: &Point3<f64>,
        radius: f64,
        spacing: f64,
    ) -> Vec<SurfacePoint> {
        let mut out = Vec::new();
        self.each_grid(centre, radius, spacing, |c, all, kept| {
            let area = 0.5 * (c[1] - c[0]).cross(&(c[2] - c[0])).norm() / all as f64;
            out.extend(kept.iter().map(|p| (*p, area)));
        });
        out
    }

    /// For each triangle that may reach within `radius` of `centre`, `visit(corners, points on
    /// its grid, those of them within radius)`.
    fn each_grid(
        &self,
        centre: &Point3<f64>,
        radius: f64,
        spacing: f64,
        mut visit: impl FnMut(&[Point3<f64>; 3], usize, &[Point3<f64>]),
    ) {
        let r2 = radius * radius;
        let mut points = Vec::new();
        for (k, (t, &longest)) in self.triangles.iter().zip(&self.longest).enumerate() {
            let c = corners(self.positions, t);
            if c.iter().all(|p| (p - centre).norm() > radius + longest) {
                continue;
            }
            let n = self.steps.map_or_else(|| steps(longest, spacing), |s| s[k]);
            points.clear();
            grid(&c, n, &mut points);
            let all = points.len();
            points.retain(|p| (p - centre).norm_squared() <= r2);
            visit(&c, all, &points);
        }
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

#[cfg(test)]
mod tests {

    #[test]
    fn thinning_keeps_one_point_per_cell() {
        let points: Vec<Point3<f64>> = (0..100)
            .map(|i| Point3::new(i as f64 * 0.001, 0.0005, 0.0005))
            .collect();
        let kept = thinned(&points, 0.01);
        assert_eq!(kept.len(), 10);
        assert_eq!(kept[1], points[10]);
    }
    use super::*;

    /// A flat square `size` m across in the z = 0 plane, `n` × `n` cells each cut in two.
    fn square(size: f64, n: u32) -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
        let step = size / n as f64;
        let mut positions = Vec::new();
        for i in 0..=n {
            for j in 0..=n {
                positions.push(Point3::new(
                    i as f64 * step - size / 2.0,
                    j as f64 * step - size / 2.0,
                    0.0,
                ));
            }
        }
        let at = |i: u32, j: u32| i * (n + 1) + j;
        let mut triangles = Vec::new();
        for i in 0..n {
            for j in 0..n {
                triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
        (positions, triangles)
    }

    #[test]
    fn the_points_areas_add_up_to_the_windows_area() {
        let (positions, triangles) = square(0.2, 17);
        let windows = SurfaceWindows::new(&positions, &triangles);
        let r = 0.05;
        let near = windows.near_with_areas(&Point3::origin(), r, 0.003);
        let area: f64 = near.iter().map(|(_, a)| a).sum();
        let disc = std::f64::consts::PI * r * r;
        assert!((area / disc - 1.0).abs() < 0.02, "{area} vs {disc}");
        // The same points as `near`.
        assert_eq!(near.len(), windows.near(&Point3::origin(), r, 0.003).len());
    }

    #[test]
    fn held_grids_move_with_the_surface_where_grids_laid_anew_change() {
        let (rest, triangles) = square(0.2, 17);
        let steps = grid_steps(&rest, &triangles, 0.003);
        // Stretched 40 % across: every edge longer, the grids laid anew finer.
        let stretched: Vec<_> = rest
            .iter()
            .map(|p| Point3::new(1.4 * p.x, p.y, p.z))
            .collect();
        let everything = |w: &SurfaceWindows| w.near_with_areas(&Point3::origin(), 1.0, 0.003);
        let at_rest = everything(&SurfaceWindows::new(&rest, &triangles));
        let held = everything(&SurfaceWindows::held(&stretched, &triangles, &steps));
        let anew = everything(&SurfaceWindows::new(&stretched, &triangles));
        assert_eq!(held.len(), at_rest.len());
        assert!(anew.len() > held.len());
        // The held points are the rest's, stretched; each stands for 1.4 times the area.
        for ((p, a), (q, b)) in held.iter().zip(&at_rest) {
            assert!((p.x - 1.4 * q.x).abs() < 1e-12 && (p.y - q.y).abs() < 1e-12);
            assert!((a / b - 1.4).abs() < 1e-9);
        }
        let total = |points: &[SurfacePoint]| points.iter().map(|(_, a)| a).sum::<f64>();
        assert!((total(&held) - total(&anew)).abs() < 1e-12);
    }
}
