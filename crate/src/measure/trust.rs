//! Whether a fit's measurement can be trusted, from where its landmarks came: the one rule every
//! path uses (the subject report carries it, `subject/fit.rs`; docs/measurements.md, "Trust").
//!
//! A measurement is
//! * `placed` when every landmark that defines it ([`Anchoring`]) was given and kept (the
//!   suspicious check did not leave it out);
//! * `body_defined` when it is found on the surface and its landmarks only seed the search
//!   ([`Anchoring::Surface`]), so it does not inherit their error;
//! * `estimated` when a defining landmark was not placed — estimated, left out as suspicious, or
//!   absent from a nearly full file and so placed by the fit alone. Its expected error E comes from
//!   the typical errors eᵢ (mm) of those landmarks (`estimate/typical_error.csv`; a placed one
//!   counts 0):
//!   - a level of `n` landmarks ([`Anchoring::Level`]): E = ½·(Σ eᵢ)/n. One axis of an isotropic
//!     3-D error has a mean absolute value of half the error's mean length (for a Gaussian,
//!     σ·√(2/π) against 2σ·√(2/π)); the landmarks of a level are added, not root-sum-squared,
//!     because the estimate places them together (a segment at a time), so their errors move
//!     together. A girth at such a level is taken to move with it mm for mm.
//!   - a span ([`Anchoring::Span`]): E = √(Σ eᵢ²), the whole error of each end (the acromia's
//!     errors lie along the breadth).
//!
//!   It is doubtful when E exceeds the measurement's ISO 20685-1 limit (`tolerance.rs`), and the
//!   report says so in words.
//!
//! Checked against the truth on held-out subjects in docs/measurements.md.

use serde::Serialize;

use super::definitions::{Anchoring, Measure};

/// Where one landmark of a fit came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Origin {
    /// Given (in a file or placed by a person) and kept by the suspicious check.
    Placed,
    /// Estimated by the landmark estimate.
    Estimated,
    /// Given, but left out of the fit as suspicious: the fit placed it without it.
    LeftOut,
    /// Neither given nor estimated (a nearly full file without it): the fit placed it alone.
    Absent,
}

impl Origin {
    fn adjective(self) -> &'static str {
        match self {
            Origin::Placed => "placed",
            Origin::Estimated => "estimated",
            Origin::LeftOut => "left-out (suspicious)",
            Origin::Absent => "absent",
        }
    }
}

/// A measurement's trust.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Trust {
    Placed,
    BodyDefined,
    Estimated,
}

/// One defining landmark that was not placed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UnplacedLandmark {
    pub name: String,
    pub origin: Origin,
    /// The estimate's typical error of this landmark (mm).
    pub typical_error_mm: f64,
}

/// One measurement's verdict on a fit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeasurementTrust {
    /// The measurement's snake_case name ([`super::Definition::name`]).
    pub name: &'static str,
    pub trust: Trust,
    /// Its defining landmarks that were not placed (empty unless `estimated`).
    pub landmarks: Vec<UnplacedLandmark>,
    /// E (mm), for an `estimated` measurement.
    pub expected_error_mm: Option<f64>,
    /// ISO 20685-1's limit (mm); `None` for volume and area.
    pub limit_mm: Option<f64>,
    /// E above the limit.
    pub doubtful: bool,
    /// What a person reads, for an `estimated` measurement (empty otherwise).
    pub words: String,
}

