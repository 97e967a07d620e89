//! [`fit_subject`]: one subject from what was read to a checked fit — the landmark policy, the
//! scan's stray pieces taken off (`mesh/strays.rs`), its parts wound inwards turned to face out
//! (`mesh/winding.rs`), then the floor or turntable under the feet
//! (`floor.rs`), the RBF warp and fine alignment ([`align_scan`]), the quality check, the frame
//! and each measurement's trust from where its landmarks came (`measure/trust.rs`) — and its
//! report.

use std::borrow::Cow;

use nalgebra::Point3;

use super::error::SubjectError;
use super::floor::scan_without_floor;
use super::frame::ToTemplate;
use super::input::{read_subject, SubjectInput};
use super::options::SubjectOptions;
use super::policy::{subject_landmarks, PriorEstimate, SubjectLandmarks};
use super::report::SubjectReport;
use crate::align::{align_scan, assess, AlignInput, AlignObserver, Alignment};
use crate::estimate::typical_error::typical_error_mm;
use crate::estimate::{given_landmarks, Verdict};
use crate::landmarks::CAESAR_LANDMARKS;
use crate::measure::{
    measurements_support, measurements_trust, note_acromia_on_vertices, upright, BodyMeasurer,
    MeasureParams, MeasurementTrust, Origin, TrustParams,
};
use crate::mesh::strays::remove_strays;
use crate::mesh::units::Units;
use crate::mesh::winding::{face_out, WindingParams};
use crate::template::{Resolution, Template};

/// A fitted subject.
#[derive(Debug, Clone)]
pub struct SubjectFit {
    /// The alignment: positions in metres, the scan's frame, template order.
    pub alignment: Alignment,
    pub report: SubjectReport,
    /// Where each CAESAR landmark of the fit came from (CAESAR order), which the report's
    /// `measurement_trust` was judged from.
    pub landmark_origins: Vec<Origin>,
}

impl SubjectFit {
    /// The fit in the scan's frame and units (as a fit is written by default).
    pub fn positions_in_scan_units(&self) -> Vec<Point3<f64>> {
        let to_m = self.alignment.scale_to_metres;
        self.alignment.positions.iter().map(|p| p / to_m).collect()
    }

    /// Adds the correspondence error against `truth` (true template positions, at least the base
    /// vertices, metres, the scan's frame) to the report.
    pub fn compare_with_truth(&mut self, template: &Template, truth: &[Point3<f64>]) {
        self.alignment.compare_with_truth(template, truth);
        self.report.alignment.correspondence = self.alignment.report.correspondence.clone();
    }

    /// The fit in the template's frame: upright, y up, metres, facing +z.
    pub fn positions_in_template_frame(&self) -> Vec<Point3<f64>> {
        let frame = &self.report.to_template;
        let to_m = self.alignment.scale_to_metres;
        self.alignment
            .positions
            .iter()
            .map(|p| frame.to_template(&(p / to_m)))
            .collect()
    }
}

