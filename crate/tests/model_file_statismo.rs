//! Statismo HDF5 models (`model_file::statismo`, `io::statismo_h5`, `bodyspace export-statismo`): a
//! model built on the embedded template written, read back and opened again; segment files;
//! segment marginals against segment models built directly; older and foreign files; refusals.
//! The command line's `export-statismo` and its reading of `.h5` models: `pca_cli.rs`.
#![cfg(not(target_arch = "wasm32"))]

mod pca_support;

use bodyspace::io::statismo_h5::{read_statismo_h5, write_statismo_h5};
use bodyspace::model_file::statismo::{body_model_from_statismo, statismo_of_part, StatismoModel};
use bodyspace::pca::random::NormalRng;
use bodyspace::pca::{
    build_body_model, BodyModel, BuildParams, PcaError, TemplateIdentity, TrainingSet,
};
use bodyspace::template::{Segment, Template};
use nalgebra::Point3;
use std::path::PathBuf;

/// `n` subjects on the embedded template: scaled along each axis, with a belly and a head
/// bulge, amounts from a seeded normal; every mode kept.
fn model(n: usize) -> (BodyModel, Template) {
    let template = Template::embedded().unwrap();
    let mesh = template.mesh();
    let mut rng = NormalRng::new(13);
    let shapes = (0..n)
        .map(|_| {
            let [sx, sy, sz, belly, head] =
                [0.04, 0.03, 0.05, 0.02, 0.01].map(|s| s * rng.next_normal());
            mesh.positions
                .iter()
                .map(|p| {
                    let bump = |c: f64, w: f64| (-((p.y - c) / w).powi(2)).exp();
                    let out = 1.0 + belly * bump(0.1, 0.15) + head * bump(0.7, 0.1);
                    Point3::new(
                        p.x * (1.0 + sx) * out,
                        p.y * (1.0 + sy),
                        p.z * (1.0 + sz) * out,
                    )
                })
                .collect()
        })
        .collect();
    let set = TrainingSet::on_template(
        &template,
        (1..=n).map(|i| format!("fit_{i}")).collect(),
        shapes,
    );
    let params = BuildParams {
        variance: 1.0,
        compute_quality: false,
        ..BuildParams::default()
    };
    (build_body_model(&set, &params).unwrap(), template)
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bodyspace-statismo-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn max_diff(a: &[f32], b: &[f32]) -> f32 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f32::max)
}

fn statismo_error(result: Result<BodyModel, PcaError>) -> String {
    match result {
        Err(PcaError::Statismo(m)) => m,
        other => panic!("expected a statismo error, got {:?}", other.err()),
    }
}

#[test]
fn the_whole_body_round_trips_through_an_hdf5_file() {
    let (model, template) = model(6);
    let file = statismo_of_part(&model, None);
    let (n, k) = (template.mesh().vertex_count(), model.whole.mode_count());
    assert_eq!(k, 5);
    assert_eq!((file.points.rows, file.points.cols), (3, n));
    assert_eq!((file.pca_basis.rows, file.pca_basis.cols), (3 * n, k));
    assert_eq!(
        (file.cells.rows, file.cells.cols),
        (3, model.triangles.len())
    );
    assert_eq!((file.scores.rows, file.scores.cols), (k, 6));
    // Millimetres; points are the mean, 3 × n by coordinate rows.
    assert!((file.mean[3] - 1000.0 * model.whole.mean[3]).abs() < 1e-3);
    assert_eq!(file.points.data[n + 1], file.mean[4]);
    assert_eq!(
        file.cells.data[2 * model.triangles.len() + 7],
        model.triangles[7][2]
    );

    let path = temp("whole.h5");
    write_statismo_h5(&path, &file, "now").unwrap();
    let read = read_statismo_h5(&path).unwrap();
    std::fs::remove_file(&path).ok();
    let strip = |f: &StatismoModel| StatismoModel {
        data_info: Vec::new(),
        parameters: Vec::new(),
        ..f.clone()
    };
    assert_eq!(
        strip(&read),
        strip(&file),
        "every dataset reads back bit for bit"
    );

    let back = body_model_from_statismo(&read, &template).unwrap();
    back.check_template(&TemplateIdentity::of_template(&template))
        .unwrap();
    assert!(max_diff(&back.whole.mean, &model.whole.mean) < 1e-6);
    assert_eq!(back.whole.basis, model.whole.basis);
    for (a, b) in back.whole.variances.iter().zip(&model.whole.variances) {
        assert!((a / b - 1.0).abs() < 1e-6, "{a} vs {b}");
    }
    assert!(max_diff(&back.whole.scores, &model.whole.scores) < 1e-6);
    assert_eq!(back.triangles, model.triangles);
    assert_eq!(back.segment_weights, model.segment_weights);
    // The same body at +2σ / −1σ / +0.5σ from both.
    let sigma = [2.0, -1.0, 0.5];
    let body = |m: &BodyModel| -> Vec<f32> {
        let c = bodyspace::pca::Coefficients {
            whole: m.whole.coefficients_from_sigma(&sigma).unwrap(),
            ..Default::default()
        };
        let mut out = vec![0.0; 3 * n];
        m.reconstruct_into(&c, &mut out).unwrap();
        out
    };
    assert!(max_diff(&body(&back), &body(&model)) < 1e-6);
}

