//! The 73 CAESAR anatomical landmarks: canonical names, `.lnd` file order and body segment.
//!
//! Canonical names and order follow the CAESAR `.lnd` standard landmark list; `segment` is the
//! template segment each landmark belongs to and `also_in` the neighbouring segments whose overlap
//! band also contains it.

use crate::template::segment::Segment;

/// One CAESAR landmark as the project knows it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CaesarLandmark {
    /// 1-based position in a CAESAR `.lnd` file.
    pub lnd_order: u8,
    /// Canonical name, e.g. `Rt. Acromion`.
    pub name: &'static str,
    /// The segment the landmark belongs to.
    pub segment: Segment,
    /// Neighbouring segments whose overlap band also holds this landmark.
    pub also_in: &'static [Segment],
}

/// Number of CAESAR anatomical landmarks.
pub const CAESAR_LANDMARK_COUNT: usize = 73;

/// The 73 CAESAR landmarks in `.lnd` file order.
pub const CAESAR_LANDMARKS: [CaesarLandmark; CAESAR_LANDMARK_COUNT] = [
    CaesarLandmark {
        lnd_order: 1,
        name: "Sellion",
        segment: Segment::Head,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 2,
        name: "Rt. Infraorbitale",
        segment: Segment::Head,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 3,
        name: "Lt. Infraorbitale",
        segment: Segment::Head,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 4,
        name: "Supramenton",
        segment: Segment::Head,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 5,
        name: "Rt. Tragion",
        segment: Segment::Head,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 6,
        name: "Rt. Gonion",
        segment: Segment::Head,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 7,
        name: "Lt. Tragion",
        segment: Segment::Head,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 8,
        name: "Lt. Gonion",
        segment: Segment::Head,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 9,
        name: "Nuchale",
        segment: Segment::Head,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 10,
        name: "Rt. Clavicale",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 11,
        name: "Suprasternale",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 12,
        name: "Lt. Clavicale",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 13,
        name: "Rt. Thelion/Bustpoint",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 14,
        name: "Lt. Thelion/Bustpoint",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 15,
        name: "Substernale",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 16,
        name: "Rt. 10th Rib",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 17,
        name: "Rt. ASIS",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 18,
        name: "Lt. 10th Rib",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 19,
        name: "Lt. ASIS",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 20,
        name: "Rt. Iliocristale",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 21,
        name: "Rt. Trochanterion",
        segment: Segment::Torso,
        also_in: &[Segment::RightLeg],
    },
    CaesarLandmark {
        lnd_order: 22,
        name: "Lt. Iliocristale",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 23,
        name: "Lt. Trochanterion",
        segment: Segment::Torso,
        also_in: &[Segment::LeftLeg],
    },
    CaesarLandmark {
        lnd_order: 24,
        name: "Cervicale",
        segment: Segment::Torso,
        also_in: &[Segment::Head],
    },
    CaesarLandmark {
        lnd_order: 25,
        name: "10th Rib Midspine",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 26,
        name: "Rt. PSIS",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 27,
        name: "Lt. PSIS",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 28,
        name: "Waist, Preferred, Post.",
        segment: Segment::Torso,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 29,
        name: "Rt. Acromion",
        segment: Segment::RightArm,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 30,
        name: "Rt. Axilla, Ant.",
        segment: Segment::RightArm,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 31,
        name: "Rt. Radial Styloid",
        segment: Segment::RightArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 32,
        name: "Rt. Axilla, Post.",
        segment: Segment::RightArm,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 33,
        name: "Rt. Olecranon",
        segment: Segment::RightArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 34,
        name: "Rt. Humeral Lateral Epicn",
        segment: Segment::RightArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 35,
        name: "Rt. Humeral Medial Epicn",
        segment: Segment::RightArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 36,
        name: "Rt. Radiale",
        segment: Segment::RightArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 37,
        name: "Rt. Metacarpal Phal. II",
        segment: Segment::RightArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 38,
        name: "Rt. Dactylion",
        segment: Segment::RightArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 39,
        name: "Rt. Ulnar Styloid",
        segment: Segment::RightArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 40,
        name: "Rt. Metacarpal Phal. V",
        segment: Segment::RightArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 41,
        name: "Lt. Acromion",
        segment: Segment::LeftArm,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 42,
        name: "Lt. Axilla, Ant.",
        segment: Segment::LeftArm,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 43,
        name: "Lt. Radial Styloid",
        segment: Segment::LeftArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 44,
        name: "Lt. Axilla, Post.",
        segment: Segment::LeftArm,
        also_in: &[Segment::Torso],
    },
    CaesarLandmark {
        lnd_order: 45,
        name: "Lt. Olecranon",
        segment: Segment::LeftArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 46,
        name: "Lt. Humeral Lateral Epicn",
        segment: Segment::LeftArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 47,
        name: "Lt. Humeral Medial Epicn",
        segment: Segment::LeftArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 48,
        name: "Lt. Radiale",
        segment: Segment::LeftArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 49,
        name: "Lt. Metacarpal Phal. II",
        segment: Segment::LeftArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 50,
        name: "Lt. Dactylion",
        segment: Segment::LeftArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 51,
        name: "Lt. Ulnar Styloid",
        segment: Segment::LeftArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 52,
        name: "Lt. Metacarpal Phal. V",
        segment: Segment::LeftArm,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 53,
        name: "Rt. Knee Crease",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 54,
        name: "Rt. Femoral Lateral Epicn",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 55,
        name: "Rt. Femoral Medial Epicn",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 56,
        name: "Rt. Metatarsal Phal. V",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 57,
        name: "Rt. Lateral Malleolus",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 58,
        name: "Rt. Medial Malleolus",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 59,
        name: "Rt. Sphyrion",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 60,
        name: "Rt. Metatarsal Phal. I",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 61,
        name: "Rt. Calcaneous, Post.",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 62,
        name: "Rt. Digit II",
        segment: Segment::RightLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 63,
        name: "Lt. Knee Crease",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 64,
        name: "Lt. Femoral Lateral Epicn",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 65,
        name: "Lt. Femoral Medial Epicn",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 66,
        name: "Lt. Metatarsal Phal. V",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 67,
        name: "Lt. Lateral Malleolus",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 68,
        name: "Lt. Medial Malleolus",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 69,
        name: "Lt. Sphyrion",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 70,
        name: "Lt. Metatarsal Phal. I",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 71,
        name: "Lt. Calcaneous, Post.",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 72,
        name: "Lt. Digit II",
        segment: Segment::LeftLeg,
        also_in: &[],
    },
    CaesarLandmark {
        lnd_order: 73,
        name: "Crotch",
        segment: Segment::Torso,
        also_in: &[Segment::LeftLeg, Segment::RightLeg],
    },
];
