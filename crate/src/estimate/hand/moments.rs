//! The surface beyond the wrist as area-weighted points and its moments: whether the scan's is
//! hand-like against the template hand's ([`hand_like`]), and the turn that takes one onto the
//! other ([`hand_rotation`]).

use nalgebra::{Matrix3, Point3, Rotation3, Vector3};

use crate::estimate::params::HandParams;

/// A surface as area-weighted points (triangle centroid, area).
pub type Surface = [(Point3<f64>, f64)];

/// The triangles of `triangles` as area-weighted centroids.
pub(super) fn surface(
    positions: &[Point3<f64>],
    triangles: &[[u32; 3]],
) -> Vec<(Point3<f64>, f64)> {
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| positions[v as usize]);
            let area = (b - a).cross(&(c - a)).norm() / 2.0;
            (Point3::from((a.coords + b.coords + c.coords) / 3.0), area)
        })
        .collect()
}

/// The region beyond a wrist where a hand is looked for: past the plane through `wrist` across
/// `axis` (the forearm's direction, unit) and within `reach` (m) of the wrist.
#[derive(Debug, Clone, Copy)]
pub struct BeyondWrist {
    pub wrist: Point3<f64>,
    pub axis: Vector3<f64>,
    pub reach: f64,
}

/// Area, centroid and covariance (area-weighted) of the part of `surface` in `region`, from
/// `beyond` (m) past the wrist's plane.
fn moments(
    surface: &Surface,
    region: BeyondWrist,
    beyond: f64,
) -> Option<(f64, Point3<f64>, Matrix3<f64>)> {
    let BeyondWrist { wrist, axis, reach } = region;
    let inside = || {
        surface
            .iter()
            .filter(move |(p, _)| (p - wrist).dot(&axis) > beyond && (p - wrist).norm() < reach)
    };
    let area: f64 = inside().map(|(_, a)| a).sum();
    if area <= 0.0 {
        return None;
    }
    let centroid = inside().map(|(p, a)| p.coords * *a).sum::<Vector3<f64>>() / area;
    let covariance = inside()
        .map(|(p, a)| {
            let d = p.coords - centroid;
            d * d.transpose() * *a
        })
        .sum::<Matrix3<f64>>()
        / area;
    Some((area, Point3::from(centroid), covariance))
}

/// Whether the scan's surface (`scan`) in `region` is hand-like: its area within `params.area_range` of the
/// template hand's (`template`) there.
pub fn hand_like(
    region: BeyondWrist,
    template: &Surface,
    scan: &Surface,
    params: &HandParams,
) -> bool {
    match (
        moments(template, region, params.beyond),
        moments(scan, region, params.beyond),
    ) {
        (Some((t, _, _)), Some((s, _, _))) => {
            (params.area_range.0..=params.area_range.1).contains(&(s / t))
        }
        _ => false,
    }
}

