//! Readers and writers of the field's file formats. Every reader is a pure function of bytes and
//! a file name (the name helps format detection and starts every error message).
//!
//! * Scans: [`scan`] (`read_scan`, format detection), [`ply_read`] with [`ply_header`],
//!   [`ply_source`] and [`ply_fast`]; [`obj_read`]; [`stl_read`]; [`text_xyz`] (coordinate
//!   triples of text formats); [`gzip`] (transparent decompression).
//! * Landmarks: [`landmarks_read`] (`read_landmarks`, format dispatch and name normalisation),
//!   [`landmarks_csv`], [`landmarks_json`], [`lnd`] (CAESAR `.lnd`), [`landmark_raw`] (the record
//!   the three readers produce).
//! * Writers: [`ply_write`], [`obj_write`], [`glb_write`] (the binary glTF container); landmark
//!   sets: `write_lnd`, `write_landmarks_csv`, `write_landmarks_json`, and [`landmarks_write`]
//!   (`write_landmarks`: one of them by the file name's extension).
//! * [`subject_files`]: which scan and landmark files make one subject of a batch.
//! * Shape models: [`statismo_h5`] (native only) reads and writes statismo HDF5 files with the
//!   HDF5 C library; the layout is `crate::model_file::statismo`'s.
//! * [`error`]: [`IoError`], the one error type of every reader; [`limits`]: the largest input
//!   accepted (inflated size, vertices, triangles), checked before memory is reserved.

pub mod error;
pub mod glb_write;
pub mod gzip;
pub mod landmark_raw;
pub mod landmarks_csv;
pub mod landmarks_json;
pub mod landmarks_read;
pub mod landmarks_write;
pub mod limits;
pub mod lnd;
pub mod obj_read;
pub mod obj_write;
pub mod ply_fast;
pub mod ply_header;
pub mod ply_read;
pub mod ply_source;
pub mod ply_write;
pub mod scan;
#[cfg(not(target_arch = "wasm32"))]
pub mod statismo_h5;
pub mod stl_read;
pub mod subject_files;
pub mod text_xyz;

pub use error::IoError;
pub use landmarks_csv::write_landmarks_csv;
pub use landmarks_json::write_landmarks_json;
pub use landmarks_read::{landmark_file_units, read_landmarks};
pub use landmarks_write::write_landmarks;
pub use lnd::write_lnd;
pub use obj_write::write_obj;
pub use ply_write::{write_ply, write_ply_ascii};
pub use scan::read_scan;
