//! The template's hands: each hand's vertices beyond the wrist with their share of a turn about
//! it (rising smoothly across the wrist: the skin over the carpus follows the hand), the forearm's
//! share of a slide along it and of a twist about it, and the landmark vertices that place the
//! wrist (the styloids), the knuckles' line and the elbow. A hand is turned about the wrist by
//! [`turn_hand`], and onto given landmarks by [`turn_hand_onto`] (the alignment's part pose,
//! `align::part_pose`); the landmark estimate poses it from the scan (`estimate::hand`).

use nalgebra::{Point3, Rotation3, UnitQuaternion, Vector3};

use crate::landmarks::LandmarkSet;
use crate::mesh::similarity::similarity;
use crate::template::{Segment, Template};

/// The hand's share of the rotation rises from 0 at this distance (m) before the wrist's plane to
/// 1 this far beyond it (the skin over the carpus follows the hand).
const BLEND: (f64, f64) = (-0.01, 0.02);

/// One hand of the template: the vertices that make the wrist and the elbow, the hand's vertices
/// with their share of the rotation, the forearm's and the hand's with their share of the slide.
#[derive(Debug, Clone)]
pub struct Hand {
    pub side: &'static str,
    pub(crate) styloids: [u32; 2],
    /// Metacarpal Phal. II and V: the knuckles' line, across the palm.
    pub(crate) knuckles: [u32; 2],
    pub(crate) epicondyles: [u32; 2],
    pub(crate) acromion: u32,
    pub(crate) share: Vec<(u32, f64)>,
    /// The vertices wholly the hand's (share 1): those matched to the scan.
    pub(crate) own: Vec<u32>,
    /// Fraction of the slide: 0 at the elbow, 1 at the wrist and beyond.
    pub(crate) slide: Vec<(u32, f64)>,
    /// Share of a turn about the forearm that the hand's turn does not already give: the
    /// fraction of the way from the elbow to the wrist, less the share of the hand's turn.
    pub(crate) twist: Vec<(u32, f64)>,
    /// The template's triangles with every corner in the hand.
    pub(crate) triangles: Vec<[u32; 3]>,
}

/// The template's two hands (`template` at the resolution fitted): the arm segment's vertices
/// (weight ≥ ½) beyond the plane across the forearm at the wrist (the forearm from the midpoint
/// of the humeral epicondyles to that of the styloids). A side whose landmark vertices are
/// missing has no hand.
pub fn hands(template: &Template) -> Vec<Hand> {
    let rest = &template.mesh().positions;
    let vertex = |name: String| template.landmark_vertex(&name);
    let mut out = Vec::new();
    for (side, segment) in [("Lt.", Segment::LeftArm), ("Rt.", Segment::RightArm)] {
        let pair = |a: &str, b: &str| {
            Some([
                vertex(format!("{side} {a}"))?,
                vertex(format!("{side} {b}"))?,
            ])
        };
        let (Some(styloids), Some(knuckles), Some(epicondyles), Some(acromion)) = (
            pair("Radial Styloid", "Ulnar Styloid"),
            pair("Metacarpal Phal. II", "Metacarpal Phal. V"),
            pair("Humeral Lateral Epicn", "Humeral Medial Epicn"),
            vertex(format!("{side} Acromion")),
        ) else {
            continue;
        };
        let (wrist, axis) = wrist_and_axis(rest, styloids, epicondyles);
        let elbow = mid(rest, epicondyles);
        let arm: Vec<(usize, &Point3<f64>)> = rest
            .iter()
            .enumerate()
            .filter(|(v, _)| template.segment_weights(*v as u32)[segment.index()] >= 0.5)
            .collect();
        // Each arm vertex's fraction of the slide and share of the hand's turn.
        let fraction = |p: &Point3<f64>| {
            ((p - elbow).dot(&(wrist - elbow)) / (wrist - elbow).norm_squared()).min(1.0)
        };
        let turned =
            |p: &Point3<f64>| smoothstep(((p - wrist).dot(&axis) - BLEND.0) / (BLEND.1 - BLEND.0));
        let slide: Vec<(u32, f64)> = arm
            .iter()
            .filter_map(|(v, p)| (fraction(p) > 0.0).then_some((*v as u32, fraction(p))))
            .collect();
        let share: Vec<(u32, f64)> = arm
            .iter()
            .filter_map(|(v, p)| (turned(p) > 0.0).then_some((*v as u32, turned(p))))
            .collect();
        let twist = arm
            .iter()
            .filter_map(|(v, p)| {
                let rest = fraction(p) - turned(p);
                (rest > 0.0).then_some((*v as u32, rest))
            })
            .collect();
        let (own, triangles) = own_and_triangles(template, &share);
        out.push(Hand {
            side,
            styloids,
            knuckles,
            epicondyles,
            acromion,
            share,
            own,
            slide,
            twist,
            triangles,
        });
    }
    out
}

/// Of a region moved by `share` (vertices with their share of a motion): its vertices wholly
/// moved (share 1), and the template's triangles with every corner in the region.
pub(crate) fn own_and_triangles(
    template: &Template,
    share: &[(u32, f64)],
) -> (Vec<u32>, Vec<[u32; 3]>) {
    let own = share
        .iter()
        .filter(|(_, s)| *s >= 1.0)
        .map(|(v, _)| *v)
        .collect();
    let mut member = vec![false; template.mesh().positions.len()];
    for (v, _) in share {
        member[*v as usize] = true;
    }
    let triangles = template
        .mesh()
        .triangles
        .iter()
        .filter(|t| t.iter().all(|&v| member[v as usize]))
        .copied()
        .collect();
    (own, triangles)
}

