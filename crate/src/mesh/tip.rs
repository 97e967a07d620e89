//! The tip of a surface near a point: where it stands out most from its surroundings in one
//! direction (a nose's tip seen from the front). Standing out from the surroundings, not lying
//! farthest along the direction: a forehead bowed forward lies farther forward than the nose, but
//! it is smooth.

use nalgebra::{Point3, Vector3};

/// Of `points` (spread over a surface) within `radius` of `near`, the one that stands out most
/// along `direction` (unit) from the mean of the points within `surroundings` of it: the tip of
/// the surface there. `None` when no point lies within `radius`.
pub fn tip(
    points: &[Point3<f64>],
    near: &Point3<f64>,
    radius: f64,
    direction: &Vector3<f64>,
    surroundings: f64,
) -> Option<Point3<f64>> {
    let reach = radius + surroundings;
    let local: Vec<&Point3<f64>> = points
        .iter()
        .filter(|p| (*p - near).norm_squared() <= reach * reach)
        .collect();
    let stands_out = |p: &Point3<f64>| {
        let (mut sum, mut count) = (0.0, 0usize);
        for q in &local {
            if (*q - p).norm_squared() <= surroundings * surroundings {
                sum += (p - *q).dot(direction);
                count += 1;
            }
        }
        sum / count as f64
    };
    local
        .iter()
        .filter(|p| (**p - near).norm_squared() <= radius * radius)
        .map(|p| (**p, stands_out(p)))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(p, _)| p)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bump of height 2 cm on the surface z = tilt·y, at (0.03, 0.01), on a 2 mm grid.
    fn bumped_plane(tilt: f64) -> Vec<Point3<f64>> {
        let mut points = Vec::new();
        for i in -50..=50 {
            for j in -50..=50 {
                let (x, y) = (i as f64 * 0.002, j as f64 * 0.002);
                let r2 = (x - 0.03).powi(2) + (y - 0.01).powi(2);
                points.push(Point3::new(x, y, tilt * y + 0.02 * (-r2 / 0.0001).exp()));
            }
        }
        points
    }

    #[test]
    fn finds_the_bump_from_beside_it() {
        let points = bumped_plane(0.0);
        let found = tip(&points, &Point3::origin(), 0.05, &Vector3::z(), 0.02).unwrap();
        assert!(
            (found - Point3::new(0.03, 0.01, 0.02)).norm() < 0.003,
            "{found}"
        );
    }

    #[test]
    fn a_surface_leaning_forward_does_not_outdo_the_bump() {
        // At the far edge the plane lies 3 cm forward, farther than the bump's top.
        let points = bumped_plane(0.4);
        let found = tip(&points, &Point3::origin(), 0.08, &Vector3::z(), 0.02).unwrap();
        assert!(
            (found.x - 0.03).abs() < 0.003 && (found.y - 0.01).abs() < 0.003,
            "{found}"
        );
    }

    #[test]
    fn only_points_within_the_radius_count() {
        let points = bumped_plane(0.0);
        let far = tip(
            &points,
            &Point3::new(-0.06, 0.0, 0.0),
            0.02,
            &Vector3::z(),
            0.02,
        );
        assert!((far.unwrap() - Point3::new(-0.06, 0.0, 0.0)).norm() <= 0.02 + 1e-9);
        assert_eq!(
            tip(
                &points,
                &Point3::new(1.0, 1.0, 0.0),
                0.02,
                &Vector3::z(),
                0.02
            ),
            None
        );
    }
}
