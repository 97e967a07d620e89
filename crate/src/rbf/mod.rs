//! RBF rough deformation (paper §3.1): landmark pairs fit one RBF network per coordinate, which
//! warps the template onto the scan.
//!
//! * [`kernel`] — Φ: thin-plate, multiquadric, Gaussian (eq. 3–5).
//! * [`network`] — the fitted network [`RbfNetwork`] and the warp loop: the network at every
//!   template vertex, vectorised.
//! * [`fit`] — fitting f(p_i) = q_i (eq. 1–2) with optional affine term, LU solve,
//!   conditioning checks.
//! * [`checks`] — input checks naming the offending landmarks; [`fast_math`] — exp/ln for the loop.
//! * [`procrustes`] — similarity pre-alignment so the scan's frame and units do not matter (the
//!   checked entry to [`crate::mesh::similarity`]).
//! * [`virtual_landmarks`] — the 12 automatically made landmarks (n = 73 + 12 = 85), re-exported
//!   from [`crate::landmarks`].
//! * [`warp`] — `rbf_warp`, `rbf_warp_mesh`: Procrustes, fit, warp every template vertex;
//!   [`LandmarkPairing`] (used, skipped, off-surface names) and the residuals.
//! * [`params`], [`error`] — the params struct with its documented defaults, the error enum.

pub mod checks;
pub mod error;
pub mod fast_math;
pub mod fit;
pub mod kernel;
pub mod network;
pub mod params;
pub mod procrustes;
pub mod warp;

pub use error::RbfError;
pub use fit::fit;
pub use kernel::Kernel;
pub use network::RbfNetwork;
pub use params::RbfParams;
pub use procrustes::{similarity, Similarity};
// The virtual landmarks live with the other landmarks; re-exported here, where the RBF uses them.
pub use crate::landmarks::virtual_landmarks;
pub use crate::landmarks::virtual_landmarks::{
    virtual_landmarks_detailed, VirtualLandmark, VIRTUAL_LANDMARK_COUNT,
};
pub use warp::{rbf_warp, rbf_warp_mesh, LandmarkPairing, LandmarkResidual, RbfWarp};
