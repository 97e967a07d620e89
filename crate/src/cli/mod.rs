//! The native `bodyspace` command-line program: one module per subcommand.

pub mod align;
pub mod batch;
pub mod batch_subjects;
pub mod body;
pub mod build_model;
pub mod export_gltf;
pub mod export_statismo;
pub mod info;
pub mod landmarks;
pub mod manifest;
pub mod manikins;
pub mod measure;
pub mod model;
pub mod project;
pub mod reconstruct;
pub mod subject_args;
pub mod synth;
pub mod template;
pub mod truth;

/// The bytes of a file the user named, or the one-line message for stderr.
pub fn read_file(path: &std::path::Path) -> Result<Vec<u8>, String> {
    std::fs::read(path).map_err(|e| format!("{}: cannot read the file: {e}", path.display()))
}
