//! PCA shape spaces (paper §4): S = S̄ + Φ·B for the whole body and six overlapping segments.
//! (Measurements of a body are [`crate::measure`]; anthropometry on a model — distributions,
//! bodies from measurements, manikins — is [`crate::anthropometry`]; the model file formats are
//! [`crate::model_file`]. Both use this module, never the reverse.)
//!
//! * [`procrustes_gpa`] — generalised Procrustes analysis (rigid pose removal, optional scale)
//! * [`gram`] — snapshot PCA through the N×N Gram matrix
//! * [`shape_model`] — [`ShapeModel`] (one part) and the [`TemplateIdentity`] it was built on
//! * [`model`] — [`BodyModel`] (whole body + six segments): assembly, projection of a new mesh,
//!   stitched reconstruction and seam report
//! * [`template_frame`] — a training shape in the template's frame (its units, a rigid fit
//!   onto the template's rest shape), where every model is built
//! * [`build`] — [`build_body_model`] from a [`TrainingSet`]; [`params`] — its [`BuildParams`]
//! * [`segments`] — segment vertex subsets and normalised blend weights
//! * [`marginal`] — a model's marginal on a vertex subset (segment models of a whole-body file)
//! * [`stitch`] — the stitching types (coefficients, plan, seam report) and f32 slider kernels
//! * [`morph`] — the body on screen: held coefficients and positions, slider moves as rank-1 updates
//! * [`subdivide`] — a model mapped exactly to the template's finer resolution (S̄_fine = S·S̄, φ_fine = S·φ)
//! * [`metrics`] — compactness, generalization, specificity (Styner 2003)
//! * [`random`] — seeded normal draws

pub mod build;
pub mod error;
pub mod gram;
pub mod marginal;
pub mod metrics;
pub mod model;
pub mod morph;
pub mod params;
pub mod procrustes_gpa;
pub mod random;
pub mod segments;
pub mod shape_model;
pub mod stitch;
pub mod subdivide;
pub mod template_frame;

pub use build::{build_body_model, TrainingSet};
pub use error::PcaError;
pub use metrics::{QualityCurves, QualityParams};
pub use model::{BodyModel, Projection};
pub use morph::{Morph, MorphUpdate};
pub use params::BuildParams;
pub use procrustes_gpa::{GpaParams, PoseRemoval};
pub use shape_model::{ShapeModel, TemplateIdentity};
pub use stitch::{Coefficients, ModeDelta, ModeTarget, SeamReport, StitchPlan};
