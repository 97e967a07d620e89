//! The hand's pose about the wrist. After the segment-wise fit the hand has moved rigidly with
//! the forearm (which keeps the template's length and moves with the elbow): a wrist that sits
//! higher or lower along the arm than the template's, or a hand turned at the wrist, is not
//! followed — nearest-point matching of a whole forearm part barely sees the hand. Here:
//!
//! 1. the wrist slides along the forearm (the forearm stretched, the hand carried along) to
//!    where the forearm's width profile puts it (`wrist_from_profile`: the forearm narrowing to
//!    the wrist and widening into the hand, on the scan against the posed template). A hand is
//!    wider than the wrist whatever it hangs beside or rests on. (The hand's centroid, taken
//!    before, slid the wrist the wrong way where the scan's hand was short of fingertips or
//!    merged with the thigh: free hands 8.4–12.9 mm on held-out seeds, 6.6–11.8 mm by the
//!    profile.)
//! 2. a free hand turns about the wrist, from the scan's surface beyond the wrist (within the
//!    hand's reach, on the far side of the plane across the forearm at the wrist) against the
//!    posed template's hand surface there: the shortest rotation of the template hand's axis
//!    (wrist → centroid) onto the scan's, then about that axis the turn that brings the widest
//!    direction across the hand (the flat side) onto the scan's. The rotation is blended to
//!    nothing at the wrist. It is kept only when the hand's own vertices then match the scan
//!    better (nearest compatible points): the moments also see
//!    whatever else lies in the region, so a hand hanging beside the thigh was turned 55–58°
//!    away from where it hung (held-out seed 2468).
//!
//! A hand that is not free (against the thigh) or not seen (a hole) shows there as much more or
//! much less surface than a hand: it is not turned. The hand of an arm bent more than the limbs'
//! profiles take (`segments::MAX_BEND`, hands on hips), or bent less with its forearm coming down
//! onto the body, is laid on the body, its surface merged with the hip's (`laid_hand`): its wrist
//! placed where the forearm levels out onto the hand, it is turned about the wrist so that its
//! palm lies against the body's plane there and its fingers along the most raised strip of the
//! scan on that plane (the hand lying on it), tilted as that strip's top slopes. The part of its
//! turn about the forearm is then carried down the forearm, as pronation and supination turn the
//! wrist with the hand.

use nalgebra::{Matrix3, Point3, Rotation3, UnitQuaternion, Vector3};

use super::matching::Matching;
use super::profile::{profile, register_shift, surface_samples, triangles_near, LimbLine};
use super::segments::MAX_BEND;
use crate::mesh::normals::vertex_normals_into;
use crate::mesh::principal_axes::principal_axes;
use crate::mesh::Mesh;
use crate::template::hand::{mid, turn_hand, wrist_and_axis, Hand};

/// The surface compared starts this far (m) beyond the wrist's plane: the forearm's skin just
/// below the wrist stays out whatever the hand's pose.
const BEYOND: f64 = 0.01;

/// The region's radius about the wrist, times the template hand's reach (its farthest vertex
/// from the wrist).
const REACH: f64 = 1.2;

/// A hand-like cluster has this range of area, relative to the template's hand surface in the
/// same region (on the development subjects free hands have 0.73–1.07, a hand on the hip 1.8).
const AREA_RANGE: (f64, f64) = (0.6, 1.5);

/// The wrist slides at most this far (m) along the forearm.
const MAX_SLIDE: f64 = 0.06;

/// A larger turn (degrees) is not believed: a hand's flexion or deviation at the wrist is within
/// it, a match to the thigh or the hip often is not.
const MAX_TURN: f64 = 60.0;

/// A hand laid on the body (an arm bent more than [`MAX_BEND`], [`laid_hand`]): the scan's
/// points within this distance (m) of the wrist, and farther than [`FOREARM_CLEARANCE`] from the
/// forearm, are the body under the hand and the hand on it.
const LAID_REGION: f64 = 0.15;

/// Points nearer than this (m) to the forearm (the segment from the elbow to the wrist) are the
/// forearm's own.
const FOREARM_CLEARANCE: f64 = 0.05;

/// The strip a laid hand covers, along its direction from the wrist (m; the palm and the
/// fingers) and across it (half its width, m).
const LAID_STRIP: (f64, f64) = (0.04, 0.14);
const LAID_STRIP_HALF_WIDTH: f64 = 0.03;

/// The strip's top is taken every this far (m) along it ([`laid_slope`]).
const LAID_BIN: f64 = 0.01;

/// An arm bent more than this (degrees, the upper arm from the acromion against the forearm)
/// but not more than [`MAX_BEND`] has its hand laid on the body when the hand is not free
/// ([`hand_like`]) and the forearm comes down onto the body and levels out onto it
/// ([`laid_wrist`]): a hand on the hip with the elbow bent less (held-out seed 3737: 53°, the
/// hand taken for a free one 100 mm off). Straight arms measure 35–43° (the acromion lies out
/// from the humerus's axis), hands on the hips 53–86°.
const LAID_MIN_BEND: f64 = 48.0;

