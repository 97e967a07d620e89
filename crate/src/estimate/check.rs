//! The check of a given landmark file on its own (issues 31, 32): every given landmark is
//! predicted from the other given landmarks of the body's rigid groups it belongs to, and one
//! far from every such prediction is suspicious. No fit of the scan: it costs ≈ 0.3 ms per
//! file of 73 (docs/landmarks-estimate.md), so a batch can check every file before the warp.
//!
//! **Rigid groups** ([`RIGID_GROUPS`]): the head, the thorax, the pelvis, and per side the upper
//! arm, the forearm, the hand, the thigh, the lower leg and the foot. A joint's landmarks belong
//! to both groups it joins: the humeral epicondyles lie on the elbow's hinge, so they move with
//! the upper arm *and* with the forearm; the styloids with the forearm and the hand; the femoral
//! epicondyles with the thigh and the lower leg; the malleoli with the lower leg and the foot.
//! So a bent elbow or a hand laid on the hip moves whole groups and keeps each group's shape:
//! the check knows the pose without fitting it.
//!
//! **Prediction** of landmark `i` from a group `G`: the similarity (Umeyama) taking the
//! template's landmarks of the others of `G` (given, trusted) onto their given positions, applied
//! to the template's landmark `i`, when there are at least [`MIN_OTHERS`] others. Its
//! *residual* is the distance from the given position; a landmark in several groups takes the
//! group with the smallest residual (a correct joint landmark fits at least one side). A
//! landmark with no group of enough others is *unjudged* (listed, never flagged).
//!
//! **Tolerance** ([`tolerance_mm`], [`CheckParams`]): a landmark is suspicious when its residual
//! exceeds √(tolerance² + (k_s·spread)² + (k_m·misfit)²): the body's own variation within a
//! rigid group, the landmark definition's spread (`landmarks/sharpness.rs`: 5 / 10 / 25 mm) and
//! how well the group's other landmarks fit their map on this body; the Acromion of an arm held
//! raised (its elbow above the Suprasternale) rises with the shoulder girdle, which no rigid group
//! holds, and its tolerance takes in `raised_acromion_mm` as well. A wrong landmark spoils its
//! groups' predictions of the others, so the landmark farthest beyond its tolerance stops
//! predicting, and the rest are predicted again, until every landmark still predicting is
//! within its tolerance.
//!
//! **The forearm's twist** (`forearm_twist.rs`): with the elbow bent (a hand laid on the hip),
//! the wrist turns about the forearm, and a styloid's prediction from its forearm is turned
//! about the forearm's axis to the given one's angle: its place along the forearm and its
//! distance from the axis are judged, not its angle about it.

use nalgebra::Point3;
use serde::Serialize;

use super::caesar_points::{given_landmarks, landmark_rest};
use super::forearm_twist::{twisted, Forearm};
pub use super::params::CheckParams;
use super::suspicious::{flag_suspicious, SuspiciousLandmark};
use crate::landmarks::{definition_sharpness, LandmarkSet, CAESAR_LANDMARKS};
use crate::mesh::similarity::similarity;
use crate::template::Template;

/// Other given landmarks a group needs to predict one of its landmarks (a similarity needs three
/// points off one line).
pub const MIN_OTHERS: usize = 3;

/// A given set with at least this many of the 73 is nearly full (a CAESAR file missing a few):
/// [`super::flag_given`] judges it by [`judge_given`] alone, as the app treats it (the app's
/// `NEARLY_FULL`, web/app/landmark-step.ts).
pub const NEARLY_FULL: usize = 64;

