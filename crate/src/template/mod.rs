//! The generic template: body mesh, 73 CAESAR landmarks, virtual landmarks, six overlapping
//! segments with blend weights, and region flags (hands, ears, soles, unseen parts).

pub mod segment;

pub use segment::Segment;
