//! Similarity Procrustes (Umeyama 1991): rotation, uniform scale and translation that best map
//! one landmark set onto another, so the scan's own frame and units do not matter to the warp.

use nalgebra::{Matrix3, Point3, Vector3};

use super::checks::{check_finite, check_spread};
use super::error::RbfError;

/// x ↦ s·R·x + t with s > 0 and R a proper rotation (det R = +1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Similarity {
    pub scale: f64,
    pub rotation: Matrix3<f64>,
    pub translation: Vector3<f64>,
}

impl Similarity {
    /// The identity map.
    pub fn identity() -> Self {
        Self {
            scale: 1.0,
            rotation: Matrix3::identity(),
            translation: Vector3::zeros(),
        }
    }

    /// s·R·x + t.
    pub fn apply(&self, x: &Point3<f64>) -> Point3<f64> {
        Point3::from(self.scale * (self.rotation * x.coords) + self.translation)
    }

    /// The inverse map Rᵀ·(y − t)/s.
    pub fn apply_inverse(&self, y: &Point3<f64>) -> Point3<f64> {
        Point3::from(self.rotation.transpose() * (y.coords - self.translation) / self.scale)
    }
}

/// The similarity minimising Σ‖s·R·source_i + t − target_i‖² (Umeyama's closed form).
///
/// Shapes: `source`, `target` n × 3, n ≥ 3, neither collinear. The reflection guard flips the
/// sign of the smallest singular direction when det(U·Vᵀ) < 0, so a mirrored landmark set gives
/// the best proper rotation, never a reflection.
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
    let inv_n = 1.0 / n as f64;
    let mu_x = source.iter().fold(Vector3::zeros(), |s, p| s + p.coords) * inv_n;
    let mu_y = target.iter().fold(Vector3::zeros(), |s, p| s + p.coords) * inv_n;
    let mut var_x = 0.0;
    let mut cov = Matrix3::zeros();
    for (x, y) in source.iter().zip(target) {
        let dx = x.coords - mu_x;
        var_x += dx.norm_squared();
        cov += (y.coords - mu_y) * dx.transpose();
    }
    var_x *= inv_n;
    cov *= inv_n;
    let svd = cov.svd(true, true);
    let (Some(u), Some(v_t)) = (svd.u, svd.v_t) else {
        return Err(RbfError::Degenerate {
            side: "template",
            shape: "numerically degenerate",
            ratio: 0.0,
            purpose: "the Procrustes rotation",
            names: super::error::name_list(names),
        });
    };
    // nalgebra does not sort singular values; the guard must flip the smallest one.
    let d = svd.singular_values;
    let smallest = (0..3).min_by(|&i, &j| d[i].total_cmp(&d[j])).unwrap_or(2);
    let mut s = Vector3::new(1.0, 1.0, 1.0);
    if (u * v_t).determinant() < 0.0 {
        s[smallest] = -1.0;
    }
    let rotation = u * Matrix3::from_diagonal(&s) * v_t;
    let scale = d.component_mul(&s).sum() / var_x;
    let translation = mu_y - scale * (rotation * mu_x);
    Ok(Similarity {
        scale,
        rotation,
        translation,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Rotation3;

    #[test]
    fn recovers_a_rotation_scale_and_translation() {
        let source: Vec<Point3<f64>> = [
            [0.0, 0.0, 0.0],
            [1.0, 0.2, 0.1],
            [0.3, 1.5, -0.2],
            [0.1, 0.4, 0.9],
            [-0.5, 0.7, 0.3],
        ]
        .iter()
        .map(|a| Point3::new(a[0], a[1], a[2]))
        .collect();
        let r = Rotation3::from_euler_angles(0.3, -1.1, 2.0);
        let truth = Similarity {
            scale: 2.5,
            rotation: *r.matrix(),
            translation: Vector3::new(3.0, -4.0, 5.0),
        };
        let target: Vec<_> = source.iter().map(|p| truth.apply(p)).collect();
        let got = similarity(&source, &target).unwrap();
        assert!((got.scale - 2.5).abs() < 1e-12);
        assert!((got.rotation - truth.rotation).norm() < 1e-12);
        assert!((got.translation - truth.translation).norm() < 1e-11);
        for (p, q) in source.iter().zip(&target) {
            assert!((got.apply_inverse(q) - p).norm() < 1e-12);
        }
    }

    #[test]
    fn mirrored_target_gives_a_proper_rotation() {
        let source: Vec<Point3<f64>> = (0..6)
            .map(|i| Point3::new(i as f64, (i * i) as f64 * 0.3, (i % 3) as f64))
            .collect();
        let target: Vec<_> = source.iter().map(|p| Point3::new(-p.x, p.y, p.z)).collect();
        let got = similarity(&source, &target).unwrap();
        assert!((got.rotation.determinant() - 1.0).abs() < 1e-12);
        assert!(got.scale > 0.0 && got.scale.is_finite());
    }

    #[test]
    fn collinear_landmarks_are_reported() {
        let source: Vec<Point3<f64>> = (0..5).map(|i| Point3::new(i as f64, 0.0, 0.0)).collect();
        let err = similarity(&source, &source).unwrap_err();
        assert!(matches!(err, RbfError::Degenerate { .. }), "{err}");
    }
}
