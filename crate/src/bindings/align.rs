//! `rbfWarp` and `alignScan`: the paper's two steps (§3.1 RBF warp, §3.2 fine alignment) on a
//! scan sent from the page. Everything crosses in metres; the scan and the landmarks are checked
//! here, then trusted by the core.

use std::ops::ControlFlow;

use js_sys::{Float32Array, Function};
use nalgebra::Point3;
use serde::{Deserialize, Serialize};
use serde_json::json;
use wasm_bindgen::prelude::*;

use super::template::TemplateHandle;
use crate::align::{
    coarse_to_fine_align, data_weights, fine_align_observed, AlignReport, CoarseToFineParams,
    DistanceStats, FineAlignParams, Progress, ScanIndex, Stage,
};
use crate::landmarks::{Landmark, LandmarkSet};
use crate::mesh::Mesh;
use crate::rbf::{rbf_warp_mesh, Kernel, RbfParams, RbfWarp};
use crate::template::Template;

/// RBF settings from the page (JSON): kernel name, its parameter (c or s, metres), λ, affine.
#[derive(Deserialize)]
struct RbfSettings {
    kernel: String,
    param: Option<f64>,
    lambda: f64,
    affine: bool,
}

/// Fine-alignment settings from the page (JSON); absent fields keep the core's defaults.
/// `max_iterations` limits the (base) fit; `fine_iterations` the fine stage of a `fine` template.
#[derive(Deserialize, Default)]
struct FineSettings {
    a: Option<f64>,
    b: Option<f64>,
    max_iterations: Option<usize>,
    fine_iterations: Option<usize>,
}

#[derive(Serialize)]
struct Residual<'a> {
    name: &'a str,
    before_mm: f64,
    after_mm: f64,
}

/// The template warped onto the scan: positions and normals (metres, scan frame, template
/// order) and the report as JSON.
#[wasm_bindgen]
pub struct WarpOutcome {
    positions: Vec<f32>,
    normals: Vec<f32>,
    report: String,
}

#[wasm_bindgen]
impl WarpOutcome {
    pub fn positions(&self) -> Float32Array {
        Float32Array::from(self.positions.as_slice())
    }
    pub fn normals(&self) -> Float32Array {
        Float32Array::from(self.normals.as_slice())
    }
    /// `{kernel, param, lambda, affine, used, skipped, virtual_off_surface, residuals:
    /// [{name, before_mm, after_mm}], similarity: {scale, rotation (3 rows), translation}, rcond}`.
    #[wasm_bindgen(js_name = reportJson)]
    pub fn report_json(&self) -> String {
        self.report.clone()
    }
}

/// Warps the template onto the scan by the landmarks (paper §3.1). `scan_positions` `#V·3`
/// metres, `scan_triangles` `#F·3`, `landmark_names` one per line, `landmark_positions` `#L·3`
/// metres, `settings` JSON `{kernel, param, lambda, affine}`.
#[wasm_bindgen(js_name = rbfWarp)]
pub fn rbf_warp_js(
    template: &TemplateHandle,
    scan_positions: &[f32],
    scan_triangles: &[u32],
    landmark_names: &str,
    landmark_positions: &[f64],
    settings: &str,
) -> Result<WarpOutcome, JsError> {
    let params = rbf_params(settings)?;
    let scan = scan_mesh(scan_positions, scan_triangles)?;
    let landmarks = scan_landmarks(landmark_names, landmark_positions)?;
    let warp = warp(&template.template, &scan, &landmarks, &params)?;
    let mesh = Mesh::new(
        warp.positions.clone(),
        template.template.mesh().triangles.clone(),
    );
    Ok(WarpOutcome {
        positions: mesh.flat_positions_f32(),
        normals: flat_normals(&mesh),
        report: warp_report(&warp, &params).to_string(),
    })
}

/// The fitted template: positions, normals, per-vertex distance to the scan (metres) and the
/// report as JSON.
#[wasm_bindgen]
pub struct AlignOutcome {
    positions: Vec<f32>,
    normals: Vec<f32>,
    distances: Vec<f32>,
    report: String,
}

#[wasm_bindgen]
impl AlignOutcome {
    pub fn positions(&self) -> Float32Array {
        Float32Array::from(self.positions.as_slice())
    }
    pub fn normals(&self) -> Float32Array {
        Float32Array::from(self.normals.as_slice())
    }
    /// `#V` distance (metres) of each fitted template vertex to the scan surface.
    pub fn distances(&self) -> Float32Array {
        Float32Array::from(self.distances.as_slice())
    }
    /// `{warp: <rbfWarp report>, rough_ms, index_ms, fine: {scan_to_template, template_to_scan
    /// (count, mean_mm, std_dev_mm, rms_mm, max_abs_mm), iterations, rounds, converged,
    /// cancelled, elapsed_ms}, total_ms}`.
    #[wasm_bindgen(js_name = reportJson)]
    pub fn report_json(&self) -> String {
        self.report.clone()
    }
}

