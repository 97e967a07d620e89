//! End-to-end: a shape model is built in the template's frame (y up, metres, facing +z) whatever
//! the frames and units of its fits. Six synthetic subjects (`tuning` population, posed bodies in
//! template vertex order) give the same model once all y-up in metres and once in a mixture of
//! y-up metres, CAESAR's z-up millimetres, turned centimetres and −x up: the same modes,
//! eigenvalues within 1e-6 relative, a mean body whose stature (the project's measurement) is
//! within 1 mm and is a person's, standing up; and a fit projects onto the model alike in either
//! frame.
#![cfg(not(target_arch = "wasm32"))]

mod synth_support;

use bodyspace::measure::{BodyMeasurer, Measure, MeasureParams};
use bodyspace::pca::{build_body_model, BodyModel, BuildParams, TrainingSet};
use bodyspace::synth::subject::{fit_height, shape_and_pose};
use bodyspace::synth::{subject_rng, PopulationProfile};
use bodyspace::template::Segment;
use nalgebra::{Point3, Rotation3, Vector3};

const SUBJECTS: u64 = 6;

/// A map of points from the template's frame (metres, y up) into another frame.
type FrameMap = Box<dyn Fn(&Point3<f64>) -> Point3<f64>>;

/// The frames a fit may come in.
fn frame(k: u64) -> (&'static str, FrameMap) {
    match k % 5 {
        0 => ("y up, m", Box::new(|p| *p)),
        // `bodyspace synth`'s CAESAR frame: (x, y, z) ↦ 1000·(x, −z, y), any origin.
        1 => (
            "z up, mm",
            Box::new(|p| Point3::new(1e3 * p.x + 120.0, -1e3 * p.z - 340.0, 1e3 * p.y + 5.0)),
        ),
        2 => {
            let turn = Rotation3::from_axis_angle(&Vector3::y_axis(), 2.2);
            (
                "turned, cm",
                Box::new(move |p| {
                    Point3::from(100.0 * (turn * p.coords) + Vector3::new(40.0, -3.0, 7.0))
                }),
            )
        }
        3 => (
            "−x up, m",
            Box::new(|p| Point3::new(-p.y + 0.4, p.x, p.z - 1.0)),
        ),
        _ => {
            let tilt = Rotation3::from_euler_angles(0.3, -1.1, 0.2);
            (
                "z up, mm, tilted",
                Box::new(move |p| {
                    let q = tilt * p.coords;
                    Point3::new(1e3 * q.x, -1e3 * q.z, 1e3 * q.y)
                }),
            )
        }
    }
}

fn model(set: &TrainingSet) -> BodyModel {
    let params = BuildParams {
        compute_quality: false,
        ..BuildParams::default()
    };
    build_body_model(set, &params).unwrap()
}

/// The mean body's extent along x, y and z (m).
fn extents(mean: &[f32]) -> [f64; 3] {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in mean.chunks_exact(3) {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k] as f64);
            hi[k] = hi[k].max(p[k] as f64);
        }
    }
    [0, 1, 2].map(|k| hi[k] - lo[k])
}

