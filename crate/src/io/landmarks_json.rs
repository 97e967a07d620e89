//! Landmark JSON: an object `{"name": [x, y, z], ...}` (`null` marks a missing landmark), or an
//! array of `{"name": .., "position": [x, y, z]}` / `{"name": .., "x": .., "y": .., "z": ..}`.
//! Keys are read in file order and duplicates are reported (a plain map would silently keep the
//! last).

use std::fmt;

use serde::de::{Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;

use super::landmark_raw::{finite, RawLandmark};
use super::IoError;
use crate::landmarks::LandmarkSet;

struct Entries(Vec<(String, Option<[f64; 3]>)>);

struct EntriesVisitor;

/// One element of the array form.
#[derive(Deserialize)]
struct Item {
    name: String,
    #[serde(default)]
    position: Option<[f64; 3]>,
    #[serde(default)]
    x: Option<f64>,
    #[serde(default)]
    y: Option<f64>,
    #[serde(default)]
    z: Option<f64>,
}

impl<'de> Visitor<'de> for EntriesVisitor {
    type Value = Entries;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an object mapping landmark names to [x, y, z] (or null)")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Entries, A::Error> {
        let mut out = Vec::new();
        while let Some(item) = seq.next_element::<Item>()? {
            let xyz = match (item.x, item.y, item.z) {
                (Some(x), Some(y), Some(z)) => Some([x, y, z]),
                _ => None,
            };
            out.push((item.name, item.position.or(xyz)));
        }
        Ok(Entries(out))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Entries, A::Error> {
        let mut out = Vec::new();
        while let Some(key) = map.next_key::<String>()? {
            let value: Option<[f64; 3]> = map.next_value()?;
            out.push((key, value));
        }
        Ok(Entries(out))
    }
}

impl<'de> serde::Deserialize<'de> for Entries {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(EntriesVisitor)
    }
}

/// The landmark entries of a JSON file, in file order.
pub fn parse_json(text: &str, file: &str) -> Result<Vec<RawLandmark>, IoError> {
    let entries: Entries = serde_json::from_str(text).map_err(|e| {
        IoError::malformed(
            file,
            format!("line {} column {}", e.line(), e.column()),
            format!("expected {{\"name\": [x, y, z], ...}} or [{{\"name\": .., \"position\": [x, y, z]}}] ({e})"),
        )
    })?;
    entries
        .0
        .into_iter()
        .map(|(name, p)| {
            let position = p.map(|p| finite(p, &name, file)).transpose()?;
            Ok(RawLandmark { name, position })
        })
        .collect()
}

/// The set as a JSON object `{"name": [x, y, z], ...}` in set order, then `"name": null` for each
/// of `set.missing` (the form [`parse_json`] reads back). Positions are written as given.
pub fn write_landmarks_json(set: &LandmarkSet) -> Vec<u8> {
    // Written by hand: serde_json's map would sort the names and lose the set's order.
    let key = |name: &str| serde_json::to_string(name).unwrap_or_default();
    let mut lines: Vec<String> = set
        .landmarks
        .iter()
        .map(|l| {
            let p = l.position;
            format!("  {}: [{}, {}, {}]", key(&l.name), p.x, p.y, p.z)
        })
        .collect();
    lines.extend(
        set.missing
            .iter()
            .map(|name| format!("  {}: null", key(name))),
    );
    format!("{{\n{}\n}}\n", lines.join(",\n")).into_bytes()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn array_forms_are_read_in_order() {
        let text = r#"[{"name": "Crotch", "position": [1, 2, 3]}, {"name": "Sellion", "x": 4, "y": 5, "z": 6}, {"name": "Cervicale"}]"#;
        let raw = parse_json(text, "a.json").unwrap();
        let names: Vec<&str> = raw.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(names, ["Crotch", "Sellion", "Cervicale"]);
        assert_eq!(raw[1].position, Some(nalgebra::Point3::new(4.0, 5.0, 6.0)));
        assert_eq!(raw[2].position, None);
    }

    #[test]
    fn a_number_is_not_a_landmark_file() {
        let err = parse_json("42", "a.json").unwrap_err();
        assert!(
            err.to_string().starts_with("a.json: line 1 column"),
            "{err}"
        );
    }

    #[test]
    fn written_json_reads_back_in_order_with_missing_as_null() {
        use crate::landmarks::Landmark;
        let set = LandmarkSet {
            landmarks: vec![
                Landmark {
                    name: "Sellion".into(),
                    position: nalgebra::Point3::new(0.5, 1.75, -0.25),
                },
                Landmark {
                    name: "Crotch".into(),
                    position: nalgebra::Point3::new(1.0, 2.0, 3.0),
                },
            ],
            missing: vec!["Cervicale".into()],
            unknown: vec![],
        };
        let bytes = write_landmarks_json(&set);
        let raw = parse_json(std::str::from_utf8(&bytes).unwrap(), "a.json").unwrap();
        let names: Vec<&str> = raw.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(names, ["Sellion", "Crotch", "Cervicale"]);
        assert_eq!(
            raw[0].position,
            Some(nalgebra::Point3::new(0.5, 1.75, -0.25))
        );
        assert_eq!(raw[2].position, None);
    }
}
