//! The synthetic population: MakeHuman-based subjects, posed, scanned by a virtual body scanner,
//! with exact ground truth.
//!
//! * [`targets`] — MakeHuman's morph-target matrix (`targets.bin`) and its row names;
//! * [`macros`] — macro modifiers (gender, age, muscle, weight, height, proportions) as target weights;
//! * [`bvh`] — ray casting against a triangle mesh;
//! * [`scanner`] — the virtual CAESAR-like scanner.

pub mod bvh;
pub mod error;
pub mod macros;
pub mod scanner;
pub mod targets;

pub use error::SynthError;
pub use scanner::{scan, Scan, ScannerParams};
