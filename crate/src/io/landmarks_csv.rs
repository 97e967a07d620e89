//! Landmark CSV: `name,x,y,z`, one landmark per row, with an optional header row. Names are
//! quoted where they contain commas (`"Rt. Axilla, Ant."`); a header may order the columns any
//! way (`x,y,z,name`); a row with empty coordinates marks a missing landmark.

use super::landmark_raw::{finite, RawLandmark};
use super::IoError;
use crate::landmarks::LandmarkSet;

/// The landmark entries of a CSV file, in file order.
pub fn parse_csv(text: &str, file: &str) -> Result<Vec<RawLandmark>, IoError> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .trim(csv::Trim::All)
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let mut columns = [0usize, 1, 2, 3];
    let mut out = Vec::new();
    let mut first_row = true;
    for (k, record) in reader.records().enumerate() {
        let record = record.map_err(|e| {
            let line = e.position().map_or(k + 1, |p| p.line() as usize);
            IoError::at_line(file, line, format!("not valid CSV ({e})"))
        })?;
        let line = record.position().map_or(k + 1, |p| p.line() as usize);
        if record.iter().all(str::is_empty) {
            continue;
        }
        let is_first = std::mem::replace(&mut first_row, false);
        if is_first && record.get(1).is_some_and(|f| f.parse::<f64>().is_err()) {
            columns = header_columns(&record).ok_or_else(|| {
                IoError::at_line(
                    file,
                    line,
                    "the header must name the columns name, x, y and z",
                )
            })?;
            continue;
        }
        let field = |c: usize| record.get(c).unwrap_or("");
        let name = field(columns[0]);
        if name.is_empty() {
            return Err(IoError::at_line(file, line, "the landmark has no name"));
        }
        let coords = [field(columns[1]), field(columns[2]), field(columns[3])];
        if coords.iter().all(|c| c.is_empty()) {
            out.push(RawLandmark {
                name: name.to_string(),
                position: None,
            });
            continue;
        }
        let mut p = [0.0f64; 3];
        for (v, c) in p.iter_mut().zip(coords) {
            *v = c.parse().map_err(|_| {
                IoError::at_line(
                    file,
                    line,
                    format!("cannot read {c:?} as a coordinate of {name:?}; expected name,x,y,z"),
                )
            })?;
        }
        out.push(RawLandmark {
            name: name.to_string(),
            position: Some(finite(p, name, file)?),
        });
    }
    Ok(out)
}

fn header_columns(record: &csv::StringRecord) -> Option<[usize; 4]> {
    let find = |names: &[&str]| {
        record
            .iter()
            .position(|h| names.contains(&h.to_ascii_lowercase().as_str()))
    };
    Some([
        find(&["name", "landmark", "label"])?,
        find(&["x"])?,
        find(&["y"])?,
        find(&["z"])?,
    ])
}

/// The set as CSV `name,x,y,z` with a header, in set order (missing landmarks are not written).
pub fn write_landmarks_csv(set: &LandmarkSet) -> Vec<u8> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    // Writing records of strings into a Vec cannot fail.
    let _ = writer.write_record(["name", "x", "y", "z"]);
    for l in &set.landmarks {
        let p = l.position;
        let _ = writer.write_record([
            l.name.clone(),
            p.x.to_string(),
            p.y.to_string(),
            p.z.to_string(),
        ]);
    }
    writer.into_inner().unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_after_blank_lines_and_comments_is_recognised() {
        let raw = parse_csv("\n# exported\n\nname,x,y,z\nSellion,1,2,3\n", "a.csv").unwrap();
        assert_eq!(raw.len(), 1);
        assert_eq!(raw[0].name, "Sellion");
    }

    #[test]
    fn a_header_without_coordinates_is_an_error() {
        let err = parse_csv("label,u,v,w\nSellion,1,2,3\n", "a.csv").unwrap_err();
        assert_eq!(
            err.to_string(),
            "a.csv: line 1: the header must name the columns name, x, y and z"
        );
    }
}