/// The rotation about `wrist` that takes the template's hand onto the scan's (the surfaces taken
/// as in [`hand_like`]): the shortest rotation of the template hand's axis (wrist → centroid)
/// onto the scan's, then the turn about it that brings the widest direction across the template
/// hand onto the scan's (the smaller of the two: the direction has no sign). `None` when either
/// has no surface there or the turn exceeds `params.max_turn_deg`.
pub fn hand_rotation(
    region: BeyondWrist,
    template: &Surface,
    scan: &Surface,
    params: &HandParams,
) -> Option<Rotation3<f64>> {
    let wrist = region.wrist;
    let (_, t_centroid, t_cov) = moments(template, region, params.beyond)?;
    let (_, s_centroid, s_cov) = moments(scan, region, params.beyond)?;
    let (t_axis, s_axis) = (t_centroid - wrist, s_centroid - wrist);
    let bend = Rotation3::rotation_between(&t_axis, &s_axis)?;
    let along = s_axis.normalize();
    let across = |cov: &Matrix3<f64>| {
        let flat = Matrix3::identity() - along * along.transpose();
        let eigen = (flat * cov * flat).symmetric_eigen();
        eigen
            .eigenvectors
            .column(eigen.eigenvalues.imax())
            .into_owned()
    };
    let t_across = across(&(bend.matrix() * t_cov * bend.matrix().transpose()));
    let s_across = across(&s_cov);
    let mut angle = t_across
        .cross(&s_across)
        .dot(&along)
        .atan2(t_across.dot(&s_across));
    if angle > std::f64::consts::FRAC_PI_2 {
        angle -= std::f64::consts::PI;
    } else if angle < -std::f64::consts::FRAC_PI_2 {
        angle += std::f64::consts::PI;
    }
    let rotation = Rotation3::new(along * angle) * bend;
    (rotation.angle() <= params.max_turn_deg.to_radians()).then_some(rotation)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimate::hand::P;

    /// A flat hand as a box's surface, area-weighted points 2 mm apart: along +z from 3 cm to
    /// 20 cm beyond a wrist at the origin, 8 cm wide (x), 2 cm thick (y).
    fn hand() -> Vec<(Point3<f64>, f64)> {
        let step = 0.002;
        let mut out = Vec::new();
        let grid = |n: f64| (0..(n / step).round() as usize).map(move |i| (i as f64 + 0.5) * step);
        for z in grid(0.17).map(|z| z + 0.03) {
            for x in grid(0.08).map(|x| x - 0.04) {
                for y in [-0.01, 0.01] {
                    out.push((Point3::new(x, y, z), step * step));
                }
            }
            for y in grid(0.02).map(|y| y - 0.01) {
                for x in [-0.04, 0.04] {
                    out.push((Point3::new(x, y, z), step * step));
                }
            }
        }
        out
    }

    fn moved(
        surface: &Surface,
        f: impl Fn(&Point3<f64>) -> Point3<f64>,
    ) -> Vec<(Point3<f64>, f64)> {
        surface.iter().map(|(p, a)| (f(p), *a)).collect()
    }

    const REACH_M: f64 = 0.25;

    #[test]
    fn a_turned_hand_gives_back_its_rotation() {
        let template = hand();
        // Flexed 25° about the wrist's x axis after a 15° turn about its own axis.
        let turn = Rotation3::from_axis_angle(&Vector3::x_axis(), 25f64.to_radians())
            * Rotation3::from_axis_angle(&Vector3::z_axis(), 15f64.to_radians());
        let scan = moved(&template, |p| turn * p);
        let region = BeyondWrist {
            wrist: Point3::origin(),
            axis: Vector3::z(),
            reach: REACH_M,
        };
        assert!(hand_like(region, &template, &scan, &P));
        let found = hand_rotation(region, &template, &scan, &P).unwrap();
        assert!(found.angle_to(&turn).to_degrees() < 0.5, "{found:?}");
        // The template's own pose: no turn.
        let same = hand_rotation(region, &template, &template, &P).unwrap();
        assert!(same.angle().to_degrees() < 1e-6);
        // Beyond the largest turn believed: none.
        let far = Rotation3::from_axis_angle(&Vector3::x_axis(), 75f64.to_radians());
        let scan = moved(&template, |p| far * p);
        assert!(hand_rotation(region, &template, &scan, &P).is_none());
    }

    #[test]
    fn a_hand_against_the_thigh_is_not_hand_like() {
        let template = hand();
        let region = BeyondWrist {
            wrist: Point3::origin(),
            axis: Vector3::z(),
            reach: REACH_M,
        };
        // The thigh: a wall of skin 3 cm beside the hand, as long as the region.
        let step = 0.004;
        let mut scan = template.clone();
        for i in 0..60 {
            for j in 0..60 {
                let p = Point3::new(0.07, -0.12 + i as f64 * step, j as f64 * step);
                scan.push((p, step * step));
            }
        }
        assert!(!hand_like(region, &template, &scan, &P));
        // Nothing scanned beyond the wrist (a hole): not hand-like either.
        assert!(!hand_like(region, &template, &[], &P));
    }
}
