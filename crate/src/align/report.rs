//! What a fine alignment reports: the paper's Table 1 statistics, per-vertex distances for the
//! heat map, iterations, time and the time-to-RMS curve (paper Table 2).

use super::error::AlignError;
use super::params::CorrespondenceMode;
use super::surface_index::{MatchQuery, SurfaceIndex};
use crate::mesh::normals::vertex_normals;
use nalgebra::Point3;
use serde::Serialize;

/// Statistics of a set of signed distances (metres), as in the paper's Table 1.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct DistanceStats {
    /// Number of points measured ("Num_of_points").
    pub count: usize,
    /// Mean signed distance ("Mean error").
    pub mean: f64,
    /// Standard deviation of the signed distance.
    pub std_dev: f64,
    /// Root mean squared distance.
    pub rms: f64,
    /// Largest absolute distance.
    pub max_abs: f64,
}

impl DistanceStats {
    /// Statistics of `values` (all zero when empty).
    pub fn of(values: impl IntoIterator<Item = f64>) -> Self {
        let (mut n, mut sum, mut sq, mut max_abs) = (0usize, 0.0, 0.0, 0.0f64);
        for v in values {
            n += 1;
            sum += v;
            sq += v * v;
            max_abs = max_abs.max(v.abs());
        }
        if n == 0 {
            return Self::default();
        }
        let mean = sum / n as f64;
        let rms = (sq / n as f64).sqrt();
        Self {
            count: n,
            mean,
            std_dev: (sq / n as f64 - mean * mean).max(0.0).sqrt(),
            rms,
            max_abs,
        }
    }
}

/// One point of the convergence curve, recorded after every L-BFGS iteration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CurvePoint {
    /// Iterations done so far.
    pub iteration: usize,
    /// Milliseconds since fine alignment started.
    pub elapsed_ms: f64,
    /// The objective E.
    pub energy: f64,
    /// RMS distance (m) of matched template vertices to their current closest scan points.
    pub rms: f64,
}

/// The report of one fine alignment.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AlignReport {
    /// Template vertices.
    pub template_vertices: usize,
    /// Scan vertices.
    pub scan_vertices: usize,
    /// Distance of every scan vertex (used by a triangle) to the fitted template surface, signed positive when the scan
    /// lies outside (along the template's normal) — the paper's Table 1.
    pub scan_to_template: DistanceStats,
    /// Distance of every template vertex with a non-zero data weight to the scan surface, signed
    /// by the template vertex normal.
    pub template_to_scan: DistanceStats,
    /// Template vertices with a data weight that had a usable scan match (compatible normal, not
    /// on a hole rim, near enough) in the last correspondence round; the others had no data
    /// term there (`template_to_scan.count` − this = vertices without a data match).
    pub matched_vertices: usize,
    /// L-BFGS iterations done.
    pub iterations: usize,
    /// Correspondence rounds done.
    pub rounds: usize,
    /// Wall time of the alignment (without this report), ms.
    pub elapsed_ms: f64,
    /// Whether the run was cancelled (the result is then the last accepted iterate).
    pub cancelled: bool,
    /// Whether the relative-energy test stopped it (rather than the iteration limit or cancel).
    pub converged: bool,
    /// E and RMS after every iteration.
    pub curve: Vec<CurvePoint>,
    /// Signed distance (m) of each fitted template vertex to the scan, `#V` (heat map).
    #[serde(skip)]
    pub per_vertex_distance: Vec<f64>,
    /// Each scan vertex's distance to the fitted template and where on the template it lies
    /// (the quality check's "scan the fit left uncovered", `quality.rs`).
    #[serde(skip)]
    pub scan_distances: Vec<ScanDistance>,
}

const EXACT: MatchQuery = MatchQuery {
    mode: CorrespondenceMode::VertexOneRing,
    min_cos: None,
    candidates: 1,
};

/// Signed distances of `fitted` template vertices to the scan (by the template vertex normal),
/// `#V`.
pub fn template_to_scan_distances(
    fitted: &[Point3<f64>],
    triangles: &[[u32; 3]],
    scan: &SurfaceIndex,
) -> Vec<f64> {
    let normals = vertex_normals(fitted, triangles);
    fitted
        .iter()
        .zip(&normals)
        .map(|(p, n)| match scan.closest(p, None, &EXACT) {
            Some(m) => {
                let d = m.point - p;
                d.norm().copysign(d.dot(n))
            }
            None => 0.0,
        })
        .collect()
}

/// One scan vertex's distance to the fitted template surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScanDistance {
    /// Signed distance (metres), positive when the scan lies outside the template (along the
    /// template face normal).
    pub distance: f64,
    /// The template vertex nearest the closest point (its triangle's corner of largest weight):
    /// where on the body the scan vertex is.
    pub nearest_vertex: u32,
}

/// The distance of every scan vertex used by a triangle to the fitted template surface.
pub fn scan_to_template_distances(
    fitted: &[Point3<f64>],
    triangles: &[[u32; 3]],
    scan: &SurfaceIndex,
) -> Result<Vec<ScanDistance>, AlignError> {
    let template = SurfaceIndex::from_parts("fitted template", fitted, triangles)?;
    Ok(scan
        .surface_vertices()
        .filter_map(|s| {
            let m = template.closest_face(s, None, &EXACT)?;
            let d = s - m.point;
            let corner = (0..3)
                .max_by(|&a, &b| m.barycentric[a].total_cmp(&m.barycentric[b]))
                .unwrap_or(0);
            Some(ScanDistance {
                distance: d.norm().copysign(d.dot(&m.normal)),
                nearest_vertex: m.corners[corner],
            })
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stats_of_known_values() {
        let s = DistanceStats::of([1.0, -1.0, 3.0, -3.0]);
        assert_eq!(s.count, 4);
        assert!(s.mean.abs() < 1e-15);
        assert!((s.rms - 5.0f64.sqrt()).abs() < 1e-12);
        assert!((s.std_dev - 5.0f64.sqrt()).abs() < 1e-12);
        assert_eq!(s.max_abs, 3.0);
    }
}
