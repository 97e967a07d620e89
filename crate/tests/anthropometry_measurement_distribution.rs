//! End-to-end: the measurement distributions of the demo model (`public/models/demo.bsm`, 100
//! synthetic subjects, 20 modes): over its training subjects and 300 sampled bodies, sorted
//! values, percentiles, correlations, a body's percentile, and that the samples reproduce the
//! training population's spread.
#![cfg(not(target_arch = "wasm32"))]

use bodyspace::anthropometry::measurement_distribution::{
    measure_at_sigma, measurement_distribution, DistributionParams, PERCENTILE_LEVELS,
};
use bodyspace::cli::model::{base_measurer, load_model};
use bodyspace::measure::Measure;
use std::path::Path;

#[test]
fn distributions_of_the_demo_model() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../public/models/demo.bsm"
    ));
    let (model, _) = load_model(path).unwrap();
    let measurer = base_measurer().unwrap();
    let params = DistributionParams::default();
    let mut reports = Vec::new();
    let d = measurement_distribution(&model.whole, &measurer, &params, &mut |f| reports.push(f))
        .unwrap();
    assert_eq!(d.training.bodies, 100);
    assert_eq!(d.samples.bodies, params.samples);
    assert!(reports.windows(2).all(|w| w[0] <= w[1]));
    assert!((reports.last().unwrap() - 1.0).abs() < 1e-12);
    let n = Measure::ALL.len();
    for population in [&d.training, &d.samples] {
        for m in Measure::ALL {
            let x = population.of(m);
            // A girth may find no section on an odd sampled body (neck: 2 of 300); never more.
            assert!(x.values.len() + 5 >= population.bodies, "{}", x.name);
            assert!(x.values.windows(2).all(|w| w[0] <= w[1]));
            assert!(x.percentiles.windows(2).all(|w| w[0] <= w[1]), "{}", x.name);
            for (level, value) in PERCENTILE_LEVELS.iter().zip(x.percentiles) {
                let p = x.percentile_of(value);
                assert!((p - level).abs() < 2.0, "{} at {level}: {p}", x.name);
            }
            let r = population.correlation[m.index() * n + m.index()];
            assert!((r - 1.0).abs() < 1e-9);
        }
        for a in 0..n {
            for b in 0..n {
                let (x, y) = (
                    population.correlation[a * n + b],
                    population.correlation[b * n + a],
                );
                assert!((x - y).abs() < 1e-12 && x.abs() <= 1.0 + 1e-12);
            }
        }
        let r = |a: Measure, b: Measure| population.correlation[a.index() * n + b.index()];
        assert!(r(Measure::Stature, Measure::CrotchHeight) > 0.8);
        assert!(r(Measure::WaistGirth, Measure::Volume) > 0.5);
    }
    // The model's samples spread as its training subjects do (the stored scores are the
    // training subjects' own, the samples N(0, λ)): standard deviations within 25 %, medians
    // within half a standard deviation.
    for m in [
        Measure::Stature,
        Measure::ChestGirth,
        Measure::WaistGirth,
        Measure::HipGirth,
        Measure::Volume,
    ] {
        let (t, s) = (d.training.of(m), d.samples.of(m));
        eprintln!(
            "{:<12} training {:.4} ± {:.4}, samples {:.4} ± {:.4}",
            t.name, t.mean, t.sd, s.mean, s.sd
        );
        assert!((s.sd / t.sd - 1.0).abs() < 0.25, "{}", t.name);
        assert!(
            (s.percentiles[2] - t.percentiles[2]).abs() < 0.5 * t.sd,
            "{}",
            t.name
        );
    }
    // The mean body sits near the middle; a training subject's own values sit where its rank is.
    let mean_body = measure_at_sigma(&model.whole, &measurer, &[]).unwrap();
    for p in d.samples.percentiles_of(&mean_body).into_iter().flatten() {
        assert!((20.0..=80.0).contains(&p), "mean body at percentile {p}");
    }
    let first = &d.training.table[0];
    let stature = first.get(Measure::Stature).unwrap();
    let rank = d
        .training
        .table
        .iter()
        .filter(|t| t.get(Measure::Stature).unwrap() < stature)
        .count() as f64;
    let p = d.training.percentiles_of(first)[Measure::Stature.index()].unwrap();
    assert!((p - (rank + 0.5)).abs() < 1e-9, "{p} vs {rank}");
    // Too few samples is refused with a message.
    let e = measurement_distribution(
        &model.whole,
        &measurer,
        &DistributionParams {
            samples: 1,
            seed: 1,
        },
        &mut |_| {},
    )
    .unwrap_err();
    assert!(e.to_string().contains("samples"), "{e}");
}
