//! Parameters of the RBF rough deformation, with the defaults measured in docs/rbf.md.

use serde::{Deserialize, Serialize};

use super::kernel::Kernel;

/// Parameters of [`super::fit::fit`] and [`super::warp::rbf_warp`].
///
/// Kernel parameters are in TEMPLATE units (metres): the warp fits in the template's frame after
/// Procrustes has taken the scan landmarks there, so c and s mean the same for a scan in
/// millimetres and one in metres.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RbfParams {
    /// The radial basis function. Default: thin-plate spline — measured after the FULL pipeline
    /// (RBF warp + fine alignment, 10 synthetic subjects) it leaves the lowest correspondence
    /// error (6.71 mm vs 7.97 mm for the paper's Gaussian at c = [`super::kernel::DEFAULT_GAUSSIAN_C`] m) and
    /// has no scale parameter; docs/rbf.md has the table.
    pub kernel: Kernel,
    /// Add the affine (degree-1 polynomial) term with side conditions Σw = 0, Σw·p = 0.
    /// Default true: it reproduces similarity/affine maps exactly and keeps vertices far from
    /// every landmark from collapsing to the origin under the decaying Gaussian.
    pub affine: bool,
    /// Smoothing λ ≥ 0 added to the kernel diagonal; 0 interpolates exactly, larger values
    /// trade landmark residuals for a smoother warp (units of Φ). Default 0 (the paper
    /// interpolates).
    pub lambda: f64,
    /// Smallest accepted reciprocal 1-norm condition number of the (n+4)² system; below it
    /// the fit fails with [`super::RbfError::IllConditioned`] rather than return weights that
    /// are mostly rounding error. Default 1e-13.
    pub min_rcond: f64,
    /// Add the 12 virtual landmarks (paper n = 73 + 12 = 85) when warping a mesh. Default true.
    pub virtual_landmarks: bool,
}

impl Default for RbfParams {
    fn default() -> Self {
        Self {
            kernel: Kernel::ThinPlate,
            affine: true,
            lambda: 0.0,
            min_rcond: 1e-13,
            virtual_landmarks: true,
        }
    }
}
