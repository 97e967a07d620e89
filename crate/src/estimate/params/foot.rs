//! Parameters of the feet's pose about the ankle (`foot.rs`). Lengths are metres, angles degrees.

use serde::{Deserialize, Serialize};

/// Parameters of the feet's pose, [`super::EstimateParams::foot`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct FootParams {
    /// Rounds of matching the foot's vertices and moving it rigidly onto their matches. Default
    /// 8.
    pub iterations: usize,
    /// A foot with fewer of its own vertices matched than this share is not moved: the scanner
    /// cut it off, or it stands in a hole. Default 0.3.
    pub min_matched: f64,
    /// A larger turn about the ankle is not believed. Default 25°.
    pub max_turn_deg: f64,
    /// A larger shift of the ankle is not believed. Default 4 cm.
    pub max_shift: f64,
}

impl Default for FootParams {
    fn default() -> Self {
        Self {
            iterations: 8,
            min_matched: 0.3,
            max_turn_deg: 25.0,
            max_shift: 0.04,
        }
    }
}
