//! The marginal of a shape model on a subset of its vertices: the PCA of the part of the body
//! the model describes there, without the training data (a segment model from a whole-body
//! model that arrived without its segments, e.g. a statismo file).

use nalgebra::{DMatrix, SymmetricEigen};

use super::shape_model::ShapeModel;

/// The marginal of `whole` on the vertices `subset`: the PCA of the Gaussian S̄ₛ + Φₛ·B,
/// B ~ N(0, Λ), where Φₛ are the basis rows of the subset. With D = √Λ and G = ΦₛᵀΦₛ (k × k),
/// the eigenpairs (σⱼ, vⱼ) of DGD give the segment's variances σⱼ and orthonormal modes
/// ψⱼ = ΦₛDvⱼ/√σⱼ; a subject's segment coefficients are ψⱼᵀΦₛbᵢ = vⱼᵀDGbᵢ/√σⱼ. Eigenvalues below
/// 1e-12 of the largest are dropped.
pub fn marginal(whole: &ShapeModel, subset: Vec<u32>, subjects: usize) -> ShapeModel {
    let k = whole.mode_count();
    let rows = 3 * subset.len();
    let phi = DMatrix::from_fn(rows, k, |r, j| {
        whole.mode(j)[3 * subset[r / 3] as usize + r % 3] as f64
    });
    let g = phi.transpose() * &phi;
    let d = nalgebra::DVector::from_iterator(k, whole.variances.iter().map(|l| l.sqrt()));
    let dgd = DMatrix::from_fn(k, k, |a, b| d[a] * g[(a, b)] * d[b]);
    let eigen = SymmetricEigen::new(dgd);
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_by(|&a, &b| eigen.eigenvalues[b].total_cmp(&eigen.eigenvalues[a]));
    let largest = order.first().map_or(0.0, |&j| eigen.eigenvalues[j]);
    let kept: Vec<usize> = order
        .into_iter()
        .filter(|&j| eigen.eigenvalues[j] > 1e-12 * largest && largest > 0.0)
        .collect();
    let variances: Vec<f64> = kept.iter().map(|&j| eigen.eigenvalues[j]).collect();
    let mut basis = Vec::with_capacity(kept.len() * rows);
    let mut weights = Vec::with_capacity(kept.len());
    for (&j, s) in kept.iter().zip(&variances) {
        let w = d.component_mul(&eigen.eigenvectors.column(j)) / s.sqrt();
        basis.extend((&phi * &w).iter().map(|&x| x as f32));
        weights.push(w);
    }
    let mut scores = vec![0.0f32; subjects * kept.len()];
    for i in 0..subjects {
        let b = nalgebra::DVector::from_iterator(
            k,
            whole.scores[i * k..(i + 1) * k].iter().map(|&x| x as f64),
        );
        let gb = &g * b;
        for (j, w) in weights.iter().enumerate() {
            scores[i * kept.len() + j] = w.dot(&gb) as f32;
        }
    }
    let mean = subset
        .iter()
        .flat_map(|&i| {
            whole.mean[3 * i as usize..3 * i as usize + 3]
                .iter()
                .copied()
        })
        .collect();
    ShapeModel::with_all_modes_kept(subset, mean, basis, variances, scores)
}
