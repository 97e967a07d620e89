//! What one run of the pipeline ([`super::pipeline::align_scan`]) reports, as one serialisable
//! type: the frame and units assumed, the parameters used, the RBF warp's landmark residuals and
//! similarity, the fine fit's statistics (the paper's Table 1) and convergence curve, timings and,
//! for a synthetic subject, the correspondence error. Lengths are in millimetres (`_mm`), times
//! in milliseconds (`_ms`).

use serde::Serialize;

use super::coarse_to_fine::CoarseToFineResult;
use super::correspondence::CorrespondenceReport;
use super::params::AlignParams;
use super::report::{AlignReport, DistanceStats};
use crate::mesh::units::Units;
use crate::rbf::{LandmarkPairing, RbfParams, RbfWarp};

/// The whole run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AlignmentReport {
    /// "base" or "fine".
    pub template_resolution: &'static str,
    /// Whether the template was aligned coarse to fine.
    pub coarse_to_fine: bool,
    pub template_vertices: usize,
    pub scan_vertices: usize,
    /// The scan's units, as given or as detected.
    pub units: Units,
    /// Whether `units` was detected from the body's extent (rather than given).
    pub units_detected: bool,
    /// Every parameter used.
    pub params: AlignParams,
    pub warp: WarpReport,
    /// Landmark anchors handed to fine alignment (weighted by `params.fine.landmark_weight`).
    pub anchors: usize,
    /// Fine alignment; absent with `rough_only`.
    pub fine: Option<FineReport>,
    /// Correspondence error against a ground truth, when one was given.
    pub correspondence: Option<CorrespondenceReport>,
    /// The RBF warp (including the virtual landmarks and unit scaling).
    pub rough_ms: f64,
    /// Building the scan's closest-point index.
    pub index_ms: f64,
    pub total_ms: f64,
}

/// A landmark's distance to its scan position (mm).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResidualMm {
    pub name: String,
    /// After the similarity (Procrustes) alone.
    pub before_mm: f64,
    /// After the RBF warp (0 up to rounding when λ = 0).
    pub after_mm: f64,
}

/// Template → scan similarity y = scale·R·x + t (the scan's frame, metres).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SimilarityReport {
    pub scale: f64,
    /// R, three rows.
    pub rotation: [[f64; 3]; 3],
    pub translation: [f64; 3],
}

/// The RBF warp (paper §3.1).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WarpReport {
    /// Kernel name (`thin-plate`, `gaussian`, `multiquadric`).
    pub kernel: &'static str,
    /// Its parameter (c or s, metres), none for the thin-plate spline.
    pub param: Option<f64>,
    pub lambda: f64,
    pub affine: bool,
    pub virtual_landmarks: bool,
    /// The landmarks used, skipped and off the scan surface (written as three fields).
    #[serde(flatten)]
    pub pairing: LandmarkPairing,
    /// One per used landmark, in `pairing.used` order.
    pub residuals: Vec<ResidualMm>,
    pub max_residual_before_mm: f64,
    pub max_residual_after_mm: f64,
    pub similarity: SimilarityReport,
    /// Reciprocal condition number of the RBF system.
    pub rcond: f64,
}

impl WarpReport {
    /// The report of `warp` (positions in metres) made with `params`.
    pub fn of(warp: &RbfWarp, params: &RbfParams) -> Self {
        let s = &warp.similarity;
        let residuals: Vec<ResidualMm> = warp
            .residuals
            .iter()
            .map(|r| ResidualMm {
                name: r.name.clone(),
                before_mm: r.before * 1e3,
                after_mm: r.after * 1e3,
            })
            .collect();
        let max = |f: fn(&ResidualMm) -> f64| residuals.iter().map(f).fold(0.0, f64::max);
        Self {
            kernel: params.kernel.name(),
            param: params.kernel.param(),
            lambda: params.lambda,
            affine: params.affine,
            virtual_landmarks: params.virtual_landmarks,
            pairing: warp.pairing.clone(),
            max_residual_before_mm: max(|r| r.before_mm),
            max_residual_after_mm: max(|r| r.after_mm),
            residuals,
            similarity: SimilarityReport {
                scale: s.scale,
                rotation: [0, 1, 2].map(|r| [0, 1, 2].map(|c| s.rotation[(r, c)])),
                translation: [s.translation.x, s.translation.y, s.translation.z],
            },
            rcond: warp.network.rcond(),
        }
    }
}

