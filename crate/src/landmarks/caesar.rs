//! The 73 CAESAR anatomical landmarks: canonical names, `.lnd` file order and body segment.
//!
//! Canonical names and order follow the CAESAR `.lnd` standard landmark list; `segment` is the
//! template segment each landmark belongs to and `also_in` the neighbouring segments whose overlap
//! band also contains it.

use crate::template::segment::Segment;
use Segment::{Head, LeftArm, LeftLeg, RightArm, RightLeg, Torso};

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
    landmark(1, "Sellion", Head, &[]),
    landmark(2, "Rt. Infraorbitale", Head, &[]),
    landmark(3, "Lt. Infraorbitale", Head, &[]),
    landmark(4, "Supramenton", Head, &[Torso]),
    landmark(5, "Rt. Tragion", Head, &[]),
    landmark(6, "Rt. Gonion", Head, &[Torso]),
    landmark(7, "Lt. Tragion", Head, &[]),
    landmark(8, "Lt. Gonion", Head, &[Torso]),
    landmark(9, "Nuchale", Head, &[Torso]),
    landmark(10, "Rt. Clavicale", Torso, &[]),
    landmark(11, "Suprasternale", Torso, &[]),
    landmark(12, "Lt. Clavicale", Torso, &[]),
    landmark(13, "Rt. Thelion/Bustpoint", Torso, &[]),
    landmark(14, "Lt. Thelion/Bustpoint", Torso, &[]),
    landmark(15, "Substernale", Torso, &[]),
    landmark(16, "Rt. 10th Rib", Torso, &[]),
    landmark(17, "Rt. ASIS", Torso, &[]),
    landmark(18, "Lt. 10th Rib", Torso, &[]),
    landmark(19, "Lt. ASIS", Torso, &[]),
    landmark(20, "Rt. Iliocristale", Torso, &[]),
    landmark(21, "Rt. Trochanterion", Torso, &[RightLeg]),
    landmark(22, "Lt. Iliocristale", Torso, &[]),
    landmark(23, "Lt. Trochanterion", Torso, &[LeftLeg]),
    landmark(24, "Cervicale", Torso, &[Head]),
    landmark(25, "10th Rib Midspine", Torso, &[]),
    landmark(26, "Rt. PSIS", Torso, &[]),
    landmark(27, "Lt. PSIS", Torso, &[]),
    landmark(28, "Waist, Preferred, Post.", Torso, &[]),
    landmark(29, "Rt. Acromion", RightArm, &[Torso]),
    landmark(30, "Rt. Axilla, Ant.", RightArm, &[Torso]),
    landmark(31, "Rt. Radial Styloid", RightArm, &[]),
    landmark(32, "Rt. Axilla, Post.", RightArm, &[Torso]),
    landmark(33, "Rt. Olecranon", RightArm, &[]),
    landmark(34, "Rt. Humeral Lateral Epicn", RightArm, &[]),
    landmark(35, "Rt. Humeral Medial Epicn", RightArm, &[]),
    landmark(36, "Rt. Radiale", RightArm, &[]),
    landmark(37, "Rt. Metacarpal Phal. II", RightArm, &[]),
    landmark(38, "Rt. Dactylion", RightArm, &[]),
    landmark(39, "Rt. Ulnar Styloid", RightArm, &[]),
    landmark(40, "Rt. Metacarpal Phal. V", RightArm, &[]),
    landmark(41, "Lt. Acromion", LeftArm, &[Torso]),
    landmark(42, "Lt. Axilla, Ant.", LeftArm, &[Torso]),
    landmark(43, "Lt. Radial Styloid", LeftArm, &[]),
    landmark(44, "Lt. Axilla, Post.", LeftArm, &[Torso]),
    landmark(45, "Lt. Olecranon", LeftArm, &[]),
    landmark(46, "Lt. Humeral Lateral Epicn", LeftArm, &[]),
    landmark(47, "Lt. Humeral Medial Epicn", LeftArm, &[]),
    landmark(48, "Lt. Radiale", LeftArm, &[]),
    landmark(49, "Lt. Metacarpal Phal. II", LeftArm, &[]),
    landmark(50, "Lt. Dactylion", LeftArm, &[]),
    landmark(51, "Lt. Ulnar Styloid", LeftArm, &[]),
    landmark(52, "Lt. Metacarpal Phal. V", LeftArm, &[]),
    landmark(53, "Rt. Knee Crease", RightLeg, &[]),
    landmark(54, "Rt. Femoral Lateral Epicn", RightLeg, &[]),
    landmark(55, "Rt. Femoral Medial Epicn", RightLeg, &[]),
    landmark(56, "Rt. Metatarsal Phal. V", RightLeg, &[]),
    landmark(57, "Rt. Lateral Malleolus", RightLeg, &[]),
    landmark(58, "Rt. Medial Malleolus", RightLeg, &[]),
    landmark(59, "Rt. Sphyrion", RightLeg, &[]),
    landmark(60, "Rt. Metatarsal Phal. I", RightLeg, &[]),
    landmark(61, "Rt. Calcaneous, Post.", RightLeg, &[]),
    landmark(62, "Rt. Digit II", RightLeg, &[]),
    landmark(63, "Lt. Knee Crease", LeftLeg, &[]),
    landmark(64, "Lt. Femoral Lateral Epicn", LeftLeg, &[]),
    landmark(65, "Lt. Femoral Medial Epicn", LeftLeg, &[]),
    landmark(66, "Lt. Metatarsal Phal. V", LeftLeg, &[]),
    landmark(67, "Lt. Lateral Malleolus", LeftLeg, &[]),
    landmark(68, "Lt. Medial Malleolus", LeftLeg, &[]),
    landmark(69, "Lt. Sphyrion", LeftLeg, &[]),
    landmark(70, "Lt. Metatarsal Phal. I", LeftLeg, &[]),
    landmark(71, "Lt. Calcaneous, Post.", LeftLeg, &[]),
    landmark(72, "Lt. Digit II", LeftLeg, &[]),
    landmark(73, "Crotch", Torso, &[LeftLeg, RightLeg]),
];

/// The index in [`CAESAR_LANDMARKS`] of the canonical `name`.
pub fn caesar_index(name: &str) -> Option<usize> {
    CAESAR_LANDMARKS.iter().position(|l| l.name == name)
}
