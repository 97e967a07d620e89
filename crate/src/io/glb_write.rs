//! The binary glTF 2.0 container (GLB): a JSON chunk and one BIN chunk holding every array.
//!
//! [`GlbWriter`] appends f32 VEC3 and u32 index arrays to the binary buffer (each 4-byte
//! aligned, with its own buffer view and accessor) and [`GlbWriter::finish`] completes the
//! caller's document with `buffers`, `bufferViews` and `accessors` and writes
//! `glTF` header (12 bytes) + JSON chunk (padded with spaces) + BIN chunk (padded with zeros).

use serde_json::{json, Value};

const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;

/// Builds the binary buffer and its accessors; see the module docs.
#[derive(Debug, Default)]
pub struct GlbWriter {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
}

impl GlbWriter {
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds `xyz` (`[x0, y0, z0, x1, …]`, f32) as a VEC3 accessor with its `min`/`max` (which
    /// glTF requires for POSITION and morph-target POSITION); returns the accessor index.
    pub fn vec3(&mut self, xyz: &[f32]) -> usize {
        let (min, max) = bounds(xyz);
        let view = self.view(
            xyz.iter().flat_map(|x| x.to_le_bytes()).collect(),
            ARRAY_BUFFER,
        );
        self.accessors.push(json!({
            "bufferView": view, "componentType": FLOAT, "count": xyz.len() / 3,
            "type": "VEC3", "min": min, "max": max,
        }));
        self.accessors.len() - 1
    }

    /// Adds triangle vertex indices as a u32 SCALAR accessor; returns the accessor index.
    pub fn indices(&mut self, indices: &[u32]) -> usize {
        let view = self.view(
            indices.iter().flat_map(|i| i.to_le_bytes()).collect(),
            ELEMENT_ARRAY_BUFFER,
        );
        self.accessors.push(json!({
            "bufferView": view, "componentType": UNSIGNED_INT, "count": indices.len(), "type": "SCALAR",
        }));
        self.accessors.len() - 1
    }

    fn view(&mut self, bytes: Vec<u8>, target: u32) -> usize {
        self.views.push(json!({
            "buffer": 0, "byteOffset": self.bin.len(), "byteLength": bytes.len(), "target": target,
        }));
        self.bin.extend_from_slice(&bytes);
        self.views.len() - 1
    }

    /// The GLB bytes of `document` (an object: asset, scenes, nodes, meshes, …) completed
    /// with the buffer, its views and the accessors.
    pub fn finish(self, mut document: Value) -> Vec<u8> {
        let mut bin = self.bin;
        document["buffers"] = json!([{ "byteLength": bin.len() }]);
        document["bufferViews"] = Value::Array(self.views);
        document["accessors"] = Value::Array(self.accessors);
        let mut json_bytes = serde_json::to_vec(&document).unwrap_or_default();
        while json_bytes.len() % 4 != 0 {
            json_bytes.push(b' ');
        }
        while bin.len() % 4 != 0 {
            bin.push(0);
        }
        let total = 12 + 8 + json_bytes.len() + 8 + bin.len();
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&(total as u32).to_le_bytes());
        out.extend_from_slice(&(json_bytes.len() as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(&json_bytes);
        out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&bin);
        out
    }
}

/// Per-axis min and max of flat xyz (zeros when empty).
fn bounds(xyz: &[f32]) -> ([f32; 3], [f32; 3]) {
    if xyz.is_empty() {
        return ([0.0; 3], [0.0; 3]);
    }
    let mut min = [f32::INFINITY; 3];
    let mut max = [f32::NEG_INFINITY; 3];
    for p in xyz.chunks_exact(3) {
        for a in 0..3 {
            min[a] = min[a].min(p[a]);
            max[a] = max[a].max(p[a]);
        }
    }
    (min, max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_triangle_makes_a_well_formed_glb() {
        let mut glb = GlbWriter::new();
        let position = glb.vec3(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 2.0, 0.0]);
        let indices = glb.indices(&[0, 1, 2]);
        let bytes = glb.finish(json!({
            "asset": {"version": "2.0"},
            "meshes": [{"primitives": [{"attributes": {"POSITION": position}, "indices": indices}]}],
        }));
        let word = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
        assert_eq!(&bytes[..4], b"glTF");
        assert_eq!(word(8), bytes.len());
        let json_len = word(12);
        assert_eq!(json_len % 4, 0);
        let doc: Value = serde_json::from_slice(&bytes[20..20 + json_len]).unwrap();
        assert_eq!(doc["accessors"][0]["max"], json!([1.0, 2.0, 0.0]));
        assert_eq!(doc["accessors"][1]["count"], 3);
        assert_eq!(doc["bufferViews"][1]["byteOffset"], 36);
        assert_eq!(word(20 + json_len), 48);
        assert_eq!(doc["buffers"][0]["byteLength"], 48);
    }
}
