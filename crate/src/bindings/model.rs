//! Shape models for JavaScript: load a model file (`model_build.rs` builds one from fits), morph
//! the stitched body shown as sliders move, give its vertex normals, measure it, and export CSV /
//! GLB / the model file.
//!
//! A [`ShapeSpace`] lives in the worker for as long as the model is shown. It holds the loaded
//! model, optionally that model mapped to the template's `fine` resolution
//! ([`crate::pca::subdivide`]), and a [`Morph`] — the current coefficients and stitched body of
//! whichever of the two is shown — so a slider move is one rank-1 update. Every array handed
//! out is a copy of WASM memory.

use js_sys::{Float32Array, Function, Uint32Array, Uint8Array};
use serde::Serialize;
use wasm_bindgen::prelude::*;

use crate::measure::{BodyMeasurer, MeasureParams};
use crate::mesh::normals::NormalTopology;
use crate::model_file::export::{eigenvalues_csv, quality_csv, scores_csv};
use crate::model_file::file::{read_model, read_model_for, write_model, BasisPrecision};
use crate::model_file::gltf::{model_glb, parts_glb};
use crate::pca::subdivide::{subdivide_model, FineTemplate};
use crate::pca::{
    BodyModel, BuildParams, Coefficients, Morph, QualityCurves, SeamReport, ShapeModel,
    TemplateIdentity,
};
use crate::template::{Resolution, Segment, Template};

use super::template::{normals_of, TemplateHandle};

pub(super) fn js(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

/// The checked triangles of `model` for its vertex normals.
fn topology_of(model: &BodyModel) -> Result<NormalTopology, JsError> {
    NormalTopology::new(&model.triangles, model.template.vertex_count)
        .ok_or_else(|| js("a triangle of the model indexes a vertex beyond its template"))
}

pub(super) fn template_at(resolution: Resolution) -> Result<Template, JsError> {
    let base = Template::embedded().map_err(|e| js(format!("embedded template: {e}")))?;
    Ok(if resolution == Resolution::Base {
        base
    } else {
        base.at_resolution(resolution)
    })
}

/// One part's facts for charts and sliders (JSON of `ShapeSpace::info_json`).
#[derive(Serialize)]
struct PartInfo<'a> {
    name: &'a str,
    vertex_count: usize,
    /// Kept modes' variances λₖ (m²).
    variances: &'a [f64],
    /// All non-zero variances, for the explained fraction.
    all_variances: &'a [f64],
    quality: &'a QualityCurves,
}

fn part<'a>(name: &'a str, m: &'a ShapeModel) -> PartInfo<'a> {
    PartInfo {
        name,
        vertex_count: m.vertex_count(),
        variances: &m.variances,
        all_variances: &m.all_variances,
        quality: &m.quality,
    }
}

#[derive(Serialize)]
struct ModelInfo<'a> {
    template: &'a TemplateIdentity,
    settings: &'a BuildParams,
    subjects: &'a [String],
    triangle_count: usize,
    /// Whole body first, then the six segments in `Segment::ALL` order.
    parts: Vec<PartInfo<'a>>,
}

/// A loaded shape model, the body it shows and the template data its measurements need.
#[wasm_bindgen]
pub struct ShapeSpace {
    /// The model as loaded or built (files, CSV, GLB, seam report and measurements use it).
    model: BodyModel,
    /// `model` mapped to the fine template, once asked for.
    fine: Option<BodyModel>,
    /// Whether the body is shown (morphed) at fine.
    at_fine: bool,
    /// The shown body's coefficients and positions, on `fine` when `at_fine`, else on `model`.
    morph: Morph,
    /// Measures the body on the base template's vertices (the first ones at every resolution).
    measurer: BodyMeasurer,
    /// Triangles of the body shown, checked once, and its normals.
    topology: NormalTopology,
    normals: Vec<f32>,
}

