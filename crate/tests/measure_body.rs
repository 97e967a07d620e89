//! End-to-end: bodies from measurements on the demo model (`public/models/demo.bsm`, 100
//! synthetic subjects). Targets inside the population's 5–95 % range (percentiles of the
//! training subjects' own measurements, each subject reconstructed from its whole-body scores)
//! are met within 2 mm for lengths and 5 mm for girths, for 1, 2 and 4 targets at once, and the
//! body stays plausible (Mahalanobis norm below 5; a tall body with a small chest, 95th and 20th
//! percentiles, needs 4.3).
#![cfg(not(target_arch = "wasm32"))]

use bodyspace::anthropometry::from_measurements::{body_from_measurements, FromMeasurementsParams};
use bodyspace::cli::model::{base_measurer, load_model};
use bodyspace::measure::{Kind, Measure};
use std::path::Path;

#[test]
fn targets_inside_the_population_are_met() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../public/models/demo.bsm"
    ));
    let (model, _) = load_model(path).unwrap();
    let measurer = base_measurer().unwrap();
    let whole = &model.whole;
    let population: Vec<_> = (0..model.subjects.len())
        .map(|i| {
            let b: Vec<f64> = whole
                .subject_scores(i)
                .unwrap()
                .iter()
                .map(|&x| x as f64)
                .collect();
            let x: Vec<f32> = whole
                .reconstruct(&b)
                .unwrap()
                .iter()
                .map(|&v| v as f32)
                .collect();
            measurer.measure(&x).unwrap()
        })
        .collect();
    let percentile = |m: Measure, p: f64| {
        let mut v: Vec<f64> = population.iter().filter_map(|x| x.get(m)).collect();
        v.sort_by(f64::total_cmp);
        v[((p / 100.0) * (v.len() - 1) as f64).round() as usize]
    };
    use Measure::*;
    let cases: Vec<Vec<(Measure, f64)>> = vec![
        vec![(Stature, percentile(Stature, 5.0))],
        vec![(WaistGirth, percentile(WaistGirth, 95.0))],
        vec![
            (Stature, percentile(Stature, 90.0)),
            (WaistGirth, percentile(WaistGirth, 10.0)),
        ],
        vec![
            (Stature, percentile(Stature, 10.0)),
            (HipGirth, percentile(HipGirth, 90.0)),
        ],
        vec![
            (CrotchHeight, percentile(CrotchHeight, 75.0)),
            (ThighGirth, percentile(ThighGirth, 25.0)),
        ],
        vec![
            (Stature, percentile(Stature, 50.0)),
            (ChestGirth, percentile(ChestGirth, 80.0)),
            (WaistGirth, percentile(WaistGirth, 30.0)),
            (HipGirth, percentile(HipGirth, 60.0)),
        ],
        vec![
            (Stature, percentile(Stature, 95.0)),
            (ChestGirth, percentile(ChestGirth, 20.0)),
            (WaistGirth, percentile(WaistGirth, 50.0)),
            (HipGirth, percentile(HipGirth, 30.0)),
        ],
    ];
    let params = FromMeasurementsParams::default();
    for targets in cases {
        let found = body_from_measurements(whole, &measurer, &targets, &params).unwrap();
        for a in &found.achieved {
            let m = Measure::from_name(a.name).unwrap();
            let limit = match m.definition().kind {
                Kind::Length => 0.002,
                _ => 0.005,
            };
            eprintln!(
                "{:<14} target {:.4} achieved {:.4} ({:+.2} mm), {} iterations, |z| {:.2}",
                a.name,
                a.target,
                a.achieved,
                (a.achieved - a.target) * 1e3,
                found.iterations,
                found.mahalanobis
            );
            assert!((a.achieved - a.target).abs() <= limit, "{targets:?}: {a:?}");
            assert!(a.met);
        }
        assert!(
            found.mahalanobis < 5.0,
            "{targets:?}: |z| = {}",
            found.mahalanobis
        );
    }
    // Bad targets are refused with a message.
    let e = body_from_measurements(whole, &measurer, &[], &params).unwrap_err();
    assert!(e.to_string().contains("no target"), "{e}");
    let e = body_from_measurements(whole, &measurer, &[(Stature, f64::NAN)], &params).unwrap_err();
    assert!(e.to_string().contains("stature"), "{e}");
}
