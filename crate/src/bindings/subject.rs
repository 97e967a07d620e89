//! `SubjectScan`, `fitSubject` and `fitSubjectFiles`: the core's one path from a subject to a
//! checked fit ([`crate::subject`]: the units rule, the landmark policy, warp, fine alignment,
//! quality check, frame), the same path `bodyspace align` and `bodyspace batch` take. The app's
//! batch hands over the dropped files' bytes (`fitSubjectFiles`); the app's single scan hands
//! over the scan it shows and the landmarks of its editor (`SubjectScan`), with the estimate its
//! landmark worker already made. Options cross as one JSON object of the core's
//! [`SubjectOptions`] (absent fields keep the core's defaults), the report as the core's
//! [`crate::subject::SubjectReport`] in JSON.

use js_sys::Function;
use wasm_bindgen::prelude::*;

use super::align::{scan_landmarks, scan_mesh, AlignOutcome, JsObserver};
use super::template::TemplateHandle;
use crate::mesh::units::Units;
use crate::mesh::Mesh;
use crate::subject::{
    fit_subject, read_subject, GivenLandmarks, PriorEstimate, SubjectFit, SubjectInput,
    SubjectOptions,
};

/// A subject as the page holds it: the scan in metres under the units the person chose, and the
/// landmarks of the editor, in metres.
#[wasm_bindgen]
pub struct SubjectScan {
    input: SubjectInput,
    prior: Option<PriorEstimate>,
    to_m: f64,
}

#[wasm_bindgen]
impl SubjectScan {
    /// `positions` `#V·3` metres (the page's scan under `units`), `triangles` `#F·3`; `units` the
    /// scan's units ("metres", "centimetres" or "millimetres"); `detected`: whether they are the
    /// detected ones (so the report says so, as the command line's does).
    #[wasm_bindgen(constructor)]
    pub fn new(
        name: &str,
        positions: &[f32],
        triangles: &[u32],
        units: &str,
        detected: bool,
    ) -> Result<SubjectScan, JsError> {
        let units: Units =
            serde_json::from_value(serde_json::Value::from(units)).map_err(|_| {
                JsError::new(&format!(
                    "scan units {units:?}: metres, centimetres or millimetres"
                ))
            })?;
        let to_m = units.scale_to_metres();
        let metres = scan_mesh(positions, triangles)?;
        let scan = Mesh::new(
            metres.positions.iter().map(|p| p / to_m).collect(),
            metres.triangles,
        );
        Ok(Self {
            input: SubjectInput {
                name: name.to_string(),
                scan,
                units: (!detected).then_some(units),
                given: None,
            },
            prior: None,
            to_m,
        })
    }

    /// The landmarks a person gave or placed (`names` one per line, `positions` `#L·3` metres);
    /// `file` names the landmark file they came from (empty: placed by hand).
    #[wasm_bindgen(js_name = setGiven)]
    pub fn set_given(&mut self, names: &str, positions: &[f64], file: &str) -> Result<(), JsError> {
        let set = scan_landmarks(names, positions)?.scaled(1.0 / self.to_m);
        self.input.given = Some(GivenLandmarks {
            set,
            units: None,
            file: file.to_string(),
        });
        Ok(())
    }

    /// The estimate the landmark worker already made on this scan with the given landmarks
    /// (`names` one per line, `positions` `#L·3` metres; `report` its report's JSON): the policy
    /// fills in from it instead of estimating again.
    #[wasm_bindgen(js_name = setEstimate)]
    pub fn set_estimate(
        &mut self,
        names: &str,
        positions: &[f64],
        report: &str,
    ) -> Result<(), JsError> {
        let set = scan_landmarks(names, positions)?.scaled(1.0 / self.to_m);
        let report = serde_json::from_str(report)
            .map_err(|e| JsError::new(&format!("the estimate's report: {e}")))?;
        self.prior = Some(PriorEstimate { set, report });
        Ok(())
    }
}

/// The one path on the page's subject: `options` JSON of [`SubjectOptions`];
/// `on_progress(progress)` after every iteration (the core's `Progress`; returning `false`
/// cancels); `on_round(stage, round, positions)` at the start of every round (`Float32Array`,
/// metres, the handle's resolution).
#[wasm_bindgen(js_name = fitSubject)]
pub fn fit_subject_js(
    template: &TemplateHandle,
    subject: &SubjectScan,
    options: &str,
    on_progress: &Function,
    on_round: &Function,
) -> Result<AlignOutcome, JsError> {
    let options = subject_options(options)?;
    let fit = fit_subject(
        &template.template,
        template.base.as_ref(),
        &subject.input,
        subject.prior.clone(),
        &options,
        &mut JsObserver {
            on_progress,
            on_round: Some(on_round),
        },
    )
    .map_err(|e| JsError::new(&e.to_string()))?;
    outcome(template, fit)
}

/// The one path on a subject's files, as the batch hands them over: the scan's bytes and name, and
/// its landmark file's (or `undefined`). `options` and `on_progress` as for `fitSubject`.
#[wasm_bindgen(js_name = fitSubjectFiles)]
pub fn fit_subject_files_js(
    template: &TemplateHandle,
    scan: &[u8],
    scan_name: &str,
    landmarks: Option<Vec<u8>>,
    landmarks_name: Option<String>,
    options: &str,
    on_progress: &Function,
) -> Result<AlignOutcome, JsError> {
    let options = subject_options(options)?;
    let landmark_file = match (&landmarks, &landmarks_name) {
        (Some(bytes), Some(name)) => Some((bytes.as_slice(), name.as_str())),
        (None, _) => None,
        (Some(_), None) => return Err(JsError::new("a landmark file needs its name")),
    };
    let input = read_subject((scan, scan_name), landmark_file, None)
        .map_err(|e| JsError::new(&e.to_string()))?;
    let fit = fit_subject(
        &template.template,
        template.base.as_ref(),
        &input,
        None,
        &options,
        &mut JsObserver {
            on_progress,
            on_round: None,
        },
    )
    .map_err(|e| JsError::new(&e.to_string()))?;
    outcome(template, fit)
}

fn subject_options(json: &str) -> Result<SubjectOptions, JsError> {
    let options: SubjectOptions = serde_json::from_str(json)
        .map_err(|e| JsError::new(&format!("alignment settings: {e}")))?;
    options
        .params
        .validate()
        .map_err(|e| JsError::new(&e.to_string()))?;
    Ok(options)
}

/// The fit in metres in the scan's frame, for the page.
fn outcome(template: &TemplateHandle, fit: SubjectFit) -> Result<AlignOutcome, JsError> {
    let json = |e: serde_json::Error| JsError::new(&e.to_string());
    let mesh = Mesh::new(
        fit.alignment.positions,
        template.template.mesh().triangles.clone(),
    );
    Ok(AlignOutcome {
        positions: mesh.flat_positions_f32(),
        normals: mesh.flat_vertex_normals_f32(),
        distances: fit
            .alignment
            .per_vertex_distance
            .iter()
            .map(|d| *d as f32)
            .collect(),
        report: serde_json::to_string(&fit.report).map_err(json)?,
        quality: serde_json::to_string(&fit.report.quality).map_err(json)?,
    })
}
