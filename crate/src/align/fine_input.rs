//! What fine alignment works on: the template to fit (positions, triangles, data weights,
//! landmark anchors) and the scan's closest-point index.

use nalgebra::Point3;

use super::surface_index::SurfaceIndex;
use crate::mesh::Mesh;

/// The template to fit and what it is fitted to.
#[derive(Debug, Clone, Copy)]
pub struct FineAlignInput<'a> {
    /// `#V` template positions (metres, in the scan's frame; usually the RBF-warped template).
    pub positions: &'a [Point3<f64>],
    /// `#F` template triangles.
    pub triangles: &'a [[u32; 3]],
    /// The scan's [`SurfaceIndex`], built once per scan.
    pub scan: &'a SurfaceIndex,
    /// `#V` data weights w_i ≥ 0 (1 normally, 0.1 hands and ears, 0 unseen regions).
    pub weights: &'a [f64],
    /// Landmark anchors `(vertex, target)` (metres, scan frame; usually where the RBF warp put
    /// the landmark vertex). Each adds a·κ·`landmark_weight`·‖T_i v_i − target‖², folded into the
    /// vertex's data term (α‖x − c‖² + β‖x − L‖² = (α+β)‖x − (αc+βL)/(α+β)‖² + const), so the
    /// reported E_d and RMS of anchored vertices are to that blended target. Empty, or
    /// `landmark_weight` 0, is the paper's energy.
    pub anchors: &'a [(u32, Point3<f64>)],
}

impl<'a> FineAlignInput<'a> {
    /// The input for a template `mesh` without anchors.
    pub fn of_mesh(mesh: &'a Mesh, scan: &'a SurfaceIndex, weights: &'a [f64]) -> Self {
        Self {
            positions: &mesh.positions,
            triangles: &mesh.triangles,
            scan,
            weights,
            anchors: &[],
        }
    }
}
