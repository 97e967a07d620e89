//! The generic template: body mesh, 73 CAESAR landmarks, virtual landmarks, six overlapping
//! segments with blend weights, and region flags (hands, ears, soles, unseen parts).
//!
//! * [`makehuman`]: reader of the MakeHuman base mesh (CC0 data) into the template frame.
//! * [`frame`]: the template frame transform (metres, y up, feet on y = 0, facing +z).
//! * [`segment`]: the six segments.
//! * [`error`]: the error enum `TemplateError`.

pub mod error;
pub mod frame;
pub mod makehuman;
pub mod segment;

pub use error::TemplateError;
pub use frame::FrameTransform;
pub use makehuman::MakeHumanModel;
pub use segment::Segment;
