//! Which way a standing body faces, from its feet: a foot reaches forward of its ankle (heel to
//! toe ≈ 25 cm, the ankle ≈ 5–7 cm in front of the heel), so the scan's points at the feet lie,
//! on average, several centimetres forward of those of the lower legs just above them. It holds
//! wherever the feet are on the scan, whatever the arms, the hair or the clothes do to the nearest
//! points; a back-to-front fit had been chosen by 7 % of the similarity's energy on a body with
//! hair (issue 31, the scanner zoo's `hair`).
//!
//! With `up` the body's up (from the head's end, `up.rs`) and the robust extent along it as
//! there (the `EXTENT_PERCENTILE` quantiles of the heights of the triangles' vertices), the feet
//! are the points of `FEET_SLAB` and the lower legs those of `SHIN_SLAB` (fractions of the extent
//! from the bottom). The feet's reach is the difference of the two slabs' centroids along the
//! body's front–back axis `depth` (square to `up`); it says which way is forward when it is at
//! least `decisive` times the extent long. Only that axis is judged: an up tilted by a raised arm
//! (the principal axis leans towards it, in the frontal plane) adds a shift across the body, not
//! along it. Cut feet leave two slabs of the lower legs, which do not reach: the feet do not say.
//! A floor or turntable left under the feet spreads around them and shortens the reach.

use nalgebra::{Point3, Vector3};

use super::up::{quantile, triangulated, EXTENT_PERCENTILE};

/// The feet and the lower legs just above them, fractions of the extent from the bottom (the
/// feet's with every point under the robust bottom).
const FEET_SLAB: (f64, f64) = (0.0, 0.03);
const SHIN_SLAB: (f64, f64) = (0.06, 0.09);

/// The feet's verdict on which way the body faces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeetForward {
    /// Forward (unit, ±`depth` made square to up): the way the feet reach from the lower legs.
    pub forward: Vector3<f64>,
    /// How far (the scan's units) the feet's centroid lies forward of the lower legs' along it.
    pub reach: f64,
}

/// The way along `depth` (the body's front–back axis, any length) that the feet of the body in
/// `positions` (the vertices of `triangles` only) reach, with `up` the way from the feet to the
/// head; `None` when they reach less than `decisive` times the body's extent, or a slab is empty.
pub fn feet_forward(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
    up: &Vector3<f64>,
    depth: &Vector3<f64>,
    decisive: f64,
) -> Option<FeetForward> {
    let up = up.try_normalize(1e-12)?;
    let depth = (depth - up * depth.dot(&up)).try_normalize(1e-12)?;
    let points = triangulated(positions, triangles);
    let heights: Vec<f64> = points.iter().map(|p| p.coords.dot(&up)).collect();
    let lo = quantile(&heights, EXTENT_PERCENTILE)?;
    let extent = quantile(&heights, 1.0 - EXTENT_PERCENTILE)? - lo;
    if extent.is_nan() || extent <= 0.0 {
        return None;
    }
    let centroid = |(a, b): (f64, f64)| {
        let (mut sum, mut count) = (Vector3::zeros(), 0usize);
        for (p, t) in points.iter().zip(&heights) {
            // The feet's slab reaches down past the robust bottom: the soles' lowest points are
            // the feet's.
            let f = (t - lo) / extent;
            if (f >= a || a == 0.0) && f <= b {
                sum += p.coords;
                count += 1;
            }
        }
        (count > 0).then(|| sum / count as f64)
    };
    let along = (centroid(FEET_SLAB)? - centroid(SHIN_SLAB)?).dot(&depth);
    (along.abs() >= decisive * extent).then(|| FeetForward {
        forward: depth * along.signum(),
        reach: along.abs(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Surface points of two legs 0.3 m apart (y up, metres) on feet 0.25 m long reaching
    /// `toes` forward (+z) of the ankles, their heels 0.06 m behind, up to a 1.7 m body; one
    /// triangle over all.
    fn legs(toes: f64) -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
        let mut points = Vec::new();
        for i in 0..171 {
            let y = i as f64 * 0.01;
            for k in 0..24 {
                let a = std::f64::consts::TAU * k as f64 / 24.0;
                for cx in [-0.15, 0.15] {
                    let p = if y < 0.055 {
                        // The foot: an ellipse from the heel to the toes.
                        let (back, front) = (-0.06, toes);
                        let cz = (back + front) / 2.0;
                        Point3::new(cx + 0.045 * a.cos(), y, cz + (front - back) / 2.0 * a.sin())
                    } else {
                        Point3::new(cx + 0.05 * a.cos(), y, 0.05 * a.sin())
                    };
                    points.push(p);
                }
            }
        }
        let n = points.len() as u32;
        let triangles = (0..n / 3).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect();
        (points, triangles)
    }

    #[test]
    fn the_feet_reach_forward_in_any_frame() {
        let (points, triangles) = legs(0.19);
        let turn = nalgebra::Rotation3::from_euler_angles(1.2, -0.4, 2.5);
        let turned: Vec<Point3<f64>> = points.iter().map(|p| turn * p * 1000.0).collect();
        let (up, depth) = (turn * Vector3::y(), turn * Vector3::z());
        // Either way along the front-back axis, and with it leaning 20° off the horizontal.
        for depth in [depth, -depth, depth + 0.36 * up] {
            let feet = feet_forward(&turned, &triangles, &up, &depth, 0.015).expect("the feet say");
            assert!((feet.forward - turn * Vector3::z()).norm() < 1e-6);
            assert!((feet.reach - 65.0).abs() < 1.0, "{}", feet.reach);
        }
        // Across the body they do not reach.
        assert_eq!(
            feet_forward(&turned, &triangles, &up, &(turn * Vector3::x()), 0.015),
            None
        );
    }

    #[test]
    fn feet_that_do_not_reach_do_not_say() {
        // Feet as long forward as back (a foot 0.12 m long centred under the leg).
        let (points, triangles) = legs(0.06);
        let (up, depth) = (Vector3::y(), Vector3::z());
        assert_eq!(feet_forward(&points, &triangles, &up, &depth, 0.015), None);
    }
}
