//! Shape-model quality curves (Styner et al. 2003): compactness, generalization, specificity.
//!
//! Everything is computed in the coordinates of the full model (all N−1 modes, f64), so the
//! leave-one-out models need no new pass over the data: leaving subject i out, the remaining
//! coefficient vectors sⱼ (j ≠ i) are re-centred and decomposed in that small space, and only the
//! residual of the left-out subject is mapped back to vertices (r = Ψρ) to measure it.

use super::gram::SnapshotPca;
use super::random::NormalRng;
use nalgebra::{DMatrix, SymmetricEigen};
use serde::{Deserialize, Serialize};

/// Parameters of [`quality_curves`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct QualityParams {
    /// Generalization and specificity are computed for M = 1..=max_modes (capped by the data);
    /// default 20 (cost grows as max_modes·N²·3V).
    pub max_modes: usize,
    /// Random shapes drawn per M for specificity; default 100.
    pub specificity_samples: usize,
    /// Seed of the specificity samples; default 2007.
    pub seed: u64,
}

impl Default for QualityParams {
    fn default() -> Self {
        Self {
            max_modes: 20,
            specificity_samples: 100,
            seed: 2007,
        }
    }
}

/// Quality curves of one model. `compactness[M−1]` = C(M) for M = 1..=all modes;
/// `generalization[M−1]` / `specificity[M−1]` (mean per-vertex distance, model units) with their
/// standard deviations over left-out subjects / samples.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct QualityCurves {
    pub compactness: Vec<f64>,
    pub generalization: Vec<f64>,
    pub generalization_sd: Vec<f64>,
    pub specificity: Vec<f64>,
    pub specificity_sd: Vec<f64>,
}

/// C(M) = Σ_{i≤M} λᵢ / Σ λᵢ for M = 1..=len.
pub fn compactness(variances: &[f64]) -> Vec<f64> {
    let total: f64 = variances.iter().sum();
    let mut cumulative = 0.0;
    variances
        .iter()
        .map(|v| {
            cumulative += v;
            if total > 0.0 {
                cumulative / total
            } else {
                1.0
            }
        })
        .collect()
}

