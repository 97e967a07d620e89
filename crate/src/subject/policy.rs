//! The landmark policy, one rule for every path: which landmarks the warp of a subject uses.
//!
//! 1. Given landmarks are checked (unless the options say not to): those far from where the other
//!    given landmarks of their rigid groups put them — a swapped Lt./Rt. pair, a typo, a landmark
//!    on the wrong part — are left out, with the reason ([`check_given`], no fit of the scan).
//! 2. A nearly full set (at least [`super::options::NEARLY_FULL`] of the 73) is used as checked:
//!    its missing landmarks stay absent and the warp runs without them.
//! 3. A partial set, or none, is filled in by the landmark estimate
//!    ([`crate::estimate::estimate_landmarks`]), which keeps the trusted given landmarks
//!    exactly as given. A caller that already ran that estimate on this scan with these landmarks
//!    (the app's landmark editor) hands its result in as a [`PriorEstimate`] instead.

use super::error::SubjectError;
use super::input::SubjectInput;
use super::options::SubjectOptions;
use super::report::{LandmarkPolicyReport, LandmarkSource};
use crate::align::AlignObserver;
use crate::estimate::{check_given, given_landmarks, GivenCheck, SelfCheck};
use crate::landmarks::LandmarkSet;
use crate::template::Template;

/// The landmark estimate a caller already ran on this scan with the trusted given landmarks.
#[derive(Debug, Clone)]
pub struct PriorEstimate {
    /// The estimated landmarks (scan frame and units); given ones in it are ignored.
    pub set: LandmarkSet,
    /// The estimate's report as it was serialised.
    pub report: serde_json::Value,
}

/// The landmarks a subject's warp uses, and how they were chosen.
#[derive(Debug, Clone)]
pub struct SubjectLandmarks {
    /// The scan's frame and units.
    pub set: LandmarkSet,
    pub report: LandmarkPolicyReport,
}

/// Applies the landmark policy to the landmarks given with `input` (if any) on its scan. The
/// estimate, when it runs, reports to `observer` (stage `estimate`; a `Break` cancels).
pub fn subject_landmarks(
    template: &Template,
    input: &SubjectInput,
    prior: Option<PriorEstimate>,
    options: &SubjectOptions,
    observer: &mut dyn AlignObserver,
) -> Result<SubjectLandmarks, SubjectError> {
    let (units, _) = input.scan_units();
    let given = &input.given_in_scan_units();
    let file = input.given.as_ref().map_or("", |g| g.file.as_str());
    let given_count = given_landmarks(given).len();
    let check = if options.check_landmarks && given_count > 0 {
        check_given(template, given, 1e3 * units.scale_to_metres())
    } else {
        GivenCheck::default()
    };
    let left_out = check.flagged;
    let trusted = LandmarkSet {
        landmarks: given
            .landmarks
            .iter()
            .filter(|l| !left_out.iter().any(|f| f.name == l.name))
            .cloned()
            .collect(),
        ..given.clone()
    };
    let source = match (given_count, options.check_landmarks) {
        (0, _) => LandmarkSource::Estimated,
        (n, _) if n < options.nearly_full => LandmarkSource::FilledIn,
        (_, true) => LandmarkSource::Checked,
        (_, false) => LandmarkSource::AsGiven,
    };
    let fill_in = matches!(source, LandmarkSource::Estimated | LandmarkSource::FilledIn);
    let prior = match prior {
        Some(prior) => Some(prior),
        None if fill_in => {
            let estimate =
                input.estimate_landmarks(template, &trusted, options.orientation, observer)?;
            let report = serde_json::to_value(&estimate.report).unwrap_or_default();
            Some(PriorEstimate {
                set: estimate.to_set(),
                report,
            })
        }
        None => None,
    };
    let mut set = trusted;
    let mut estimated = 0;
    let mut estimate_report = None;
    let mut estimate_check = None;
    if let Some(prior) = prior {
        for l in prior.set.landmarks {
            if set.get(&l.name).is_none() && !left_out.iter().any(|f| f.name == l.name) {
                set.missing.retain(|m| *m != l.name);
                set.landmarks.push(l);
                estimated += 1;
            }
        }
        estimate_check = prior
            .report
            .get("self_check")
            .and_then(|c| serde_json::from_value::<SelfCheck>(c.clone()).ok())
            .filter(|_| estimated > 0);
        estimate_report = Some(prior.report);
    }
    Ok(SubjectLandmarks {
        report: LandmarkPolicyReport {
            source,
            file: file.to_string(),
            given: given_count,
            left_out,
            unjudged: check.unjudged,
            estimated,
            used: given_landmarks(&set).len(),
            estimate: estimate_report,
            estimate_check,
        },
        set,
    })
}
