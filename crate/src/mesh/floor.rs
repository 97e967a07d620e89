//! [`remove_floor`]: a floor, platform or turntable remnant under the feet, found and taken off a
//! scan once its up direction is known.
//!
//! Scanners see what the body stands on: patches of the floor around the feet, a platform, a
//! turntable's disc with its rim. Left in, the fit matches it as the soles and the body comes out
//! too tall. The evidence holds on any scanner's output and not on a body: with heights
//! h = p·û along the unit up û,
//!
//! 1. **the plane**: the height where the most level surface lies (triangles whose normal is
//!    within `level_deg` of ±û: a remnant may be wound either way), among the heights from the
//!    lowest vertex of a triangle to `search` above it (area-weighted histogram of the
//!    triangles' centroid heights in bins of `bin`), refined to the area-weighted median height
//!    h₀ of the level triangles within `layer` of the bin; then û is turned to the plane's own
//!    normal (the least-squares plane through those triangles' centroids, `level_iterations`
//!    times, h₀ re-taken along it each time) and the heights taken along it: up from a body's
//!    fit leans a few degrees, which lifts a turntable's far edge out of the layer;
//! 2. **the footprint** of the body: the vertices from `footprint_from` to `footprint_to` above
//!    h₀, projected across û (the feet and ankles, above any floor noise and any rim);
//! 3. **the remnant**: every vertex with h < h₀ + `layer` (the plane's layer and anything below
//!    it: a disc's rim, a platform's sides) that lies farther than `clear` across û from every
//!    footprint vertex; the body's soles lie under its footprint and stay, and the tops of the
//!    feet lie centimetres above the plane;
//! 4. **the verdict**: it is a remnant only when the body stands on it (at most `below_share` of
//!    the vertices under the footprint lie below the layer: the tops of the feet have the soles
//!    under them), its level area in the layer is at least `min_area`, and it reaches at least
//!    `beyond` out of the footprint's box across û (a body's own level surface lies within its
//!    outline); up to `tries` heights are tried, the fullest first. Then those vertices and
//!    every triangle using one are removed.
//!
//! A floor hidden under the soles is not seen by a scanner and not looked for; a floor fused to
//! the feet keeps a ring up to `clear` wide around them. Units: the parameters are metres, the
//! mesh in any units (`to_m`: its units → metres).

use std::collections::HashMap;

use nalgebra::{Point3, Vector3};
use serde::Serialize;

use super::Mesh;

/// The remnant's rule (module documentation); lengths in metres.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
#[serde(default)]
pub struct FloorParams {
    /// The plane is looked for up to this height above the lowest vertex of a triangle (0.15 m:
    /// a turntable's rim or a platform's side may reach that far below its top).
    pub search: f64,
    /// Bin of the height histogram of level area (0.004 m: the scanner's noise, ≈ 1 mm,
    /// well inside one or two bins).
    pub bin: f64,
    /// A triangle is level when its normal is within this angle of ±û (40°: 1 mm of noise on a
    /// floor sampled every 4 mm tilts its triangles by ≈ 20° typically).
    pub level_deg: f64,
    /// The plane's normal refined from its own level faces this many times (3; up from a fit
    /// may lean a few degrees).
    pub level_iterations: usize,
    /// The fullest bins tried as the plane, in order, until one holds the evidence (3).
    pub tries: usize,
    /// Half the plane's thickness (0.008 m: four times the noise, and below the tops of the toes).
    pub layer: f64,
    /// The footprint: body vertices from this height above the plane (0.015 m, above the layer
    /// and its noise)…
    pub footprint_from: f64,
    /// …to this one (0.15 m: the feet and ankles).
    pub footprint_to: f64,
    /// A remnant's vertex lies farther than this across û from the footprint (0.012 m: the soles'
    /// rounded edges stay within it).
    pub clear: f64,
    /// The body stands on the plane: at most this share of the vertices under its footprint
    /// (within `clear`, below the layer's top) lie below the layer (0.02; the tops of the feet
    /// have the soles under them).
    pub below_share: f64,
    /// The remnant's level part reaches at least this far beyond the footprint's box across û
    /// (0.02 m; floor patches reach 4–12 cm around the feet, a turntable decimetres).
    pub beyond: f64,
    /// Least level area (m²) of the remnant in the plane's layer (0.004 m² = 40 cm²: a
    /// 6 × 6 cm patch; the floor patches of a scan are hundreds of cm²).
    pub min_area: f64,
}

