//! The body's plane under a hand laid on it (hands on the hips): fitted to the scan's points about
//! the wrist that are not the forearm's. The laid hand lies on it (`laid.rs`); the forearm comes
//! down onto it and levels out onto the hand (`laid_wrist.rs`).

use nalgebra::{Point3, Vector3};

use crate::estimate::params::LaidHandParams;
use crate::mesh::principal_axes::principal_axes;

/// The body's plane about the `wrist` of an arm bent onto it (from `elbow`): fitted to the
/// `scan`'s points within `params.region` of the wrist and farther than `params.forearm_clearance`
/// from the forearm. Those points (from the wrist) and the plane's unit normal, on the elbow's
/// side; `None` with fewer than 30 points.
pub(super) fn body_plane(
    wrist: Point3<f64>,
    elbow: Point3<f64>,
    scan: &[Point3<f64>],
    params: &LaidHandParams,
) -> Option<(Vec<Vector3<f64>>, Vector3<f64>)> {
    let near: Vec<Vector3<f64>> = scan
        .iter()
        .filter(|p| {
            (*p - wrist).norm() < params.region
                && off_forearm(p, wrist, elbow, params.forearm_clearance)
        })
        .map(|p| p - wrist)
        .collect();
    if near.len() < 30 {
        return None;
    }
    let points: Vec<Point3<f64>> = near.iter().map(|v| Point3::from(*v)).collect();
    let mut normal: Vector3<f64> = principal_axes(&points)?.column(2).into();
    if normal.dot(&(elbow - wrist)) < 0.0 {
        normal = -normal;
    }
    Some((near, normal))
}

/// Whether `p` lies farther than `clearance` (m) from the forearm (the segment from the
/// `elbow` to the `wrist`).
pub(super) fn off_forearm(
    p: &Point3<f64>,
    wrist: Point3<f64>,
    elbow: Point3<f64>,
    clearance: f64,
) -> bool {
    let forearm = (wrist - elbow).norm();
    let axis = (wrist - elbow) / forearm;
    let t = (p - elbow).dot(&axis).clamp(0.0, forearm);
    (p - (elbow + axis * t)).norm() > clearance
}
