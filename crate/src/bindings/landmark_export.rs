//! `writeLandmarks`: a landmark set from the page as a CAESAR `.lnd`, CSV or JSON file, by the
//! core's one writer of each format.

use nalgebra::Point3;
use wasm_bindgen::prelude::*;

use super::align::landmark_names;
use crate::io::write_landmarks as write_landmarks_file;
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
    if !["lnd", "csv", "json"].contains(&format) {
        return Err(JsError::new(&format!(
            "landmark export: unknown format {format:?} (lnd, csv or json)"
        )));
    }
    // The page gives `.lnd` positions in millimetres already: a metre factor of 1e-3 keeps them.
    write_landmarks_file(&set, &format!("landmarks.{format}"), 1e-3, subject_id)
        .map_err(|e| JsError::new(&e))
}

/// The set `names` / `positions` describe, absent landmarks (all-NaN) listed as missing.
fn landmark_set(names: &str, positions: &[f64]) -> Result<LandmarkSet, String> {
    let names = landmark_names(names, positions, "landmark export")?;
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
