//! Similarity Procrustes on landmark pairs: the checked entry to [`crate::mesh::similarity`]
//! (rotation, uniform scale and translation, Umeyama 1991) so the scan's own frame and units do
//! not matter to the warp; bad landmarks are reported by name.

use nalgebra::Point3;

pub use crate::mesh::similarity::Similarity;

use super::checks::{check_finite, check_spread};
use super::error::RbfError;

/// The similarity minimising Σ‖s·R·source_i + t − target_i‖² (Umeyama's closed form).
///
/// Shapes: `source`, `target` n × 3, n ≥ 3, finite, neither collinear; a mirrored landmark set
/// gets the best proper rotation, never a reflection.
pub fn similarity(source: &[Point3<f64>], target: &[Point3<f64>]) -> Result<Similarity, RbfError> {
    let names: Vec<String> = (0..source.len()).map(|i| format!("#{i}")).collect();
    similarity_named(&names, source, target)
}

/// [`similarity`] naming the landmarks in its errors.
pub fn similarity_named(
    names: &[String],
    source: &[Point3<f64>],
    target: &[Point3<f64>],
) -> Result<Similarity, RbfError> {
    let n = source.len();
    if target.len() != n || names.len() != n {
        return Err(RbfError::LengthMismatch {
            what: "Procrustes target landmarks",
            expected: n,
            got: target.len().min(names.len()),
        });
    }
    if n < 3 {
        return Err(RbfError::TooFewLandmarks {
            needed: 3,
            got: n,
            purpose: "Procrustes alignment",
            names: super::error::name_list(names),
        });
    }
    check_finite(names, source, "template")?;
    check_finite(names, target, "scan")?;
    check_spread(names, source, 2, "template", "the Procrustes rotation")?;
    check_spread(names, target, 2, "scan", "the Procrustes rotation")?;
    crate::mesh::similarity::similarity(source, target, true).ok_or_else(|| RbfError::Degenerate {
        side: "template",
        shape: "numerically degenerate",
        ratio: 0.0,
        purpose: "the Procrustes rotation",
        names: super::error::name_list(names),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::test_points::scattered;

    #[test]
    fn maps_the_source_onto_a_similar_target() {
        let source = scattered();
        let truth = Similarity::from_euler_angles(0.001, [0.3, -1.1, 2.0], [3.0, -4.0, 5.0]);
        let target = truth.apply_all(&source);
        let got = similarity(&source, &target).unwrap();
        assert!((got.scale - truth.scale).abs() < 1e-15);
        assert!((got.rotation - truth.rotation).norm() < 1e-10);
    }

    #[test]
    fn collinear_and_too_few_landmarks_are_reported() {
        let source: Vec<Point3<f64>> = (0..5).map(|i| Point3::new(i as f64, 0.0, 0.0)).collect();
        let err = similarity(&source, &source).unwrap_err();
        assert!(matches!(err, RbfError::Degenerate { .. }), "{err}");
        let err = similarity(&source[..2], &source[..2]).unwrap_err();
        assert!(matches!(err, RbfError::TooFewLandmarks { .. }), "{err}");
    }
}
