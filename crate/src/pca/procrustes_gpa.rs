//! Generalised Procrustes analysis (GPA): removes each subject's rigid pose before PCA.
//!
//! Iterates: align every shape to the current mean by the optimal rotation + translation
//! (Kabsch / Umeyama, optionally with an isotropic scale), then re-average. The mean keeps the
//! orientation of the first subject and, with scaling, the average centroid size of the inputs
//! so coordinates stay in metres.

use nalgebra::{Point3, Vector3};

use crate::mesh::similarity::{centroid, similarity, Similarity};
use serde::{Deserialize, Serialize};

/// Which part of each subject's pose is removed before PCA. Recorded in the model file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum PoseRemoval {
    /// Shapes are used as given (already aligned data, tests).
    None,
    /// Rotation + translation (default: stature stays a mode of variation).
    #[default]
    Rigid,
    /// Rotation + translation + isotropic scale (size is removed from the model).
    Similarity,
}

/// Parameters of [`generalised_procrustes`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GpaParams {
    /// What is removed; default [`PoseRemoval::Rigid`].
    pub pose: PoseRemoval,
    /// Maximum number of align/re-average rounds; default 20.
    pub max_iterations: usize,
    /// Stop when the mean moves less than this RMS distance per vertex (model units); default 1e-7.
    pub tolerance: f64,
}

impl Default for GpaParams {
    fn default() -> Self {
        Self {
            pose: PoseRemoval::Rigid,
            max_iterations: 20,
            tolerance: 1e-7,
        }
    }
}

/// Result of [`generalised_procrustes`]: aligned shapes (same order as the input), the transforms
/// that produced them, the final mean and the number of rounds run.
#[derive(Debug, Clone)]
pub struct GpaResult {
    pub aligned: Vec<Vec<Point3<f64>>>,
    pub transforms: Vec<Similarity>,
    pub mean: Vec<Point3<f64>>,
    pub iterations: usize,
}

/// The transform minimising Σ‖s·R·a_i + t − b_i‖² ([`crate::mesh::similarity`]), with s = 1
/// unless `with_scale`; R is a proper rotation (det = +1). Shapes: `source`, `target` both `#V`.
/// The identity when no transform can be computed (empty or mismatched shapes).
pub fn rigid_align(source: &[Point3<f64>], target: &[Point3<f64>], with_scale: bool) -> Similarity {
    similarity(source, target, with_scale).unwrap_or_else(Similarity::identity)
}

fn centroid_size(points: &[Point3<f64>]) -> f64 {
    let c = centroid(points);
    points
        .iter()
        .map(|p| (p.coords - c).norm_squared())
        .sum::<f64>()
        .sqrt()
}

/// Aligns `shapes` (N shapes of `#V` points each, same vertex order) to their common mean.
/// The caller guarantees N ≥ 1 and equal lengths.
pub fn generalised_procrustes(shapes: &[&[Point3<f64>]], params: &GpaParams) -> GpaResult {
    let n = shapes.len();
    if params.pose == PoseRemoval::None || n == 0 {
        let aligned: Vec<Vec<Point3<f64>>> = shapes.iter().map(|s| s.to_vec()).collect();
        let mean = mean_shape(&aligned);
        return GpaResult {
            aligned,
            transforms: vec![Similarity::identity(); n],
            mean,
            iterations: 0,
        };
    }
    let with_scale = params.pose == PoseRemoval::Similarity;
    let reference_size = shapes.iter().map(|s| centroid_size(s)).sum::<f64>() / n as f64;
    // Start from the first subject, centred, so the model keeps its orientation.
    let c0 = centroid(shapes[0]);
    let mut mean: Vec<Point3<f64>> = shapes[0]
        .iter()
        .map(|p| Point3::from(p.coords - c0))
        .collect();
    let mut transforms = vec![Similarity::identity(); n];
    let mut aligned: Vec<Vec<Point3<f64>>> = Vec::with_capacity(n);
    let mut iterations = 0;
    for _ in 0..params.max_iterations.max(1) {
        iterations += 1;
        aligned.clear();
        for (k, shape) in shapes.iter().enumerate() {
            let t = rigid_align(shape, &mean, with_scale);
            aligned.push(t.apply_all(shape));
            transforms[k] = t;
        }
        let mut new_mean = mean_shape(&aligned);
        if with_scale {
            // Without a fixed size the similarity GPA shrinks the mean towards a point.
            let size = centroid_size(&new_mean);
            if size > 0.0 {
                let f = reference_size / size;
                let c = centroid(&new_mean);
                for p in &mut new_mean {
                    *p = Point3::from((p.coords - c) * f);
                }
            }
        }
        let change = (mean
            .iter()
            .zip(&new_mean)
            .map(|(a, b)| (a - b).norm_squared())
            .sum::<f64>()
            / mean.len().max(1) as f64)
            .sqrt();
        mean = new_mean;
        if change < params.tolerance {
            break;
        }
    }
    // Final pass so aligned shapes and transforms refer to the returned mean.
    aligned.clear();
    for (k, shape) in shapes.iter().enumerate() {
        let t = rigid_align(shape, &mean, with_scale);
        aligned.push(t.apply_all(shape));
        transforms[k] = t;
    }
    let mean = mean_shape(&aligned);
    GpaResult {
        aligned,
        transforms,
        mean,
        iterations,
    }
}

/// Vertex-wise average of equally long shapes.
pub fn mean_shape(shapes: &[Vec<Point3<f64>>]) -> Vec<Point3<f64>> {
    let Some(first) = shapes.first() else {
        return Vec::new();
    };
    let mut sum = vec![Vector3::zeros(); first.len()];
    for s in shapes {
        for (acc, p) in sum.iter_mut().zip(s) {
            *acc += p.coords;
        }
    }
    let inv = 1.0 / shapes.len() as f64;
    sum.into_iter().map(|v| Point3::from(v * inv)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::test_points::scattered;
    use nalgebra::Rotation3;

    #[test]
    fn gpa_removes_rigid_pose() {
        let base = scattered();
        let poses = [(0.0, 0.0, 0.0), (0.2, 0.1, -0.3), (-0.4, 0.9, 0.5)];
        let shapes: Vec<Vec<Point3<f64>>> = poses
            .iter()
            .map(|&(a, b, c)| {
                let r = Rotation3::from_euler_angles(a, b, c);
                base.iter().map(|p| r * p + Vector3::new(a, b, c)).collect()
            })
            .collect();
        let refs: Vec<&[Point3<f64>]> = shapes.iter().map(|s| s.as_slice()).collect();
        let out = generalised_procrustes(&refs, &GpaParams::default());
        for s in &out.aligned {
            for (p, q) in s.iter().zip(&out.mean) {
                assert!((p - q).norm() < 1e-9);
            }
        }
    }
}
