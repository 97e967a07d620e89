//! The one layer that exposes the core to JavaScript (wasm32 only): flat typed arrays in and out,
//! errors as `JsError` with messages a person can act on. Validates at the boundary, trusts inside.
//!
//! Every array handed to JavaScript is a copy (`Float32Array::from(&[f32])`), never a view into
//! WASM memory, so a later allocation cannot invalidate it.
//!
//! * this file: `coreVersion`, `caesarLandmarkNames`, `parseScan` ([`ParsedScan`]: counts,
//!   positions, triangles, normals, summary), `parseLandmarks`, `pairSubjectFiles`;
//! * `template.rs`: `loadTemplate` ([`TemplateHandle`]);
//! * `align.rs`: `alignDefaults`, [`ScanWithLandmarks`], `rbfWarp`, `exportMesh`;
//! * `subject.rs`: [`SubjectScan`], `fitSubject`, `fitSubjectFiles`: the one path from a subject
//!   to a checked fit, as the command line takes it;
//! * `landmarks.rs`: `estimateLandmarks` ([`LandmarkEstimate`]), `checkLandmarks`;
//! * `landmark_export.rs`: `writeLandmarks` (`.lnd`, CSV or JSON);
//! * `model.rs`: `loadShapeModel` ([`ShapeSpace`]); `model_build.rs`: `buildShapeModel`;
//!   `statismo.rs`: [`StatismoArrays`], `loadStatismoModel`, `ShapeSpace.statismoArrays`;
//!   `anthropometry.rs`: `ShapeSpace.bodyFromMeasurementsJson`, `targetTolerancesJson`,
//!   `measurePopulation` ([`ModelPopulation`]: distributions, `boundaryManikinsJson`),
//!   `manikinDefaultsJson`.

mod align;
mod landmark_export;
mod landmarks;
mod subject;
mod template;

pub use align::{align_defaults, export_mesh, rbf_warp_js, AlignOutcome, ScanWithLandmarks};
pub use landmark_export::write_landmarks;
pub use landmarks::{check_landmarks_js, estimate_landmarks_js, LandmarkEstimate};
pub use subject::{fit_subject_files_js, fit_subject_js, SubjectScan};
pub use template::{load_template, TemplateHandle};

use js_sys::{Float32Array, Int8Array, Uint32Array};
use serde::Serialize;
use wasm_bindgen::prelude::*;

mod anthropometry;
mod model;
mod model_build;
mod statismo;

pub use anthropometry::{manikin_defaults_json, ModelPopulation};
pub use model::{load_shape_model, ShapeSpace};
pub use model_build::build_shape_model;
pub use statismo::{load_statismo_model, max_model_bytes, StatismoArrays};

use crate::io::subject_files::pair_subject_files;
use crate::io::{read_landmarks, read_scan};
use crate::landmarks::report::{report, LandmarkReport};
use crate::landmarks::CAESAR_LANDMARKS;
use crate::mesh::bounding_extent;
use crate::mesh::summary::{summarise, MeshSummary};
use crate::mesh::units::{detect_units, Units};
use crate::mesh::winding::turned_out;
use crate::mesh::Mesh;

/// The core's version, so the front end can show what it runs.
#[wasm_bindgen(js_name = coreVersion)]
pub fn core_version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// Traps the WebAssembly instance on purpose, exactly as a bug in the core would (a panic is an
/// `unreachable` trap in the browser): the app's crash-recovery test uses it to check that a
/// trapped worker is replaced and that the page keeps its state.
#[wasm_bindgen(js_name = trapForTest)]
pub fn trap_for_test() {
    panic!("deliberate trap (the crash-recovery test)");
}

/// The 73 canonical CAESAR landmark names in `.lnd` file order.
#[wasm_bindgen(js_name = caesarLandmarkNames)]
pub fn caesar_landmark_names() -> Vec<String> {
    CAESAR_LANDMARKS
        .iter()
        .map(|l| l.name.to_string())
        .collect()
}

/// A scan read by the core: `#V` positions in the file's units, `#F` triangles, `#V` unit vertex
/// normals and the mesh summary (counts, bounding box in metres, detected units, holes, parts).
#[wasm_bindgen]
pub struct ParsedScan {
    mesh: Mesh,
    /// `#V·3` unit vertex normals, xyz interleaved, of the triangles each turned to face out of
    /// the body where the summary knows it faces in ([`turned_out`]): a file whose triangles face
    /// both ways is shaded as one surface.
    normals: Vec<f32>,
    summary: MeshSummary,
}

#[wasm_bindgen]
impl ParsedScan {
    /// Number of vertices `#V`.
    #[wasm_bindgen(getter, js_name = vertexCount)]
    pub fn vertex_count(&self) -> u32 {
        self.mesh.vertex_count() as u32
    }

    /// Number of triangles `#F`.
    #[wasm_bindgen(getter, js_name = triangleCount)]
    pub fn triangle_count(&self) -> u32 {
        self.mesh.triangle_count() as u32
    }

