//! End to end on the `held-out` population (never tuned on): subjects fitted at `base` with the
//! defaults from their true landmarks (`align_scan`), measured like their truth by the same code
//! (both moved rigidly onto the template first), held to the tolerances the measurement
//! benchmark supports (docs/measurements.md, "Accuracy against ISO 20685-1": 8 subjects of seed
//! 6161; these are three others, of seed 4343). Every judged measurement of every subject within
//! BOUND of its truth; the measurements the benchmark found within ISO 20685-1 with a mean
//! difference over these subjects inside the standard's limit. Native only: it reads the
//! MakeHuman data from node_modules.
#![cfg(not(target_arch = "wasm32"))]

mod synth_support;

use bodyspace::align::QualityFlag;
use bodyspace::measure::{upright, BodyMeasurer, Measure, MeasureParams, Trust};
use bodyspace::subject::{fit_subject, SubjectInput, SubjectOptions};
use bodyspace::synth::*;
use nalgebra::Point3;
use synth_support::{base_template_and_data, fitted_and_true_measurements, subject_in_metres};

/// Largest difference of one subject's measurement from its truth: 4 × the ISO 20685-1 limit
/// (16 mm for heights, breadths and small girths, 20 mm segment lengths, 36 mm large girths,
/// 8 mm head girth; the largest here, the landmark-defined upper-arm girth of a raised arm,
/// −14.9 mm).
const BOUND: f64 = 4.0;

/// The measurements within ISO 20685-1 on the benchmark's fits from the true landmarks, whose
/// mean difference over these subjects must be inside the limit. Crotch height is not among
/// them: the fit's crotch, where the scanner sees nothing, is shallower than the truth's (+2.8 mm
/// on the benchmark).
const WITHIN: [Measure; 11] = [
    Measure::Stature,
    Measure::CervicaleHeight,
    Measure::AcromionHeight,
    Measure::KneeHeight,
    Measure::BustGirth,
    Measure::UnderbustGirth,
    Measure::WaistGirth,
    Measure::ThighGirth,
    Measure::NeckGirth,
    Measure::ArmLength,
    Measure::WaistToHipBack,
];

