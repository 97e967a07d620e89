//! Each estimated landmark's confidence in [0, 1]: how far the estimate typically lands from
//! the template's landmark (its mean error on the development subjects, `typical_error.rs`),
//! how far apart independent placements of the landmark's definition lie on a body (its
//! definition's sharpness, `landmarks/sharpness.rs`), and how well the fit went around it.
//!
//! expected = √(typical² + spread²): the estimate's error and the definition's spread are
//! independent, so their squares add.
//! confidence = exp(−expected / `confidence_error` − (residual / `confidence_residual`)²), the
//! residual being the RMS distance to the scan of the fitted vertices within
//! `confidence_radius` of the landmark vertex. Measured against alternatives (the surface's
//! sharpness from the template's normals, the residual alone, no spread) in
//! docs/landmarks-estimate.md; [`spearman`] is the measure.

use nalgebra::Point3;

use super::params::EstimateParams;

/// Template vertices within `radius` of each landmark vertex (rest positions, `#V` metres).
pub fn neighbourhoods(rest: &[Point3<f64>], landmarks: &[u32], radius: f64) -> Vec<Vec<u32>> {
    landmarks
        .iter()
        .map(|&l| {
            let c = rest[l as usize];
            (0..rest.len() as u32)
                .filter(|&v| (rest[v as usize] - c).norm() <= radius)
                .collect()
        })
        .collect()
}

/// The fit's RMS distance (m) to the scan over `neighbours`, from the per-vertex distances;
/// non-finite distances (no scan near) count as `missing` metres.
pub fn residual(distances: &[f64], neighbours: &[u32], missing: f64) -> f64 {
    let sum: f64 = neighbours
        .iter()
        .map(|&v| {
            let d = distances.get(v as usize).copied().unwrap_or(f64::NAN);
            if d.is_finite() {
                d * d
            } else {
                missing * missing
            }
        })
        .sum();
    (sum / neighbours.len().max(1) as f64).sqrt()
}

/// The confidence of a landmark with `typical` error (m) of the estimate, `spread` (m) of
/// independent placements of its definition ([`DefinitionSharpness::spread`]) and local
/// `residual` (m).
///
/// [`DefinitionSharpness::spread`]: crate::landmarks::DefinitionSharpness::spread
pub fn confidence(typical: f64, spread: f64, residual: f64, params: &EstimateParams) -> f64 {
    let expected = typical.hypot(spread);
    (-expected / params.confidence_error - (residual / params.confidence_residual).powi(2)).exp()
}

/// Spearman's rank correlation of `a` and `b` (equal lengths; ties get their mean rank): how
/// well the confidence ranks the measured errors (−1: the highest confidence always has the
/// smallest error). 0 for fewer than two values or a constant series.
pub fn spearman(a: &[f64], b: &[f64]) -> f64 {
    fn ranks(x: &[f64]) -> Vec<f64> {
        let mut order: Vec<usize> = (0..x.len()).collect();
        order.sort_by(|&i, &j| x[i].total_cmp(&x[j]));
        let mut r = vec![0.0; x.len()];
        let mut i = 0;
        while i < order.len() {
            let mut j = i;
            while j + 1 < order.len() && x[order[j + 1]] == x[order[i]] {
                j += 1;
            }
            for &k in &order[i..=j] {
                r[k] = (i + j) as f64 / 2.0;
            }
            i = j + 1;
        }
        r
    }
    let n = a.len().min(b.len());
    if n < 2 {
        return 0.0;
    }
    let (ra, rb) = (ranks(&a[..n]), ranks(&b[..n]));
    let mean = (n - 1) as f64 / 2.0;
    let (mut ab, mut aa, mut bb) = (0.0, 0.0, 0.0);
    for (x, y) in ra.iter().zip(&rb) {
        ab += (x - mean) * (y - mean);
        aa += (x - mean).powi(2);
        bb += (y - mean).powi(2);
    }
    if aa == 0.0 || bb == 0.0 {
        0.0
    } else {
        ab / (aa * bb).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn confidence_falls_with_the_error_the_spread_and_the_residual() {
        let params = EstimateParams::default();
        assert_eq!(confidence(0.0, 0.0, 0.0, &params), 1.0);
        let c = confidence(params.confidence_error, 0.0, 0.0, &params);
        assert!((c - (-1.0f64).exp()).abs() < 1e-12);
        let c = confidence(0.0, params.confidence_error, 0.0, &params);
        assert!((c - (-1.0f64).exp()).abs() < 1e-12);
        let c = confidence(0.0, 0.0, params.confidence_residual, &params);
        assert!((c - (-1.0f64).exp()).abs() < 1e-12);
        // 3-4-5: a 12 mm typical error on a landmark whose placements spread by 9 mm.
        let c = confidence(0.012, 0.009, 0.0, &params);
        assert!((c - (-0.015 / params.confidence_error).exp()).abs() < 1e-12);
        assert!(confidence(0.008, 0.005, 0.004, &params) > confidence(0.03, 0.005, 0.004, &params));
        assert!(confidence(0.01, 0.005, 0.0, &params) > confidence(0.01, 0.025, 0.0, &params));
        let r = residual(&[0.003, f64::NAN, 0.004], &[0, 2], 0.05);
        assert!((r - (0.0000125f64).sqrt()).abs() < 1e-12);
        assert_eq!(residual(&[f64::NAN], &[0], 0.05), 0.05);
    }

    #[test]
    fn neighbourhoods_by_distance() {
        let rest = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(0.01, 0.0, 0.0),
            Point3::new(0.1, 0.0, 0.0),
        ];
        assert_eq!(
            neighbourhoods(&rest, &[0, 2], 0.02),
            vec![vec![0, 1], vec![2]]
        );
    }

    #[test]
    fn spearman_ranks() {
        let a = [1.0, 2.0, 3.0, 4.0];
        assert!((spearman(&a, &[10.0, 20.0, 30.0, 400.0]) - 1.0).abs() < 1e-12);
        assert!((spearman(&a, &[4.0, 3.0, 2.0, 1.0]) + 1.0).abs() < 1e-12);
        // Ties share their mean rank: ranks (0.5, 0.5, 2, 3) against (0, 1, 2, 3).
        let r = spearman(&[1.0, 1.0, 2.0, 3.0], &a);
        assert!((r - 0.9486832980505138).abs() < 1e-12, "{r}");
        assert_eq!(spearman(&[1.0; 3], &a[..3]), 0.0);
        assert_eq!(spearman(&[1.0], &[2.0]), 0.0);
    }
}