impl Default for FloorParams {
    fn default() -> Self {
        Self {
            search: 0.15,
            bin: 0.004,
            level_deg: 40.0,
            tries: 3,
            level_iterations: 3,
            layer: 0.008,
            footprint_from: 0.015,
            footprint_to: 0.15,
            clear: 0.012,
            below_share: 0.02,
            beyond: 0.02,
            min_area: 0.004,
        }
    }
}

/// What [`remove_floor`] took off.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FloorRemoval {
    /// Vertices removed.
    pub vertices: usize,
    /// Triangles removed (those using a removed vertex).
    pub triangles: usize,
    /// The plane's height h₀ along its own normal û (the mesh's units: p·û of a point on it).
    pub height: f64,
    /// Its height above the lowest vertex of a triangle (mm).
    pub above_lowest_mm: f64,
    /// The remnant's level area in the plane's layer (cm²).
    pub area_cm2: f64,
    /// The removal in words, for a report.
    pub words: String,
}

/// The scan without its floor remnant, and what was removed (module documentation). `mesh`: `#V`
/// positions, `#F` triangles, its own frame and units; `up`: the body's up in that frame (any
/// length; the feet are at the low end); `to_m`: the mesh's units → metres. Returns `None` when
/// nothing is removed (no remnant found, or up is zero); else the mesh with the kept vertices in
/// their order and the kept triangles re-indexed.
pub fn remove_floor(
    mesh: &Mesh,
    up: &Vector3<f64>,
    to_m: f64,
    params: &FloorParams,
) -> Option<(Mesh, FloorRemoval)> {
    let up = up.try_normalize(1e-12)?;
    if !(to_m > 0.0 && to_m.is_finite()) {
        return None;
    }
    let height = heights(mesh, &up, to_m);
    let lowest = lowest_of_triangles(mesh, &height)?;
    let faces = level_faces(mesh, &up, &height, to_m, lowest, params);
    let (plane, lowest, remnant, area) = plane_heights(&faces, lowest, params)
        .into_iter()
        .find_map(|plane| {
            // The plane's own normal is up from here on: up from a body's fit may lean a
            // few degrees, which lifts a turntable's far edge out of the layer.
            let (up, plane) = level_up(&faces, up, plane, to_m, params);
            let height = heights(mesh, &up, to_m);
            let lowest = lowest_of_triangles(mesh, &height)?;
            let faces = level_faces(mesh, &up, &height, to_m, lowest, params);
            let (across_a, across_b) = across(&up);
            let flat: Vec<[f64; 2]> = mesh
                .positions
                .iter()
                .map(|p| {
                    [
                        p.coords.dot(&across_a) * to_m,
                        p.coords.dot(&across_b) * to_m,
                    ]
                })
                .collect();
            let (remnant, area) = remnant(mesh, &faces, &height, &flat, plane, params)?;
            Some((plane, lowest, remnant, area))
        })?;
    let keep: Vec<bool> = remnant.iter().map(|r| !r).collect();
    let kept = mesh.with_vertices(&keep);
    let vertices = mesh.positions.len() - kept.positions.len();
    let (above_lowest_mm, area_cm2) = ((plane - lowest) * 1000.0, area * 1e4);
    let removal = FloorRemoval {
        vertices,
        triangles: mesh.triangles.len() - kept.triangles.len(),
        height: plane / to_m,
        above_lowest_mm,
        area_cm2,
        words: format!(
            "a floor or turntable under the feet ({vertices} vertices, {area_cm2:.0} cm² of level \
             surface {above_lowest_mm:.0} mm above the scan's lowest point) was left out"
        ),
    };
    Some((kept, removal))
}

/// Each vertex's height p·û (m).
fn heights(mesh: &Mesh, up: &Vector3<f64>, to_m: f64) -> Vec<f64> {
    mesh.positions
        .iter()
        .map(|p| p.coords.dot(up) * to_m)
        .collect()
}