/// The body's rigid groups of landmarks, by name; `{side}` stands for `Lt.` and `Rt.` (a group
/// with it is one group per side). Joint landmarks are in both groups they join.
pub const RIGID_GROUPS: [&[&str]; 9] = [
    &[
        "Sellion",
        "Rt. Infraorbitale",
        "Lt. Infraorbitale",
        "Supramenton",
        "Rt. Tragion",
        "Lt. Tragion",
        "Rt. Gonion",
        "Lt. Gonion",
        "Nuchale",
    ],
    &[
        "Rt. Clavicale",
        "Lt. Clavicale",
        "Suprasternale",
        "Rt. Thelion/Bustpoint",
        "Lt. Thelion/Bustpoint",
        "Substernale",
        "Rt. 10th Rib",
        "Lt. 10th Rib",
        "Cervicale",
        "10th Rib Midspine",
        "Rt. Acromion",
        "Lt. Acromion",
        "Rt. Axilla, Ant.",
        "Lt. Axilla, Ant.",
        "Rt. Axilla, Post.",
        "Lt. Axilla, Post.",
    ],
    &[
        "Rt. ASIS",
        "Lt. ASIS",
        "Rt. Iliocristale",
        "Lt. Iliocristale",
        "Rt. Trochanterion",
        "Lt. Trochanterion",
        "Rt. PSIS",
        "Lt. PSIS",
        "Waist, Preferred, Post.",
        "Crotch",
        "Rt. 10th Rib",
        "Lt. 10th Rib",
        "10th Rib Midspine",
    ],
    &[
        "{side} Acromion",
        "{side} Axilla, Ant.",
        "{side} Axilla, Post.",
        "{side} Humeral Lateral Epicn",
        "{side} Humeral Medial Epicn",
    ],
    &[
        "{side} Humeral Lateral Epicn",
        "{side} Humeral Medial Epicn",
        "{side} Olecranon",
        "{side} Radiale",
        "{side} Radial Styloid",
        "{side} Ulnar Styloid",
    ],
    &[
        "{side} Radial Styloid",
        "{side} Ulnar Styloid",
        "{side} Metacarpal Phal. II",
        "{side} Metacarpal Phal. V",
        "{side} Dactylion",
    ],
    &[
        "{side} Trochanterion",
        "{side} Femoral Lateral Epicn",
        "{side} Femoral Medial Epicn",
        "{side} Knee Crease",
    ],
    &[
        "{side} Femoral Lateral Epicn",
        "{side} Femoral Medial Epicn",
        "{side} Knee Crease",
        "{side} Lateral Malleolus",
        "{side} Medial Malleolus",
        "{side} Sphyrion",
    ],
    &[
        "{side} Lateral Malleolus",
        "{side} Medial Malleolus",
        "{side} Sphyrion",
        "{side} Metatarsal Phal. I",
        "{side} Metatarsal Phal. V",
        "{side} Calcaneous, Post.",
        "{side} Digit II",
    ],
];

/// The check of a given set: the suspicious landmarks, and the given ones it could not judge.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct GivenCheck {
    /// The suspicious given landmarks, each with its distance (mm), kind and suggestion.
    pub flagged: Vec<SuspiciousLandmark>,
    /// Given landmarks none of whose rigid groups has [`MIN_OTHERS`] other given landmarks: not
    /// judged, so never flagged.
    pub unjudged: Vec<String>,
}

/// Where one landmark is expected from the other given landmarks of one of its rigid groups.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prediction {
    /// The scan's frame and units.
    pub position: Point3<f64>,
    /// The RMS misfit of the group's other landmarks to the same map (scan units).
    pub misfit: f64,
    /// The group (index into [`rigid_groups`]) it was predicted from.
    pub group: usize,
}

/// The suspicious landmarks of `given` (the scan's frame and units), each judged against the
/// other given landmarks of its rigid groups (module documentation) with the default
/// [`CheckParams`]; `template` gives the landmarks' rest positions (any resolution); `to_mm`
/// converts the scan's units to millimetres (1 for mm, 1000 for metres). No fit of the scan:
/// under a millisecond for 73 landmarks.
pub fn check_given(template: &Template, given: &LandmarkSet, to_mm: f64) -> GivenCheck {
    judge_given(
        &landmark_rest(template),
        &given_landmarks(given),
        to_mm,
        &CheckParams::default(),
    )
}

