//! Statismo HDF5 models for JavaScript. The worker reads and writes the HDF5 file with h5wasm
//! and moves its datasets through [`StatismoArrays`]; the core makes them from the model in
//! view (`ShapeSpace.statismoArrays`) and opens them on the template (`loadStatismoModel`), with
//! the same functions and checks as the native reader (`model_file::statismo`).

use js_sys::{Float32Array, Uint32Array};
use wasm_bindgen::prelude::*;

use crate::model_file::statismo::{
    body_model_from_statismo, statismo_of_part, RowMajor, StatismoModel,
};
use crate::template::{Resolution, Segment};

use super::model::{js, template_at, ShapeSpace};

/// The datasets of one statismo model (layout and units: `model_file::statismo`), copied in and out.
#[wasm_bindgen]
#[derive(Default)]
pub struct StatismoArrays {
    inner: StatismoModel,
}

fn matrix<T: Copy>(
    rows: usize,
    cols: usize,
    data: Vec<T>,
    what: &str,
) -> Result<RowMajor<T>, JsError> {
    if rows * cols != data.len() {
        return Err(js(format!(
            "{what}: {rows} × {cols} but {} values",
            data.len()
        )));
    }
    Ok(RowMajor { rows, cols, data })
}

#[wasm_bindgen]
impl StatismoArrays {
    /// Empty datasets, to be filled by the setters from a file.
    #[wasm_bindgen(constructor)]
    pub fn new() -> StatismoArrays {
        StatismoArrays::default()
    }

    /// `/version/majorVersion` and `minorVersion`; not called when the file has no `/version`.
    #[wasm_bindgen(js_name = setVersion)]
    pub fn set_version(&mut self, major: i32, minor: i32) {
        self.inner.version = Some((major, minor));
    }

    /// `/representer/points`: `rows × cols` (3 × n) row-major.
    #[wasm_bindgen(js_name = setPoints)]
    pub fn set_points(&mut self, rows: usize, cols: usize, data: &[f32]) -> Result<(), JsError> {
        self.inner.points = matrix(rows, cols, data.to_vec(), "/representer/points")?;
        Ok(())
    }

    /// `/representer/cells`: `rows × cols` (3 × m) row-major.
    #[wasm_bindgen(js_name = setCells)]
    pub fn set_cells(&mut self, rows: usize, cols: usize, data: &[u32]) -> Result<(), JsError> {
        self.inner.cells = matrix(rows, cols, data.to_vec(), "/representer/cells")?;
        Ok(())
    }

    /// `/model/mean` (3n).
    #[wasm_bindgen(js_name = setMean)]
    pub fn set_mean(&mut self, data: &[f32]) {
        self.inner.mean = data.to_vec();
    }

    /// `/model/pcaBasis`: `rows × cols` (3n × k) row-major.
    #[wasm_bindgen(js_name = setPcaBasis)]
    pub fn set_pca_basis(&mut self, rows: usize, cols: usize, data: &[f32]) -> Result<(), JsError> {
        self.inner.pca_basis = matrix(rows, cols, data.to_vec(), "/model/pcaBasis")?;
        Ok(())
    }

    /// `/model/pcaVariance` (k).
    #[wasm_bindgen(js_name = setPcaVariance)]
    pub fn set_pca_variance(&mut self, data: &[f32]) {
        self.inner.pca_variance = data.to_vec();
    }

    /// `/modelinfo/scores`: `rows × cols` (k × N) row-major; not called when there are none.
    #[wasm_bindgen(js_name = setScores)]
    pub fn set_scores(&mut self, rows: usize, cols: usize, data: &[f32]) -> Result<(), JsError> {
        self.inner.scores = matrix(rows, cols, data.to_vec(), "/modelinfo/scores")?;
        Ok(())
    }

    #[wasm_bindgen(getter, js_name = majorVersion)]
    pub fn major_version(&self) -> i32 {
        self.inner.version.map_or(0, |v| v.0)
    }

    #[wasm_bindgen(getter, js_name = minorVersion)]
    pub fn minor_version(&self) -> i32 {
        self.inner.version.map_or(8, |v| v.1)
    }

    /// n: points of the representer.
    #[wasm_bindgen(getter, js_name = pointCount)]
    pub fn point_count(&self) -> usize {
        self.inner.point_count()
    }

