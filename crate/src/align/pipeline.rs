//! The whole alignment of one scan, in one place: scan → units → (parts posed, `pose_parts`) →
//! RBF warp (paper §3.1) → data
//! weights and landmark anchors → scan index → fine alignment (§3.2), coarse to fine at the `fine`
//! resolution → report. The command line, the WASM bindings, the examples and the tests all call
//! [`align_scan`]; nothing else assembles this chain.
//!
//! Frames and units: the scan and its landmarks come in the scan's own frame and units; the
//! pipeline scales them to metres (given units, or detected from the body's extent) and works in
//! the scan's frame in metres from then on. Every position it returns is in that frame, in metres,
//! in template vertex order; [`Alignment::scale_to_metres`] converts back to the scan's units.

use std::borrow::Cow;

use nalgebra::Point3;
use thiserror::Error;

use super::alignment_report::{AlignmentReport, FineReport, WarpReport};
use super::anchors::landmark_anchors;
use super::coarse_to_fine::{coarse_to_fine_align, CoarseToFineInput};
use super::correspondence::correspondence_report;
use super::error::AlignError;
use super::fine_align::fine_align;
use super::fine_input::FineAlignInput;
use super::observer::AlignObserver;
use super::params::AlignParams;
use super::part_pose::pose_parts;
use super::report::{AlignReport, ScanDistance};
use super::surface_index::SurfaceIndex;
use super::weights::data_weights;
use crate::landmarks::LandmarkSet;
use crate::mesh::bounding_extent;
use crate::mesh::units::{detect_units, Units};
use crate::mesh::Mesh;
use crate::rbf::{rbf_warp_mesh, RbfError};
use crate::template::{Resolution, Template};
use crate::utils::now_ms;

/// What one alignment works on.
#[derive(Debug, Clone, Copy)]
pub struct AlignInput<'a> {
    /// The template at the resolution to align (`base`, or `fine`: aligned coarse to fine).
    pub template: &'a Template,
    /// At `fine`: the same template at `base`, when the caller keeps one (it is made from
    /// `template` otherwise).
    pub base_template: Option<&'a Template>,
    /// The scan, in its own frame and units.
    pub scan: &'a Mesh,
    /// The scan's landmarks, in the scan's frame and units (missing ones are skipped).
    pub landmarks: &'a LandmarkSet,
    /// The scan's units; `None` detects them from the body's extent ([`detect_units`]).
    pub units: Option<Units>,
}

