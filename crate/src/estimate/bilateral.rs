//! The body's two sides agree: a limb segment between two landmarks on one bone (the femur from
//! the Trochanterion to the lateral epicondyle, the tibia from there to the lateral malleolus,
//! …) is about as long on the left as on the right, whatever the pose — bending a knee or an
//! elbow turns the bones, it does not lengthen them. An estimate whose segments differ between
//! the sides by far more than people's do has misplaced a landmark along the limb: the surface
//! fit cannot see that (the template slid along a smooth leg still lies on the scan), so the
//! self-check asks this (`self_check.rs`). Its companion, a limb fitted much farther from the scan
//! on one side than on the other, is a property of any fit and lives with the fit's checks
//! (`align/uneven_fit.rs`).

use nalgebra::Point3;
use serde::{Deserialize, Serialize};

use crate::landmarks::caesar::CAESAR_LANDMARKS;

/// The segments compared, by the side-less names of their end landmarks: each is a length on one
/// bone (or the foot's), which a pose does not change.
pub const BILATERAL_SEGMENTS: [(&str, &str, &str); 7] = [
    ("thigh", "Trochanterion", "Femoral Lateral Epicn"),
    ("lower leg", "Femoral Lateral Epicn", "Lateral Malleolus"),
    (
        "lower leg (inner)",
        "Femoral Medial Epicn",
        "Medial Malleolus",
    ),
    ("upper arm", "Acromion", "Radiale"),
    ("forearm", "Radiale", "Radial Styloid"),
    ("forearm (ulna)", "Olecranon", "Ulnar Styloid"),
    ("foot", "Lateral Malleolus", "Metatarsal Phal. V"),
];

/// One segment whose two sides disagree: its lengths (mm) and the four landmarks that make them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Asymmetry {
    pub segment: String,
    pub left_mm: f64,
    pub right_mm: f64,
    pub landmarks: Vec<String>,
}

impl Asymmetry {
    /// The sentence a person reads.
    pub fn sentence(&self) -> String {
        let (longer, by) = if self.left_mm > self.right_mm {
            ("left", self.left_mm - self.right_mm)
        } else {
            ("right", self.right_mm - self.left_mm)
        };
        format!(
            "the {longer} {} is {by:.0} mm longer than the other ({:.0} against {:.0} mm, {}): \
             a landmark along it is probably misplaced",
            self.segment,
            self.left_mm.max(self.right_mm),
            self.left_mm.min(self.right_mm),
            self.landmarks.join(", ")
        )
    }
}

fn index(name: &str) -> Option<usize> {
    CAESAR_LANDMARKS.iter().position(|l| l.name == name)
}

/// The segments of [`BILATERAL_SEGMENTS`] whose left and right lengths differ by more than
/// `max_mm`, from `positions` (by CAESAR index, `None` where absent) in units that `to_mm` turns
/// into millimetres. A segment with an end absent on either side is not compared.
pub fn asymmetries(positions: &[Option<Point3<f64>>], to_mm: f64, max_mm: f64) -> Vec<Asymmetry> {
    let at = |name: &str| index(name).and_then(|k| positions.get(k).copied().flatten());
    BILATERAL_SEGMENTS
        .iter()
        .filter_map(|&(segment, a, b)| {
            let names = ["Lt.", "Rt."].map(|side| [format!("{side} {a}"), format!("{side} {b}")]);
            let length = |[a, b]: &[String; 2]| Some((at(a)? - at(b)?).norm() * to_mm);
            let (left, right) = (length(&names[0])?, length(&names[1])?);
            ((left - right).abs() > max_mm).then(|| Asymmetry {
                segment: segment.to_string(),
                left_mm: left,
                right_mm: right,
                landmarks: names.into_iter().flatten().collect(),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::landmarks::caesar::CAESAR_LANDMARK_COUNT;

    /// A body's landmarks mirrored across x = 0: every segment as long on both sides.
    fn symmetric() -> Vec<Option<Point3<f64>>> {
        let mut p = vec![None; CAESAR_LANDMARK_COUNT];
        for (k, l) in CAESAR_LANDMARKS.iter().enumerate() {
            let h = k as f64 * 0.02;
            p[k] = Some(match l.name.split_at(4) {
                ("Lt. ", _) => Point3::new(0.2 + 0.01 * h, h, 0.03 * h),
                ("Rt. ", _) => Point3::new(-0.2 - 0.01 * h, h, 0.03 * h),
                _ => Point3::new(0.0, h, 0.0),
            });
        }
        // The partners' heights differ in this table's order: put each right one at its left
        // one's mirror image.
        for (k, l) in CAESAR_LANDMARKS.iter().enumerate() {
            if let Some(rest) = l.name.strip_prefix("Rt. ") {
                let left = p[index(&format!("Lt. {rest}")).unwrap()].unwrap();
                p[k] = Some(Point3::new(-left.x, left.y, left.z));
            }
        }
        p
    }

    #[test]
    fn a_mirror_image_body_has_no_asymmetry_and_a_misplaced_knee_is_named() {
        let mut p = symmetric();
        assert!(asymmetries(&p, 1000.0, 1.0).is_empty());
        // The right knee 60 mm up the leg: the thigh shorter, the lower leg longer on the right.
        let knee = index("Rt. Femoral Lateral Epicn").unwrap();
        let moved = p[knee].unwrap();
        let up_the_leg = (p[index("Rt. Trochanterion").unwrap()].unwrap() - moved).normalize();
        p[knee] = Some(moved + up_the_leg * 0.06);
        let found = asymmetries(&p, 1000.0, 40.0);
        let names: Vec<&str> = found.iter().map(|a| a.segment.as_str()).collect();
        assert_eq!(names, ["thigh", "lower leg"], "{found:?}");
        let thigh = &found[0];
        assert!(
            (thigh.left_mm - thigh.right_mm - 60.0).abs() < 1e-6,
            "{thigh:?}"
        );
        assert!(thigh
            .landmarks
            .contains(&"Rt. Femoral Lateral Epicn".to_string()));
        let said = thigh.sentence();
        assert!(said.starts_with("the left thigh is 60 mm longer"), "{said}");
        // Below the limit nothing is said; an absent end leaves its segments out.
        assert!(asymmetries(&p, 1000.0, 61.0).is_empty());
        p[knee] = None;
        assert!(asymmetries(&p, 1000.0, 1.0).is_empty());
    }
}
