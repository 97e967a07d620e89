//! The template posed part by part to the scan's landmarks, before the RBF warp (not in the
//! paper): the RBF then interpolates only what the pose leaves — the residual landmark
//! displacements — instead of bending a straight template limb into a posed one, which shears
//! the surface along the limb.
//!
//! The parts are the template's ten rigid parts (`template::parts::parts`: torso,
//! head, upper and lower part of each limb, with the template's segment blend weights). A global
//! similarity S (Procrustes on the torso's landmark pairs) fixes the common scale s; then,
//! parents first, each posed part ([`POSED`]: head and arms) gets the rigid motion (at scale s)
//! that best maps its landmarks (those whose vertex the part dominates) to the scan's, with its
//! joint held where the already-moved parent puts it. A part with fewer than [`MIN_LANDMARKS`]
//! landmarks, and every part not posed, follows its parent. Vertices move by the blend
//! Σ_p w_p(v)·T_p(v) (linear blend skinning). Each hand is then turned about its wrist onto its
//! own landmarks (`template::hand::turn_hand_onto`: the knuckles and the fingertip seen from the
//! styloids), blended to nothing at the wrist: the forearm part carries the hand rigidly, and a
//! hand laid on the hip is bent back 20–50° at the wrist.

use nalgebra::Point3;

use crate::landmarks::LandmarkSet;
use crate::mesh::similarity::{similarity, Similarity};
use crate::template::hand::{hands, turn_hand_onto};
use crate::template::parts::{blend, dominant_part, parts, PartPose};
use crate::template::Template;

/// The parts that get their own motion; the torso and the legs keep the global similarity and
/// leave the rest to the RBF. Posing the legs too (thigh and lower leg each from their own
/// landmarks) made the legs' correspondence after the warp worse (15.8 → 17.6 mm, 4 development
/// subjects): a thigh has two landmarks, and the lower leg's knee and ankle landmarks already
/// bend it well through the RBF.
const POSED: [&str; 5] = [
    "head",
    "left upper arm",
    "left forearm",
    "right upper arm",
    "right forearm",
];

/// A part with fewer landmarks than this follows its parent: two landmarks and the joint, nearly
/// on one line (the thighs: trochanterion, medial epicondyle), leave the turn about the limb
/// axis to the landmarks' noise.
const MIN_LANDMARKS: usize = 3;

