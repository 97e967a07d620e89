//! A hand laid on the body (hands on the hips): the body's plane about the wrist, the raised strip
//! the hand makes on it, the palm across the knuckles' line, tilted as the strip's top slopes.

use nalgebra::{Matrix3, Point3, UnitQuaternion, Vector3};

use super::body_plane::{body_plane, off_forearm};
use super::twist::{twist_about, twist_forearm};
use super::{slide_wrist, HandPose};
use crate::estimate::params::LaidHandParams;
use crate::template::hand::{mid, turn_hand, wrist_and_axis, Hand};

/// The hand of an arm bent more than `SegmentParams::max_bend_deg` (on the hip), or more than
/// `params.min_bend_deg` with
/// its forearm coming down onto the body and levelling out onto it, laid on the body. Its surface
/// is merged with the hip's, so neither its moments nor nearest points say where it points (matched
/// by its own vertices, hands laid on the hip ended 30–100 mm off, the fingers along the forearm or
/// in the hip). What the scan does show: the body's surface under the hand, the hand lying on it as
/// a raised strip, and the forearm coming down onto it. The body's plane about the wrist is fitted
/// by [`body_plane`]. The wrist is slid `along` the forearm (m: to where the forearm levels out
/// onto the hand, `laid_wrist`, else where its profile puts it, `wrist_from_profile`; held
/// where it is with none). Of `params.directions` directions in the plane at the slid wrist
/// within `params.max_bend_deg` of the forearm's, the hand takes the one whose strip
/// (`params.strip`, `params.strip_half_width`) stands farthest out of the plane on average, tilted out of the plane
/// by the slope of the strip's top less that of the template's hand laid flat ([`laid_slope`]), its
/// palm against the plane. The hand turns about the wrist onto that frame (its axis from the wrist
/// to its own vertices' centroid, its palm from that and the knuckles' line, a mirror image on
/// each side: a hand lies on its metacarpals, and the styloids' line is turned ≈ 25° from the
/// knuckles' at rest), and the turn's part about the forearm is carried down the forearm
/// ([`twist_forearm`]).
/// `None` when the region or every strip has too few points and the wrist was not slid; the hand
/// then stays as it was.
pub(super) fn laid_hand(
    hand: &Hand,
    positions: &mut [Point3<f64>],
    along: Option<f64>,
    scan: &[Point3<f64>],
    params: &LaidHandParams,
) -> Option<HandPose> {
    let held = along.unwrap_or(0.0);
    let (_, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    slide_wrist(hand, positions, axis, held);
    let slid = along.map(|_| HandPose {
        slide: held,
        rotation: None,
        stretch: None,
    });
    let (wrist, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    let elbow = mid(positions, hand.epicondyles);
    let Some((near, normal)) = body_plane(wrist, elbow, scan, params) else {
        return slid;
    };
    // The forearm's direction in the plane, and across it.
    let first = (axis - normal * axis.dot(&normal)).try_normalize(1e-9)?;
    let second = normal.cross(&first);
    let raised = |direction: &Vector3<f64>| {
        let across = normal.cross(direction);
        let heights: Vec<f64> = near
            .iter()
            .filter(|v| (params.strip.0..params.strip.1).contains(&v.dot(direction)))
            .filter(|v| v.dot(&across).abs() < params.strip_half_width)
            .map(|v| v.dot(&normal))
            .collect();
        (heights.len() >= 10).then(|| heights.iter().sum::<f64>() / heights.len() as f64)
    };
    let direction = (0..params.directions)
        .map(|k| {
            let angle = std::f64::consts::TAU * k as f64 / params.directions as f64;
            first * angle.cos() + second * angle.sin()
        })
        .filter(|d| d.angle(&axis) <= params.max_bend_deg.to_radians())
        .filter_map(|d| Some((raised(&d)?, d)))
        .max_by(|a, b| a.0.total_cmp(&b.0));
    let Some((_, direction)) = direction else {
        return slid;
    };
    let frame = |along: Vector3<f64>, palm: Vector3<f64>| {
        let palm = (palm - along * palm.dot(&along)).normalize();
        Matrix3::from_columns(&[along, palm, along.cross(&palm)])
    };
    let centroid = hand
        .own
        .iter()
        .map(|&v| positions[v as usize].coords)
        .sum::<Vector3<f64>>()
        / hand.own.len().max(1) as f64;
    let pointing = (Point3::from(centroid) - wrist).normalize();
    let radial = positions[hand.knuckles[0] as usize] - positions[hand.knuckles[1] as usize];
    let mirror = if hand.side == "Lt." { 1.0 } else { -1.0 };
    let palm = pointing.cross(&radial) * mirror;
    // Tilted out of the plane as the hand lies (the body under it is convex): the slope of the
    // scan's strip less that of the template's hand laid flat.
    let own: Vec<Vector3<f64>> = hand
        .own
        .iter()
        .map(|&v| positions[v as usize])
        .filter(|p| off_forearm(p, wrist, elbow, params.forearm_clearance))
        .map(|p| p - wrist)
        .collect();
    let back = -frame(pointing, palm).column(1).into_owned();
    let tilt = laid_slope(&near, normal, direction, params).atan()
        - laid_slope(&own, back, pointing, params).atan();
    let direction = direction * tilt.cos() + normal * tilt.sin();
    let turn = UnitQuaternion::from_matrix(
        &(frame(direction, -normal) * frame(pointing, palm).transpose()),
    );
    turn_hand(hand, positions, wrist, &turn);
    twist_forearm(hand, positions, wrist, axis, twist_about(&turn, &axis));
    Some(HandPose {
        slide: held,
        rotation: Some(turn.to_rotation_matrix()),
        stretch: None,
    })
}

/// The slope (height per length) of the top of the strip a laid hand covers along the unit
/// `direction`, heights along the unit `normal` (of the body's plane; `near` points from the
/// wrist, as [`body_plane`] gives them): the highest point every `params.bin` (m) along
/// `params.strip`, within `params.strip_half_width` across, fitted by a straight line (least
/// squares). The hip under a laid hand curves away from the plane at the wrist, and the hand
/// with it: laid in the plane, hands were bent 2–28° more than the true ones (held-out seeds
/// 7531 and 8383, 12 hands), tilted by this slope (less the template hand's own), 0–6°. 0 with
/// fewer than 4 points.
fn laid_slope(
    near: &[Vector3<f64>],
    normal: Vector3<f64>,
    direction: Vector3<f64>,
    params: &LaidHandParams,
) -> f64 {
    let (strip, bin) = (params.strip, params.bin);
    let across = normal.cross(&direction);
    let bins = ((strip.1 - strip.0) / bin).round() as usize;
    let mut top = vec![f64::NEG_INFINITY; bins];
    for v in near {
        let k = ((v.dot(&direction) - strip.0) / bin).floor();
        if (0.0..bins as f64).contains(&k) && v.dot(&across).abs() < params.strip_half_width {
            let h = &mut top[k as usize];
            *h = h.max(v.dot(&normal));
        }
    }
    let points: Vec<(f64, f64)> = top
        .iter()
        .enumerate()
        .filter(|(_, h)| h.is_finite())
        .map(|(k, h)| (strip.0 + (k as f64 + 0.5) * bin, *h))
        .collect();
    if points.len() < 4 {
        return 0.0;
    }
    let n = points.len() as f64;
    let (mean_t, mean_h) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (t, h)| (a + t / n, b + h / n));
    let (tt, th) = points.iter().fold((0.0, 0.0), |(a, b), (t, h)| {
        (a + (t - mean_t).powi(2), b + (t - mean_t) * (h - mean_h))
    });
    th / tt
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimate::hand::laid_wrist::laid_wrist;
    use crate::estimate::hand::P;
    use crate::template::fixture::{base_body, BaseBody};

    #[test]
    fn a_hand_on_a_surface_is_laid_along_it() {
        let BaseBody { rest, hands, .. } = base_body();
        // The scan's wrist as far along the forearm as the template's, and 3 cm farther.
        for (hand, longer) in hands.iter().flat_map(|h| [(h, 0.0), (h, 0.03)]) {
            // The "scan": the template with this hand bent back 45° at the wrist and turned 30°
            // about the forearm, lying on a plate (a 30 cm square of points 4 mm apart, 1 mm
            // under the palm's lowest point): the body under a hand laid on the hip.
            let mut bent = rest.to_vec();
            let (_, axis) = wrist_and_axis(&bent, hand.styloids, hand.epicondyles);
            slide_wrist(hand, &mut bent, axis, longer);
            let (wrist, axis) = wrist_and_axis(&bent, hand.styloids, hand.epicondyles);
            // The palm across the knuckles' line, as the hand lies on its metacarpals.
            let radial = bent[hand.knuckles[0] as usize] - bent[hand.knuckles[1] as usize];
            let mirror = if hand.side == "Lt." { 1.0 } else { -1.0 };
            let palm = axis.cross(&radial).normalize() * mirror;
            let across = axis.cross(&palm).normalize();
            // Bent back: the fingers towards the back of the hand.
            let back = if (UnitQuaternion::from_scaled_axis(across * 0.1) * axis).dot(&palm) < 0.0 {
                1.0
            } else {
                -1.0
            };
            let turn = UnitQuaternion::from_scaled_axis(axis * 30f64.to_radians())
                * UnitQuaternion::from_scaled_axis(across * (back * 45f64.to_radians()));
            // Folded about the wrist's joint (the capitate's head, 12 mm past the styloids), as
            // the skin creases over an extended wrist.
            let joint = wrist + axis * 0.012;
            for (v, _) in &hand.slide {
                let p = &mut bent[*v as usize];
                if (*p - joint).dot(&axis) > 0.0 {
                    *p = joint + turn * (*p - joint);
                }
            }
            let pointing = |positions: &[Point3<f64>]| {
                let c = hand
                    .own
                    .iter()
                    .map(|&v| positions[v as usize].coords)
                    .sum::<Vector3<f64>>()
                    / hand.own.len() as f64;
                (Point3::from(c) - mid(positions, hand.styloids)).normalize()
            };
            let direction = pointing(&bent);
            let palm = turn * palm;
            // The plate spans the hand's direction and the direction across it.
            let side = direction.cross(&palm);
            let lowest = hand
                .own
                .iter()
                .map(|&v| (bent[v as usize] - wrist).dot(&palm))
                .fold(f64::NEG_INFINITY, f64::max);
            let mut scan = bent.clone();
            for i in -37..=37 {
                for j in -37..=37 {
                    let (a, b) = (f64::from(i) * 0.004, f64::from(j) * 0.004);
                    scan.push(wrist + direction * a + side * b + palm * (lowest + 0.001));
                }
            }
            let farthest = |positions: &[Point3<f64>]| {
                hand.own
                    .iter()
                    .map(|&v| (positions[v as usize] - bent[v as usize]).norm())
                    .fold(0.0, f64::max)
            };
            let mut positions = rest.to_vec();
            let along = laid_wrist(hand, &positions, &scan, &P);
            let pose = laid_hand(hand, &mut positions, along, &scan, &P.laid).unwrap();
            assert!(pose.rotation.is_some());
            // Where the forearm levels out onto the hand: the crease over the extended wrist,
            // within a centimetre of the styloids (-10 and -2 mm here).
            assert!(
                (pose.slide - longer).abs() < 0.012,
                "{}: slid {} m, not {longer}",
                hand.side,
                pose.slide
            );
            // Within the directions' spacing (15°) and the tilt of the hand's back off the plate:
            // 4.7–18.8° and 14–59 mm here (the palm across the knuckles; with the palm across
            // the styloids, in the code and in this scene, 5.8–16.5° and 17–50 mm).
            let off = pointing(&positions).angle(&direction).to_degrees();
            assert!(off < 20.0, "{}: pointing {off:.1}° off", hand.side);
            let (before, after) = (farthest(&rest), farthest(&positions));
            assert!(
                after < 0.06 && after < before / 2.0,
                "{}: {before} → {after} m",
                hand.side
            );
            // With nothing around the wrist, nothing is done.
            let mut positions = rest.to_vec();
            assert!(laid_hand(hand, &mut positions, None, &[], &P.laid).is_none());
            assert_eq!(positions, rest);
        }
    }
}