/// The lowest height of a triangle's vertex; `None` without triangles.
fn lowest_of_triangles(mesh: &Mesh, height: &[f64]) -> Option<f64> {
    let lowest = mesh
        .triangles
        .iter()
        .flatten()
        .map(|&v| height[v as usize])
        .fold(f64::INFINITY, f64::min);
    lowest.is_finite().then_some(lowest)
}

/// The plane's own up and height (m): `level_iterations` times, the normal of the plane fitted
/// to the level `faces` within `layer` of the plane (heights along the current up;
/// [`plane_normal`]), and the area-weighted median height of those faces along it.
fn level_up(
    faces: &[LevelFace],
    up: Vector3<f64>,
    plane: f64,
    to_m: f64,
    params: &FloorParams,
) -> (Vector3<f64>, f64) {
    let (mut up, mut plane) = (up, plane);
    for _ in 0..params.level_iterations {
        let near: Vec<(f64, &LevelFace)> = faces
            .iter()
            .map(|f| (f.centroid.coords.dot(&up) * to_m, f))
            .filter(|(h, _)| (h - plane).abs() <= params.layer)
            .collect();
        let Some(next) = plane_normal(&near, &up) else {
            break;
        };
        let heights: Vec<(f64, f64)> = near
            .iter()
            .map(|(_, f)| (f.centroid.coords.dot(&next) * to_m, f.area))
            .collect();
        match weighted_median(heights) {
            Some(h) => (up, plane) = (next, h),
            None => break,
        }
    }
    (up, plane)
}

/// The normal (turned towards `up`) of the plane through the faces' centroids, area-weighted
/// least squares: the eigenvector of their covariance with the smallest eigenvalue. Centroids,
/// not the faces' normals: the level faces are chosen by their normals' angle to a leaning up,
/// which keeps the noisy faces leaning its way and biases their mean normal towards it.
fn plane_normal(near: &[(f64, &LevelFace)], up: &Vector3<f64>) -> Option<Vector3<f64>> {
    let weight: f64 = near.iter().map(|(_, f)| f.area).sum();
    if near.len() < 3 || weight <= 0.0 {
        return None;
    }
    let mean = near
        .iter()
        .map(|(_, f)| f.centroid.coords * f.area)
        .sum::<Vector3<f64>>()
        / weight;
    let covariance = near
        .iter()
        .map(|(_, f)| {
            let d = f.centroid.coords - mean;
            d * d.transpose() * f.area
        })
        .sum::<nalgebra::Matrix3<f64>>();
    let eigen = covariance.symmetric_eigen();
    let smallest = eigen.eigenvalues.imin();
    let normal = eigen.eigenvectors.column(smallest).into_owned();
    normal.try_normalize(1e-12).map(|n| n * n.dot(up).signum())
}

/// The weighted median of `(value, weight)` pairs; `None` when they weigh nothing.
fn weighted_median(mut pairs: Vec<(f64, f64)>) -> Option<f64> {
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let total: f64 = pairs.iter().map(|(_, w)| w).sum();
    let mut below = 0.0;
    pairs
        .iter()
        .find(|(_, w)| {
            below += w;
            below >= 0.5 * total && total > 0.0
        })
        .map(|(v, _)| *v)
}

/// A level triangle near the bottom: its index, centroid height (m) and area (m²).
struct LevelFace {
    triangle: usize,
    height: f64,
    area: f64,
    /// Its centroid (the mesh's units).
    centroid: Point3<f64>,
}

/// The level triangles (normal within `level_deg` of ±`up`: a remnant's triangles may be wound
/// either way) whose centroid lies from `lowest` to `search` above it (heights in metres).
fn level_faces(
    mesh: &Mesh,
    up: &Vector3<f64>,
    height: &[f64],
    to_m: f64,
    lowest: f64,
    params: &FloorParams,
) -> Vec<LevelFace> {
    let cos = params.level_deg.to_radians().cos();
    mesh.triangles
        .iter()
        .enumerate()
        .filter_map(|(k, t)| {
            let h = t.iter().map(|&v| height[v as usize]).sum::<f64>() / 3.0;
            if h > lowest + params.search {
                return None;
            }
            let [a, b, c] = t.map(|v| mesh.positions[v as usize]);
            let n = (b - a).cross(&(c - a));
            let norm = n.norm();
            (norm > 0.0 && n.dot(up).abs() >= cos * norm).then_some(LevelFace {
                triangle: k,
                height: h,
                area: 0.5 * norm * to_m * to_m,
                centroid: Point3::from((a.coords + b.coords + c.coords) / 3.0),
            })
        })
        .collect()
}

