//! `estimateLandmarks` and `checkLandmarks`: the core's landmark estimate
//! ([`crate::estimate::estimate_landmarks`]) on a scan sent from the page, which may
//! carry a partial or empty landmark set, and the check of an edited set against the last
//! estimate's prediction ([`crate::estimate::flag_given`], no fit). Everything crosses
//! in metres (the page scales the scan before making the `ScanWithLandmarks`); positions come
//! back in the same frame and units.

use js_sys::{Float64Array, Function, Uint32Array, Uint8Array};
use nalgebra::Point3;
use wasm_bindgen::prelude::*;

use super::align::{scan_landmarks, JsObserver, ScanWithLandmarks};
use super::template::TemplateHandle;
use crate::estimate::{
    estimate_landmarks, flag_given, given_landmarks, landmark_rest, EstimateInput, EstimateParams,
    LandmarkEstimate as Estimate, Orientation,
};
use crate::landmarks::CAESAR_LANDMARKS;
use crate::mesh::units::Units;
use crate::template::{Resolution, Template};

/// The 73 landmarks of a scan, CAESAR order.
#[wasm_bindgen]
pub struct LandmarkEstimate {
    positions: Vec<f64>,
    confidence: Vec<f64>,
    given: Vec<u8>,
    predicted: Vec<f64>,
    parts: Vec<u32>,
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
    /// `73·3` positions (metres, the scan's frame) where the landmark-free part fit puts each
    /// landmark: with [`LandmarkEstimate::parts`], what `checkLandmarks` checks an edited set
    /// against.
    pub fn predicted(&self) -> Float64Array {
        Float64Array::from(self.predicted.as_slice())
    }
    /// `73` part indices: the rigid part of the fit each landmark belongs to.
    pub fn parts(&self) -> Uint32Array {
        Uint32Array::from(self.parts.as_slice())
    }
    /// The core's `EstimateReport` as JSON: frame and units assumed, candidates, per-landmark
    /// confidence, flagged landmarks with distance (mm) and suggestion, times (ms).
    #[wasm_bindgen(js_name = reportJson)]
    pub fn report_json(&self) -> String {
        self.report.clone()
    }
}

/// Estimates the landmarks `scan` lacks (all of them for an empty set); the given ones are kept
/// as given. `orientation`: JSON of the core's `Orientation` (`{"up":"+z","facing":null}`) when a
/// person said which way is up, else empty. `on_progress(progress)` after every iteration with the core's `Progress` (stage
/// `"estimate"`; returning `false` cancels, and the call then fails with "cancelled").
#[wasm_bindgen(js_name = estimateLandmarks)]
pub fn estimate_landmarks_js(
    template: &TemplateHandle,
    scan: &ScanWithLandmarks,
    orientation: &str,
    on_progress: &Function,
) -> Result<LandmarkEstimate, JsError> {
    let orientation = if orientation.is_empty() {
        None
    } else {
        let o: Orientation = serde_json::from_str(orientation)
            .map_err(|e| JsError::new(&format!("orientation {orientation}: {e}")))?;
        o.validate().map_err(|e| JsError::new(&e))?;
        Some(o)
    };
    let estimate = run(&template.template, scan, orientation, on_progress)?;
    Ok(LandmarkEstimate {
        positions: estimate
            .positions
            .iter()
            .flat_map(|p| p.map_or([f64::NAN; 3], |p| [p.x, p.y, p.z]))
            .collect(),
        confidence: estimate.confidence.clone(),
        given: estimate.given.iter().map(|&g| g as u8).collect(),
        predicted: estimate
            .predicted
            .iter()
            .flat_map(|p| [p.x, p.y, p.z])
            .collect(),
        parts: estimate.part.iter().map(|&p| p as u32).collect(),
        report: serde_json::to_string(&estimate.report)
            .map_err(|e| JsError::new(&e.to_string()))?,
    })
}

/// The suspicious landmarks of a set the user placed or edited (`landmark_names` one per line,
/// `landmark_positions` `#L·3` metres), checked against the prediction of the last estimate on the
/// same scan (`predicted` `73·3` metres, `parts` `73`, from [`LandmarkEstimate`]): no fit, so it
/// can run after every edit. JSON: a list of `{name, distance_mm, kind, suggestion, expected}`
/// (`kind`: swapped, coordinate, other_landmark, far; `expected` in metres, the scan's frame).
/// `template` is the base template the estimate fitted.
#[wasm_bindgen(js_name = checkLandmarks)]
pub fn check_landmarks_js(
    template: &TemplateHandle,
    landmark_names: &str,
    landmark_positions: &[f64],
    predicted: &[f64],
    parts: &[u32],
) -> Result<String, JsError> {
    let n = CAESAR_LANDMARKS.len();
    if predicted.len() != 3 * n || parts.len() != n {
        return Err(JsError::new(&format!(
            "the prediction has {} values and {} parts; the estimate gives {} and {n}",
            predicted.len(),
            parts.len(),
            3 * n
        )));
    }
    if template.template.resolution() != Resolution::Base {
        return Err(JsError::new("checkLandmarks takes the base template"));
    }
    let set = scan_landmarks(landmark_names, landmark_positions)?;
    let predicted: Vec<Point3<f64>> = predicted
        .chunks_exact(3)
        .map(|p| Point3::new(p[0], p[1], p[2]))
        .collect();
    let parts: Vec<usize> = parts.iter().map(|&p| p as usize).collect();
    let flagged = flag_given(
        &landmark_rest(&template.template),
        &parts,
        &given_landmarks(&set),
        &predicted,
        &EstimateParams::default(),
        1.0,
    );
    serde_json::to_string(&flagged).map_err(|e| JsError::new(&e.to_string()))
}

fn run(
    template: &Template,
    scan: &ScanWithLandmarks,
    orientation: Option<Orientation>,
    on_progress: &Function,
) -> Result<Estimate, JsError> {
    let input = EstimateInput {
        template,
        scan: &scan.scan,
        given: &scan.landmarks,
        units: Some(Units::Metres),
        orientation,
    };
    let mut observer = JsObserver {
        on_progress,
        on_round: None,
    };
    estimate_landmarks(&input, &EstimateParams::default(), &mut observer)
        .map_err(|e| JsError::new(&e.to_string()))
}
