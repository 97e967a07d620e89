//! The scan's frame, as candidates: the vertical of a standing body is the principal axis of
//! largest extent, its side-to-side axis the second (shoulders and arms are wider than the body
//! is deep). Which way is up and which way the body faces are ambiguous from the axes alone, so
//! each of the four proper rotations (up ±, facing ±) is a candidate; the fit decides
//! (`candidates.rs`).

use nalgebra::{Matrix3, Point3, Vector3};
use serde::Serialize;

use crate::mesh::principal_axes::principal_axes;
use crate::mesh::similarity::Similarity;

/// One guess of the scan's frame: the similarity that takes the template (metres, y up, facing
/// +z) onto the scan (metres), from the axes and extents alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameCandidate {
    /// Template → scan.
    pub start: Similarity,
}

/// The frame assumed, for the report: the scan directions of the template's up (+y) and facing
/// (+z) axes, and the nearest coordinate axis of each (`"+z"`, `"-y"`, …).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrameReport {
    pub up: [f64; 3],
    pub up_axis: String,
    pub facing: [f64; 3],
    pub facing_axis: String,
}

impl FrameReport {
    /// The frame of a template → scan similarity.
    pub fn of(t: &Similarity) -> Self {
        let up = t.rotation * Vector3::y();
        let facing = t.rotation * Vector3::z();
        Self {
            up: up.into(),
            up_axis: nearest_axis(&up),
            facing: facing.into(),
            facing_axis: nearest_axis(&facing),
        }
    }
}

/// `"+x"`, `"-y"`, … : the coordinate axis nearest to `v`.
pub fn nearest_axis(v: &Vector3<f64>) -> String {
    let k = v.iamax();
    let sign = if v[k] < 0.0 { '-' } else { '+' };
    format!("{sign}{}", ['x', 'y', 'z'][k])
}

/// The four frame candidates: template up (+y) along ±(first axis), template side (+x) along
/// ±(second axis); scale from the extents along up, translation matching the template's
/// [`body_centre`] to the scan's. `None` when the axes cannot be found.
pub fn frame_candidates(
    template: &[Point3<f64>],
    scan: &[Point3<f64>],
) -> Option<Vec<FrameCandidate>> {
    let axes = principal_axes(scan)?;
    let scan_mid = body_centre(scan, &axes, 1);
    let scan_height = extent_along(scan, &axes.column(0).into_owned());
    let template_height = extent_along(template, &Vector3::y());
    if !(scan_height > 0.0 && template_height > 0.0) {
        return None;
    }
    let scale = scan_height / template_height;
    let template_mid = body_centre(template, &Matrix3::identity(), 0);
    let mut candidates = Vec::with_capacity(4);
    for up_sign in [1.0, -1.0] {
        for side_sign in [1.0, -1.0] {
            let up = axes.column(0) * up_sign;
            let side = axes.column(1) * side_sign;
            // Columns: where the template's x, y, z go.
            let rotation = Matrix3::from_columns(&[side, up, side.cross(&up)]);
            let translation = scan_mid - scale * (rotation * template_mid);
            candidates.push(FrameCandidate {
                start: Similarity {
                    scale,
                    rotation,
                    translation,
                },
            });
        }
    }
    Some(candidates)
}

/// Whether two template → scan similarities agree on the frame: the template's up (+y) and its
/// facing (+z) each go within `max_deg` (degrees, `EstimateParams::same_frame_deg`) of the same
/// direction (the candidates differ by half turns; a body's pose by far less).
pub fn same_frame(a: &Similarity, b: &Similarity, max_deg: f64) -> bool {
    same_up(a, b, max_deg) && close(a, b, Vector3::z(), max_deg)
}

/// Whether two template → scan similarities agree on which way is up: the template's up (+y)
/// goes within `max_deg` (degrees) of the same direction.
pub fn same_up(a: &Similarity, b: &Similarity, max_deg: f64) -> bool {
    close(a, b, Vector3::y(), max_deg)
}

/// Whether `a` and `b` take the template's `axis` within `max_deg` (degrees) of each other.
fn close(a: &Similarity, b: &Similarity, axis: Vector3<f64>, max_deg: f64) -> bool {
    (a.rotation * axis).angle(&(b.rotation * axis)) <= max_deg.to_radians()
}

/// The median of `values` (the mean of the two middle ones for an even count, so that the median
/// of the negated values is the negated median; 0 for none). Reorders `values`.
fn median(values: &mut [f64]) -> f64 {
    let n = values.len();
    if n == 0 {
        return 0.0;
    }
    let (below, &mut upper, _) = values.select_nth_unstable_by(n / 2, f64::total_cmp);
    if n % 2 == 1 {
        upper
    } else {
        let lower = below.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        0.5 * (lower + upper)
    }
}

/// The extent of `points` along the unit `axis`.
pub(super) fn extent_along(points: &[Point3<f64>], axis: &Vector3<f64>) -> f64 {
    let (lo, hi) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            let t = p.coords.dot(axis);
            (lo.min(t), hi.max(t))
        });
    hi - lo
}

