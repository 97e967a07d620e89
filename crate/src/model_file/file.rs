//! The BodySpace shape-model file (`.bsm`), format version 1. Documented in docs/shape-model.md.
//!
//! ```text
//! 0   8 bytes  magic "BSPCAMDL"
//! 8   u32 LE   format version (1)
//! 12  u32 LE   header length H
//! 16  H bytes  JSON header (UTF-8): template identity, settings, subjects, per-model variances
//!              and quality curves, the array table {name, dtype, count, offset}, data_bytes,
//!              data_crc32
//! 16+H, padded with zeros to a multiple of 4: the data section, little-endian arrays at their
//!              table offsets (relative to the data section, 4-byte aligned)
//! ```
//! Arrays: `triangles` u32 3F, `segment_weights` f32 6V, and per model (`whole`, then the six
//! segments by name) `<model>/mean` f32 3n, `<model>/basis` f32 or f16 M·3n (mode-major),
//! `<model>/scores` f32 N·M. Segment vertex subsets are derived from the weights (weight > 0).

use super::f16::{f16_to_f32, f32_to_f16};
use crate::pca::error::PcaError;
use crate::pca::metrics::QualityCurves;
use crate::pca::model::BodyModel;
use crate::pca::params::BuildParams;
use crate::pca::segments::segment_subsets;
use crate::pca::shape_model::{ShapeModel, TemplateIdentity};
use crate::template::Segment;
use serde::{Deserialize, Serialize};

/// The 8 bytes every model file starts with.
pub const MAGIC: &[u8; 8] = b"BSPCAMDL";
/// The format version this build writes and reads.
pub const FORMAT_VERSION: u32 = 1;
/// Largest model file accepted: 1 GiB. Reading converts every array to `f32` (twice the bytes for
/// an f16 basis), so a model of this size needs about 2–3 GiB, what a browser tab (wasm32, 4 GiB)
/// can hold. The demo model is a few MB; a `fine` model with 20 modes per part is about 110 MB.
/// Every array is checked against the bytes of the data section before it is read, so memory stays
/// in proportion to the file whatever its header declares.
pub const MAX_MODEL_BYTES: u64 = 1 << 30;

/// Precision of the stored basis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum BasisPrecision {
    /// Bit-exact (default).
    #[default]
    F32,
    /// Half the size; relative error ≤ 2⁻¹¹ per basis entry.
    F16,
}

#[derive(Debug, Serialize, Deserialize)]
struct ArrayEntry {
    name: String,
    dtype: String,
    count: usize,
    offset: usize,
}

#[derive(Debug, Serialize, Deserialize)]
struct ModelHeader {
    name: String,
    vertex_count: usize,
    modes: usize,
    variances: Vec<f64>,
    all_variances: Vec<f64>,
    quality: QualityCurves,
}

#[derive(Debug, Serialize, Deserialize)]
struct Header {
    format: String,
    template: TemplateIdentity,
    settings: BuildParams,
    subjects: Vec<String>,
    basis_precision: BasisPrecision,
    triangle_count: usize,
    models: Vec<ModelHeader>,
    arrays: Vec<ArrayEntry>,
    data_bytes: usize,
    data_crc32: u32,
}

fn model_names() -> Vec<&'static str> {
    std::iter::once("whole")
        .chain(Segment::ALL.iter().map(|s| s.name()))
        .collect()
}

struct DataWriter {
    bytes: Vec<u8>,
    arrays: Vec<ArrayEntry>,
}

impl DataWriter {
    fn push(
        &mut self,
        name: String,
        dtype: &str,
        count: usize,
        data: impl Iterator<Item = [u8; 4]>,
    ) {
        self.arrays.push(ArrayEntry {
            name,
            dtype: dtype.into(),
            count,
            offset: self.bytes.len(),
        });
        data.for_each(|b| self.bytes.extend_from_slice(&b));
    }

    fn push_f16(&mut self, name: String, data: &[f32]) {
        self.arrays.push(ArrayEntry {
            name,
            dtype: "f16".into(),
            count: data.len(),
            offset: self.bytes.len(),
        });
        for &x in data {
            self.bytes.extend_from_slice(&f32_to_f16(x).to_le_bytes());
        }
        while self.bytes.len() % 4 != 0 {
            self.bytes.push(0);
        }
    }
}

fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = flate2::Crc::new();
    crc.update(bytes);
    crc.sum()
}

