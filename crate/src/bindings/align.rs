//! `alignDefaults`, `ScanWithLandmarks`, `rbfWarp` and `exportMesh`: the core's defaults, the
//! RBF warp alone (paper §3.1, [`crate::align::align_scan`] with `rough_only`) on a scan sent from
//! the page — the whole path to a fit is `subject.rs` — and a fitted template written as PLY or
//! OBJ. Everything crosses in metres; the scan and the landmarks are checked once, when the
//! `ScanWithLandmarks` is made, then trusted by the core. Parameters cross as one JSON object of
//! the core's [`AlignParams`] (absent fields keep the core's defaults), progress as one object per
//! iteration (the core's [`Progress`]), reports as the core's [`crate::align::AlignmentReport`]
//! in JSON.

use std::ops::ControlFlow;

use js_sys::{Float32Array, Function};
use nalgebra::Point3;
use serde_json::json;
use wasm_bindgen::prelude::*;

use super::template::TemplateHandle;
use crate::align::{
    align_scan, assess, AlignInput, AlignObserver, AlignParams, Alignment, Progress,
    QualityThresholds, Stage,
};
use crate::landmarks::{Landmark, LandmarkSet};
use crate::mesh::units::Units;
use crate::mesh::Mesh;
use crate::rbf::Kernel;

/// The core's defaults as JSON: `{params: AlignParams, kernels: [Kernel with its default
/// parameter, one per kernel], subject: SubjectOptions}` — the one source of the app's default
/// settings (the landmark policy's `nearly_full` among them).
#[wasm_bindgen(js_name = alignDefaults)]
pub fn align_defaults() -> Result<String, JsError> {
    let kernels: Vec<Kernel> = ["thin-plate", "gaussian", "multiquadric"]
        .iter()
        .filter_map(|name| Kernel::from_name(name, None))
        .collect();
    serde_json::to_string(&json!({
        "params": AlignParams::default(),
        "kernels": kernels,
        "subject": crate::subject::SubjectOptions::default(),
    }))
    .map_err(|e| JsError::new(&e.to_string()))
}

/// A scan and its landmarks from the page, checked once at the boundary: `positions` `#V·3`
/// metres, `triangles` `#F·3`, `landmark_names` one per line, `landmark_positions` `#L·3` metres.
#[wasm_bindgen]
pub struct ScanWithLandmarks {
    pub(super) scan: Mesh,
    pub(super) landmarks: LandmarkSet,
}

#[wasm_bindgen]
impl ScanWithLandmarks {
    #[wasm_bindgen(constructor)]
    pub fn new(
        positions: &[f32],
        triangles: &[u32],
        landmark_names: &str,
        landmark_positions: &[f64],
    ) -> Result<ScanWithLandmarks, JsError> {
        Ok(Self {
            scan: scan_mesh(positions, triangles)?,
            landmarks: scan_landmarks(landmark_names, landmark_positions)?,
        })
    }
}

/// Warps the template onto the scan by the landmarks (paper §3.1); `params` JSON of
/// [`AlignParams`] (its `rbf` part is used).
#[wasm_bindgen(js_name = rbfWarp)]
pub fn rbf_warp_js(
    template: &TemplateHandle,
    scan: &ScanWithLandmarks,
    params: &str,
) -> Result<AlignOutcome, JsError> {
    let params = AlignParams {
        rough_only: true,
        ..align_params(params)?
    };
    let alignment = run(template, scan, &params, &mut ())?;
    outcome(template, alignment)
}

/// The fitted (or warped) template: positions, normals, per-vertex distance to the scan (metres;
/// empty after the warp alone), the core's report and its quality flags as JSON.
#[wasm_bindgen]
pub struct AlignOutcome {
    pub(super) positions: Vec<f32>,
    pub(super) normals: Vec<f32>,
    pub(super) distances: Vec<f32>,
    pub(super) report: String,
    pub(super) quality: String,
}

#[wasm_bindgen]
impl AlignOutcome {
    /// `#V·3` positions, metres, the scan's frame, template order.
    pub fn positions(&self) -> Float32Array {
        Float32Array::from(self.positions.as_slice())
    }
    /// `#V·3` unit vertex normals.
    pub fn normals(&self) -> Float32Array {
        Float32Array::from(self.normals.as_slice())
    }
    /// `#V` distance (metres) of each fitted template vertex to the scan surface.
    pub fn distances(&self) -> Float32Array {
        Float32Array::from(self.distances.as_slice())
    }
    /// The core's `AlignmentReport` as JSON (lengths in mm, times in ms).
    #[wasm_bindgen(js_name = reportJson)]
    pub fn report_json(&self) -> String {
        self.report.clone()
    }
    /// The core's `QualityReport` of the fit as JSON (measures, flags raised, the default
    /// thresholds of `align/quality.rs`); `null` after the warp alone.
    #[wasm_bindgen(js_name = qualityJson)]
    pub fn quality_json(&self) -> String {
        self.quality.clone()
    }
}

