//! `bodyspace export-statismo --model MODEL --out FILE.h5 [--segment NAME]`: a model as a
//! statismo HDF5 file (`model_file::statismo`, written by `io::statismo_h5`) for statismo, Scalismo
//! and exploreCOSMOS: the whole body, or one segment over its own vertices.

use super::model::load_model;
use crate::io::statismo_h5::write_statismo_h5;
use crate::model_file::statismo::statismo_of_part;
use crate::template::Segment;
use std::path::PathBuf;

/// Arguments of `bodyspace export-statismo`.
#[derive(clap::Args, Debug)]
pub struct ExportStatismoArgs {
    /// The model: a `.bsm` model file or a statismo `.h5` made on the template.
    #[arg(long)]
    pub model: PathBuf,
    /// The HDF5 file to write (replaced if it exists).
    #[arg(long)]
    pub out: PathBuf,
    /// One segment's model instead of the whole body: head, left_arm, right_arm, torso,
    /// left_leg or right_leg.
    #[arg(long)]
    pub segment: Option<String>,
}

/// Runs `bodyspace export-statismo`; prints `{out, bytes, part, points, triangles, modes, units}`.
pub fn run(args: &ExportStatismoArgs) -> Result<(), String> {
    let segment = match &args.segment {
        None => None,
        Some(name) => Some(Segment::from_name(name).ok_or_else(|| {
            format!(
                "unknown segment {name:?} (head, left_arm, right_arm, torso, left_leg, right_leg)"
            )
        })?),
    };
    let (model, _) = load_model(&args.model)?;
    let file = statismo_of_part(&model, segment);
    write_statismo_h5(&args.out, &file, &utc_now()).map_err(|e| e.to_string())?;
    let bytes = std::fs::metadata(&args.out)
        .map_err(|e| format!("{}: {e}", args.out.display()))?
        .len();
    println!(
        "{}",
        serde_json::json!({
            "out": args.out.display().to_string(),
            "bytes": bytes,
            "part": segment.map_or("whole", |s| s.name()),
            "points": file.point_count(),
            "triangles": file.cells.cols,
            "modes": file.mode_count(),
            "subjects": file.scores.cols,
            "units": "millimetres",
        })
    );
    Ok(())
}

/// The current time as `YYYY-MM-DD HH:MM:SS UTC` (statismo's build-time is free text).
fn utc_now() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs()) as i64;
    let (days, rest) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    // Days since 1970-01-01 to a civil date (the proleptic Gregorian calendar in 400-year eras).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02} {:02}:{:02}:{:02} UTC",
        rest / 3600,
        rest % 3600 / 60,
        rest % 60
    )
}
