//! Coarse-to-fine fine alignment (paper §3.2 at the `fine` resolution): fit the `base` template
//! with the normal schedule, carry the fitted surface to `fine` through the template's
//! subdivision operator (fine = S · base), then run a short fine-level alignment that only adds
//! the detail the base mesh cannot hold.
//!
//! Why: the base fit does the large, slow part of the work (annealing from the RBF warp, ≈ 28
//! iterations) on 16× fewer vertices; the subdivided fit already lies within the base mesh's
//! chord sag (≈ 0.5 mm) of the scan, so the fine level needs a few rounds at the paper's b and
//! no annealing. Both stages are [`fine_align`]; a and b carry across the resolutions
//! through `reference_edge_length` (docs/fine-alignment.md, "How a and b scale with the mesh").
//! The fine stage keeps the base fit's correspondence: its tangential term holds each vertex
//! along the carried surface, and a fine vertex gets no more data weight than its base sources.

use std::ops::ControlFlow;

use nalgebra::Point3;

use super::error::AlignError;
use super::fine_align::fine_align;
use super::fine_input::FineAlignInput;
use super::observer::{AlignObserver, Progress, Stage};
use super::params::{FineAlignParams, FineStageParams};
use super::report::{AlignReport, CurvePoint};
use crate::template::Subdivision;
use crate::utils::now_ms;

/// The base template's fit and how it is carried to fine.
#[derive(Debug, Clone, Copy)]
pub struct CoarseToFineInput<'a> {
    /// The base stage's input: `#Vb` RBF-warped base template (metres, scan frame), its
    /// triangles, the scan, `#Vb` data weights and landmark anchors (base vertex indices, the
    /// same vertices at fine; both stages use them).
    pub base: FineAlignInput<'a>,
    /// The template's subdivision operator base → fine (its `stencils` are `#Vf`, the first
    /// `#Vb` being the base vertices; its `triangles` are the fine faces).
    pub refinement: &'a Subdivision,
    /// `#Vf` data weights of the fine template (a base vertex has the same flags at both
    /// resolutions, so their first `#Vb` equal the base stage's).
    pub fine_weights: &'a [f64],
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
/// `observer` hears both stages: iterations, rounds and `elapsed_ms` count on from the start of
/// the whole run, `max_iterations` is both stages' limit together; its rounds hand the current
/// surface at the fine resolution (the base stage's surface carried through S), so a caller that
/// may be stopped abruptly holds the last good state at the resolution it shows.
///
/// A cancelled base stage returns its last iterate carried to fine, with the report measured
/// there and `cancelled = true`; a cancelled fine stage returns the fine stage's last iterate.
pub fn coarse_to_fine_align(
    input: &CoarseToFineInput<'_>,
    base_params: &FineAlignParams,
    fine_stage: &FineStageParams,
    observer: &mut dyn AlignObserver,
) -> Result<CoarseToFineResult, AlignError> {
    let start = now_ms();
    let CoarseToFineInput {
        base: base_input,
        refinement,
        fine_weights,
    } = *input;
    let base_count = base_input.positions.len();
    let fine_count = refinement.stencils.len();
    if refinement.base_vertex_count != base_count || fine_count < base_count {
        return Err(AlignError::Refinement {
            base_vertices: base_count,
            operator_base_vertices: refinement.base_vertex_count,
            operator_fine_vertices: fine_count,
        });
    }
    if fine_weights.len() != fine_count {
        return Err(AlignError::WeightCount {
            got: fine_weights.len(),
            expected: fine_count,
        });
    }
    let fine_params = fine_stage.around(base_params);
    fine_params.validate()?;
    let max_iterations = base_params
        .max_iterations
        .saturating_add(fine_params.max_iterations);

    let base = fine_align(
        &base_input,
        base_params,
        &mut Staged {
            outer: observer,
            stage: Stage::Base,
            max_iterations,
            offsets: (0, 0, 0.0),
            refinement: Some(refinement),
        },
    )?;

    let subdivide_start = now_ms();
    let fine_start = refinement.apply(&base.positions);
    let subdivide_ms = now_ms() - subdivide_start;

    // A cancelled base stage still ends at the fine resolution: zero iterations of the fine
    // stage measure the carried surface without moving it.
    let fine_params = if base.report.cancelled {
        FineAlignParams {
            max_iterations: 0,
            ..fine_params
        }
    } else {
        fine_params
    };
    let (iteration_offset, round_offset) = (base.report.iterations, base.report.rounds);
    let elapsed_offset = now_ms() - start;
    // A fine vertex gets no more data weight than the base vertices it is made from: the new
    // vertices on the rim of a never-scanned region stay without data, as the base rim does.
    let fine_weights: Vec<f64> = refinement
        .stencils
        .iter()
        .zip(fine_weights)
        .map(|(stencil, w)| {
            stencil
                .iter()
                .fold(*w, |m, &(v, _)| m.min(base_input.weights[v as usize]))
        })
        .collect();
    let fine = fine_align(
        &FineAlignInput {
            positions: &fine_start,
            triangles: &refinement.triangles,
            weights: &fine_weights,
            ..base_input
        },
        &fine_params,
        &mut Staged {
            outer: observer,
            stage: Stage::Fine,
            max_iterations,
            offsets: (iteration_offset, round_offset, elapsed_offset),
            refinement: None,
        },
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

/// One stage's view of the caller's observer: progress renumbered to count on across the
/// stages, rounds of the base stage carried to fine.
struct Staged<'a, 'b> {
    outer: &'a mut dyn AlignObserver,
    stage: Stage,
    max_iterations: usize,
    /// Iterations, rounds and milliseconds of the stages before this one.
    offsets: (usize, usize, f64),
    /// At the base stage: the operator that carries its surface to fine.
    refinement: Option<&'b Subdivision>,
}

impl AlignObserver for Staged<'_, '_> {
    fn progress(&mut self, p: &Progress) -> ControlFlow<()> {
        let (iterations, rounds, ms) = self.offsets;
        self.outer.progress(&Progress {
            stage: self.stage,
            iteration: p.iteration + iterations,
            max_iterations: self.max_iterations,
            round: p.round + rounds,
            elapsed_ms: p.elapsed_ms + ms,
            ..*p
        })
    }

    fn round(&mut self, _stage: Stage, round: usize, positions: &[Point3<f64>]) {
        let round = round + self.offsets.1;
        match self.refinement {
            Some(s) => self.outer.round(self.stage, round, &s.apply(positions)),
            None => self.outer.round(self.stage, round, positions),
        }
    }
}
