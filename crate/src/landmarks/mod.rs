//! Anatomical landmarks: the CAESAR list, how sharply each is defined, name normalisation,
//! and landmark sets (the data; the estimate of the landmarks on a bare scan is `crate::estimate`),
//! and the shoulder's rule that places the Acromion on a body's own surface ([`shoulder`]).

pub mod caesar;
pub mod head_pitch;
pub mod names;
pub mod report;
pub mod set;
pub mod sharpness;
pub mod shoulder;
pub mod virtual_landmarks;

pub use caesar::{caesar_index, CaesarLandmark, CAESAR_LANDMARKS, CAESAR_LANDMARK_COUNT};
pub use names::canonical_name;
pub use report::{report, LandmarkReport};
pub use set::{Landmark, LandmarkSet};
pub use sharpness::{definition_sharpness, DefinitionSharpness, DEFINITION_SHARPNESS};
pub use virtual_landmarks::{
    virtual_landmarks, virtual_landmarks_detailed, VirtualLandmark, VIRTUAL_LANDMARK_COUNT,
    VIRTUAL_PREFIX,
};
