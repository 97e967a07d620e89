//! The least-squares similarity (or rigid) transform between two corresponding point sets
//! (Umeyama 1991), used by the RBF pre-alignment and by the Procrustes pose removal before PCA.

use nalgebra::{Matrix3, Point3, Vector3};

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

    /// [`Self::apply`] to each of `points` (`#P` in, `#P` out, same order).
    pub fn apply_all(&self, points: &[Point3<f64>]) -> Vec<Point3<f64>> {
        points.iter().map(|p| self.apply(p)).collect()
    }

    /// The inverse map Rᵀ·(y − t)/s.
    pub fn apply_inverse(&self, y: &Point3<f64>) -> Point3<f64> {
        Point3::from(self.rotation.transpose() * (y.coords - self.translation) / self.scale)
    }

    /// x ↦ s·R·x + t with R from the Euler angles `[roll, pitch, yaw]` (radians, as nalgebra's
    /// `Rotation3::from_euler_angles`): a known transform for tests to recover.
    #[cfg(test)]
    pub(crate) fn from_euler_angles(scale: f64, angles: [f64; 3], translation: [f64; 3]) -> Self {
        let [roll, pitch, yaw] = angles;
        Self {
            scale,
            rotation: *nalgebra::Rotation3::from_euler_angles(roll, pitch, yaw).matrix(),
            translation: Vector3::from(translation),
        }
    }
}

/// The transform minimising Σ‖s·R·from_i + t − to_i‖² over proper rotations R, translations t
/// and, when `allow_scale`, scales s > 0 (otherwise s = 1). Umeyama's closed form: with centred
/// points x_i, y_i and H = Σ y_i x_iᵀ = U·diag(σ)·Vᵀ, R = U·S·Vᵀ where S flips the direction of the
/// smallest σ when det(U·Vᵀ) < 0 (a mirrored set gets the best rotation, never a reflection), and
/// s = Σ σ_k S_kk / Σ ‖x_i‖².
///
/// Shapes: `from`, `to` both `#P` points, in correspondence. `None` when the lengths differ, the
/// sets are empty, or the SVD does not converge. Checking that the points are finite and not
/// collinear is the caller's job (a collinear set gives one of the equally good rotations).
pub fn similarity(
    from: &[Point3<f64>],
    to: &[Point3<f64>],
    allow_scale: bool,
) -> Option<Similarity> {
    if from.len() != to.len() || from.is_empty() {
        return None;
    }
    let mu_x = centroid(from);
    let mu_y = centroid(to);
    let mut h = Matrix3::zeros();
    let mut var_x = 0.0;
    for (x, y) in from.iter().zip(to) {
        let dx = x.coords - mu_x;
        h += (y.coords - mu_y) * dx.transpose();
        var_x += dx.norm_squared();
    }
    let svd = h.svd(true, true);
    let (u, sigma, v_t) = (svd.u?, svd.singular_values, svd.v_t?);
    let signs = reflection_guard(&u, &sigma, &v_t);
    let rotation = u * Matrix3::from_diagonal(&signs) * v_t;
    let scale = if allow_scale && var_x > 0.0 {
        sigma.component_mul(&signs).sum() / var_x
    } else {
        1.0
    };
    Some(Similarity {
        scale,
        rotation,
        translation: mu_y - scale * (rotation * mu_x),
    })
}

/// The mean of `points` (zero for an empty set).
pub fn centroid(points: &[Point3<f64>]) -> Vector3<f64> {
    let sum = points.iter().fold(Vector3::zeros(), |a, p| a + p.coords);
    sum / points.len().max(1) as f64
}