fn outcome(template: &TemplateHandle, alignment: Alignment) -> Result<AlignOutcome, JsError> {
    // Fold-overs are counted on the base template's triangles, which index the warped template
    // and the first vertices of a fit at either resolution (as `bodyspace batch` does).
    let quality = alignment.report.fine.is_some().then(|| {
        let base = template.base.as_ref().unwrap_or(&template.template);
        assess(&alignment, base, &QualityThresholds::default())
    });
    let json = |e: serde_json::Error| JsError::new(&e.to_string());
    let mesh = Mesh::new(
        alignment.positions,
        template.template.mesh().triangles.clone(),
    );
    Ok(AlignOutcome {
        positions: mesh.flat_positions_f32(),
        normals: mesh.flat_vertex_normals_f32(),
        distances: alignment
            .per_vertex_distance
            .iter()
            .map(|d| *d as f32)
            .collect(),
        report: serde_json::to_string(&alignment.report).map_err(json)?,
        quality: serde_json::to_string(&quality).map_err(json)?,
    })
}

/// The page's callbacks as the core's observer (`on_round` optional).
pub(super) struct JsObserver<'a> {
    pub(super) on_progress: &'a Function,
    pub(super) on_round: Option<&'a Function>,
}

impl AlignObserver for JsObserver<'_> {
    fn progress(&mut self, progress: &Progress) -> ControlFlow<()> {
        let object = serde_json::to_string(progress)
            .ok()
            .and_then(|text| js_sys::JSON::parse(&text).ok())
            .unwrap_or(JsValue::NULL);
        match self.on_progress.call1(&JsValue::NULL, &object) {
            Ok(v) if v.is_falsy() && !v.is_undefined() => ControlFlow::Break(()),
            _ => ControlFlow::Continue(()),
        }
    }

    fn round(&mut self, stage: Stage, round: usize, positions: &[Point3<f64>]) {
        let Some(on_round) = self.on_round else {
            return;
        };
        let flat: Vec<f32> = positions
            .iter()
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect();
        let _ = on_round.call3(
            &JsValue::NULL,
            &JsValue::from(stage.name()),
            &JsValue::from(round as u32),
            &Float32Array::from(flat.as_slice()),
        );
    }
}

/// The pipeline on the page's scan (metres) with the handle's template.
fn run(
    template: &TemplateHandle,
    scan: &ScanWithLandmarks,
    params: &AlignParams,
    observer: &mut dyn AlignObserver,
) -> Result<Alignment, JsError> {
    let input = AlignInput {
        template: &template.template,
        base_template: template.base.as_ref(),
        scan: &scan.scan,
        landmarks: &scan.landmarks,
        units: Some(Units::Metres),
    };
    align_scan(&input, params, observer).map_err(|e| JsError::new(&e.to_string()))
}

/// The page's parameters over the core's defaults.
fn align_params(json: &str) -> Result<AlignParams, JsError> {
    let params: AlignParams = serde_json::from_str(json)
        .map_err(|e| JsError::new(&format!("alignment settings: {e}")))?;
    params
        .validate()
        .map_err(|e| JsError::new(&e.to_string()))?;
    Ok(params)
}

/// The scan as a mesh in metres, with its sizes and indices checked.
pub(super) fn scan_mesh(positions: &[f32], triangles: &[u32]) -> Result<Mesh, JsError> {
    if positions.len() % 3 != 0 || triangles.len() % 3 != 0 {
        return Err(JsError::new(
            "scan: positions and triangles must hold whole xyz / abc triples",
        ));
    }
    let n = positions.len() / 3;
    if let Some(bad) = triangles.iter().find(|&&i| i as usize >= n) {
        return Err(JsError::new(&format!(
            "scan: a triangle refers to vertex {bad} but the scan has {n} vertices"
        )));
    }
    let points = positions
        .chunks_exact(3)
        .map(|c| Point3::new(c[0] as f64, c[1] as f64, c[2] as f64))
        .collect();
    let faces = triangles
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    Ok(Mesh::new(points, faces))
}

/// The landmark names of `names` (one per line, none for an empty string), checked against
/// `positions` (`#L·3`); the message starts with `what`.
pub(super) fn landmark_names<'a>(
    names: &'a str,
    positions: &[f64],
    what: &str,
) -> Result<Vec<&'a str>, String> {
    let names: Vec<&str> = if names.is_empty() {
        Vec::new()
    } else {
        names.split('\n').collect()
    };
    if positions.len() != names.len() * 3 {
        return Err(format!(
            "{what}: {} names but {} coordinates (3 per landmark expected)",
            names.len(),
            positions.len()
        ));
    }
    Ok(names)
}

pub(super) fn scan_landmarks(names: &str, positions: &[f64]) -> Result<LandmarkSet, JsError> {
    let names = landmark_names(names, positions, "landmarks").map_err(|e| JsError::new(&e))?;
    let landmarks = names
        .iter()
        .zip(positions.chunks_exact(3))
        .map(|(name, p)| Landmark {
            name: name.to_string(),
            position: Point3::new(p[0], p[1], p[2]),
        })
        .collect();
    Ok(LandmarkSet {
        landmarks,
        missing: Vec::new(),
        unknown: Vec::new(),
    })
}

/// The mesh as a file: `format` "ply" (binary little-endian) or "obj"; positions `#V·3`, as given.
#[wasm_bindgen(js_name = exportMesh)]
pub fn export_mesh(positions: &[f32], triangles: &[u32], format: &str) -> Result<Vec<u8>, JsError> {
    let mesh = scan_mesh(positions, triangles)?;
    match format {
        "ply" => Ok(crate::io::write_ply(&mesh)),
        "obj" => Ok(crate::io::write_obj(&mesh)),
        other => Err(JsError::new(&format!(
            "export format {other:?}: use ply or obj"
        ))),
    }
}
