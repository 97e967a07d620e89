//! Fine alignment (paper §3.2): per-vertex affine transforms minimising E = a·E_d + b·E_s.
//!
//! * [`ScanIndex`] (`scan_index.rs`) — closest points on the scan, built once per scan.
//! * [`surface`] — normals, edges, one-rings, boundary flags, closest point on a triangle.
//! * [`energy`] — E_d, E_s (paper eq. 6–8) and their analytic gradient.
//! * [`scan_term`] — the optional scan-to-template term E_r (not in the paper).
//! * [`lbfgs`] — allocation-free L-BFGS with exact line search on the quadratic inner problem.
//! * [`fine_align()`] (`fine_align.rs`) — the outer loop: find correspondences, minimise, repeat.
//! * [`coarse_to_fine_align`] (`coarse_to_fine.rs`) — the `fine` template: base fit, carried to
//!   fine by the subdivision operator, then a short fine-level alignment.
//! * [`report`] — the paper's Table 1 statistics, per-vertex distances, time-to-RMS curve.
//! * [`FineAlignParams`] (`params.rs`), [`AlignError`] (`error.rs`).

pub mod coarse_to_fine;
pub mod energy;
pub mod error;
pub mod fine_align;
pub mod lbfgs;
pub mod params;
pub mod report;
pub mod scan_index;
pub mod scan_term;
pub mod surface;
pub mod weights;

pub use coarse_to_fine::{
    coarse_to_fine_align, CoarseToFineParams, CoarseToFineResult, Stage, StagedRoundObserver,
    FINE_STAGE_ITERATIONS,
};
pub use error::AlignError;
pub use fine_align::{
    fine_align, fine_align_anchored, fine_align_general, fine_align_observed, FineAlignResult,
    Progress,
};
pub use params::{CorrespondenceMode, FineAlignParams};
pub use report::{
    scan_to_template_distances, template_to_scan_distances, AlignReport, CurvePoint, DistanceStats,
};
pub use scan_index::{FaceMatch, Match, MatchQuery, ScanIndex};
pub use weights::{data_weights, HAND_EAR_WEIGHT};