impl ShapeSpace {
    pub(super) fn new(model: BodyModel, template: &Template) -> Result<ShapeSpace, JsError> {
        let embedded_base;
        let base = if template.resolution() == Resolution::Base {
            template
        } else {
            embedded_base = template_at(Resolution::Base)?;
            &embedded_base
        };
        let measurer = BodyMeasurer::of_template(base, MeasureParams::default()).map_err(js)?;
        let morph = Morph::new(&model, &Coefficients::default()).map_err(js)?;
        let topology = topology_of(&model)?;
        Ok(ShapeSpace {
            model,
            fine: None,
            at_fine: false,
            morph,
            measurer,
            topology,
            normals: Vec::new(),
        })
    }

    /// The model as loaded or built.
    pub(super) fn model(&self) -> &BodyModel {
        &self.model
    }

    /// The coefficients of the body shown (model units).
    pub(super) fn shown_coefficients(&self) -> &Coefficients {
        self.morph.coefficients()
    }

    /// Measures bodies of the model on the base template's vertices.
    pub(super) fn measurer(&self) -> &BodyMeasurer {
        &self.measurer
    }

    /// The model whose body is shown.
    fn shown(&self) -> &BodyModel {
        match (&self.fine, self.at_fine) {
            (Some(fine), true) => fine,
            _ => &self.model,
        }
    }

    /// σ-unit values to model coefficients; `segment_counts[s] < 0` means "not overridden".
    fn coefficients(
        &self,
        whole_sigma: &[f64],
        segment_sigma: &[f64],
        segment_counts: &[i32],
    ) -> Result<Coefficients, JsError> {
        if segment_counts.len() != 6 {
            return Err(js("segment_counts must hold one entry per segment (6)"));
        }
        if whole_sigma
            .iter()
            .chain(segment_sigma)
            .any(|x| !x.is_finite())
        {
            return Err(js("coefficients must be finite numbers"));
        }
        let mut c = Coefficients {
            whole: self
                .model
                .whole
                .coefficients_from_sigma(whole_sigma)
                .map_err(|e| js(format!("whole body: {e}")))?,
            ..Coefficients::default()
        };
        let mut at = 0usize;
        for (s, &n) in Segment::ALL.iter().zip(segment_counts) {
            if n < 0 {
                continue;
            }
            let n = n as usize;
            let values = segment_sigma
                .get(at..at + n)
                .ok_or_else(|| js("segment coefficients are shorter than their counts say"))?;
            at += n;
            c.segments[s.index()] = Some(
                self.model
                    .segment(*s)
                    .coefficients_from_sigma(values)
                    .map_err(|e| js(format!("segment {}: {e}", s.name())))?,
            );
        }
        Ok(c)
    }
}

#[wasm_bindgen]
impl ShapeSpace {
    /// Vertex count `#V` of the body shown (the model's resolution, or fine).
    #[wasm_bindgen(getter, js_name = vertexCount)]
    pub fn vertex_count(&self) -> u32 {
        self.shown().template.vertex_count as u32
    }

    /// Resolution of the body shown: the model's own (`base`, `fine`) or `fine` once mapped.
    #[wasm_bindgen(getter)]
    pub fn resolution(&self) -> String {
        self.shown().template.resolution.clone()
    }

    /// `#F·3` triangle vertex indices of the body shown (copied out).
    pub fn triangles(&self) -> Uint32Array {
        let flat: Vec<u32> = self.shown().triangles.iter().flatten().copied().collect();
        Uint32Array::from(flat.as_slice())
    }

    /// Template identity, settings, subjects and per-part variances and quality curves of the
    /// loaded model, as JSON.
    #[wasm_bindgen(js_name = infoJson)]
    pub fn info_json(&self) -> Result<String, JsError> {
        let mut parts = vec![part("whole", &self.model.whole)];
        for s in Segment::ALL {
            parts.push(part(s.name(), self.model.segment(s)));
        }
        let info = ModelInfo {
            template: &self.model.template,
            settings: &self.model.settings,
            subjects: &self.model.subjects,
            triangle_count: self.model.triangles.len(),
            parts,
        };
        serde_json::to_string(&info).map_err(js)
    }

