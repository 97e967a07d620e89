//! Building a body model from aligned subjects: each brought into the template's frame, GPA,
//! then snapshot PCA of the whole body and of each segment, then the quality curves.
//!
//! A model is always built in the template's frame (y up, metres, facing +z), whatever the
//! frames and units of its fits: unless the pose removal is [`PoseRemoval::None`] (shapes used as
//! given), every shape is first mapped there by its units and a rigid fit onto the template's
//! rest shape ([`super::template_frame`]); GPA then removes what pose differences remain.
//!
//! Segment models share the whole-body GPA frame rather than running their own GPA: then every
//! segment reconstruction lives in the same coordinates as the whole body and its neighbours, so
//! stitching is a plain per-vertex blend with no per-segment pose to undo. The price is that a
//! segment model keeps the segment's pose relative to the body as variation — which the paper
//! observes in its own segment modes (§4.2.2: "pose and scale").

use super::error::PcaError;
use super::gram::{modes_for_variance, snapshot_pca, SnapshotPca};
use super::metrics::{quality_curves, QualityCurves};
use super::model::BodyModel;
use super::params::BuildParams;
use super::procrustes_gpa::{generalised_procrustes, PoseRemoval};
use super::segments::{segment_subsets, validate_weights};
use super::shape_model::{ShapeModel, TemplateIdentity};
use super::template_frame::into_template_frame;
use crate::template::Template;
use nalgebra::Point3;

/// Aligned subjects in template vertex order plus what the model must remember of the template.
#[derive(Debug, Clone)]
pub struct TrainingSet {
    pub template: TemplateIdentity,
    pub triangles: Vec<[u32; 3]>,
    /// One `[f32; 6]` per template vertex, [`crate::template::Segment::ALL`] order.
    pub segment_weights: Vec<[f32; 6]>,
    /// The template's rest shape (`template.vertex_count` points, y up, metres, facing +z): the
    /// frame every shape is brought into before GPA.
    pub rest_shape: Vec<Point3<f64>>,
    /// Subject names, same order as `shapes`.
    pub names: Vec<String>,
    /// N shapes of `template.vertex_count` points, each in any frame and in metres,
    /// centimetres or millimetres.
    pub shapes: Vec<Vec<Point3<f64>>>,
}

impl TrainingSet {
    /// The `shapes` (fits in `template`'s vertex order) named `names`, with what the model
    /// keeps of `template`: its identity, triangles, segment weights and rest shape.
    pub fn on_template(
        template: &Template,
        names: Vec<String>,
        shapes: Vec<Vec<Point3<f64>>>,
    ) -> Self {
        let mesh = template.mesh();
        Self {
            template: TemplateIdentity::of_template(template),
            triangles: mesh.triangles.clone(),
            segment_weights: template.segment_weight_table().to_vec(),
            rest_shape: mesh.positions.clone(),
            names,
            shapes,
        }
    }

    fn validate(&self) -> Result<(), PcaError> {
        let v = self.template.vertex_count;
        if self.shapes.len() < 2 {
            return Err(PcaError::TooFewSubjects(self.shapes.len()));
        }
        if self.rest_shape.len() != v {
            return Err(PcaError::BadParameter(format!(
                "the template's rest shape has {} vertices, the template {v}",
                self.rest_shape.len()
            )));
        }
        for (k, shape) in self.shapes.iter().enumerate() {
            let name = self
                .names
                .get(k)
                .cloned()
                .unwrap_or_else(|| format!("#{k}"));
            if shape.len() != v {
                return Err(PcaError::VertexCountMismatch {
                    subject: name,
                    got: shape.len(),
                    expected: v,
                });
            }
            if shape
                .iter()
                .any(|p| !p.coords.iter().all(|c| c.is_finite()))
            {
                return Err(PcaError::NonFinite(name));
            }
        }
        validate_weights(&self.segment_weights, v).map_err(PcaError::BadSegmentWeights)?;
        if self.triangles.iter().flatten().any(|&i| i as usize >= v) {
            return Err(PcaError::BadParameter(format!(
                "a triangle indexes a vertex beyond the template's {v}"
            )));
        }
        Ok(())
    }
}

