//! Shape models as binary glTF 2.0 (GLB) with their modes as morph targets, which three.js
//! (`GLTFLoader`, `mesh.morphTargetInfluences`) and Blender (shape keys) open as is.
//!
//! Each model is one mesh: the base mesh is the mean S̄, morph target k is the displacement
//! √λₖ·φₖ, so a morph weight equals the slider value in standard deviations (weight 2 = +2σ).
//! Target names are in `mesh.extras.targetNames` (the convention three.js reads).
//!
//! * [`model_glb`]: the whole-body model alone (node and mesh `body`).
//! * [`parts_glb`]: all seven models in one file. Node `whole` holds the whole-body mesh at the
//!   origin; node `segments` holds one child node and mesh per segment (`head`, `left_arm`, …),
//!   each over its own vertices (the template vertices of the segment, ascending) and the
//!   triangles whose three vertices are all in the segment, so neighbouring segments overlap in
//!   their bands as the models do. The `segments` node is translated 1 m along +x so the
//!   two bodies stand side by side; vertex data are in the model frame (metres, y up).

use crate::io::glb_write::GlbWriter;
use crate::pca::model::BodyModel;
use crate::pca::segments::segment_triangles;
use crate::pca::shape_model::ShapeModel;
use crate::template::Segment;
use serde_json::{json, Value};

/// Offset of the `segments` node from the whole body in [`parts_glb`], metres along +x.
pub const SEGMENTS_OFFSET_M: f32 = 1.0;

/// GLB bytes of the whole-body model with its first `modes` modes (all kept modes if larger).
pub fn model_glb(model: &BodyModel, modes: usize) -> Vec<u8> {
    let mut glb = GlbWriter::new();
    let indices: Vec<u32> = model.triangles.iter().flatten().copied().collect();
    let (mesh, variances) = part_mesh(&mut glb, "body", &model.whole, &indices, modes);
    glb.finish(json!({
        "asset": {"version": "2.0", "generator": "BodySpace shape model"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "body"}],
        "meshes": [mesh],
        "extras": {"template": model.template, "subjects": model.subjects.len(), "variances": variances},
    }))
}

/// GLB bytes of the whole-body model and the six segment models, each with its first `modes`
/// modes (all kept modes if larger); layout in the module docs.
pub fn parts_glb(model: &BodyModel, modes: usize) -> Vec<u8> {
    let mut glb = GlbWriter::new();
    let whole_indices: Vec<u32> = model.triangles.iter().flatten().copied().collect();
    let (whole, whole_variances) =
        part_mesh(&mut glb, "whole", &model.whole, &whole_indices, modes);
    let mut meshes = vec![whole];
    let mut parts = vec![
        json!({"name": "whole", "vertices": model.whole.vertex_count(), "variances": whole_variances}),
    ];
    for s in Segment::ALL {
        let part = model.segment(s);
        let indices = segment_triangles(
            &model.triangles,
            &part.vertex_indices,
            model.template.vertex_count,
        );
        let (mesh, variances) = part_mesh(&mut glb, s.name(), part, &indices, modes);
        meshes.push(mesh);
        parts.push(
            json!({"name": s.name(), "vertices": part.vertex_count(), "variances": variances}),
        );
    }
    // Node 0: whole; node 1: segments (children 2..8 = meshes 1..7).
    let mut nodes = vec![
        json!({"name": "whole", "mesh": 0}),
        json!({"name": "segments", "translation": [SEGMENTS_OFFSET_M, 0.0, 0.0], "children": (2..2 + Segment::ALL.len()).collect::<Vec<_>>()}),
    ];
    for (i, s) in Segment::ALL.iter().enumerate() {
        nodes.push(json!({"name": s.name(), "mesh": i + 1}));
    }
    glb.finish(json!({
        "asset": {"version": "2.0", "generator": "BodySpace shape model (whole body and six segments)"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": nodes,
        "meshes": meshes,
        "extras": {"template": model.template, "subjects": model.subjects.len(), "parts": parts},
    }))
}

/// One model as a glTF mesh named `name`: mean as POSITION, √λₖ·φₖ as morph targets for the
/// first `modes` modes, `indices` into the model's own vertices. Returns the mesh and the
/// variances of the exported modes.
fn part_mesh(
    glb: &mut GlbWriter,
    name: &str,
    part: &ShapeModel,
    indices: &[u32],
    modes: usize,
) -> (Value, Vec<f64>) {
    let m = modes.min(part.mode_count());
    let position = glb.vec3(&part.mean);
    let targets: Vec<Value> = (0..m)
        .map(|k| {
            let sd = part.variances[k].sqrt() as f32;
            let displacement: Vec<f32> = part.mode(k).iter().map(|p| p * sd).collect();
            json!({"POSITION": glb.vec3(&displacement)})
        })
        .collect();
    let indices = glb.indices(indices);
    let names: Vec<String> = (1..=m).map(|k| format!("mode {k} (+1 sd)")).collect();
    let mesh = json!({
        "name": name,
        "primitives": [{"attributes": {"POSITION": position}, "indices": indices, "targets": targets, "mode": 4}],
        "weights": vec![0.0; m],
        "extras": {"targetNames": names},
    });
    (mesh, part.variances[..m].to_vec())
}
