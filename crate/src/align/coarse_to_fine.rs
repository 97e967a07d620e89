//! Coarse-to-fine fine alignment (paper §3.2 at the `fine` resolution): fit the `base` template
//! with the normal schedule, carry the fitted surface to `fine` through the template's
//! subdivision operator (fine = S · base), then run a short fine-level alignment that only adds
//! the detail the base mesh cannot hold.
//!
//! Why: the base fit does the large, slow part of the work (annealing from the RBF warp, ≈ 28
//! iterations) on 16× fewer vertices; the subdivided fit already lies within the base mesh's
//! chord sag (≈ 0.5 mm) of the scan, so the fine level needs a few rounds at the paper's b and
//! no annealing. Both stages are [`fine_align_general`]; a and b carry across the resolutions
//! through `reference_edge_length` (docs/fine-alignment.md, "How a and b scale with the mesh").

use std::ops::ControlFlow;

use nalgebra::Point3;

use super::error::AlignError;
use super::fine_align::{fine_align_general, now_ms, Progress};
use super::params::FineAlignParams;
use super::report::{AlignReport, CurvePoint};
use super::scan_index::ScanIndex;
use crate::template::Subdivision;

/// Which of the two stages a progress report or a round belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// Fine alignment of the base-resolution template.
    Base,
    /// The short fine alignment of the subdivided fit.
    Fine,
}

impl Stage {
    /// "base" or "fine".
    pub fn name(self) -> &'static str {
        match self {
            Stage::Base => "base",
            Stage::Fine => "fine",
        }
    }
}

/// `on_round(stage, round, positions)` of [`coarse_to_fine_align`]: the surface at the fine
/// resolution at the start of every round.
pub type StagedRoundObserver<'a> = dyn FnMut(Stage, usize, &[Point3<f64>]) + 'a;

/// The two schedules of [`coarse_to_fine_align`].
#[derive(Debug, Clone, PartialEq)]
pub struct CoarseToFineParams {
    /// The base stage: the normal defaults ([`FineAlignParams::default`]).
    pub base: FineAlignParams,
    /// The fine stage: same a, b, treatments and correspondence search; no stiffness annealing
    /// (the base stage has done it), 2 iterations per round, at most
    /// [`FINE_STAGE_ITERATIONS`] iterations, stop when a round moves the surface by less than
    /// 0.1 mm RMS, L-BFGS memory 3 (the fine level has 16× the unknowns; memory 7 would hold
    /// ≈ 390 MB of correction pairs). Measured in docs/fine-alignment.md, "Coarse to fine".
    pub fine: FineAlignParams,
}

/// Iteration limit of the default fine stage.
pub const FINE_STAGE_ITERATIONS: usize = 8;

impl Default for CoarseToFineParams {
    fn default() -> Self {
        let base = FineAlignParams::default();
        let fine = FineAlignParams {
            initial_stiffness: 1.0,
            iterations_per_round: 2,
            max_iterations: FINE_STAGE_ITERATIONS,
            displacement_tolerance: 1e-4,
            lbfgs_memory: 3,
            ..base.clone()
        };
        Self { base, fine }
    }
}

impl CoarseToFineParams {
    /// The default schedules around a caller's base-stage parameters: the fine stage keeps the
    /// same energy (a, b, landmark and scan-to-template weights) and runs at most
    /// `fine_iterations` iterations ([`FINE_STAGE_ITERATIONS`] when `None`).
    pub fn around(base: &FineAlignParams, fine_iterations: Option<usize>) -> Self {
        let defaults = Self::default();
        let fine = FineAlignParams {
            a: base.a,
            b: base.b,
            landmark_weight: base.landmark_weight,
            scan_term_weight: base.scan_term_weight,
            max_iterations: fine_iterations.unwrap_or(defaults.fine.max_iterations),
            ..defaults.fine
        };
        Self {
            base: base.clone(),
            fine,
        }
    }

    /// Both stages' limits together: the most iterations a run can report.
    pub fn max_iterations(&self) -> usize {
        self.base
            .max_iterations
            .saturating_add(self.fine.max_iterations)
    }
}

/// The fine-resolution fit and its reports.
#[derive(Debug, Clone, PartialEq)]
pub struct CoarseToFineResult {
    /// Fitted fine template positions, `#Vf`, fine template order (base vertices first), metres.
    pub positions: Vec<Point3<f64>>,
    /// The whole run: statistics and per-vertex distances of the fine fit; iterations, rounds,
    /// time and curve over both stages (iteration numbers continue from the base stage).
    pub report: AlignReport,
    /// The base stage alone, as it ended (statistics of the base fit, `#Vb` distances).
    pub base: AlignReport,
    /// Milliseconds spent carrying the base fit to fine (S · base).
    pub subdivide_ms: f64,
}

