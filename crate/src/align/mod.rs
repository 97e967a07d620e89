//! Fine alignment (paper §3.2) and the whole alignment pipeline around it.
//!
//! * [`pipeline`] — [`align_scan`]: scan → units → RBF warp → weights and anchors → scan index →
//!   fine or coarse-to-fine alignment → [`AlignmentReport`]; the one place the chain is assembled.
//! * [`observer`] — [`Progress`], [`Stage`] and [`AlignObserver`]: progress, rounds, cancel.
//! * [`fine_align()`] (`fine_align.rs`) — the outer loop: find correspondences, minimise, repeat.
//! * [`part_pose`] — the template posed part by part to the scan's landmarks before the warp.
//! * [`follow`] — regions without data take their neighbours' transforms (harmonic extension).
//! * [`coarse_to_fine_align`] (`coarse_to_fine.rs`) — the `fine` template: base fit, carried to
//!   fine by the subdivision operator, then a short fine-level alignment.
//! * [`energy`] — E_d, E_s (paper eq. 6–8) and their analytic gradient.
//! * [`scan_term`] — the scan-to-template term E_r (not in the paper; switchable).
//! * [`lbfgs`] — allocation-free L-BFGS with exact line search on the quadratic inner problem.
//! * [`SurfaceIndex`] (`surface_index.rs`) — closest points on a triangle mesh, built once per mesh.
//! * [`surface`] — closest point on a triangle, one-rings.
//! * [`uneven_fit`] — a limb fitted much farther from the scan on one side than on the other.
//! * [`weights`] — the per-vertex data weights from the template's region flags.
//! * [`anchors`] — landmark anchors (optional, weight 0 by default).
//! * [`report`] — the paper's Table 1 statistics, per-vertex distances, the convergence curve.
//! * [`alignment_report`] — the pipeline's serialisable report (lengths in mm).
//! * [`correspondence`] — correspondence error against a ground truth.
//! * [`correspondence_split`] — that error over many subjects split as a shape model sees it:
//!   the part common to all subjects and each subject's own (leave one out).
//! * [`quality`] — quality flags of a finished alignment (RMS, unmatched vertices, fold-overs,
//!   uncovered scan, uneven limbs).
//! * [`FineAlignInput`] (`fine_input.rs`) — what fine alignment works on.
//! * [`AlignParams`], [`FineAlignParams`], [`FineStageParams`] (`params.rs`) — every parameter
//!   with its default; [`AlignError`] (`error.rs`).

pub mod alignment_report;
pub mod anchors;
pub mod coarse_to_fine;
pub mod correspondence;
pub mod correspondence_split;
pub mod energy;
pub mod error;
pub mod fine_align;
pub mod fine_input;
pub mod follow;
pub mod lbfgs;
pub mod observer;
pub mod params;
pub mod part_pose;
pub mod pipeline;
pub mod quality;
pub mod report;
pub mod scan_term;
pub mod surface;
pub mod surface_index;
pub mod uneven_fit;
pub mod weights;

pub use alignment_report::{AlignmentReport, FineReport, WarpReport};
pub use anchors::landmark_anchors;
pub use coarse_to_fine::{coarse_to_fine_align, CoarseToFineInput, CoarseToFineResult};
pub use correspondence::{
    correspondence_report, CorrespondenceReport, ErrorSummaryMm, PartError, SegmentError,
};
pub use correspondence_split::{
    correspondence_split, CorrespondenceSplit, CorrespondenceSplitError, FitAndTruth, PartSplit,
};
pub use error::AlignError;
pub use fine_align::{fine_align, FineAlignResult};
pub use fine_input::FineAlignInput;
pub use observer::{AlignObserver, Progress, Stage};
pub use params::{AlignParams, CorrespondenceMode, FineAlignParams, FineStageParams, Preset};
pub use pipeline::{align_scan, AlignInput, Alignment, PipelineError};
pub use quality::{
    assess, folded_triangles, uncovered_scan, QualityFlag, QualityReport, QualityThresholds,
    Uncovered,
};
pub use report::{
    scan_to_template_distances, template_to_scan_distances, AlignReport, CurvePoint, DistanceStats,
    ScanDistance,
};
pub use surface_index::{FaceMatch, Match, MatchQuery, SurfaceIndex};
pub use uneven_fit::{uneven_fits, UnevenFit};
pub use weights::{data_weights, HAND_EAR_WEIGHT};
