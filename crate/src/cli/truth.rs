//! Ground truth of synthetic subjects (`bodyspace synth` writes `truth_ID.ply`): vertex i is
//! template vertex i on the subject, in the scan's frame and units. `align --truth` and
//! `batch --truth` read it to add the correspondence error to a report.

use std::path::{Path, PathBuf};

use nalgebra::Point3;

use super::read_file;
use crate::io::read_scan;

/// Ground truth in metres; `expected` lists the vertex counts accepted (the base vertices, which
/// come first at every resolution, or all template vertices).
pub fn read_truth(
    path: &Path,
    expected: &[usize],
    to_metres: f64,
) -> Result<Vec<Point3<f64>>, String> {
    let name = path.display().to_string();
    let mesh = read_scan(&read_file(path)?, &name).map_err(|e| e.to_string())?;
    if !expected.contains(&mesh.positions.len()) {
        return Err(format!(
            "{name}: {} vertices but the template has {} ({} at base); ground truth must be in template vertex order",
            mesh.positions.len(),
            expected[expected.len() - 1],
            expected[0],
        ));
    }
    Ok(mesh.positions.iter().map(|p| p * to_metres).collect())
}

/// The ground-truth file of subject `subject` in `folder`: `truth_ID.ply` for a subject
/// `scan_ID` (the `bodyspace synth` layout, where `scan_ID.ply` is the scan), else
/// `<subject>.ply`.
pub fn find_truth_file(subject: &str, folder: &Path) -> Option<PathBuf> {
    let synth = subject
        .strip_prefix("scan_")
        .map(|id| format!("truth_{id}.ply"));
    synth
        .into_iter()
        .chain([format!("{subject}.ply")])
        .map(|n| folder.join(n))
        .find(|p| p.is_file())
}