/// RBF warp then fine alignment (paper §3.1 + §3.2). Same inputs as `rbfWarp`, plus fine
/// settings JSON `{a?, b?, max_iterations?, fine_iterations?}`, `on_progress(iteration, round, E,
/// E_d, E_s, rmsMetres, elapsedMs, stage, maxIterations)` after every L-BFGS iteration and
/// `on_round(round, positions)` with the current template positions (`Float32Array`, metres,
/// the handle's resolution) at the start of every round. A `fine` template is aligned coarse to
/// fine (the base template warped and fitted, carried to fine, fitted briefly there): `stage` is
/// "base" or "fine", and iterations count on across the two stages.
#[wasm_bindgen(js_name = alignScan)]
#[allow(clippy::too_many_arguments)]
pub fn align_scan(
    template: &TemplateHandle,
    scan_positions: &[f32],
    scan_triangles: &[u32],
    landmark_names: &str,
    landmark_positions: &[f64],
    rbf_settings: &str,
    fine_settings: &str,
    on_progress: &Function,
    on_round: &Function,
) -> Result<AlignOutcome, JsError> {
    let params = rbf_params(rbf_settings)?;
    let (fine, fine_iterations) = fine_params(fine_settings)?;
    let scan = scan_mesh(scan_positions, scan_triangles)?;
    let landmarks = scan_landmarks(landmark_names, landmark_positions)?;
    // Coarse to fine warps the base template; its vertices come first at fine.
    let warped = template.base.as_ref().unwrap_or(&template.template);
    let t0 = js_sys::Date::now();
    let warp = warp(warped, &scan, &landmarks, &params)?;
    let t1 = js_sys::Date::now();
    let index = ScanIndex::new(&scan).map_err(|e| JsError::new(&format!("scan: {e}")))?;
    let t2 = js_sys::Date::now();
    let triangles = &template.template.mesh().triangles;
    let weights = data_weights(&template.template);
    let c2f = CoarseToFineParams::around(&fine, fine_iterations);
    let max_iterations = match template.template.refinement() {
        Some(_) => c2f.max_iterations(),
        None => fine.max_iterations,
    };
    let mut progress = |stage: Stage, p: &Progress| {
        let args = js_sys::Array::of4(
            &JsValue::from(p.iteration as u32),
            &JsValue::from(p.round as u32),
            &JsValue::from(p.energy),
            &JsValue::from(p.data_error),
        );
        args.push(&JsValue::from(p.smoothness_error));
        args.push(&JsValue::from(p.rms));
        args.push(&JsValue::from(p.elapsed_ms));
        args.push(&JsValue::from(stage.name()));
        args.push(&JsValue::from(max_iterations as u32));
        match on_progress.apply(&JsValue::NULL, &args) {
            Ok(v) if v.is_falsy() && !v.is_undefined() => ControlFlow::Break(()),
            _ => ControlFlow::Continue(()),
        }
    };
    let mut round = |r: usize, positions: &[Point3<f64>]| {
        let flat: Vec<f32> = positions
            .iter()
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect();
        let _ = on_round.call2(
            &JsValue::NULL,
            &JsValue::from(r as u32),
            &Float32Array::from(flat.as_slice()),
        );
    };
    let (positions, fine_report_json, per_vertex_distance) = match template.template.refinement() {
        None => {
            let result = fine_align_observed(
                &warp.positions,
                triangles,
                &index,
                &weights,
                &fine,
                &mut |p| progress(Stage::Base, p),
                &mut round,
            )
            .map_err(|e| JsError::new(&format!("fine alignment: {e}")))?;
            let report = fine_report(&result.report);
            (result.positions, report, result.report.per_vertex_distance)
        }
        Some(refinement) => {
            let result = coarse_to_fine_align(
                &warp.positions,
                &warped.mesh().triangles,
                refinement,
                &index,
                &weights,
                &[],
                &c2f,
                &mut progress,
                &mut |_, r, positions| round(r, positions),
            )
            .map_err(|e| JsError::new(&format!("fine alignment: {e}")))?;
            let mut report = fine_report(&result.report);
            report["stages"] = json!({
                "base": fine_report(&result.base),
                "subdivide_ms": result.subdivide_ms,
                "fine_iterations": result.report.iterations - result.base.iterations,
                "fine_max_iterations": c2f.fine.max_iterations,
            });
            (result.positions, report, result.report.per_vertex_distance)
        }
    };
    let t3 = js_sys::Date::now();
    let mesh = Mesh::new(positions, triangles.clone());
    let report = json!({
        "warp": warp_report(&warp, &params),
        "rough_ms": t1 - t0,
        "index_ms": t2 - t1,
        "fine": fine_report_json,
        "total_ms": t3 - t0,
    });
    Ok(AlignOutcome {
        positions: mesh.flat_positions_f32(),
        normals: flat_normals(&mesh),
        distances: per_vertex_distance.iter().map(|d| *d as f32).collect(),
        report: report.to_string(),
    })
}

