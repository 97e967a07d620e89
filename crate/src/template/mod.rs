//! The generic template: body mesh, 73 CAESAR landmarks, six overlapping segments with blend
//! weights, and region flags (hands, ears, soles, unseen parts). See `docs/template.md`.
//!
//! * [`model`]: the [`Template`] type and its accessors; [`resolution`]: base / fine.
//! * [`subdivide`]: the linear subdivision operator base → fine.
//! * [`store`]: the stored file format; [`flags`]: region flag bits.
//! * [`makehuman`]: reader of the MakeHuman base mesh (CC0 data) into the template frame.
//! * [`frame`]: the template frame transform (metres, y up, feet on y = 0, facing +z).
//! * [`build`]: the tool that made the stored template (landmark rules, segments, flags).
//! * [`topology`]: signed volume, edge distance.
//! * [`segment`]: the six segments; [`error`]: the error enum `TemplateError`.
//! * [`body_part`]: head, torso, arms, hands, legs, feet per vertex, for reports.
//! * [`parts`]: the rigid parts (segments split at elbow and knee), their poses and blend;
//!   [`hand`]: each hand's vertices and its turn about the wrist; [`face`]: its nose tip.
//! * `fixture` (tests only): the base template with its parts and hands, as unit tests take it.

pub mod body_part;
pub mod build;
pub mod error;
pub mod face;
#[cfg(test)]
pub(crate) mod fixture;
pub mod flags;
pub mod foot;
pub mod frame;
pub mod hand;
pub mod makehuman;
pub mod model;
pub mod parts;
pub mod resolution;
pub mod segment;
pub mod store;
pub mod subdivide;
pub mod topology;

pub use body_part::{body_parts, BodyPart};
pub use error::TemplateError;
pub use flags::RegionFlags;
pub use frame::FrameTransform;
pub use makehuman::MakeHumanModel;
pub use model::Template;
pub use resolution::Resolution;
pub use segment::Segment;
pub use subdivide::Subdivision;
