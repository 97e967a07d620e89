//! Landmarks from a bare scan (issue 11), a module of its own above `align` (which it uses:
//! `SurfaceIndex`, `FineAlignParams`, …): the 73 CAESAR landmarks estimated by fitting the
//! template, or the rest of a partial set filled in; suspicious given landmarks flagged.
//! docs/landmarks-estimate.md describes the method and what it was measured against.
//!
//! * [`steps`] — [`estimate_landmarks`], [`EstimateInput`], [`LandmarkEstimate`]: the steps.
//! * [`frame`] — principal axes and the four frame candidates; [`FrameReport`];
//!   [`orientation`] — the candidates when a person says which way is up ([`Orientation`]).
//! * [`candidates`] — the similarity ICP of each candidate.
//! * [`up`] — which end of the body is the head, from the scan's shape (width ratios at its
//!   ends), before any fit.
//! * [`facing`] — which way the body faces, from its feet reaching forward of the lower legs.
//! * [`segments`] — the segment-wise rigid fit of the template's parts (`template::parts`,
//!   shared with `align::part_pose`) to the scan's pose.
//!   [`arm_swing`] — each arm's swing about the shoulder tried from several starts;
//!   [`bent_arm`] — the elbow of an arm bent at it (hands on hips); [`buttocks`] — the torso's
//!   length from the height of the buttocks; [`knees`] — the two knees side against side.
//! * [`acromion`] — the Acromions on the scan's shoulder near the fit's, after the fine fit.
//! * [`profile`] — the limbs' cross-section profiles (knees, elbows, the wrist).
//! * [`hand`] — the hand's pose about the wrist, from the scan's surface beyond it (the
//!   template's hands: `template::hand`); [`foot`] — the foot's pose about the ankle, moved
//!   rigidly onto the scan's foot (the template's feet: `template::foot`).
//! * [`matching`] — closest compatible scan points, the ICP energy.
//! * [`suspicious`] — [`flag_suspicious`]: given landmarks far from where they are expected;
//!   [`expected`] — where: from the other given landmarks of the part, or from the fit;
//!   [`check`] — [`check_given`]: a nearly full given file judged on its own, each landmark
//!   against the other given landmarks of its rigid groups (no fit); [`forearm_twist`] — the
//!   forearm's twist there, for a bent elbow.
//! * [`confidence`] — the typical error of each landmark (`typical_error`) and the fit's residual.
//! * [`self_check`] — the estimate's verdict on itself (good, doubtful, failed) and why;
//!   [`bilateral`] — limb segments compared between the body's sides.
//! * [`caesar_points`] — the template's landmark vertices at rest and a given set's CAESAR
//!   landmarks, as points in CAESAR order (for the estimate and the checks).
//! * [`tick`] — progress and cancel through the caller's `AlignObserver`.
//! * [`params`] — [`EstimateParams`] and the parameter structs it holds (every tuning number,
//!   with its documented default); [`EstimateReport`] (`report.rs`), [`EstimateError`]
//!   (`error.rs`).

pub mod acromion;
pub mod arm_swing;
pub mod bent_arm;
pub mod bilateral;
pub mod buttocks;
pub mod caesar_points;
pub mod candidates;
pub mod check;
pub mod confidence;
pub mod error;
pub mod expected;
pub mod facing;
pub mod foot;
pub mod forearm_twist;
pub mod frame;
pub mod hand;
pub mod knees;
pub mod matching;
pub mod orientation;
pub mod params;
pub mod profile;
pub mod report;
pub mod segments;
pub mod self_check;
pub mod steps;
pub mod suspicious;
pub mod tick;
pub mod typical_error;
pub mod up;

pub use caesar_points::{given_landmarks, landmark_rest};
pub use check::{check_given, GivenCheck};
pub use error::EstimateError;
pub use frame::FrameReport;
pub use orientation::{Axis, Orientation};
pub use params::EstimateParams;
pub use report::EstimateReport;
pub use self_check::{SelfCheck, Verdict};
pub use steps::{estimate_landmarks, flag_given, EstimateInput, LandmarkEstimate};
pub use suspicious::{flag_suspicious, SuspicionKind, SuspiciousLandmark};
