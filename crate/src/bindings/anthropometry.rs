//! Anthropometry for JavaScript on the loaded [`ShapeSpace`]: the body of the model that has
//! target measurements ([`crate::anthropometry::from_measurements`]) and the tolerances that say "met",
//! the measurement distributions of the model's population
//! ([`crate::anthropometry::measurement_distribution`], held as a [`ModelPopulation`]) and its boundary
//! manikins ([`crate::anthropometry::boundary_manikins`]).
//!
//! Targets cross as a JSON object `{name: value}` (names of `docs/measurements.md`, values in
//! m, m³, m²); results as JSON.

use std::collections::BTreeMap;

use js_sys::Function;
use serde::Serialize;
use wasm_bindgen::prelude::*;

use crate::anthropometry::boundary_manikins::{boundary_manikins, ManikinParams};
use crate::anthropometry::from_measurements::{body_from_measurements, FromMeasurementsParams};
use crate::anthropometry::measurement_distribution::{
    measurement_distribution, DistributionParams, MeasurementDistribution,
};
use crate::anthropometry::segment_targets::{segment_body_from_measurements, segment_measurements};
use crate::measure::Measure;
use crate::template::Segment;

use super::model::{js, ShapeSpace};

/// A body found for targets (JSON of `ShapeSpace::bodyFromMeasurementsJson`): σ-unit
/// coefficients of the part's model, each target's achieved value, iterations and ‖z‖.
#[derive(Serialize)]
struct Found<'a> {
    /// "whole" or the segment whose model the coefficients are of.
    part: &'a str,
    #[serde(flatten)]
    found: &'a crate::anthropometry::from_measurements::BodyFromMeasurements,
}

/// How close "met" is per kind (JSON of `ShapeSpace::targetTolerancesJson`), m / m³ / m².
#[derive(Serialize)]
struct Tolerances {
    length: f64,
    girth: f64,
    volume: f64,
    area: f64,
}

/// A JavaScript progress callback as the core takes it; a failing callback only loses a report.
fn reporter(on_progress: &Function) -> impl FnMut(f64) + '_ {
    move |f: f64| {
        let _ = on_progress.call1(&JsValue::NULL, &JsValue::from_f64(f));
    }
}