/// The paper's Table 1 statistics of a signed distance, in millimetres.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DistanceStatsMm {
    /// Points measured.
    pub count: usize,
    pub mean_mm: f64,
    pub std_dev_mm: f64,
    pub rms_mm: f64,
    pub max_abs_mm: f64,
}

impl From<&DistanceStats> for DistanceStatsMm {
    fn from(s: &DistanceStats) -> Self {
        Self {
            count: s.count,
            mean_mm: s.mean * 1e3,
            std_dev_mm: s.std_dev * 1e3,
            rms_mm: s.rms * 1e3,
            max_abs_mm: s.max_abs * 1e3,
        }
    }
}

/// One point of the convergence curve (paper Table 2's time-to-RMS).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CurvePointMm {
    pub iteration: usize,
    pub elapsed_ms: f64,
    pub energy: f64,
    pub rms_mm: f64,
}

/// Fine alignment (paper §3.2): the whole run, or one stage of it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FineReport {
    pub template_vertices: usize,
    pub scan_vertices: usize,
    /// Every scan vertex used by a triangle to the fitted template, signed positive outside
    /// (the paper's Table 1).
    pub scan_to_template: DistanceStatsMm,
    /// Every template vertex with a data weight to the scan.
    pub template_to_scan: DistanceStatsMm,
    /// Of the `template_to_scan.count` weighted template vertices, those with a usable scan
    /// match in the last correspondence round (the rest had no data term at the end).
    pub matched_vertices: usize,
    pub iterations: usize,
    pub rounds: usize,
    pub converged: bool,
    pub cancelled: bool,
    pub elapsed_ms: f64,
    /// E and RMS after every iteration (absent for a stage inside a coarse-to-fine run).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub curve: Option<Vec<CurvePointMm>>,
    /// Coarse to fine only: the base stage and how the fine stage ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stages: Option<Box<StagesReport>>,
}

/// The two stages of a coarse-to-fine run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StagesReport {
    /// The base stage as it ended.
    pub base: FineReport,
    /// Carrying the base fit to fine.
    pub subdivide_ms: f64,
    /// Iterations the fine stage ran, and its limit.
    pub fine_iterations: usize,
    pub fine_max_iterations: usize,
}

impl FineReport {
    /// The report of one fine alignment, with its curve when `with_curve`.
    pub fn of(r: &AlignReport, with_curve: bool) -> Self {
        Self {
            template_vertices: r.template_vertices,
            scan_vertices: r.scan_vertices,
            scan_to_template: (&r.scan_to_template).into(),
            template_to_scan: (&r.template_to_scan).into(),
            matched_vertices: r.matched_vertices,
            iterations: r.iterations,
            rounds: r.rounds,
            converged: r.converged,
            cancelled: r.cancelled,
            elapsed_ms: r.elapsed_ms,
            curve: with_curve.then(|| {
                r.curve
                    .iter()
                    .map(|p| CurvePointMm {
                        iteration: p.iteration,
                        elapsed_ms: p.elapsed_ms,
                        energy: p.energy,
                        rms_mm: p.rms * 1e3,
                    })
                    .collect()
            }),
            stages: None,
        }
    }

    /// The report of a coarse-to-fine run whose fine stage was limited to
    /// `fine_max_iterations`.
    pub fn of_coarse_to_fine(r: &CoarseToFineResult, fine_max_iterations: usize) -> Self {
        Self {
            stages: Some(Box::new(StagesReport {
                base: Self::of(&r.base, false),
                subdivide_ms: r.subdivide_ms,
                fine_iterations: r.report.iterations - r.base.iterations,
                fine_max_iterations,
            })),
            ..Self::of(&r.report, true)
        }
    }
}