/// The trust of `m` on a fit whose landmark `name` came from `origin(name)` = (where it came
/// from, its typical error in mm).
pub fn measurement_trust(m: Measure, origin: &dyn Fn(&str) -> (Origin, f64)) -> MeasurementTrust {
    let d = m.definition();
    let limit_mm = m.iso_class().map(|c| c.limit() * 1e3);
    let defining = match d.anchoring {
        Anchoring::Surface => 0,
        Anchoring::Level(n) => n.min(d.landmarks.len()),
        Anchoring::Span => d.landmarks.len(),
    };
    let landmarks: Vec<UnplacedLandmark> = d.landmarks[..defining]
        .iter()
        .map(|&name| (name, origin(name)))
        .filter(|(_, (o, _))| *o != Origin::Placed)
        .map(|(name, (origin, typical_error_mm))| UnplacedLandmark {
            name: name.to_string(),
            origin,
            typical_error_mm,
        })
        .collect();
    let trust = match (d.anchoring, landmarks.is_empty()) {
        (Anchoring::Surface, _) => Trust::BodyDefined,
        (_, true) => Trust::Placed,
        (_, false) => Trust::Estimated,
    };
    let expected_error_mm = (trust == Trust::Estimated).then(|| {
        let e = landmarks.iter().map(|l| l.typical_error_mm);
        match d.anchoring {
            Anchoring::Level(_) => 0.5 * e.sum::<f64>() / defining as f64,
            _ => e.map(|x| x * x).sum::<f64>().sqrt(),
        }
    });
    let doubtful = match (expected_error_mm, limit_mm) {
        (Some(e), Some(limit)) => e > limit,
        _ => false,
    };
    let words = expected_error_mm
        .map(|e| words(d.label, &landmarks, e, limit_mm, doubtful))
        .unwrap_or_default();
    MeasurementTrust {
        name: d.name,
        trust,
        landmarks,
        expected_error_mm,
        limit_mm,
        doubtful,
        words,
    }
}

/// Every measurement's trust, in [`Measure::ALL`] order.
pub fn measurements_trust(origin: &dyn Fn(&str) -> (Origin, f64)) -> Vec<MeasurementTrust> {
    Measure::ALL
        .into_iter()
        .map(|m| measurement_trust(m, origin))
        .collect()
}

