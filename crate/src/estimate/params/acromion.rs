//! Parameters of the Acromions' search on the scan's surface (`acromion.rs`). Lengths are
//! metres at the template's size (times the body's scale on a scan), angles degrees.

use serde::{Deserialize, Serialize};

/// Parameters of [`crate::estimate::acromion`], [`super::EstimateParams::acromion`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct AcromionParams {
    /// Only the surface within this distance of the fit's Acromion is searched. Default 35 mm
    /// (the accepted point then lies within 25 mm of the fit's): the fit's Acromions lay 23 mm
    /// from the true ones on average on the development subjects, mostly sliding along the
    /// shoulder's cap. The Acromions' mean error on the development seeds 2026, 101 and 202
    /// (22.7 mm without the search): 30 mm 18.3, 35 mm 18.3, 45 mm 19.1 (the search runs along
    /// the arm more often).
    pub radius: f64,
    /// A shoulder point found nearer the window's edge than this is not sure (the surface still
    /// rises beyond the window in the search's direction: a raised arm's top); the fit's guess
    /// is kept. Default 10 mm.
    pub edge: f64,
    /// The shoulder point is the centroid of the surface within this distance of its highest
    /// point in the search's direction (not one noisy vertex). Default 4 mm.
    pub cap: f64,
    /// Spacing of the points taken on the surface's triangles (the scan's and the template's
    /// near the shoulder). Default 3 mm: a decimated scan's vertices lie centimetres apart.
    pub spacing: f64,
    /// Fewer surface points than this in the window: no search (a hole, a cut scan). Default 50.
    pub min_points: usize,
    /// An upper arm raised more than this from hanging down (in the trunk's frontal plane) has no
    /// shoulder point (the shoulder's top runs on along the arm): the fit's guess is kept.
    /// Default 30°: 35° gave 18.8 mm on the development seeds (above) against 18.3; at 60°
    /// (and a 60 mm window) the search ran along arms held out (the turn is shallow there) and
    /// made them worse.
    pub max_abduction_deg: f64,
    /// How much of the fit's guess front to back is kept (1: all, 0: the shoulder point's).
    /// Default 1: the cap's crest lay further back than the fit's guess (the mean error on the
    /// development seeds, 45 mm window: 20.2 mm with the crest's, 19.1 with the fit's).
    pub keep_forward: f64,
    /// The confidence of an Acromion left at the fit's guess is multiplied by this. Default 0.7
    /// (a choice, not tuned: the fallen-back Acromions are the larger errors, and the
    /// typical-error table is their mean with the found ones).
    pub fallback_confidence: f64,
}

impl Default for AcromionParams {
    fn default() -> Self {
        Self {
            radius: 0.035,
            edge: 0.01,
            cap: 0.004,
            spacing: 0.003,
            min_points: 50,
            max_abduction_deg: 30.0,
            keep_forward: 1.0,
            fallback_confidence: 0.7,
        }
    }
}