    /// `#V·3` positions `[x0, y0, z0, x1, ...]` in the file's units (copied out).
    pub fn positions(&self) -> Float32Array {
        Float32Array::from(self.mesh.flat_positions_f32().as_slice())
    }

    /// `#F·3` vertex indices `[a0, b0, c0, a1, ...]` (copied out).
    pub fn triangles(&self) -> Uint32Array {
        Uint32Array::from(self.mesh.flat_triangles().as_slice())
    }

    /// `#V·3` unit vertex normals of the triangles turned to face out, xyz interleaved (copied out).
    pub fn normals(&self) -> Float32Array {
        Float32Array::from(self.normals.as_slice())
    }

    /// `#F` per triangle, which way its front faces: 1 out of the body, −1 into it, 0 not known
    /// ([`MeshSummary::triangle_facing`], copied out).
    #[wasm_bindgen(js_name = triangleFacing)]
    pub fn triangle_facing(&self) -> Int8Array {
        Int8Array::from(self.summary.triangle_facing.as_slice())
    }

    /// The [`MeshSummary`] as JSON (snake_case fields, bounding box in metres).
    #[wasm_bindgen(js_name = summaryJson)]
    pub fn summary_json(&self) -> Result<String, JsError> {
        serde_json::to_string(&self.summary).map_err(|e| JsError::new(&e.to_string()))
    }
}

/// Reads a scan (PLY, OBJ or STL, optionally gzip-compressed) and computes its normals and
/// summary. The error message is the core's, starting with `file_name`.
#[wasm_bindgen(js_name = parseScan)]
pub fn parse_scan(bytes: &[u8], file_name: &str) -> Result<ParsedScan, JsError> {
    let file_name = checked_file_name(file_name)?;
    let mesh = read_scan(bytes, file_name).map_err(|e| JsError::new(&e.to_string()))?;
    let summary = summarise(&mesh);
    // A file wound one way (no triangle faces in) is shaded as it is, without a copy.
    let normals = match turned_out(&mesh.triangles, &summary.triangle_facing) {
        Some(triangles) => Mesh::new(mesh.positions.clone(), triangles).flat_vertex_normals_f32(),
        None => mesh.flat_vertex_normals_f32(),
    };
    Ok(ParsedScan {
        mesh,
        normals,
        summary,
    })
}

/// What `parseLandmarks` returns (as JSON): landmarks in file order with their positions in the
/// file's units, and the report against the 73 CAESAR landmarks.
#[derive(Serialize)]
struct ParsedLandmarks {
    /// Canonical name of each present landmark (or the name as given when unknown).
    names: Vec<String>,
    /// `#L·3` positions, xyz interleaved, in the file's units.
    positions: Vec<f64>,
    /// Units the file format fixes (`"millimetres"` for CAESAR `.lnd`), else `null`: the
    /// landmarks then follow the scan's units.
    units: Option<&'static str>,
    /// The units the landmarks' own extent suggests (the scan rule of `mesh::units`), for a file
    /// opened without a scan.
    detected_units: Units,
    report: LandmarkReport,
}

/// Reads a landmark file (CSV, CAESAR `.lnd` or JSON; names mapped to canonical CAESAR names) and
/// returns it as JSON: `{names, positions, units, detected_units, report: {found, missing,
/// unknown}}`.
#[wasm_bindgen(js_name = parseLandmarks)]
pub fn parse_landmarks(bytes: &[u8], file_name: &str) -> Result<String, JsError> {
    let file_name = checked_file_name(file_name)?;
    let set = read_landmarks(bytes, file_name).map_err(|e| JsError::new(&e.to_string()))?;
    let parsed = ParsedLandmarks {
        names: set.landmarks.iter().map(|l| l.name.clone()).collect(),
        positions: set
            .landmarks
            .iter()
            .flat_map(|l| [l.position.x, l.position.y, l.position.z])
            .collect(),
        units: crate::io::landmark_file_units(file_name).map(Units::name),
        detected_units: detect_units(bounding_extent(
            &set.landmarks.iter().map(|l| l.position).collect::<Vec<_>>(),
        )),
        report: report(&set),
    };
    serde_json::to_string(&parsed).map_err(|e| JsError::new(&e.to_string()))
}

/// The subjects among files given together (a drop or a folder), by the batch's pairing rule
/// ([`crate::io::subject_files`]), as JSON: `{subjects: [{subject, scan, landmarks}],
/// duplicates: [{file, kept}], not_scans: [index], unpaired: [index]}`, every index into
/// `file_names` ([`crate::io::subject_files::SubjectPairing`]).
#[wasm_bindgen(js_name = pairSubjectFiles)]
pub fn pair_subject_files_js(file_names: Vec<String>) -> Result<String, JsError> {
    serde_json::to_string(&pair_subject_files(&file_names))
        .map_err(|e| JsError::new(&e.to_string()))
}

/// The file name as given, or an error naming the problem when it is blank.
fn checked_file_name(file_name: &str) -> Result<&str, JsError> {
    if file_name.trim().is_empty() {
        return Err(JsError::new(
            "a file name is needed to tell the format and to name the file in messages",
        ));
    }
    Ok(file_name)
}
