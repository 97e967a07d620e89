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
//!   E is the mean absolute error to expect; the error of one body then exceeds the
//!   measurement's ISO 20685-1 limit L (`tolerance.rs`) with the chance
//!   P = erfc(L / (E·√π)) (a half-normal error of mean E has σ = E·√(π/2), and
//!   P(|x| > L) = erfc(L / (σ·√2))). The measurement is doubtful when P exceeds
//!   [`TrustParams::max_chance_over_limit`] (default 5 %, i.e. E > 0.41·L), and the report says
//!   so in words.
//!
//! Every measurement with a limit also carries **the fit's own error** E_f ([`super::fit_error`]):
//! what a fit's value typically differs from the body's even where its landmarks are right (the
//! alignment's error where the measurement is taken), measured against the truth on the tuning
//! subjects — for a placed or estimated measurement the figure of fits from placed landmarks, for
//! a body-defined one that of fits whose seeds were placed, or of landmark-free fits when one was
//! not (the larger of the two when it has no seed). The landmarks' error E_l (above; 0 when every
//! defining landmark was placed) and E_f are independent, so E = √(E_l² + E_f²), and P and the
//! verdict follow from E as above: a measurement the fit cannot take within the standard is
//! doubtful however its landmarks were placed, and the words say so.
//!
//! A body-defined measurement is also doubtful where the fit is not the scan's: when too much of
//! the fit where it is taken lies far from the scan ([`super::support`], [`TrustParams::support`]).
//!
//! Checked against the truth on held-out subjects in docs/measurements.md ("Trust"): E matches
//! the measured MAE, and P the share of bodies over the limit.

use serde::Serialize;

use super::definitions::{Anchoring, Measure};
use super::fit_error::FitErrors;
use super::support::{self, Support, SupportParams};
use super::tolerance::chance_over;

/// The rule's parameters, with their defaults.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TrustParams {
    /// A measurement from unplaced landmarks is doubtful when its chance of an error over ISO
    /// 20685-1's limit exceeds this; default 0.05 ("never silently wrong": a measurement is
    /// trusted only when it is nearly sure to be within the standard).
    pub max_chance_over_limit: f64,
    /// The fit's own error of each measurement, added to its landmarks'; default: the measured
    /// table ([`FitErrors::measured`]).
    pub fit_errors: FitErrors,
    /// When the fit carries a body-defined measurement ([`super::support`]).
    pub support: SupportParams,
}

impl Default for TrustParams {
    fn default() -> Self {
        Self {
            max_chance_over_limit: 0.05,
            fit_errors: FitErrors::measured(),
            support: SupportParams::default(),
        }
    }
}

/// Where one landmark of a fit came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
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
    /// E_f (mm), the fit's own error included in E; `None` for volume and area.
    pub fit_error_mm: Option<f64>,
    /// E (mm) = √(E_l² + E_f²), with E_l the unplaced landmarks' error; `None` when neither is
    /// known (volume, area).
    pub expected_error_mm: Option<f64>,
    /// ISO 20685-1's limit (mm); `None` for volume and area.
    pub limit_mm: Option<f64>,
    /// P, the chance that this body's error exceeds the limit, when E and the limit are known.
    pub chance_over_limit: Option<f64>,
    /// For a `body_defined` measurement with a limit, when the fit's distances to the scan were
    /// known: the fit's support where it is taken ([`super::support`]).
    pub support: Option<Support>,
    /// P above [`TrustParams::max_chance_over_limit`], or too little support.
    pub doubtful: bool,
    /// What a person reads, for an `estimated` or doubtful measurement (empty otherwise).
    pub words: String,
}

