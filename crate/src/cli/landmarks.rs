//! `bodyspace landmarks --scan SCAN --out FILE [--landmarks PARTIAL]`: the 73 CAESAR landmarks
//! of a bare scan (or the rest of a partial file) by the core's estimate
//! ([`estimate_landmarks`]); writes `.csv` / `.json` in the scan's frame and units or `.lnd` in
//! millimetres, by the extension, and prints the [`crate::estimate::EstimateReport`]
//! as JSON (frame and units assumed, per-landmark confidence, flagged landmarks, times).

use std::path::{Path, PathBuf};

use super::read_file;
use crate::estimate::{estimate_landmarks, EstimateInput, EstimateParams, LandmarkEstimate};
use crate::io::{read_landmarks, read_scan, write_landmarks};
use crate::landmarks::LandmarkSet;
use crate::mesh::Mesh;
use crate::template::Template;

/// Arguments of `bodyspace landmarks`.
#[derive(clap::Args, Debug)]
pub struct LandmarksArgs {
    /// The scan: PLY, OBJ or STL, optionally gzip-compressed, in any frame and units.
    #[arg(long)]
    pub scan: PathBuf,
    /// Where to write the landmarks: .csv or .json (the scan's frame and units) or .lnd (mm).
    #[arg(long)]
    pub out: PathBuf,
    /// A partial landmark file (CSV, .lnd or JSON, the scan's frame and units): its landmarks
    /// are kept as given and the estimate fills in the rest.
    #[arg(long)]
    pub landmarks: Option<PathBuf>,
    /// Also write the JSON report to this file.
    #[arg(long)]
    pub report: Option<PathBuf>,
}

/// Runs `bodyspace landmarks`; the error is the one-line message for stderr.
pub fn run(args: &LandmarksArgs) -> Result<(), String> {
    let scan = read_scan_file(&args.scan)?;
    let given = match &args.landmarks {
        Some(path) => read_landmark_file(path)?,
        None => LandmarkSet::default(),
    };
    let template = Template::embedded().map_err(|e| format!("embedded template: {e}"))?;
    let estimate = estimate(&template, &scan, &given, &args.scan)?;
    let name = args.out.display().to_string();
    let subject = args
        .scan
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let bytes = write_landmarks(
        &estimate.to_set(),
        &name,
        estimate.scale_to_metres,
        &subject,
    )?;
    std::fs::write(&args.out, bytes)
        .map_err(|e| format!("{name}: cannot write the landmarks: {e}"))?;
    let text = serde_json::to_string_pretty(&estimate.report).map_err(|e| e.to_string())?;
    if let Some(path) = &args.report {
        std::fs::write(path, &text)
            .map_err(|e| format!("{}: cannot write the report: {e}", path.display()))?;
    }
    println!("{text}");
    Ok(())
}

/// The core's estimate with its defaults, the error prefixed by the scan's file name.
pub fn estimate(
    template: &Template,
    scan: &Mesh,
    given: &LandmarkSet,
    scan_path: &Path,
) -> Result<LandmarkEstimate, String> {
    let input = EstimateInput {
        template,
        scan,
        given,
        units: None,
    };
    estimate_landmarks(&input, &EstimateParams::default(), &mut ())
        .map_err(|e| format!("{}: landmark estimate: {e}", scan_path.display()))
}

fn read_scan_file(path: &Path) -> Result<Mesh, String> {
    let name = path.display().to_string();
    read_scan(&read_file(path)?, &name).map_err(|e| e.to_string())
}

fn read_landmark_file(path: &Path) -> Result<LandmarkSet, String> {
    read_landmarks(&read_file(path)?, &path.display().to_string()).map_err(|e| e.to_string())
}
