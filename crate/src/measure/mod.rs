//! Anthropometry: standard body measurements after ISO 8559-1 and ISO 7250-1 on a body in
//! template vertex order, anchored on the template's landmarks (docs/measurements.md).
//!
//! * [`definitions`] — the [`Measure`] table: names, kinds, sources, landmarks
//! * [`acromion`] — the acromia found on the body's surface around the Acromion vertices
//!   (shoulder breadth, acromion height, arm length), by the shoulder's rule the estimate shares
//! * [`parting`] — levels where a section's loops part, found on the surface: the armpits' apex
//!   (the chest girth's level) and the crotch (crotch height, the thigh girth's level)
//! * [`cervicale`] — the cervicale found on the body's back profile, where the back turns into
//!   the neck (cervicale height)
//! * [`section`] — plane sections of a triangle mesh ([`Plane`], [`plane_section`])
//! * `spans` — each triangle's span along the up axis, so that a horizontal section is cut from
//!   the triangles that reach its plane alone
//! * [`surface`] — body points found on the surface around a landmark's guess: the prominence,
//!   the buttocks' level, the neck's narrowest level
//! * [`tape`] — a tape around a section: convex-hull perimeter of the chosen loop
//! * [`neck_base`] — the neck base girth's tape over the Cervicale, the side neck points and
//!   the front neck point
//! * [`body`] — [`BodyMeasurer`]: every measurement of a body
//! * [`levels`] — one body being measured and the levels its measurements share
//! * [`measurements`] — what measuring gives: [`Measurements`], [`Reading`], [`TapePath`]
//! * [`upright`] — a body in any frame moved rigidly onto the template's
//! * [`params`] — [`MeasureParams`], the plane offsets and up axis with their defaults
//! * [`tolerance`] — ISO 20685-1's limit per measurement ([`IsoClass`]) and its verdict on a set
//!   of differences ([`Agreement`])
//! * [`trust`] — [`measurements_trust`]: each measurement of a fit placed, body-defined or
//!   estimated from where its landmarks came, with its expected error against ISO 20685-1, and
//!   a body-defined one doubtful where the fit there is not the scan's
//! * [`support`] — [`measurements_support`]: whether the scan is under a fit where each
//!   body-defined measurement is taken
//! * [`fit_error`] — [`FitErrors`]: the fit's own error of each measurement, measured
//! * `vec3` — the 3-vector operations the searches share
//! * [`error`] — [`MeasureError`]
//!
//! Volume and surface area are [`crate::mesh::volume`].

pub mod acromion;
pub mod body;
pub mod cervicale;
pub mod definitions;
pub mod error;
pub mod fit_error;
mod levels;
pub mod measurements;
pub mod neck_base;
pub mod params;
pub mod parting;
pub mod section;
mod spans;
pub mod support;
pub mod surface;
pub mod tape;
pub mod tolerance;
pub mod trust;
pub mod upright;
mod vec3;

pub use body::BodyMeasurer;
pub use definitions::{Anchoring, Definition, Kind, Measure};
pub use error::MeasureError;
pub use fit_error::{FitError, FitErrors};
pub use measurements::{Measurements, Reading, TapePath};
pub use params::MeasureParams;
pub use section::{plane_section, Plane, SectionLoop};
pub use support::{measurements_support, At, Support, SupportParams};
pub use tolerance::{Agreement, IsoClass};
pub use trust::{
    acromion_sides, measurement_trust, measurements_trust, note_acromia_on_vertices,
    MeasurementTrust, Origin, Trust, TrustParams,
};
pub use upright::upright;