/// The trust of `m` on a fit whose landmark `name` came from `origin(name)` = (where it came
/// from, its typical error in mm) and whose support where `m` is taken is `support`.
pub fn measurement_trust(
    m: Measure,
    origin: &dyn Fn(&str) -> (Origin, f64),
    support: Option<Support>,
    params: &TrustParams,
) -> MeasurementTrust {
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
    let landmark_error_mm = (trust == Trust::Estimated).then(|| {
        let e = landmarks.iter().map(|l| l.typical_error_mm);
        match d.anchoring {
            Anchoring::Level(_) => 0.5 * e.sum::<f64>() / defining as f64,
            _ => e.map(|x| x * x).sum::<f64>().sqrt(),
        }
    });
    let fit_error_mm = limit_mm.and(params.fit_errors.of(m)).map(|f| match trust {
        Trust::BodyDefined if d.landmarks.is_empty() => f.placed_mm.max(f.estimated_mm),
        Trust::BodyDefined if d.landmarks.iter().all(|l| origin(l).0 == Origin::Placed) => {
            f.placed_mm
        }
        Trust::BodyDefined => f.estimated_mm,
        _ => f.placed_mm,
    });
    let expected_error_mm = match (landmark_error_mm, fit_error_mm) {
        (None, None) => None,
        (l, f) => Some(l.unwrap_or(0.0).hypot(f.unwrap_or(0.0))),
    };
    let chance = |e: f64| limit_mm.map(|limit| chance_over(limit, e));
    let chance_over_limit = expected_error_mm.and_then(chance);
    let over = |p: Option<f64>| p.is_some_and(|p| p > params.max_chance_over_limit);
    let support = support.filter(|_| trust == Trust::BodyDefined);
    let unsupported = support.as_ref().filter(|s| s.doubtful);
    let doubtful = over(chance_over_limit) || unsupported.is_some();
    let words = match (unsupported, expected_error_mm) {
        (Some(s), _) => support::words(m, s, &params.support),
        (None, Some(e)) if doubtful || trust == Trust::Estimated => words(
            d.label,
            &landmarks,
            fit_error_mm,
            e,
            limit_mm.zip(chance_over_limit),
            doubtful.then_some(over(fit_error_mm.and_then(chance))),
        ),
        _ => String::new(),
    };
    MeasurementTrust {
        name: d.name,
        trust,
        landmarks,
        fit_error_mm,
        expected_error_mm,
        limit_mm,
        chance_over_limit,
        support,
        doubtful,
        words,
    }
}

/// Every measurement's trust, in [`Measure::ALL`] order; `supports`: each one's support in that
/// order (empty when the fit's distances to the scan are not known).
pub fn measurements_trust(
    origin: &dyn Fn(&str) -> (Origin, f64),
    supports: Vec<Option<Support>>,
    params: &TrustParams,
) -> Vec<MeasurementTrust> {
    let mut supports = supports.into_iter();
    Measure::ALL
        .into_iter()
        .map(|m| measurement_trust(m, origin, supports.next().flatten(), params))
        .collect()
}

