//! The principal axes of a point set: the eigenvectors of its scatter about the centroid. The
//! first is the direction of largest extent (a standing body's vertical, `estimate::
//! frame`); the last is the normal of the plane that fits the points best (the body's surface
//! under a hand on the hip, in the estimate and in the synthetic population).

use nalgebra::{Matrix3, Point3};

use super::similarity::centroid;

/// The principal axes of `points` (`#P`), largest variance first, as the columns of a proper
/// rotation; `None` for fewer than 3 points or a non-finite covariance.
pub fn principal_axes(points: &[Point3<f64>]) -> Option<Matrix3<f64>> {
    if points.len() < 3 {
        return None;
    }
    let mu = centroid(points);
    let mut cov = Matrix3::zeros();
    for p in points {
        let d = p.coords - mu;
        cov += d * d.transpose();
    }
    if !cov.iter().all(|c| c.is_finite()) {
        return None;
    }
    let eigen = cov.symmetric_eigen();
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| eigen.eigenvalues[b].total_cmp(&eigen.eigenvalues[a]));
    let e1 = eigen.eigenvectors.column(order[0]).into_owned();
    let e2 = eigen.eigenvectors.column(order[1]).into_owned();
    Some(Matrix3::from_columns(&[e1, e2, e1.cross(&e2)]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    #[test]
    fn the_last_axis_is_a_planes_normal() {
        // Points on the plane through (1, 2, 3) with normal (1, 1, 1)/√3, spread 4 × 2.
        let normal = Vector3::new(1.0, 1.0, 1.0).normalize();
        let u = Vector3::new(1.0, -1.0, 0.0).normalize();
        let v = normal.cross(&u);
        let points: Vec<Point3<f64>> = (0..40)
            .flat_map(|i| (0..20).map(move |j| (i, j)))
            .map(|(i, j)| {
                Point3::new(1.0, 2.0, 3.0) + u * (f64::from(i) * 0.1) + v * (f64::from(j) * 0.1)
            })
            .collect();
        let axes = principal_axes(&points).unwrap();
        assert!(axes.column(0).dot(&u).abs() > 0.999, "{axes}");
        assert!(axes.column(2).dot(&normal).abs() > 0.999, "{axes}");
    }
}