#[test]
fn held_out_fits_measure_like_their_truth() {
    let (template, data) = base_template_and_data();
    let measurer = BodyMeasurer::of_template(&template, MeasureParams::default()).unwrap();
    let mut differences = vec![Vec::new(); Measure::ALL.len()];
    let mut failures = Vec::new();
    for index in SUBJECTS {
        let id = held_out(index);
        let (got, want) =
            fitted_and_true_measurements(&data, &template, &measurer, id, &id.profile.scanner());
        for m in Measure::ALL {
            let Some(class) = m.iso_class() else {
                continue;
            };
            let name = m.definition().name;
            let (Some(g), Some(w)) = (got.get(m), want.get(m)) else {
                failures.push(format!("subject {index}: {name} not taken"));
                continue;
            };
            let d = g - w;
            eprintln!("subject {index} {name:<18} {:+.1} mm", d * 1e3);
            differences[m.index()].push(d);
            if d.abs() > BOUND * class.limit() {
                failures.push(format!(
                    "subject {index}: {name} {:+.1} mm (bound {:.1} mm)",
                    d * 1e3,
                    BOUND * class.limit() * 1e3
                ));
            }
        }
    }
    means_within(&WITHIN, &differences, &mut failures);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The body-defined measurements whose mean difference over these subjects, fitted without
/// landmarks, must be inside ISO 20685-1's limit: within it on the benchmark's landmark-free fits
/// of seeds 6161 and 9595 (the bust girth at its points: 6161 and 3535; docs/measurements.md).
const WITHIN_LANDMARK_FREE: [Measure; 4] = [
    Measure::ChestGirth,
    Measure::BustGirth,
    Measure::HipGirth,
    Measure::ThighGirth,
];

/// The same subjects fitted without landmarks by the one path (`fit_subject`, the landmarks
/// estimated): every body-defined measurement within BOUND of its truth and those the benchmark
/// found within ISO 20685-1 with a mean difference inside the limit; and never silently wrong —
/// every measurement defined by the estimated landmarks that is off by more than its limit is
/// called doubtful in the subject report, with words.
#[test]
fn landmark_free_fits_measure_the_body_defined_ones_and_doubt_the_others() {
    let (template, data) = base_template_and_data();
    let measurer = BodyMeasurer::of_template(&template, MeasureParams::default()).unwrap();
    let reference = &template.mesh().positions;
    let mut differences = vec![Vec::new(); Measure::ALL.len()];
    let mut failures = Vec::new();
    for index in SUBJECTS {
        let id = held_out(index);
        let (scan, _, truth) = subject_in_metres(&data, &template, id, &id.profile.scanner());
        let input = SubjectInput {
            name: format!("subject {index}"),
            scan,
            units: Some(bodyspace::mesh::units::Units::Metres),
            given: None,
        };
        let fit = fit_subject(
            &template,
            None,
            &input,
            None,
            &SubjectOptions::default(),
            &mut (),
        )
        .unwrap();
        // The fit is good or says where it is not: subject 2's arms hang 8° from the body, and
        // its estimated elbows lie 4 cm too high on both arms since the head is held by its nose
        // tip (2026-12-03; before, only the left, and the estimate doubted itself for the upper
        // arms' lengths). Its right forearm is then left off the scan, which the fit's own check
        // flags (`uncovered_scan`). No other flag is raised.
        let quality = fit.report.quality.as_ref().unwrap();
        let expected = [QualityFlag::LandmarkEstimate, QualityFlag::UncoveredScan];
        assert!(
            quality.flags.iter().all(|f| expected.contains(f)),
            "subject {index} flagged: {quality:?}"
        );
        let measure = |body: &[Point3<f64>]| {
            measurer
                .measure(&upright(body, reference).unwrap())
                .unwrap()
        };
        let (got, want) = (measure(&fit.alignment.positions), measure(&truth));
        for (m, trust) in Measure::ALL.into_iter().zip(&fit.report.measurement_trust) {
            let Some(class) = m.iso_class() else {
                continue;
            };
            let name = m.definition().name;
            assert_eq!(trust.name, name);
            let (Some(g), Some(w)) = (got.get(m), want.get(m)) else {
                // Not taken on the fit (the neck base's plane, through an estimated Cervicale a
                // few centimetres low, running into the shoulders): not silently wrong when the
                // report already doubts it.
                if want.get(m).is_none() || trust.trust != Trust::Estimated || !trust.doubtful {
                    failures.push(format!("subject {index}: {name} not taken, {trust:?}"));
                }
                continue;
            };
            let d = g - w;
            eprintln!(
                "subject {index} {name:<18} {:+.1} mm {:?}",
                d * 1e3,
                trust.trust
            );
            differences[m.index()].push(d);
            match trust.trust {
                Trust::BodyDefined if d.abs() > BOUND * class.limit() => failures.push(format!(
                    "subject {index}: {name} {:+.1} mm (bound {:.1} mm)",
                    d * 1e3,
                    BOUND * class.limit() * 1e3
                )),
                Trust::Estimated if d.abs() > class.limit() && !trust.doubtful => {
                    failures.push(format!(
                        "subject {index}: {name} {:+.1} mm, over ISO 20685-1's {:.0} mm, trusted",
                        d * 1e3,
                        class.limit() * 1e3
                    ))
                }
                Trust::Estimated if trust.doubtful && !trust.words.contains("estimated") => {
                    failures.push(format!("subject {index}: {name}'s words: {}", trust.words))
                }
                Trust::Placed => failures.push(format!("subject {index}: {name} placed")),
                _ => {}
            }
        }
    }
    means_within(&WITHIN_LANDMARK_FREE, &differences, &mut failures);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Each of `measures` whose mean difference (`differences`, per measurement, m) lies beyond its
/// ISO 20685-1 limit adds a failure.
fn means_within(measures: &[Measure], differences: &[Vec<f64>], failures: &mut Vec<String>) {
    for &m in measures {
        let d = &differences[m.index()];
        let mean = d.iter().sum::<f64>() / d.len().max(1) as f64;
        let limit = m.iso_class().unwrap().limit();
        let name = m.definition().name;
        eprintln!(
            "{name:<18} mean {:+.1} mm (limit {:.0})",
            mean * 1e3,
            limit * 1e3
        );
        if mean.abs() > limit {
            failures.push(format!(
                "{name}: mean difference {:+.1} mm beyond ISO 20685-1's {:.0} mm",
                mean * 1e3,
                limit * 1e3
            ));
        }
    }
}

/// The three held-out subjects of seed 4343 these tests fit.
const SUBJECTS: [u64; 3] = [0, 1, 2];

fn held_out(index: u64) -> SubjectId {
    SubjectId {
        profile: PopulationProfile::HeldOut,
        seed: 4343,
        index,
    }
}