/// Serialises `model` to the version-1 file format.
pub fn write_model(model: &BodyModel, precision: BasisPrecision) -> Vec<u8> {
    let mut data = DataWriter {
        bytes: Vec::new(),
        arrays: Vec::new(),
    };
    let f32s = |v: &[f32]| {
        v.iter()
            .map(|x| x.to_le_bytes())
            .collect::<Vec<_>>()
            .into_iter()
    };
    data.push(
        "triangles".into(),
        "u32",
        3 * model.triangles.len(),
        model.triangles.iter().flatten().map(|i| i.to_le_bytes()),
    );
    let weights: Vec<f32> = model.segment_weights.iter().flatten().copied().collect();
    data.push(
        "segment_weights".into(),
        "f32",
        weights.len(),
        f32s(&weights),
    );
    let parts: Vec<&ShapeModel> = std::iter::once(&model.whole)
        .chain(&model.segments)
        .collect();
    let mut models = Vec::new();
    for (name, m) in model_names().into_iter().zip(&parts) {
        data.push(format!("{name}/mean"), "f32", m.mean.len(), f32s(&m.mean));
        match precision {
            BasisPrecision::F32 => data.push(
                format!("{name}/basis"),
                "f32",
                m.basis.len(),
                f32s(&m.basis),
            ),
            BasisPrecision::F16 => data.push_f16(format!("{name}/basis"), &m.basis),
        }
        data.push(
            format!("{name}/scores"),
            "f32",
            m.scores.len(),
            f32s(&m.scores),
        );
        models.push(ModelHeader {
            name: name.into(),
            vertex_count: m.vertex_count(),
            modes: m.mode_count(),
            variances: m.variances.clone(),
            all_variances: m.all_variances.clone(),
            quality: m.quality.clone(),
        });
    }
    let header = Header {
        format: "bodyspace-shape-model".into(),
        template: model.template.clone(),
        settings: model.settings,
        subjects: model.subjects.clone(),
        basis_precision: precision,
        triangle_count: model.triangles.len(),
        models,
        data_bytes: data.bytes.len(),
        data_crc32: crc32(&data.bytes),
        arrays: data.arrays,
    };
    // Serialising plain structs of strings and finite numbers cannot fail; NaN becomes null.
    let json = serde_json::to_vec(&header).unwrap_or_default();
    let mut out = Vec::with_capacity(16 + json.len() + 3 + data.bytes.len());
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(&json);
    while out.len() % 4 != 0 {
        out.push(b' ');
    }
    out.extend_from_slice(&data.bytes);
    out
}

struct DataReader<'a> {
    data: &'a [u8],
    arrays: &'a [ArrayEntry],
}

impl DataReader<'_> {
    fn raw(&self, name: &str, dtype: &str, count: usize) -> Result<&[u8], PcaError> {
        let entry = self
            .arrays
            .iter()
            .find(|a| a.name == name)
            .ok_or_else(|| PcaError::Corrupted(format!("array {name} is missing")))?;
        if entry.dtype != dtype || entry.count != count {
            return Err(PcaError::Corrupted(format!(
                "array {name} is {} × {} but the header implies {dtype} × {count}",
                entry.dtype, entry.count
            )));
        }
        let size = if dtype == "f16" { 2 } else { 4 };
        let end = count
            .checked_mul(size)
            .and_then(|b| b.checked_add(entry.offset))
            .filter(|&e| e <= self.data.len())
            .ok_or_else(|| {
                PcaError::Corrupted(format!("array {name} lies outside the data section"))
            })?;
        Ok(&self.data[entry.offset..end])
    }

    fn f32s(&self, name: &str, dtype: &str, count: usize) -> Result<Vec<f32>, PcaError> {
        let raw = self.raw(name, dtype, count)?;
        Ok(match dtype {
            "f16" => raw
                .chunks_exact(2)
                .map(|c| f16_to_f32(u16::from_le_bytes([c[0], c[1]])))
                .collect(),
            _ => raw
                .chunks_exact(4)
                .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                .collect(),
        })
    }
}

