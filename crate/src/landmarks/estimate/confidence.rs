//! Each estimated landmark's confidence in [0, 1]: how sharply the landmark is defined on the
//! surface (a bony tip or a crease, where the normals turn, is found again on any body; a point
//! on a flat or gently curved stretch slides) times how well the fit went around it.
//!
//! confidence = (½ + ½·sharpness) · exp(−(residual / σ)²), where sharpness = s/(s + s₀) with
//! s the mean of 1 − n·n_j over the template vertices j within `radius` of the landmark vertex
//! (normals of the template at rest), s₀ = [`SHARPNESS_HALF`]; residual is the RMS distance to
//! the scan of the fitted vertices within `radius`, σ = `confidence_residual`.

use nalgebra::{Point3, Vector3};

/// The normal spread s at which the sharpness is ½ (about the spread of a 5 cm sphere cap of
/// 2.5 cm radius, the curvature of a wrist or an ankle).
pub const SHARPNESS_HALF: f64 = 0.03;

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

/// Sharpness in [0, 1) of the surface at `centre` over `neighbours`, from unit `normals`.
pub fn sharpness(normals: &[Vector3<f64>], centre: u32, neighbours: &[u32]) -> f64 {
    let n0 = normals[centre as usize];
    let spread = neighbours
        .iter()
        .map(|&v| 1.0 - n0.dot(&normals[v as usize]))
        .sum::<f64>()
        / neighbours.len().max(1) as f64;
    spread / (spread + SHARPNESS_HALF)
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

/// The confidence from a sharpness and a residual (m), with σ (m).
pub fn confidence(sharpness: f64, residual: f64, sigma: f64) -> f64 {
    (0.5 + 0.5 * sharpness) * (-(residual / sigma).powi(2)).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_is_dull_and_a_fold_is_sharp() {
        let flat = vec![Vector3::z(); 5];
        assert_eq!(sharpness(&flat, 0, &[0, 1, 2, 3, 4]), 0.0);
        let mut fold = flat.clone();
        fold[3] = Vector3::x();
        fold[4] = Vector3::x();
        let s = sharpness(&fold, 0, &[0, 1, 2, 3, 4]);
        assert!(s > 0.9, "{s}");
    }

    #[test]
    fn confidence_falls_with_the_residual() {
        assert_eq!(confidence(1.0, 0.0, 0.004), 1.0);
        assert_eq!(confidence(0.0, 0.0, 0.004), 0.5);
        let c = confidence(1.0, 0.004, 0.004);
        assert!((c - (-1.0f64).exp()).abs() < 1e-12);
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
}
