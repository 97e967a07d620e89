//! What is written per subject, in the output frame.
//!
//! Output frame (CAESAR's convention by default): millimetres (or metres with `Units::Metres`),
//! z up, feet on z = 0, the subject facing −y, the subject's left at +x. From the template frame
//! (metres, y up, facing +z): `(x, y, z) ↦ s·(x, −z, y)` with `s` = 1000 or 1. Scan, noise-free
//! surface, ground truth and landmarks are all in this one frame.

use std::io::Write;
use std::path::Path;

use flate2::write::GzEncoder;
use flate2::Compression;

use nalgebra::Point3;
use rand::Rng;
use rand_distr::{Distribution, Normal};

use crate::io::{write_landmarks_csv, write_lnd, write_ply};
use crate::landmarks::{Landmark, LandmarkSet};
use crate::mesh::Mesh;

use super::error::SynthError;
use super::subject::Subject;

/// Units of the output files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
pub enum Units {
    /// Millimetres, as CAESAR.
    #[default]
    Millimetres,
    /// Metres, as the template.
    Metres,
}

impl Units {
    /// Output units per metre.
    pub fn per_metre(self) -> f64 {
        match self {
            Units::Millimetres => 1000.0,
            Units::Metres => 1.0,
        }
    }

    /// Short name (`mm`, `m`).
    pub fn name(self) -> &'static str {
        match self {
            Units::Millimetres => "mm",
            Units::Metres => "m",
        }
    }
}

/// A template-frame point in the output frame.
pub fn to_output_frame(p: &Point3<f64>, units: Units) -> Point3<f64> {
    let s = units.per_metre();
    Point3::new(s * p.x, -s * p.z, s * p.y)
}

/// A template-frame mesh in the output frame.
pub fn mesh_to_output_frame(mesh: &Mesh, units: Units) -> Mesh {
    Mesh::new(
        mesh.positions
            .iter()
            .map(|p| to_output_frame(p, units))
            .collect(),
        mesh.triangles.clone(),
    )
}

/// Settings of the landmark files.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LandmarkParams {
    /// Placement noise: isotropic Gaussian standard deviation per axis (m).
    pub sigma: f64,
    /// Probability that a landmark is reported missing.
    pub missing: f64,
}

impl Default for LandmarkParams {
    /// 2 mm per axis (≈ 3.5 mm RMS in 3D, CAESAR-like placement spread), none missing.
    fn default() -> Self {
        Self {
            sigma: 0.002,
            missing: 0.0,
        }
    }
}

/// The landmarks of a subject: template landmark vertex `(name, vertex)` positions on the posed
/// subject (template frame), plus placement noise, some dropped; returned in the output frame.
pub fn subject_landmarks<R: Rng>(
    landmark_vertices: &[(String, u32)],
    posed: &[Point3<f64>],
    params: &LandmarkParams,
    units: Units,
    rng: &mut R,
) -> LandmarkSet {
    let noise = Normal::new(0.0, params.sigma.max(0.0))
        .unwrap_or_else(|_| Normal::new(0.0, 0.0).expect("sd 0 is valid"));
    let mut set = LandmarkSet::default();
    for (name, v) in landmark_vertices {
        let Some(p) = posed.get(*v as usize) else {
            continue;
        };
        let jitter =
            nalgebra::Vector3::new(noise.sample(rng), noise.sample(rng), noise.sample(rng));
        let dropped = rng.gen_bool(params.missing.clamp(0.0, 1.0));
        if dropped {
            set.missing.push(name.clone());
        } else {
            set.landmarks.push(Landmark {
                name: name.clone(),
                position: to_output_frame(&(p + jitter), units),
            });
        }
    }
    set
}

/// The truth file: a vertex-only PLY of the template vertices on the subject.
pub fn truth_points(subject: &Subject, units: Units) -> Mesh {
    Mesh::new(
        subject
            .surface
            .positions
            .iter()
            .map(|p| to_output_frame(p, units))
            .collect(),
        Vec::new(),
    )
}

/// Writes `scan_ID.ply`, `surface_ID.ply`, `truth_ID.ply` (each `.ply.gz` when `gzip`),
/// `landmarks_ID.csv` and `landmarks_ID.lnd`.
pub fn write_subject(
    dir: &Path,
    id: &str,
    subject: &Subject,
    landmarks: &LandmarkSet,
    units: Units,
    gzip: bool,
) -> Result<(), SynthError> {
    let ply = |name: &str, mesh: &Mesh| -> Result<(String, Vec<u8>), SynthError> {
        let bytes = write_ply(mesh);
        if !gzip {
            return Ok((format!("{name}_{id}.ply"), bytes));
        }
        let file = format!("{name}_{id}.ply.gz");
        let mut z = GzEncoder::new(Vec::new(), Compression::best());
        z.write_all(&bytes)
            .and_then(|_| z.finish())
            .map(|b| (file.clone(), b))
            .map_err(|e| SynthError::Write {
                path: dir.join(&file).display().to_string(),
                message: e.to_string(),
            })
    };
    let files: [(String, Vec<u8>); 5] = [
        ply("scan", &mesh_to_output_frame(&subject.scan.mesh, units))?,
        ply("surface", &mesh_to_output_frame(&subject.surface, units))?,
        ply("truth", &truth_points(subject, units))?,
        (
            format!("landmarks_{id}.csv"),
            write_landmarks_csv(landmarks),
        ),
        (format!("landmarks_{id}.lnd"), write_lnd(landmarks, id)),
    ];
    for (name, bytes) in files {
        let path = dir.join(&name);
        std::fs::write(&path, bytes).map_err(|e| SynthError::Write {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
    }
    Ok(())
}
