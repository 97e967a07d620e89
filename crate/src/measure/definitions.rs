//! The measurements: name, kind, source and the template landmarks each is anchored on. The one
//! table the core, the CLI, the app and docs/measurements.md share; how each is taken is in
//! [`super::body`], which of its landmarks define it and which only seed a search is its
//! [`Anchoring`].

use serde::Serialize;

/// What a measurement is, which fixes its unit (m, m, m³, m²) and its tolerance when a body is
/// made to meet it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// A straight or polyline distance: heights, breadths, lengths (m).
    Length,
    /// A tape around a plane section (m).
    Girth,
    /// Enclosed volume (m³).
    Volume,
    /// Surface area (m²).
    Area,
}

/// How a measurement's landmarks make its value, which fixes what an error in a landmark does to
/// it (`trust.rs`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Anchoring {
    /// Found on the body's surface: the landmarks, if any, only seed the search (a landmark moved
    /// 2 cm moves the value ≤ 2 mm, `crate/tests/measure_body_defined.rs`, `measure_chest.rs`,
    /// `measure_crotch.rs`),
    /// or there are none (stature at the crown, volume, area).
    Surface,
    /// A level: the mean position of the first `n` landmarks along one direction (a height above
    /// the floor, the plane of a girth, the midpoint along the upper arm). The landmarks after
    /// the first `n` only pick the section's loop or seed a surface search.
    Level(usize),
    /// A distance or polyline through all the landmarks (a breadth, a segment length).
    Span,
}

/// One standard measurement.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Measure {
    Stature,
    CervicaleHeight,
    AcromionHeight,
    CrotchHeight,
    KneeHeight,
    ShoulderBreadth,
    ChestGirth,
    BustGirth,
    UnderbustGirth,
    WaistGirth,
    HipGirth,
    ThighGirth,
    UpperArmGirth,
    NeckGirth,
    NeckBaseGirth,
    HeadGirth,
    ArmLength,
    WaistToHipBack,
    Volume,
    SurfaceArea,
}

/// A measurement's description: what the docs, the CLI and the app show.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Definition {
    /// snake_case name used in JSON, CSV and on the command line (`waist_girth`).
    pub name: &'static str,
    /// Short human label ("Waist girth").
    pub label: &'static str,
    pub kind: Kind,
    /// The standard and the clause title it follows.
    pub source: &'static str,
    /// Canonical CAESAR landmark names it is anchored on (resolved through the template's
    /// landmark list, so revised landmark vertices flow through).
    pub landmarks: &'static [&'static str],
    /// How the landmarks make the value: which of them define it and which only seed a search.
    pub anchoring: Anchoring,
}

const AXILLAE: &[&str] = &[
    "Rt. Axilla, Ant.",
    "Lt. Axilla, Ant.",
    "Rt. Axilla, Post.",
    "Lt. Axilla, Post.",
];
const WAIST: &[&str] = &[
    "Rt. 10th Rib",
    "Lt. 10th Rib",
    "Rt. Iliocristale",
    "Lt. Iliocristale",
];
/// The Acromions and the landmarks of the shoulders' frames (`landmarks::shoulder`), Acromions
/// first: the acromia of shoulder breadth, acromion height and arm length are sought on the
/// surface from them (`acromion.rs`). Only the Acromions define those measurements' trust (their
/// definitions' landmarks): a guess far off still moves the point found (docs/measurements.md).
pub const SHOULDERS: &[&str] = &[
    "Rt. Acromion",
    "Lt. Acromion",
    "Suprasternale",
    "Cervicale",
    "Rt. ASIS",
    "Lt. ASIS",
    "Rt. Humeral Lateral Epicn",
    "Rt. Humeral Medial Epicn",
    "Lt. Humeral Lateral Epicn",
    "Lt. Humeral Medial Epicn",
];
const HIP: &[&str] = &["Rt. Trochanterion", "Lt. Trochanterion", "Crotch"];

impl Measure {
    /// Every measurement, in the order of tables and JSON.
    pub const ALL: [Measure; 20] = [
        Measure::Stature,
        Measure::CervicaleHeight,
        Measure::AcromionHeight,
        Measure::CrotchHeight,
        Measure::KneeHeight,
        Measure::ShoulderBreadth,
        Measure::ChestGirth,
        Measure::BustGirth,
        Measure::UnderbustGirth,
        Measure::WaistGirth,
        Measure::HipGirth,
        Measure::ThighGirth,
        Measure::UpperArmGirth,
        Measure::NeckGirth,
        Measure::NeckBaseGirth,
        Measure::HeadGirth,
        Measure::ArmLength,
        Measure::WaistToHipBack,
        Measure::Volume,
        Measure::SurfaceArea,
    ];

    /// Position in [`Measure::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// The measurement named `name` (snake_case, as [`Definition::name`]).
    pub fn from_name(name: &str) -> Option<Measure> {
        Measure::ALL
            .into_iter()
            .find(|m| m.definition().name == name)
    }

