//! Triangle meshes and what can be measured on them.

pub mod normals;
pub mod summary;
pub mod topology;
pub mod trimesh;
pub mod units;

pub use summary::{summarise, MeshSummary};
pub use trimesh::Mesh;
pub use units::{detect_units, Units};