/// Candidate heights h₀ (m) of the plane, the fullest first: the histogram's `tries` fullest
/// bins (bins of `bin` from `lowest`, at least `layer` apart), each refined to the area-weighted
/// median height of the level faces within `layer` of its centre (a sole seen beside the floor
/// does not lift it).
fn plane_heights(faces: &[LevelFace], lowest: f64, params: &FloorParams) -> Vec<f64> {
    let bins = (params.search / params.bin).ceil().max(1.0) as usize + 1;
    let mut area = vec![0.0; bins];
    for f in faces {
        let b = (((f.height - lowest) / params.bin).floor().max(0.0) as usize).min(bins - 1);
        area[b] += f.area;
    }
    let mut order: Vec<usize> = (0..bins).filter(|&b| area[b] > 0.0).collect();
    order.sort_by(|a, b| area[*b].total_cmp(&area[*a]));
    let mut heights: Vec<f64> = Vec::new();
    for b in order {
        if heights.len() >= params.tries {
            break;
        }
        let centre = lowest + (b as f64 + 0.5) * params.bin;
        let near: Vec<(f64, f64)> = faces
            .iter()
            .filter(|f| (f.height - centre).abs() <= params.layer)
            .map(|f| (f.height, f.area))
            .collect();
        let Some(h) = weighted_median(near) else {
            continue;
        };
        if heights.iter().all(|o| (o - h).abs() > params.layer) {
            heights.push(h);
        }
    }
    heights
}

/// The remnant at plane height `plane` (m), if the evidence holds (module documentation, steps
/// 2–4): which vertices it takes (`#V` flags) and its level area in the layer (m²). `height`:
/// each vertex's height (m); `flat`: its position across up (m).
fn remnant(
    mesh: &Mesh,
    faces: &[LevelFace],
    height: &[f64],
    flat: &[[f64; 2]],
    plane: f64,
    params: &FloorParams,
) -> Option<(Vec<bool>, f64)> {
    let footprint = Footprint::new(
        flat.iter()
            .zip(height)
            .filter(|(_, &h)| h > plane + params.footprint_from && h <= plane + params.footprint_to)
            .map(|(p, _)| *p),
        params.clear,
    );
    let under: Vec<bool> = flat
        .iter()
        .zip(height)
        .map(|(p, &h)| h < plane + params.layer && footprint.within(*p, params.clear))
        .collect();
    // The body stands on the plane: none of it under its footprint lies below the layer.
    let standing = under.iter().filter(|u| **u).count();
    let below = under
        .iter()
        .zip(height)
        .filter(|(u, &h)| **u && h < plane - params.layer)
        .count();
    if below as f64 > params.below_share * standing.max(1) as f64 {
        return None;
    }
    let remnant: Vec<bool> = under
        .iter()
        .zip(height)
        .map(|(u, &h)| !u && h < plane + params.layer)
        .collect();
    let area: f64 = faces
        .iter()
        .filter(|f| (f.height - plane).abs() <= params.layer)
        .filter(|f| {
            mesh.triangles[f.triangle]
                .iter()
                .all(|&v| remnant[v as usize])
        })
        .map(|f| f.area)
        .sum();
    // It reaches out beyond the footprint's box across up (a body's own level surface, such as
    // a flat top seen upside down, lies within its outline).
    let (lo, hi) = footprint.extent()?;
    let reach = flat
        .iter()
        .zip(height)
        .zip(&remnant)
        .filter(|((_, &h), &r)| r && (h - plane).abs() <= params.layer)
        .map(|((p, _), _)| {
            (lo[0] - p[0])
                .max(p[0] - hi[0])
                .max(lo[1] - p[1])
                .max(p[1] - hi[1])
        })
        .fold(f64::NEG_INFINITY, f64::max);
    (area >= params.min_area && reach >= params.beyond).then_some((remnant, area))
}

