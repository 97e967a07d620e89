//! Small point sets that the unit tests of several modules share (compiled for tests only).

use nalgebra::Point3;

/// Five points in general position (no three collinear, not coplanar), about a unit apart: a
/// similarity or rigid fit between two copies of them is unique.
pub fn scattered() -> Vec<Point3<f64>> {
    [
        [0.0, 0.0, 0.0],
        [1.0, 0.2, 0.1],
        [0.3, 1.5, -0.2],
        [0.1, 0.4, 0.9],
        [-0.5, 0.7, 0.3],
    ]
    .iter()
    .map(|&a| Point3::from(a))
    .collect()
}

/// A body reduced to five points in the template's frame (metres, y up, facing +z): the feet's
/// midpoint at the origin, the crown, the two shoulders (not quite symmetric) and the belly in
/// front, so that up, left–right and front–back are all determined.
pub fn stick_body() -> Vec<Point3<f64>> {
    vec![
        Point3::new(0.0, 0.0, 0.0),
        Point3::new(0.0, 1.7, 0.0),
        Point3::new(0.3, 1.4, 0.0),
        Point3::new(-0.3, 1.4, 0.05),
        Point3::new(0.0, 1.0, 0.12),
    ]
}