/// Parses a model file. Errors: [`PcaError::TooLarge`], [`PcaError::BadMagic`], [`PcaError::UnsupportedVersion`],
/// [`PcaError::Truncated`], [`PcaError::Corrupted`] (bad header, inconsistent arrays, checksum).
pub fn read_model(bytes: &[u8]) -> Result<BodyModel, PcaError> {
    if bytes.len() as u64 > MAX_MODEL_BYTES {
        return Err(PcaError::TooLarge {
            bytes: bytes.len() as u64,
            limit: MAX_MODEL_BYTES,
        });
    }
    if bytes.len() < 8 || &bytes[..8] != MAGIC {
        return Err(if bytes.len() < 8 && MAGIC.starts_with(bytes) {
            PcaError::Truncated(format!("{} bytes, not even the magic", bytes.len()))
        } else {
            PcaError::BadMagic
        });
    }
    let word = |at: usize| {
        bytes
            .get(at..at + 4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    if let Some(version) = word(8).filter(|&v| v != FORMAT_VERSION) {
        return Err(PcaError::UnsupportedVersion {
            found: version,
            supported: FORMAT_VERSION,
        });
    }
    let Some(header_len) = word(12) else {
        return Err(PcaError::Truncated(format!(
            "{} bytes, the fixed header needs 16",
            bytes.len()
        )));
    };
    let header_len = header_len as usize;
    let header_end = header_len.saturating_add(16);
    let data_start = header_end.saturating_add(3) / 4 * 4;
    if bytes.len() < header_end {
        return Err(PcaError::Truncated(format!(
            "the header declares {header_len} bytes but the file ends after {}",
            bytes.len() - 16
        )));
    }
    let header: Header = serde_json::from_slice(&bytes[16..header_end])
        .map_err(|e| PcaError::Corrupted(format!("header is not valid: {e}")))?;
    let available = bytes.len().saturating_sub(data_start);
    if data_start > bytes.len() || available < header.data_bytes {
        return Err(PcaError::Truncated(format!(
            "the data section needs {} bytes but the file ends after {available}",
            header.data_bytes
        )));
    }
    let data = &bytes[data_start..data_start + header.data_bytes];
    if crc32(data) != header.data_crc32 {
        return Err(PcaError::Corrupted(
            "data section fails its CRC-32 checksum".into(),
        ));
    }
    let v = header.template.vertex_count;
    let n = header.subjects.len();
    let mul = |a: usize, b: usize| {
        a.checked_mul(b)
            .ok_or_else(|| PcaError::Corrupted("an array size overflows".into()))
    };
    let reader = DataReader {
        data,
        arrays: &header.arrays,
    };
    let triangles: Vec<[u32; 3]> = reader
        .raw("triangles", "u32", mul(3, header.triangle_count)?)?
        .chunks_exact(12)
        .map(|c| {
            std::array::from_fn(|k| {
                u32::from_le_bytes([c[4 * k], c[4 * k + 1], c[4 * k + 2], c[4 * k + 3]])
            })
        })
        .collect();
    let weights: Vec<[f32; 6]> = reader
        .f32s("segment_weights", "f32", mul(6, v)?)?
        .chunks_exact(6)
        .map(|c| std::array::from_fn(|k| c[k]))
        .collect();
    let subsets = segment_subsets(&weights);
    let basis_dtype = match header.basis_precision {
        BasisPrecision::F32 => "f32",
        BasisPrecision::F16 => "f16",
    };
    if header.models.len() != 7 {
        return Err(PcaError::Corrupted(format!(
            "{} models instead of 7",
            header.models.len()
        )));
    }
    let mut parts = Vec::with_capacity(7);
    for (k, (name, mh)) in model_names().into_iter().zip(header.models).enumerate() {
        let indices = if k == 0 {
            Vec::new()
        } else {
            subsets[k - 1].clone()
        };
        let count = if k == 0 { v } else { indices.len() };
        if mh.name != name || mh.vertex_count != count || mh.variances.len() != mh.modes {
            return Err(PcaError::Corrupted(format!(
                "model {name} does not match its segment weights"
            )));
        }
        let d = mul(3, count)?;
        let size = mul(mh.modes, d)?;
        let scores = mul(mh.modes, n)?;
        parts.push(ShapeModel {
            vertex_indices: indices,
            mean: reader.f32s(&format!("{name}/mean"), "f32", d)?,
            basis: reader.f32s(&format!("{name}/basis"), basis_dtype, size)?,
            variances: mh.variances,
            all_variances: mh.all_variances,
            scores: reader.f32s(&format!("{name}/scores"), "f32", scores)?,
            quality: mh.quality,
        });
    }
    let whole = parts.remove(0);
    BodyModel::assemble(
        header.template,
        header.settings,
        header.subjects,
        triangles,
        weights,
        whole,
        parts,
    )
}

/// [`read_model`], then fails with [`PcaError::TemplateMismatch`] unless the model was built for
/// `template`.
pub fn read_model_for(bytes: &[u8], template: &TemplateIdentity) -> Result<BodyModel, PcaError> {
    let model = read_model(bytes)?;
    model.check_template(template)?;
    Ok(model)
}