    /// The description of this measurement.
    pub fn definition(self) -> Definition {
        use Anchoring::*;
        use Kind::*;
        let d = |name, label, kind, source, landmarks, anchoring| Definition {
            name,
            label,
            kind,
            source,
            landmarks,
            anchoring,
        };
        match self {
            Measure::Stature => d("stature", "Stature", Length, "ISO 7250-1 stature (body height)", &[], Surface),
            Measure::CervicaleHeight => d(
                "cervicale_height",
                "Cervicale height",
                Length,
                "ISO 8559-1 cervicale height",
                // Found on the back profile around the Cervicale (`cervicale.rs`).
                &["Cervicale"], Surface),
            Measure::AcromionHeight => d(
                "acromion_height",
                "Acromion height",
                Length,
                "ISO 7250-1 shoulder (acromion) height",
                &["Rt. Acromion", "Lt. Acromion"], Level(2)),
            Measure::CrotchHeight => d(
                "crotch_height",
                "Crotch height (inseam)",
                Length,
                "ISO 7250-1 crotch height; ISO 8559-1 inside leg length",
                &["Crotch", "Rt. Trochanterion", "Lt. Trochanterion"], Surface),
            Measure::KneeHeight => d(
                "knee_height",
                "Knee height",
                Length,
                "ISO 8559-1 knee height",
                &["Rt. Femoral Lateral Epicn", "Rt. Femoral Medial Epicn"], Level(2)),
            Measure::ShoulderBreadth => d(
                "shoulder_breadth",
                "Shoulder breadth (biacromial)",
                Length,
                "ISO 7250-1 biacromial breadth",
                &["Rt. Acromion", "Lt. Acromion"], Span),
            Measure::ChestGirth => d("chest_girth", "Chest girth", Girth, "ISO 8559-1 chest girth", AXILLAE, Surface),
            Measure::BustGirth => d(
                "bust_girth",
                "Bust girth",
                Girth,
                "ISO 8559-1 bust girth",
                // The level of the bust points found on the surface (`surface.rs`, `bust_level`).
                &["Rt. Thelion/Bustpoint", "Lt. Thelion/Bustpoint"], Surface),
            Measure::UnderbustGirth => d(
                "underbust_girth",
                "Underbust girth",
                Girth,
                "ISO 8559-1 underbust girth",
                &["Substernale"], Level(1)),
            Measure::WaistGirth => d("waist_girth", "Waist girth", Girth, "ISO 8559-1 waist girth", WAIST, Level(4)),
            Measure::HipGirth => d("hip_girth", "Hip girth", Girth, "ISO 8559-1 hip girth", HIP, Surface),
            Measure::ThighGirth => d(
                "thigh_girth",
                "Thigh girth",
                Girth,
                "ISO 8559-1 thigh girth",
                &["Crotch", "Rt. Trochanterion"], Surface),
            Measure::UpperArmGirth => d(
                "upper_arm_girth",
                "Upper-arm girth",
                Girth,
                "ISO 8559-1 upper arm girth",
                &["Rt. Acromion", "Rt. Olecranon"], Level(2)),
            Measure::NeckGirth => d(
                "neck_girth",
                "Neck girth",
                Girth,
                "ISO 8559-1 neck girth",
                &["Cervicale", "Suprasternale", "Rt. Tragion", "Lt. Tragion"], Surface),
            Measure::NeckBaseGirth => d(
                "neck_base_girth",
                "Neck base girth",
                Girth,
                "ISO 8559-1 neck base girth",
                // Over both bony points (`neck_base.rs`): a level of two landmarks; the Tragions
                // only tilt the back's plane with the neck's axis.
                &["Cervicale", "Suprasternale", "Rt. Tragion", "Lt. Tragion"], Level(2)),
            Measure::HeadGirth => d(
                "head_girth",
                "Head girth",
                Girth,
                "ISO 8559-1 head girth; ISO 7250-1 head circumference",
                // Found on the surface from the Sellion down (`surface.rs`), but trusted as the
                // Sellion's level: on landmark-free fits the head's own surface misses the 2 mm
                // limit too often (docs/measurements.md, "Trust").
                &["Sellion", "Rt. Tragion", "Lt. Tragion"], Level(1)),
            Measure::ArmLength => d(
                "arm_length",
                "Arm length",
                Length,
                "ISO 8559-1 arm length",
                &["Rt. Acromion", "Rt. Radiale", "Rt. Radial Styloid"], Span),
            Measure::WaistToHipBack => d(
                "waist_to_hip_back",
                "Waist to hip (back)",
                Length,
                "ISO 8559-1 waist to hip length",
                &[
                    "Rt. 10th Rib",
                    "Lt. 10th Rib",
                    "Rt. Iliocristale",
                    "Lt. Iliocristale",
                    "Rt. Trochanterion",
                    "Lt. Trochanterion",
                    "Crotch",
                ], Level(4)),
            Measure::Volume => d("volume", "Body volume", Volume, "volume enclosed by the body surface (no ISO 7250-1 clause; for density and BMI-like indices)", &[], Surface),
            Measure::SurfaceArea => d("surface_area", "Surface area", Area, "area of the body surface (no ISO clause; what DuBois-type formulas estimate)", &[], Surface),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_round_trip() {
        for (i, m) in Measure::ALL.into_iter().enumerate() {
            assert_eq!(m.index(), i);
            assert_eq!(Measure::from_name(m.definition().name), Some(m));
        }
        assert_eq!(Measure::from_name("waist"), None);
    }
}
