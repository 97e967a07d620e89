//! A virtual whole-body scanner in the manner of CAESAR's Cyberware WB4: range images from several
//! heads around the subject, grazing samples dropped, views merged into one triangulated mesh
//! with noise along the rays.
//!
//! Geometry (template frame, metres, y up): head `k` sits on a vertical line at distance
//! `head_distance` from the subject's vertical axis, at azimuth `φ_k = first_azimuth + k·360°/heads`
//! (0° = in front of the subject, +z). It sweeps that line in steps of `vertical_step`; at each
//! height it casts a horizontal fan of rays whose angular step gives `horizontal_step` at the
//! subject's axis. Range image `k` is a grid `rows × cols` of first hits.
//!
//! Per sample: dropped when the angle between ray and surface normal exceeds `max_grazing_deg`.
//! Merging: a surface point seen by several heads is kept only in the view that faces it best
//! (largest `|cos|` between ray and normal; ties to the lower head index), found by projecting
//! the point into every other range image and checking that image sees the same point there.
//! Each view's kept samples are triangulated as a grid (a cell's corners are connected when
//! their 3D distance is below `max_edge_steps` sampling steps), so the merged mesh has its own
//! triangulation with holes where no head looked (armpits, crotch, top of head, soles, between
//! fingers) and narrow cracks along the seams between views. Finally every kept point moves along
//! its ray by Gaussian noise `N(0, noise_sigma²)`.

use nalgebra::{Point3, Vector3};
use rand::Rng;
use rand_distr::{Distribution, Normal};

use crate::mesh::bvh::TriangleBvh;
use crate::mesh::normals::face_normals;
use crate::mesh::{bounding_box, Mesh};

/// Settings of the virtual scanner.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ScannerParams {
    /// Number of scan heads around the subject (CAESAR's WB4: 4).
    pub heads: usize,
    /// Azimuth of the first head, degrees from the subject's front (+z) towards its left (+x).
    pub first_azimuth_deg: f64,
    /// Horizontal distance of each head's sweep line from the subject's vertical axis (m).
    pub head_distance: f64,
    /// Vertical sampling step (m).
    pub vertical_step: f64,
    /// Horizontal sampling step at the subject's axis (m).
    pub horizontal_step: f64,
    /// Samples whose ray meets the surface at more than this angle from its normal are dropped.
    pub max_grazing_deg: f64,
    /// Standard deviation of the range noise along the ray (m).
    pub noise_sigma: f64,
    /// Grid neighbours are connected when closer than this many sampling steps.
    pub max_edge_steps: f64,
}

impl Default for ScannerParams {
    /// Four heads on the diagonals (two in front, two behind), 1.2 m away, 3 mm sampling,
    /// 75° grazing limit, 1 mm noise: CAESAR-like density (~150–250 thousand vertices).
    fn default() -> Self {
        Self {
            heads: 4,
            first_azimuth_deg: 45.0,
            head_distance: 1.2,
            vertical_step: 0.003,
            horizontal_step: 0.003,
            max_grazing_deg: 75.0,
            noise_sigma: 0.001,
            max_edge_steps: 5.0,
        }
    }
}

/// The scanner's output: the merged, noisy scan mesh and, per scan vertex, where it really is.
#[derive(Debug, Clone, Default)]
pub struct Scan {
    /// The merged scan (noisy positions, own triangulation).
    pub mesh: Mesh,
    /// Per scan vertex, the noise-free point on the scanned surface.
    pub clean: Vec<Point3<f64>>,
    /// Per scan vertex, the head that measured it.
    pub head: Vec<u8>,
}

#[cfg(test)]
impl Scan {
    /// A scan of `positions` (`#V`) over `triangles` without noise, every vertex measured by
    /// head 0: a made-up surface for the zoo's tests.
    pub(crate) fn exact(positions: Vec<Point3<f64>>, triangles: Vec<[u32; 3]>) -> Self {
        Self {
            head: vec![0; positions.len()],
            clean: positions.clone(),
            mesh: Mesh::new(positions, triangles),
        }
    }
}

#[derive(Clone, Copy)]
struct Sample {
    point: Point3<f64>,
    normal: Vector3<f64>,
    facing: f64,
    kept: bool,
    vertex: u32,
}

struct View {
    origin_xz: Vector3<f64>,
    axis: Vector3<f64>,
    alpha0: f64,
    dalpha: f64,
    cols: usize,
    samples: Vec<Option<Sample>>,
}

impl View {
    fn direction(&self, col: usize) -> Vector3<f64> {
        let a = self.alpha0 + col as f64 * self.dalpha;
        let (s, c) = a.sin_cos();
        // Rotate the head's axis about +y by `a`.
        Vector3::new(
            c * self.axis.x + s * self.axis.z,
            0.0,
            -s * self.axis.x + c * self.axis.z,
        )
    }