/// "shoulder breadth (biacromial): from the estimated Rt. Acromion (typical error 17 mm) and Lt.
/// Acromion (18 mm) and the fit's own error (3 mm), expected error ≈ 24 mm against ISO 20685-1's
/// 4 mm (over it on 89 % of bodies) — place these landmarks to measure it", or, with no unplaced
/// landmark, "neck girth: the fit's own error ≈ 3 mm against …"; `fit`: E_f; `limit`: the limit
/// (mm) and P; `doubtful`: `Some(whether the fit's own error alone is over the rule)` when the
/// measurement is doubtful, which picks the advice.
fn words(
    label: &str,
    landmarks: &[UnplacedLandmark],
    fit: Option<f64>,
    expected: f64,
    limit: Option<(f64, f64)>,
    doubtful: Option<bool>,
) -> String {
    let mut from = String::new();
    for (i, l) in landmarks.iter().enumerate() {
        let same_origin = i > 0 && landmarks[i - 1].origin == l.origin;
        from += match i {
            0 => "",
            _ if i + 1 == landmarks.len() && fit.is_none() => " and ",
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
        Some((limit, p)) => format!(
            " against ISO 20685-1's {limit:.0} mm (over it on {:.0} % of bodies)",
            100.0 * p
        ),
        None => String::new(),
    };
    let advice = match (doubtful, landmarks.len()) {
        (None, _) => "",
        (Some(true), _) | (Some(false), 0) => " — measure it by hand where it matters",
        (Some(false), 1) => " — place this landmark to measure it",
        (Some(false), _) => " — place these landmarks to measure it",
    };
    let label = label.to_lowercase();
    match (landmarks.is_empty(), fit) {
        (true, _) => {
            format!("{label}: the fit's own typical error here ≈ {expected:.1} mm{against}{advice}")
        }
        (false, Some(f)) => format!(
            "{label}: from {from} and the fit's own error ({f:.1} mm), expected error ≈ \
             {expected:.0} mm{against}{advice}"
        ),
        (false, None) => {
            format!("{label}: from {from}, expected error ≈ {expected:.0} mm{against}{advice}")
        }
    }
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

    /// The rule of the landmarks alone: the defaults without the fit's own error.
    fn landmarks_only() -> TrustParams {
        TrustParams {
            fit_errors: FitErrors::none(),
            ..TrustParams::default()
        }
    }

    /// The trust of `m` by its landmarks alone, no support known.
    fn trust_of(m: Measure, origin: &dyn Fn(&str) -> (Origin, f64)) -> MeasurementTrust {
        measurement_trust(m, origin, None, &landmarks_only())
    }

    #[test]
    fn placed_landmarks_are_trusted_and_body_defined_ones_never_inherit() {
        for t in measurements_trust(&all(Origin::Placed), vec![], &landmarks_only()) {
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
            let t = trust_of(m, &all(Origin::Estimated));
            assert_eq!(t.trust, Trust::BodyDefined, "{}", t.name);
            assert!(!t.doubtful);
        }
    }

    #[test]
    fn a_body_defined_measurement_is_doubtful_where_the_scan_is_not_under_the_fit() {
        let params = landmarks_only();
        let (near, far) = ([0.001; 4], [0.001, 0.012, 0.012, 0.012]);
        let s = |d: &[f64]| {
            Some(support::support(
                support::At::Place,
                &[0, 1, 2, 3],
                d,
                &params.support,
            ))
        };
        let t = measurement_trust(Measure::HipGirth, &all(Origin::Placed), s(&far), &params);
        assert_eq!(t.trust, Trust::BodyDefined);
        assert!(t.doubtful);
        assert_eq!(t.support.as_ref().unwrap().unsupported, 3);
        assert!(
            t.words.starts_with(
                "hip girth: the scan has no surface within 5 mm of 75 % of the fit where its \
                 tape runs (up to 12 mm away): the fit there is the template's"
            ),
            "{}",
            t.words
        );
        let t = measurement_trust(Measure::HipGirth, &all(Origin::Placed), s(&near), &params);
        assert!(!t.doubtful && t.words.is_empty() && t.support.is_some());
        // A landmark-defined measurement is judged by its landmarks alone.
        let t = measurement_trust(Measure::WaistGirth, &all(Origin::Placed), s(&far), &params);
        assert!(!t.doubtful && t.support.is_none());
    }

    #[test]
    fn a_span_adds_its_ends_errors_in_quadrature_and_a_level_halves_their_mean() {
        let t = trust_of(Measure::ShoulderBreadth, &all(Origin::Estimated));
        assert_eq!(t.trust, Trust::Estimated);
        let e = t.expected_error_mm.unwrap();
        assert!((e - 23.6 * 2f64.sqrt()).abs() < 1e-9, "{e}");
        assert!(t.doubtful);
        assert_eq!(t.limit_mm, Some(4.0));
        assert_eq!(
            t.words,
            "shoulder breadth (biacromial): from the estimated Rt. Acromion (typical error 24 \
             mm) and Lt. Acromion (24 mm), expected error ≈ 33 mm against ISO 20685-1's 4 mm \
             (over it on 92 % of bodies) — place these landmarks to measure it"
        );
        // Acromion height: the mean level of the two, ½·(23.6 + 23.6)/2.
        let t = trust_of(Measure::AcromionHeight, &all(Origin::Estimated));
        assert!((t.expected_error_mm.unwrap() - 11.8).abs() < 1e-9);
        // One of two placed: it counts 0 in the mean, the other stays.
        let one = |name: &str| match name {
            "Rt. Acromion" => (Origin::Placed, 23.6),
            _ => (Origin::LeftOut, 23.6),
        };
        let t = trust_of(Measure::AcromionHeight, &one);
        assert!((t.expected_error_mm.unwrap() - 5.9).abs() < 1e-9);
        assert_eq!(t.landmarks.len(), 1);
        assert!(t.words.contains("the left-out (suspicious) Lt. Acromion"));
        assert!(t.words.ends_with("place this landmark to measure it"));
    }

    #[test]
    fn only_the_defining_landmarks_count_and_the_chance_decides() {
        // Head girth's level is Sellion's; the Tragions only pick the loop.
        let sellion_placed = |name: &str| match name {
            "Sellion" => (Origin::Placed, 13.5),
            _ => (Origin::Estimated, 17.5),
        };
        let t = trust_of(Measure::HeadGirth, &sellion_placed);
        assert_eq!(t.trust, Trust::Placed);
        // Thigh girth is found at the crotch on the surface, whatever its landmarks.
        let t = trust_of(Measure::ThighGirth, &all(Origin::Estimated));
        assert_eq!(t.trust, Trust::BodyDefined);
        // Waist girth: four landmarks of 10 mm, E = 5 mm against the 9 mm of a large girth:
        // P = erfc(9 / (5·√π)) = erfc(1.0155) = 0.1509, doubtful at the default 5 %, not at 20 %.
        let waist = |params: TrustParams| {
            measurement_trust(Measure::WaistGirth, &all(Origin::Absent), None, &params)
        };
        let t = waist(landmarks_only());
        assert_eq!(t.trust, Trust::Estimated);
        assert!((t.expected_error_mm.unwrap() - 5.0).abs() < 1e-9);
        assert!((t.chance_over_limit.unwrap() - 0.1509).abs() < 1e-4);
        assert!(t.doubtful);
        assert!(t
            .words
            .starts_with("waist girth: from the absent Rt. 10th Rib"));
        let t = waist(TrustParams {
            max_chance_over_limit: 0.2,
            ..landmarks_only()
        });
        assert!(!t.doubtful);
        assert!(
            t.words
                .ends_with("against ISO 20685-1's 9 mm (over it on 15 % of bodies)"),
            "{}",
            t.words
        );
        // Arm length: √(23.6² + 10² + 2.6²).
        let t = trust_of(Measure::ArmLength, &all(Origin::Estimated));
        let want = (23.6f64.powi(2) + 100.0 + 2.6f64.powi(2)).sqrt();
        assert!((t.expected_error_mm.unwrap() - want).abs() < 1e-9);
        assert!(t
            .words
            .contains(", Rt. Radiale (10 mm) and Rt. Radial Styloid (3 mm)"));
    }

    #[test]
    fn the_fits_own_error_adds_to_the_landmarks_and_can_make_a_placed_measurement_doubtful() {
        let mut table = FitErrors::none();
        let own = |placed_mm, estimated_mm| {
            Some(crate::measure::FitError {
                placed_mm,
                estimated_mm,
            })
        };
        table.0[Measure::ShoulderBreadth.index()] = own(3.0, 5.0);
        table.0[Measure::NeckGirth.index()] = own(1.0, 3.0);
        table.0[Measure::Stature.index()] = own(0.5, 1.2);
        let params = TrustParams {
            fit_errors: table,
            ..TrustParams::default()
        };
        let trust = |m, origin: Origin| measurement_trust(m, &all(origin), None, &params);

        // Placed: E = E_f = 3 mm against 4 mm, P = erfc(4 / (3·√π)) = erfc(0.7523) = 0.2873.
        let t = trust(Measure::ShoulderBreadth, Origin::Placed);
        assert_eq!(t.trust, Trust::Placed);
        assert_eq!(
            (t.fit_error_mm, t.expected_error_mm),
            (Some(3.0), Some(3.0))
        );
        assert!((t.chance_over_limit.unwrap() - 0.2873).abs() < 1e-4);
        assert!(t.doubtful);
        assert_eq!(
            t.words,
            "shoulder breadth (biacromial): the fit's own typical error here ≈ 3.0 mm against ISO \
             20685-1's 4 mm (over it on 29 % of bodies) — measure it by hand where it matters"
        );
        // Estimated: the landmarks' √2·23.6 and the fit's own 3 mm in quadrature; placing the
        // landmarks would not make it trusted, so the advice is the hand.
        let t = trust(Measure::ShoulderBreadth, Origin::Estimated);
        let want = (2.0 * 23.6f64.powi(2) + 9.0).sqrt();
        assert!((t.expected_error_mm.unwrap() - want).abs() < 1e-9);
        assert!(t.words.contains(
            "Rt. Acromion (typical error 24 mm), Lt. Acromion (24 mm) and the fit's own error \
             (3.0 mm), expected error ≈ 34 mm"
        ));
        assert!(
            t.words.ends_with("measure it by hand where it matters"),
            "{}",
            t.words
        );

        // Body-defined: the column follows its seeds; 1 mm placed is trusted, silently.
        let t = trust(Measure::NeckGirth, Origin::Placed);
        assert_eq!(t.trust, Trust::BodyDefined);
        assert_eq!(t.fit_error_mm, Some(1.0));
        assert!(!t.doubtful && t.words.is_empty());
        let t = trust(Measure::NeckGirth, Origin::Estimated);
        assert_eq!(t.fit_error_mm, Some(3.0));
        assert!(t.doubtful);
        assert!(t
            .words
            .starts_with("neck girth: the fit's own typical error here ≈ 3.0 mm"));
        // No seed: the larger column.
        assert_eq!(
            trust(Measure::Stature, Origin::Placed).fit_error_mm,
            Some(1.2)
        );
        // No limit, no error: volume is never judged.
        let t = trust(Measure::Volume, Origin::Estimated);
        assert_eq!((t.expected_error_mm, t.doubtful), (None, false));

        // A measurement whose own error is small keeps the landmarks' advice.
        let t = trust(Measure::UpperArmGirth, Origin::Estimated);
        assert_eq!(t.fit_error_mm, None);
        assert!(
            t.words.ends_with("place these landmarks to measure it"),
            "{}",
            t.words
        );
    }
}
