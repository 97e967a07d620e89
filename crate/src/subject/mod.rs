//! One subject, from its files to a checked fit: the one path that `bodyspace align`,
//! `bodyspace batch`, the app's single scan and the app's batch all take, so the same scan and
//! landmarks give the same report whichever way they came in.
//!
//! * [`input`] — [`read_subject`]: a scan file and its landmark file (optional) → [`SubjectInput`],
//!   with the units rule (a landmark file is in the units its format fixes, else the scan's).
//! * [`policy`] — [`subject_landmarks`]: the landmark policy. A nearly full file is checked and
//!   its suspicious landmarks left out; a partial file is filled in by the estimate, a scan
//!   without a file gets the estimate's 73.
//! * [`floor`] — [`scan_without_floor`]: the floor or turntable remnant under the feet taken off
//!   the scan, up from the landmarks (`mesh/floor.rs`).
//! * [`frame`] — [`ToTemplate`]: the unit scale and rigid motion from the scan's frame into the
//!   template's (upright, y up, metres, facing +z), where bodies are compared — the shape
//!   model's own rule (`pca/template_frame.rs`), recorded with the fit.
//! * [`fit`] — [`fit_subject`]: RBF warp and fine alignment ([`crate::align::align_scan`]), the
//!   quality check, the frame, each measurement's trust (`crate::measure::trust`) →
//!   [`SubjectFit`] with its [`SubjectReport`] (`report.rs`).
//! * [`SubjectOptions`] (`options.rs`): every choice of the path, with its default;
//!   [`SubjectError`] (`error.rs`).
//!
//! It sits above `align` and the landmark estimate and below the command line and the bindings.

pub mod error;
pub mod fit;
pub mod floor;
pub mod frame;
pub mod input;
pub mod options;
pub mod policy;
pub mod report;

pub use error::SubjectError;
pub use fit::{fit_measurements_trust, fit_subject, fit_subject_files, SubjectFit};
pub use floor::scan_without_floor;
pub use frame::ToTemplate;
pub use input::{read_subject, GivenLandmarks, SubjectInput};
pub use options::SubjectOptions;
pub use policy::{subject_landmarks, PriorEstimate, SubjectLandmarks};
pub use report::{LandmarkPolicyReport, LandmarkSource, SubjectReport};