    /// The column whose ray passes nearest to `p` (horizontal projection), if inside the fan.
    fn column_of(&self, p: &Point3<f64>) -> Option<usize> {
        let d = Vector3::new(p.x - self.origin_xz.x, 0.0, p.z - self.origin_xz.z);
        let fwd = d.dot(&self.axis);
        let side = self.axis.z * d.x - self.axis.x * d.z;
        let a = side.atan2(fwd);
        let c = ((a - self.alpha0) / self.dalpha).round();
        (c >= 0.0 && (c as usize) < self.cols).then_some(c as usize)
    }
}

/// Scans `surface` (the posed subject, triangles counter-clockwise from outside) with `params`;
/// the noise is drawn from `rng`.
pub fn scan<R: Rng>(surface: &Mesh, params: &ScannerParams, rng: &mut R) -> Scan {
    let mut out = Scan::default();
    let Some((min, max)) = bounding_box(&surface.positions) else {
        return out;
    };
    if params.heads == 0 {
        return out;
    }
    let bvh = TriangleBvh::new(surface);
    let centre = Point3::new((min.x + max.x) / 2.0, 0.0, (min.z + max.z) / 2.0);
    let radius = ((max.x - min.x).powi(2) + (max.z - min.z).powi(2)).sqrt() / 2.0 + 0.01;
    let rows = ((max.y - min.y) / params.vertical_step).ceil() as usize + 1;
    let y0 = min.y;
    let cos_limit = params.max_grazing_deg.to_radians().cos();
    // A degenerate triangle has no normal; +y keeps a (never expected) hit on one usable.
    let face_normals: Vec<Vector3<f64>> = face_normals(&surface.positions, &surface.triangles)
        .into_iter()
        .map(|n| {
            if n == Vector3::zeros() {
                Vector3::y()
            } else {
                n
            }
        })
        .collect();

    let mut views: Vec<View> = (0..params.heads)
        .map(|k| {
            let phi =
                (params.first_azimuth_deg + k as f64 * 360.0 / params.heads as f64).to_radians();
            let out_dir = Vector3::new(phi.sin(), 0.0, phi.cos());
            let origin_xz = centre.coords + out_dir * params.head_distance;
            let half = (radius / params.head_distance).clamp(-1.0, 1.0).asin();
            let dalpha = params.horizontal_step / params.head_distance;
            let cols = (2.0 * half / dalpha).ceil() as usize + 1;
            View {
                origin_xz,
                axis: -out_dir,
                alpha0: -half,
                dalpha,
                cols,
                samples: vec![None; rows * cols],
            }
        })
        .collect();

    for view in &mut views {
        for r in 0..rows {
            let y = y0 + r as f64 * params.vertical_step;
            let origin = Point3::new(view.origin_xz.x, y, view.origin_xz.z);
            for c in 0..view.cols {
                let dir = view.direction(c);
                let Some(hit) = bvh.cast(&origin, &dir, params.head_distance + radius) else {
                    continue;
                };
                let normal = face_normals[hit.triangle];
                let facing = -dir.dot(&normal);
                if facing.abs() < cos_limit {
                    continue;
                }
                view.samples[r * view.cols + c] = Some(Sample {
                    point: origin + dir * hit.t,
                    normal,
                    facing: facing.abs(),
                    kept: true,
                    vertex: 0,
                });
            }
        }
    }

    select_best_views(&mut views, rows, params);
    triangulate(&mut views, rows, params, rng, &mut out);
    out
}

/// Keeps each sample only in the view that faces its surface point best.
fn select_best_views(views: &mut [View], rows: usize, params: &ScannerParams) {
    let tol = 3.0 * params.vertical_step.max(params.horizontal_step);
    let n = views.len();
    for v in 0..n {
        for r in 0..rows {
            for c in 0..views[v].cols {
                let Some(s) = views[v].samples[r * views[v].cols + c] else {
                    continue;
                };
                let beaten = (0..n).filter(|&u| u != v).any(|u| {
                    let other = &views[u];
                    let Some(cu) = other.column_of(&s.point) else {
                        return false;
                    };
                    let Some(q) = other.samples[r * other.cols + cu] else {
                        return false;
                    };
                    if (q.point - s.point).norm() > tol {
                        return false; // view u sees something else there: occluded
                    }
                    let dir = other.direction(cu);
                    let facing_u = dir.dot(&s.normal).abs();
                    facing_u > s.facing || (facing_u == s.facing && u < v)
                });
                if beaten {
                    if let Some(sample) = views[v].samples[r * views[v].cols + c].as_mut() {
                        sample.kept = false;
                    }
                }
            }
        }
    }
}

