//! Body parts for reporting: head, torso, arms, hands, legs, feet — one per vertex, made from the
//! template's own data only (segments, region flags, landmarks), so any subject's figures are cut
//! the same way.
//!
//! * hands: vertices flagged [`RegionFlags::HAND`];
//! * feet: vertices flagged [`RegionFlags::SOLE`], and leg vertices no higher than that side's
//!   ankle (the higher of its lateral and medial malleolus landmarks);
//! * otherwise the vertex's dominant segment: head, torso, arms (left or right arm), legs.

use super::flags::RegionFlags;
use super::model::Template;
use super::segment::Segment;

/// One body part.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BodyPart {
    Head,
    Torso,
    Arms,
    Hands,
    Legs,
    Feet,
}

impl BodyPart {
    /// All parts in report order.
    pub const ALL: [BodyPart; 6] = [
        BodyPart::Head,
        BodyPart::Torso,
        BodyPart::Arms,
        BodyPart::Hands,
        BodyPart::Legs,
        BodyPart::Feet,
    ];

    /// The lower-case name used in reports.
    pub fn name(self) -> &'static str {
        match self {
            BodyPart::Head => "head",
            BodyPart::Torso => "torso",
            BodyPart::Arms => "arms",
            BodyPart::Hands => "hands",
            BodyPart::Legs => "legs",
            BodyPart::Feet => "feet",
        }
    }

    /// Index of this part in [`BodyPart::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }
}

/// The body part of every vertex of `template` (its resolution's vertex count).
pub fn body_parts(template: &Template) -> Vec<BodyPart> {
    let landmark_y = |name: &str| {
        template
            .landmark_vertex(name)
            .map(|v| template.mesh().positions[v as usize].y)
    };
    let ankle = |side: &str| {
        ["Lateral Malleolus", "Medial Malleolus"]
            .iter()
            .filter_map(|l| landmark_y(&format!("{side}. {l}")))
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (left_ankle, right_ankle) = (ankle("Lt"), ankle("Rt"));
    let weights = template.segment_weight_table();
    template
        .mesh()
        .positions
        .iter()
        .zip(weights)
        .enumerate()
        .map(|(v, (p, w))| {
            let flags = template.flags(v as u32);
            let dominant = (0..w.len())
                .max_by(|&i, &j| w[i].total_cmp(&w[j]))
                .map_or(Segment::Torso, |i| Segment::ALL[i]);
            if flags.any(RegionFlags::HAND) {
                return BodyPart::Hands;
            }
            match dominant {
                _ if flags.any(RegionFlags::SOLE) => BodyPart::Feet,
                Segment::LeftLeg if p.y <= left_ankle => BodyPart::Feet,
                Segment::RightLeg if p.y <= right_ankle => BodyPart::Feet,
                Segment::LeftLeg | Segment::RightLeg => BodyPart::Legs,
                Segment::LeftArm | Segment::RightArm => BodyPart::Arms,
                Segment::Head => BodyPart::Head,
                Segment::Torso => BodyPart::Torso,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_part_is_there_and_landmarks_fall_in_their_parts() {
        let t = Template::embedded().unwrap();
        let parts = body_parts(&t);
        assert_eq!(parts.len(), t.mesh().positions.len());
        let mut count = [0usize; 6];
        for p in &parts {
            count[p.index()] += 1;
        }
        assert!(count.iter().all(|&c| c > 100), "{count:?}");
        let part_of = |name: &str| parts[t.landmark_vertex(name).unwrap() as usize];
        assert_eq!(part_of("Sellion"), BodyPart::Head);
        assert_eq!(part_of("Lt. Olecranon"), BodyPart::Arms);
        assert_eq!(part_of("Rt. Knee Crease"), BodyPart::Legs);
        assert_eq!(part_of("Lt. Calcaneous, Post."), BodyPart::Feet);
        assert_eq!(part_of("Rt. Metatarsal Phal. V"), BodyPart::Feet);
        assert_eq!(part_of("Lt. Dactylion"), BodyPart::Hands);
        assert_eq!(part_of("Substernale"), BodyPart::Torso);
    }
}