/// Truncates a full snapshot PCA to the kept modes and stores it in f32.
fn shape_model(
    pca: &SnapshotPca,
    vertex_indices: Vec<u32>,
    params: &BuildParams,
    quality: QualityCurves,
) -> ShapeModel {
    let m = match params.modes {
        Some(n) => n.min(pca.variances.len()),
        None => modes_for_variance(&pca.variances, params.variance, params.max_modes),
    };
    ShapeModel {
        vertex_indices,
        mean: pca.mean.iter().map(|&x| x as f32).collect(),
        basis: pca.modes[..m]
            .iter()
            .flat_map(|phi| phi.iter().map(|&x| x as f32))
            .collect(),
        variances: pca.variances[..m].to_vec(),
        all_variances: pca.variances.clone(),
        scores: pca
            .scores
            .iter()
            .flat_map(|s| s[..m].iter().map(|&x| x as f32))
            .collect(),
        quality,
    }
}

fn model_of(rows: &[Vec<f64>], vertex_indices: Vec<u32>, params: &BuildParams) -> ShapeModel {
    let pca = snapshot_pca(rows);
    let quality = if params.compute_quality {
        quality_curves(&pca, &params.quality)
    } else {
        QualityCurves {
            compactness: super::metrics::compactness(&pca.variances),
            ..QualityCurves::default()
        }
    };
    shape_model(&pca, vertex_indices, params, quality)
}

/// Builds the whole-body model and the six segment models (paper §4, eq. 9) from `set`.
pub fn build_body_model(set: &TrainingSet, params: &BuildParams) -> Result<BodyModel, PcaError> {
    if !(params.variance > 0.0 && params.variance <= 1.0) {
        return Err(PcaError::BadParameter(format!(
            "variance threshold {} is not in (0, 1]",
            params.variance
        )));
    }
    if params.modes == Some(0) {
        return Err(PcaError::BadParameter(
            "a model keeps at least 1 mode (modes = 0)".into(),
        ));
    }
    set.validate()?;
    let framed: Vec<Vec<Point3<f64>>> = if params.gpa.pose == PoseRemoval::None {
        Vec::new()
    } else {
        set.shapes
            .iter()
            .map(|s| into_template_frame(s, &set.rest_shape))
            .collect()
    };
    let shapes = if framed.is_empty() {
        &set.shapes
    } else {
        &framed
    };
    let refs: Vec<&[Point3<f64>]> = shapes.iter().map(|s| s.as_slice()).collect();
    let gpa = generalised_procrustes(&refs, &params.gpa);
    let rows: Vec<Vec<f64>> = gpa
        .aligned
        .iter()
        .map(|s| s.iter().flat_map(|p| [p.x, p.y, p.z]).collect())
        .collect();
    drop(gpa);
    drop(framed);
    let whole = model_of(&rows, Vec::new(), params);
    let segments = segment_subsets(&set.segment_weights)
        .into_iter()
        .map(|subset| {
            let sub_rows: Vec<Vec<f64>> = rows
                .iter()
                .map(|r| {
                    subset
                        .iter()
                        .flat_map(|&v| r[3 * v as usize..3 * v as usize + 3].iter().copied())
                        .collect()
                })
                .collect();
            model_of(&sub_rows, subset, params)
        })
        .collect();
    let names = (0..set.shapes.len())
        .map(|k| set.names.get(k).cloned().unwrap_or_else(|| format!("#{k}")))
        .collect();
    BodyModel::assemble(
        set.template.clone(),
        *params,
        names,
        set.triangles.clone(),
        set.segment_weights.clone(),
        whole,
        segments,
    )
}
