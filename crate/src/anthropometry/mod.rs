//! Anthropometry on a shape model ([`crate::pca`]): the model's population read as
//! measurements ([`crate::measure`]).
//!
//! * [`measurement_distribution`] — every measurement over the training subjects and sampled
//!   bodies: percentiles, histograms, correlations, a body's percentile
//! * [`from_measurements`] — the most likely body with given measurements (least Mahalanobis norm)
//! * [`segment_targets`] — targets of a segment acting on its model; which measurements belong
//!   to which segment
//! * [`boundary_manikins`] — the bodies on the boundary of a coverage region of 2–4 measurements
//! * [`outliers`] — training subjects far outside the model (Mahalanobis distance of their scores)
//! * [`chi_square`] — normal and χ² quantiles

pub mod boundary_manikins;
pub mod chi_square;
pub mod from_measurements;
pub mod measurement_distribution;
pub mod outliers;
pub mod segment_targets;
