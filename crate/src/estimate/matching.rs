//! Closest compatible scan points for a set of template vertices, the step both ICP stages of
//! the estimate repeat (`candidates.rs`, `segments.rs`).

use nalgebra::{Point3, Vector3};

use super::params::EstimateParams;
use crate::align::{CorrespondenceMode, MatchQuery, SurfaceIndex};
use crate::utils::parallel::filter_map_into;

/// One template vertex matched to the scan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pair {
    pub vertex: u32,
    pub target: Point3<f64>,
    pub distance: f64,
}

/// How the ICP stages match.
#[derive(Debug, Clone, Copy)]
pub struct Matching<'a> {
    pub scan: &'a SurfaceIndex,
    /// Cosine of the largest angle between template and scan normals.
    pub min_cos: f64,
    /// Matches farther than this (m) are dropped.
    pub outlier_distance: f64,
}

impl<'a> Matching<'a> {
    /// Matching onto `scan` with the estimate's normal angle and outlier distance.
    pub fn new(scan: &'a SurfaceIndex, params: &EstimateParams) -> Self {
        Self {
            scan,
            min_cos: params.max_normal_angle_deg.to_radians().cos(),
            outlier_distance: params.outlier_distance,
        }
    }

    /// The matches of `vertices` at `positions` with unit `normals` (both indexed by vertex),
    /// nearest scan vertex with a compatible normal, outliers and incompatible ones dropped.
    pub fn pairs(
        &self,
        vertices: &[u32],
        positions: &[Point3<f64>],
        normals: &[Vector3<f64>],
    ) -> Vec<Pair> {
        let query = MatchQuery {
            mode: CorrespondenceMode::NearestVertex,
            min_cos: Some(self.min_cos),
            candidates: 8,
        };
        let mut out = Vec::with_capacity(vertices.len());
        filter_map_into(vertices, &mut out, |&v| {
            let p = positions[v as usize];
            let n = normals[v as usize];
            let m = self.scan.closest(&p, Some(&n), &query)?;
            let distance = (m.point - p).norm();
            (distance <= self.outlier_distance && !m.on_boundary).then_some(Pair {
                vertex: v,
                target: m.point,
                distance,
            })
        });
        out
    }

    /// The RMS distance (m) of `pairs` (0 for none).
    pub fn rms(pairs: &[Pair]) -> f64 {
        let sum: f64 = pairs.iter().map(|p| p.distance * p.distance).sum();
        (sum / pairs.len().max(1) as f64).sqrt()
    }

    /// The ICP energy of `pairs` out of `tried` vertices: the mean squared distance, an unmatched
    /// vertex counting as `outlier_distance` (so a candidate cannot win by matching little).
    pub fn energy(&self, pairs: &[Pair], tried: usize) -> f64 {
        let unmatched = tried.saturating_sub(pairs.len()) as f64;
        let sum: f64 = pairs.iter().map(|p| p.distance * p.distance).sum();
        (sum + unmatched * self.outlier_distance.powi(2)) / tried.max(1) as f64
    }
}