#[test]
fn the_same_subjects_in_any_frames_and_units_give_the_same_model() {
    let (template, data) = synth_support::base_template_and_data();
    let bodies: Vec<Vec<Point3<f64>>> = (0..SUBJECTS)
        .map(|i| {
            let mut rng = subject_rng(2026, i);
            let params = fit_height(&data, &PopulationProfile::Tuning.sample_subject(&mut rng));
            shape_and_pose(&data, &params).unwrap().1
        })
        .collect();
    let names: Vec<String> = (0..SUBJECTS).map(|i| format!("subject_{i}")).collect();
    let upright = TrainingSet::on_template(&template, names.clone(), bodies.clone());
    let mixed = TrainingSet::on_template(
        &template,
        names,
        bodies
            .iter()
            .zip(0..)
            .map(|(b, k)| {
                let (name, map) = frame(k);
                eprintln!("subject {k}: {name}");
                b.iter().map(&map).collect()
            })
            .collect(),
    );
    let (a, b) = (model(&upright), model(&mixed));
    let measurer = BodyMeasurer::of_template(&template, MeasureParams::default()).unwrap();
    let (ma, mb) = (
        measurer.measure(&a.whole.mean).unwrap(),
        measurer.measure(&b.whole.mean).unwrap(),
    );
    let stature = |m: &bodyspace::measure::Measurements| m.get(Measure::Stature).unwrap();
    let hip = |m: &bodyspace::measure::Measurements| m.get(Measure::HipGirth).unwrap();
    eprintln!(
        "mean stature {:.5} / {:.5} m, hip girth {:.5} / {:.5} m",
        stature(&ma),
        stature(&mb),
        hip(&ma),
        hip(&mb)
    );
    assert!((stature(&ma) - stature(&mb)).abs() < 1e-3);
    assert!((hip(&ma) - hip(&mb)).abs() < 1e-3);
    // A person's, standing up: y the longest side of the mean body, in metres.
    assert!((1.4..2.1).contains(&stature(&mb)), "{}", stature(&mb));
    assert!((0.7..1.4).contains(&hip(&mb)), "{}", hip(&mb));
    let [x, y, z] = extents(&b.whole.mean);
    assert!(y > 1.4 && y > 1.5 * x && y > 3.0 * z, "extents {x} {y} {z}");
    // The same model: modes and eigenvalues, whole body and every segment.
    for (pa, pb, name) in std::iter::once((&a.whole, &b.whole, "whole")).chain(
        Segment::ALL
            .iter()
            .map(|s| (a.segment(*s), b.segment(*s), s.name())),
    ) {
        assert_eq!(pa.mode_count(), pb.mode_count(), "{name}");
        for (la, lb) in pa.variances.iter().zip(&pb.variances) {
            assert!(
                (la - lb).abs() <= 1e-6 * pa.variances[0],
                "{name}: λ {la} vs {lb}"
            );
        }
    }
    let mean_gap = a
        .whole
        .mean
        .iter()
        .zip(&b.whole.mean)
        .map(|(p, q)| (p - q).abs())
        .fold(0.0f32, f32::max);
    assert!(mean_gap < 1e-4, "means differ by up to {mean_gap} m");
    // A fit projects the same in any frame and units (subject 1 is z up in millimetres).
    let (in_metres, in_mm) = (
        b.project(&upright.shapes[1]).unwrap(),
        b.project(&mixed.shapes[1]).unwrap(),
    );
    assert!((in_mm.pose.scale - 1e-3).abs() < 1e-12);
    for (x, y) in in_metres
        .coefficients
        .whole
        .iter()
        .zip(&in_mm.coefficients.whole)
    {
        assert!((x - y).abs() < 1e-6, "b {x} vs {y}");
    }
    assert!((in_metres.residual - in_mm.residual).abs() < 1e-6);
}

#[test]
fn pose_removal_none_uses_the_shapes_as_given() {
    let (template, _) = synth_support::base_template_and_data();
    let rest = &template.mesh().positions;
    let shapes: Vec<Vec<Point3<f64>>> = [1.0, 1.02]
        .iter()
        .map(|s| {
            rest.iter()
                .map(|p| Point3::new(p.x, s * p.y, -p.z))
                .collect()
        })
        .collect();
    let set = TrainingSet::on_template(&template, vec!["a".into(), "b".into()], shapes);
    let params = BuildParams {
        gpa: bodyspace::pca::GpaParams {
            pose: bodyspace::pca::PoseRemoval::None,
            ..Default::default()
        },
        compute_quality: false,
        ..BuildParams::default()
    };
    let m = build_body_model(&set, &params).unwrap();
    // Facing −z as given: the mean's first vertex is the average of the inputs' own.
    let p = rest[0];
    let expected = [p.x, 1.01 * p.y, -p.z];
    for (got, want) in m.whole.mean.iter().zip(expected) {
        assert!((*got as f64 - want).abs() < 1e-5);
    }
}
