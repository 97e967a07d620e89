//! Anthropometry for JavaScript on the loaded [`ShapeSpace`]: the body of the model that has
//! target measurements ([`crate::pca::from_measurements`]) and the tolerances that say "met".
//!
//! Targets cross as a JSON object `{name: value}` (names of `docs/measurements.md`, values in
//! m, m³, m²); results as JSON.

use std::collections::BTreeMap;

use serde::Serialize;
use wasm_bindgen::prelude::*;

use crate::measure::Measure;
use crate::pca::from_measurements::{body_from_measurements, FromMeasurementsParams};

use super::model::{js, ShapeSpace};

/// How close "met" is per kind (JSON of `ShapeSpace::targetTolerancesJson`), m / m³ / m².
#[derive(Serialize)]
struct Tolerances {
    length: f64,
    girth: f64,
    volume: f64,
    area: f64,
}

/// `{name: value}` → targets in the order given; unknown names and non-numbers are refused.
fn parse_targets(json: &str) -> Result<Vec<(Measure, f64)>, JsError> {
    let raw: BTreeMap<String, serde_json::Value> = serde_json::from_str(json).map_err(|e| {
        js(format!(
            "targets must be a JSON object {{name: value}}: {e}"
        ))
    })?;
    raw.into_iter()
        .map(|(name, value)| {
            let m = Measure::from_name(&name).ok_or_else(|| {
                let names: Vec<&str> = Measure::ALL.iter().map(|m| m.definition().name).collect();
                js(format!(
                    "unknown measurement {name:?} (one of {})",
                    names.join(", ")
                ))
            })?;
            let v = value
                .as_f64()
                .ok_or_else(|| js(format!("target {name}: {value} is not a number")))?;
            Ok((m, v))
        })
        .collect()
}

#[wasm_bindgen]
impl ShapeSpace {
    /// The whole-body σ coefficients meeting `targets_json` (`{name: value}`, m / m³ / m²) with
    /// the least Mahalanobis norm, as JSON `{sigma, achieved: [{name, target, achieved, met}],
    /// iterations, mahalanobis}`. Fails with the core's message on an empty target set, a
    /// non-positive value or an unknown name. The body shown is not touched.
    #[wasm_bindgen(js_name = bodyFromMeasurementsJson)]
    pub fn body_from_measurements_json(&self, targets_json: &str) -> Result<String, JsError> {
        let targets = parse_targets(targets_json)?;
        let found = body_from_measurements(
            &self.model().whole,
            self.measurer(),
            &targets,
            &FromMeasurementsParams::default(),
        )
        .map_err(js)?;
        serde_json::to_string(&found).map_err(js)
    }

    /// The tolerances within which a target counts as met (the core's defaults), as JSON
    /// `{length, girth, volume, area}`.
    #[wasm_bindgen(js_name = targetTolerancesJson)]
    pub fn target_tolerances_json(&self) -> Result<String, JsError> {
        let p = FromMeasurementsParams::default();
        serde_json::to_string(&Tolerances {
            length: p.length_tolerance,
            girth: p.girth_tolerance,
            volume: p.volume_tolerance,
            area: p.area_tolerance,
        })
        .map_err(js)
    }
}