fn triangulate<R: Rng>(
    views: &mut [View],
    rows: usize,
    params: &ScannerParams,
    rng: &mut R,
    out: &mut Scan,
) {
    let noise = Normal::new(0.0, params.noise_sigma.max(0.0))
        .unwrap_or_else(|_| Normal::new(0.0, 0.0).expect("zero sigma is valid"));
    let max_edge = params.max_edge_steps * params.vertical_step.max(params.horizontal_step);
    for (k, view) in views.iter_mut().enumerate() {
        // Vertices first, in grid order (deterministic).
        for r in 0..rows {
            for c in 0..view.cols {
                let dir = view.direction(c);
                if let Some(s) = view.samples[r * view.cols + c].as_mut() {
                    if !s.kept {
                        continue;
                    }
                    s.vertex = out.mesh.positions.len() as u32;
                    let e: f64 = noise.sample(rng);
                    out.mesh.positions.push(s.point + dir * e);
                    out.clean.push(s.point);
                    out.head.push(k as u8);
                }
            }
        }
        let at = |r: usize, c: usize| view.samples[r * view.cols + c].filter(|s| s.kept);
        for r in 0..rows.saturating_sub(1) {
            for c in 0..view.cols.saturating_sub(1) {
                let ray = view.direction(c);
                let quad = [at(r, c), at(r, c + 1), at(r + 1, c + 1), at(r + 1, c)];
                let close = |a: &Sample, b: &Sample| (a.point - b.point).norm() < max_edge;
                let mut tri = |a: &Sample, b: &Sample, cc: &Sample| {
                    if close(a, b) && close(b, cc) && close(cc, a) {
                        // Outward = facing the head that saw it.
                        let n = (b.point - a.point).cross(&(cc.point - a.point));
                        if n.dot(&ray) < 0.0 {
                            out.mesh.triangles.push([a.vertex, b.vertex, cc.vertex]);
                        } else {
                            out.mesh.triangles.push([a.vertex, cc.vertex, b.vertex]);
                        }
                    }
                };
                match quad {
                    [Some(a), Some(b), Some(c2), Some(d)] => {
                        if (a.point - c2.point).norm() <= (b.point - d.point).norm() {
                            tri(&a, &b, &c2);
                            tri(&a, &c2, &d);
                        } else {
                            tri(&a, &b, &d);
                            tri(&b, &c2, &d);
                        }
                    }
                    [None, Some(b), Some(c2), Some(d)] => tri(&b, &c2, &d),
                    [Some(a), None, Some(c2), Some(d)] => tri(&a, &c2, &d),
                    [Some(a), Some(b), None, Some(d)] => tri(&a, &b, &d),
                    [Some(a), Some(b), Some(c2), None] => tri(&a, &b, &c2),
                    _ => {}
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    /// A UV sphere of radius `r` centred at (0, r + 0.1, 0), outward triangles.
    fn sphere(r: f64, n: usize) -> Mesh {
        let mut positions = Vec::new();
        for i in 0..=n {
            let theta = std::f64::consts::PI * i as f64 / n as f64;
            for j in 0..2 * n {
                let phi = std::f64::consts::PI * j as f64 / n as f64;
                positions.push(Point3::new(
                    r * theta.sin() * phi.cos(),
                    r + 0.1 + r * theta.cos(),
                    r * theta.sin() * phi.sin(),
                ));
            }
        }
        let w = 2 * n as u32;
        let mut triangles = Vec::new();
        for i in 0..n as u32 {
            for j in 0..w {
                let (a, b) = (i * w + j, i * w + (j + 1) % w);
                let (c, d) = (a + w, b + w);
                triangles.push([a, b, d]);
                triangles.push([a, d, c]);
            }
        }
        Mesh::new(positions, triangles)
    }

    #[test]
    fn sphere_scan_is_on_the_sphere_with_grazing_holes_at_the_poles() {
        let r = 0.3;
        let mesh = sphere(r, 64);
        let params = ScannerParams {
            vertical_step: 0.01,
            horizontal_step: 0.01,
            noise_sigma: 0.0,
            ..ScannerParams::default()
        };
        let s = scan(&mesh, &params, &mut ChaCha8Rng::seed_from_u64(1));
        assert!(s.mesh.vertex_count() > 1000);
        let centre = Point3::new(0.0, r + 0.1, 0.0);
        for p in &s.mesh.positions {
            let d = ((p - centre).norm() - r).abs();
            assert!(d < 2e-3, "sample {d} m off the sphere");
        }
        // Horizontal rays meet the poles at grazing angles: nothing above ~75° latitude.
        let top = s
            .mesh
            .positions
            .iter()
            .map(|p| p.y)
            .fold(f64::MIN, f64::max);
        assert!(top < centre.y + r * 0.97, "pole was scanned ({top})");
        // Every triangle faces outward (towards the head that saw it).
        for t in &s.mesh.triangles {
            let [a, b, c] = t.map(|i| s.mesh.positions[i as usize]);
            let n = (b - a).cross(&(c - a));
            let mid = Point3::from((a.coords + b.coords + c.coords) / 3.0);
            assert!(n.dot(&(mid - centre)) > 0.0);
        }
        // Views are partitioned: no two samples from different heads at the same place.
        let mut seen = std::collections::HashMap::new();
        for (p, h) in s.mesh.positions.iter().zip(&s.head) {
            let key = ((p.x * 1e4) as i64, (p.y * 1e4) as i64, (p.z * 1e4) as i64);
            if let Some(other) = seen.insert(key, *h) {
                assert_eq!(other, *h, "two heads kept the same point");
            }
        }
    }
}
