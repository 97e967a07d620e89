//! The synthetic population: MakeHuman-based subjects, posed, scanned by a virtual body scanner,
//! with exact ground truth.
//!
//! * [`data`] — loading the MakeHuman package (base mesh, targets, rig);
//! * [`targets`] — MakeHuman's morph-target matrix (`targets.bin`) and its row names;
//! * [`macros`] — macro modifiers (gender, age, muscle, weight, height, proportions) as target weights;
//! * [`population`] — the distributions subjects are drawn from (population profiles);
//! * [`skeleton`] — joints on the morphed body and linear-blend skinning;
//! * [`subject`] — morph, pose, floor and scan one subject;
//! * [`arm_contact`] — arms hanging against the body (the abduction where the skin meets the torso);
//! * [`hand_on_hip`] — hands on hips as a real arm lays them (the elbow's hinge, the hand on the hip);
//! * [`population_run`] — subject `i` of seed `S`, deterministic;
//! * [`random_stream`] — each subject's own random stream;
//! * [`output`] — the output frame and the files written per subject;
//! * [`scanner`] — the virtual CAESAR-like scanner;
//! * [`zoo`] — the scanner zoo: what other scanners deliver (parts, cuts, floors, slices, blobs,
//!   densities, strays) and what people bring to it (arms against the body, an arm raised, hair,
//!   tight clothing).

pub mod arm_contact;
pub mod data;
pub mod error;
pub mod hand_on_hip;
pub mod macros;
pub mod output;
pub mod population;
pub mod population_run;
pub mod random_stream;
pub mod scanner;
pub mod skeleton;
pub mod subject;
pub mod targets;
pub mod zoo;

pub use data::MakeHumanData;
pub use error::SynthError;
pub use output::{LandmarkParams, Units};
pub use population::{sample_subject, PopulationProfile, PoseParams, SubjectParams};
pub use population_run::{population_subject, zoo_subject, SubjectId};
pub use random_stream::subject_rng;
pub use scanner::{scan, Scan, ScannerParams};
pub use subject::{make_subject, Subject};
pub use zoo::{ScannerClass, ZooParams};
