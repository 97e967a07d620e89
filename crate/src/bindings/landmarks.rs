//! `estimateLandmarks` and `flagSuspicious`: the core's landmark estimate
//! ([`crate::landmarks::estimate::estimate_landmarks`]) on a scan sent from the page, which may
//! carry a partial or empty landmark set. Everything crosses in metres (the page scales the scan
//! before making the `ScanWithLandmarks`); positions come back in the same frame and units.

use js_sys::{Float64Array, Function, Uint8Array};
use wasm_bindgen::prelude::*;

use super::align::{JsObserver, ScanWithLandmarks};
use super::template::TemplateHandle;
use crate::landmarks::estimate::{
    estimate_landmarks, EstimateInput, EstimateParams, LandmarkEstimate as Estimate,
};
use crate::landmarks::CAESAR_LANDMARKS;
use crate::mesh::units::Units;
use crate::template::Template;

/// The 73 landmarks of a scan, CAESAR order.
#[wasm_bindgen]
pub struct LandmarkEstimate {
    positions: Vec<f64>,
    confidence: Vec<f64>,
    given: Vec<u8>,
    report: String,
}

#[wasm_bindgen]
impl LandmarkEstimate {
    /// The 73 canonical CAESAR names, `.lnd` file order.
    pub fn names(&self) -> Vec<String> {
        CAESAR_LANDMARKS
            .iter()
            .map(|l| l.name.to_string())
            .collect()
    }
    /// `73·3` positions (metres, the scan's frame); NaN for a landmark that could not be placed.
    pub fn positions(&self) -> Float64Array {
        Float64Array::from(self.positions.as_slice())
    }
    /// `73` confidences in 0..1 (1 for a given landmark).
    pub fn confidence(&self) -> Float64Array {
        Float64Array::from(self.confidence.as_slice())
    }
    /// `73` flags: 1 = taken from the given set, never moved.
    pub fn given(&self) -> Uint8Array {
        Uint8Array::from(self.given.as_slice())
    }
    /// The core's `EstimateReport` as JSON: frame and units assumed, candidates, per-landmark
    /// confidence, flagged landmarks with distance (mm) and suggestion, times (ms).
    #[wasm_bindgen(js_name = reportJson)]
    pub fn report_json(&self) -> String {
        self.report.clone()
    }
}

/// Estimates the landmarks `scan` lacks (all of them for an empty set); the given ones are kept
/// as given. `on_progress(progress)` after every iteration with the core's `Progress` (stage
/// `"estimate"`; returning `false` cancels, and the call then fails with "cancelled").
#[wasm_bindgen(js_name = estimateLandmarks)]
pub fn estimate_landmarks_js(
    template: &TemplateHandle,
    scan: &ScanWithLandmarks,
    on_progress: &Function,
) -> Result<LandmarkEstimate, JsError> {
    let estimate = run(&template.template, scan, Some(on_progress))?;
    Ok(LandmarkEstimate {
        positions: estimate
            .positions
            .iter()
            .flat_map(|p| p.map_or([f64::NAN; 3], |p| [p.x, p.y, p.z]))
            .collect(),
        confidence: estimate.confidence.clone(),
        given: estimate.given.iter().map(|&g| g as u8).collect(),
        report: serde_json::to_string(&estimate.report)
            .map_err(|e| JsError::new(&e.to_string()))?,
    })
}

/// The suspicious landmarks of a set the user placed or edited, as JSON: a list of
/// `{name, distance_mm, kind, suggestion, expected}` (`kind`: swapped, coordinate,
/// other_landmark, far; `expected` in metres, the scan's frame). Fits the embedded base
/// template to the scan without the landmarks and compares.
#[wasm_bindgen(js_name = flagSuspicious)]
pub fn flag_suspicious_js(scan: &ScanWithLandmarks) -> Result<String, JsError> {
    let template =
        Template::embedded().map_err(|e| JsError::new(&format!("embedded template: {e}")))?;
    let estimate = run(&template, scan, None)?;
    serde_json::to_string(&estimate.report.flagged).map_err(|e| JsError::new(&e.to_string()))
}

fn run(
    template: &Template,
    scan: &ScanWithLandmarks,
    on_progress: Option<&Function>,
) -> Result<Estimate, JsError> {
    let input = EstimateInput {
        template,
        scan: &scan.scan,
        given: &scan.landmarks,
        units: Some(Units::Metres),
    };
    let params = EstimateParams::default();
    let result = match on_progress {
        Some(on_progress) => estimate_landmarks(
            &input,
            &params,
            &mut JsObserver {
                on_progress,
                on_round: None,
            },
        ),
        None => estimate_landmarks(&input, &params, &mut ()),
    };
    result.map_err(|e| JsError::new(&e.to_string()))
}