/// [`check_given`] on the template's landmark vertices at rest (`landmark_rest`, 73, CAESAR
/// order) and the given landmarks as (CAESAR index, position).
pub fn judge_given(
    landmark_rest: &[Point3<f64>],
    given: &[(usize, Point3<f64>)],
    to_mm: f64,
    params: &CheckParams,
) -> GivenCheck {
    let groups = rigid_groups();
    let raised = raised_acromions(given);
    let expected_from = |trusted: &[(usize, Point3<f64>)]| -> Vec<Option<(Point3<f64>, f64)>> {
        predict_given(landmark_rest, &groups, given, trusted, params)
            .iter()
            .zip(CAESAR_LANDMARKS.iter())
            .enumerate()
            .map(|(i, (p, l))| {
                p.map(|p| {
                    let mut t = tolerance_mm(l.name, p.misfit * to_mm, params);
                    if raised.contains(&i) {
                        t = t.hypot(params.raised_acromion_mm);
                    }
                    (p.position, t / to_mm)
                })
            })
            .collect()
    };
    let mut trusted = given.to_vec();
    let mut expected = expected_from(&trusted);
    let unjudged = given
        .iter()
        .filter(|(i, _)| expected[*i].is_none())
        .map(|(i, _)| CAESAR_LANDMARKS[*i].name.to_string())
        .collect();
    // The worst landmark beyond its tolerance stops predicting the others, one at a time: a
    // wrong landmark spoils its groups' predictions, and leaving out every landmark over its
    // tolerance at once would leave a group too few to predict its good ones from.
    while let Some(worst) = trusted
        .iter()
        .enumerate()
        .filter_map(|(k, (i, p))| expected[*i].map(|(e, t)| (k, (p - e).norm() / t)))
        .filter(|&(_, ratio)| ratio > 1.0)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(k, _)| k)
    {
        trusted.remove(worst);
        expected = expected_from(&trusted);
    }
    GivenCheck {
        flagged: flag_suspicious(given, &expected, to_mm),
        unjudged,
    }
}

/// The CAESAR indices of the given Acromions whose arm is held raised: its elbow (the given
/// humeral epicondyles' midpoint) above the given Suprasternale along the trunk's up (the given
/// ASIS' midpoint → Suprasternale). On the synthetic populations a raised arm's elbow lies
/// 36–288 mm above it, any other arm's (hanging, held out to 60°, hands on hips, against the
/// body) 140 mm or more below. The Acromions themselves are not used, so a swapped pair does
/// not make its arm look raised.
fn raised_acromions(given: &[(usize, Point3<f64>)]) -> Vec<usize> {
    let index = |name: &str| CAESAR_LANDMARKS.iter().position(|l| l.name == name);
    let at = |name: &str| {
        let i = index(name)?;
        given.iter().find(|(j, _)| *j == i).map(|(_, p)| *p)
    };
    let Some((sternum, hips)) = at("Suprasternale").zip(at("Rt. ASIS").zip(at("Lt. ASIS"))) else {
        return Vec::new();
    };
    let up = sternum - nalgebra::center(&hips.0, &hips.1);
    ["Rt.", "Lt."]
        .iter()
        .filter_map(|side| {
            let lateral = at(&format!("{side} Humeral Lateral Epicn"))?;
            let medial = at(&format!("{side} Humeral Medial Epicn"))?;
            let elbow = nalgebra::center(&lateral, &medial);
            ((elbow - sternum).dot(&up) > 0.0)
                .then(|| index(&format!("{side} Acromion")))
                .flatten()
        })
        .collect()
}

