//! `bodyspace info SCAN [--landmarks FILE]`, or `bodyspace info MODEL` for a shape model
//! (`.bsm` or statismo `.h5`).

use std::path::{Path, PathBuf};

use crate::io::{read_landmarks, read_scan};
use crate::landmarks::report;
use crate::mesh::summarise;

/// Arguments of `bodyspace info`.
#[derive(clap::Args, Debug)]
pub struct InfoArgs {
    /// The scan: PLY, OBJ or STL, optionally gzip-compressed; or a shape model (`.bsm`, or a
    /// statismo `.h5` made on the template).
    pub scan: PathBuf,
    /// A landmark file: CSV, CAESAR .lnd or JSON.
    #[arg(long)]
    pub landmarks: Option<PathBuf>,
}

fn read_file(path: &Path) -> Result<(Vec<u8>, String), String> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| format!("{name}: cannot read the file: {e}"))?;
    Ok((bytes, name))
}

/// Runs `bodyspace info`: prints one JSON object (`vertices`, `triangles`, `bbox_min`/`bbox_max`
/// in metres, `units_detected`, `scale_to_metres`, `boundary_loops`, `components`, `winding`
/// (`outward`, `inward` or `mixed`: which way the triangles face), and with
/// `--landmarks` also `landmarks_found`, `landmarks_missing`, `landmarks_unknown`). The error is
/// the one-line message for stderr.
pub fn run(args: &InfoArgs) -> Result<(), String> {
    let (bytes, name) = read_file(&args.scan)?;
    if bytes.starts_with(crate::model_file::file::MAGIC) || super::model::is_hdf5(&args.scan)? {
        return model_info(&args.scan);
    }
    let mesh = read_scan(&bytes, &name).map_err(|e| e.to_string())?;
    let summary = summarise(&mesh);
    let mut json = serde_json::to_value(&summary).map_err(|e| e.to_string())?;
    if let Some(path) = &args.landmarks {
        let (bytes, name) = read_file(path)?;
        let set = read_landmarks(&bytes, &name).map_err(|e| e.to_string())?;
        let r = report(&set);
        if let Some(object) = json.as_object_mut() {
            object.insert("landmarks_found".into(), r.found.into());
            object.insert("landmarks_missing".into(), r.missing.into());
            object.insert("landmarks_unknown".into(), r.unknown.into());
        }
    }
    println!("{json}");
    Ok(())
}

/// Prints a model's JSON summary: template, subjects, and per part (whole body, then the six
/// segments) its vertex count, modes and variances (m²). The model is read by the one model
/// reader of every `--model` command (`cli::model::load_model`).
fn model_info(path: &Path) -> Result<(), String> {
    let (model, _) = super::model::load_model(path)?;
    let parts: Vec<_> = std::iter::once(("whole", &model.whole))
        .chain(
            crate::template::Segment::ALL
                .iter()
                .map(|s| (s.name(), model.segment(*s))),
        )
        .map(|(name, m)| {
            serde_json::json!({"name": name, "vertices": m.vertex_count(), "modes": m.mode_count(), "variances": m.variances})
        })
        .collect();
    println!(
        "{}",
        serde_json::json!({
            "model": path.display().to_string(),
            "template": model.template,
            "subjects": model.subjects.len(),
            "triangles": model.triangles.len(),
            "parts": parts,
        })
    );
    Ok(())
}
