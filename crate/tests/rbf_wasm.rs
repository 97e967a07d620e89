//! The RBF core in a real browser (`wasm-pack test --headless --chrome`): the same checks and
//! tolerances as the native tests rbf_fit.rs / rbf_warp.rs, so the WASM build is held to the
//! same numbers (its warp loop takes the portable path, without AVX2/FMA or threads).
#![cfg(target_arch = "wasm32")]

mod rbf_support;

use bodyspace::landmarks::{Landmark, LandmarkSet};
use bodyspace::mesh::Mesh;
use bodyspace::rbf::{fit, rbf_warp_mesh, similarity, Kernel, RbfParams};
use nalgebra::{Matrix3, Point3, Vector3};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
fn interpolation_and_affine_reproduction_hold_in_wasm() {
    let body = rbf_support::body(8);
    let set = rbf_support::landmarks(&body);
    let names: Vec<String> = set.landmarks.iter().map(|l| l.name.clone()).collect();
    let p: Vec<_> = set.landmarks.iter().map(|l| l.position).collect();
    let q: Vec<_> = p.iter().map(rbf_support::subject_shape).collect();
    let a = Matrix3::new(1.1, 0.2, -0.1, 0.05, 0.9, 0.3, -0.2, 0.1, 1.3);
    let b = Vector3::new(0.4, -1.2, 2.0);
    let affine: Vec<_> = p.iter().map(|x| Point3::from(a * x.coords + b)).collect();
    for kernel in [
        Kernel::ThinPlate,
        Kernel::Multiquadric { s: 0.01 },
        Kernel::Gaussian { c: 0.2 },
    ] {
        let params = RbfParams {
            kernel,
            ..RbfParams::default()
        };
        let net = fit(&names, &p, &q, &params).unwrap();
        let warped = net.warp(&p);
        for (w, qi) in warped.iter().zip(&q) {
            assert!((w - qi).norm() < 1e-8 * 1.8, "{kernel:?}");
        }
        let net = fit(&names, &p, &affine, &params).unwrap();
        for x in &body.positions {
            let err = (net.evaluate(x) - Point3::from(a * x.coords + b)).norm();
            assert!(err < 1e-9, "{kernel:?}: {err}");
        }
    }
}

#[wasm_bindgen_test]
fn rbf_warp_follows_the_subject_in_wasm() {
    let template = rbf_support::body(10);
    let template_landmarks = rbf_support::landmarks(&template);
    let scan = Mesh::new(
        template
            .positions
            .iter()
            .map(rbf_support::subject)
            .collect(),
        template.triangles.clone(),
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
    let p: Vec<_> = template_landmarks
        .landmarks
        .iter()
        .map(|l| l.position)
        .collect();
    let s = similarity(
        &p,
        &p.iter().map(rbf_support::to_scan_frame).collect::<Vec<_>>(),
    )
    .unwrap();
    assert!((s.scale - 1000.0).abs() < 1e-9);
    let w = rbf_warp_mesh(
        &template,
        &template_landmarks,
        &scan,
        &scan_landmarks,
        &RbfParams::default(),
    )
    .unwrap();
    assert_eq!(w.pairing.used.len(), 85);
    assert!(w.residuals.iter().all(|r| r.after < 1e-8 * 1908.0));
    let mean = w
        .positions
        .iter()
        .zip(&scan.positions)
        .map(|(a, b)| (a - b).norm())
        .sum::<f64>()
        / scan.positions.len() as f64;
    assert!(mean < 8.0, "mean vertex error {mean} mm");
}
