//! `loadTemplate`: the generic template (paper §3) for the viewer and the align step — positions
//! in metres, triangles, normals, the 73 CAESAR + 12 virtual landmarks, segment blend weights and
//! region flags, all as flat typed arrays (copies).

use std::str::FromStr;

use js_sys::{Float32Array, Uint32Array, Uint8Array};
use wasm_bindgen::prelude::*;

use crate::landmarks::Landmark;
use crate::mesh::normals::NormalTopology;
use crate::rbf::virtual_landmarks;
use crate::template::{Resolution, Template};

/// The template at one resolution, kept in the worker so later calls need not rebuild it.
#[wasm_bindgen]
pub struct TemplateHandle {
    pub(super) template: Template,
    /// At `fine`: the base template, which coarse-to-fine alignment warps and fits first.
    pub(super) base: Option<Template>,
    /// `#V·3` unit vertex normals, xyz interleaved.
    normals: Vec<f32>,
    /// The template's triangles, for the normals of other positions ([`TemplateHandle::normals_of`]).
    topology: NormalTopology,
    /// The 12 virtual landmarks made by the RBF's own rule on the template surface (the same
    /// points `rbf_warp_mesh` pairs with the scan's), for display.
    virtual_landmarks: Vec<Landmark>,
}

/// The embedded template at `resolution` ("base" or "fine").
#[wasm_bindgen(js_name = loadTemplate)]
pub fn load_template(resolution: &str) -> Result<TemplateHandle, JsError> {
    let resolution = Resolution::from_str(resolution)
        .map_err(|e| JsError::new(&format!("template resolution {resolution:?}: {e}")))?;
    let template = Template::embedded()
        .map_err(|e| JsError::new(&format!("embedded template: {e}")))?
        .at_resolution(resolution);
    let virtual_landmarks = virtual_landmarks(&template.landmark_positions(), template.mesh());
    let normals = template.mesh().flat_vertex_normals_f32();
    let base = (template.resolution() != Resolution::Base)
        .then(|| template.at_resolution(Resolution::Base));
    let mesh = template.mesh();
    let topology = NormalTopology::new(&mesh.triangles, mesh.positions.len())
        .ok_or_else(|| JsError::new("embedded template: a triangle indexes no vertex"))?;
    Ok(TemplateHandle {
        template,
        base,
        normals,
        topology,
        virtual_landmarks,
    })
}

impl TemplateHandle {
    /// All 85 landmarks shown: the 73 CAESAR ones at their vertices, then the 12 virtual ones.
    fn all_landmarks(&self) -> Vec<Landmark> {
        let mut all = self.template.landmark_positions().landmarks;
        all.extend(self.virtual_landmarks.iter().cloned());
        all
    }
}

#[wasm_bindgen]
impl TemplateHandle {
    /// "base" or "fine".
    #[wasm_bindgen(getter)]
    pub fn resolution(&self) -> String {
        self.template.resolution().name().to_string()
    }

    #[wasm_bindgen(getter, js_name = vertexCount)]
    pub fn vertex_count(&self) -> u32 {
        self.template.mesh().positions.len() as u32
    }

    #[wasm_bindgen(getter, js_name = triangleCount)]
    pub fn triangle_count(&self) -> u32 {
        self.template.mesh().triangles.len() as u32
    }

    /// `#V·3` positions in metres (y up, feet on y = 0, facing +z).
    pub fn positions(&self) -> Float32Array {
        Float32Array::from(self.template.mesh().flat_positions_f32().as_slice())
    }

    /// `#F·3` vertex indices.
    pub fn triangles(&self) -> Uint32Array {
        Uint32Array::from(self.template.mesh().flat_triangles().as_slice())
    }

    /// `#V·3` unit vertex normals.
    pub fn normals(&self) -> Float32Array {
        Float32Array::from(self.normals.as_slice())
    }

    /// `#V·3` unit vertex normals of other `positions` (`#V·3`, e.g. an alignment's round) over
    /// the template's triangles (computed now, copied out): the worker's work, so the page only
    /// hands the arrays to the view.
    #[wasm_bindgen(js_name = normalsOf)]
    pub fn normals_of(&self, positions: &[f32]) -> Result<Float32Array, JsError> {
        normals_of(&self.topology, positions, "the template")
    }

    /// Landmark names, one per line: the 73 CAESAR names in `.lnd` order, then the 12 virtual.
    #[wasm_bindgen(js_name = landmarkNames)]
    pub fn landmark_names(&self) -> String {
        let names: Vec<String> = self.all_landmarks().into_iter().map(|l| l.name).collect();
        names.join("\n")
    }

    /// `#L·3` landmark positions in metres, in `landmarkNames` order.
    #[wasm_bindgen(js_name = landmarkPositions)]
    pub fn landmark_positions(&self) -> Float32Array {
        let flat: Vec<f32> = self
            .all_landmarks()
            .iter()
            .flat_map(|l| {
                [
                    l.position.x as f32,
                    l.position.y as f32,
                    l.position.z as f32,
                ]
            })
            .collect();
        Float32Array::from(flat.as_slice())
    }

    /// How many of the landmarks (the last ones) are virtual.
    #[wasm_bindgen(getter, js_name = virtualLandmarkCount)]
    pub fn virtual_landmark_count(&self) -> u32 {
        self.virtual_landmarks.len() as u32
    }

    /// `#V·6` segment blend weights (head, left arm, right arm, torso, left leg, right leg).
    #[wasm_bindgen(js_name = segmentWeights)]
    pub fn segment_weights(&self) -> Float32Array {
        let n = self.template.mesh().positions.len() as u32;
        let flat: Vec<f32> = (0..n)
            .flat_map(|v| self.template.segment_weights(v))
            .collect();
        Float32Array::from(flat.as_slice())
    }

    /// `#V` region flags: HAND = 1, EAR = 2, SOLE = 4, UNSEEN = 8.
    pub fn flags(&self) -> Uint8Array {
        let n = self.template.mesh().positions.len() as u32;
        let flat: Vec<u8> = (0..n).map(|v| self.template.flags(v).0).collect();
        Uint8Array::from(flat.as_slice())
    }
}

/// `#V·3` unit vertex normals of `positions` (`#V·3`) over `topology`'s triangles, copied out;
/// an error naming `mesh` (what the triangles belong to) when `positions` is not `#V·3` long.
pub(super) fn normals_of(
    topology: &NormalTopology,
    positions: &[f32],
    mesh: &str,
) -> Result<Float32Array, JsError> {
    let n = 3 * topology.vertex_count();
    if positions.len() != n {
        return Err(JsError::new(&format!(
            "positions hold {} values; {mesh} has {} vertices ({n} values)",
            positions.len(),
            n / 3
        )));
    }
    let mut out = vec![0.0f32; n];
    topology.vertex_normals_into(positions, &mut out);
    Ok(Float32Array::from(out.as_slice()))
}
