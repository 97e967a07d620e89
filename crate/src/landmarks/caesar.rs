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

/// One table row of [`CAESAR_LANDMARKS`].
const fn landmark(
    lnd_order: u8,
    name: &'static str,
    segment: Segment,
    also_in: &'static [Segment],
) -> CaesarLandmark {
    CaesarLandmark {
        lnd_order,
        name,
        segment,
        also_in,
    }
}

/// Number of CAESAR anatomical landmarks.
pub const CAESAR_LANDMARK_COUNT: usize = 73;

/// The 73 CAESAR landmarks in `.lnd` file order.
pub const CAESAR_LANDMARKS: [CaesarLandmark; CAESAR_LANDMARK_COUNT] = [
    landmark(1, "Sellion", Segment::Head, &[]),
    landmark(2, "Rt. Infraorbitale", Segment::Head, &[]),
    landmark(3, "Lt. Infraorbitale", Segment::Head, &[]),
    landmark(4, "Supramenton", Segment::Head, &[Segment::Torso]),
    landmark(5, "Rt. Tragion", Segment::Head, &[]),
    landmark(6, "Rt. Gonion", Segment::Head, &[Segment::Torso]),
    landmark(7, "Lt. Tragion", Segment::Head, &[]),
    landmark(8, "Lt. Gonion", Segment::Head, &[Segment::Torso]),
    landmark(9, "Nuchale", Segment::Head, &[Segment::Torso]),
    landmark(10, "Rt. Clavicale", Segment::Torso, &[]),
    landmark(11, "Suprasternale", Segment::Torso, &[]),
    landmark(12, "Lt. Clavicale", Segment::Torso, &[]),
    landmark(13, "Rt. Thelion/Bustpoint", Segment::Torso, &[]),
    landmark(14, "Lt. Thelion/Bustpoint", Segment::Torso, &[]),
    landmark(15, "Substernale", Segment::Torso, &[]),
    landmark(16, "Rt. 10th Rib", Segment::Torso, &[]),
    landmark(17, "Rt. ASIS", Segment::Torso, &[]),
    landmark(18, "Lt. 10th Rib", Segment::Torso, &[]),
    landmark(19, "Lt. ASIS", Segment::Torso, &[]),
    landmark(20, "Rt. Iliocristale", Segment::Torso, &[]),
    landmark(
        21,
        "Rt. Trochanterion",
        Segment::Torso,
        &[Segment::RightLeg],
    ),
    landmark(22, "Lt. Iliocristale", Segment::Torso, &[]),
    landmark(23, "Lt. Trochanterion", Segment::Torso, &[Segment::LeftLeg]),
    landmark(24, "Cervicale", Segment::Torso, &[Segment::Head]),
    landmark(25, "10th Rib Midspine", Segment::Torso, &[]),
    landmark(26, "Rt. PSIS", Segment::Torso, &[]),
    landmark(27, "Lt. PSIS", Segment::Torso, &[]),
    landmark(28, "Waist, Preferred, Post.", Segment::Torso, &[]),
    landmark(29, "Rt. Acromion", Segment::RightArm, &[Segment::Torso]),
    landmark(30, "Rt. Axilla, Ant.", Segment::RightArm, &[Segment::Torso]),
    landmark(31, "Rt. Radial Styloid", Segment::RightArm, &[]),
    landmark(
        32,
        "Rt. Axilla, Post.",
        Segment::RightArm,
        &[Segment::Torso],
    ),
    landmark(33, "Rt. Olecranon", Segment::RightArm, &[]),
    landmark(34, "Rt. Humeral Lateral Epicn", Segment::RightArm, &[]),
    landmark(35, "Rt. Humeral Medial Epicn", Segment::RightArm, &[]),
    landmark(36, "Rt. Radiale", Segment::RightArm, &[]),
    landmark(37, "Rt. Metacarpal Phal. II", Segment::RightArm, &[]),
    landmark(38, "Rt. Dactylion", Segment::RightArm, &[]),
    landmark(39, "Rt. Ulnar Styloid", Segment::RightArm, &[]),
    landmark(40, "Rt. Metacarpal Phal. V", Segment::RightArm, &[]),
    landmark(41, "Lt. Acromion", Segment::LeftArm, &[Segment::Torso]),
    landmark(42, "Lt. Axilla, Ant.", Segment::LeftArm, &[Segment::Torso]),
    landmark(43, "Lt. Radial Styloid", Segment::LeftArm, &[]),
    landmark(44, "Lt. Axilla, Post.", Segment::LeftArm, &[Segment::Torso]),
    landmark(45, "Lt. Olecranon", Segment::LeftArm, &[]),
    landmark(46, "Lt. Humeral Lateral Epicn", Segment::LeftArm, &[]),
    landmark(47, "Lt. Humeral Medial Epicn", Segment::LeftArm, &[]),
    landmark(48, "Lt. Radiale", Segment::LeftArm, &[]),
    landmark(49, "Lt. Metacarpal Phal. II", Segment::LeftArm, &[]),
    landmark(50, "Lt. Dactylion", Segment::LeftArm, &[]),
    landmark(51, "Lt. Ulnar Styloid", Segment::LeftArm, &[]),
    landmark(52, "Lt. Metacarpal Phal. V", Segment::LeftArm, &[]),
    landmark(53, "Rt. Knee Crease", Segment::RightLeg, &[]),
    landmark(54, "Rt. Femoral Lateral Epicn", Segment::RightLeg, &[]),
    landmark(55, "Rt. Femoral Medial Epicn", Segment::RightLeg, &[]),
    landmark(56, "Rt. Metatarsal Phal. V", Segment::RightLeg, &[]),
    landmark(57, "Rt. Lateral Malleolus", Segment::RightLeg, &[]),
    landmark(58, "Rt. Medial Malleolus", Segment::RightLeg, &[]),
    landmark(59, "Rt. Sphyrion", Segment::RightLeg, &[]),
    landmark(60, "Rt. Metatarsal Phal. I", Segment::RightLeg, &[]),
    landmark(61, "Rt. Calcaneous, Post.", Segment::RightLeg, &[]),
    landmark(62, "Rt. Digit II", Segment::RightLeg, &[]),
    landmark(63, "Lt. Knee Crease", Segment::LeftLeg, &[]),
    landmark(64, "Lt. Femoral Lateral Epicn", Segment::LeftLeg, &[]),
    landmark(65, "Lt. Femoral Medial Epicn", Segment::LeftLeg, &[]),
    landmark(66, "Lt. Metatarsal Phal. V", Segment::LeftLeg, &[]),
    landmark(67, "Lt. Lateral Malleolus", Segment::LeftLeg, &[]),
    landmark(68, "Lt. Medial Malleolus", Segment::LeftLeg, &[]),
    landmark(69, "Lt. Sphyrion", Segment::LeftLeg, &[]),
    landmark(70, "Lt. Metatarsal Phal. I", Segment::LeftLeg, &[]),
    landmark(71, "Lt. Calcaneous, Post.", Segment::LeftLeg, &[]),
    landmark(72, "Lt. Digit II", Segment::LeftLeg, &[]),
    landmark(
        73,
        "Crotch",
        Segment::Torso,
        &[Segment::LeftLeg, Segment::RightLeg],
    ),
];