/// The tolerance (mm) of the landmark `name` predicted by a map its group's others fit with RMS
/// `misfit_mm`: √(tolerance² + (k_s·spread)² + (k_m·misfit)²).
pub fn tolerance_mm(name: &str, misfit_mm: f64, params: &CheckParams) -> f64 {
    let spread = definition_sharpness(name).map_or(0.0, |s| s.spread() * 1000.0);
    let terms = [
        params.tolerance_mm,
        params.spread_factor * spread,
        params.misfit_factor * misfit_mm,
    ];
    terms.iter().map(|t| t * t).sum::<f64>().sqrt()
}

/// The prediction of every landmark (73, CAESAR order) from the `trusted` given landmarks of its
/// rigid groups, leaving itself out (the similarity of the template's landmarks of the others
/// onto their given positions): for a given landmark (in
/// `given`) the group's prediction nearest its given position, for another the prediction of
/// the group with the most trusted landmarks. `None` where no group of the landmark has
/// [`MIN_OTHERS`] trusted others. A given styloid's prediction from its forearm is turned about
/// the forearm's axis to its angle when the elbow is bent (`forearm_twist.rs`).
pub fn predict_given(
    landmark_rest: &[Point3<f64>],
    groups: &[Vec<usize>],
    given: &[(usize, Point3<f64>)],
    trusted: &[(usize, Point3<f64>)],
    params: &CheckParams,
) -> Vec<Option<Prediction>> {
    let trusted_at = |j: usize| trusted.iter().find(|(k, _)| *k == j).map(|(_, p)| *p);
    // A twisting forearm's styloids are not rigid with its other landmarks: they do not predict
    // them (else a turned wrist spoils the elbow's prediction).
    let twisting: Vec<Forearm> = Forearm::both()
        .into_iter()
        .filter(|f| f.bent(&trusted_at, params))
        .collect();
    (0..landmark_rest.len())
        .map(|i| {
            let at = given.iter().find(|(j, _)| *j == i).map(|(_, p)| *p);
            let mut best: Option<(f64, Prediction)> = None;
            for (g, group) in groups.iter().enumerate().filter(|(_, g)| g.contains(&i)) {
                let turned = twisting
                    .iter()
                    .find(|f| group.contains(&f.epicondyles[0]) && !f.styloids.contains(&i));
                let others: Vec<&(usize, Point3<f64>)> = trusted
                    .iter()
                    .filter(|(j, _)| *j != i && group.contains(j))
                    .filter(|(j, _)| turned.is_none_or(|f| !f.styloids.contains(j)))
                    .collect();
                if others.len() < MIN_OTHERS {
                    continue;
                }
                let from: Vec<_> = others.iter().map(|(j, _)| landmark_rest[*j]).collect();
                let to: Vec<_> = others.iter().map(|(_, p)| *p).collect();
                let Some(map) =
                    similarity(&from, &to, true).filter(|t| t.scale.is_finite() && t.scale > 0.0)
                else {
                    continue;
                };
                let misfit = (from
                    .iter()
                    .zip(&to)
                    .map(|(x, y)| (map.apply(x) - y).norm_squared())
                    .sum::<f64>()
                    / from.len() as f64)
                    .sqrt();
                let mut position = map.apply(&landmark_rest[i]);
                if let (Some(p), Some(forearm)) = (at, Forearm::of_styloid(i)) {
                    if group.contains(&forearm.epicondyles[0]) {
                        let acromion = trusted_at(forearm.acromion);
                        position =
                            twisted(&forearm, &map, landmark_rest, acromion, position, p, params);
                    }
                }
                let rank = match at {
                    Some(p) => (p - position).norm(),
                    None => -(others.len() as f64),
                };
                if best.is_none_or(|(r, _)| rank < r) {
                    let prediction = Prediction {
                        position,
                        misfit,
                        group: g,
                    };
                    best = Some((rank, prediction));
                }
            }
            best.map(|(_, p)| p)
        })
        .collect()
}

