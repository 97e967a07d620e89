//! End-to-end `rbf_warp` (paper §3.1): a procedural body warped onto a known non-linear subject
//! given in CAESAR's frame (millimetres, z-up), with explicit tolerances.
// Native only; tests/rbf_wasm.rs runs the same checks in the browser.
#![cfg(not(target_arch = "wasm32"))]
mod rbf_support;

use bodyspace::landmarks::{Landmark, LandmarkSet};
use bodyspace::mesh::Mesh;
use bodyspace::rbf::{
    rbf_warp_mesh, similarity, virtual_landmarks_detailed, RbfParams, VIRTUAL_LANDMARK_COUNT,
};
use nalgebra::{Matrix3, Point3, Vector3};

struct Case {
    template: Mesh,
    template_landmarks: LandmarkSet,
    scan: Mesh,
    scan_landmarks: LandmarkSet,
    truth: Vec<Point3<f64>>,
}

/// Template at one sampling, the scan at another (as a real scan is), both from the procedural
/// body; the truth is the known map of each template vertex.
fn case() -> Case {
    let template = rbf_support::body(12);
    let template_landmarks = rbf_support::landmarks(&template);
    let scan_body = rbf_support::body(14);
    let scan = Mesh::new(
        scan_body
            .positions
            .iter()
            .map(rbf_support::subject)
            .collect(),
        scan_body.triangles,
    );
    let scan_landmarks = LandmarkSet {
        landmarks: template_landmarks
            .landmarks
            .iter()
            .map(|l| Landmark {
                name: l.name.clone(),
                position: rbf_support::subject(&l.position),
            })
            .collect(),
        ..LandmarkSet::default()
    };
    let truth = template
        .positions
        .iter()
        .map(rbf_support::subject)
        .collect();
    Case {
        template,
        template_landmarks,
        scan,
        scan_landmarks,
        truth,
    }
}

fn mean_distance(a: &[Point3<f64>], b: &[Point3<f64>]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).norm()).sum::<f64>() / a.len() as f64
}

#[test]
fn procrustes_recovers_millimetres_and_z_up() {
    let c = case();
    let p: Vec<_> = c
        .template_landmarks
        .landmarks
        .iter()
        .map(|l| l.position)
        .collect();
    let q: Vec<_> = p.iter().map(rbf_support::to_scan_frame).collect();
    let s = similarity(&p, &q).unwrap();
    assert!((s.scale - 1000.0).abs() < 1e-9, "scale {}", s.scale);
    let y_up_to_z_up = Matrix3::new(1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0);
    assert!((s.rotation - y_up_to_z_up).norm() < 1e-12);
    assert!((s.translation - Vector3::new(120.0, -40.0, 5.0)).norm() < 1e-8);
}

#[test]
fn the_warp_lands_every_landmark_and_follows_the_subject() {
    let c = case();
    let w = rbf_warp_mesh(
        &c.template,
        &c.template_landmarks,
        &c.scan,
        &c.scan_landmarks,
        &RbfParams::default(),
    )
    .unwrap();
    assert_eq!(w.positions.len(), c.template.positions.len());
    assert_eq!(w.pairing.used.len(), 73 + VIRTUAL_LANDMARK_COUNT);
    assert!(w.pairing.skipped.is_empty() && w.pairing.virtual_off_surface.is_empty());
    let body_size_mm = 1.06 * 1800.0;
    for r in &w.residuals {
        assert!(r.after < 1e-8 * body_size_mm, "{}: {}", r.name, r.after);
        assert!(r.before.is_finite());
    }
    // The subject is taller, bellied and has raised arms: similarity alone leaves centimetres.
    let worst_before = w.residuals.iter().map(|r| r.before).fold(0.0, f64::max);
    assert!(worst_before > 30.0, "{worst_before}");
    // The warped template is in the scan's frame (mm, z-up) and close to the truth everywhere.
    let similarity_only = w.similarity.apply_all(&c.template.positions);
    let before = mean_distance(&similarity_only, &c.truth);
    let after = mean_distance(&w.positions, &c.truth);
    assert!(after < 8.0, "mean vertex error {after} mm");
    assert!(
        after < 0.5 * before,
        "warp {after} mm vs similarity only {before} mm"
    );
}

#[test]
fn missing_scan_landmarks_are_skipped_and_reported() {
    let mut c = case();
    let gone = ["Sellion", "Lt. Dactylion", "Rt. Knee Crease"];
    c.scan_landmarks
        .landmarks
        .retain(|l| !gone.contains(&l.name.as_str()));
    c.scan_landmarks.missing = gone.iter().map(|s| s.to_string()).collect();
    let w = rbf_warp_mesh(
        &c.template,
        &c.template_landmarks,
        &c.scan,
        &c.scan_landmarks,
        &RbfParams::default(),
    )
    .unwrap();
    assert_eq!(w.pairing.skipped, gone);
    assert_eq!(w.pairing.used.len(), 73 + VIRTUAL_LANDMARK_COUNT - 3);
    assert!(w.positions.iter().all(|p| p.iter().all(|v| v.is_finite())));
}

#[test]
fn virtual_landmarks_lie_on_the_surface_or_say_they_do_not() {
    let c = case();
    let v = virtual_landmarks_detailed(&c.template_landmarks, &c.template);
    assert_eq!(v.len(), VIRTUAL_LANDMARK_COUNT);
    for l in &v {
        assert!(l.on_surface, "{}", l.landmark.name);
        assert!(l.landmark.name.starts_with("virtual: "));
        assert!(
            c.template.positions.contains(&l.landmark.position),
            "{} is not a surface vertex",
            l.landmark.name
        );
    }
    // A scan with a hole over the head: the head-top ray finds no surface, the constructed
    // point is kept and flagged, and the warp still succeeds.
    let top = c
        .scan
        .positions
        .iter()
        .map(|p| p.z)
        .fold(f64::MIN, f64::max);
    let holed = Mesh::new(
        c.scan
            .positions
            .iter()
            .copied()
            .filter(|p| p.z < top - 40.0)
            .collect(),
        Vec::new(),
    );
    let v = virtual_landmarks_detailed(&c.scan_landmarks, &holed);
    let head = v
        .iter()
        .find(|l| l.landmark.name == "virtual: top of head")
        .unwrap();
    assert!(!head.on_surface);
    let w = rbf_warp_mesh(
        &c.template,
        &c.template_landmarks,
        &holed,
        &c.scan_landmarks,
        &RbfParams::default(),
    )
    .unwrap();
    assert_eq!(w.pairing.virtual_off_surface, ["virtual: top of head"]);
}