/// Fits the fine template to the scan, coarse to fine.
///
/// * `base_positions`: `#Vb` RBF-warped base template (metres, scan frame); `base_triangles`.
/// * `refinement`: the template's subdivision operator base → fine (its `stencils` are `#Vf`,
///   the first `#Vb` being the base vertices; its `triangles` are the fine faces).
/// * `weights`: `#Vf` data weights of the fine template; the base stage uses the first `#Vb`
///   (a base vertex has the same flags at both resolutions).
/// * `anchors`: landmark anchors as in [`super::fine_align_anchored`], base vertex indices
///   (the same vertices at fine); both stages use them.
/// * `on_progress(stage, progress)`: after every iteration, `iteration`, `round` and
///   `elapsed_ms` counted from the start of the whole run; `Break` cancels.
/// * `on_round(stage, round, positions)`: at the start of every round, the current surface at
///   the fine resolution (`#Vf`; the base stage's surface carried through S), so a caller that
///   may be stopped abruptly holds the last good state at the resolution it shows.
///
/// A cancelled base stage returns its last iterate carried to fine, with the report measured
/// there and `cancelled = true`; a cancelled fine stage returns the fine stage's last iterate.
#[allow(clippy::too_many_arguments)]
pub fn coarse_to_fine_align(
    base_positions: &[Point3<f64>],
    base_triangles: &[[u32; 3]],
    refinement: &Subdivision,
    scan: &ScanIndex,
    weights: &[f64],
    anchors: &[(u32, Point3<f64>)],
    params: &CoarseToFineParams,
    on_progress: &mut dyn FnMut(Stage, &Progress) -> ControlFlow<()>,
    on_round: &mut StagedRoundObserver<'_>,
) -> Result<CoarseToFineResult, AlignError> {
    let start = now_ms();
    let base_count = base_positions.len();
    let fine_count = refinement.stencils.len();
    if refinement.base_vertex_count != base_count || fine_count < base_count {
        return Err(AlignError::Refinement {
            base_vertices: base_count,
            operator_base_vertices: refinement.base_vertex_count,
            operator_fine_vertices: fine_count,
        });
    }
    if weights.len() != fine_count {
        return Err(AlignError::WeightCount {
            got: weights.len(),
            expected: fine_count,
        });
    }
    params.fine.validate()?;

    let base = fine_align_general(
        base_positions,
        base_triangles,
        scan,
        &weights[..base_count],
        anchors,
        &params.base,
        &mut |p| on_progress(Stage::Base, p),
        &mut |round, positions| on_round(Stage::Base, round, &refinement.apply(positions)),
    )?;

    let subdivide_start = now_ms();
    let fine_start = refinement.apply(&base.positions);
    let subdivide_ms = now_ms() - subdivide_start;

    // A cancelled base stage still ends at the fine resolution: zero iterations of the fine
    // stage measure the carried surface without moving it.
    let fine_params = if base.report.cancelled {
        FineAlignParams {
            max_iterations: 0,
            ..params.fine.clone()
        }
    } else {
        params.fine.clone()
    };
    let (iteration_offset, round_offset) = (base.report.iterations, base.report.rounds);
    let elapsed_offset = now_ms() - start;
    let fine = fine_align_general(
        &fine_start,
        &refinement.triangles,
        scan,
        weights,
        anchors,
        &fine_params,
        &mut |p| {
            let continued = Progress {
                iteration: p.iteration + iteration_offset,
                round: p.round + round_offset,
                elapsed_ms: p.elapsed_ms + elapsed_offset,
                ..*p
            };
            on_progress(Stage::Fine, &continued)
        },
        &mut |round, positions| on_round(Stage::Fine, round + round_offset, positions),
    )?;

    let mut curve = base.report.curve.clone();
    curve.extend(
        fine.report
            .curve
            .iter()
            .filter(|p| p.iteration > 0)
            .map(|p| CurvePoint {
                iteration: p.iteration + iteration_offset,
                elapsed_ms: p.elapsed_ms + elapsed_offset,
                ..*p
            }),
    );
    let report = AlignReport {
        iterations: iteration_offset + fine.report.iterations,
        rounds: round_offset + fine.report.rounds,
        elapsed_ms: elapsed_offset + fine.report.elapsed_ms,
        cancelled: base.report.cancelled || fine.report.cancelled,
        curve,
        ..fine.report
    };
    Ok(CoarseToFineResult {
        positions: fine.positions,
        report,
        base: base.report,
        subdivide_ms,
    })
}
