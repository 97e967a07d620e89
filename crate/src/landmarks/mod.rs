//! Anatomical landmarks: the CAESAR list, name normalisation and landmark sets.

pub mod caesar;
pub mod names;
pub mod report;
pub mod set;

pub use caesar::{CaesarLandmark, CAESAR_LANDMARKS, CAESAR_LANDMARK_COUNT};
pub use names::canonical_name;
pub use report::{report, LandmarkReport};
pub use set::{Landmark, LandmarkSet};
