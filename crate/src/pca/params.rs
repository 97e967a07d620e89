//! The parameters of a model build ([`BuildParams`]), with their documented defaults; recorded
//! in the model file.

use serde::{Deserialize, Serialize};

use super::metrics::QualityParams;
use super::procrustes_gpa::GpaParams;

/// Parameters of [`super::build_body_model`]; recorded in the model file.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BuildParams {
    /// Keep the leading modes explaining this fraction of the variance; default 0.99 (issue 6).
    /// Never more than N−1 modes.
    pub variance: f64,
    /// Optional hard cap on the modes kept per model; default none.
    pub max_modes: Option<usize>,
    /// Keep exactly this many leading modes per model (capped by the N−1 that exist),
    /// overriding `variance` and `max_modes`; default none. Files written before this field
    /// existed read as `None`.
    #[serde(default)]
    pub modes: Option<usize>,
    /// Pose removal before PCA; default rigid (rotation + translation).
    pub gpa: GpaParams,
    /// Compute the quality curves (the expensive part of a build); default true.
    pub compute_quality: bool,
    pub quality: QualityParams,
}

impl Default for BuildParams {
    fn default() -> Self {
        Self {
            variance: 0.99,
            max_modes: None,
            modes: None,
            gpa: GpaParams::default(),
            compute_quality: true,
            quality: QualityParams::default(),
        }
    }
}
