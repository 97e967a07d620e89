//! The native `bodyspace` command-line program: one module per subcommand.

pub mod align;
pub mod batch;
pub mod batch_subjects;
pub mod build_model;
pub mod export_gltf;
pub mod info;
pub mod landmarks;
pub mod manifest;
pub mod model;
pub mod project;
pub mod reconstruct;
pub mod synth;
pub mod template;
