//! Parameters of the limbs' cross-section profiles (`profile.rs`).

use serde::{Deserialize, Serialize};

/// Parameters of a limb's profile and its registration, [`super::EstimateParams::profile`].
/// Fractions are of the limb's line (root 0, end 1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ProfileParams {
    /// Bins of a profile from the root of the limb (hip) to its end (ankle). Default 60.
    pub bins: usize,
    /// A bin with fewer points than this has no width. Default 6.
    pub min_points: usize,
    /// The fractions of the limb over which the profiles are compared: below the crotch and the
    /// hands hanging beside the thigh, above the foot. Default 0.3–0.92.
    pub window: (f64, f64),
    /// How far (fraction of the limb) the knee may move from where the fit put it. Default 0.08.
    pub search: f64,
    /// How far (fraction of the limb) from the knee the fall of the leg's front below the
    /// patella is looked for (the template's: from its knee; the scan's: from where the width's
    /// profile put it). Default 0.08.
    pub front_search: f64,
    /// Shifts tried when a profile is registered by a shift alone (the wrist's). Default 90.
    pub shift_steps: usize,
}

impl Default for ProfileParams {
    fn default() -> Self {
        Self {
            bins: 60,
            min_points: 6,
            window: (0.3, 0.92),
            search: 0.08,
            front_search: 0.08,
            shift_steps: 90,
        }
    }
}
