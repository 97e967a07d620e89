//! Parameters of the hand's pose about the wrist (`hand/`). Lengths are metres, angles degrees.

use serde::{Deserialize, Serialize};

/// Parameters of the hands' pose, [`super::EstimateParams::hand`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct HandParams {
    /// The wrist slides at most this far along the forearm. Default 6 cm.
    pub max_slide: f64,
    /// The region compared beyond the wrist: its radius about the wrist, times the template
    /// hand's reach (its farthest vertex from the wrist). Default 1.2.
    pub reach: f64,
    /// The surface compared starts this far beyond the wrist's plane: the forearm's skin just
    /// below the wrist stays out whatever the hand's pose. Default 1 cm.
    pub beyond: f64,
    /// A hand-like cluster has this range of area, relative to the template's hand surface in
    /// the same region. Default 0.6–1.5 (on the development subjects free hands have
    /// 0.73–1.07, a hand on the hip 1.8).
    pub area_range: (f64, f64),
    /// A larger turn of a free hand is not believed: a hand's flexion or deviation at the wrist
    /// is within it, a match to the thigh or the hip often is not. Default 60°.
    pub max_turn_deg: f64,
    /// A free hand's fingertip is the scan's farthest point beyond the wrist within this
    /// distance of the template hand's farthest vertex (`hand/length.rs`). Default 6 cm.
    pub fingertip_search: f64,
    /// The hand is stretched to the scan's fingertip only when it lies less than this farther or
    /// nearer than the template's: farther, it is the thigh beside the hand, or a blob's swollen
    /// surface. Default 1.5 cm (on the tuning zoo 4242 free hands' fingertips lay 3–12 mm beyond
    /// the estimate's, those of hands beside the thigh 40–60 mm; at 2.5 cm the `blob` scans'
    /// landmarks were worse, 11.9 → 12.1 mm on subjects 3–8).
    pub fingertip_gate: f64,
    /// The forearm's width profile (the wrist's slide).
    pub profile: WristProfileParams,
    /// A hand laid on the body.
    pub laid: LaidHandParams,
}

impl Default for HandParams {
    fn default() -> Self {
        Self {
            max_slide: 0.06,
            reach: 1.2,
            beyond: 0.01,
            area_range: (0.6, 1.5),
            max_turn_deg: 60.0,
            fingertip_search: 0.06,
            fingertip_gate: 0.015,
            profile: WristProfileParams::default(),
            laid: LaidHandParams::default(),
        }
    }
}

/// Parameters of the wrist's place from the forearm's width profile (`hand/wrist_profile.rs`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct WristProfileParams {
    /// The profile runs from the elbow this many times the way to the wrist, over the hand.
    /// Default 1.6.
    pub line: f64,
    /// Points farther from the forearm's line are not the forearm or the hand. Default 6 cm.
    pub radius: f64,
    /// Points spread this far apart over the surfaces profiled. Default 4 mm.
    pub spacing: f64,
    /// The part of the template's profile (m from its wrist) registered to the scan's: the
    /// forearm's narrowing to the wrist and the hand widening out of it. Default −6 cm to
    /// +5 cm.
    pub window: (f64, f64),
}

impl Default for WristProfileParams {
    fn default() -> Self {
        Self {
            line: 1.6,
            radius: 0.06,
            spacing: 0.004,
            window: (-0.06, 0.05),
        }
    }
}

/// Parameters of a hand laid on the body (`hand/laid.rs`, `hand/laid_wrist.rs`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct LaidHandParams {
    /// An arm bent more than this (degrees, the upper arm from the acromion against the
    /// forearm) but not more than the segments' `max_bend_deg` has its hand laid on the body
    /// when the hand is not free and the forearm comes down onto the body and levels out onto
    /// it: a hand on the hip with the elbow bent less (held-out seed 3737: 53°). Default 48°
    /// (straight arms measure 35–43°, the acromion lying out from the humerus's axis; hands on
    /// the hips 53–86°).
    pub min_bend_deg: f64,
    /// The scan's points within this distance of the wrist, and farther than
    /// `forearm_clearance` from the forearm, are the body under the hand and the hand on it.
    /// Default 15 cm.
    pub region: f64,
    /// Points nearer than this to the forearm (the segment from the elbow to the wrist) are the
    /// forearm's own. Default 5 cm.
    pub forearm_clearance: f64,
    /// The strip a laid hand covers along its direction from the wrist (the palm and the
    /// fingers). Default 4–14 cm.
    pub strip: (f64, f64),
    /// Half the strip's width. Default 3 cm.
    pub strip_half_width: f64,
    /// The strip's top is taken every this far along it. Default 1 cm.
    pub bin: f64,
    /// Directions tried, evenly around the wrist in the body's tangent plane. Default 24.
    pub directions: usize,
    /// A laid hand's direction is at most this far (degrees) from the forearm's. Default 75°
    /// (a wrist extends to ≈ 70°).
    pub max_bend_deg: f64,
    /// Where the forearm levels out onto the hand: its heights are taken from this fraction of
    /// the way from the elbow ... Default 0.4.
    pub knee_from: f64,
    /// ... to this far past the wrist. Default 8.5 cm.
    pub knee_beyond: f64,
    /// ... every this far. Default 4 mm.
    pub knee_step: f64,
    /// ... of the points within this distance of its axis. Default 8 cm.
    pub knee_radius: f64,
    /// The knee needs this many heights on either side. Default 6.
    pub knee_min_heights: usize,
    /// The forearm must fall at least this much (degrees) more steeply than the hand. Default
    /// 10°.
    pub knee_turn_deg: f64,
}

impl Default for LaidHandParams {
    fn default() -> Self {
        Self {
            min_bend_deg: 48.0,
            region: 0.15,
            forearm_clearance: 0.05,
            strip: (0.04, 0.14),
            strip_half_width: 0.03,
            bin: 0.01,
            directions: 24,
            max_bend_deg: 75.0,
            knee_from: 0.4,
            knee_beyond: 0.085,
            knee_step: 0.004,
            knee_radius: 0.08,
            knee_min_heights: 6,
            knee_turn_deg: 10.0,
        }
    }
}
