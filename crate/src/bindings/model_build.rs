//! `buildShapeModel`: a shape model built in the browser from the session's fits (aligned
//! subjects and dropped fitted meshes in template vertex order), held as a [`ShapeSpace`].

use nalgebra::Point3;
use wasm_bindgen::prelude::*;

use super::model::{js, ShapeSpace};
use crate::pca::{build_body_model, BuildParams, TrainingSet};
use crate::template::{Resolution, Template};

/// Builds a model from `count` fits in template vertex order (`positions` = count·#V·3, each fit
/// in its scan's frame and units: the core brings it into the template's), keeping modes up to
/// `variance` (0 < variance ≤ 1). `names_json` is a JSON array of names.
#[wasm_bindgen(js_name = buildShapeModel)]
pub fn build_shape_model(
    positions: &[f32],
    count: u32,
    names_json: &str,
    variance: f64,
    compute_quality: bool,
) -> Result<ShapeSpace, JsError> {
    let count = count as usize;
    if count < 2 {
        return Err(js("a shape model needs at least 2 aligned subjects"));
    }
    if !(variance > 0.0 && variance <= 1.0) {
        return Err(js("the variance to keep must be in (0, 1]"));
    }
    if positions.len() % (3 * count) != 0 {
        return Err(js("the subjects' positions do not split into equal bodies"));
    }
    let vertex_count = positions.len() / (3 * count);
    let base = Template::embedded().map_err(|e| js(format!("embedded template: {e}")))?;
    let template = if base.mesh().vertex_count() == vertex_count {
        base
    } else {
        let fine = base.at_resolution(Resolution::Fine);
        if fine.mesh().vertex_count() != vertex_count {
            return Err(js(format!(
                "{vertex_count} vertices per subject match no template resolution (base {}, fine {}); fitted meshes must be in template vertex order",
                base.mesh().vertex_count(),
                fine.mesh().vertex_count()
            )));
        }
        fine
    };
    let names: Vec<String> = serde_json::from_str(names_json)
        .map_err(|e| js(format!("subject names are not a JSON list: {e}")))?;
    if names.len() != count {
        return Err(js("one name per subject is needed"));
    }
    let shapes = positions
        .chunks_exact(3 * vertex_count)
        .map(|body| {
            body.chunks_exact(3)
                .map(|p| Point3::new(p[0] as f64, p[1] as f64, p[2] as f64))
                .collect()
        })
        .collect();
    let set = TrainingSet::on_template(&template, names, shapes);
    let params = BuildParams {
        variance,
        compute_quality,
        ..BuildParams::default()
    };
    let model = build_body_model(&set, &params).map_err(js)?;
    ShapeSpace::new(model, &template)
}
