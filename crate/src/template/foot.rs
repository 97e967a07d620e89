//! The template's feet: each foot's vertices about and beyond the ankle with their share of a
//! motion about it (rising smoothly over the few centimetres above it, so that the malleoli move
//! with the foot), and the landmark vertices that place the ankle (the malleoli) and the knee
//! (the femoral epicondyles).
//! The landmark estimate poses each foot on the scan (`estimate::foot`).

use super::hand::{end_and_axis, own_and_triangles, smoothstep};
use crate::template::{Segment, Template};

/// The foot's share of the motion rises from 0 at the first of these distances (m) along the
/// lower leg from the ankle's plane to 1 at the second: from 5 cm above the ankle to 1 cm above
/// it. Rising across the ankle instead (−1 to +2 cm, as the hand's does across the wrist), the
/// malleoli hardly moved with the foot (docs/landmarks-estimate.md).
const BLEND: (f64, f64) = (-0.05, -0.01);

/// One foot of the template.
#[derive(Debug, Clone)]
pub struct Foot {
    pub side: &'static str,
    /// Lateral and medial malleolus: the ankle is their midpoint.
    pub(crate) malleoli: [u32; 2],
    /// The vertices the foot's motion moves, each with its share of it.
    pub(crate) share: Vec<(u32, f64)>,
    /// The vertices wholly the foot's (share 1): those matched to the scan.
    pub(crate) own: Vec<u32>,
    /// The template's triangles with every corner among the moved vertices: every triangle
    /// around a vertex wholly the foot's, so its normal is the whole mesh's.
    pub(crate) triangles: Vec<[u32; 3]>,
}

/// The template's two feet (`template` at the resolution fitted): the leg segment's vertices
/// (weight ≥ ½) beyond a plane across the lower leg 5 cm above the ankle (the lower leg from the
/// midpoint of the femoral epicondyles to that of the malleoli), wholly the foot's from 1 cm
/// above it. A side whose landmark vertices are missing has no foot.
pub fn feet(template: &Template) -> Vec<Foot> {
    let rest = &template.mesh().positions;
    let mut out = Vec::new();
    for (side, segment) in [("Lt.", Segment::LeftLeg), ("Rt.", Segment::RightLeg)] {
        let pair = |a: &str, b: &str| {
            Some([
                template.landmark_vertex(&format!("{side} {a}"))?,
                template.landmark_vertex(&format!("{side} {b}"))?,
            ])
        };
        let (Some(malleoli), Some(epicondyles)) = (
            pair("Lateral Malleolus", "Medial Malleolus"),
            pair("Femoral Lateral Epicn", "Femoral Medial Epicn"),
        ) else {
            continue;
        };
        let (ankle, axis) = end_and_axis(rest, malleoli, epicondyles);
        let share: Vec<(u32, f64)> = rest
            .iter()
            .enumerate()
            .filter(|(v, _)| template.segment_weights(*v as u32)[segment.index()] >= 0.5)
            .filter_map(|(v, p)| {
                let s = smoothstep(((p - ankle).dot(&axis) - BLEND.0) / (BLEND.1 - BLEND.0));
                (s > 0.0).then_some((v as u32, s))
            })
            .collect();
        let (own, triangles) = own_and_triangles(template, &share);
        out.push(Foot {
            side,
            malleoli,
            share,
            own,
            triangles,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::template::body_part::{body_parts, BodyPart};
    use crate::template::fixture::base_body;

    #[test]
    fn each_foot_is_the_leg_below_its_ankle_and_holds_the_foot_landmarks() {
        let template = base_body().template;
        let feet = feet(&template);
        assert_eq!(feet.len(), 2);
        let parts = body_parts(&template);
        for foot in &feet {
            // The vertices the reports call this side's foot move wholly with it (all but a few
            // at the top of the inner ankle, over the plane across the leg).
            let segment = if foot.side == "Lt." {
                Segment::LeftLeg
            } else {
                Segment::RightLeg
            };
            let reported: Vec<u32> = (0..parts.len() as u32)
                .filter(|&v| parts[v as usize] == BodyPart::Feet)
                .filter(|&v| template.segment_weights(v)[segment.index()] >= 0.5)
                .collect();
            assert!(reported.len() > 100, "{} {}", foot.side, reported.len());
            let outside = reported.iter().filter(|v| !foot.own.contains(v)).count();
            assert!(outside * 100 <= reported.len(), "{} {outside}", foot.side);
            // Every triangle around a vertex wholly the foot's is the foot's.
            let around = template
                .mesh()
                .triangles
                .iter()
                .filter(|t| t.iter().any(|v| foot.own.contains(v)));
            assert!(around.into_iter().all(|t| foot.triangles.contains(t)));
            let moved = |name: &str| {
                let v = template
                    .landmark_vertex(&format!("{} {name}", foot.side))
                    .unwrap();
                foot.share
                    .iter()
                    .find(|(u, _)| *u == v)
                    .map_or(0.0, |(_, s)| *s)
            };
            // The toes, the heel and the sole move with the foot; the knee does not.
            for name in ["Metatarsal Phal. I", "Digit II", "Calcaneous, Post."] {
                assert_eq!(moved(name), 1.0, "{} {name}", foot.side);
            }
            assert_eq!(moved("Femoral Lateral Epicn"), 0.0);
        }
    }
}
