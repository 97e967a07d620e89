//! BodySpace core: turns raw 3D body scans into a consistent, statistically analysable form.
//!
//! Implements "Consistent parameterization and statistical analysis of segmented human body
//! scans" (GI 2007): RBF rough deformation of a generic template from landmark pairs (§3.1),
//! fine alignment by per-vertex affine transforms (§3.2), and PCA shape spaces of the whole body
//! and of six overlapping segments (§4, [`pca`]); above them, anthropometry on a model
//! ([`anthropometry`]) and the model file formats ([`model_file`]).
//!
//! The core knows nothing of the web: everything here compiles and is tested natively. The
//! `bindings` module (wasm32 only) is the one thin layer that exposes it to JavaScript.

pub mod align;
pub mod anthropometry;
pub mod estimate;
pub mod io;
pub mod landmarks;
pub mod measure;
pub mod mesh;
pub mod model_file;
pub mod pca;
pub mod rbf;
pub mod subject;
pub mod synth;
pub mod template;
pub mod utils;

#[cfg(target_arch = "wasm32")]
pub mod bindings;

#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
