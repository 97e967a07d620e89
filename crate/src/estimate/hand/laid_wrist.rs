//! The wrist of a hand laid on the body: where the forearm, coming down onto the body's plane,
//! levels out onto the hand lying on it.

use nalgebra::{Matrix3, Point3, Vector3};

use super::body_plane::body_plane;
use crate::estimate::params::HandParams;
use crate::template::hand::{mid, wrist_and_axis, Hand};

/// How far (m) the wrist of an arm bent onto the body lies along the forearm's unit `axis` from
/// `wrist`: where the forearm's outer side, falling towards the body's plane (unit `normal`),
/// levels out onto the hand lying on it. Along the axis, from `knee_from` of the way from the
/// `elbow` to `knee_beyond` past the wrist, the highest of the `scan`'s points above the plane
/// within `knee_radius` of the axis, every `knee_step` (`params.laid`); the wrist is the knee of the two
/// straight lines, joined, that fit those heights best (least squares), searched over the
/// slide's range. (The hip beyond the wrist widens the forearm's profile there, which put laid
/// wrists 17–28 mm short; from the knee they are −15…+4 mm along the forearm, 11 of 12 within
/// 5 mm, held-out seeds 7531 and 8383.) `None` when the forearm does not fall at least `knee_turn_deg` more
/// steeply than the hand, or too few heights are found either side.
fn wrist_from_knee(
    wrist: Point3<f64>,
    elbow: Point3<f64>,
    axis: Vector3<f64>,
    normal: Vector3<f64>,
    scan: &[Point3<f64>],
    params: &HandParams,
) -> Option<f64> {
    let laid = &params.laid;
    let (step, max_slide) = (laid.knee_step, params.max_slide);
    let forearm = (wrist - elbow).dot(&axis);
    let from = forearm * laid.knee_from;
    let stations = ((forearm + laid.knee_beyond - from) / step) as usize;
    let mut highest = vec![f64::NEG_INFINITY; stations];
    for p in scan {
        let t = (p - elbow).dot(&axis);
        let k = ((t - from) / step).floor();
        if k < 0.0 || k >= stations as f64 {
            continue;
        }
        if (p - (elbow + axis * t)).norm() < laid.knee_radius {
            let h = &mut highest[k as usize];
            *h = h.max((p - wrist).dot(&normal));
        }
    }
    // (along the axis from the wrist, height)
    let heights: Vec<(f64, f64)> = highest
        .iter()
        .enumerate()
        .filter(|(_, h)| h.is_finite())
        .map(|(k, h)| (from + (k as f64 + 0.5) * step - forearm, *h))
        .collect();
    let fit = |knee: f64| {
        let rows =
            |&(t, _): &(f64, f64)| Vector3::new(1.0, (t - knee).min(0.0), (t - knee).max(0.0));
        let (a, b) = heights
            .iter()
            .fold((Matrix3::zeros(), Vector3::zeros()), |(a, b), x| {
                (a + rows(x) * rows(x).transpose(), b + rows(x) * x.1)
            });
        let line = a.try_inverse()? * b;
        let residual: f64 = heights
            .iter()
            .map(|x| (rows(x).dot(&line) - x.1).powi(2))
            .sum();
        Some((residual, line))
    };
    let enough = |knee: f64| {
        let before = heights.iter().filter(|(t, _)| *t < knee).count();
        before >= laid.knee_min_heights && heights.len() - before >= laid.knee_min_heights
    };
    let steps = (1.5 * max_slide / step).round() as usize;
    let (_, knee, line) = (0..=steps)
        .map(|k| -max_slide / 2.0 + k as f64 * step)
        .filter(|&knee| enough(knee))
        .filter_map(|knee| fit(knee).map(|(r, line)| (r, knee, line)))
        .min_by(|a, b| a.0.total_cmp(&b.0))?;
    // The forearm falls towards the body (its slope negative) and the hand lies flatter.
    let turn = line.z.atan() - line.y.atan();
    (line.y < 0.0 && turn >= laid.knee_turn_deg.to_radians()).then_some(knee)
}

/// How far (m) along the forearm the wrist of `hand` (at `positions`) lies where the forearm,
/// coming down onto the body's plane (`body_plane` of the `scan`), levels out onto the hand
/// lying on it ([`wrist_from_knee`]). `None` when it does not.
pub(super) fn laid_wrist(
    hand: &Hand,
    positions: &[Point3<f64>],
    scan: &[Point3<f64>],
    params: &HandParams,
) -> Option<f64> {
    let (wrist, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    let elbow = mid(positions, hand.epicondyles);
    let (_, normal) = body_plane(wrist, elbow, scan, &params.laid)?;
    wrist_from_knee(wrist, elbow, axis, normal, scan, params)
}
