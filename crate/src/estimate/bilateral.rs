//! The body's two sides agree: a limb segment between two landmarks on one bone (the femur from
//! the Trochanterion to the lateral epicondyle, the tibia from there to the lateral malleolus,
//! …) is about as long on the left as on the right, whatever the pose — bending a knee or an
//! elbow turns the bones, it does not lengthen them. An estimate whose segments differ between
//! the sides by far more than people's do has misplaced a landmark along the limb: the surface
//! fit cannot see that (the template slid along a smooth leg still lies on the scan), so the
//! self-check asks this (`self_check.rs`). Likewise a limb's part fits the scan about as closely
//! on one side as on the other: an arm laid against the torso and posed wrongly leaves the
//! template's arm far from its scan while the other arm and the rest fit, which the RMS over the
//! whole body hides ([`uneven_fits`]).

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

/// A limb's part whose fit lies much farther from the scan on one side than on the other.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct UnevenFit {
    /// The part without its side (`upper arm`, `lower leg`, …).
    pub part: String,
    pub left_rms_mm: f64,
    pub right_rms_mm: f64,
}

impl UnevenFit {
    /// The sentence a person reads.
    pub fn sentence(&self) -> String {
        let (worse, better, side) = if self.left_rms_mm > self.right_rms_mm {
            (self.left_rms_mm, self.right_rms_mm, "left")
        } else {
            (self.right_rms_mm, self.left_rms_mm, "right")
        };
        format!(
            "the {side} {} lies far from the scan (RMS {worse:.1} mm, the other side {better:.1} mm): \
             it was probably posed wrongly; place its landmarks by hand",
            self.part
        )
    }
}

/// The parts named `left X` and `right X` in `part_names` whose fits' RMS distance to the scan
/// (`distance`, metres, per template vertex, over the vertices of `part_of` that part with a
/// positive `weight`) is above `ratio` times the other side's and above it by more than `min_mm`.
pub fn uneven_fits(
    distance: &[f64],
    weight: &[f64],
    part_of: &[usize],
    part_names: &[&str],
    (ratio, min_mm): (f64, f64),
) -> Vec<UnevenFit> {
    let mut sum = vec![(0.0, 0usize); part_names.len()];
    for ((&d, &w), &p) in distance.iter().zip(weight).zip(part_of) {
        if w > 0.0 && d.is_finite() {
            sum[p].0 += d * d;
            sum[p].1 += 1;
        }
    }
    let rms_mm = |p: usize| (sum[p].1 > 0).then(|| (sum[p].0 / sum[p].1 as f64).sqrt() * 1000.0);
    part_names
        .iter()
        .enumerate()
        .filter_map(|(l, name)| {
            let part = name.strip_prefix("left ")?;
            let r = part_names
                .iter()
                .position(|n| *n == format!("right {part}"))?;
            let (left, right) = (rms_mm(l)?, rms_mm(r)?);
            let (worse, better) = (left.max(right), left.min(right));
            (worse > ratio * better && worse - better > min_mm).then(|| UnevenFit {
                part: part.to_string(),
                left_rms_mm: left,
                right_rms_mm: right,
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

    #[test]
    fn a_limb_fitted_far_from_its_scan_on_one_side_only_is_named() {
        let names = ["torso", "left arm", "right arm", "left leg", "right leg"];
        // Vertices: 2 per part; the right arm 30 mm from the scan, everything else 3 mm, the
        // torso's second vertex unweighted (its 1 m does not count).
        let part_of = [0, 0, 1, 1, 2, 2, 3, 3, 4, 4];
        let mut distance = [0.003; 10];
        distance[1] = 1.0;
        distance[4] = 0.03;
        distance[5] = 0.03;
        let mut weight = [1.0; 10];
        weight[1] = 0.0;
        let found = uneven_fits(&distance, &weight, &part_of, &names, (2.5, 5.0));
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].part, "arm");
        assert!((found[0].right_rms_mm - 30.0).abs() < 1e-9);
        assert!(found[0]
            .sentence()
            .starts_with("the right arm lies far from the scan (RMS 30.0 mm"));
        // Both sides alike (a feet-cut scan's lower legs), or a small difference: nothing.
        distance[2] = 0.03;
        distance[3] = 0.03;
        assert!(uneven_fits(&distance, &weight, &part_of, &names, (2.5, 5.0)).is_empty());
        assert!(uneven_fits(&distance, &weight, &part_of, &names, (2.5, 30.0)).is_empty());
    }
}
