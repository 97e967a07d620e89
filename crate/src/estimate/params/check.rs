//! Parameters of the check of a given landmark file on its own (`check.rs`).

use serde::{Deserialize, Serialize};

/// Parameters of [`crate::estimate::check::check_given`], each with its documented default
/// (lengths in mm, angles in degrees).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct CheckParams {
    /// The body's own variation of a landmark about the prediction from its rigid group (body
    /// shapes differ within a group, a joint is no exact hinge). Default 21 mm: with the
    /// forearm's twist, the smallest step that finds no fewer typos (docs/landmarks-estimate.md,
    /// "False alarms and detection"; 22 mm before the twist).
    pub tolerance_mm: f64,
    /// How many of its definition's spreads (`sharpness.rs`: 5 / 10 / 25 mm) a placed landmark
    /// may lie off. Default 2.
    pub spread_factor: f64,
    /// How many times the RMS misfit of the group's other landmarks (how rigid the group is on
    /// this body) the prediction may be off. Default 2.5.
    pub misfit_factor: f64,
    /// An elbow bent more than this (the upper arm, acromion → the epicondyles' midpoint,
    /// against the forearm's axis) lets the forearm twist: its styloids are predicted turned
    /// about the forearm's axis to the given one's angle (`forearm_twist.rs`). A hand laid on
    /// the hip turns the wrist about the forearm (pronation), which no rigid forearm predicts.
    /// 180 turns it off. Default 60° (straight arms bend 35–43°, hands on hips 53–92°): it
    /// meets the false-alarm goal on hands on hips (docs/landmarks-estimate.md).
    pub twist_min_bend_deg: f64,
    /// A given styloid more than this many times as far from the forearm's axis as its
    /// prediction is not turned to: it is no turned wrist (a styloid of the other side lies
    /// across the body) and is judged against the forearm as it is. Default 2.
    pub twist_max_off_axis: f64,
    /// The Acromion of an arm held raised — its elbow (the humeral epicondyles' midpoint) above
    /// the Suprasternale along the trunk's up (the ASIS' midpoint → Suprasternale) — rises with
    /// the shoulder girdle, which no rigid group holds: this (mm) is added to its tolerance in
    /// quadrature. Default 120 mm: correct raised-arm files had their raised Acromion 44–101 mm
    /// from where the thorax and the upper arm put it (docs/landmarks-estimate.md, "A raised
    /// arm's Acromion in the check"); a swapped pair lies 300 mm and more off.
    pub raised_acromion_mm: f64,
}

impl Default for CheckParams {
    fn default() -> Self {
        Self {
            tolerance_mm: 21.0,
            spread_factor: 2.0,
            misfit_factor: 2.5,
            twist_min_bend_deg: 60.0,
            twist_max_off_axis: 2.0,
            raised_acromion_mm: 120.0,
        }
    }
}
