//! The WASM half of the native-vs-WASM agreement check of the landmark estimate, through the
//! bindings the worker calls (`loadTemplate`, `ScanWithLandmarks`, `estimateLandmarks`): the
//! same case and band as `landmarks_estimate_agreement.rs`, in a real browser
//! (scripts/test-wasm.sh).
#![cfg(target_arch = "wasm32")]

mod estimate_agreement;

use bodyspace::bindings::{estimate_landmarks_js, load_template, ScanWithLandmarks};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
fn the_estimate_in_the_browser_equals_the_native_one() {
    let (scan, truth, given) = estimate_agreement::agreement_case();
    let template = load_template("base").unwrap();
    let names: Vec<&str> = given.landmarks.iter().map(|l| l.name.as_str()).collect();
    let positions: Vec<f64> = given
        .landmarks
        .iter()
        .flat_map(|l| [l.position.x, l.position.y, l.position.z])
        .collect();
    let scan = ScanWithLandmarks::new(
        &scan.flat_positions_f32(),
        &scan.flat_triangles(),
        &names.join("\n"),
        &positions,
    )
    .unwrap();
    let on_progress = js_sys::Function::new_no_args("return true;");
    let estimate = estimate_landmarks_js(&template, &scan, &on_progress).unwrap();
    assert_eq!(estimate.names().len(), 73);
    let confidence = estimate.confidence().to_vec();
    assert!(confidence.iter().all(|c| (0.0..=1.0).contains(c)));
    let report: serde_json::Value = serde_json::from_str(&estimate.report_json()).unwrap();
    assert_eq!(report["frame"]["up_axis"], "+z");
    assert_eq!(report["frame"]["facing_axis"], "-y");
    estimate_agreement::check_agreement(
        &estimate.positions().to_vec(),
        &estimate.given().to_vec(),
        &truth,
    );
}
