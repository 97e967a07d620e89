//! `read_landmarks`: bytes of a landmark file (CSV, CAESAR `.lnd`, JSON) → [`LandmarkSet`] with
//! canonical CAESAR names.
//!
//! Units: positions are returned in the file's own units. `.lnd` files are millimetres by
//! definition. CSV and JSON carry no unit, and a partial set (say three landmarks on the head)
//! has too small an extent to guess from, so the caller should take the units of the scan the
//! landmarks were placed on (`crate::mesh::summary::summarise(&scan).units_detected`).

use std::collections::HashSet;

use super::gzip::{inner_name, maybe_gunzip};
use super::landmark_raw::RawLandmark;
use super::{landmarks_csv, landmarks_json, lnd, IoError};
use crate::landmarks::{canonical_name, Landmark, LandmarkSet};
use crate::mesh::units::Units;

/// The units a landmark file's format fixes: CAESAR `.lnd` files are millimetres by definition
/// (`name.lnd` or `name.lnd.gz`); CSV and JSON carry none, and their landmarks are in the units
/// of the scan they were placed on. The one place this rule lives: the command line, the batch
/// and the app all read a landmark file's units from here.
pub fn landmark_file_units(file_name: &str) -> Option<Units> {
    let lower = file_name.to_ascii_lowercase();
    let stem = lower.strip_suffix(".gz").unwrap_or(&lower);
    stem.ends_with(".lnd").then_some(Units::Millimetres)
}

/// Reads a landmark file: CAESAR `.lnd`, CSV `name,x,y,z` (header optional, quoted names) or JSON
/// `{"name": [x, y, z]}` (`null` = missing; an array of `{name, position}` also works), optionally gzip-compressed. Names are normalised to
/// canonical CAESAR names; unrecognised names are kept as written and listed in `unknown`; a
/// landmark given twice is an error naming it.
pub fn read_landmarks(bytes: &[u8], file_name: &str) -> Result<LandmarkSet, IoError> {
    if bytes.is_empty() {
        return Err(IoError::Empty {
            file: file_name.to_string(),
        });
    }
    let data = maybe_gunzip(bytes, file_name)?;
    let data = data.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&data);
    let text = std::str::from_utf8(data).map_err(|e| {
        IoError::malformed(
            file_name,
            format!("byte {}", e.valid_up_to()),
            "not text; landmark files are CSV, CAESAR .lnd or JSON text",
        )
    })?;
    if text.trim().is_empty() {
        return Err(IoError::Empty {
            file: file_name.to_string(),
        });
    }
    let name = inner_name(file_name);
    let raw = match name.rsplit('.').next() {
        Some("lnd") => lnd::parse_lnd(text, file_name)?,
        Some("json") => landmarks_json::parse_json(text, file_name)?,
        Some("csv") => landmarks_csv::parse_csv(text, file_name)?,
        _ if text.trim_start().starts_with(['{', '[']) => {
            landmarks_json::parse_json(text, file_name)?
        }
        _ if lnd::looks_like_lnd(text) => lnd::parse_lnd(text, file_name)?,
        _ => landmarks_csv::parse_csv(text, file_name)?,
    };
    assemble(raw, file_name)
}

/// Normalises names, rejects duplicates and splits present / missing / unknown.
fn assemble(raw: Vec<RawLandmark>, file: &str) -> Result<LandmarkSet, IoError> {
    let mut set = LandmarkSet::default();
    // A set, not a list: a file of many thousand distinct names must not cost quadratic time.
    let mut seen: HashSet<String> = HashSet::with_capacity(raw.len());
    let mut duplicates: Vec<String> = Vec::new();
    let mut reported: HashSet<String> = HashSet::new();
    for entry in raw {
        let canonical = canonical_name(&entry.name);
        let name = canonical
            .map(str::to_string)
            .unwrap_or_else(|| entry.name.trim().to_string());
        if !seen.insert(name.clone()) {
            if reported.insert(name.clone()) {
                duplicates.push(name);
            }
            continue;
        }
        if canonical.is_none() {
            set.unknown.push(name.clone());
        }
        match entry.position {
            Some(position) => set.landmarks.push(Landmark { name, position }),
            None if canonical.is_some() => set.missing.push(name),
            None => {}
        }
    }
    if !duplicates.is_empty() {
        return Err(IoError::DuplicateLandmarks {
            file: file.to_string(),
            names: duplicates,
        });
    }
    if set.landmarks.is_empty() && set.missing.is_empty() {
        return Err(IoError::NothingUsable {
            file: file.to_string(),
            detail: "no landmarks found".to_string(),
        });
    }
    Ok(set)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_lnd_files_fix_their_units() {
        for name in ["a.lnd", "A.LND", "dir/a.lnd.gz"] {
            assert_eq!(
                landmark_file_units(name),
                Some(Units::Millimetres),
                "{name}"
            );
        }
        for name in ["a.csv", "a.json", "a.lnd.csv", "lnd", "a.csv.gz"] {
            assert_eq!(landmark_file_units(name), None, "{name}");
        }
    }
}