/// 0 below 0, 1 above 1, and the cubic 3t² − 2t³ rising smoothly between.
pub(crate) fn smoothstep(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// The midpoint of two vertices.
pub fn mid(positions: &[Point3<f64>], [a, b]: [u32; 2]) -> Point3<f64> {
    Point3::from((positions[a as usize].coords + positions[b as usize].coords) / 2.0)
}

/// The end of a limb's lower part (the midpoint of the pair `end`) and the part's unit direction
/// (from the midpoint of the pair `joint` to that end) at `positions`: the wrist and the forearm,
/// the ankle and the lower leg.
pub fn end_and_axis(
    positions: &[Point3<f64>],
    end: [u32; 2],
    joint: [u32; 2],
) -> (Point3<f64>, Vector3<f64>) {
    let at = mid(positions, end);
    (at, (at - mid(positions, joint)).normalize())
}

/// The wrist (midpoint of the styloids) and the forearm's unit direction (from the midpoint of
/// the epicondyles to the wrist) at `positions`.
pub fn wrist_and_axis(
    positions: &[Point3<f64>],
    styloids: [u32; 2],
    epicondyles: [u32; 2],
) -> (Point3<f64>, Vector3<f64>) {
    end_and_axis(positions, styloids, epicondyles)
}

/// Turns the hand by `rotation` about `wrist`, each vertex by its share of it.
pub fn turn_hand(
    hand: &Hand,
    positions: &mut [Point3<f64>],
    wrist: Point3<f64>,
    rotation: &UnitQuaternion<f64>,
) {
    let scaled_axis = rotation.scaled_axis();
    for (v, s) in &hand.share {
        let p = &mut positions[*v as usize];
        let turn = Rotation3::from_scaled_axis(scaled_axis * *s);
        *p = wrist + turn * (*p - wrist);
    }
}

/// The hand's landmarks beyond the wrist, after the side's prefix.
const HAND_LANDMARKS: [&str; 3] = ["Metacarpal Phal. II", "Metacarpal Phal. V", "Dactylion"];

/// Turns `hand` in `positions` about its wrist (each vertex by its share) so that its landmark
/// vertices (the knuckles and the fingertip, seen from the midpoint of the styloids) point where
/// `landmarks` (same frame and units) have them, seen from theirs: a wrist bent back, as a hand
/// laid on the hip is. Needs both styloids and the three hand landmarks; returns whether the hand
/// was turned.
pub fn turn_hand_onto(
    hand: &Hand,
    positions: &mut [Point3<f64>],
    template: &Template,
    landmarks: &LandmarkSet,
) -> bool {
    let side = |name: &str| format!("{} {name}", hand.side);
    let given = |name: &str| landmarks.get(&side(name));
    let (Some(radial), Some(ulnar)) = (given("Radial Styloid"), given("Ulnar Styloid")) else {
        return false;
    };
    let wrist = mid(positions, hand.styloids);
    let to_wrist = nalgebra::center(&radial, &ulnar);
    let mut from = vec![Point3::origin()];
    let mut to = vec![Point3::origin()];
    for name in HAND_LANDMARKS {
        let (Some(v), Some(q)) = (template.landmark_vertex(&side(name)), given(name)) else {
            return false;
        };
        from.push(Point3::from(positions[v as usize] - wrist));
        to.push(Point3::from(q - to_wrist));
    }
    let Some(fit) = similarity(&from, &to, false) else {
        return false;
    };
    turn_hand(
        hand,
        positions,
        wrist,
        &UnitQuaternion::from_matrix(&fit.rotation),
    );
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_hand_is_turned_at_the_wrist_onto_its_landmarks() {
        let template = Template::embedded()
            .unwrap()
            .at_resolution(crate::template::Resolution::Base);
        let hands = hands(&template);
        let rest = &template.mesh().positions;
        for hand in &hands {
            // The "scan": the template with this hand bent back 40° at the wrist and turned 20°
            // about the forearm, then the whole body moved 1 m (only directions from the wrist
            // count).
            let mut bent = rest.to_vec();
            let (wrist, axis) = wrist_and_axis(&bent, hand.styloids, hand.epicondyles);
            let across = (bent[hand.styloids[0] as usize] - bent[hand.styloids[1] as usize])
                .cross(&axis)
                .normalize();
            let turn = UnitQuaternion::from_scaled_axis(across * 40f64.to_radians())
                * UnitQuaternion::from_scaled_axis(axis * 20f64.to_radians());
            turn_hand(hand, &mut bent, wrist, &turn);
            let shift = Vector3::new(1.0, 0.0, 0.0);
            let moved: Vec<Point3<f64>> = bent.iter().map(|p| p + shift).collect();
            let landmarks = template.landmarks_at(&moved);
            let mut positions = rest.to_vec();
            assert!(turn_hand_onto(hand, &mut positions, &template, &landmarks));
            for name in HAND_LANDMARKS {
                let v = template
                    .landmark_vertex(&format!("{} {name}", hand.side))
                    .unwrap() as usize;
                // (The styloids turn a little with the hand: the wrist moves ≈ 1 mm.)
                let off = (positions[v] - bent[v]).norm();
                assert!(off < 3e-3, "{} {name}: {off} m", hand.side);
            }
            // Without the hand's landmarks nothing is turned.
            let partial = LandmarkSet {
                landmarks: landmarks
                    .landmarks
                    .iter()
                    .filter(|l| !l.name.contains("Dactylion"))
                    .cloned()
                    .collect(),
                ..LandmarkSet::default()
            };
            let mut untouched = rest.to_vec();
            assert!(!turn_hand_onto(hand, &mut untouched, &template, &partial));
            assert_eq!(&untouched, rest);
        }
    }
}
