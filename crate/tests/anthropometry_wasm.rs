//! The anthropometry bindings in a real browser (`wasm-pack test --headless --chrome`) on the
//! demo model: a body from two targets meets them; targets in a segment's view take only that
//! segment's measurements; the population and two-measurement boundary manikins cross as JSON
//! with the core's CSV.
#![cfg(target_arch = "wasm32")]

use bodyspace::bindings::{load_shape_model, ShapeSpace};
use js_sys::Function;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

const DEMO: &[u8] = include_bytes!("../../public/models/demo.bsm");

fn json(s: Result<String, wasm_bindgen::JsError>) -> serde_json::Value {
    let text = s.unwrap_or_else(|_| panic!("the binding failed"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}"))
}

fn reading(space: &ShapeSpace, name: &str) -> f64 {
    let all = json(space.measure_json());
    all.as_array()
        .and_then(|a| a.iter().find(|r| r["name"] == name))
        .and_then(|r| r["value"].as_f64())
        .unwrap_or_else(|| panic!("no {name}"))
}

#[wasm_bindgen_test]
fn targets_population_and_manikins_cross_the_bindings() {
    let space = load_shape_model(DEMO, "demo.bsm").unwrap_or_else(|_| panic!("load"));
    let (stature, waist) = (reading(&space, "stature"), reading(&space, "waist_girth"));
    let targets = format!(
        r#"{{"stature": {}, "waist_girth": {}}}"#,
        stature + 0.04,
        waist - 0.03
    );
    let found = json(space.body_from_measurements_json(&targets, "whole"));
    assert_eq!(found["part"], "whole");
    assert_eq!(found["sigma"].as_array().map(Vec::len), Some(20));
    for a in found["achieved"].as_array().into_iter().flatten() {
        assert_eq!(a["met"], true, "{a}");
        let limit = if a["name"] == "stature" { 0.002 } else { 0.005 };
        let error = (a["achieved"].as_f64().unwrap_or(f64::NAN)
            - a["target"].as_f64().unwrap_or(0.0))
        .abs();
        assert!(error <= limit, "{a}");
    }
    assert!(space
        .body_from_measurements_json(r#"{"stature": -1}"#, "whole")
        .is_err());
    assert!(space
        .body_from_measurements_json(r#"{"tallness": 1.8}"#, "whole")
        .is_err());
    assert!(space
        .body_from_measurements_json(&targets, "torso")
        .is_err());
    let torso =
        json(space.body_from_measurements_json(
            &format!(r#"{{"waist_girth": {}}}"#, waist + 0.03),
            "torso",
        ));
    assert_eq!(torso["part"], "torso");
    assert_eq!(torso["achieved"][0]["met"], true);
    let targetable = json(space.targetable_json());
    assert_eq!(targetable["whole"].as_array().map(Vec::len), Some(20));
    assert!(targetable["torso"]
        .as_array()
        .is_some_and(|a| a.contains(&"waist_girth".into())));

    let population = space
        .measure_population(&Function::new_no_args(""))
        .unwrap_or_else(|_| panic!("population"));
    let d = json(population.json());
    assert_eq!(d["samples"]["bodies"], 300);
    assert_eq!(
        d["samples"]["correlation"].as_array().map(Vec::len),
        Some(20 * 20)
    );
    let set = json(population.boundary_manikins_json(
        &space,
        r#"["stature", "waist_girth"]"#,
        0.9,
        &Function::new_no_args(""),
    ));
    assert_eq!(
        set["manikins"]["manikins"].as_array().map(Vec::len),
        Some(8)
    );
    let csv = set["csv"].as_str().unwrap_or_default();
    assert_eq!(csv.lines().count(), 9);
    assert!(csv.starts_with("name,"));
    assert!(population
        .boundary_manikins_json(&space, r#"["stature"]"#, 0.9, &Function::new_no_args(""))
        .is_err());
}
