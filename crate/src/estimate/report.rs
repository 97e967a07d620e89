//! What a landmark estimate reports, ready for JSON (lengths in mm, times in ms).

use serde::Serialize;

use super::frame::FrameReport;
use super::orientation::Orientation;
use super::self_check::SelfCheck;
use super::suspicious::SuspiciousLandmark;
use crate::mesh::floor::FloorRemoval;
use crate::mesh::strays::StrayRemoval;
use crate::mesh::units::Units;
use crate::mesh::winding::Reorientation;

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

/// What said which way is up and which way the body faces, in words the app shows as they are:
/// `"chosen"` (the person's orientation), `"given landmarks"`, `"the scan's shape"` (the head's
/// end narrower than the feet's, up only), `"the feet"` or `"the legs"` (facing only), or `"the
/// fits"` (the frame candidates' fits alone).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrameBasis {
    pub up: &'static str,
    pub facing: &'static str,
}

impl FrameBasis {
    /// The basis of the assumed `frame`: the person's `chosen` orientation where the frame agrees
    /// with it, else the given landmarks where their frame ruled out the others (`given_ruled`),
    /// else the scan's cue (`up_cue`, `facing_cue`), else the fits. A chosen facing that given
    /// landmarks overruled is thus reported as the landmarks'.
    pub fn of(
        frame: &FrameReport,
        chosen: Option<&Orientation>,
        given_ruled: bool,
        up_cue: Option<&'static str>,
        facing_cue: Option<&'static str>,
    ) -> Self {
        let basis = |chose: Option<&str>, axis: &str, cue: Option<&'static str>| {
            if chose == Some(axis) {
                "chosen"
            } else if given_ruled {
                "given landmarks"
            } else {
                cue.unwrap_or("the fits")
            }
        };
        Self {
            up: basis(chosen.map(|o| o.up.name()), &frame.up_axis, up_cue),
            facing: basis(
                chosen.and_then(|o| o.facing).map(|f| f.name()),
                &frame.facing_axis,
                facing_cue,
            ),
        }
    }
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
    /// The parts wound inwards turned to face out before anything else but the strays
    /// (`mesh/winding.rs`), if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub turned: Option<Reorientation>,
    /// The frame assumed (the best candidate after the whole fit).
    pub frame: FrameReport,
    /// What said the frame's up and facing.
    pub frame_from: FrameBasis,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimate::orientation::Axis;

    fn frame(up: &str, facing: &str) -> FrameReport {
        FrameReport {
            up: [0.0; 3],
            up_axis: up.to_string(),
            facing: [0.0; 3],
            facing_axis: facing.to_string(),
        }
    }

    #[test]
    fn the_frame_is_said_to_come_from_what_decided_it() {
        let chosen = Orientation {
            up: Axis::PlusZ,
            facing: Some(Axis::PlusY),
        };
        // The person's choice, where the frame agrees with it.
        let f = FrameBasis::of(&frame("+z", "+y"), Some(&chosen), false, None, None);
        assert_eq!((f.up, f.facing), ("chosen", "chosen"));
        // Given landmarks that overruled the chosen facing are named, not the choice.
        let f = FrameBasis::of(&frame("+z", "-y"), Some(&chosen), true, None, None);
        assert_eq!((f.up, f.facing), ("chosen", "given landmarks"));
        // Up chosen only: the legs said the facing.
        let up_only = Orientation {
            facing: None,
            ..chosen
        };
        let f = FrameBasis::of(
            &frame("+z", "-y"),
            Some(&up_only),
            false,
            None,
            Some("the legs"),
        );
        assert_eq!((f.up, f.facing), ("chosen", "the legs"));
        // Nothing chosen or given: the scan's cues, else the fits.
        let f = FrameBasis::of(
            &frame("+z", "-y"),
            None,
            false,
            Some("the scan's shape"),
            None,
        );
        assert_eq!((f.up, f.facing), ("the scan's shape", "the fits"));
    }
}
