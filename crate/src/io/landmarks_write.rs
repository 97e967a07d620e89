//! Writing a landmark set in the format its file name asks for: `.csv` (`name,x,y,z`) and
//! `.json` in the set's own units, CAESAR `.lnd` in millimetres (the format's unit). One place
//! decides, for the command line and the app.

use super::landmarks_csv::write_landmarks_csv;
use super::landmarks_json::write_landmarks_json;
use super::lnd::write_lnd;
use crate::landmarks::LandmarkSet;

/// The bytes of `set` (positions in units whose metre factor is `scale_to_metres`) as the file
/// `file_name` (`.csv`, `.lnd` or `.json`, any case); `subject_id` goes into an `.lnd` header.
/// The error names the file and the extensions accepted.
pub fn write_landmarks(
    set: &LandmarkSet,
    file_name: &str,
    scale_to_metres: f64,
    subject_id: &str,
) -> Result<Vec<u8>, String> {
    let lower = file_name.to_ascii_lowercase();
    if lower.ends_with(".csv") {
        Ok(write_landmarks_csv(set))
    } else if lower.ends_with(".json") {
        Ok(write_landmarks_json(set))
    } else if lower.ends_with(".lnd") {
        Ok(write_lnd(&set.scaled(scale_to_metres * 1000.0), subject_id))
    } else {
        Err(format!(
            "{file_name}: unknown landmark format; name the file .csv, .lnd or .json"
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::read_landmarks;
    use crate::landmarks::Landmark;
    use nalgebra::Point3;

    #[test]
    fn each_format_reads_back_and_lnd_is_in_millimetres() {
        let set = LandmarkSet {
            landmarks: vec![Landmark {
                name: "Sellion".into(),
                position: Point3::new(0.1, 1.6, 0.05),
            }],
            ..LandmarkSet::default()
        };
        for name in ["a.csv", "a.JSON", "a.lnd"] {
            let bytes = write_landmarks(&set, name, 1.0, "a").unwrap();
            let back = read_landmarks(&bytes, name).unwrap();
            let p = back.get("Sellion").unwrap();
            let scale = if name.ends_with(".lnd") { 1000.0 } else { 1.0 };
            assert!(
                (p - set.landmarks[0].position * scale).norm() < 1e-6,
                "{name}: {p}"
            );
        }
        let err = write_landmarks(&set, "a.txt", 1.0, "a").unwrap_err();
        assert!(err.contains(".csv, .lnd or .json"), "{err}");
    }
}
