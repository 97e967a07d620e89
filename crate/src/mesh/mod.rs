//! Triangle meshes and what can be measured on them.

pub mod trimesh;

pub use trimesh::Mesh;