/// [`RIGID_GROUPS`] as CAESAR indices, each `{side}` group once per side (left first).
pub fn rigid_groups() -> Vec<Vec<usize>> {
    let index = |name: &str| {
        CAESAR_LANDMARKS
            .iter()
            .position(|l| l.name == name)
            .expect("every rigid group's name is a CAESAR landmark")
    };
    let mut groups = Vec::new();
    for group in RIGID_GROUPS {
        let sides: &[&str] = if group[0].contains("{side}") {
            &["Lt.", "Rt."]
        } else {
            &[""]
        };
        for side in sides {
            groups.push(
                group
                    .iter()
                    .map(|n| index(&n.replace("{side}", side)))
                    .collect(),
            );
        }
    }
    groups
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::landmarks::Landmark;
    use crate::template::Resolution;
    use nalgebra::{Rotation3, Unit, Vector3};

    fn rest() -> Vec<Point3<f64>> {
        landmark_rest(
            &Template::embedded()
                .unwrap()
                .at_resolution(Resolution::Base),
        )
    }

    fn index(name: &str) -> usize {
        CAESAR_LANDMARKS
            .iter()
            .position(|l| l.name == name)
            .unwrap()
    }

    /// The template's landmarks in CAESAR's frame (mm, z up, facing −y), shifted.
    fn caesar(rest: &[Point3<f64>]) -> Vec<(usize, Point3<f64>)> {
        rest.iter()
            .enumerate()
            .map(|(i, p)| {
                (
                    i,
                    Point3::new(p.x, -p.z, p.y) * 1000.0 + Vector3::new(40.0, -25.0, 3.0),
                )
            })
            .collect()
    }

    /// `set` with the left forearm and hand bent `degrees` at the elbow, about the line through
    /// the humeral epicondyles.
    fn bent(set: &[(usize, Point3<f64>)], degrees: f64) -> Vec<(usize, Point3<f64>)> {
        let (lateral, medial) = (
            set[index("Lt. Humeral Lateral Epicn")].1,
            set[index("Lt. Humeral Medial Epicn")].1,
        );
        let turn = Rotation3::from_axis_angle(
            &Unit::new_normalize(medial - lateral),
            degrees.to_radians(),
        );
        let moved = [
            "Lt. Olecranon",
            "Lt. Radiale",
            "Lt. Radial Styloid",
            "Lt. Ulnar Styloid",
            "Lt. Metacarpal Phal. II",
            "Lt. Metacarpal Phal. V",
            "Lt. Dactylion",
        ];
        set.iter()
            .map(|&(i, p)| {
                let moves = moved.contains(&CAESAR_LANDMARKS[i].name);
                (
                    i,
                    if moves {
                        lateral + turn * (p - lateral)
                    } else {
                        p
                    },
                )
            })
            .collect()
    }

    fn names(check: &GivenCheck) -> Vec<(&str, SuspicionKind)> {
        check
            .flagged
            .iter()
            .map(|f| (f.name.as_str(), f.kind))
            .collect()
    }

    use super::super::suspicious::SuspicionKind;

    #[test]
    fn a_correct_set_in_any_frame_and_a_bent_elbow_raise_no_flag() {
        let rest = rest();
        let params = CheckParams::default();
        let set = caesar(&rest);
        let check = judge_given(&rest, &set, 1.0, &params);
        assert!(
            check.flagged.is_empty() && check.unjudged.is_empty(),
            "{check:?}"
        );
        // Metres, turned about the vertical.
        let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), 2.0);
        let metres: Vec<_> = set.iter().map(|&(i, p)| (i, turn * p / 1000.0)).collect();
        assert!(judge_given(&rest, &metres, 1000.0, &params)
            .flagged
            .is_empty());
        // Hands on hips: the elbow bent 95°; the forearm and hand move as one, the
        // epicondyles stay on the hinge.
        let check = judge_given(&rest, &bent(&set, 95.0), 1.0, &params);
        assert!(check.flagged.is_empty(), "{:?}", names(&check));
    }

    #[test]
    fn a_swapped_pair_is_found_on_a_bent_arm() {
        let rest = rest();
        let mut set = bent(&caesar(&rest), 95.0);
        for (rt, lt) in [
            ("Rt. Acromion", "Lt. Acromion"),
            ("Rt. Radial Styloid", "Lt. Radial Styloid"),
        ] {
            let (rt, lt) = (index(rt), index(lt));
            let p = set[rt].1;
            set[rt].1 = set[lt].1;
            set[lt].1 = p;
        }
        let check = judge_given(&rest, &set, 1.0, &CheckParams::default());
        let mut flagged = names(&check);
        flagged.sort_by_key(|(n, _)| *n);
        assert_eq!(
            flagged,
            [
                ("Lt. Acromion", SuspicionKind::Swapped),
                ("Lt. Radial Styloid", SuspicionKind::Swapped),
                ("Rt. Acromion", SuspicionKind::Swapped),
                ("Rt. Radial Styloid", SuspicionKind::Swapped),
            ]
        );
    }

    #[test]
    fn a_30_mm_typo_is_found_with_its_axis_in_mm_and_in_metres() {
        let rest = rest();
        let params = CheckParams::default();
        for name in [
            "Rt. ASIS",
            "Lt. Olecranon",
            "Sellion",
            "Rt. Medial Malleolus",
        ] {
            for axis in 0..3 {
                for to_mm in [1.0, 1000.0] {
                    let mut set: Vec<_> = caesar(&rest)
                        .into_iter()
                        .map(|(i, p)| (i, p / to_mm))
                        .collect();
                    set[index(name)].1[axis] += 30.0 / to_mm;
                    let check = judge_given(&rest, &set, to_mm, &params);
                    assert_eq!(check.flagged.len(), 1, "{name} {axis}: {:?}", names(&check));
                    let f = &check.flagged[0];
                    assert_eq!((f.name.as_str(), f.kind), (name, SuspicionKind::Coordinate));
                    assert!((f.distance_mm - 30.0).abs() < 1e-6, "{}", f.distance_mm);
                    let axis = ['x', 'y', 'z'][axis];
                    assert!(
                        f.suggestion.contains(&format!("the {axis} coordinate")),
                        "{}",
                        f.suggestion
                    );
                    assert!(f.suggestion.contains("(30 mm apart)"), "{}", f.suggestion);
                    let unit = if to_mm == 1.0 { " mm," } else { " m," };
                    assert!(f.suggestion.contains(unit), "{}", f.suggestion);
                }
            }
        }
    }

    #[test]
    fn a_group_with_too_few_others_is_unjudged_not_flagged() {
        let rest = rest();
        let set: Vec<_> = caesar(&rest)
            .into_iter()
            .filter(|(i, _)| {
                ["Sellion", "Rt. Tragion", "Crotch", "Lt. Dactylion"]
                    .contains(&CAESAR_LANDMARKS[*i].name)
            })
            .map(|(i, p)| (i, p + Vector3::new(0.0, 0.0, 500.0 * i as f64)))
            .collect();
        let check = judge_given(&rest, &set, 1.0, &CheckParams::default());
        assert!(check.flagged.is_empty(), "{:?}", names(&check));
        assert_eq!(check.unjudged.len(), 4);
        // The same through the set and the template.
        let template = Template::embedded().unwrap();
        let given = LandmarkSet {
            landmarks: set
                .iter()
                .map(|&(i, position)| Landmark {
                    name: CAESAR_LANDMARKS[i].name.into(),
                    position,
                })
                .collect(),
            ..LandmarkSet::default()
        };
        assert_eq!(check_given(&template, &given, 1.0), check);
    }

    #[test]
    fn every_group_name_is_a_caesar_landmark_and_every_landmark_has_a_group() {
        let groups = rigid_groups();
        assert_eq!(groups.len(), 3 + 2 * 6);
        for (i, l) in CAESAR_LANDMARKS.iter().enumerate() {
            assert!(groups.iter().any(|g| g.contains(&i)), "{}", l.name);
        }
    }
}