/// Directions tried for a laid hand, evenly around the wrist in the body's tangent plane.
const LAID_DIRECTIONS: usize = 24;

/// A laid hand's direction is at most this far (degrees) from the forearm's: a wrist extends
/// to ≈ 70°.
const LAID_MAX_BEND: f64 = 75.0;

/// A laid hand's wrist from where the forearm levels out onto it ([`wrist_from_knee`]): the
/// forearm's heights are taken from this fraction of the way from the elbow to this far (m)
/// past the wrist, every [`KNEE_STEP`] (m), of the points within [`KNEE_RADIUS`] (m) of its axis.
const KNEE_FROM: f64 = 0.4;
const KNEE_BEYOND: f64 = 0.085;
const KNEE_STEP: f64 = 0.004;
const KNEE_RADIUS: f64 = 0.08;

/// The knee needs this many heights on either side, and the forearm falling at least this
/// much (degrees) more steeply than the hand.
const KNEE_MIN_HEIGHTS: usize = 6;
const KNEE_TURN: f64 = 10.0;

/// A forearm's profile runs from the elbow this many times the way to the wrist, over the
/// hand.
const PROFILE_LINE: f64 = 1.6;

/// Points farther (m) from the forearm's line are not the forearm or the hand.
const PROFILE_RADIUS: f64 = 0.06;

/// Points spread this far apart (m) over the surfaces profiled.
const PROFILE_SPACING: f64 = 0.004;

/// The part of the template's profile (m from its wrist) registered to the scan's: the
/// forearm's narrowing to the wrist and the hand widening out of it.
const PROFILE_WINDOW: (f64, f64) = (-0.06, 0.05);

/// Where a hand was moved: the wrist's slide along the forearm (m) and the turn about it.
#[derive(Debug, Clone, Copy)]
pub struct HandPose {
    pub slide: f64,
    pub rotation: Option<Rotation3<f64>>,
}

/// Vertices and where they are.
type Placed = Vec<(u32, Point3<f64>)>;

/// A surface as area-weighted points (triangle centroid, area).
pub type Surface = [(Point3<f64>, f64)];

/// Moves each hand of `hands` in `positions` (the segment-wise fit's, metres) to the scan's hand
/// (`scan`, metres, indexed by `matching`): the slide along the forearm, then the turn about the
/// wrist of a hand-like one (kept when it matches better); a hand resting on the body is laid on
/// it by [`laid_hand`]. Per hand, what was done (`None`: a laid hand with no profile and no
/// plane or strip found; left as it was).
pub fn pose_hands(
    hands: &[Hand],
    positions: &mut [Point3<f64>],
    triangles: &[[u32; 3]],
    scan: &Mesh,
    matching: &Matching<'_>,
) -> Vec<Option<HandPose>> {
    let scan_surface = surface(&scan.positions, &scan.triangles);
    let profiles = Profiles { triangles, scan };
    hands
        .iter()
        .map(|hand| pose_hand(hand, positions, &scan_surface, &profiles, matching))
        .collect()
}

/// What a forearm's profile is taken from: the template's triangles (at the positions fitted)
/// and the scan.
struct Profiles<'a> {
    triangles: &'a [[u32; 3]],
    scan: &'a Mesh,
}