/// `{name: value}` → targets (sorted by name); unknown names and non-numbers are refused.
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
    /// The coefficients of `part`'s model meeting `targets_json` (`{name: value}`, m / m³ /
    /// m²) with the least Mahalanobis norm, as JSON `{part, sigma, achieved: [{name, target,
    /// achieved, met}], iterations, mahalanobis}`. `part` "whole": whole-body σ values, every
    /// segment following; a segment name: that segment model's σ values, on the stitched body
    /// with the rest of the body shown held ([`segment_body_from_measurements`]). Fails with
    /// the core's message on an empty target set, a non-positive value, an unknown name or a
    /// target that does not belong to the segment. The body shown is not touched.
    #[wasm_bindgen(js_name = bodyFromMeasurementsJson)]
    pub fn body_from_measurements_json(
        &self,
        targets_json: &str,
        part: &str,
    ) -> Result<String, JsError> {
        let targets = parse_targets(targets_json)?;
        let params = FromMeasurementsParams::default();
        let found = if part == "whole" {
            body_from_measurements(&self.model().whole, self.measurer(), &targets, &params)
        } else {
            let segment = Segment::from_name(part)
                .ok_or_else(|| js(format!("unknown part {part:?}: \"whole\" or a segment")))?;
            segment_body_from_measurements(
                self.model(),
                segment,
                self.shown_coefficients(),
                self.measurer(),
                &targets,
                &params,
            )
            .map(|s| s.found)
        }
        .map_err(js)?;
        serde_json::to_string(&Found {
            part,
            found: &found,
        })
        .map_err(js)
    }

    /// The measurements a target may name in each part's view, as JSON `{whole: [...], head:
    /// [...], ...}` (whole: all; a segment: those that act on its model,
    /// [`crate::anthropometry::segment_targets::measurement_segment`]).
    #[wasm_bindgen(js_name = targetableJson)]
    pub fn targetable_json(&self) -> Result<String, JsError> {
        let mut out = BTreeMap::new();
        out.insert(
            "whole",
            Measure::ALL
                .iter()
                .map(|m| m.definition().name)
                .collect::<Vec<_>>(),
        );
        for s in Segment::ALL {
            let names = segment_measurements(s)
                .iter()
                .map(|m| m.definition().name)
                .collect();
            out.insert(s.name(), names);
        }
        serde_json::to_string(&out).map_err(js)
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

/// The measurement distributions of one model, computed once ([`ShapeSpace::measure_population`])
/// and kept for its boundary manikins.
#[wasm_bindgen]
pub struct ModelPopulation {
    distribution: MeasurementDistribution,
}

#[wasm_bindgen]
impl ShapeSpace {
    /// Every measurement of the whole-body model over its training subjects and over bodies
    /// sampled from it (the core's default count and seed); `on_progress(fraction)` is called as
    /// bodies are measured.
    #[wasm_bindgen(js_name = measurePopulation)]
    pub fn measure_population(&self, on_progress: &Function) -> Result<ModelPopulation, JsError> {
        let distribution = measurement_distribution(
            &self.model().whole,
            self.measurer(),
            &DistributionParams::default(),
            &mut reporter(on_progress),
        )
        .map_err(js)?;
        Ok(ModelPopulation { distribution })
    }
}

#[wasm_bindgen]
impl ModelPopulation {
    /// The distributions as JSON `{params, training, samples}`, each population `{bodies,
    /// measures: [{name, kind, values (ascending), mean, sd, percentiles}], correlation
    /// (row-major)}`; NaN is `null`.
    pub fn json(&self) -> Result<String, JsError> {
        serde_json::to_string(&self.distribution).map_err(js)
    }

    /// The boundary manikins of `names_json` (a JSON list of 2–4 measurement names) at
    /// `coverage` (a share in (0, 1)) of the sampled bodies, on `space`'s model (the one this
    /// population was measured on), as JSON `{manikins: BoundaryManikins, csv}`;
    /// `on_progress(fraction)` after each manikin.
    #[wasm_bindgen(js_name = boundaryManikinsJson)]
    pub fn boundary_manikins_json(
        &self,
        space: &ShapeSpace,
        names_json: &str,
        coverage: f64,
        on_progress: &Function,
    ) -> Result<String, JsError> {
        let names: Vec<String> = serde_json::from_str(names_json)
            .map_err(|e| js(format!("measurements must be a JSON list of names: {e}")))?;
        let measures = names
            .iter()
            .map(|n| Measure::from_name(n).ok_or_else(|| js(format!("unknown measurement {n:?}"))))
            .collect::<Result<Vec<_>, _>>()?;
        let params = ManikinParams {
            coverage,
            ..ManikinParams::default()
        };
        let found = boundary_manikins(
            &space.model().whole,
            space.measurer(),
            &self.distribution.samples,
            &measures,
            &params,
            &FromMeasurementsParams::default(),
            &mut reporter(on_progress),
        )
        .map_err(js)?;
        let csv = found.to_csv();
        serde_json::to_string(&serde_json::json!({ "manikins": found, "csv": csv })).map_err(js)
    }
}

/// The defaults of boundary manikins as JSON `{coverage, ellipse_points}`.
#[wasm_bindgen(js_name = manikinDefaultsJson)]
pub fn manikin_defaults_json() -> Result<String, JsError> {
    serde_json::to_string(&ManikinParams::default()).map_err(js)
}

/// The percentile (0–100) of `value` among `sorted` (ascending): the core's
/// [`crate::anthropometry::measurement_distribution::percentile_of`], which the UI keeps in
/// TypeScript for speed (`web/shared/anthropometry.ts`); exported so that a test holds the two
/// to the same results.
#[wasm_bindgen(js_name = percentileOf)]
pub fn percentile_of(sorted: &[f64], value: f64) -> f64 {
    crate::anthropometry::measurement_distribution::percentile_of(sorted, value)
}