/// The diagonal S of Umeyama's R = U·S·Vᵀ: all +1, except −1 at the smallest singular value when
/// det(U·Vᵀ) < 0. The smallest is searched for rather than assumed last, so the guard holds for
/// an SVD in any order (nalgebra documents `new_unordered` as unsorted); among equal smallest
/// values the last is flipped.
fn reflection_guard(u: &Matrix3<f64>, sigma: &Vector3<f64>, v_t: &Matrix3<f64>) -> Vector3<f64> {
    let mut signs = Vector3::new(1.0, 1.0, 1.0);
    if (u * v_t).determinant() < 0.0 {
        let smallest = (0..3)
            .rev()
            .min_by(|&i, &j| sigma[i].total_cmp(&sigma[j]))
            .unwrap_or(2);
        signs[smallest] = -1.0;
    }
    signs
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::test_points::scattered;

    fn residual(t: &Similarity, from: &[Point3<f64>], to: &[Point3<f64>]) -> f64 {
        from.iter()
            .zip(to)
            .map(|(p, q)| (t.apply(p) - q).norm_squared())
            .sum()
    }

    #[test]
    fn recovers_a_known_similarity_and_rigid_fit_keeps_unit_scale() {
        let truth = Similarity::from_euler_angles(2.5, [0.3, -1.1, 2.0], [3.0, -4.0, 5.0]);
        let from = scattered();
        let to = truth.apply_all(&from);
        let got = similarity(&from, &to, true).unwrap();
        assert!((got.scale - 2.5).abs() < 1e-12);
        assert!((got.rotation - truth.rotation).norm() < 1e-12);
        assert!((got.translation - truth.translation).norm() < 1e-11);
        for (p, q) in from.iter().zip(&to) {
            assert!((got.apply_inverse(q) - p).norm() < 1e-12);
        }
        let rigid = similarity(&from, &to, false).unwrap();
        assert_eq!(rigid.scale, 1.0);
        assert!((rigid.rotation - truth.rotation).norm() < 1e-12);
        assert!(similarity(&from, &to[1..], true).is_none());
        assert!(similarity(&[], &[], true).is_none());
    }

    #[test]
    fn mirrored_set_gets_a_proper_rotation() {
        let from = scattered();
        let to: Vec<_> = from.iter().map(|p| Point3::new(-p.x, p.y, p.z)).collect();
        let got = similarity(&from, &to, true).unwrap();
        assert!((got.rotation.determinant() - 1.0).abs() < 1e-12);
        assert!(got.scale > 0.0 && got.scale.is_finite());
    }

    /// The guard must flip the smallest singular direction wherever the SVD puts it. Here the SVD
    /// of a mirrored, anisotropic set is reordered so the smallest σ comes first (a valid SVD of
    /// the same H): flipping column 2 regardless, as a guard that trusts the order would, gives
    /// a worse rotation than flipping the smallest.
    #[test]
    fn reflection_guard_flips_the_smallest_singular_value_in_an_unsorted_svd() {
        // Spread 3 : 2 : 1 along x, y, z, mirrored in z, so the smallest σ belongs to z.
        let from: Vec<Point3<f64>> = scattered()
            .iter()
            .map(|p| Point3::new(3.0 * p.x, 2.0 * p.y, p.z))
            .collect();
        let to: Vec<_> = from.iter().map(|p| Point3::new(p.x, p.y, -p.z)).collect();
        let (mx, my) = (centroid(&from), centroid(&to));
        let h = from.iter().zip(&to).fold(Matrix3::zeros(), |h, (x, y)| {
            h + (y.coords - my) * (x.coords - mx).transpose()
        });
        let svd = h.svd(true, true);
        let (u, sigma, v_t) = (svd.u.unwrap(), svd.singular_values, svd.v_t.unwrap());
        let smallest = (0..3)
            .min_by(|&i, &j| sigma[i].total_cmp(&sigma[j]))
            .unwrap();
        // Move the smallest singular triple to index 0: still U·diag(σ)·Vᵀ = H.
        let order = [smallest, (smallest + 1) % 3, (smallest + 2) % 3];
        let u2 = Matrix3::from_columns(&order.map(|k| u.column(k).into_owned()));
        let v_t2 = Matrix3::from_rows(&order.map(|k| v_t.row(k).into_owned()));
        let sigma2 = Vector3::from(order.map(|k| sigma[k]));
        assert!((u2 * Matrix3::from_diagonal(&sigma2) * v_t2 - h).norm() < 1e-9);
        assert!(sigma2[0] < sigma2[1] && sigma2[0] < sigma2[2]);

        let rotation_with = |signs: Vector3<f64>| Similarity {
            scale: 1.0,
            rotation: u2 * Matrix3::from_diagonal(&signs) * v_t2,
            translation: Vector3::zeros(),
        };
        let guarded = rotation_with(reflection_guard(&u2, &sigma2, &v_t2));
        let last_flipped = rotation_with(Vector3::new(1.0, 1.0, -1.0));
        let reference = similarity(&from, &to, false).unwrap();
        assert!((guarded.rotation - reference.rotation).norm() < 1e-9);
        let centred = |s: &[Point3<f64>], m: Vector3<f64>| -> Vec<Point3<f64>> {
            s.iter().map(|p| Point3::from(p.coords - m)).collect()
        };
        let (cx, cy) = (centred(&from, mx), centred(&to, my));
        let best = residual(&guarded, &cx, &cy);
        let wrong = residual(&last_flipped, &cx, &cy);
        assert!((last_flipped.rotation.determinant() - 1.0).abs() < 1e-9);
        assert!(
            wrong > best + 1.0,
            "last-column flip {wrong} vs guarded {best}"
        );
    }
}