fn rbf_params(settings: &str) -> Result<RbfParams, JsError> {
    let s: RbfSettings =
        serde_json::from_str(settings).map_err(|e| JsError::new(&format!("RBF settings: {e}")))?;
    let kernel = Kernel::from_name(&s.kernel, s.param).ok_or_else(|| {
        JsError::new(&format!(
            "RBF kernel {:?}: unknown; use gaussian, thin-plate or multiquadric",
            s.kernel
        ))
    })?;
    kernel
        .validate()
        .map_err(|e| JsError::new(&format!("RBF kernel parameter: {e}")))?;
    if !(s.lambda.is_finite() && s.lambda >= 0.0) {
        return Err(JsError::new(&format!(
            "RBF λ = {}: must be a finite number ≥ 0",
            s.lambda
        )));
    }
    Ok(RbfParams {
        kernel,
        affine: s.affine,
        lambda: s.lambda,
        ..RbfParams::default()
    })
}

/// The (base) fit's parameters and the fine stage's iteration limit, if given.
fn fine_params(settings: &str) -> Result<(FineAlignParams, Option<usize>), JsError> {
    let s: FineSettings = serde_json::from_str(settings)
        .map_err(|e| JsError::new(&format!("alignment settings: {e}")))?;
    let defaults = FineAlignParams::default();
    let params = FineAlignParams {
        a: s.a.unwrap_or(defaults.a),
        b: s.b.unwrap_or(defaults.b),
        max_iterations: s.max_iterations.unwrap_or(defaults.max_iterations),
        ..defaults
    };
    params
        .validate()
        .map_err(|e| JsError::new(&e.to_string()))?;
    Ok((params, s.fine_iterations))
}

/// The scan as a mesh in metres, with its sizes and indices checked.
fn scan_mesh(positions: &[f32], triangles: &[u32]) -> Result<Mesh, JsError> {
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

fn scan_landmarks(names: &str, positions: &[f64]) -> Result<LandmarkSet, JsError> {
    let names: Vec<&str> = if names.is_empty() {
        Vec::new()
    } else {
        names.split('\n').collect()
    };
    if positions.len() != names.len() * 3 {
        return Err(JsError::new(&format!(
            "landmarks: {} names but {} coordinates (3 per landmark expected)",
            names.len(),
            positions.len()
        )));
    }
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

fn warp(
    template: &Template,
    scan: &Mesh,
    landmarks: &LandmarkSet,
    params: &RbfParams,
) -> Result<RbfWarp, JsError> {
    rbf_warp_mesh(
        template.mesh(),
        &template.landmark_positions(),
        scan,
        landmarks,
        params,
    )
    .map_err(|e| JsError::new(&format!("RBF warp: {e}")))
}

fn warp_report(warp: &RbfWarp, params: &RbfParams) -> serde_json::Value {
    let s = &warp.similarity;
    let rotation: Vec<[f64; 3]> = (0..3)
        .map(|r| [s.rotation[(r, 0)], s.rotation[(r, 1)], s.rotation[(r, 2)]])
        .collect();
    let residuals: Vec<Residual> = warp
        .residuals
        .iter()
        .map(|r| Residual {
            name: &r.name,
            before_mm: r.before * 1e3,
            after_mm: r.after * 1e3,
        })
        .collect();
    json!({
        "kernel": params.kernel.name(),
        "param": params.kernel.param(),
        "lambda": params.lambda,
        "affine": params.affine,
        "used": warp.used,
        "skipped": warp.skipped,
        "virtual_off_surface": warp.virtual_off_surface,
        "residuals": residuals,
        "similarity": {
            "scale": s.scale,
            "rotation": rotation,
            "translation": [s.translation.x, s.translation.y, s.translation.z],
        },
        "rcond": warp.network.rcond(),
    })
}

fn stats_mm(s: &DistanceStats) -> serde_json::Value {
    json!({
        "count": s.count,
        "mean_mm": s.mean * 1e3,
        "std_dev_mm": s.std_dev * 1e3,
        "rms_mm": s.rms * 1e3,
        "max_abs_mm": s.max_abs * 1e3,
    })
}

fn fine_report(r: &AlignReport) -> serde_json::Value {
    json!({
        "template_vertices": r.template_vertices,
        "scan_vertices": r.scan_vertices,
        "scan_to_template": stats_mm(&r.scan_to_template),
        "template_to_scan": stats_mm(&r.template_to_scan),
        "iterations": r.iterations,
        "rounds": r.rounds,
        "converged": r.converged,
        "cancelled": r.cancelled,
        "elapsed_ms": r.elapsed_ms,
    })
}

fn flat_normals(mesh: &Mesh) -> Vec<f32> {
    mesh.vertex_normals()
        .iter()
        .flat_map(|n| [n.x as f32, n.y as f32, n.z as f32])
        .collect()
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