/// Two unit directions across `up`, orthogonal to it and to each other.
fn across(up: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let other = if up.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let a = up.cross(&other).normalize();
    (a, up.cross(&a))
}

/// The footprint's points across up (m), bucketed in square cells.
struct Footprint {
    cell: f64,
    cells: HashMap<(i64, i64), Vec<[f64; 2]>>,
}

impl Footprint {
    fn new(points: impl Iterator<Item = [f64; 2]>, cell: f64) -> Self {
        let cell = cell.max(1e-6);
        let mut cells: HashMap<(i64, i64), Vec<[f64; 2]>> = HashMap::new();
        for p in points {
            cells.entry(Self::key(p, cell)).or_default().push(p);
        }
        Self { cell, cells }
    }

    /// The smallest and largest coordinates of the points; `None` without points.
    fn extent(&self) -> Option<([f64; 2], [f64; 2])> {
        let points = self.cells.values().flatten();
        let lo = points
            .clone()
            .fold([f64::INFINITY; 2], |m, p| [m[0].min(p[0]), m[1].min(p[1])]);
        let hi = points.fold([f64::NEG_INFINITY; 2], |m, p| {
            [m[0].max(p[0]), m[1].max(p[1])]
        });
        lo[0].is_finite().then_some((lo, hi))
    }

    fn key(p: [f64; 2], cell: f64) -> (i64, i64) {
        ((p[0] / cell).floor() as i64, (p[1] / cell).floor() as i64)
    }

