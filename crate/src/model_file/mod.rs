//! The file formats of a shape model ([`crate::pca::BodyModel`]).
//!
//! * [`file`] — the versioned `.bsm` model file ([`f16`] for the compact basis)
//! * [`statismo`] — a model as statismo's HDF5 datasets (what Scalismo and exploreCOSMOS read),
//!   and a statismo model opened on the template
//! * [`gltf`] — the whole-body model, or all seven models, as GLB with modes as morph targets
//! * [`export`] — eigenvalues, scores and quality curves as CSV

pub mod export;
pub mod f16;
pub mod file;
pub mod gltf;
pub mod statismo;
