//! Triangle meshes and the geometry measured on them, one concept per file:
//!
//! * [`trimesh`]: the [`Mesh`] type.
//! * [`bounds`]: bounding box and largest extent.
//! * [`bvh`]: a bounding-volume hierarchy for casting rays at a mesh.
//! * [`floor`]: a floor, platform or turntable remnant under the feet, found and removed.
//! * [`orientation`]: each part's triangles turned to agree with their neighbours.
//! * [`normals`]: area-weighted vertex normals (f64 and flat f32) and face normals.
//! * [`ray`]: ray–triangle intersection.
//! * [`topology`]: unique edges, neighbours, boundary edges/vertices/loops, components.
//! * [`similarity`]: the least-squares similarity or rigid transform between point sets (Umeyama).
//! * [`units`]: metres or millimetres from a body's extent.
//! * [`volume`]: enclosed volume and surface area.
//! * [`winding`]: which way a scan's triangles face (out of the body, into it, or mixed).
//! * [`summary`]: the one-look summary of a loaded scan.
//! * [`surface_points`]: points spread over a mesh's triangles, everywhere or near a point.
//! * [`tip`]: where a surface near a point stands out most from its surroundings in one direction
//!   (a nose's tip).
//! * [`strays`]: small pieces of a scan floating apart from the body, found and taken off.
//! * `test_points` (tests only): small point sets the unit tests of several modules share.

pub mod bounds;
pub mod bvh;
pub mod floor;
pub mod normals;
pub mod orientation;
pub mod principal_axes;
pub mod ray;
pub mod similarity;
pub mod strays;
pub mod summary;
pub mod surface_points;
#[cfg(test)]
pub(crate) mod test_points;
pub mod tip;
pub mod topology;
pub mod trimesh;
pub mod units;
pub mod volume;
pub mod winding;

pub use bounds::{bounding_box, bounding_extent};
pub use summary::{summarise, MeshSummary};
pub use trimesh::Mesh;
pub use units::{detect_units, Units};
