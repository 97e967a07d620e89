//! Anatomical landmarks: the CAESAR list, name normalisation and landmark sets.

pub mod caesar;
pub mod set;

pub use caesar::{CaesarLandmark, CAESAR_LANDMARKS, CAESAR_LANDMARK_COUNT};
pub use set::{Landmark, LandmarkSet};