    /// Shows the body at `resolution` ("base" or "fine") from now on, keeping its coefficients.
    /// A model built at base is mapped to fine exactly through the subdivision stencils of
    /// `fine_template` (the worker's cached fine template) on first use; `on_progress(fraction)`
    /// is called as the seven models' means and modes are mapped. A model built at fine has no
    /// base body to show.
    #[wasm_bindgen(js_name = useResolution)]
    pub fn use_resolution(
        &mut self,
        resolution: &str,
        fine_template: &TemplateHandle,
        on_progress: &Function,
    ) -> Result<(), JsError> {
        let resolution: Resolution = resolution
            .parse()
            .map_err(|e| js(format!("resolution {resolution:?}: {e}")))?;
        let own = self.model.template.resolution.as_str();
        let at_fine = resolution == Resolution::Fine && own == Resolution::Base.name();
        if resolution == Resolution::Base && own != Resolution::Base.name() {
            return Err(js(format!(
                "this model was built at {own} resolution; it has no base body to show"
            )));
        }
        if at_fine && self.fine.is_none() {
            let base = Template::embedded().map_err(|e| js(format!("embedded template: {e}")))?;
            let target = FineTemplate::of_templates(&base, &fine_template.template).map_err(js)?;
            let mut progress = |f: f64| {
                // A failing callback only loses a progress report.
                let _ = on_progress.call1(&JsValue::NULL, &JsValue::from_f64(f));
            };
            self.fine = Some(subdivide_model(&self.model, &target, &mut progress).map_err(js)?);
        }
        if at_fine != self.at_fine {
            let coefficients = self.morph.coefficients().clone();
            self.at_fine = at_fine;
            self.morph = Morph::new(self.shown(), &coefficients).map_err(js)?;
            self.topology = topology_of(self.shown())?;
        }
        Ok(())
    }

    /// Moves the body shown to the coefficients given as σ values: `whole_sigma` (shorter =
    /// trailing zeros), `segment_sigma` the overridden segments' values concatenated in segment
    /// order, `segment_counts` (6 entries) how many belong to each (negative: not overridden).
    /// With `rebuild` the body is reconstructed from scratch (reset, random body, a link, a new
    /// model); otherwise each changed coefficient is one rank-1 update, unless the set of
    /// overridden segments changed or more than `pca::morph::MAX_DELTAS` values did. Returns
    /// `{rebuilt, deltas}` as JSON; `positions()` then holds the body.
    pub fn morph(
        &mut self,
        whole_sigma: &[f64],
        segment_sigma: &[f64],
        segment_counts: &[i32],
        rebuild: bool,
    ) -> Result<String, JsError> {
        let c = self.coefficients(whole_sigma, segment_sigma, segment_counts)?;
        let model = match (&self.fine, self.at_fine) {
            (Some(fine), true) => fine,
            _ => &self.model,
        };
        let update = if rebuild {
            self.morph.rebuild(model, &c)
        } else {
            self.morph.update(model, &c)
        }
        .map_err(js)?;
        serde_json::to_string(&update).map_err(js)
    }

    /// `#V·3` positions of the body shown, metres (copied out).
    pub fn positions(&self) -> Float32Array {
        Float32Array::from(self.morph.positions())
    }

    /// `#V·3` unit vertex normals of the body shown (computed now, copied out).
    pub fn normals(&mut self) -> Float32Array {
        let positions = self.morph.positions();
        self.normals.resize(positions.len(), 0.0);
        self.topology
            .vertex_normals_into(positions, &mut self.normals);
        Float32Array::from(self.normals.as_slice())
    }

    /// `#V·3` unit vertex normals of other `positions` (`#V·3`) over the triangles of the body
    /// shown, e.g. of a body from `reconstruct` (computed now, copied out).
    #[wasm_bindgen(js_name = normalsOf)]
    pub fn normals_of(&self, positions: &[f32]) -> Result<Float32Array, JsError> {
        normals_of(&self.topology, positions, "the body shown")
    }

