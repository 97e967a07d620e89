//! One synthetic subject's files in a `bodyspace synth` folder (`scan_XXX.ply`,
//! `landmarks_XXX.lnd`, `truth_XXX.ply`), read for the accuracy examples.

use bodyspace::io::{read_landmarks, read_scan};
use bodyspace::landmarks::set::LandmarkSet;
use bodyspace::mesh::Mesh;
use std::path::Path;

/// A subject's scan, ground truth (the base template's vertices on the subject) and landmarks,
/// in the files' units.
pub struct SubjectFiles {
    pub scan: Mesh,
    pub truth: Mesh,
    pub landmarks: LandmarkSet,
}

fn read_mesh(path: &Path) -> Result<Mesh, String> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| format!("{name}: {e}"))?;
    read_scan(&bytes, &name).map_err(|e| e.to_string())
}

/// Subject `id` (1-based, as in the file names) of the folder `dir`.
pub fn read_subject(dir: &Path, id: usize) -> Result<SubjectFiles, String> {
    let file = |stem: &str, ext: &str| dir.join(format!("{stem}_{id:03}.{ext}"));
    let lnd = file("landmarks", "lnd");
    let bytes = std::fs::read(&lnd).map_err(|e| format!("{}: {e}", lnd.display()))?;
    Ok(SubjectFiles {
        scan: read_mesh(&file("scan", "ply"))?,
        truth: read_mesh(&file("truth", "ply"))?,
        landmarks: read_landmarks(&bytes, &lnd.display().to_string()).map_err(|e| e.to_string())?,
    })
}
