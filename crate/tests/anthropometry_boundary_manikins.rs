//! End-to-end: boundary manikins of the demo model (`public/models/demo.bsm`): for two
//! measurements at 90 % and three at 95 %, every manikin's achieved values lie on the coverage
//! ellipsoid of the sampled population (Mahalanobis distance r = √χ²ₖ(p) within 0.1), every
//! target is met within its tolerance (2 mm lengths, 5 mm girths), and the CSV has a row per
//! manikin; bad choices are refused with a message.
#![cfg(not(target_arch = "wasm32"))]

use bodyspace::anthropometry::boundary_manikins::{boundary_manikins, ManikinParams};
use bodyspace::anthropometry::chi_square::chi_square_quantile;
use bodyspace::anthropometry::from_measurements::FromMeasurementsParams;
use bodyspace::anthropometry::measurement_distribution::{
    sampled_measurements, DistributionParams, PopulationMeasurements,
};
use bodyspace::cli::model::{base_measurer, load_model};
use bodyspace::measure::Measure;
use std::path::Path;

#[test]
fn manikins_lie_on_the_coverage_boundary() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../public/models/demo.bsm"
    ));
    let (model, _) = load_model(path).unwrap();
    let measurer = base_measurer().unwrap();
    let p = DistributionParams::default();
    let population = PopulationMeasurements::of_bodies(
        sampled_measurements(&model.whole, &measurer, p.samples, p.seed, &mut |_| {}).unwrap(),
    );
    let solver = FromMeasurementsParams::default();
    use Measure::*;
    for (measures, coverage, count) in [
        (vec![Stature, WaistGirth], 0.9, 8),
        (vec![Stature, ChestGirth, HipGirth], 0.95, 14),
    ] {
        let params = ManikinParams {
            coverage,
            ..ManikinParams::default()
        };
        let found = boundary_manikins(
            &model.whole,
            &measurer,
            &population,
            &measures,
            &params,
            &solver,
            &mut |_| {},
        )
        .unwrap();
        let r = chi_square_quantile(measures.len(), coverage).sqrt();
        assert!((found.radius - r).abs() < 1e-12);
        assert_eq!(found.manikins.len(), count);
        for m in &found.manikins {
            eprintln!(
                "{} distance {:.3} (r {r:.3}), |z| {:.2}, {} iterations",
                m.name, m.distance, m.body.mahalanobis, m.body.iterations
            );
            assert!(
                (m.distance - r).abs() < 0.1,
                "{}: {} vs {r}",
                m.name,
                m.distance
            );
            for a in &m.body.achieved {
                assert!(a.met, "{}: {a:?}", m.name);
                let measured = m
                    .measurements
                    .get(Measure::from_name(a.name).unwrap())
                    .unwrap();
                assert!((measured - a.achieved).abs() < 1e-9);
            }
        }
        let csv = found.to_csv();
        assert_eq!(csv.lines().count(), count + 1);
        assert!(csv.starts_with("name,distance,mahalanobis,target_stature,"));
    }
    let refuse = |measures: &[Measure], coverage: f64, what: &str| {
        let params = ManikinParams {
            coverage,
            ..ManikinParams::default()
        };
        let e = boundary_manikins(
            &model.whole,
            &measurer,
            &population,
            measures,
            &params,
            &solver,
            &mut |_| {},
        )
        .unwrap_err();
        assert!(e.to_string().contains(what), "{e}");
    };
    refuse(&[Stature], 0.9, "2, 3 or 4");
    refuse(&[Stature, Stature], 0.9, "twice");
    refuse(&[Stature, WaistGirth], 1.5, "coverage");
}
