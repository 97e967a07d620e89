//! PCA by the N×N Gram ("snapshot") method (Sirovich 1987): exact and cheap when the number of
//! subjects N is far below the number of coordinates D = 3V.
//!
//! With centred data rows cᵢ = xᵢ − x̄ (N × D), the Gram matrix G = C·Cᵀ (N × N) has eigenpairs
//! (gₖ, uₖ); the covariance C ᵀC/(N−1) then has eigenvalues λₖ = gₖ/(N−1) with orthonormal
//! eigenvectors (modes) φₖ = Cᵀuₖ/√gₖ, and subject i's coefficient on mode k is √gₖ·uᵢₖ.

use nalgebra::{DMatrix, SymmetricEigen};

/// Eigenvalues below this fraction of the largest are numerically zero (rank deficiency).
const RANK_TOLERANCE: f64 = 1e-12;

/// All numerically non-zero modes of a data set, in descending order of variance.
#[derive(Debug, Clone)]
pub struct SnapshotPca {
    /// x̄, length D.
    pub mean: Vec<f64>,
    /// φₖ, each of length D, orthonormal; at most N−1 of them.
    pub modes: Vec<Vec<f64>>,
    /// λₖ = gₖ/(N−1), descending.
    pub variances: Vec<f64>,
    /// N rows of coefficients bᵢ (one per mode): xᵢ = x̄ + Σₖ bᵢₖ φₖ.
    pub scores: Vec<Vec<f64>>,
}

/// Snapshot PCA of `data` (N rows of equal length D). The caller guarantees N ≥ 2.
pub fn snapshot_pca(data: &[Vec<f64>]) -> SnapshotPca {
    let n = data.len();
    let d = data.first().map_or(0, |r| r.len());
    let mut mean = vec![0.0; d];
    for row in data {
        for (m, x) in mean.iter_mut().zip(row) {
            *m += x;
        }
    }
    mean.iter_mut().for_each(|m| *m /= n as f64);
    let centred: Vec<Vec<f64>> = data
        .iter()
        .map(|row| row.iter().zip(&mean).map(|(x, m)| x - m).collect())
        .collect();
    let mut gram = DMatrix::zeros(n, n);
    for i in 0..n {
        for j in 0..=i {
            let g: f64 = centred[i].iter().zip(&centred[j]).map(|(a, b)| a * b).sum();
            gram[(i, j)] = g;
            gram[(j, i)] = g;
        }
    }
    let eigen = SymmetricEigen::new(gram);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| eigen.eigenvalues[b].total_cmp(&eigen.eigenvalues[a]));
    let largest = eigen.eigenvalues[order[0]].max(0.0);
    let mut modes = Vec::new();
    let mut variances = Vec::new();
    let mut scores = vec![Vec::new(); n];
    for &k in order.iter().take(n - 1) {
        let g = eigen.eigenvalues[k];
        if largest <= 0.0 || g <= RANK_TOLERANCE * largest {
            break;
        }
        let root = g.sqrt();
        let u = eigen.eigenvectors.column(k);
        let mut phi = vec![0.0; d];
        for (i, row) in centred.iter().enumerate() {
            let w = u[i] / root;
            for (p, c) in phi.iter_mut().zip(row) {
                *p += w * c;
            }
        }
        modes.push(phi);
        variances.push(g / (n - 1) as f64);
        for (i, s) in scores.iter_mut().enumerate() {
            s.push(root * u[i]);
        }
    }
    SnapshotPca {
        mean,
        modes,
        variances,
        scores,
    }
}

/// Number of leading modes whose cumulative variance reaches `threshold` (0 < threshold ≤ 1) of
/// the total, capped at `max_modes`. A threshold of 1 keeps every mode.
pub fn modes_for_variance(variances: &[f64], threshold: f64, max_modes: Option<usize>) -> usize {
    let cap = max_modes.unwrap_or(usize::MAX).min(variances.len());
    let total: f64 = variances.iter().sum();
    if threshold >= 1.0 || total <= 0.0 {
        return cap;
    }
    let mut cumulative = 0.0;
    for (k, v) in variances.iter().enumerate() {
        cumulative += v;
        if cumulative >= threshold * total * (1.0 - 1e-12) {
            return (k + 1).min(cap);
        }
    }
    cap
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snapshot_pca_matches_a_hand_computed_case() {
        // Two-coordinate data along (1, 1)/√2 with values ±1, ±3: covariance eigenvalue 20/3.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let data: Vec<Vec<f64>> = [-3.0, -1.0, 1.0, 3.0]
            .iter()
            .map(|t| vec![1.0 + t * s, 2.0 + t * s])
            .collect();
        let pca = snapshot_pca(&data);
        assert_eq!(pca.modes.len(), 1);
        assert!((pca.variances[0] - 20.0 / 3.0).abs() < 1e-12);
        assert!((pca.modes[0][0].abs() - s).abs() < 1e-12);
        assert!((pca.scores[3][0].abs() - 3.0).abs() < 1e-12);
        assert!((pca.mean[0] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn variance_threshold_counts_modes() {
        let v = [6.0, 3.0, 0.9, 0.1];
        assert_eq!(modes_for_variance(&v, 0.9, None), 2);
        assert_eq!(modes_for_variance(&v, 0.99, None), 3);
        assert_eq!(modes_for_variance(&v, 1.0, None), 4);
        assert_eq!(modes_for_variance(&v, 0.99, Some(2)), 2);
    }
}
