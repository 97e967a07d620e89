//! How sharply each CAESAR landmark's definition pins it on the body surface: a property of the
//! definition (what an anthropometrist palpates or looks for), not of any one scan. The reasons,
//! landmark by landmark, are in `docs/template.md` ("Landmarks").
//!
//! The estimate reads its spread for the confidence (`estimate/confidence.rs`): a
//! landmark defined as a level on a smooth surface (Waist Preferred Post., 10th Rib Midspine) is
//! uncertain along that surface however well the body is fitted, and independent placements of
//! it spread by centimetres.

/// How sharply a landmark's definition fixes it on the surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DefinitionSharpness {
    /// A tip, notch, crease end or bony point under thin skin, seen or felt within a few
    /// millimetres (Sellion, Suprasternale, the styloids, Dactylion, the malleoli).
    Point,
    /// A bony prominence palpated through soft tissue or a rounded surface extreme, placed
    /// within about a centimetre (Acromion, ASIS, PSIS, the epicondyles, Gonion).
    Prominence,
    /// A level or extreme on a smooth surface — by counting vertebrae, by a height or by the
    /// subject's choice (Cervicale on a scan, 10th Rib Midspine, Waist Preferred Post.,
    /// Iliocristale, Trochanterion); placements spread by 2 cm or more along the surface.
    Level,
}

impl DefinitionSharpness {
    /// The typical spread (m) of independent placements along the surface: 5, 10, 25 mm.
    pub fn spread(self) -> f64 {
        match self {
            Self::Point => 0.005,
            Self::Prominence => 0.010,
            Self::Level => 0.025,
        }
    }

    /// `point`, `prominence` or `level` (reports, docs).
    pub fn name(self) -> &'static str {
        match self {
            Self::Point => "point",
            Self::Prominence => "prominence",
            Self::Level => "level",
        }
    }
}

use DefinitionSharpness::{Level, Point, Prominence};

/// Each CAESAR landmark name without its `Lt. ` / `Rt. ` side, with its sharpness (41 names
/// for the 73 landmarks).
pub const DEFINITION_SHARPNESS: [(&str, DefinitionSharpness); 41] = [
    ("Sellion", Point),
    ("Infraorbitale", Prominence),
    ("Supramenton", Point),
    ("Tragion", Point),
    ("Gonion", Prominence),
    ("Nuchale", Level),
    ("Clavicale", Prominence),
    ("Suprasternale", Point),
    ("Thelion/Bustpoint", Prominence),
    ("Substernale", Prominence),
    ("10th Rib", Level),
    ("ASIS", Prominence),
    ("Iliocristale", Level),
    ("Trochanterion", Level),
    ("Cervicale", Level),
    ("10th Rib Midspine", Level),
    ("PSIS", Prominence),
    ("Waist, Preferred, Post.", Level),
    ("Acromion", Prominence),
    ("Axilla, Ant.", Prominence),
    ("Radial Styloid", Point),
    ("Axilla, Post.", Prominence),
    ("Olecranon", Point),
    ("Humeral Lateral Epicn", Prominence),
    ("Humeral Medial Epicn", Prominence),
    ("Radiale", Prominence),
    ("Metacarpal Phal. II", Point),
    ("Dactylion", Point),
    ("Ulnar Styloid", Point),
    ("Metacarpal Phal. V", Point),
    ("Knee Crease", Level),
    ("Femoral Lateral Epicn", Prominence),
    ("Femoral Medial Epicn", Prominence),
    ("Metatarsal Phal. V", Prominence),
    ("Lateral Malleolus", Point),
    ("Medial Malleolus", Point),
    ("Sphyrion", Point),
    ("Metatarsal Phal. I", Prominence),
    ("Calcaneous, Post.", Point),
    ("Digit II", Point),
    ("Crotch", Prominence),
];

/// The sharpness of a canonical CAESAR landmark name (`Lt. ASIS`, `Cervicale`); `None` for a
/// name that is not one of the 73.
pub fn definition_sharpness(name: &str) -> Option<DefinitionSharpness> {
    let base = name
        .strip_prefix("Lt. ")
        .or_else(|| name.strip_prefix("Rt. "))
        .unwrap_or(name);
    DEFINITION_SHARPNESS
        .iter()
        .find(|(n, _)| *n == base)
        .map(|&(_, s)| s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::landmarks::CAESAR_LANDMARKS;

    #[test]
    fn every_caesar_landmark_has_a_sharpness_and_every_entry_is_used() {
        for l in CAESAR_LANDMARKS {
            assert!(definition_sharpness(l.name).is_some(), "{}", l.name);
        }
        for (base, _) in DEFINITION_SHARPNESS {
            assert!(
                CAESAR_LANDMARKS.iter().any(|l| l.name == base
                    || l.name.strip_prefix("Lt. ") == Some(base)
                    || l.name.strip_prefix("Rt. ") == Some(base)),
                "{base}"
            );
        }
        assert_eq!(definition_sharpness("Nose"), None);
    }

    #[test]
    fn both_sides_share_one_sharpness() {
        assert_eq!(definition_sharpness("Rt. ASIS"), Some(Prominence));
        assert_eq!(definition_sharpness("Lt. ASIS"), Some(Prominence));
        assert_eq!(definition_sharpness("Waist, Preferred, Post."), Some(Level));
        assert!(Point.spread() < Prominence.spread() && Prominence.spread() < Level.spread());
    }
}
