//! Subjects far outside a model: the Mahalanobis distance of each training subject's
//! coefficients over the kept modes, d = √(Σⱼ bⱼ² / λⱼ), against the χ distribution with as many
//! degrees of freedom as modes (what d would follow for normally distributed bodies). A subject
//! beyond its [`FAR_PROBABILITY`] quantile is listed: a failed fit, a mislabelled file, or a body
//! unlike the rest.

use super::chi_square::chi_square_quantile;
use crate::pca::shape_model::ShapeModel;

/// The share of a normal population inside the threshold; one body in a thousand lies beyond it.
pub const FAR_PROBABILITY: f64 = 0.999;

/// Each training subject's Mahalanobis distance in `model`, in score order.
pub fn mahalanobis_distances(model: &ShapeModel) -> Vec<f64> {
    let modes = model.variances.len();
    if modes == 0 {
        return vec![0.0; model.scores.len()];
    }
    model
        .scores
        .chunks_exact(modes)
        .map(|b| {
            b.iter()
                .zip(&model.variances)
                .map(|(&b, &v)| if v > 0.0 { (b as f64).powi(2) / v } else { 0.0 })
                .sum::<f64>()
                .sqrt()
        })
        .collect()
}

/// The distance beyond which a subject is far outside a model of `modes` modes: √ of the χ²
/// quantile of [`FAR_PROBABILITY`] with as many degrees of freedom ([`chi_square_quantile`]).
pub fn far_threshold(modes: usize) -> f64 {
    chi_square_quantile(modes.max(1), FAR_PROBABILITY).sqrt()
}

/// `(subject index, distance)` of the subjects beyond [`far_threshold`], farthest first.
pub fn far_subjects(model: &ShapeModel) -> Vec<(usize, f64)> {
    let limit = far_threshold(model.variances.len());
    let mut far: Vec<(usize, f64)> = mahalanobis_distances(model)
        .into_iter()
        .enumerate()
        .filter(|(_, d)| *d > limit)
        .collect();
    far.sort_by(|a, b| b.1.total_cmp(&a.1));
    far
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_threshold_is_near_the_exact_chi_square_quantiles() {
        // χ²₀.₉₉₉ for 1, 10 and 20 degrees of freedom: 10.828, 29.588, 45.315.
        for (k, q) in [(10, 29.588), (20, 45.315)] {
            let t = far_threshold(k);
            assert!((t * t - q).abs() / q < 0.01, "k {k}: {} vs {q}", t * t);
        }
        assert!((far_threshold(1).powi(2) - 10.828).abs() / 10.828 < 0.05);
    }

    #[test]
    fn a_subject_many_standard_deviations_out_is_listed_and_the_rest_are_not() {
        let variances = vec![4.0, 1.0];
        // Scores: three ordinary subjects (within 2 σ) and one at 6 σ on each mode.
        let scores: Vec<f32> = vec![2.0, 0.5, -1.0, 1.0, 0.0, -1.5, 12.0, 6.0];
        let model = ShapeModel {
            vertex_indices: Vec::new(),
            mean: Vec::new(),
            basis: Vec::new(),
            variances: variances.clone(),
            all_variances: variances,
            scores,
            quality: Default::default(),
        };
        let d = mahalanobis_distances(&model);
        assert!((d[0] - (1.0f64 + 0.25).sqrt()).abs() < 1e-9);
        assert!((d[3] - (36.0f64 + 36.0).sqrt()).abs() < 1e-9);
        let far = far_subjects(&model);
        assert_eq!(far.len(), 1);
        assert_eq!(far[0].0, 3);
    }
}