    /// A body for export, without touching the one shown: same arguments as `morph`, positions
    /// (`#V·3`, metres, at the shown resolution) copied out; `normalsOf` gives its normals.
    pub fn reconstruct(
        &self,
        whole_sigma: &[f64],
        segment_sigma: &[f64],
        segment_counts: &[i32],
    ) -> Result<Float32Array, JsError> {
        let c = self.coefficients(whole_sigma, segment_sigma, segment_counts)?;
        let model = self.shown();
        let mut out = vec![0.0f32; 3 * model.template.vertex_count];
        model.reconstruct_into(&c, &mut out).map_err(js)?;
        Ok(Float32Array::from(out.as_slice()))
    }

    /// Seam quality of the body shown, on the loaded model, as JSON
    /// `{max_jump, segments: [a, b] | null, vertex}` (metres); 0 and `null` when no segment has
    /// its own coefficients (every segment then is the whole body).
    #[wasm_bindgen(js_name = seamJson)]
    pub fn seam_json(&self) -> Result<String, JsError> {
        let c = self.morph.coefficients();
        let seam = if c.overridden().iter().any(|&o| o) {
            self.model.seam_report(c).map_err(js)?
        } else {
            SeamReport {
                max_jump: 0.0,
                segments: None,
                vertex: None,
            }
        };
        serde_json::to_string(&seam).map_err(js)
    }

    /// Every measurement of the body shown as a JSON list of `{name, label, kind, value}`
    /// (`crate::measure::Reading`; m, m³, m²; `value` `null`: a girth whose plane found no
    /// section), taken on the base template's vertices, which are the first vertices of a finer
    /// body and sit exactly where the base body's do.
    #[wasm_bindgen(js_name = measureJson)]
    pub fn measure_json(&self) -> Result<String, JsError> {
        let m = self.measurer.measure(self.morph.positions()).map_err(js)?;
        serde_json::to_string(&m.readings()).map_err(js)
    }

    /// `eigenvalues.csv` of all seven models.
    #[wasm_bindgen(js_name = eigenvaluesCsv)]
    pub fn eigenvalues_csv(&self) -> String {
        eigenvalues_csv(&self.model)
    }

    /// `scores.csv` (long format) of all seven models.
    #[wasm_bindgen(js_name = scoresCsv)]
    pub fn scores_csv(&self) -> String {
        scores_csv(&self.model)
    }

    /// `quality.csv` of all seven models.
    #[wasm_bindgen(js_name = qualityCsv)]
    pub fn quality_csv(&self) -> String {
        quality_csv(&self.model)
    }

    /// The whole-body model as GLB: mean base mesh, the first `modes` modes at +1σ as morph targets.
    #[wasm_bindgen(js_name = modelGlb)]
    pub fn model_glb(&self, modes: u32) -> Uint8Array {
        Uint8Array::from(model_glb(&self.model, modes as usize).as_slice())
    }

    /// The whole-body model and the six segment models as one GLB (seven meshes, each with its
    /// first `modes` modes at +1σ as morph targets; layout in `model_file::gltf`).
    #[wasm_bindgen(js_name = partsGlb)]
    pub fn parts_glb(&self, modes: u32) -> Uint8Array {
        Uint8Array::from(parts_glb(&self.model, modes as usize).as_slice())
    }

    /// The model as a version-1 model file (f32 basis).
    #[wasm_bindgen(js_name = fileBytes)]
    pub fn file_bytes(&self) -> Uint8Array {
        Uint8Array::from(write_model(&self.model, BasisPrecision::F32).as_slice())
    }
}

/// Reads a model file and checks it against the embedded template at the model's resolution.
/// Errors are the core's documented messages prefixed by `file_name`.
#[wasm_bindgen(js_name = loadShapeModel)]
pub fn load_shape_model(bytes: &[u8], file_name: &str) -> Result<ShapeSpace, JsError> {
    let named = |e: &dyn std::fmt::Display| js(format!("{file_name}: {e}"));
    let header = read_model(bytes).map_err(|e| named(&e))?;
    let resolution: Resolution = header.template.resolution.parse().map_err(|e| named(&e))?;
    drop(header);
    let template = template_at(resolution)?;
    let model =
        read_model_for(bytes, &TemplateIdentity::of_template(&template)).map_err(|e| named(&e))?;
    ShapeSpace::new(model, &template)
}
