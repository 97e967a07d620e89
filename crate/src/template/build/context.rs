//! What every build step needs: the oriented body skin, its skinning and joints.

use nalgebra::{Point3, Vector3};

use super::super::error::TemplateError;
use super::super::makehuman::MakeHumanModel;
use super::super::segment::Segment;
use crate::mesh::normals::vertex_normals;
use crate::mesh::topology::vertex_neighbours;
use crate::mesh::volume::signed_volume;
use crate::mesh::Mesh;

/// The body skin with per-vertex skinning and the joint positions, in the template frame.
pub struct BuildContext<'a> {
    pub model: &'a MakeHumanModel,
    pub mesh: Mesh,
    /// MakeHuman vertex index of each template vertex.
    pub provenance: Vec<u32>,
    pub normals: Vec<Vector3<f64>>,
    pub neighbours: Vec<Vec<u32>>,
    /// Whether the triangles had to be flipped to point outward.
    pub flipped: bool,
}

impl<'a> BuildContext<'a> {
    /// Extracts the body skin and orients it outward (positive signed volume).
    pub fn new(model: &'a MakeHumanModel) -> Result<Self, TemplateError> {
        let (mut mesh, provenance) = model.body_skin()?;
        if model.skin_indices.is_empty() {
            return Err(TemplateError::Model("no skin weights".into()));
        }
        let flipped = signed_volume(&mesh.positions, &mesh.triangles) < 0.0;
        if flipped {
            for t in &mut mesh.triangles {
                t.swap(1, 2);
            }
        }
        let normals = vertex_normals(&mesh.positions, &mesh.triangles);
        let neighbours = vertex_neighbours(mesh.positions.len(), &mesh.triangles);
        Ok(Self {
            model,
            mesh,
            provenance,
            normals,
            neighbours,
            flipped,
        })
    }

    pub fn vertex_count(&self) -> usize {
        self.mesh.positions.len()
    }

    pub fn p(&self, v: u32) -> Point3<f64> {
        self.mesh.positions[v as usize]
    }

    /// A joint position, e.g. `"upperarm01.L____head"`.
    pub fn joint(&self, name: &str) -> Result<Point3<f64>, TemplateError> {
        self.model
            .joint_position(name)
            .ok_or_else(|| TemplateError::MissingJoint(name.to_string()))
    }

    /// Sum of vertex `v`'s skin weights on bones whose name satisfies `pred`.
    pub fn bone_weight(&self, v: u32, pred: impl Fn(&str) -> bool) -> f64 {
        let mv = self.provenance[v as usize] as usize;
        let idx = self.model.skin_indices[mv];
        let w = self.model.skin_weights[mv];
        (0..4)
            .filter(|&k| {
                self.model
                    .bones
                    .get(idx[k] as usize)
                    .is_some_and(|b| pred(&b.name))
            })
            .map(|k| w[k] as f64)
            .sum()
    }

    /// Skin weight of vertex `v` summed per segment (bones mapped by [`bone_segment`]).
    pub fn segment_skin_weights(&self, v: u32) -> [f64; 6] {
        let mv = self.provenance[v as usize] as usize;
        let idx = self.model.skin_indices[mv];
        let w = self.model.skin_weights[mv];
        let mut out = [0.0; 6];
        for k in 0..4 {
            if let Some(b) = self.model.bones.get(idx[k] as usize) {
                out[bone_segment(&b.name).index()] += w[k] as f64;
            }
        }
        out
    }
}

/// Name prefixes of the MakeHuman arm bones (shoulder to fingertips), either side.
pub const ARM_BONES: &[&str] = &[
    "shoulder",
    "upperarm",
    "lowerarm",
    "wrist",
    "finger",
    "metacarpal",
];

/// The segment a MakeHuman bone belongs to. Neck: `neck01` stays with the torso so that the
/// head/torso boundary falls mid-neck (Cervicale in the torso, Gonion in the head).
pub fn bone_segment(bone: &str) -> Segment {
    let name = bone.split("____").next().unwrap_or(bone);
    let left = name.ends_with(".L");
    let right = name.ends_with(".R");
    let starts = |prefixes: &[&str]| prefixes.iter().any(|p| name.starts_with(p));
    if starts(ARM_BONES) {
        if right {
            return Segment::RightArm;
        }
        if left {
            return Segment::LeftArm;
        }
    }
    if starts(&["upperleg", "lowerleg", "foot", "toe"]) {
        if right {
            return Segment::RightLeg;
        }
        if left {
            return Segment::LeftLeg;
        }
    }
    if starts(&[
        "neck02",
        "neck03",
        "head",
        "jaw",
        "eye",
        "tongue",
        "levator",
        "special",
        "temporalis",
        "oris",
        "oculi",
        "orbicularis",
        "risorius",
    ]) {
        return Segment::Head;
    }
    Segment::Torso
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bones_map_to_segments() {
        assert_eq!(bone_segment("finger3-2.L"), Segment::LeftArm);
        assert_eq!(bone_segment("upperarm01.R____head"), Segment::RightArm);
        assert_eq!(bone_segment("toe1-1.R"), Segment::RightLeg);
        assert_eq!(bone_segment("neck01"), Segment::Torso);
        assert_eq!(bone_segment("jaw"), Segment::Head);
        assert_eq!(bone_segment("clavicle.L"), Segment::Torso);
        assert_eq!(bone_segment("pelvis.L"), Segment::Torso);
    }
}