/// `template` posed to `scan_landmarks` (scan frame and units): its `#V` vertex positions and its
/// CAESAR landmarks at their posed vertices. `None` when fewer than three of the torso's landmarks
/// match by name or they are degenerate (the caller warps the rest template then).
pub fn pose_parts(
    template: &Template,
    scan_landmarks: &LandmarkSet,
) -> Option<(Vec<Point3<f64>>, LandmarkSet)> {
    let rest = &template.mesh().positions;
    let pairs: Vec<(u32, Point3<f64>)> = template
        .landmark_vertices()
        .iter()
        .filter_map(|(name, v)| Some((*v, scan_landmarks.get(name)?)))
        .collect();
    let parts = parts(template);
    // The torso's landmarks alone fix the global similarity: the limbs' would turn it with
    // their pose.
    let (from, to): (Vec<_>, Vec<_>) = pairs
        .iter()
        .filter(|(v, _)| dominant_part(&parts, *v) == 0)
        .map(|(v, q)| (rest[*v as usize], *q))
        .unzip();
    if from.len() < 3 {
        return None;
    }
    let global = similarity(&from, &to, true)?;
    let mut transforms: Vec<Similarity> = vec![global; parts.len()];
    for (k, part) in parts.iter().enumerate() {
        let (mut from, mut to): (Vec<_>, Vec<_>) = pairs
            .iter()
            .filter(|(v, _)| dominant_part(&parts, *v) == k)
            .map(|(v, q)| (rest[*v as usize] * global.scale, *q))
            .unzip();
        let own = from.len();
        let parent = part.parent.map(|p| transforms[p]);
        if let Some(parent) = parent {
            from.push(part.joint * global.scale);
            to.push(parent.apply(&part.joint));
        }
        let posed = POSED.contains(&part.name);
        let rigid = (posed && own >= MIN_LANDMARKS)
            .then(|| similarity(&from, &to, false))
            .flatten();
        transforms[k] = match (rigid, parent) {
            (Some(r), _) => Similarity {
                scale: global.scale,
                rotation: r.rotation,
                translation: r.translation,
            },
            (None, Some(parent)) => parent,
            (None, None) => global,
        };
    }
    // Rigid at the body's scale: no stretch along a part's axis.
    let poses: Vec<PartPose> = transforms
        .into_iter()
        .map(|transform| PartPose {
            transform,
            stretch: 1.0,
        })
        .collect();
    let mut posed = blend(&parts, &poses, rest);
    for hand in hands(template) {
        turn_hand_onto(&hand, &mut posed, template, scan_landmarks);
    }
    let landmarks = template.landmarks_at(&posed);
    Some((posed, landmarks))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Rotation3, Vector3};

    #[test]
    fn the_template_posed_to_its_own_landmarks_stays_where_it_is() {
        let t = Template::embedded().unwrap();
        let (posed, landmarks) = pose_parts(&t, &t.landmark_positions()).unwrap();
        let rest = &t.mesh().positions;
        let worst = posed
            .iter()
            .zip(rest)
            .map(|(p, q)| (p - q).norm())
            .fold(0.0, f64::max);
        assert!(worst < 1e-9, "moved by {worst} m");
        assert_eq!(landmarks.landmarks.len(), t.landmark_vertices().len());
    }

    #[test]
    fn without_three_torso_landmarks_nothing_is_posed() {
        let t = Template::embedded().unwrap();
        let mut scan = t.landmark_positions();
        scan.landmarks
            .retain(|l| ["Suprasternale", "Crotch", "Lt. Radiale"].contains(&l.name.as_str()));
        assert!(pose_parts(&t, &scan).is_none());
        scan.landmarks.clear();
        assert!(pose_parts(&t, &scan).is_none());
    }

    #[test]
    fn a_bent_forearm_is_followed_and_the_torso_stays() {
        let t = Template::embedded().unwrap();
        let rest = &t.mesh().positions;
        let parts = parts(&t);
        let forearm = parts.iter().position(|p| p.name == "left forearm").unwrap();
        let elbow = parts[forearm].joint;
        // Scan landmarks: the template's, with the left forearm's bent 60° about the elbow and
        // the whole body moved by 1 m.
        let bend = Rotation3::from_axis_angle(&Vector3::x_axis(), 60f64.to_radians());
        let shift = Vector3::new(1.0, 0.0, 0.0);
        let mut scan = t.landmark_positions();
        for (l, (_, v)) in scan.landmarks.iter_mut().zip(t.landmark_vertices()) {
            if dominant_part(&parts, *v) == forearm {
                l.position = elbow + bend * (l.position - elbow);
            }
            l.position += shift;
        }
        let (posed, _) = pose_parts(&t, &scan).unwrap();
        // The global similarity sees the bent landmarks too, so nothing lands exactly; unposed,
        // the fingertips would be ≈ 0.3 m away.
        let (mut hand, mut unposed, mut torso) = (0.0f64, 0.0f64, 0.0f64);
        for (v, p) in posed.iter().enumerate() {
            let w = |k: usize| parts[k].weights[v];
            if w(forearm) > 0.999 {
                let expected = elbow + bend * (rest[v] - elbow) + shift;
                hand = hand.max((p - expected).norm());
                unposed = unposed.max((rest[v] + shift - expected).norm());
            }
            if w(0) > 0.999 {
                torso = torso.max((p - (rest[v] + shift)).norm());
            }
        }
        assert!(unposed > 0.2, "the bend moves the hand by {unposed} m");
        assert!(hand < 0.01, "forearm off by {hand} m");
        assert!(torso < 0.01, "torso off by {torso} m");
    }
}