    /// Whether a footprint point lies within `reach` (≤ the cell) of `p`.
    fn within(&self, p: [f64; 2], reach: f64) -> bool {
        let (i, k) = Self::key(p, self.cell);
        let r2 = reach * reach;
        (-1..=1).any(|di| {
            (-1..=1).any(|dk| {
                self.cells.get(&(i + di, k + dk)).is_some_and(|c| {
                    c.iter()
                        .any(|q| (q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2) <= r2)
                })
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point3;

    /// Appends a grid of `n1 × n2` quads spanning `e1`, `e2` from `origin` (y up, metres), the
    /// points `keep` refuses left out with their quads; returns the indices of the added points.
    fn grid(
        mesh: &mut Mesh,
        origin: Point3<f64>,
        (e1, n1): (Vector3<f64>, usize),
        (e2, n2): (Vector3<f64>, usize),
        keep: &dyn Fn(&Point3<f64>) -> bool,
    ) -> Vec<u32> {
        let mut at = vec![None; (n1 + 1) * (n2 + 1)];
        let mut added = Vec::new();
        for j in 0..=n2 {
            for i in 0..=n1 {
                let p = origin + e1 * (i as f64 / n1 as f64) + e2 * (j as f64 / n2 as f64);
                if keep(&p) {
                    at[j * (n1 + 1) + i] = Some(mesh.positions.len() as u32);
                    added.push(mesh.positions.len() as u32);
                    mesh.positions.push(p);
                }
            }
        }
        for j in 0..n2 {
            for i in 0..n1 {
                let q = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                    .map(|(a, b)| at[b * (n1 + 1) + a]);
                if let [Some(a), Some(b), Some(c), Some(d)] = q {
                    mesh.triangles.push([a, b, c]);
                    mesh.triangles.push([a, c, d]);
                }
            }
        }
        added
    }

    /// A box from `lo` to `hi` sampled about every centimetre; `bottom`: with its bottom face.
    fn cuboid(mesh: &mut Mesh, lo: Point3<f64>, hi: Point3<f64>, bottom: bool) {
        let d = hi - lo;
        let n = |l: f64| ((l / 0.01).ceil() as usize).max(1);
        let (x, y, z) = (Vector3::x() * d.x, Vector3::y() * d.y, Vector3::z() * d.z);
        let all = |_: &Point3<f64>| true;
        grid(mesh, lo, (x, n(d.x)), (y, n(d.y)), &all);
        grid(mesh, lo + z, (x, n(d.x)), (y, n(d.y)), &all);
        grid(mesh, lo, (z, n(d.z)), (y, n(d.y)), &all);
        grid(mesh, lo + x, (z, n(d.z)), (y, n(d.y)), &all);
        grid(mesh, lo + y, (x, n(d.x)), (z, n(d.z)), &all);
        if bottom {
            grid(mesh, lo, (x, n(d.x)), (z, n(d.z)), &all);
        }
    }

    /// The feet's two boxes (25 × 10 cm, soles 4 mm above y = 0), the legs above them and a
    /// trunk; `feet: false` cuts the body at the shins (no feet, open legs).
    fn body(feet: bool) -> Mesh {
        let mut mesh = Mesh::default();
        for x in [-0.15, 0.05] {
            let shin = if feet { 0.08 } else { 0.3 };
            if feet {
                cuboid(
                    &mut mesh,
                    Point3::new(x, 0.004, -0.08),
                    Point3::new(x + 0.1, 0.08, 0.17),
                    true,
                );
            }
            cuboid(
                &mut mesh,
                Point3::new(x + 0.02, shin, -0.05),
                Point3::new(x + 0.08, 0.9, 0.02),
                false,
            );
        }
        cuboid(
            &mut mesh,
            Point3::new(-0.18, 0.9, -0.12),
            Point3::new(0.18, 1.6, 0.1),
            true,
        );
        mesh
    }

    /// Whether `(x, z)` lies within `reach` of a foot's box.
    fn near_feet(p: &Point3<f64>, reach: f64) -> bool {
        [-0.15, 0.05].iter().any(|&x| {
            p.x > x - reach && p.x < x + 0.1 + reach && p.z > -0.08 - reach && p.z < 0.17 + reach
        })
    }

    /// `body(true)` on a floor patch (y = 0, every 1 cm, 8 cm around the feet, hidden within
    /// 1 cm of them); the floor's vertex indices.
    fn on_floor() -> (Mesh, Vec<u32>) {
        let mut mesh = body(true);
        let floor = grid(
            &mut mesh,
            Point3::new(-0.25, 0.0, -0.18),
            (Vector3::x() * 0.5, 50),
            (Vector3::z() * 0.45, 45),
            &|p| near_feet(p, 0.08) && !near_feet(p, 0.01),
        );
        (mesh, floor)
    }

    /// The vertices of `mesh` not kept in `kept` (the kept ones keep their order).
    fn removed(mesh: &Mesh, kept: &Mesh) -> Vec<u32> {
        let mut out = Vec::new();
        let mut k = 0;
        for (v, p) in mesh.positions.iter().enumerate() {
            if kept.positions.get(k) == Some(p) {
                k += 1;
            } else {
                out.push(v as u32);
            }
        }
        out
    }

    /// Every removed vertex is the remnant's, and the remnant's farther than `clear` from the
    /// feet are all removed.
    /// `upright`: the same vertices y up in metres.
    fn only_the_remnant(mesh: &Mesh, kept: &Mesh, remnant: &[u32], upright: &Mesh) {
        let gone = removed(mesh, kept);
        assert!(
            gone.iter().all(|v| remnant.contains(v)),
            "a body vertex was removed"
        );
        let far: Vec<u32> = remnant
            .iter()
            .copied()
            .filter(|&v| !near_feet(&upright.positions[v as usize], 0.013))
            .collect();
        assert!(
            far.iter().all(|v| gone.contains(v)),
            "a remnant vertex stayed"
        );
        assert!(kept
            .triangles
            .iter()
            .flatten()
            .all(|&v| (v as usize) < kept.positions.len()));
        assert_eq!(mesh.triangles.len() - kept.triangles.len(), {
            mesh.triangles
                .iter()
                .filter(|t| t.iter().any(|v| gone.contains(v)))
                .count()
        });
    }

    #[test]
    fn a_floor_patch_around_the_feet_is_removed_and_the_feet_stay() {
        let (mesh, floor) = on_floor();
        let (kept, r) = remove_floor(&mesh, &Vector3::y(), 1.0, &FloorParams::default()).unwrap();
        only_the_remnant(&mesh, &kept, &floor, &mesh);
        assert!(r.height.abs() < 0.001, "{}", r.height);
        assert!(r.area_cm2 > 800.0, "{}", r.area_cm2);
        assert_eq!(r.vertices, mesh.positions.len() - kept.positions.len());
        assert!(
            r.words.contains(&format!("{} vertices", r.vertices)),
            "{}",
            r.words
        );
    }

    #[test]
    fn a_turntable_disc_and_its_rim_are_removed() {
        let mut mesh = body(true);
        let centre = Point3::new(-0.05, 0.0, 0.045);
        let inside = |p: &Point3<f64>| (p - centre).xz().norm() <= 0.45;
        let mut disc = grid(
            &mut mesh,
            Point3::new(-0.5, 0.0, -0.405),
            (Vector3::x() * 0.9, 90),
            (Vector3::z() * 0.9, 90),
            &|p| inside(p) && !near_feet(p, 0.01),
        );
        // The rim: 3 cm below the disc's edge, 2 cm steps around and 1 cm down, wound inwards.
        let around = 140;
        let first = mesh.positions.len() as u32;
        for r in 0..4 {
            for k in 0..around {
                let a = std::f64::consts::TAU * k as f64 / around as f64;
                disc.push(mesh.positions.len() as u32);
                mesh.positions
                    .push(centre + Vector3::new(0.45 * a.cos(), -0.01 * r as f64, 0.45 * a.sin()));
            }
        }
        let id = |r: u32, k: u32| first + r * around + k % around;
        for r in 0..3 {
            for k in 0..around {
                mesh.triangles
                    .push([id(r, k), id(r + 1, k), id(r + 1, k + 1)]);
                mesh.triangles
                    .push([id(r, k), id(r + 1, k + 1), id(r, k + 1)]);
            }
        }
        let (kept, r) = remove_floor(&mesh, &Vector3::y(), 1.0, &FloorParams::default()).unwrap();
        only_the_remnant(&mesh, &kept, &disc, &mesh);
        assert!(
            r.height.abs() < 0.001 && (r.above_lowest_mm - 30.0).abs() < 1.0,
            "{r:?}"
        );
        // Up from a body's fit leaning 6°: the disc's far edge 47 mm off the layer along it.
        let lean = nalgebra::Rotation3::from_axis_angle(&Vector3::x_axis(), 6f64.to_radians());
        let (kept, _) =
            remove_floor(&mesh, &(lean * Vector3::y()), 1.0, &FloorParams::default()).unwrap();
        only_the_remnant(&mesh, &kept, &disc, &mesh);
    }

    #[test]
    fn a_body_without_floor_or_without_feet_keeps_every_vertex() {
        for feet in [true, false] {
            let mesh = body(feet);
            assert!(remove_floor(&mesh, &Vector3::y(), 1.0, &FloorParams::default()).is_none());
        }
    }

    #[test]
    fn a_body_in_another_frame_and_units_loses_the_same_floor() {
        // z up in millimetres: (x, y, z) m → (x, −z, y) mm.
        let (mesh, floor) = on_floor();
        let turned = Mesh::new(
            mesh.positions
                .iter()
                .map(|p| Point3::new(p.x, -p.z, p.y) * 1000.0)
                .collect(),
            mesh.triangles.clone(),
        );
        let params = FloorParams::default();
        let (kept, r) = remove_floor(&turned, &Vector3::z(), 0.001, &params).unwrap();
        let (kept_m, r_m) = remove_floor(&mesh, &Vector3::y(), 1.0, &params).unwrap();
        only_the_remnant(&turned, &kept, &floor, &mesh);
        assert_eq!((r.vertices, r.triangles), (r_m.vertices, r_m.triangles));
        assert_eq!(kept.positions.len(), kept_m.positions.len());
        assert!(r.height.abs() < 1.0 && (r.area_cm2 - r_m.area_cm2).abs() < 1e-6);
        // Upside down, the "feet" are the trunk's top: nothing level lies around it.
        assert!(remove_floor(&turned, &-Vector3::z(), 0.001, &params).is_none());
    }
}
