//! Slider-path and build benchmarks of the PCA core (native). Prints figures; asserts nothing.
//!
//!   cargo run --release --example pca_bench [-- SUBJECTS]
//!
//! 1. Reconstruction for sliders at the `fine` template's size and at 650K vertices (issue 6's
//!    figure): 20 whole-body modes + 20 modes in each of the six segments, stitched; full
//!    `reconstruct_into` and one-slider `apply_delta`. The basis content does not matter for
//!    speed, so it is seeded noise over the template's real segment weights.
//! 2. A real build at `base` resolution from SUBJECTS (default 100) posed, scaled copies of the
//!    template: GPA + 7 snapshot PCAs + quality curves, and the model file sizes (f32 / f16).

use bodyspace::pca::file::{write_model, BasisPrecision};
use bodyspace::pca::random::NormalRng;
use bodyspace::pca::segments::segment_subsets;
use bodyspace::pca::{
    build_body_model, BodyModel, BuildParams, Coefficients, ModeTarget, QualityCurves, ShapeModel,
    TemplateIdentity, TrainingSet,
};
use bodyspace::template::{Resolution, Segment, Template};
use nalgebra::{Point3, Rotation3, Vector3};
use std::time::Instant;

const MODES: usize = 20;

fn noise_model(rng: &mut NormalRng, indices: Vec<u32>, n: usize) -> ShapeModel {
    let d = 3 * n;
    ShapeModel {
        vertex_indices: indices,
        mean: (0..d).map(|_| rng.next_normal() as f32).collect(),
        basis: (0..MODES * d)
            .map(|_| (rng.next_normal() * 1e-3) as f32)
            .collect(),
        variances: (0..MODES).map(|k| 1.0 / (k + 1) as f64).collect(),
        all_variances: (0..MODES).map(|k| 1.0 / (k + 1) as f64).collect(),
        scores: Vec::new(),
        quality: QualityCurves::default(),
    }
}

fn median_ms(mut f: impl FnMut(), runs: usize) -> f64 {
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[runs / 2]
}

fn slider_bench(label: &str, weights: Vec<[f32; 6]>) {
    let v = weights.len();
    let mut rng = NormalRng::new(1);
    let subsets = segment_subsets(&weights);
    let whole = noise_model(&mut rng, Vec::new(), v);
    let segments: Vec<ShapeModel> = subsets
        .iter()
        .map(|s| noise_model(&mut rng, s.clone(), s.len()))
        .collect();
    let covered: usize = subsets.iter().map(|s| s.len()).sum();
    let template = TemplateIdentity {
        name: "bench".into(),
        hash: "0".into(),
        resolution: label.into(),
        vertex_count: v,
    };
    let model = BodyModel::assemble(
        template,
        BuildParams::default(),
        Vec::new(),
        Vec::new(),
        weights,
        whole,
        segments,
    )
    .expect("bench model is consistent");
    let b: Vec<f64> = (0..MODES).map(|k| 0.1 * (k + 1) as f64).collect();
    let whole_only = Coefficients {
        whole: b.clone(),
        ..Coefficients::default()
    };
    let stitched = Coefficients {
        whole: b.clone(),
        segments: std::array::from_fn(|_| Some(b.clone())),
    };
    let mut out = vec![0.0f32; 3 * v];
    let t_whole = median_ms(|| drop(model.reconstruct_into(&whole_only, &mut out)), 11);
    let t_stitched = median_ms(|| drop(model.reconstruct_into(&stitched, &mut out)), 11);
    let plan_whole = model.stitch_plan([false; 6]);
    let plan_all = model.stitch_plan([true; 6]);
    let t_delta = median_ms(
        || drop(model.apply_delta(&plan_whole, ModeTarget::Whole, 3, 0.01, &mut out)),
        51,
    );
    let t_delta_mixed = median_ms(
        || drop(model.apply_delta(&plan_all, ModeTarget::Whole, 3, 0.01, &mut out)),
        51,
    );
    let t_delta_torso = median_ms(
        || {
            drop(model.apply_delta(
                &plan_all,
                ModeTarget::Segment(Segment::Torso),
                3,
                0.01,
                &mut out,
            ))
        },
        51,
    );
    println!(
        "{label}: V = {v}, segment vertices = {covered} ({:.2}×V), {MODES} modes per model",
        covered as f64 / v as f64
    );
    println!("  reconstruct_into, whole body only:            {t_whole:7.2} ms");
    println!("  reconstruct_into, whole + 6 segments stitched: {t_stitched:7.2} ms");
    println!("  apply_delta, one whole-body slider:            {t_delta:7.2} ms");
    println!("  apply_delta, whole-body slider under overrides:{t_delta_mixed:7.2} ms");
    println!("  apply_delta, one torso slider:                 {t_delta_torso:7.2} ms");
}

