//! Landmark JSON: an object `{"name": [x, y, z], ...}`; `null` marks a missing landmark. Keys
//! are read in file order and duplicates are reported (a plain map would silently keep the last).

use std::fmt;

use serde::de::{Deserializer, MapAccess, Visitor};

use super::landmarks_read::{finite, RawLandmark};
use super::IoError;

struct Entries(Vec<(String, Option<[f64; 3]>)>);

struct EntriesVisitor;

impl<'de> Visitor<'de> for EntriesVisitor {
    type Value = Entries;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an object mapping landmark names to [x, y, z] (or null)")
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
        d.deserialize_map(EntriesVisitor)
    }
}

/// The landmark entries of a JSON file, in file order.
pub fn parse_json(text: &str, file: &str) -> Result<Vec<RawLandmark>, IoError> {
    let entries: Entries = serde_json::from_str(text).map_err(|e| {
        IoError::malformed(
            file,
            format!("line {} column {}", e.line(), e.column()),
            format!("expected {{\"name\": [x, y, z], ...}} ({e})"),
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
