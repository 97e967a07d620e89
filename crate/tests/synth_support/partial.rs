//! Partial landmark files of a synthetic subject, and the correspondence error of its fit by the
//! one subject path (`subject::fit_subject`): what `tests/subject_paths.rs` and the
//! `partial_files` example measure (issue 31: a partial file of correct landmarks is never worse
//! than none).

use bodyspace::landmarks::LandmarkSet;
use bodyspace::mesh::Mesh;
use bodyspace::subject::{
    fit_subject, GivenLandmarks, PriorEstimate, SubjectInput, SubjectOptions, SubjectReport,
};
use bodyspace::template::Template;
use nalgebra::Point3;

/// Ten landmarks a person would click first (the partial file of the tests and the benchmark):
/// head, neck, shoulders, wrists, knees, ankles.
pub const PARTIAL: [&str; 10] = [
    "Sellion",
    "Cervicale",
    "Rt. Acromion",
    "Lt. Acromion",
    "Rt. Radial Styloid",
    "Lt. Radial Styloid",
    "Rt. Femoral Lateral Epicn",
    "Lt. Femoral Lateral Epicn",
    "Rt. Lateral Malleolus",
    "Lt. Lateral Malleolus",
];

/// Partial files of 4–10 landmarks, each named: what a person might click or a file might hold.
pub const PARTIAL_FILES: [(&str, &[&str]); 6] = [
    (
        "head-shoulders-crotch",
        &["Sellion", "Rt. Acromion", "Lt. Acromion", "Crotch"],
    ),
    (
        "back-hips",
        &[
            "Sellion",
            "Cervicale",
            "Crotch",
            "Rt. Trochanterion",
            "Lt. Trochanterion",
        ],
    ),
    (
        "clicked-5",
        &[
            "Sellion",
            "Rt. Acromion",
            "Lt. Acromion",
            "Rt. Lateral Malleolus",
            "Lt. Lateral Malleolus",
        ],
    ),
    (
        "midline-pelvis-ankles",
        &[
            "Sellion",
            "Suprasternale",
            "Rt. ASIS",
            "Lt. ASIS",
            "Rt. Lateral Malleolus",
            "Lt. Lateral Malleolus",
        ],
    ),
    (
        "limbs",
        &[
            "Rt. Acromion",
            "Lt. Acromion",
            "Rt. Lateral Malleolus",
            "Lt. Lateral Malleolus",
            "Rt. Femoral Lateral Epicn",
            "Lt. Femoral Lateral Epicn",
            "Rt. Radial Styloid",
            "Lt. Radial Styloid",
        ],
    ),
    (
        "issue-10",
        &[
            "Sellion",
            "Suprasternale",
            "Rt. Acromion",
            "Lt. Acromion",
            "Rt. Dactylion",
            "Lt. Dactylion",
            "Rt. ASIS",
            "Lt. ASIS",
            "Rt. Lateral Malleolus",
            "Lt. Lateral Malleolus",
        ],
    ),
];

/// The landmarks of `set` named in `names`.
pub fn only(set: &LandmarkSet, names: &[&str]) -> LandmarkSet {
    LandmarkSet {
        landmarks: set
            .landmarks
            .iter()
            .filter(|l| names.contains(&l.name.as_str()))
            .cloned()
            .collect(),
        ..LandmarkSet::default()
    }
}

/// The mean correspondence error (mm) against `truth` (metres, template order) of the fit of
/// `scan` by `fit_subject` with `options`, the `given` landmarks as a file (none: `None`) and a
/// `prior` estimate, and the fit's report.
pub fn correspondence_mm(
    template: &Template,
    scan: &Mesh,
    truth: &[Point3<f64>],
    given: Option<LandmarkSet>,
    prior: Option<PriorEstimate>,
    options: &SubjectOptions,
) -> (f64, SubjectReport) {
    let input = SubjectInput {
        name: "partial".into(),
        scan: scan.clone(),
        units: None,
        given: given.map(|set| GivenLandmarks {
            set,
            units: None,
            file: "partial.csv".into(),
        }),
    };
    let mut fit = fit_subject(template, None, &input, prior, options, &mut ()).unwrap();
    fit.compare_with_truth(template, truth);
    let error = fit
        .report
        .alignment
        .correspondence
        .as_ref()
        .unwrap()
        .fitted
        .mean_mm;
    (error, fit.report)
}
