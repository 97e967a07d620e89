//! `bodyspace landmarks --scan SCAN --out FILE [--landmarks PARTIAL]`: the 73 CAESAR landmarks
//! of a bare scan (or the rest of a partial file) by the core's estimate
//! ([`crate::subject::SubjectInput::estimate_landmarks`]); writes `.csv` / `.json` in the scan's frame and units or `.lnd` in
//! millimetres, by the extension, and prints the [`crate::estimate::EstimateReport`]
//! as JSON (frame and units assumed, per-landmark confidence, flagged landmarks, times).

use std::path::PathBuf;

use super::subject_args::{OrientationArgs, ReportArgs, SubjectFiles};
use crate::io::write_landmarks;
use crate::template::Template;

/// Arguments of `bodyspace landmarks`.
#[derive(clap::Args, Debug)]
pub struct LandmarksArgs {
    /// The scan and a partial landmark file, if any: its landmarks are kept as given and the
    /// estimate fills in the rest.
    #[command(flatten)]
    pub files: SubjectFiles,
    #[command(flatten)]
    pub orientation: OrientationArgs,
    /// Where to write the landmarks: .csv or .json (the scan's frame and units) or .lnd (mm).
    #[arg(long)]
    pub out: PathBuf,
    #[command(flatten)]
    pub report: ReportArgs,
}

/// Runs `bodyspace landmarks`; the error is the one-line message for stderr.
pub fn run(args: &LandmarksArgs) -> Result<(), String> {
    let input = args.files.read()?;
    let template = Template::embedded().map_err(|e| format!("embedded template: {e}"))?;
    let estimate = input
        .estimate_landmarks(
            &template,
            &input.given_in_scan_units(),
            args.orientation.orientation()?,
            &mut (),
        )
        .map_err(|e| e.to_string())?;
    let name = args.out.display().to_string();
    let subject = args
        .files
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
    args.report.print(&estimate.report)
}
