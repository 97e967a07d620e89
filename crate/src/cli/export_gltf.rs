//! `bodyspace export-gltf --model MODEL --out FILE.glb [--parts whole|all] [--modes N]`: a model
//! file as binary glTF with its modes as morph targets (`model_file::gltf`).

use super::model::load_model;
use crate::model_file::gltf::{model_glb, parts_glb};
use std::path::PathBuf;

/// Which models go into the GLB.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parts {
    /// The whole-body model alone (one mesh `body`).
    Whole,
    /// The whole-body model and the six segment models (seven meshes).
    All,
}

/// Arguments of `bodyspace export-gltf`.
#[derive(clap::Args, Debug)]
pub struct ExportGltfArgs {
    /// The model file.
    #[arg(long)]
    pub model: PathBuf,
    /// The GLB file to write.
    #[arg(long)]
    pub out: PathBuf,
    /// `whole`: the whole-body model; `all`: whole body + six segments, one mesh each.
    #[arg(long, value_enum, default_value_t = Parts::All)]
    pub parts: Parts,
    /// Morph targets per model (default: every kept mode).
    #[arg(long)]
    pub modes: Option<usize>,
}

/// Runs `bodyspace export-gltf`; prints `{out, bytes, meshes, modes}`.
pub fn run(args: &ExportGltfArgs) -> Result<(), String> {
    let (model, _) = load_model(&args.model)?;
    let modes = args.modes.unwrap_or(usize::MAX);
    let glb = match args.parts {
        Parts::Whole => model_glb(&model, modes),
        Parts::All => parts_glb(&model, modes),
    };
    std::fs::write(&args.out, &glb).map_err(|e| format!("{}: {e}", args.out.display()))?;
    let parts: Vec<_> = std::iter::once(("whole", &model.whole))
        .chain(
            crate::template::Segment::ALL
                .iter()
                .map(|s| (s.name(), model.segment(*s))),
        )
        .take(if args.parts == Parts::All { 7 } else { 1 })
        .map(|(name, m)| serde_json::json!({"name": name, "vertices": m.vertex_count(), "morph_targets": modes.min(m.mode_count())}))
        .collect();
    println!(
        "{}",
        serde_json::json!({"out": args.out.display().to_string(), "bytes": glb.len(), "meshes": parts})
    );
    Ok(())
}