/// Where a frame candidate centres a body: along the side-to-side axis (column `side` of the
/// orthonormal `axes`) the median of the points' coordinates, along the other two the middle of
/// the extent of `points` (along up the extent also gives the candidate's scale). An arm raised
/// sideways reaches far to one side, and the middle of the extent across moves with it (175 mm
/// from the median on fresh seed 1212's subject 14, an arm at 120°; 13 mm on its neighbour with
/// the arms down); from there the similarity fit settled with the template shrunk to 0.86 and
/// turned 6° (development seed 9090 subject 1, an arm at 104°). The median stays on the trunk.
/// In depth the middle of the extent stays: the median there moved ordinary subjects' landmarks
/// (docs/landmarks-estimate.md, "The frame candidates centred on the trunk").
pub(super) fn body_centre(
    points: &[Point3<f64>],
    axes: &Matrix3<f64>,
    side: usize,
) -> Vector3<f64> {
    let mut centre = Vector3::zeros();
    let mut along: Vec<f64> = Vec::with_capacity(points.len());
    for k in 0..3 {
        let axis = axes.column(k).into_owned();
        along.clear();
        along.extend(points.iter().map(|p| p.coords.dot(&axis)));
        let t = if k == side {
            median(&mut along)
        } else {
            let (lo, hi) = along
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &t| {
                    (lo.min(t), hi.max(t))
                });
            0.5 * (lo + hi)
        };
        centre += axis * t;
    }
    centre
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Rotation3;

    #[test]
    fn a_frame_turned_half_round_is_another_frame() {
        let turn = |axis: Vector3<f64>, deg: f64| Similarity {
            scale: 1.0,
            rotation: *Rotation3::from_scaled_axis(axis * deg.to_radians()).matrix(),
            translation: Vector3::zeros(),
        };
        let a = turn(Vector3::x(), 90.0);
        // The same frame, the body turned 30° and leaning 20°.
        let b = Similarity {
            rotation: *Rotation3::from_scaled_axis(Vector3::y() * 0.5).matrix()
                * *Rotation3::from_scaled_axis(Vector3::z() * 0.35).matrix()
                * a.rotation,
            ..a
        };
        assert!(same_frame(&a, &b, 60.0));
        // Facing the other way, or upside down.
        for axis in [Vector3::y(), Vector3::z()] {
            let c = Similarity {
                rotation: a.rotation * turn(axis, 180.0).rotation,
                ..a
            };
            assert!(!same_frame(&a, &c, 60.0));
        }
    }

    /// A box-shaped "body": 1.8 tall (y), 0.5 wide (x), 0.25 deep (z), sampled on a grid.
    fn body() -> Vec<Point3<f64>> {
        let mut pts = Vec::new();
        for i in 0..10 {
            for j in 0..37 {
                for k in 0..6 {
                    pts.push(Point3::new(
                        i as f64 * 0.05 - 0.2,
                        j as f64 * 0.05,
                        k as f64 * 0.05 - 0.1,
                    ));
                }
            }
        }
        pts
    }

    #[test]
    fn principal_axes_are_ordered_and_proper() {
        let axes = principal_axes(&body()).unwrap();
        assert!(axes.column(0).y.abs() > 0.999, "{axes}");
        assert!(axes.column(1).x.abs() > 0.999, "{axes}");
        assert!((axes.determinant() - 1.0).abs() < 1e-9);
        assert!(principal_axes(&body()[..2]).is_none());
    }

    #[test]
    fn one_of_the_candidates_is_the_true_frame() {
        let template = body();
        let truth = Similarity::from_euler_angles(1.1, [1.2, -0.4, 2.5], [3.0, -1.0, 0.5]);
        let scan = truth.apply_all(&template);
        let candidates = frame_candidates(&template, &scan).unwrap();
        assert_eq!(candidates.len(), 4);
        let best = candidates
            .iter()
            .map(|c| {
                (c.start.rotation - truth.rotation).norm()
                    + (c.start.translation - truth.translation).norm()
                    + (c.start.scale - truth.scale).abs()
            })
            .fold(f64::INFINITY, f64::min);
        assert!(best < 1e-6, "{best}");
        for c in &candidates {
            assert!((c.start.rotation.determinant() - 1.0).abs() < 1e-9);
        }
    }

    #[test]
    fn the_centre_stays_on_the_trunk_when_an_arm_reaches_out() {
        // The box body (x across, y up, z depth; its middle across at x = 0.025) with an "arm"
        // held out 0.7 to +x at shoulder height and a hand above the head: the middle of the
        // extent across moves 0.35 towards the arm, the median a grid step at most.
        let mut pts = body();
        for i in 1..=14 {
            pts.push(Point3::new(0.25 + i as f64 * 0.05, 1.45, 0.0));
        }
        for j in 1..=6 {
            pts.push(Point3::new(0.0, 1.8 + j as f64 * 0.05, 0.0));
        }
        let identity = Matrix3::identity();
        let centre = body_centre(&pts, &identity, 0);
        assert!((centre.x - 0.025).abs() <= 0.05, "{centre}");
        // Along up and in depth, the middles of the extents (0 to 2.1; -0.1 to 0.15).
        assert!((centre.y - 1.05).abs() < 1e-12, "{centre}");
        assert!((centre.z - 0.025).abs() < 1e-12, "{centre}");
        // The same point whichever way the axes point (an even count's median is symmetric).
        let turned = Matrix3::from_columns(&[-Vector3::x(), Vector3::y(), -Vector3::z()]);
        assert!((body_centre(&pts, &turned, 0) - centre).norm() < 1e-12);
        let mut values = [3.0, 1.0, 2.0, 10.0];
        assert_eq!(median(&mut values), 2.5);
        assert_eq!(median(&mut [4.0, -1.0, 7.0]), 4.0);
    }

    #[test]
    fn report_names_the_nearest_axes() {
        let t = Similarity {
            scale: 1.0,
            rotation: Matrix3::from_columns(&[Vector3::x(), Vector3::z(), -Vector3::y()]),
            translation: Vector3::zeros(),
        };
        let r = FrameReport::of(&t);
        assert_eq!(r.up_axis, "+z");
        assert_eq!(r.facing_axis, "-y");
    }
}
