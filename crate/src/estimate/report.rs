//! What a landmark estimate reports, ready for JSON (lengths in mm, times in ms).

use serde::Serialize;

use super::frame::FrameReport;
use super::self_check::SelfCheck;
use super::suspicious::SuspiciousLandmark;
use crate::mesh::floor::FloorRemoval;
use crate::mesh::strays::StrayRemoval;
use crate::mesh::units::Units;

/// One frame candidate after its similarity fit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CandidateReport {
    pub frame: FrameReport,
    /// Where the candidate came from: `"axes"` (principal axes) or `"given landmarks"`.
    pub source: &'static str,
    /// RMS match distance (mm), unmatched vertices counting as the outlier distance.
    pub rms_mm: f64,
    /// Fraction of the sampled template vertices that found a match.
    pub matched: f64,
}

/// One landmark of the estimate.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LandmarkReport {
    pub name: &'static str,
    /// 0..1; 1 for a given landmark.
    pub confidence: f64,
    /// How sharply the landmark's definition pins it on a body: `point`, `prominence` or
    /// `level` (`landmarks/sharpness.rs`); part of the confidence.
    pub sharpness: &'static str,
    /// Taken from the given file, never moved.
    pub given: bool,
    /// Listed in `flagged`.
    pub flagged: bool,
}

/// The whole report of one estimate.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EstimateReport {
    /// The scan's units, as given or detected.
    pub units: Units,
    pub units_detected: bool,
    /// The stray pieces taken off the scan before anything else (`mesh/strays.rs`), if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub strays: Option<StrayRemoval>,
    /// The frame assumed (the best candidate after the whole fit).
    pub frame: FrameReport,
    /// Every candidate tried, by the energy of its similarity fit (the first is `frame`).
    pub candidates: Vec<CandidateReport>,
    /// Landmarks taken from the given file, and estimated.
    pub given: usize,
    pub estimated: usize,
    /// The 73 landmarks in CAESAR order.
    pub landmarks: Vec<LandmarkReport>,
    /// Given landmarks far from where the scan puts them (not used to anchor the fit).
    pub flagged: Vec<SuspiciousLandmark>,
    /// The floor or turntable remnant taken off the scan once the frame was known
    /// (`mesh/floor.rs`), if one was found.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub floor: Option<FloorRemoval>,
    /// The estimate's verdict on itself, with its reasons in words (`self_check.rs`); the
    /// confidences already carry its factor.
    pub self_check: SelfCheck,
    /// RMS distance (mm) of the matched template vertices after the segment-wise fit.
    pub segment_rms_mm: f64,
    /// RMS distance (mm) of the fitted template to the scan after the landmark-free fine fit.
    pub fit_rms_mm: f64,
    /// Iterations of all steps, and whether fine alignment stopped on its iteration limit.
    pub iterations: usize,
    pub candidates_ms: f64,
    pub segments_ms: f64,
    pub fine_ms: f64,
    pub total_ms: f64,
}
