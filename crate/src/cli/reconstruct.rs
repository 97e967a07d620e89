//! `bodyspace reconstruct --model MODEL --coefficients FILE|LIST [--segment NAME=LIST ...]
//! [--sigma] --out BODY.ply`.
//!
//! Coefficients are in model units unless `--sigma` (then in standard deviations of each mode).
//! FILE is the JSON `project` prints (its `coefficients` object is used, with any segment
//! vectors in it) or a bare JSON array; LIST is comma-separated numbers. `--segment torso=...`
//! overrides one segment (the stitching semantics of `pca::stitch`).

use super::model::{load_model, measure_body, write_ply};
use crate::pca::{BodyModel, Coefficients};
use crate::template::Segment;
use std::path::PathBuf;

/// Arguments of `bodyspace reconstruct`.
#[derive(clap::Args, Debug)]
pub struct ReconstructArgs {
    /// The model file.
    #[arg(long)]
    pub model: PathBuf,
    /// Whole-body coefficients: a JSON file (as printed by `project`) or a comma-separated list.
    #[arg(long, allow_hyphen_values = true)]
    pub coefficients: String,
    /// A segment's own coefficients, NAME=LIST (head, left_arm, right_arm, torso, left_leg, right_leg).
    #[arg(long = "segment", allow_hyphen_values = true)]
    pub segments: Vec<String>,
    /// Values are in standard deviations (slider units) instead of model units.
    #[arg(long)]
    pub sigma: bool,
    /// Output PLY.
    #[arg(long)]
    pub out: PathBuf,
}

fn parse_list(text: &str, what: &str) -> Result<Vec<f64>, String> {
    if text.trim().is_empty() {
        return Ok(Vec::new());
    }
    text.split(',')
        .map(|t| {
            t.trim()
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| format!("{what}: {t:?} is not a number"))
        })
        .collect()
}

fn json_list(v: &serde_json::Value, what: &str) -> Result<Vec<f64>, String> {
    v.as_array()
        .ok_or_else(|| format!("{what} is not an array"))?
        .iter()
        .map(|x| {
            x.as_f64()
                .ok_or_else(|| format!("{what} holds a non-number"))
        })
        .collect()
}

fn read_coefficients(arg: &str) -> Result<Coefficients, String> {
    let path = std::path::Path::new(arg);
    if !path.is_file() {
        return Ok(Coefficients {
            whole: parse_list(arg, "--coefficients")?,
            ..Coefficients::default()
        });
    }
    let text = std::fs::read_to_string(path).map_err(|e| format!("{arg}: {e}"))?;
    let value: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| format!("{arg}: not JSON: {e}"))?;
    let object = value.get("coefficients").unwrap_or(&value);
    if object.is_array() {
        return Ok(Coefficients {
            whole: json_list(object, arg)?,
            ..Coefficients::default()
        });
    }
    let mut c = Coefficients {
        whole: json_list(
            object
                .get("whole")
                .ok_or_else(|| format!("{arg}: no \"whole\" coefficients"))?,
            arg,
        )?,
        ..Coefficients::default()
    };
    if let Some(segments) = object.get("segments").and_then(|s| s.as_object()) {
        for (name, list) in segments {
            let s =
                Segment::from_name(name).ok_or_else(|| format!("{arg}: unknown segment {name}"))?;
            c.segments[s.index()] = Some(json_list(list, &format!("{arg}: segment {name}"))?);
        }
    }
    Ok(c)
}

fn to_model_units(model: &BodyModel, c: &mut Coefficients) -> Result<(), String> {
    c.whole = model
        .whole
        .coefficients_from_sigma(&c.whole)
        .map_err(|e| format!("whole body: {e}"))?;
    for (s, b) in Segment::ALL.iter().zip(c.segments.iter_mut()) {
        if let Some(b) = b {
            *b = model
                .segment(*s)
                .coefficients_from_sigma(b)
                .map_err(|e| format!("segment {}: {e}", s.name()))?;
        }
    }
    Ok(())
}

/// Runs `bodyspace reconstruct`; the error is the one-line message for stderr.
pub fn run(args: &ReconstructArgs) -> Result<(), String> {
    let (model, _) = load_model(&args.model)?;
    let mut c = read_coefficients(&args.coefficients)?;
    for s in &args.segments {
        let (name, list) = s
            .split_once('=')
            .ok_or_else(|| format!("--segment {s}: expected NAME=LIST"))?;
        let segment = Segment::from_name(name)
            .ok_or_else(|| format!("--segment {s}: unknown segment {name}"))?;
        c.segments[segment.index()] = Some(parse_list(list, &format!("--segment {name}"))?);
    }
    if args.sigma {
        to_model_units(&model, &mut c)?;
    }
    let mut out = vec![0.0f32; 3 * model.template.vertex_count];
    model
        .reconstruct_into(&c, &mut out)
        .map_err(|e| e.to_string())?;
    let seam = model.seam_report(&c).map_err(|e| e.to_string())?;
    write_ply(&args.out, &out, &model.triangles)?;
    let measurements = measure_body(&out)?;
    let summary = serde_json::json!({
        "out": args.out.display().to_string(),
        "vertices": model.template.vertex_count,
        "coefficients": super::project::coefficients_json(&model, &c, false),
        "seam": seam,
        "measurements": measurements,
    });
    println!("{summary}");
    Ok(())
}
