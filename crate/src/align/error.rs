//! Errors of fine alignment: every one names the input and what to do about it.

use thiserror::Error;

/// Why [`crate::align::fine_align`] or [`crate::align::SurfaceIndex::new`] refused to run.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum AlignError {
    /// The scan has no triangles (a point cloud): normals, holes and closest points on the
    /// surface all need a triangulated scan.
    #[error("scan has {vertices} vertices but no triangles; fine alignment needs a triangulated scan (mesh it first)")]
    ScanHasNoTriangles {
        /// Number of scan vertices.
        vertices: usize,
    },
    /// A triangle indexes a vertex that does not exist.
    #[error(
        "{what}: triangle {triangle} uses vertex {index} but there are only {vertices} vertices"
    )]
    IndexOutOfRange {
        /// "scan" or "template".
        what: &'static str,
        /// Triangle number.
        triangle: usize,
        /// The bad index.
        index: u32,
        /// Number of vertices.
        vertices: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("{what}: vertex {vertex} has a non-finite coordinate; fix or drop it before aligning")]
    NonFinite {
        /// "scan" or "template".
        what: &'static str,
        /// Vertex number.
        vertex: usize,
    },
    /// The data weights do not match the template.
    #[error("data weights: got {got} weights for a template of {expected} vertices (one weight per template vertex)")]
    WeightCount {
        /// Number of weights supplied.
        got: usize,
        /// Number of template vertices.
        expected: usize,
    },
    /// A data weight is negative or not finite.
    #[error("data weights: weight {value} at vertex {vertex} must be finite and ≥ 0")]
    BadWeight {
        /// Vertex number.
        vertex: usize,
        /// The bad weight.
        value: f64,
    },
    /// A parameter is outside its meaningful range.
    /// A landmark anchor names a template vertex that does not exist or a non-finite target.
    #[error("landmark anchor {anchor}: vertex {vertex} with target {target:?} is not a finite point on a template of {vertices} vertices")]
    BadAnchor {
        /// Position of the anchor in the list.
        anchor: usize,
        /// The template vertex it names.
        vertex: u32,
        /// Its target (m).
        target: [f64; 3],
        /// Template vertex count.
        vertices: usize,
    },
    #[error("fine alignment parameter {name} = {value}: {reason}")]
    BadParameter {
        /// Parameter name as in [`crate::align::FineAlignParams`].
        name: &'static str,
        /// The value given.
        value: f64,
        /// What range is allowed.
        reason: String,
    },
    /// The template has no vertices or no triangles.
    #[error(
        "template is empty ({vertices} vertices, {triangles} triangles); load a template first"
    )]
    EmptyTemplate {
        /// Number of template vertices.
        vertices: usize,
        /// Number of template triangles.
        triangles: usize,
    },
    /// The subdivision operator of coarse-to-fine alignment was made for another base mesh.
    #[error("coarse to fine: the base template has {base_vertices} vertices but the subdivision operator maps {operator_base_vertices} base vertices to {operator_fine_vertices}; use the operator of the same template")]
    Refinement {
        /// Vertices of the base template given.
        base_vertices: usize,
        /// Base vertices the operator expects.
        operator_base_vertices: usize,
        /// Fine vertices the operator makes.
        operator_fine_vertices: usize,
    },
}
