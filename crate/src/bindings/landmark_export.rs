//! `writeLandmarks`: a landmark set from the page as a CAESAR `.lnd`, CSV or JSON file, by the
//! core's one writer of each format.

use nalgebra::Point3;
use wasm_bindgen::prelude::*;

use crate::io::{write_landmarks_csv, write_landmarks_json, write_lnd};
use crate::landmarks::{Landmark, LandmarkSet};

/// The file bytes of a landmark set. `names` one per line, `positions` `#L·3` (xyz interleaved,
/// written as given: `.lnd` readers expect millimetres); a landmark whose three coordinates are
/// NaN is absent (`.lnd`: −999, JSON: `null`, CSV: left out). `format`: `lnd`, `csv` or `json`;
/// `subject_id` goes into the `.lnd` header.
#[wasm_bindgen(js_name = writeLandmarks)]
pub fn write_landmarks(
    names: &str,
    positions: &[f64],
    format: &str,
    subject_id: &str,
) -> Result<Vec<u8>, JsError> {
    let set = landmark_set(names, positions).map_err(|e| JsError::new(&e))?;
    match format {
        "lnd" => Ok(write_lnd(&set, subject_id)),
        "csv" => Ok(write_landmarks_csv(&set)),
        "json" => Ok(write_landmarks_json(&set)),
        other => Err(JsError::new(&format!(
            "landmark export: unknown format {other:?} (lnd, csv or json)"
        ))),
    }
}

/// The set `names` / `positions` describe, absent landmarks (all-NaN) listed as missing.
fn landmark_set(names: &str, positions: &[f64]) -> Result<LandmarkSet, String> {
    let names: Vec<&str> = if names.is_empty() {
        Vec::new()
    } else {
        names.split('\n').collect()
    };
    if positions.len() != names.len() * 3 {
        return Err(format!(
            "landmark export: {} names but {} coordinates (3 per landmark expected)",
            names.len(),
            positions.len()
        ));
    }
    let mut set = LandmarkSet::default();
    for (name, p) in names.iter().zip(positions.chunks_exact(3)) {
        if p.iter().all(|v| v.is_nan()) {
            set.missing.push(name.to_string());
        } else if p.iter().all(|v| v.is_finite()) {
            set.landmarks.push(Landmark {
                name: name.to_string(),
                position: Point3::new(p[0], p[1], p[2]),
            });
        } else {
            return Err(format!(
                "landmark export: {name:?} has a coordinate that is not a finite number ({p:?})"
            ));
        }
    }
    Ok(set)
}
