//! What the path from files to a fit reports, as one serialisable type: how the landmarks were
//! chosen, the alignment's own report (`align/alignment_report.rs`, flattened in), the quality
//! check and the frame. The command line prints it, the batch writes it beside each fit, the app
//! shows it: the same fields whichever path the subject took. Lengths in mm, times in ms.

use serde::Serialize;

use super::frame::ToTemplate;
use crate::align::{AlignmentReport, QualityReport};
use crate::estimate::{SelfCheck, SuspiciousLandmark};
use crate::measure::MeasurementTrust;
use crate::mesh::floor::FloorRemoval;
use crate::mesh::strays::StrayRemoval;
use crate::mesh::winding::Reorientation;

/// Where a subject's landmarks came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LandmarkSource {
    /// No landmarks were given: all come from the estimate.
    Estimated,
    /// A partial set was given and the estimate filled in the rest.
    FilledIn,
    /// A nearly full set was given and checked; suspicious ones were left out.
    Checked,
    /// Given landmarks used as they are, unchecked (the options said so).
    AsGiven,
}

/// How the warp's landmarks were chosen ([`super::policy::subject_landmarks`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LandmarkPolicyReport {
    pub source: LandmarkSource,
    /// The landmark file's name; empty when none was given.
    pub file: String,
    /// CAESAR landmarks given (in the file, or placed by a person).
    pub given: usize,
    /// Given landmarks the check found suspicious and left out of the warp, each with its reason.
    pub left_out: Vec<SuspiciousLandmark>,
    /// Given landmarks the check could not judge (too few other given landmarks in their rigid
    /// groups): used as given.
    pub unjudged: Vec<String>,
    /// Landmarks the estimate filled in.
    pub estimated: usize,
    /// CAESAR landmarks the warp used (given and trusted, plus estimated).
    pub used: usize,
    /// The landmark estimate's report, when it ran (`estimate/report.rs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub estimate: Option<serde_json::Value>,
    /// The estimate's verdict on itself, when the warp used landmarks it estimated
    /// (`estimate/self_check.rs`); a doubtful or failed one raises the fit's
    /// `landmark_estimate` flag.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub estimate_check: Option<SelfCheck>,
}

/// One subject's report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SubjectReport {
    pub landmarks: LandmarkPolicyReport,
    /// The floor or turntable remnant taken off the scan before the fit (`mesh/floor.rs`), if
    /// one was found under the feet.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub floor: Option<FloorRemoval>,
    /// The stray pieces taken off the scan before the fit (`mesh/strays.rs`), if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub strays: Option<StrayRemoval>,
    /// The parts wound inwards turned to face out before the fit (`mesh/winding.rs`), if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub turned: Option<Reorientation>,
    /// The quality check of the fit (`align/quality.rs`); absent after the warp alone.
    pub quality: Option<QualityReport>,
    /// From the scan's frame and units into the template's.
    pub to_template: ToTemplate,
    /// Each measurement's trust on this fit, from where its landmarks came
    /// (`measure/trust.rs`), in `Measure::ALL` order: a per-measurement verdict, not a quality
    /// flag.
    pub measurement_trust: Vec<MeasurementTrust>,
    #[serde(flatten)]
    pub alignment: AlignmentReport,
}

impl SubjectReport {
    /// Whether the quality check raised any flag.
    pub fn flagged(&self) -> bool {
        self.quality.as_ref().is_some_and(|q| !q.flags.is_empty())
    }

    /// The measurements whose expected error from estimated landmarks exceeds ISO 20685-1's
    /// limit.
    pub fn doubtful_measurements(&self) -> impl Iterator<Item = &MeasurementTrust> {
        self.measurement_trust.iter().filter(|t| t.doubtful)
    }
}