#[test]
fn segment_models_are_the_whole_body_marginals_and_equal_the_built_ones_when_every_mode_is_kept() {
    let (model, template) = model(6);
    let back = body_model_from_statismo(&statismo_of_part(&model, None), &template).unwrap();
    for s in Segment::ALL {
        let (built, marginal) = (model.segment(s), back.segment(s));
        assert_eq!(marginal.vertex_indices, built.vertex_indices);
        assert_eq!(marginal.mode_count(), built.mode_count(), "{}", s.name());
        for (a, b) in marginal.variances.iter().zip(&built.variances) {
            assert!((a / b - 1.0).abs() < 1e-4, "{}: {a} vs {b}", s.name());
        }
        // Each subject's segment, rebuilt from the marginal's scores, is the built model's.
        for i in 0..6 {
            let b = |m: &bodyspace::pca::ShapeModel| {
                let c: Vec<f64> = m
                    .subject_scores(i)
                    .unwrap()
                    .iter()
                    .map(|&x| x as f64)
                    .collect();
                m.reconstruct(&c).unwrap()
            };
            let (x, y) = (b(marginal), b(built));
            let d = x
                .iter()
                .zip(&y)
                .map(|(p, q)| (p - q).abs())
                .fold(0.0, f64::max);
            assert!(d < 1e-6, "{} subject {i}: {d} m", s.name());
        }
        pca_support::check_orthonormal(marginal);
    }
}

#[test]
fn a_segment_file_is_its_own_vertices_and_triangles_and_is_refused_as_a_body() {
    let (model, template) = model(4);
    let torso = model.segment(Segment::Torso);
    let file = statismo_of_part(&model, Some(Segment::Torso));
    let n = torso.vertex_count();
    assert_eq!(file.point_count(), n);
    assert_eq!(file.mode_count(), torso.mode_count());
    assert!(file.cells.cols > 0 && file.cells.data.iter().all(|&i| (i as usize) < n));
    // Every triangle of the file is a template triangle inside the torso.
    let t = file.cells.cols;
    let global = |j: usize| torso.vertex_indices[file.cells.data[j] as usize];
    let tri = [global(0), global(t), global(2 * t)];
    assert!(model.triangles.contains(&tri));
    let message = statismo_error(body_model_from_statismo(&file, &template));
    assert!(
        message.contains("torso segment") && message.contains(&n.to_string()),
        "{message}"
    );
}

#[test]
fn version_0_8_files_store_a_scaled_basis_and_metre_files_read_as_metres() {
    let (model, template) = model(5);
    let file = statismo_of_part(&model, None);
    let k = file.mode_count();
    let mut old = file.clone();
    old.version = None;
    for (i, x) in old.pca_basis.data.iter_mut().enumerate() {
        *x *= file.pca_variance[i % k].sqrt();
    }
    let back = body_model_from_statismo(&old, &template).unwrap();
    assert!(max_diff(&back.whole.basis, &model.whole.basis) < 1e-5);

    let mut metres = file.clone();
    metres
        .mean
        .iter_mut()
        .chain(&mut metres.points.data)
        .for_each(|x| *x /= 1000.0);
    metres.pca_variance.iter_mut().for_each(|x| *x /= 1e6);
    let back = body_model_from_statismo(&metres, &template).unwrap();
    assert!(max_diff(&back.whole.mean, &model.whole.mean) < 1e-6);
    assert!((back.whole.variances[0] / model.whole.variances[0] - 1.0).abs() < 1e-6);
}

#[test]
fn inconsistent_or_foreign_files_are_refused_with_the_reason() {
    let (model, template) = model(3);
    let good = statismo_of_part(&model, None);
    let refuse = |f: StatismoModel| statismo_error(body_model_from_statismo(&f, &template));

    let mut f = good.clone();
    f.version = Some((2, 0));
    assert!(refuse(f).contains("version 2.0"));
    let mut f = good.clone();
    f.mean.pop();
    assert!(refuse(f).contains("/model/mean"));
    let mut f = good.clone();
    f.pca_basis.cols += 1;
    assert!(refuse(f).contains("/model/pcaBasis"));
    let mut f = good.clone();
    f.pca_variance[0] = f32::NAN;
    assert!(refuse(f).contains("finite"));
    let mut f = good.clone();
    let m = f.cells.cols;
    f.cells.data.swap(0, m);
    assert!(refuse(f).contains("other triangles"));
    let mut f = good.clone();
    f.cells.data[0] = 1 << 30;
    assert!(refuse(f).contains("refers to point"));
    let mut f = good;
    f.points = bodyspace::model_file::statismo::RowMajor {
        rows: 3,
        cols: 100,
        data: vec![0.0; 300],
    };
    f.mean = vec![0.0; 300];
    let k = f.mode_count();
    f.pca_basis = bodyspace::model_file::statismo::RowMajor {
        rows: 300,
        cols: k,
        data: vec![0.0; 300 * k],
    };
    f.cells = bodyspace::model_file::statismo::RowMajor {
        rows: 3,
        cols: 1,
        data: vec![0, 1, 2],
    };
    let message = refuse(f);
    assert!(
        message.contains("100 points") && message.contains("13380"),
        "{message}"
    );

    // Not HDF5, and an HDF5 file cut short: errors, not panics.
    let path = temp("not.h5");
    std::fs::write(&path, b"hello").unwrap();
    assert!(read_statismo_h5(&path).is_err());
    let whole = temp("cut-source.h5");
    write_statismo_h5(&whole, &statismo_of_part(&model, None), "now").unwrap();
    let bytes = std::fs::read(&whole).unwrap();
    std::fs::write(&path, &bytes[..bytes.len() / 2]).unwrap();
    assert!(read_statismo_h5(&path).is_err());
    for p in [path, whole] {
        std::fs::remove_file(p).ok();
    }
}
