//! Targets of a segment act on its model: the coefficients of one segment model meeting target
//! measurements with the rest of the body held, measured on the stitched body
//! ([`BodyModel::reconstruct`]), and which measurements belong to which segment.
//!
//! A measurement belongs to the segment whose surface it is taken on ([`measurement_segment`];
//! docs/measurements.md): head and neck girth → head (the neck plane lies in the head
//! segment's part of the neck); upper-arm girth and arm length → right arm (both are taken on
//! the right arm); thigh girth and knee height → right leg (the right thigh's loop, the right
//! knee over the right foot); the torso girths, waist-to-hip length and neck base girth → torso
//! (the neck base's plane runs through the torso's triangles, under the head segment's part of
//! the neck). Stature,
//! cervicale, acromion and crotch height run from the floor through several segments, shoulder
//! breadth joins the two arms' acromions, and volume and area cover every segment: they are
//! whole-body targets only. (Anchoring this on
//! the landmarks' blend weights alone puts the acromions in the arms and the crotch and
//! trochanterion, hence thigh girth, in the torso, which is not where those values are taken.)
//! The end-to-end test checks that every segment's model moves each of its measurements.
//!
//! The segment's σ-unit coefficients start where the held body is (its override, or the
//! projection of the whole-body reconstruction onto the segment model) and the Gauss–Newton
//! iteration of [`super::from_measurements`] is regularised towards that start: among the
//! segment shapes that meet the targets, the one that changes the body least in σ units.

use super::from_measurements::{solve, BodyFromMeasurements, FromMeasurementsParams, MeasuredBody};
use crate::measure::{BodyMeasurer, Measure};
use crate::pca::error::PcaError;
use crate::pca::model::BodyModel;
use crate::pca::stitch::{Coefficients, ModeDelta, ModeTarget, StitchPlan};
use crate::template::Segment;

/// The segment whose model a target of `m` acts on (module doc); `None` for a measurement of
/// the whole body.
pub fn measurement_segment(m: Measure) -> Option<Segment> {
    use Measure::*;
    match m {
        HeadGirth | NeckGirth => Some(Segment::Head),
        UpperArmGirth | ArmLength => Some(Segment::RightArm),
        ThighGirth | KneeHeight => Some(Segment::RightLeg),
        ChestGirth | BustGirth | UnderbustGirth | WaistGirth | HipGirth | WaistToHipBack
        | NeckBaseGirth => Some(Segment::Torso),
        Stature | CervicaleHeight | AcromionHeight | CrotchHeight | ShoulderBreadth | Volume
        | SurfaceArea => None,
    }
}

/// The measurements whose targets act on `segment`, [`Measure::ALL`] order.
pub fn segment_measurements(segment: Segment) -> Vec<Measure> {
    Measure::ALL
        .into_iter()
        .filter(|&m| measurement_segment(m) == Some(segment))
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
/// does not act on `segment` ([`measurement_segment`]), and as
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
        if measurement_segment(*m) != Some(segment) {
            let own: Vec<&str> = segment_measurements(segment)
                .iter()
                .map(|m| m.definition().name)
                .collect();
            let own = if own.is_empty() {
                "none: its measurements are taken on the right side".to_string()
            } else {
                own.join(", ")
            };
            return Err(PcaError::BadParameter(format!(
                "{} does not belong to the {} segment (its targets: {own})",
                m.definition().name,
                segment.name(),
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

    fn moved(&self, at: &[f32], k: usize, delta: f64, out: &mut [f32]) -> Result<(), PcaError> {
        out.copy_from_slice(at);
        let change = ModeDelta {
            target: ModeTarget::Segment(self.segment),
            mode: k,
            delta: delta * self.sd[k],
        };
        self.model.apply_delta(&self.plan, change, out)
    }
}
