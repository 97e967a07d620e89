//! Every choice of the path from files to a fit, with its default: the alignment's parameters,
//! whether given landmarks are checked, the quality thresholds, the landmark estimate's
//! parameters and what counts as a stray piece of the scan. `bodyspace align` and `bodyspace batch` share their flags for these
//! (`cli/subject_args.rs`); the app sends the same fields as JSON.

use serde::{Deserialize, Serialize};

use crate::align::{AlignParams, QualityThresholds};
use crate::estimate::Orientation;
use crate::mesh::floor::FloorParams;
use crate::mesh::strays::StrayParams;

pub use crate::estimate::check::NEARLY_FULL;

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SubjectOptions {
    /// RBF warp and fine alignment (`align/params.rs`; default: the `paper` preset).
    pub params: AlignParams,
    /// Check given landmarks and leave the suspicious ones out of the warp (default true).
    pub check_landmarks: bool,
    /// When a fit is flagged (`align/quality.rs`).
    pub thresholds: QualityThresholds,
    /// A landmark file with at least this many of the 73 CAESAR landmarks is nearly full (a
    /// CAESAR file missing a few): it is checked, not filled in, and its missing landmarks stay
    /// absent. Default [`NEARLY_FULL`], 64.
    pub nearly_full: usize,
    /// Which way is up on the scans (and which way they face), when a person said so; the
    /// landmark estimate then tries only that frame. Default `None`: the estimate finds it.
    pub orientation: Option<Orientation>,
    /// The floor or turntable remnant under the feet, taken off the scan once the landmarks say
    /// which way is up (`mesh/floor.rs`; its defaults there).
    pub floor: FloorParams,
    /// Small pieces floating off the body, taken off the scan before the fit
    /// (`mesh/strays.rs`; its defaults there), as the landmark estimate takes them off.
    pub strays: StrayParams,
}

impl Default for SubjectOptions {
    fn default() -> Self {
        Self {
            params: AlignParams::default(),
            check_landmarks: true,
            thresholds: QualityThresholds::default(),
            nearly_full: NEARLY_FULL,
            orientation: None,
            floor: FloorParams::default(),
            strays: StrayParams::default(),
        }
    }
}