/// Fits `template` (at `fine`: coarse to fine, from `base_template` when the caller keeps one) to
/// the subject: its landmarks by the one policy (`policy.rs`; `prior`: an estimate already run on
/// this scan with these landmarks), then [`align_scan`], the quality check with the options'
/// thresholds (left-out landmarks raise `suspicious_landmarks`), the frame and each measurement's
/// trust ([`measurements_trust`] from `landmark_origins`). `observer` hears
/// the estimate and every iteration of the alignment; a `Break` cancels.
pub fn fit_subject(
    template: &Template,
    base_template: Option<&Template>,
    input: &SubjectInput,
    prior: Option<PriorEstimate>,
    options: &SubjectOptions,
    observer: &mut dyn AlignObserver,
) -> Result<SubjectFit, SubjectError> {
    let (units, units_detected) = input.scan_units();
    let landmarks = subject_landmarks(template, input, prior, options, observer)?;
    // Stray pieces floating off the body are not fitted (the estimate takes them off too).
    let (scan, strays) = match remove_strays(&input.scan, units.scale_to_metres(), &options.strays)
    {
        Some((kept, removal)) => (Cow::Owned(kept), Some(removal)),
        None => (Cow::Borrowed(&input.scan), None),
    };
    // A part wound inwards is turned to face out: its normals would rule out every match on it.
    let (scan, turned) = match face_out(&scan, &WindingParams::default()) {
        Some((out, turned)) => (Cow::Owned(out), Some(turned)),
        None => (scan, None),
    };
    // With up from the landmarks, the floor or turntable under the feet is not fitted either.
    let (scan, floor) = scan_without_floor(
        template,
        &scan,
        &landmarks.set,
        units.scale_to_metres(),
        &options.floor,
    );
    let align_input = AlignInput {
        template,
        base_template,
        scan: &scan,
        landmarks: &landmarks.set,
        units: Some(units),
    };
    let mut alignment = align_scan(&align_input, &options.params, observer).map_err(|source| {
        SubjectError::Align {
            scan: input.name.clone(),
            source,
        }
    })?;
    alignment.report.units_detected = units_detected;

    let owned_base;
    let base = match (base_template, template.resolution()) {
        (Some(base), _) => base,
        (None, Resolution::Base) => template,
        (None, _) => {
            owned_base = template.at_resolution(Resolution::Base);
            &owned_base
        }
    };
    let quality = alignment.report.fine.is_some().then(|| {
        let mut quality = assess(&alignment, base, &options.thresholds);
        quality.add_suspicious_landmarks(
            landmarks
                .report
                .left_out
                .iter()
                .map(|l| l.name.clone())
                .collect(),
        );
        if let Some(check) = &landmarks.report.estimate_check {
            if check.verdict != Verdict::Good {
                let mut words = vec![format!("the landmark estimate {}", check.verdict.name())];
                words.extend(check.reasons.iter().cloned());
                if !check.check_first.is_empty() {
                    words.push(format!("check first: {}", check.check_first.join(", ")));
                }
                quality.add_landmark_estimate(words);
            }
        }
        quality
    });
    let to_m = alignment.scale_to_metres;
    let in_scan_units: Vec<_> = alignment.positions.iter().map(|p| p / to_m).collect();
    let to_template = ToTemplate::of_fit(&in_scan_units, &base.mesh().positions, units);
    let origins = landmark_origins(input, &landmarks);
    let report = SubjectReport {
        measurement_trust: fit_measurements_trust(
            base,
            &alignment.positions,
            &alignment.per_vertex_distance,
            &origins,
            &TrustParams::default(),
        ),
        landmarks: landmarks.report,
        floor,
        strays,
        turned,
        quality,
        to_template,
        alignment: alignment.report.clone(),
    };
    Ok(SubjectFit {
        alignment,
        report,
        landmark_origins: origins,
    })
}

/// Each measurement's trust on a fit ([`measurements_trust`]): from where its landmarks came
/// (`origins`, CAESAR order), the fit's own error and, for a body-defined one, the fit's support
/// by the scan where it is taken ([`measurements_support`]); a doubtful one whose acromia stand
/// on the Acromion vertices says so ([`note_acromia_on_vertices`]). `positions`: the fit
/// (metres, any frame, at least the `base` template's `#Vb` vertices first); `distances`: each
/// fitted vertex's distance to the scan (metres, the same order; empty after the warp alone,
/// when support is not judged).
pub fn fit_measurements_trust(
    base: &Template,
    positions: &[Point3<f64>],
    distances: &[f64],
    origins: &[Origin],
    params: &TrustParams,
) -> Vec<MeasurementTrust> {
    let n = base.mesh().vertex_count();
    let measure = MeasureParams::default();
    let stood = (positions.len() >= n)
        .then(|| upright(&positions[..n], &base.mesh().positions))
        .flatten();
    let measurer = BodyMeasurer::of_template(base, measure).ok();
    let supports = match (&stood, &measurer) {
        (Some(stood), Some(measurer)) if distances.len() >= n => measurements_support(
            measurer,
            base.landmark_vertices(),
            stood,
            measure.up_axis,
            &distances[..n],
            &params.support,
        ),
        _ => vec![],
    };
    let mut trust = measurements_trust(
        &|name: &str| {
            let k = CAESAR_LANDMARKS.iter().position(|l| l.name == name);
            let typical = k.map_or(f64::NAN, typical_error_mm);
            let origin = k.and_then(|k| origins.get(k).copied());
            (origin.unwrap_or(Origin::Absent), typical)
        },
        supports,
        params,
    );
    if let (Some(stood), Some(measurer)) = (&stood, &measurer) {
        if let Ok(acromia) = measurer.acromia(stood) {
            for t in &mut trust {
                note_acromia_on_vertices(t, acromia.map(|a| a.on_surface));
            }
        }
    }
    trust
}

