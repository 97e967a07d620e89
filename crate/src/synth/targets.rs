//! MakeHuman morph targets: the dense `targets.bin` matrix and its row names.
//!
//! Layout (learnt from the package's `Export_targets_to_bin.ipynb`): `targets.bin` is a row-major
//! `#T by 3·#V` matrix of little-endian `i16`, one row per target in the *sorted* order of the
//! target paths in `target-list.json` (`data/targets/...`), `#V` = 19158 base-mesh vertices
//! (skin, helpers and joint cubes). Offsets are `value · 1e-3` model units (decimetres).

use std::collections::HashMap;
use std::io::{Read, Seek, SeekFrom};

use nalgebra::Vector3;

use super::error::SynthError;

/// Scale of the stored integers: `offset = value · 1e-3` model units.
pub const TARGET_UNIT: f64 = 1e-3;

/// The names of all targets in `targets.bin` row order.
#[derive(Debug, Clone)]
pub struct TargetList {
    names: Vec<String>,
    rows: HashMap<String, usize>,
}

impl TargetList {
    /// Parses `target-list.json` (`{"targets": {"data/targets/x/y.target": [...]}, ...}`).
    /// Names are kept as the short form `x/y` (no `data/targets/` prefix, no `.target`).
    pub fn from_json(bytes: &[u8], path: &str) -> Result<Self, SynthError> {
        let value: serde_json::Value =
            serde_json::from_slice(bytes).map_err(|e| SynthError::Format {
                path: path.to_string(),
                message: format!("not JSON ({e})"),
            })?;
        let targets = value
            .get("targets")
            .and_then(|t| t.as_object())
            .ok_or_else(|| SynthError::Format {
                path: path.to_string(),
                message: "no `targets` object".into(),
            })?;
        let mut full: Vec<&String> = targets.keys().collect();
        // The notebook wrote rows in Python's sorted order of the full paths.
        full.sort();
        let names: Vec<String> = full.iter().map(|p| short_name(p)).collect();
        let rows = names
            .iter()
            .enumerate()
            .map(|(i, n)| (n.clone(), i))
            .collect();
        Ok(Self { names, rows })
    }

    /// Number of targets `#T`.
    pub fn len(&self) -> usize {
        self.names.len()
    }

    /// True when the list is empty.
    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }

    /// The row of target `name` (short form, e.g. `macrodetails/universal-female-young-averagemuscle-averageweight`).
    pub fn row(&self, name: &str) -> Option<usize> {
        self.rows.get(name).copied()
    }

    /// All names in row order.
    pub fn names(&self) -> &[String] {
        &self.names
    }
}

fn short_name(path: &str) -> String {
    let p = path.strip_prefix("data/targets/").unwrap_or(path);
    p.strip_suffix(".target").unwrap_or(p).to_string()
}

/// A set of target rows held in memory, ready to be blended.
#[derive(Debug, Clone, Default)]
pub struct TargetSet {
    vertex_count: usize,
    by_name: HashMap<String, Vec<i16>>,
}

impl TargetSet {
    /// Reads the rows named in `names` from a `targets.bin` source with `vertex_count` vertices
    /// per row. Unknown names are an error (the generator's target names are fixed).
    pub fn read<R: Read + Seek>(
        source: &mut R,
        list: &TargetList,
        names: &[String],
        vertex_count: usize,
        path: &str,
    ) -> Result<Self, SynthError> {
        let row_bytes = vertex_count * 3 * 2;
        let total = source
            .seek(SeekFrom::End(0))
            .map_err(|e| read_err(path, e))?;
        if total != (list.len() * row_bytes) as u64 {
            return Err(SynthError::Format {
                path: path.to_string(),
                message: format!(
                    "{total} bytes, expected {} targets × {vertex_count} vertices × 3 × 2 bytes",
                    list.len()
                ),
            });
        }
        let mut by_name = HashMap::new();
        let mut buf = vec![0u8; row_bytes];
        for name in names {
            if by_name.contains_key(name) {
                continue;
            }
            let row = list
                .row(name)
                .ok_or_else(|| SynthError::MissingTarget(name.clone()))?;
            source
                .seek(SeekFrom::Start((row * row_bytes) as u64))
                .map_err(|e| read_err(path, e))?;
            source.read_exact(&mut buf).map_err(|e| read_err(path, e))?;
            let values = buf
                .chunks_exact(2)
                .map(|c| i16::from_le_bytes([c[0], c[1]]))
                .collect();
            by_name.insert(name.clone(), values);
        }
        Ok(Self {
            vertex_count,
            by_name,
        })
    }

    /// Number of vertices per target.
    pub fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    /// True when `name` was loaded.
    pub fn contains(&self, name: &str) -> bool {
        self.by_name.contains_key(name)
    }

    /// Adds `Σ wᵢ · scale · TARGET_UNIT · targetᵢ` to `positions` (`#V` points). `scale` converts
    /// model units to the caller's frame (0.1 for the template's metres). Unloaded names are skipped
    /// by design of the caller, which only asks for names it loaded; zero weights cost nothing.
    pub fn blend_into(
        &self,
        weights: &[(String, f64)],
        scale: f64,
        positions: &mut [Vector3<f64>],
    ) {
        for (name, w) in weights {
            if *w == 0.0 {
                continue;
            }
            let Some(values) = self.by_name.get(name) else {
                continue;
            };
            let k = w * scale * TARGET_UNIT;
            for (p, d) in positions.iter_mut().zip(values.chunks_exact(3)) {
                if d[0] != 0 || d[1] != 0 || d[2] != 0 {
                    p.x += k * f64::from(d[0]);
                    p.y += k * f64::from(d[1]);
                    p.z += k * f64::from(d[2]);
                }
            }
        }
    }
}

fn read_err(path: &str, e: std::io::Error) -> SynthError {
    SynthError::Read {
        path: path.to_string(),
        message: e.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Cursor;

    #[test]
    fn rows_follow_sorted_paths_and_blend() {
        let json =
            br#"{"targets": {"data/targets/b/y.target": [], "data/targets/a/x.target": []}}"#;
        let list = TargetList::from_json(json, "t.json").unwrap();
        assert_eq!(list.row("a/x"), Some(0));
        assert_eq!(list.row("b/y"), Some(1));
        // 2 targets × 1 vertex × 3 values.
        let mut bin = Vec::new();
        for v in [1000i16, 0, 0, 0, -2000, 0] {
            bin.extend_from_slice(&v.to_le_bytes());
        }
        let names = vec!["b/y".to_string(), "a/x".to_string()];
        let set = TargetSet::read(&mut Cursor::new(bin), &list, &names, 1, "t.bin").unwrap();
        let mut p = vec![Vector3::zeros()];
        set.blend_into(&[("a/x".into(), 0.5), ("b/y".into(), 1.0)], 0.1, &mut p);
        assert!((p[0].x - 0.05).abs() < 1e-12 && (p[0].y + 0.2).abs() < 1e-12);
    }

    #[test]
    fn wrong_size_is_an_error() {
        let json = br#"{"targets": {"data/targets/a/x.target": []}}"#;
        let list = TargetList::from_json(json, "t.json").unwrap();
        let r = TargetSet::read(&mut Cursor::new(vec![0u8; 5]), &list, &[], 1, "t.bin");
        assert!(matches!(r, Err(SynthError::Format { .. })));
    }
}
