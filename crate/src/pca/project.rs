//! Coefficients of a new mesh in template vertex order: rigid alignment to the model mean (with
//! the model's own pose removal), then B = Φᵀ(x − S̄) for the whole body and every segment.

use super::error::PcaError;
use super::model::BodyModel;
use super::procrustes_gpa::{rigid_align, PoseRemoval};
use super::stitch::Coefficients;
use crate::mesh::similarity::Similarity;
use nalgebra::Point3;

/// Result of [`BodyModel::project`].
#[derive(Debug, Clone, PartialEq)]
pub struct Projection {
    /// Whole-body and all six segment coefficients (model units).
    pub coefficients: Coefficients,
    /// The transform that brought the mesh into the model frame.
    pub pose: Similarity,
    /// Mean per-vertex distance between the aligned mesh and its whole-body reconstruction.
    pub residual: f64,
}

impl BodyModel {
    /// Projects `positions` (`#V` points in template order) onto every model.
    pub fn project(&self, positions: &[Point3<f64>]) -> Result<Projection, PcaError> {
        let v = self.template.vertex_count;
        if positions.len() != v {
            return Err(PcaError::VertexCountMismatch {
                subject: "mesh".into(),
                got: positions.len(),
                expected: v,
            });
        }
        if positions
            .iter()
            .any(|p| !p.coords.iter().all(|c| c.is_finite()))
        {
            return Err(PcaError::NonFinite("mesh".into()));
        }
        let mean: Vec<Point3<f64>> = self
            .whole
            .mean
            .chunks_exact(3)
            .map(|c| Point3::new(c[0] as f64, c[1] as f64, c[2] as f64))
            .collect();
        let pose = match self.settings.gpa.pose {
            PoseRemoval::None => Similarity::identity(),
            PoseRemoval::Rigid => rigid_align(positions, &mean, false),
            PoseRemoval::Similarity => rigid_align(positions, &mean, true),
        };
        let x: Vec<f64> = positions
            .iter()
            .flat_map(|p| {
                let q = pose.apply(p);
                [q.x, q.y, q.z]
            })
            .collect();
        let whole = self.whole.project_flat(&x);
        let segments = std::array::from_fn(|s| {
            let model = &self.segments[s];
            let sub: Vec<f64> = model
                .vertex_indices
                .iter()
                .flat_map(|&i| x[3 * i as usize..3 * i as usize + 3].iter().copied())
                .collect();
            Some(model.project_flat(&sub))
        });
        let rebuilt = self.whole.reconstruct(&whole)?;
        let diff: Vec<f64> = rebuilt.iter().zip(&x).map(|(a, b)| a - b).collect();
        Ok(Projection {
            coefficients: Coefficients { whole, segments },
            pose,
            residual: super::metrics::mean_vertex_norm(&diff),
        })
    }
}