/// Mean over vertices of ‖rᵥ‖ for a flat `[x0, y0, z0, ...]` residual.
pub fn mean_vertex_norm(r: &[f64]) -> f64 {
    let n = r.len() / 3;
    if n == 0 {
        return 0.0;
    }
    r.chunks_exact(3)
        .map(|c| (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt())
        .sum::<f64>()
        / n as f64
}

fn mean_sd(values: &[f64]) -> (f64, f64) {
    let n = values.len().max(1) as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n;
    (mean, var.sqrt())
}

/// Maps a full-model coefficient vector back to a flat displacement Ψρ.
fn to_vertices(pca: &SnapshotPca, rho: &[f64], out: &mut [f64]) {
    out.iter_mut().for_each(|x| *x = 0.0);
    for (phi, &c) in pca.modes.iter().zip(rho) {
        if c != 0.0 {
            for (o, p) in out.iter_mut().zip(phi) {
                *o += c * p;
            }
        }
    }
}

/// G(M) for M = 1..=min(max_modes, N−2): mean over left-out subjects of the mean per-vertex
/// distance between the subject and its projection on the first M modes of the model built
/// from the other N−1 subjects (same GPA frame). Returns (means, standard deviations).
pub fn generalization(pca: &SnapshotPca, max_modes: usize) -> (Vec<f64>, Vec<f64>) {
    let n = pca.scores.len();
    let k = pca.modes.len();
    let d = pca.mean.len();
    let m_max = max_modes.min(n.saturating_sub(2)).min(k);
    if m_max == 0 {
        return (Vec::new(), Vec::new());
    }
    let mut per_m = vec![Vec::with_capacity(n); m_max];
    let mut residual = vec![0.0; d];
    for i in 0..n {
        let others: Vec<&Vec<f64>> = (0..n).filter(|&j| j != i).map(|j| &pca.scores[j]).collect();
        let mut mu = vec![0.0; k];
        for s in &others {
            for (m, v) in mu.iter_mut().zip(s.iter()) {
                *m += v / others.len() as f64;
            }
        }
        let mut cov: DMatrix<f64> = DMatrix::zeros(k, k);
        for s in &others {
            for a in 0..k {
                let ya = s[a] - mu[a];
                for b in 0..=a {
                    cov[(a, b)] += ya * (s[b] - mu[b]);
                }
            }
        }
        cov.fill_upper_triangle_with_lower_triangle();
        let eigen = SymmetricEigen::new(cov);
        let mut order: Vec<usize> = (0..k).collect();
        order.sort_by(|&a, &b| eigen.eigenvalues[b].total_cmp(&eigen.eigenvalues[a]));
        let mut rho: Vec<f64> = pca.scores[i].iter().zip(&mu).map(|(s, m)| s - m).collect();
        for (m, &e) in order.iter().take(m_max).enumerate() {
            let axis = eigen.eigenvectors.column(e);
            let c: f64 = rho.iter().zip(axis.iter()).map(|(r, a)| r * a).sum();
            for (r, a) in rho.iter_mut().zip(axis.iter()) {
                *r -= c * a;
            }
            to_vertices(pca, &rho, &mut residual);
            per_m[m].push(mean_vertex_norm(&residual));
        }
    }
    per_m.iter().map(|v| mean_sd(v)).unzip()
}

/// S(M) for M = 1..=min(max_modes, modes): `samples` random shapes b ~ N(0, diag(λ₁..λ_M))
/// (the same standard-normal draws for every M), each scored by the mean per-vertex distance
/// to its closest training subject; returns (means, standard deviations) over samples.
pub fn specificity(pca: &SnapshotPca, params: &QualityParams) -> (Vec<f64>, Vec<f64>) {
    let m_max = params.max_modes.min(pca.modes.len());
    let d = pca.mean.len();
    if m_max == 0 || params.specificity_samples == 0 {
        return (Vec::new(), Vec::new());
    }
    let training: Vec<Vec<f64>> = pca
        .scores
        .iter()
        .map(|s| {
            let mut x = vec![0.0; d];
            to_vertices(pca, s, &mut x);
            x
        })
        .collect();
    let mut rng = NormalRng::new(params.seed);
    let mut per_m = vec![Vec::with_capacity(params.specificity_samples); m_max];
    let mut sample = vec![0.0; d];
    let mut diff = vec![0.0; d];
    for _ in 0..params.specificity_samples {
        sample.iter_mut().for_each(|x| *x = 0.0);
        for (m, curve) in per_m.iter_mut().enumerate() {
            let b = rng.next_normal() * pca.variances[m].sqrt();
            for (x, p) in sample.iter_mut().zip(&pca.modes[m]) {
                *x += b * p;
            }
            let closest = training
                .iter()
                .map(|t| {
                    for ((o, a), b) in diff.iter_mut().zip(&sample).zip(t) {
                        *o = a - b;
                    }
                    mean_vertex_norm(&diff)
                })
                .fold(f64::INFINITY, f64::min);
            curve.push(closest);
        }
    }
    per_m.iter().map(|v| mean_sd(v)).unzip()
}

/// All three curves of one model.
pub fn quality_curves(pca: &SnapshotPca, params: &QualityParams) -> QualityCurves {
    let (generalization, generalization_sd) = generalization(pca, params.max_modes);
    let (specificity, specificity_sd) = specificity(pca, params);
    QualityCurves {
        compactness: compactness(&pca.variances),
        generalization,
        generalization_sd,
        specificity,
        specificity_sd,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compactness_accumulates_to_one() {
        let c = compactness(&[3.0, 1.0]);
        assert_eq!(c, vec![0.75, 1.0]);
    }

    #[test]
    fn mean_vertex_norm_of_a_3_4_5_triangle() {
        assert!((mean_vertex_norm(&[3.0, 4.0, 0.0, 0.0, 0.0, 0.0]) - 2.5).abs() < 1e-15);
    }
}
