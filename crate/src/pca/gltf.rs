//! The whole-body model as a binary glTF 2.0 (GLB) with its modes as morph targets, which
//! three.js (`GLTFLoader`, `mesh.morphTargetInfluences`) and Blender (shape keys) open as is.
//!
//! The base mesh is the mean S̄; morph target k is the displacement √λₖ·φₖ, so a morph weight
//! equals the slider value in standard deviations (weight 2 = +2σ). Target names are in
//! `mesh.extras.targetNames` (the convention three.js reads).

use super::model::BodyModel;
use serde_json::json;

const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;

fn bounds(xyz: &[f32]) -> (Vec<f32>, Vec<f32>) {
    let mut min = vec![f32::INFINITY; 3];
    let mut max = vec![f32::NEG_INFINITY; 3];
    for p in xyz.chunks_exact(3) {
        for a in 0..3 {
            min[a] = min[a].min(p[a]);
            max[a] = max[a].max(p[a]);
        }
    }
    if xyz.is_empty() {
        return (vec![0.0; 3], vec![0.0; 3]);
    }
    (min, max)
}

/// GLB bytes of the whole-body model with its first `modes` modes (all kept modes if larger).
pub fn model_glb(model: &BodyModel, modes: usize) -> Vec<u8> {
    let whole = &model.whole;
    let m = modes.min(whole.mode_count());
    let v = whole.vertex_count();
    let mut bin: Vec<u8> = Vec::new();
    let mut views = Vec::new();
    let mut accessors = Vec::new();
    let mut push_vec3 = |bin: &mut Vec<u8>, data: &[f32]| {
        let (min, max) = bounds(data);
        views.push(json!({"buffer": 0, "byteOffset": bin.len(), "byteLength": data.len() * 4, "target": ARRAY_BUFFER}));
        data.iter()
            .for_each(|x| bin.extend_from_slice(&x.to_le_bytes()));
        accessors.push(json!({"bufferView": views.len() - 1, "componentType": FLOAT, "count": v, "type": "VEC3", "min": min, "max": max}));
        accessors.len() - 1
    };
    let position = push_vec3(&mut bin, &whole.mean);
    let targets: Vec<serde_json::Value> = (0..m)
        .map(|k| {
            let sd = whole.variances[k].sqrt() as f32;
            let displacement: Vec<f32> = whole.mode(k).iter().map(|p| p * sd).collect();
            json!({"POSITION": push_vec3(&mut bin, &displacement)})
        })
        .collect();
    let index_offset = bin.len();
    model
        .triangles
        .iter()
        .flatten()
        .for_each(|i| bin.extend_from_slice(&i.to_le_bytes()));
    views.push(json!({"buffer": 0, "byteOffset": index_offset, "byteLength": bin.len() - index_offset, "target": ELEMENT_ARRAY_BUFFER}));
    accessors.push(json!({"bufferView": views.len() - 1, "componentType": UNSIGNED_INT, "count": 3 * model.triangles.len(), "type": "SCALAR"}));
    let indices = accessors.len() - 1;
    let names: Vec<String> = (1..=m).map(|k| format!("mode {k} (+1 sd)")).collect();
    let document = json!({
        "asset": {"version": "2.0", "generator": "BodySpace shape model"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "body"}],
        "meshes": [{
            "name": "body",
            "primitives": [{"attributes": {"POSITION": position}, "indices": indices, "targets": targets, "mode": 4}],
            "weights": vec![0.0; m],
            "extras": {"targetNames": names},
        }],
        "buffers": [{"byteLength": bin.len()}],
        "bufferViews": views,
        "accessors": accessors,
        "extras": {"template": model.template, "subjects": model.subjects.len(), "variances": whole.variances[..m].to_vec()},
    });
    let mut json_bytes = serde_json::to_vec(&document).unwrap_or_default();
    while json_bytes.len() % 4 != 0 {
        json_bytes.push(b' ');
    }
    while bin.len() % 4 != 0 {
        bin.push(0);
    }
    let total = 12 + 8 + json_bytes.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json_bytes.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json_bytes);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}