    /// m: triangles of the representer.
    #[wasm_bindgen(getter, js_name = cellCount)]
    pub fn cell_count(&self) -> usize {
        self.inner.cells.cols
    }

    /// k: modes.
    #[wasm_bindgen(getter, js_name = modeCount)]
    pub fn mode_count(&self) -> usize {
        self.inner.mode_count()
    }

    /// N: subjects with scores (0: none).
    #[wasm_bindgen(getter, js_name = subjectCount)]
    pub fn subject_count(&self) -> usize {
        self.inner.scores.cols
    }

    /// 3 × n, row-major.
    pub fn points(&self) -> Float32Array {
        Float32Array::from(self.inner.points.data.as_slice())
    }

    /// 3 × m, row-major.
    pub fn cells(&self) -> Uint32Array {
        Uint32Array::from(self.inner.cells.data.as_slice())
    }

    /// 3n.
    pub fn mean(&self) -> Float32Array {
        Float32Array::from(self.inner.mean.as_slice())
    }

    /// 3n × k, row-major, orthonormal columns.
    #[wasm_bindgen(js_name = pcaBasis)]
    pub fn pca_basis(&self) -> Float32Array {
        Float32Array::from(self.inner.pca_basis.data.as_slice())
    }

    /// k.
    #[wasm_bindgen(js_name = pcaVariance)]
    pub fn pca_variance(&self) -> Float32Array {
        Float32Array::from(self.inner.pca_variance.as_slice())
    }

    /// k × N, row-major, standard deviations.
    pub fn scores(&self) -> Float32Array {
        Float32Array::from(self.inner.scores.data.as_slice())
    }

    /// `[[key, value], …]` of `/modelinfo/modelBuilder-0/dataInfo` and `/parameters`, as JSON
    /// `{dataInfo, parameters, builderName}`.
    #[wasm_bindgen(js_name = infoJson)]
    pub fn info_json(&self) -> String {
        serde_json::json!({
            "dataInfo": self.inner.data_info,
            "parameters": self.inner.parameters,
            "builderName": crate::model_file::statismo::BUILDER_NAME,
            "representer": {
                "name": crate::model_file::statismo::REPRESENTER_NAME,
                "version": crate::model_file::statismo::REPRESENTER_VERSION,
                "datasetType": crate::model_file::statismo::DATASET_TYPE,
            },
        })
        .to_string()
    }
}

#[wasm_bindgen]
impl ShapeSpace {
    /// The loaded model's `part` (`whole` or a segment name) as statismo datasets, in
    /// millimetres. The loaded model, not its mapping to fine (whose modes are not orthonormal).
    #[wasm_bindgen(js_name = statismoArrays)]
    pub fn statismo_arrays(&self, part: &str) -> Result<StatismoArrays, JsError> {
        let segment = match part {
            "whole" => None,
            name => {
                Some(Segment::from_name(name).ok_or_else(|| js(format!("unknown part {name:?}")))?)
            }
        };
        Ok(StatismoArrays {
            inner: statismo_of_part(self.model(), segment),
        })
    }
}

/// The largest model file accepted, in bytes (`model_file::file::MAX_MODEL_BYTES`, for `.h5` files too).
#[wasm_bindgen(js_name = maxModelBytes)]
pub fn max_model_bytes() -> f64 {
    crate::model_file::file::MAX_MODEL_BYTES as f64
}

/// Opens statismo datasets read from `file_name` on the embedded template at the resolution of
/// its point count (`model_file::statismo::body_model_from_statismo`: a model on other points is
/// refused with the reason). Errors are prefixed by `file_name`.
#[wasm_bindgen(js_name = loadStatismoModel)]
pub fn load_statismo_model(
    arrays: &StatismoArrays,
    file_name: &str,
) -> Result<ShapeSpace, JsError> {
    let base = template_at(Resolution::Base)?;
    let template = if arrays.inner.point_count() == base.mesh().vertex_count() {
        base
    } else {
        let fine = template_at(Resolution::Fine)?;
        if arrays.inner.point_count() == fine.mesh().vertex_count() {
            fine
        } else {
            base
        }
    };
    let model = body_model_from_statismo(&arrays.inner, &template)
        .map_err(|e| js(format!("{file_name}: {e}")))?;
    ShapeSpace::new(model, &template)
}
