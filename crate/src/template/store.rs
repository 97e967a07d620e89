//! The stored template file (`public/template/template_base.bin.gz`).
//!
//! gzip of: magic `BSTMPL` (6 bytes), version `u16` (1), header length `u32`, UTF-8 JSON header
//! ([`StoredHeader`]), then little-endian arrays: positions `f32 × 3V` (metres), triangles
//! `u32 × 3F`, segment weights `u16 × 6V` (weight · 65535, segments in [`Segment::ALL`] order),
//! flags `u8 × V` ([`RegionFlags`]), provenance `u32 × V` (MakeHuman vertex index).

use std::io::{Read, Write};

use nalgebra::Point3;
use serde::{Deserialize, Serialize};

use super::error::TemplateError;
use super::segment::Segment;
use crate::mesh::Mesh;

/// File magic.
pub const MAGIC: &[u8; 6] = b"BSTMPL";
/// Current format version.
pub const VERSION: u16 = 1;

/// The JSON header of a stored template.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct StoredHeader {
    pub vertex_count: usize,
    pub triangle_count: usize,
    /// Landmark name → template vertex, in CAESAR order.
    pub landmarks: Vec<(String, u32)>,
    /// Segment names in the order of the weight columns.
    pub segments: Vec<String>,
    /// Width of the overlap band between neighbouring segments, metres.
    pub band_width: f64,
    /// Flag name → bit.
    pub flags: Vec<(String, u8)>,
    /// Where the mesh comes from and under which licence.
    pub source: String,
    pub licence: String,
    /// Units and axes.
    pub frame: String,
}

/// The decoded contents of a stored template.
#[derive(Debug, Clone, PartialEq)]
pub struct StoredTemplate {
    pub header: StoredHeader,
    pub mesh: Mesh,
    pub segment_weights: Vec<[f32; 6]>,
    pub flags: Vec<u8>,
    pub provenance: Vec<u32>,
}

/// Encodes and gzips a template.
pub fn encode(t: &StoredTemplate) -> Vec<u8> {
    let header = serde_json::to_vec(&t.header).unwrap_or_default();
    let mut raw = Vec::new();
    raw.extend_from_slice(MAGIC);
    raw.extend_from_slice(&VERSION.to_le_bytes());
    raw.extend_from_slice(&(header.len() as u32).to_le_bytes());
    raw.extend_from_slice(&header);
    for p in &t.mesh.positions {
        for c in [p.x, p.y, p.z] {
            raw.extend_from_slice(&(c as f32).to_le_bytes());
        }
    }
    for tri in &t.mesh.triangles {
        for i in tri {
            raw.extend_from_slice(&i.to_le_bytes());
        }
    }
    for w in &t.segment_weights {
        for q in quantise(w) {
            raw.extend_from_slice(&q.to_le_bytes());
        }
    }
    raw.extend_from_slice(&t.flags);
    for p in &t.provenance {
        raw.extend_from_slice(&p.to_le_bytes());
    }
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    // Writing into a Vec cannot fail.
    let _ = gz.write_all(&raw);
    gz.finish().unwrap_or_default()
}

/// Quantises six weights to u16 so that the quantised values sum to exactly 65535.
pub fn quantise(w: &[f32; 6]) -> [u16; 6] {
    let sum: f32 = w.iter().sum();
    let sum = if sum > 0.0 { sum } else { 1.0 };
    let mut q = w.map(|x| ((x / sum).clamp(0.0, 1.0) * 65535.0).round() as i64);
    let diff = 65535 - q.iter().sum::<i64>();
    let largest = (0..6).max_by_key(|&i| q[i]).unwrap_or(0);
    q[largest] += diff;
    q.map(|x| x.clamp(0, 65535) as u16)
}