/// "shoulder breadth (biacromial): from the estimated Rt. Acromion (typical error 24 mm) and Lt.
/// Acromion (24 mm), expected error ≈ 33 mm against ISO 20685-1's 4 mm — place these landmarks to
/// measure it".
fn words(
    label: &str,
    landmarks: &[UnplacedLandmark],
    expected: f64,
    limit: Option<f64>,
    doubtful: bool,
) -> String {
    let mut from = String::new();
    for (i, l) in landmarks.iter().enumerate() {
        let same_origin = i > 0 && landmarks[i - 1].origin == l.origin;
        from += match i {
            0 => "",
            _ if i + 1 == landmarks.len() => " and ",
            _ => ", ",
        };
        if !same_origin {
            from += &format!("the {} ", l.origin.adjective());
        }
        from += &l.name;
        from += &if i == 0 {
            format!(" (typical error {:.0} mm)", l.typical_error_mm)
        } else {
            format!(" ({:.0} mm)", l.typical_error_mm)
        };
    }
    let against = match limit {
        Some(limit) => format!(" against ISO 20685-1's {limit:.0} mm"),
        None => String::new(),
    };
    let advice = match (doubtful, landmarks.len()) {
        (false, _) => "",
        (true, 1) => " — place this landmark to measure it",
        (true, _) => " — place these landmarks to measure it",
    };
    format!(
        "{}: from {from}, expected error ≈ {expected:.0} mm{against}{advice}",
        label.to_lowercase()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(origin: Origin) -> impl Fn(&str) -> (Origin, f64) {
        move |name: &str| {
            let e = match name {
                "Rt. Acromion" | "Lt. Acromion" => 23.6,
                "Rt. Radial Styloid" => 2.6,
                _ => 10.0,
            };
            (origin, e)
        }
    }

    #[test]
    fn placed_landmarks_are_trusted_and_body_defined_ones_never_inherit() {
        for t in measurements_trust(&all(Origin::Placed)) {
            assert!(!t.doubtful, "{}", t.name);
            assert!(t.landmarks.is_empty() && t.words.is_empty());
            assert_eq!(t.expected_error_mm, None);
            let m = Measure::from_name(t.name).unwrap();
            let surface = m.definition().anchoring == Anchoring::Surface;
            let want = if surface {
                Trust::BodyDefined
            } else {
                Trust::Placed
            };
            assert_eq!(t.trust, want, "{}", t.name);
        }
        for m in [
            Measure::Stature,
            Measure::ChestGirth,
            Measure::HipGirth,
            Measure::NeckGirth,
        ] {
            let t = measurement_trust(m, &all(Origin::Estimated));
            assert_eq!(t.trust, Trust::BodyDefined, "{}", t.name);
            assert!(!t.doubtful);
        }
    }

    #[test]
    fn a_span_adds_its_ends_errors_in_quadrature_and_a_level_halves_their_mean() {
        let t = measurement_trust(Measure::ShoulderBreadth, &all(Origin::Estimated));
        assert_eq!(t.trust, Trust::Estimated);
        let e = t.expected_error_mm.unwrap();
        assert!((e - 23.6 * 2f64.sqrt()).abs() < 1e-9, "{e}");
        assert!(t.doubtful);
        assert_eq!(t.limit_mm, Some(4.0));
        assert_eq!(
            t.words,
            "shoulder breadth (biacromial): from the estimated Rt. Acromion (typical error 24 \
             mm) and Lt. Acromion (24 mm), expected error ≈ 33 mm against ISO 20685-1's 4 mm — \
             place these landmarks to measure it"
        );
        // Acromion height: the mean level of the two, ½·(23.6 + 23.6)/2.
        let t = measurement_trust(Measure::AcromionHeight, &all(Origin::Estimated));
        assert!((t.expected_error_mm.unwrap() - 11.8).abs() < 1e-9);
        // One of two placed: it counts 0 in the mean, the other stays.
        let one = |name: &str| match name {
            "Rt. Acromion" => (Origin::Placed, 23.6),
            _ => (Origin::LeftOut, 23.6),
        };
        let t = measurement_trust(Measure::AcromionHeight, &one);
        assert!((t.expected_error_mm.unwrap() - 5.9).abs() < 1e-9);
        assert_eq!(t.landmarks.len(), 1);
        assert!(t.words.contains("the left-out (suspicious) Lt. Acromion"));
        assert!(t.words.ends_with("place this landmark to measure it"));
    }

    #[test]
    fn only_the_defining_landmarks_count_and_a_small_error_is_not_doubtful() {
        // Thigh girth's level is the Crotch's; the Trochanterion only picks the loop.
        let crotch_placed = |name: &str| match name {
            "Crotch" => (Origin::Placed, 14.0),
            _ => (Origin::Estimated, 17.5),
        };
        let t = measurement_trust(Measure::ThighGirth, &crotch_placed);
        assert_eq!(t.trust, Trust::Placed);
        // Waist girth: four landmarks of 10 mm, E = 5 mm, within the 9 mm of a large girth.
        let t = measurement_trust(Measure::WaistGirth, &all(Origin::Absent));
        assert_eq!(t.trust, Trust::Estimated);
        assert!((t.expected_error_mm.unwrap() - 5.0).abs() < 1e-9);
        assert!(!t.doubtful);
        assert!(t
            .words
            .starts_with("waist girth: from the absent Rt. 10th Rib"));
        assert!(
            t.words.ends_with("against ISO 20685-1's 9 mm"),
            "{}",
            t.words
        );
        // Arm length: √(23.6² + 10² + 2.6²).
        let t = measurement_trust(Measure::ArmLength, &all(Origin::Estimated));
        let want = (23.6f64.powi(2) + 100.0 + 2.6f64.powi(2)).sqrt();
        assert!((t.expected_error_mm.unwrap() - want).abs() < 1e-9);
        assert!(t
            .words
            .contains(", Rt. Radiale (10 mm) and Rt. Radial Styloid (3 mm)"));
    }
}
