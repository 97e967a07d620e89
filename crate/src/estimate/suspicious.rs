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

/// Flags the `given` landmarks (CAESAR index, position) lying farther than their threshold from
/// where they are expected: `expected[i]` (73, CAESAR order) is the expected position and the
/// threshold, both in the scan's units, or `None` where landmark `i` cannot be judged. `to_mm`
/// converts a scan length to millimetres: distances are reported in mm, a coordinate in the
/// scan's units with the digits that tell 0.1 mm apart ([`coordinate_text`]).
pub fn flag_suspicious(
    given: &[(usize, Point3<f64>)],
    expected: &[Option<(Point3<f64>, f64)>],
    to_mm: f64,
) -> Vec<SuspiciousLandmark> {
    let position_of = |index: usize| given.iter().find(|(i, _)| *i == index).map(|(_, p)| *p);
    let near = |p: &Point3<f64>, j: usize| expected[j].is_some_and(|(e, t)| (p - e).norm() <= t);
    let mut flagged = Vec::new();
    for &(index, p) in given {
        let Some((expected_here, threshold)) = expected[index] else {
            continue;
        };
        let error = p - expected_here;
        let distance = error.norm();
        if distance <= threshold || distance.is_nan() {
            continue;
        }
        let name = CAESAR_LANDMARKS[index].name;
        let (kind, suggestion) = if let Some(partner) = partner_of(index)
            .filter(|&j| near(&p, j) && position_of(j).is_some_and(|q| near(&q, index)))
        {
            let other = CAESAR_LANDMARKS[partner].name;
            (
                SuspicionKind::Swapped,
                format!("{name} and {other} look swapped: exchange their positions"),
            )
        } else if let Some(other) = (0..expected.len())
            .filter(|&j| j != index)
            .filter_map(|j| expected[j].map(|(e, _)| (j, (p - e).norm())))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .filter(|&(_, d)| d <= threshold / 2.0)
            .map(|(j, _)| j)
        {
            (
                SuspicionKind::OtherLandmark,
                format!(
                    "it lies where {} is expected: place {name} on its own body part",
                    CAESAR_LANDMARKS[other].name
                ),
            )
        } else if let Some(axis) = lone_axis(&error) {
            let (value, wanted) = coordinate_text(p[axis], expected_here[axis], to_mm);
            let apart = error[axis].abs() * to_mm;
            let axis = ['x', 'y', 'z'][axis];
            (
                SuspicionKind::Coordinate,
                format!(
                    "check the {axis} coordinate: it is {value}, the others suggest about {wanted} ({apart:.0} mm apart)"
                ),
            )
        } else {
            (
                SuspicionKind::Far,
                format!(
                    "{:.0} mm from where the other landmarks put it: re-place it or leave it out",
                    distance * to_mm
                ),
            )
        };
        flagged.push(SuspiciousLandmark {
            name: name.to_string(),
            distance_mm: distance * to_mm,
            kind,
            suggestion,
            expected: expected_here.into(),
        });
    }
    flagged
}

/// Two coordinates in the scan's units (`to_mm`: units → mm), named by their unit when it is
/// mm, cm or m, with the decimals that resolve 0.1 mm (mm: 1, cm: 2, m: 4) and more while the
/// two would print alike: "1234.5 mm", "1.2345 m".
pub fn coordinate_text(value: f64, wanted: f64, to_mm: f64) -> (String, String) {
    let unit = [(1.0, " mm"), (10.0, " cm"), (1000.0, " m")]
        .iter()
        .find(|(k, _)| (to_mm / k - 1.0).abs() < 1e-9)
        .map_or("", |(_, u)| u);
    let mut decimals = (to_mm / 0.1).log10().ceil().clamp(0.0, 12.0) as usize;
    loop {
        let (a, b) = (
            format!("{value:.decimals$}"),
            format!("{wanted:.decimals$}"),
        );
        if a != b || decimals >= 12 {
            return (format!("{a}{unit}"), format!("{b}{unit}"));
        }
        decimals += 1;
    }
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

/// The one axis that carries the error: the other two components together at most half of it.
fn lone_axis(error: &nalgebra::Vector3<f64>) -> Option<usize> {
    let k = error.iamax();
    let others = (0..3)
        .filter(|&j| j != k)
        .map(|j| error[j] * error[j])
        .sum::<f64>()
        .sqrt();
    (others <= error[k].abs() / 2.0).then_some(k)
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
        let expected: Vec<_> = pred.iter().map(|p| Some((*p, 60.0))).collect();
        let flags = flag_suspicious(&given, &expected, 1.0);
        let kinds: Vec<(&str, SuspicionKind)> =
            flags.iter().map(|f| (f.name.as_str(), f.kind)).collect();
        let told = [
            ("Rt. Acromion", SuspicionKind::Swapped),
            ("Lt. Acromion", SuspicionKind::Swapped),
            ("Sellion", SuspicionKind::Coordinate),
            ("Crotch", SuspicionKind::OtherLandmark),
        ];
        for flag in &told {
            assert!(kinds.contains(flag), "{flag:?} not in {kinds:?}");
        }
        assert_eq!(flags.len(), told.len(), "{kinds:?}");
        let sellion = flags.iter().find(|f| f.name == "Sellion").unwrap();
        assert!((sellion.distance_mm - 400.0).abs() < 1e-9);
        assert!(
            sellion.suggestion.contains("z coordinate"),
            "{}",
            sellion.suggestion
        );
    }

    #[test]
    fn a_coordinate_is_printed_in_the_scan_units_never_two_alike() {
        assert_eq!(
            coordinate_text(1234.52, 1204.0, 1.0),
            ("1234.5 mm".to_string(), "1204.0 mm".to_string())
        );
        assert_eq!(
            coordinate_text(-0.1234, -0.0931, 1000.0),
            ("-0.1234 m".to_string(), "-0.0931 m".to_string())
        );
        assert_eq!(
            coordinate_text(12.3, 15.3, 10.0),
            ("12.30 cm".to_string(), "15.30 cm".to_string())
        );
        // Closer than the scan's precision: more digits until they differ.
        let (a, b) = coordinate_text(1.000_01, 1.000_02, 1000.0);
        assert_ne!(a, b);
        assert_eq!((a.as_str(), b.as_str()), ("1.00001 m", "1.00002 m"));
    }
}