/// Decodes a (gzipped) stored template, checking every length against the header.
pub fn decode(bytes: &[u8]) -> Result<StoredTemplate, TemplateError> {
    let fmt = |m: String| TemplateError::Format(m);
    let mut raw = Vec::new();
    if bytes.starts_with(&[0x1f, 0x8b]) {
        flate2::read::GzDecoder::new(bytes)
            .read_to_end(&mut raw)
            .map_err(|e| fmt(format!("gzip: {e}")))?;
    } else {
        raw = bytes.to_vec();
    }
    if raw.len() < 12 || &raw[..6] != MAGIC {
        return Err(fmt(
            "not a BodySpace template (magic `BSTMPL` missing)".into()
        ));
    }
    let version = u16::from_le_bytes([raw[6], raw[7]]);
    if version != VERSION {
        return Err(fmt(format!(
            "version {version}, this build reads {VERSION}"
        )));
    }
    let hlen = u32::from_le_bytes([raw[8], raw[9], raw[10], raw[11]]) as usize;
    let mut r = Reader { data: &raw, at: 12 };
    let header: StoredHeader =
        serde_json::from_slice(r.take(hlen, "header")?).map_err(|e| fmt(format!("header: {e}")))?;
    let (nv, nf) = (header.vertex_count, header.triangle_count);
    let pos = r.take(nv.saturating_mul(12), "positions")?;
    let positions: Vec<Point3<f64>> = pos
        .chunks_exact(12)
        .map(|c| {
            let f = |i: usize| f32::from_le_bytes([c[i], c[i + 1], c[i + 2], c[i + 3]]) as f64;
            Point3::new(f(0), f(4), f(8))
        })
        .collect();
    let tri = r.take(nf.saturating_mul(12), "triangles")?;
    let mut triangles = Vec::with_capacity(nf);
    for c in tri.chunks_exact(12) {
        let f = |i: usize| u32::from_le_bytes([c[i], c[i + 1], c[i + 2], c[i + 3]]);
        let t = [f(0), f(4), f(8)];
        if t.iter().any(|&i| i as usize >= nv) {
            return Err(fmt(format!("triangle {t:?} indexes past {nv} vertices")));
        }
        triangles.push(t);
    }
    let sw = r.take(nv.saturating_mul(12), "segment weights")?;
    let segment_weights = sw
        .chunks_exact(12)
        .map(|c| {
            std::array::from_fn(|k| u16::from_le_bytes([c[2 * k], c[2 * k + 1]]) as f32 / 65535.0)
        })
        .collect();
    let flags = r.take(nv, "flags")?.to_vec();
    let provenance = r
        .take(nv.saturating_mul(4), "provenance")?
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    if let Some((name, v)) = header.landmarks.iter().find(|(_, v)| *v as usize >= nv) {
        return Err(fmt(format!(
            "landmark `{name}` at vertex {v}, past {nv} vertices"
        )));
    }
    if header.segments.len() != Segment::ALL.len() {
        return Err(fmt(format!(
            "{} segments, expected 6",
            header.segments.len()
        )));
    }
    Ok(StoredTemplate {
        header,
        mesh: Mesh::new(positions, triangles),
        segment_weights,
        flags,
        provenance,
    })
}

struct Reader<'a> {
    data: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize, what: &str) -> Result<&'a [u8], TemplateError> {
        let end = self.at.checked_add(n).filter(|&e| e <= self.data.len());
        let end = end.ok_or_else(|| {
            TemplateError::Format(format!(
                "file ends inside the {what} ({n} bytes needed at offset {}, {} left)",
                self.at,
                self.data.len().saturating_sub(self.at)
            ))
        })?;
        let s = &self.data[self.at..end];
        self.at = end;
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> StoredTemplate {
        StoredTemplate {
            header: StoredHeader {
                vertex_count: 3,
                triangle_count: 1,
                landmarks: vec![("Sellion".into(), 2)],
                segments: Segment::ALL.iter().map(|s| s.name().to_string()).collect(),
                band_width: 0.06,
                flags: vec![("hand".into(), 1)],
                source: "test".into(),
                licence: "CC0".into(),
                frame: "metres".into(),
            },
            mesh: Mesh::new(
                vec![
                    Point3::new(0.0, 0.0, 0.0),
                    Point3::new(1.0, 0.0, 0.0),
                    Point3::new(0.0, 1.0, 0.0),
                ],
                vec![[0, 1, 2]],
            ),
            segment_weights: vec![
                [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                [0.5, 0.5, 0.0, 0.0, 0.0, 0.0],
                [0.0, 0.0, 0.0, 1.0, 0.0, 0.0],
            ],
            flags: vec![0, 1, 8],
            provenance: vec![0, 1, 2],
        }
    }

    #[test]
    fn round_trip_and_truncation() {
        let t = sample();
        let bytes = encode(&t);
        let back = decode(&bytes).unwrap();
        assert_eq!(back.header, t.header);
        assert_eq!(back.mesh, t.mesh);
        assert_eq!(back.flags, t.flags);
        assert!((back.segment_weights[1][1] - 0.5).abs() < 1e-4);
        let mut raw = Vec::new();
        flate2::read::GzDecoder::new(&bytes[..])
            .read_to_end(&mut raw)
            .unwrap();
        assert!(decode(&raw[..raw.len() - 1]).is_err());
        assert!(decode(b"nonsense").is_err());
    }

    #[test]
    fn quantised_weights_sum_exactly() {
        let q = quantise(&[0.3333, 0.3333, 0.3334, 0.0, 0.0, 0.0]);
        assert_eq!(q.iter().map(|&x| x as u32).sum::<u32>(), 65535);
    }
}
