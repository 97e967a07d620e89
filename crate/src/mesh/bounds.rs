//! Axis-aligned bounding box of a point set, and its largest side (what unit detection and scale
//! checks read).

use nalgebra::Point3;

/// Bounding box `(min, max)` of `points` (`#P`) in their own units; `None` when empty.
pub fn bounding_box(points: &[Point3<f64>]) -> Option<(Point3<f64>, Point3<f64>)> {
    let first = *points.first()?;
    Some(
        points
            .iter()
            .fold((first, first), |(lo, hi), p| (lo.inf(p), hi.sup(p))),
    )
}

/// The largest side of the [`bounding_box`] of `points`; 0 for an empty set.
pub fn bounding_extent(points: &[Point3<f64>]) -> f64 {
    bounding_box(points).map_or(0.0, |(lo, hi)| (hi - lo).max())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_and_largest_side() {
        let p = [
            Point3::new(1.0, -2.0, 0.5),
            Point3::new(-1.0, 3.0, 0.0),
            Point3::new(0.0, 0.0, 2.0),
        ];
        let (lo, hi) = bounding_box(&p).unwrap();
        assert_eq!(lo, Point3::new(-1.0, -2.0, 0.0));
        assert_eq!(hi, Point3::new(1.0, 3.0, 2.0));
        assert_eq!(bounding_extent(&p), 5.0);
        assert_eq!(bounding_box(&[]), None);
        assert_eq!(bounding_extent(&[]), 0.0);
    }
}
