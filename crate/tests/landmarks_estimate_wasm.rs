//! The WASM half of the native-vs-WASM agreement check of the landmark estimate, through the
//! bindings the worker calls (`loadTemplate`, `ScanWithLandmarks`, `estimateLandmarks`): the
//! same case and band as `landmarks_estimate_agreement.rs`, in a real browser
//! (scripts/test-wasm.sh); and `checkLandmarks`, the check of an edited set against the
//! estimate's prediction.
#![cfg(target_arch = "wasm32")]

mod estimate_agreement;

use bodyspace::bindings::{
    check_landmarks_js, estimate_landmarks_js, load_template, ScanWithLandmarks,
};
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
    let estimate = estimate_landmarks_js(&template, &scan, "", &on_progress).unwrap();
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

    // The 73 true landmarks with the acromions swapped, as after an edit: both flagged as
    // swapped, nothing else; the true set flags nothing.
    let check = |set: &[(String, [f64; 3])]| -> Vec<(String, String)> {
        let names: Vec<&str> = set.iter().map(|(n, _)| n.as_str()).collect();
        let positions: Vec<f64> = set.iter().flat_map(|(_, p)| *p).collect();
        let json = check_landmarks_js(
            &template,
            &names.join("\n"),
            &positions,
            &estimate.predicted().to_vec(),
            &estimate.parts().to_vec(),
        )
        .unwrap();
        let list: Vec<serde_json::Value> = serde_json::from_str(&json).unwrap();
        list.iter()
            .map(|f| {
                (
                    f["name"].as_str().unwrap().into(),
                    f["kind"].as_str().unwrap().into(),
                )
            })
            .collect()
    };
    let mut set: Vec<(String, [f64; 3])> = truth
        .landmarks
        .iter()
        .map(|l| (l.name.clone(), [l.position.x, l.position.y, l.position.z]))
        .collect();
    assert_eq!(check(&set), []);
    let at =
        |set: &[(String, [f64; 3])], name: &str| set.iter().position(|(n, _)| n == name).unwrap();
    let (rt, lt) = (at(&set, "Rt. Acromion"), at(&set, "Lt. Acromion"));
    let p = set[rt].1;
    set[rt].1 = set[lt].1;
    set[lt].1 = p;
    let mut flagged = check(&set);
    flagged.sort();
    assert_eq!(
        flagged,
        [
            ("Lt. Acromion".to_string(), "swapped".to_string()),
            ("Rt. Acromion".to_string(), "swapped".to_string())
        ]
    );
}
