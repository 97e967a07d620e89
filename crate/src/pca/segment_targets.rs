//! Targets of a segment act on its model: the coefficients of one segment model meeting target
//! measurements with the rest of the body held, measured on the stitched body
//! ([`BodyModel::reconstruct`]), and which measurements belong to which segment.
//!
//! A measurement belongs to the segment holding the largest blend weight summed over the
//! template vertices of its landmarks (head girth → head; upper-arm girth and arm length → right
//! arm; knee height → right leg; chest, waist, hip → torso; the table is in
//! docs/measurements.md). Stature, volume and surface area have no landmarks and belong to the
//! whole body only.
//!
//! The segment's σ-unit coefficients start where the held body is (its override, or the
//! projection of the whole-body reconstruction onto the segment model) and the Gauss–Newton
//! iteration of [`super::from_measurements`] is regularised towards that start: among the
//! segment shapes that meet the targets, the one that changes the body least in σ units.

use super::error::PcaError;
use super::from_measurements::{solve, BodyFromMeasurements, FromMeasurementsParams, MeasuredBody};
use super::model::BodyModel;
use super::stitch::{Coefficients, ModeDelta, ModeTarget, StitchPlan};
use crate::measure::{BodyMeasurer, Measure};
use crate::template::Segment;

/// The segment `m` belongs to (module doc), from `measurer`'s landmark vertices and the
/// per-vertex blend weights `segment_weights` ([`Segment::ALL`] order); `None` for a measurement
/// without landmarks.
pub fn measurement_segment(
    measurer: &BodyMeasurer,
    segment_weights: &[[f32; 6]],
    m: Measure,
) -> Option<Segment> {
    let anchors = measurer.anchor_vertices(m);
    if anchors.is_empty() {
        return None;
    }
    let mut sum = [0.0f64; 6];
    for &v in anchors {
        for (s, &w) in sum.iter_mut().zip(segment_weights.get(v as usize)?) {
            *s += w as f64;
        }
    }
    (0..6)
        .max_by(|&a, &b| sum[a].total_cmp(&sum[b]))
        .filter(|&s| sum[s] > 0.0)
        .map(|s| Segment::ALL[s])
}

/// The measurements that belong to `segment`, [`Measure::ALL`] order.
pub fn segment_measurements(
    measurer: &BodyMeasurer,
    segment_weights: &[[f32; 6]],
    segment: Segment,
) -> Vec<Measure> {
    Measure::ALL
        .into_iter()
        .filter(|&m| measurement_segment(measurer, segment_weights, m) == Some(segment))
        .collect()
}

/// A segment body found: the solver's result (σ-unit coefficients of the segment model) and
/// the full coefficients of the body (the held ones with the segment overridden).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SegmentBodyFromMeasurements {
    pub segment: Segment,
    pub found: BodyFromMeasurements,
    pub coefficients: Coefficients,
}

/// The coefficients of `segment`'s model meeting `targets` on the stitched body of `model`, the
/// other coefficients of `held` (model units) unchanged (module doc). Fails on a target that
/// does not belong to `segment` ([`measurement_segment`]), and as
/// [`super::from_measurements::body_from_measurements`] does.
pub fn segment_body_from_measurements(
    model: &BodyModel,
    segment: Segment,
    held: &Coefficients,
    measurer: &BodyMeasurer,
    targets: &[(Measure, f64)],
    params: &FromMeasurementsParams,
) -> Result<SegmentBodyFromMeasurements, PcaError> {
    for (m, _) in targets {
        if measurement_segment(measurer, &model.segment_weights, *m) != Some(segment) {
            let name = m.definition().name;
            return Err(PcaError::BadParameter(format!(
                "{name} does not belong to the {} segment (its targets: {})",
                segment.name(),
                segment_measurements(measurer, &model.segment_weights, segment)
                    .iter()
                    .map(|m| m.definition().name)
                    .collect::<Vec<_>>()
                    .join(", ")
            )));
        }
    }
    let part = model.segment(segment);
    let start_b = match &held.segments[segment.index()] {
        Some(b) => b.clone(),
        None => part.project_flat(&model.segment_reconstructions(held)?[segment.index()]),
    };
    let mut overridden = held.overridden();
    overridden[segment.index()] = true;
    let body = SegmentBody {
        model,
        segment,
        held,
        plan: model.stitch_plan(overridden),
        sd: part.standard_deviations(),
    };
    let mut start = part.sigma_from_coefficients(&start_b);
    start.resize(part.mode_count(), 0.0);
    let found = solve(&body, start, measurer, targets, params)?;
    let coefficients = body.coefficients(&found.sigma)?;
    Ok(SegmentBodyFromMeasurements {
        segment,
        found,
        coefficients,
    })
}

/// The stitched body as a function of one segment's σ-unit coefficients.
struct SegmentBody<'a> {
    model: &'a BodyModel,
    segment: Segment,
    held: &'a Coefficients,
    plan: StitchPlan,
    sd: Vec<f64>,
}

impl SegmentBody<'_> {
    fn coefficients(&self, z: &[f64]) -> Result<Coefficients, PcaError> {
        let mut c = self.held.clone();
        c.segments[self.segment.index()] = Some(
            self.model
                .segment(self.segment)
                .coefficients_from_sigma(z)?,
        );
        Ok(c)
    }
}

impl MeasuredBody for SegmentBody<'_> {
    fn standard_deviations(&self) -> Vec<f64> {
        self.sd.clone()
    }

    fn body(&self, z: &[f64]) -> Result<Vec<f32>, PcaError> {
        let mut out = vec![0.0f32; 3 * self.model.template.vertex_count];
        self.model
            .reconstruct_into(&self.coefficients(z)?, &mut out)?;
        Ok(out)
    }

    fn moved(
        &self,
        positions: &[f32],
        k: usize,
        delta: f64,
        out: &mut [f32],
    ) -> Result<(), PcaError> {
        out.copy_from_slice(positions);
        let change = ModeDelta {
            target: ModeTarget::Segment(self.segment),
            mode: k,
            delta: delta * self.sd[k],
        };
        self.model.apply_delta(&self.plan, change, out)
    }
}