fn build_bench(subjects: usize) {
    let template = Template::embedded().expect("embedded template");
    let mesh = template.mesh();
    let mut rng = NormalRng::new(9);
    let shapes: Vec<Vec<Point3<f64>>> = (0..subjects)
        .map(|_| {
            let (tall, wide, belly) = (
                0.04 * rng.next_normal(),
                0.08 * rng.next_normal(),
                0.05 * rng.next_normal(),
            );
            let rot = Rotation3::from_euler_angles(
                0.05 * rng.next_normal(),
                0.5 * rng.next_normal(),
                0.0,
            );
            let shift = Vector3::new(rng.next_normal(), 0.0, rng.next_normal());
            mesh.positions
                .iter()
                .map(|p| {
                    let bump = (-((p.y - 1.05) / 0.12).powi(2)).exp() * (p.z > 0.0) as i32 as f64;
                    let q = Point3::new(
                        p.x * (1.0 + wide),
                        p.y * (1.0 + tall),
                        p.z * (1.0 + wide) + belly * bump * p.z,
                    );
                    rot * q + shift
                })
                .collect()
        })
        .collect();
    let set = TrainingSet {
        template: TemplateIdentity {
            name: "bench".into(),
            hash: "0".into(),
            resolution: "base".into(),
            vertex_count: mesh.vertex_count(),
        },
        triangles: mesh.triangles.clone(),
        segment_weights: (0..mesh.vertex_count() as u32)
            .map(|v| template.segment_weights(v))
            .collect(),
        names: (0..subjects).map(|i| format!("s{i}")).collect(),
        shapes,
    };
    for quality in [false, true] {
        let params = BuildParams {
            compute_quality: quality,
            ..BuildParams::default()
        };
        let t = Instant::now();
        let model = build_body_model(&set, &params).expect("build");
        let secs = t.elapsed().as_secs_f64();
        println!(
            "build at base (V = {}), N = {subjects}, quality curves {}: {secs:.2} s; modes whole/segments {}/{:?}",
            mesh.vertex_count(),
            if quality { "on" } else { "off" },
            model.whole.mode_count(),
            model.segments.iter().map(|m| m.mode_count()).collect::<Vec<_>>()
        );
        if quality {
            let f32_bytes = write_model(&model, BasisPrecision::F32).len();
            let f16_bytes = write_model(&model, BasisPrecision::F16).len();
            println!(
                "  model file: f32 {:.2} MB, f16 {:.2} MB",
                f32_bytes as f64 / 1e6,
                f16_bytes as f64 / 1e6
            );
        }
    }
}

fn main() {
    let subjects = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(100);
    let base = Template::embedded().expect("embedded template");
    let fine = base.at_resolution(Resolution::Fine);
    let weights: Vec<[f32; 6]> = (0..fine.mesh().vertex_count() as u32)
        .map(|v| fine.segment_weights(v))
        .collect();
    slider_bench("fine", weights.clone());
    // Issue 6 states ~650K vertices for `fine`; the real template is smaller, so also time a
    // 650K body with the fine template's weights repeated (same overlap fraction).
    let big: Vec<[f32; 6]> = (0..650_000).map(|v| weights[v % weights.len()]).collect();
    slider_bench("650K", big);
    build_bench(subjects);
}