/// Why an alignment did not run; each message names the step and what to do.
#[derive(Debug, Error)]
pub enum PipelineError {
    /// The RBF warp refused (too few landmarks, a degenerate configuration, a bad kernel…).
    #[error("RBF warp: {0}")]
    Warp(#[from] RbfError),
    /// The scan cannot be indexed for closest points (no triangles, bad indices, NaN).
    #[error("{0}")]
    Scan(AlignError),
    /// Fine alignment refused its parameters or inputs.
    #[error("fine alignment: {0}")]
    Align(#[from] AlignError),
}

/// A finished (or cancelled) alignment.
#[derive(Debug, Clone)]
pub struct Alignment {
    /// `#V` fitted template positions (the warped ones with `rough_only`): metres, the scan's
    /// frame, template order.
    pub positions: Vec<Point3<f64>>,
    /// The RBF-warped template that fine alignment started from (at `fine`: the base template),
    /// metres, the scan's frame.
    pub warped: Vec<Point3<f64>>,
    /// `#V` signed distance (metres) of each fitted vertex to the scan (empty with `rough_only`).
    pub per_vertex_distance: Vec<f64>,
    /// Each scan vertex's distance to the fit and the template vertex nearest it (empty with
    /// `rough_only`).
    pub scan_distances: Vec<ScanDistance>,
    /// The factor that took the scan's units to metres (divide by it to write in scan units).
    pub scale_to_metres: f64,
    /// Everything the run measured, ready for JSON.
    pub report: AlignmentReport,
}

impl Alignment {
    /// Adds the correspondence error against `truth` (true template positions, at least the base
    /// vertices, metres, the scan's frame) to the report.
    pub fn compare_with_truth(&mut self, template: &Template, truth: &[Point3<f64>]) {
        self.report.correspondence = Some(correspondence_report(
            template,
            &self.warped,
            &self.positions,
            truth,
        ));
    }
}

/// Aligns `input.template` to `input.scan`: the RBF warp of the (base) template by the landmarks,
/// then — unless `params.rough_only` — fine alignment, coarse to fine when the template is at
/// `fine`. `observer` hears every iteration (a `Break` cancels: the result is the last accepted
/// iterate, flagged `cancelled` in the report) and every round's surface.
pub fn align_scan(
    input: &AlignInput<'_>,
    params: &AlignParams,
    observer: &mut dyn AlignObserver,
) -> Result<Alignment, PipelineError> {
    let started = now_ms();
    params.validate()?;
    let template = input.template;
    // A rough-only run warps the template at its own resolution; a full run at `fine` warps and
    // fits the base template first.
    let coarse_to_fine = template.refinement().filter(|_| !params.rough_only);
    let warped_template: Cow<Template> = match (coarse_to_fine, input.base_template) {
        (None, _) => Cow::Borrowed(template),
        (Some(_), Some(base)) => Cow::Borrowed(base),
        (Some(_), None) => Cow::Owned(template.at_resolution(Resolution::Base)),
    };

    let units = input
        .units
        .unwrap_or_else(|| detect_units(bounding_extent(&input.scan.positions)));
    let to_m = units.scale_to_metres();
    let scan = Mesh::new(
        input.scan.positions.iter().map(|p| p * to_m).collect(),
        input.scan.triangles.clone(),
    );
    let landmarks = input.landmarks.scaled(to_m);

    let posed = params
        .pose_parts
        .then(|| pose_parts(&warped_template, &landmarks))
        .flatten();
    let (start, start_landmarks) = match posed {
        Some((positions, posed_landmarks)) => (
            Cow::Owned(Mesh::new(
                positions,
                warped_template.mesh().triangles.clone(),
            )),
            posed_landmarks,
        ),
        None => (
            Cow::Borrowed(warped_template.mesh()),
            warped_template.landmark_positions(),
        ),
    };
    let warp = rbf_warp_mesh(&start, &start_landmarks, &scan, &landmarks, &params.rbf)?;
    let rough_ms = now_ms() - started;
    let anchors = landmark_anchors(&warped_template, &warp.positions, &warp.pairing.used);
    let mut report = AlignmentReport {
        template_resolution: template.resolution().name(),
        coarse_to_fine: coarse_to_fine.is_some(),
        template_vertices: template.mesh().positions.len(),
        scan_vertices: scan.positions.len(),
        units,
        units_detected: input.units.is_none(),
        params: params.clone(),
        warp: WarpReport::of(&warp, &params.rbf),
        anchors: anchors.len(),
        fine: None,
        correspondence: None,
        rough_ms,
        index_ms: 0.0,
        total_ms: rough_ms,
    };
    if params.rough_only {
        return Ok(Alignment {
            positions: warp.positions.clone(),
            warped: warp.positions,
            per_vertex_distance: Vec::new(),
            scan_distances: Vec::new(),
            scale_to_metres: to_m,
            report,
        });
    }

    let index_start = now_ms();
    let index = SurfaceIndex::new(&scan).map_err(PipelineError::Scan)?;
    report.index_ms = now_ms() - index_start;
    let weights = data_weights(template, params.fine.sole_weight);
    let base_input = FineAlignInput {
        positions: &warp.positions,
        triangles: &warped_template.mesh().triangles,
        scan: &index,
        weights: &weights[..warp.positions.len()],
        anchors: &anchors,
    };
    let (positions, (per_vertex_distance, scan_distances), fine) = match coarse_to_fine {
        None => {
            let result = fine_align(&base_input, &params.fine, observer)?;
            let fine = FineReport::of(&result.report, true);
            (result.positions, distances(result.report), fine)
        }
        Some(refinement) => {
            let result = coarse_to_fine_align(
                &CoarseToFineInput {
                    base: base_input,
                    refinement,
                    fine_weights: &weights,
                },
                &params.fine,
                &params.fine_stage,
                observer,
            )?;
            let fine = FineReport::of_coarse_to_fine(&result, params.fine_stage.max_iterations);
            (result.positions, distances(result.report), fine)
        }
    };
    report.fine = Some(fine);
    report.total_ms = now_ms() - started;
    Ok(Alignment {
        positions,
        warped: warp.positions,
        per_vertex_distance,
        scan_distances,
        scale_to_metres: to_m,
        report,
    })
}

/// A fine alignment's per-vertex distances both ways, taken out of its report.
fn distances(report: AlignReport) -> (Vec<f64>, Vec<ScanDistance>) {
    (report.per_vertex_distance, report.scan_distances)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::align::FineAlignParams;

    #[test]
    fn defaults_survive_a_json_round_trip_and_partial_json_keeps_them() {
        let defaults = AlignParams::default();
        let json = serde_json::to_string(&defaults).unwrap();
        // Infinity (max_match_distance) is written as null and read back as infinity.
        let back: AlignParams = serde_json::from_str(&json).unwrap();
        assert_eq!(back, defaults);
        let partial: AlignParams =
            serde_json::from_str(r#"{"fine": {"a": 0.5}, "rbf": {"lambda": 0.1}}"#).unwrap();
        assert_eq!(partial.fine.a, 0.5);
        assert_eq!(partial.fine.b, defaults.fine.b);
        assert_eq!(partial.rbf.lambda, 0.1);
        assert_eq!(partial.rbf.kernel, defaults.rbf.kernel);
        assert_eq!(partial.fine_stage, defaults.fine_stage);
    }

    #[test]
    fn bad_parameters_are_refused_before_any_work() {
        let params = AlignParams {
            fine: FineAlignParams {
                b: -1.0,
                ..FineAlignParams::default()
            },
            ..AlignParams::default()
        };
        let err = params.validate().unwrap_err();
        assert!(err.to_string().contains("b = -1"), "{err}");
    }
}
