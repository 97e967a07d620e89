//! Suspicious landmarks: a given landmark far from where the fit of the scan without it predicts
//! it — a swapped Lt./Rt. pair, a typo in one coordinate, a landmark on the wrong body part — is
//! listed with its distance and a suggestion, so a person can fix it and the warp can run
//! without it.
//!
//! The prediction (`expected.rs`) is the similarity fit of the other given landmarks of the same
//! rigid part when there are enough, else the segment-wise fit of the scan (which uses no given
//! landmark): after one similarity fit of the whole body the wrists of an arms-down scan are
//! 30 cm from the template's, so a landmark is judged per part, or against a fit that has
//! already taken the pose.

use nalgebra::Point3;
use serde::Serialize;

use crate::landmarks::CAESAR_LANDMARKS;

/// Why a landmark looks wrong.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SuspicionKind {
    /// It sits where its Lt./Rt. partner is expected, and the partner where it is expected.
    Swapped,
    /// One coordinate alone is off (a typo).
    Coordinate,
    /// It sits where another landmark is expected.
    OtherLandmark,
    /// Far from where it is expected, for no reason found.
    Far,
}

/// One flagged landmark.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SuspiciousLandmark {
    pub name: String,
    /// Distance from the given position to the predicted one (mm).
    pub distance_mm: f64,
    pub kind: SuspicionKind,
    /// What a person could do, in words.
    pub suggestion: String,
    /// The predicted position (the scan's frame and units).
    pub expected: [f64; 3],
}

/// Flags the `given` landmarks (CAESAR index, position) lying farther than `thresholds[i]` from
/// `predicted[i]` (both 73, CAESAR order). Positions and thresholds are in the scan's units;
/// `to_mm` converts a scan length to millimetres for the report.
pub fn flag_suspicious(
    given: &[(usize, Point3<f64>)],
    predicted: &[Point3<f64>],
    thresholds: &[f64],
    to_mm: f64,
) -> Vec<SuspiciousLandmark> {
    let position_of = |index: usize| given.iter().find(|(i, _)| *i == index).map(|(_, p)| *p);
    let mut flagged = Vec::new();
    for &(index, p) in given {
        let expected = predicted[index];
        let threshold = thresholds[index];
        let error = p - expected;
        let distance = error.norm();
        if distance <= threshold || distance.is_nan() {
            continue;
        }
        let name = CAESAR_LANDMARKS[index].name;
        let (kind, suggestion) = if let Some(partner) = partner_of(index).filter(|&j| {
            position_of(j).is_some_and(|q| {
                (p - predicted[j]).norm() <= thresholds[j] && (q - expected).norm() <= threshold
            })
        }) {
            let other = CAESAR_LANDMARKS[partner].name;
            (
                SuspicionKind::Swapped,
                format!("{name} and {other} look swapped: exchange their positions"),
            )
        } else if let Some(axis) = lone_axis(&error, threshold) {
            let value = [p.x, p.y, p.z][axis];
            let wanted = [expected.x, expected.y, expected.z][axis];
            let axis = ['x', 'y', 'z'][axis];
            (
                SuspicionKind::Coordinate,
                format!("check the {axis} coordinate: it is {value:.1}, the others suggest about {wanted:.1}"),
            )
        } else if let Some(other) = (0..predicted.len())
            .filter(|&j| j != index)
            .min_by(|&a, &b| {
                (p - predicted[a])
                    .norm()
                    .total_cmp(&(p - predicted[b]).norm())
            })
            .filter(|&j| (p - predicted[j]).norm() <= threshold / 2.0)
        {
            (
                SuspicionKind::OtherLandmark,
                format!(
                    "it lies where {} is expected: place {name} on its own body part",
                    CAESAR_LANDMARKS[other].name
                ),
            )
        } else {
            (
                SuspicionKind::Far,
                format!(
                    "{:.0} mm from where the scan puts it: re-place it or leave it out",
                    distance * to_mm
                ),
            )
        };
        flagged.push(SuspiciousLandmark {
            name: name.to_string(),
            distance_mm: distance * to_mm,
            kind,
            suggestion,
            expected: expected.into(),
        });
    }
    flagged
}

/// The CAESAR index of the other side's landmark (`Lt. X` ↔ `Rt. X`).
pub fn partner_of(index: usize) -> Option<usize> {
    let name = CAESAR_LANDMARKS[index].name;
    let other = if let Some(rest) = name.strip_prefix("Lt. ") {
        format!("Rt. {rest}")
    } else if let Some(rest) = name.strip_prefix("Rt. ") {
        format!("Lt. {rest}")
    } else {
        return None;
    };
    CAESAR_LANDMARKS.iter().position(|l| l.name == other)
}

/// The one axis that carries the error when the other two are within `threshold / 2`.
fn lone_axis(error: &nalgebra::Vector3<f64>, threshold: f64) -> Option<usize> {
    let k = error.iamax();
    let others = (0..3)
        .filter(|&j| j != k)
        .all(|j| error[j].abs() <= threshold / 2.0);
    others.then_some(k)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn predicted() -> Vec<Point3<f64>> {
        (0..73)
            .map(|i| Point3::new((i % 8) as f64 * 100.0, (i / 8) as f64 * 200.0, 0.0))
            .collect()
    }

    fn index(name: &str) -> usize {
        CAESAR_LANDMARKS
            .iter()
            .position(|l| l.name == name)
            .unwrap()
    }

    #[test]
    fn partners() {
        assert_eq!(
            partner_of(index("Rt. Acromion")),
            Some(index("Lt. Acromion"))
        );
        assert_eq!(
            partner_of(index("Lt. Digit II")),
            Some(index("Rt. Digit II"))
        );
        assert_eq!(partner_of(index("Sellion")), None);
    }

    #[test]
    fn swapped_pair_typo_and_wrong_part_are_told_apart() {
        let pred = predicted();
        let (rt, lt) = (index("Rt. Acromion"), index("Lt. Acromion"));
        let mut given: Vec<(usize, Point3<f64>)> = (0..73).map(|i| (i, pred[i])).collect();
        given[rt].1 = pred[lt];
        given[lt].1 = pred[rt];
        let sellion = index("Sellion");
        given[sellion].1.z += 400.0;
        let crotch = index("Crotch");
        given[crotch].1 = pred[index("Suprasternale")] + nalgebra::Vector3::new(5.0, 5.0, 5.0);
        let near = index("Rt. Gonion");
        given[near].1.x += 20.0;
        let flags = flag_suspicious(&given, &pred, &[60.0; 73], 1.0);
        let kinds: Vec<(&str, SuspicionKind)> =
            flags.iter().map(|f| (f.name.as_str(), f.kind)).collect();
        assert!(
            kinds.contains(&("Rt. Acromion", SuspicionKind::Swapped)),
            "{kinds:?}"
        );
        assert!(
            kinds.contains(&("Lt. Acromion", SuspicionKind::Swapped)),
            "{kinds:?}"
        );
        assert!(
            kinds.contains(&("Sellion", SuspicionKind::Coordinate)),
            "{kinds:?}"
        );
        assert!(
            kinds.contains(&("Crotch", SuspicionKind::OtherLandmark)),
            "{kinds:?}"
        );
        assert_eq!(flags.len(), 4, "{kinds:?}");
        let sellion = flags.iter().find(|f| f.name == "Sellion").unwrap();
        assert!((sellion.distance_mm - 400.0).abs() < 1e-9);
        assert!(
            sellion.suggestion.contains("z coordinate"),
            "{}",
            sellion.suggestion
        );
    }
}