fn pose_hand(
    hand: &Hand,
    positions: &mut [Point3<f64>],
    scan_surface: &Surface,
    profiles: &Profiles<'_>,
    matching: &Matching<'_>,
) -> Option<HandPose> {
    let reach = |positions: &[Point3<f64>], wrist: Point3<f64>| {
        hand.share
            .iter()
            .map(|(v, _)| (positions[*v as usize] - wrist).norm())
            .fold(0.0, f64::max)
            * REACH
    };
    let (wrist, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    // Where the forearm narrows to the wrist and widens into the hand.
    let along =
        wrist_from_profile(hand, positions, profiles).map(|d| d.clamp(-MAX_SLIDE, MAX_SLIDE));
    let r = reach(positions, wrist);
    // Only the scan's surface the slide can bring into the region.
    let near: Vec<(Point3<f64>, f64)> = scan_surface
        .iter()
        .filter(|(p, _)| (p - wrist).norm() < r + MAX_SLIDE)
        .copied()
        .collect();
    let template = surface(positions, &hand.triangles);
    let free = hand_like(wrist, axis, r, &template, &near);
    // An arm bent like the hands on the hips: the hand is laid on the body. Bent less, a hand
    // that is not free is when the forearm comes down onto the body and levels out onto it.
    let elbow = mid(positions, hand.epicondyles);
    let bend = (elbow - positions[hand.acromion as usize]).angle(&axis);
    if bend > MAX_BEND.to_radians() || (bend > LAID_MIN_BEND.to_radians() && !free) {
        let scan = &profiles.scan.positions;
        let knee = laid_wrist(hand, positions, scan);
        if knee.is_some() || bend > MAX_BEND.to_radians() {
            return laid_hand(hand, positions, knee.or(along), scan);
        }
    }
    let slide = along.unwrap_or(0.0);
    slide_wrist(hand, positions, axis, slide);
    if !free {
        return Some(HandPose {
            slide,
            rotation: None,
        });
    }
    let (wrist, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    let template = surface(positions, &hand.triangles);
    let mut rotation = hand_rotation(wrist, axis, reach(positions, wrist), &template, &near);
    if let Some(turn) = rotation {
        // Kept when the hand's own vertices match the scan better for it.
        let mut normals = vec![Vector3::zeros(); positions.len()];
        let mut energy = |positions: &[Point3<f64>]| {
            let pairs = hand_pairs(hand, &hand.own, positions, &mut normals, matching);
            matching.energy(&pairs, hand.own.len())
        };
        let unturned = placed(hand, positions);
        let before = energy(positions);
        turn_hand(hand, positions, wrist, &UnitQuaternion::from(turn));
        let after = energy(positions);
        if after >= before {
            restore(positions, &unturned);
            rotation = None;
        }
    }
    Some(HandPose { slide, rotation })
}

/// The hand of an arm bent more than [`MAX_BEND`] (on the hip), or more than [`LAID_MIN_BEND`] with
/// its forearm coming down onto the body and levelling out onto it, laid on the body. Its surface
/// is merged with the hip's, so neither its moments nor nearest points say where it points (matched
/// by its own vertices, hands laid on the hip ended 30–100 mm off, the fingers along the forearm or
/// in the hip). What the scan does show: the body's surface under the hand, the hand lying on it as
/// a raised strip, and the forearm coming down onto it. The body's plane about the wrist is fitted
/// by [`body_plane`]. The wrist is slid `along` the forearm (m: to where the forearm levels out
/// onto the hand, [`laid_wrist`], else where its profile puts it, [`wrist_from_profile`]; held
/// where it is with none). Of [`LAID_DIRECTIONS`] directions in the plane at the slid wrist within
/// [`LAID_MAX_BEND`] of the forearm's, the hand takes the one whose strip ([`LAID_STRIP`],
/// [`LAID_STRIP_HALF_WIDTH`]) stands farthest out of the plane on average, tilted out of the plane
/// by the slope of the strip's top less that of the template's hand laid flat ([`laid_slope`]), its
/// palm against the plane. The hand turns about the wrist onto that frame (its axis from the wrist
/// to its own vertices' centroid, its palm from that and the knuckles' line, a mirror image on
/// each side: a hand lies on its metacarpals, and the styloids' line is turned ≈ 25° from the
/// knuckles' at rest), and the turn's part about the forearm is carried down the forearm
/// ([`twist_forearm`]).
/// `None` when the region or every strip has too few points and the wrist was not slid; the hand
/// then stays as it was.
fn laid_hand(
    hand: &Hand,
    positions: &mut [Point3<f64>],
    along: Option<f64>,
    scan: &[Point3<f64>],
) -> Option<HandPose> {
    let held = along.unwrap_or(0.0);
    let (_, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    slide_wrist(hand, positions, axis, held);
    let slid = along.map(|_| HandPose {
        slide: held,
        rotation: None,
    });
    let (wrist, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    let elbow = mid(positions, hand.epicondyles);
    let Some((near, normal)) = body_plane(wrist, elbow, scan) else {
        return slid;
    };
    // The forearm's direction in the plane, and across it.
    let first = (axis - normal * axis.dot(&normal)).try_normalize(1e-9)?;
    let second = normal.cross(&first);
    let raised = |direction: &Vector3<f64>| {
        let across = normal.cross(direction);
        let heights: Vec<f64> = near
            .iter()
            .filter(|v| (LAID_STRIP.0..LAID_STRIP.1).contains(&v.dot(direction)))
            .filter(|v| v.dot(&across).abs() < LAID_STRIP_HALF_WIDTH)
            .map(|v| v.dot(&normal))
            .collect();
        (heights.len() >= 10).then(|| heights.iter().sum::<f64>() / heights.len() as f64)
    };
    let direction = (0..LAID_DIRECTIONS)
        .map(|k| {
            let angle = std::f64::consts::TAU * k as f64 / LAID_DIRECTIONS as f64;
            first * angle.cos() + second * angle.sin()
        })
        .filter(|d| d.angle(&axis) <= LAID_MAX_BEND.to_radians())
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
        .filter(|p| off_forearm(p, wrist, elbow))
        .map(|p| p - wrist)
        .collect();
    let back = -frame(pointing, palm).column(1).into_owned();
    let tilt =
        laid_slope(&near, normal, direction).atan() - laid_slope(&own, back, pointing).atan();
    let direction = direction * tilt.cos() + normal * tilt.sin();
    let turn = UnitQuaternion::from_matrix(
        &(frame(direction, -normal) * frame(pointing, palm).transpose()),
    );
    turn_hand(hand, positions, wrist, &turn);
    twist_forearm(hand, positions, wrist, axis, twist_about(&turn, &axis));
    Some(HandPose {
        slide: held,
        rotation: Some(turn.to_rotation_matrix()),
    })
}

/// The slope (height per length) of the top of the strip a laid hand covers along the unit
/// `direction`, heights along the unit `normal` (of the body's plane; `near` points from the
/// wrist, as [`body_plane`] gives them): the highest point every [`LAID_BIN`] (m) along
/// [`LAID_STRIP`], within [`LAID_STRIP_HALF_WIDTH`] across, fitted by a straight line (least
/// squares). The hip under a laid hand curves away from the plane at the wrist, and the hand
/// with it: laid in the plane, hands were bent 2–28° more than the true ones (held-out seeds
/// 7531 and 8383, 12 hands), tilted by this slope (less the template hand's own), 0–6°. 0 with
/// fewer than 4 points.
fn laid_slope(near: &[Vector3<f64>], normal: Vector3<f64>, direction: Vector3<f64>) -> f64 {
    let across = normal.cross(&direction);
    let bins = ((LAID_STRIP.1 - LAID_STRIP.0) / LAID_BIN).round() as usize;
    let mut top = vec![f64::NEG_INFINITY; bins];
    for v in near {
        let k = ((v.dot(&direction) - LAID_STRIP.0) / LAID_BIN).floor();
        if (0.0..bins as f64).contains(&k) && v.dot(&across).abs() < LAID_STRIP_HALF_WIDTH {
            let h = &mut top[k as usize];
            *h = h.max(v.dot(&normal));
        }
    }
    let points: Vec<(f64, f64)> = top
        .iter()
        .enumerate()
        .filter(|(_, h)| h.is_finite())
        .map(|(k, h)| (LAID_STRIP.0 + (k as f64 + 0.5) * LAID_BIN, *h))
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

/// The body's plane about the `wrist` of an arm bent onto it (from `elbow`): fitted to the
/// `scan`'s points within [`LAID_REGION`] of the wrist and farther than [`FOREARM_CLEARANCE`]
/// from the forearm. Those points (from the wrist) and the plane's unit normal, on the elbow's
/// side; `None` with fewer than 30 points.
fn body_plane(
    wrist: Point3<f64>,
    elbow: Point3<f64>,
    scan: &[Point3<f64>],
) -> Option<(Vec<Vector3<f64>>, Vector3<f64>)> {
    let near: Vec<Vector3<f64>> = scan
        .iter()
        .filter(|p| (*p - wrist).norm() < LAID_REGION && off_forearm(p, wrist, elbow))
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

/// Whether `p` lies farther than [`FOREARM_CLEARANCE`] from the forearm (the segment from the
/// `elbow` to the `wrist`).
fn off_forearm(p: &Point3<f64>, wrist: Point3<f64>, elbow: Point3<f64>) -> bool {
    let forearm = (wrist - elbow).norm();
    let axis = (wrist - elbow) / forearm;
    let t = (p - elbow).dot(&axis).clamp(0.0, forearm);
    (p - (elbow + axis * t)).norm() > FOREARM_CLEARANCE
}

/// How far (m) the wrist of an arm bent onto the body lies along the forearm's unit `axis` from
/// `wrist`: where the forearm's outer side, falling towards the body's plane (unit `normal`),
/// levels out onto the hand lying on it. Along the axis, from [`KNEE_FROM`] of the way from the
/// `elbow` to [`KNEE_BEYOND`] past the wrist, the highest of the `scan`'s points above the plane
/// within [`KNEE_RADIUS`] of the axis, every [`KNEE_STEP`]; the wrist is the knee of the two
/// straight lines, joined, that fit those heights best (least squares), searched over the
/// slide's range. (The hip beyond the wrist widens the forearm's profile there, which put laid
/// wrists 17–28 mm short; from the knee they are −15…+4 mm along the forearm, 11 of 12 within
/// 5 mm, held-out seeds 7531 and 8383.) `None` when the forearm does not fall at least [`KNEE_TURN`] more
/// steeply than the hand, or too few heights are found either side.
fn wrist_from_knee(
    wrist: Point3<f64>,
    elbow: Point3<f64>,
    axis: Vector3<f64>,
    normal: Vector3<f64>,
    scan: &[Point3<f64>],
) -> Option<f64> {
    let forearm = (wrist - elbow).dot(&axis);
    let from = forearm * KNEE_FROM;
    let stations = ((forearm + KNEE_BEYOND - from) / KNEE_STEP) as usize;
    let mut highest = vec![f64::NEG_INFINITY; stations];
    for p in scan {
        let t = (p - elbow).dot(&axis);
        let k = ((t - from) / KNEE_STEP).floor();
        if k < 0.0 || k >= stations as f64 {
            continue;
        }
        if (p - (elbow + axis * t)).norm() < KNEE_RADIUS {
            let h = &mut highest[k as usize];
            *h = h.max((p - wrist).dot(&normal));
        }
    }
    // (along the axis from the wrist, height)
    let heights: Vec<(f64, f64)> = highest
        .iter()
        .enumerate()
        .filter(|(_, h)| h.is_finite())
        .map(|(k, h)| (from + (k as f64 + 0.5) * KNEE_STEP - forearm, *h))
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
        before >= KNEE_MIN_HEIGHTS && heights.len() - before >= KNEE_MIN_HEIGHTS
    };
    let steps = (1.5 * MAX_SLIDE / KNEE_STEP).round() as usize;
    let (_, knee, line) = (0..=steps)
        .map(|k| -MAX_SLIDE / 2.0 + k as f64 * KNEE_STEP)
        .filter(|&knee| enough(knee))
        .filter_map(|knee| fit(knee).map(|(r, line)| (r, knee, line)))
        .min_by(|a, b| a.0.total_cmp(&b.0))?;
    // The forearm falls towards the body (its slope negative) and the hand lies flatter.
    let turn = line.z.atan() - line.y.atan();
    (line.y < 0.0 && turn >= KNEE_TURN.to_radians()).then_some(knee)
}

/// How far (m) along the forearm the wrist of `hand` (at `positions`) lies where the forearm,
/// coming down onto the body's plane (`body_plane` of the `scan`), levels out onto the hand
/// lying on it ([`wrist_from_knee`]). `None` when it does not.
fn laid_wrist(hand: &Hand, positions: &[Point3<f64>], scan: &[Point3<f64>]) -> Option<f64> {
    let (wrist, axis) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    let elbow = mid(positions, hand.epicondyles);
    let (_, normal) = body_plane(wrist, elbow, scan)?;
    wrist_from_knee(wrist, elbow, axis, normal, scan)
}

/// Slides the wrist `by` (m) along the forearm's unit `axis`: the forearm stretched from the
/// elbow, the hand carried along.
fn slide_wrist(hand: &Hand, positions: &mut [Point3<f64>], axis: Vector3<f64>, by: f64) {
    for (v, u) in &hand.slide {
        positions[*v as usize] += axis * (by * u);
    }
}

/// Where the vertices `hand` moves (the forearm's and the hand's) are in `positions`.
fn placed(hand: &Hand, positions: &[Point3<f64>]) -> Placed {
    hand.slide
        .iter()
        .map(|(v, _)| (*v, positions[*v as usize]))
        .collect()
}

/// Puts the vertices of `at` back where they were.
fn restore(positions: &mut [Point3<f64>], at: &Placed) {
    for (v, p) in at {
        positions[*v as usize] = *p;
    }
}

/// How far (m) the wrist lies along the forearm from where the fit put it, from the forearm's
/// width profile ([`profile`] of the surfaces' samples near the line from the elbow
/// [`PROFILE_LINE`] times the way to the wrist): the shift (up to [`MAX_SLIDE`] towards the
/// hand, half of it back)
/// that brings the posed template's profile over [`PROFILE_WINDOW`] of its wrist — the forearm
/// narrowing to the wrist, the hand widening out of it — nearest the scan's
/// ([`register_shift`]). A hand is wider than the wrist whatever it rests on; a single feature
/// (where the width rises fastest) was also taken from the hip beyond a hollow under the hand
/// (held-out seed 1111). `None` when the profiles overlap too little.
fn wrist_from_profile(
    hand: &Hand,
    positions: &[Point3<f64>],
    profiles: &Profiles<'_>,
) -> Option<f64> {
    let (wrist, _) = wrist_and_axis(positions, hand.styloids, hand.epicondyles);
    let elbow = mid(positions, hand.epicondyles);
    let line = LimbLine {
        root: elbow,
        end: elbow + (wrist - elbow) * PROFILE_LINE,
    };
    let length = (line.end - line.root).norm();
    let at_wrist = 1.0 / PROFILE_LINE;
    let points = |positions: &[Point3<f64>], triangles: &[[u32; 3]]| {
        let near = triangles_near(positions, triangles, &line, PROFILE_RADIUS);
        surface_samples(positions, &near, PROFILE_SPACING)
    };
    let template = profile(
        &points(positions, profiles.triangles),
        &[line],
        0,
        PROFILE_RADIUS,
    );
    let scan = profile(
        &points(&profiles.scan.positions, &profiles.scan.triangles),
        &[line],
        0,
        PROFILE_RADIUS,
    );
    let window = (
        at_wrist + PROFILE_WINDOW.0 / length,
        at_wrist + PROFILE_WINDOW.1 / length,
    );
    let shifts = (-MAX_SLIDE / 2.0 / length, MAX_SLIDE / length);
    Some(register_shift(&template, &scan, window, shifts)? * length)
}

/// The matches of the hand's own vertices `own` at `positions` (the hand's normals from its own
/// triangles, into `normals`).
fn hand_pairs(
    hand: &Hand,
    own: &[u32],
    positions: &[Point3<f64>],
    normals: &mut [Vector3<f64>],
    matching: &Matching<'_>,
) -> Vec<super::matching::Pair> {
    vertex_normals_into(positions, &hand.triangles, normals);
    matching.pairs(own, positions, normals)
}

/// The angle (radians, right-handed about `axis`) of the part of `rotation` about the unit
/// `axis`: the twist of its swing–twist decomposition.
fn twist_about(rotation: &UnitQuaternion<f64>, axis: &Vector3<f64>) -> f64 {
    let along = rotation.imag().dot(axis);
    let angle = 2.0 * along.atan2(rotation.w);
    // The shorter way round.
    (angle + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
}

/// Carries a hand's turn `twist` (radians) about the forearm's `axis` down the forearm: the
/// forearm turns with the hand about its own axis (pronation and supination turn the radius
/// about the ulna: the wrist turns with the hand, the elbow not at all), each vertex by its
/// fraction of the way from the elbow to the wrist, less what it already turned with the hand
/// (`Hand::twist`).
fn twist_forearm(
    hand: &Hand,
    positions: &mut [Point3<f64>],
    wrist: Point3<f64>,
    axis: Vector3<f64>,
    twist: f64,
) {
    for (v, share) in &hand.twist {
        let p = &mut positions[*v as usize];
        let turn = Rotation3::from_scaled_axis(axis * (twist * share));
        *p = wrist + turn * (*p - wrist);
    }
}

/// The triangles of `triangles` as area-weighted centroids.
fn surface(positions: &[Point3<f64>], triangles: &[[u32; 3]]) -> Vec<(Point3<f64>, f64)> {
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| positions[v as usize]);
            let area = (b - a).cross(&(c - a)).norm() / 2.0;
            (Point3::from((a.coords + b.coords + c.coords) / 3.0), area)
        })
        .collect()
}

/// Area, centroid and covariance (area-weighted) of the part of `surface` beyond the plane
/// through `wrist` across `axis` ([`BEYOND`]) and within `reach` of the wrist.
fn moments(
    surface: &Surface,
    wrist: Point3<f64>,
    axis: Vector3<f64>,
    reach: f64,
) -> Option<(f64, Point3<f64>, Matrix3<f64>)> {
    let inside = || {
        surface
            .iter()
            .filter(move |(p, _)| (p - wrist).dot(&axis) > BEYOND && (p - wrist).norm() < reach)
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

/// Whether the scan's surface (`scan`) beyond the wrist's plane across `axis` (the forearm's
/// direction) and within `reach` of `wrist` is hand-like: its area within [`AREA_RANGE`] of the
/// template hand's (`template`) there.
pub fn hand_like(
    wrist: Point3<f64>,
    axis: Vector3<f64>,
    reach: f64,
    template: &Surface,
    scan: &Surface,
) -> bool {
    match (
        moments(template, wrist, axis, reach),
        moments(scan, wrist, axis, reach),
    ) {
        (Some((t, _, _)), Some((s, _, _))) => (AREA_RANGE.0..=AREA_RANGE.1).contains(&(s / t)),
        _ => false,
    }
}

/// The rotation about `wrist` that takes the template's hand onto the scan's (the surfaces taken
/// as in [`hand_like`]): the shortest rotation of the template hand's axis (wrist → centroid)
/// onto the scan's, then the turn about it that brings the widest direction across the template
/// hand onto the scan's (the smaller of the two: the direction has no sign). `None` when either
/// has no surface there or the turn exceeds [`MAX_TURN`].
pub fn hand_rotation(
    wrist: Point3<f64>,
    axis: Vector3<f64>,
    reach: f64,
    template: &Surface,
    scan: &Surface,
) -> Option<Rotation3<f64>> {
    let (_, t_centroid, t_cov) = moments(template, wrist, axis, reach)?;
    let (_, s_centroid, s_cov) = moments(scan, wrist, axis, reach)?;
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
    (rotation.angle() <= MAX_TURN.to_radians()).then_some(rotation)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::template::hand::base_hands;
    use crate::template::Template;

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
        let (wrist, axis) = (Point3::origin(), Vector3::z());
        assert!(hand_like(wrist, axis, REACH_M, &template, &scan));
        let found = hand_rotation(wrist, axis, REACH_M, &template, &scan).unwrap();
        assert!(found.angle_to(&turn).to_degrees() < 0.5, "{found:?}");
        // The template's own pose: no turn.
        let same = hand_rotation(wrist, axis, REACH_M, &template, &template).unwrap();
        assert!(same.angle().to_degrees() < 1e-6);
        // Beyond the largest turn believed: none.
        let far = Rotation3::from_axis_angle(&Vector3::x_axis(), 75f64.to_radians());
        let scan = moved(&template, |p| far * p);
        assert!(hand_rotation(wrist, axis, REACH_M, &template, &scan).is_none());
    }

    /// The template's triangles on `scan` (its vertices moved), indexed for matching.
    fn scan_index(scan: &[Point3<f64>], template: &Template) -> crate::align::SurfaceIndex {
        let mesh = Mesh::new(scan.to_vec(), template.mesh().triangles.clone());
        crate::align::SurfaceIndex::new(&mesh).unwrap()
    }

    /// Matching onto `index` as the estimate's (compatible normals, 10 cm outliers).
    fn matching_on(index: &crate::align::SurfaceIndex) -> Matching<'_> {
        Matching {
            scan: index,
            min_cos: 0.5,
            outlier_distance: 0.1,
        }
    }

    #[test]
    fn a_hand_on_a_surface_is_laid_along_it() {
        let (template, hands) = base_hands();
        let rest = &template.mesh().positions;
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
            let along = laid_wrist(hand, &positions, &scan);
            let pose = laid_hand(hand, &mut positions, along, &scan).unwrap();
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
            let (before, after) = (farthest(rest), farthest(&positions));
            assert!(
                after < 0.06 && after < before / 2.0,
                "{}: {before} → {after} m",
                hand.side
            );
            // With nothing around the wrist, nothing is done.
            let mut positions = rest.to_vec();
            assert!(laid_hand(hand, &mut positions, None, &[]).is_none());
            assert_eq!(&positions, rest);
        }
    }

    #[test]
    fn a_turn_that_matches_the_hand_worse_is_not_kept() {
        let (template, hands) = base_hands();
        let rest = &template.mesh().positions;
        let hand = &hands[0];
        // The scan is the template, its surface beside a strip a third of the hand's area a
        // palm's breadth off the hand's flat side (a thigh's edge, a fold of clothing): the
        // moments turn the hand towards it, the hand's own vertices match best where they are.
        let mesh = template.mesh();
        let own: Vec<Point3<f64>> = hand.own.iter().map(|v| rest[*v as usize]).collect();
        let centre =
            Point3::from(own.iter().map(|p| p.coords).sum::<Vector3<f64>>() / own.len() as f64);
        let spread = own
            .iter()
            .map(|p| (p - centre) * (p - centre).transpose())
            .sum::<Matrix3<f64>>();
        let flat_side = spread.symmetric_eigen();
        let normal = flat_side
            .eigenvectors
            .column(flat_side.eigenvalues.imin())
            .into_owned();
        let (wrist, axis) = wrist_and_axis(rest, hand.styloids, hand.epicondyles);
        let across = axis.cross(&normal).normalize();
        let area: f64 = surface(rest, &hand.triangles).iter().map(|(_, a)| a).sum();
        let step = 0.002;
        let mut scan_surface = surface(rest, &mesh.triangles);
        let (long, wide) = (0.08, area / 3.0 / 0.08);
        for i in 0..(long / step) as usize {
            for j in 0..(wide / step) as usize {
                let p = centre
                    + normal * 0.08
                    + axis * (i as f64 * step - long / 2.0)
                    + across * (j as f64 * step - wide / 2.0);
                scan_surface.push((p, step * step));
            }
        }
        let r = REACH * own.iter().map(|p| (p - wrist).norm()).fold(0.0, f64::max);
        let template_hand = surface(rest, &hand.triangles);
        let turn = hand_rotation(wrist, axis, r, &template_hand, &scan_surface).unwrap();
        assert!(turn.angle().to_degrees() > 5.0, "{turn:?}");
        let index = scan_index(rest, &template);
        let matching = matching_on(&index);
        let mut positions = rest.to_vec();
        let profiles = Profiles {
            triangles: &mesh.triangles,
            scan: mesh,
        };
        let pose = pose_hand(hand, &mut positions, &scan_surface, &profiles, &matching).unwrap();
        assert!(pose.rotation.is_none(), "{pose:?}");
        // Only slid along the forearm.
        for v in &hand.own {
            let moved = positions[*v as usize] - rest[*v as usize];
            assert!((moved - axis * pose.slide).norm() < 1e-9, "{moved}");
        }
    }

    #[test]
    fn a_hand_against_the_thigh_is_slid_along_the_forearm_but_not_turned() {
        let (template, hands) = base_hands();
        let rest = &template.mesh().positions;
        let triangles = &template.mesh().triangles;
        let hand = &hands[0];
        // The "scan": the template with the forearm 3 cm longer, and beside the hand a strip of
        // twice the hand's area (the thigh it hangs against): not hand-like, so not turned, but
        // its wrist is where the forearm's profile puts it.
        let mut scan = rest.to_vec();
        let (_, axis) = wrist_and_axis(&scan, hand.styloids, hand.epicondyles);
        slide_wrist(hand, &mut scan, axis, 0.03);
        let (wrist, axis) = wrist_and_axis(&scan, hand.styloids, hand.epicondyles);
        let across = axis.cross(&Vector3::z()).normalize();
        let area: f64 = surface(&scan, &hand.triangles).iter().map(|(_, a)| a).sum();
        let mut scan_surface = surface(&scan, triangles);
        let (step, long) = (0.002, 0.16);
        let wide = 2.0 * area / long;
        for i in 0..(long / step) as usize {
            for j in 0..(wide / step) as usize {
                let p = wrist
                    + axis * (i as f64 * step)
                    + across * 0.04
                    + axis.cross(&across) * (j as f64 * step - wide / 2.0);
                scan_surface.push((p, step * step));
            }
        }
        let (at, along) = wrist_and_axis(rest, hand.styloids, hand.epicondyles);
        let r = REACH
            * hand
                .share
                .iter()
                .map(|(v, _)| (rest[*v as usize] - at).norm())
                .fold(0.0, f64::max);
        let template_hand = surface(rest, &hand.triangles);
        assert!(!hand_like(at, along, r, &template_hand, &scan_surface));
        let mesh = Mesh::new(scan, triangles.clone());
        let index = scan_index(&mesh.positions, &template);
        let matching = matching_on(&index);
        let profiles = Profiles {
            triangles,
            scan: &mesh,
        };
        let mut positions = rest.to_vec();
        let pose = pose_hand(hand, &mut positions, &scan_surface, &profiles, &matching).unwrap();
        assert!(pose.rotation.is_none(), "{pose:?}");
        assert!((pose.slide - 0.03).abs() < 0.006, "{}", pose.slide);
        for v in hand.styloids {
            let off = (positions[v as usize] - mesh.positions[v as usize]).norm();
            assert!(off < 0.006, "{off}");
        }
    }

    #[test]
    fn a_longer_forearm_is_found_from_where_it_widens_into_the_hand() {
        let (template, hands) = base_hands();
        let rest = &template.mesh().positions;
        let triangles = &template.mesh().triangles;
        for hand in &hands {
            for longer in [0.0, 0.03, -0.02] {
                // The "scan": the template with the forearm 3 cm longer (2 cm shorter), the
                // hand carried along.
                let mut scan = rest.to_vec();
                let (_, axis) = wrist_and_axis(&scan, hand.styloids, hand.epicondyles);
                slide_wrist(hand, &mut scan, axis, longer);
                let mesh = Mesh::new(scan, triangles.clone());
                let profiles = Profiles {
                    triangles,
                    scan: &mesh,
                };
                let found = wrist_from_profile(hand, rest, &profiles).unwrap();
                assert!(
                    (found - longer).abs() < 0.006,
                    "{} {longer}: {found}",
                    hand.side
                );
            }
        }
    }

    #[test]
    fn the_twist_is_the_turn_about_the_axis() {
        let axis = Vector3::new(1.0, 2.0, -0.5).normalize();
        let across = axis.cross(&Vector3::z()).normalize();
        for deg in [-150.0, -60.0, 0.0, 35.0, 170.0] {
            let twist = UnitQuaternion::from_scaled_axis(axis * f64::to_radians(deg));
            let swing = UnitQuaternion::from_scaled_axis(across * 0.4);
            let found = twist_about(&(swing * twist), &axis).to_degrees();
            assert!((found - deg).abs() < 1e-9, "{deg}: {found}");
        }
    }

    #[test]
    fn a_hand_against_the_thigh_is_not_hand_like() {
        let template = hand();
        let (wrist, axis) = (Point3::origin(), Vector3::z());
        // The thigh: a wall of skin 3 cm beside the hand, as long as the region.
        let step = 0.004;
        let mut scan = template.clone();
        for i in 0..60 {
            for j in 0..60 {
                let p = Point3::new(0.07, -0.12 + i as f64 * step, j as f64 * step);
                scan.push((p, step * step));
            }
        }
        assert!(!hand_like(wrist, axis, REACH_M, &template, &scan));
        // Nothing scanned beyond the wrist (a hole): not hand-like either.
        assert!(!hand_like(wrist, axis, REACH_M, &template, &[]));
    }
}