/// Where each CAESAR landmark of the fit came from (CAESAR order): given and kept by the check,
/// left out as suspicious, estimated (in the warp's set and not given), or absent.
fn landmark_origins(input: &SubjectInput, landmarks: &SubjectLandmarks) -> Vec<Origin> {
    let given = given_landmarks(&input.given_in_scan_units());
    let used = given_landmarks(&landmarks.set);
    let left_out = &landmarks.report.left_out;
    (0..CAESAR_LANDMARKS.len())
        .map(|k| {
            let name = CAESAR_LANDMARKS[k].name;
            if left_out.iter().any(|l| l.name == name) {
                Origin::LeftOut
            } else if given.iter().any(|(i, _)| *i == k) {
                Origin::Placed
            } else if used.iter().any(|(i, _)| *i == k) {
                Origin::Estimated
            } else {
                Origin::Absent
            }
        })
        .collect()
}

/// [`read_subject`] then [`fit_subject`]: the whole path from file bytes (`scan`: bytes and file
/// name; `landmarks`: the same for its landmark file, if any; `units` overrides the scan's
/// detected units).
pub fn fit_subject_files(
    template: &Template,
    base_template: Option<&Template>,
    scan: (&[u8], &str),
    landmarks: Option<(&[u8], &str)>,
    units: Option<Units>,
    options: &SubjectOptions,
    observer: &mut dyn AlignObserver,
) -> Result<SubjectFit, SubjectError> {
    let input = read_subject(scan, landmarks, units)?;
    fit_subject(template, base_template, &input, None, options, observer)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimate::SuspicionKind;
    use crate::landmarks::{Landmark, LandmarkSet};
    use crate::mesh::Mesh;
    use crate::subject::input::GivenLandmarks;
    use crate::subject::report::{LandmarkPolicyReport, LandmarkSource};

    fn set(names: &[&str]) -> LandmarkSet {
        LandmarkSet {
            landmarks: names
                .iter()
                .map(|n| Landmark {
                    name: n.to_string(),
                    position: Point3::origin(),
                })
                .collect(),
            ..LandmarkSet::default()
        }
    }

    #[test]
    fn each_landmark_is_placed_left_out_estimated_or_absent() {
        // Given: both Acromions and Sellion; Sellion left out as suspicious. The warp's set: the
        // Rt. Acromion kept and Cervicale estimated; the Lt. Acromion given and kept too.
        let input = SubjectInput {
            name: "s".into(),
            scan: Mesh::new(vec![Point3::origin()], vec![]),
            units: Some(Units::Metres),
            given: Some(GivenLandmarks {
                set: set(&["Rt. Acromion", "Lt. Acromion", "Sellion"]),
                units: None,
                file: "l.csv".into(),
            }),
        };
        let landmarks = SubjectLandmarks {
            set: set(&["Rt. Acromion", "Lt. Acromion", "Cervicale"]),
            report: LandmarkPolicyReport {
                source: LandmarkSource::FilledIn,
                file: "l.csv".into(),
                given: 3,
                left_out: vec![crate::estimate::SuspiciousLandmark {
                    name: "Sellion".into(),
                    distance_mm: 40.0,
                    kind: SuspicionKind::Far,
                    suggestion: String::new(),
                    expected: [0.0; 3],
                }],
                unjudged: vec![],
                estimated: 1,
                used: 3,
                estimate: None,
                estimate_check: None,
            },
        };
        let origin = landmark_origins(&input, &landmarks);
        let of = |name: &str| {
            origin[CAESAR_LANDMARKS
                .iter()
                .position(|l| l.name == name)
                .unwrap()]
        };
        assert_eq!(of("Rt. Acromion"), Origin::Placed);
        assert_eq!(of("Lt. Acromion"), Origin::Placed);
        assert_eq!(of("Sellion"), Origin::LeftOut);
        assert_eq!(of("Cervicale"), Origin::Estimated);
        assert_eq!(of("Crotch"), Origin::Absent);
    }
}
