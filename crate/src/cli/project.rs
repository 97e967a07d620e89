//! `bodyspace project --model MODEL --mesh FIT`: prints the fit's coefficients as JSON.

use super::model::{load_model, read_fit};
use crate::pca::BodyModel;
use crate::pca::Coefficients;
use crate::template::Segment;
use std::path::PathBuf;

/// Arguments of `bodyspace project`.
#[derive(clap::Args, Debug)]
pub struct ProjectArgs {
    /// The model file.
    #[arg(long)]
    pub model: PathBuf,
    /// A fitted mesh (PLY or OBJ) in the model's template vertex order.
    #[arg(long)]
    pub mesh: PathBuf,
}

/// Coefficients as `{"whole": [...], "segments": {"head": [...], ...}}` (model units); the
/// format `reconstruct --coefficients FILE` reads back.
pub fn coefficients_json(model: &BodyModel, c: &Coefficients, sigma: bool) -> serde_json::Value {
    let convert = |m: &crate::pca::ShapeModel, b: &[f64]| {
        if sigma {
            m.sigma_from_coefficients(b)
        } else {
            b.to_vec()
        }
    };
    let segments: serde_json::Map<String, serde_json::Value> = Segment::ALL
        .iter()
        .zip(&c.segments)
        .filter_map(|(s, b)| {
            b.as_ref().map(|b| {
                (
                    s.name().to_string(),
                    serde_json::json!(convert(model.segment(*s), b)),
                )
            })
        })
        .collect();
    serde_json::json!({ "whole": convert(&model.whole, &c.whole), "segments": segments })
}

/// Runs `bodyspace project`; the error is the one-line message for stderr.
pub fn run(args: &ProjectArgs) -> Result<(), String> {
    let (model, _) = load_model(&args.model)?;
    let mesh = read_fit(&args.mesh)?;
    let p = model
        .project(&mesh.positions)
        .map_err(|e| format!("{}: {e}", args.mesh.display()))?;
    let summary = serde_json::json!({
        "mesh": args.mesh.display().to_string(),
        "coefficients": coefficients_json(&model, &p.coefficients, false),
        "sigma": coefficients_json(&model, &p.coefficients, true),
        "residual_m": p.residual,
        "pose": {
            "rotation": p.pose.rotation.transpose().as_slice(),
            "translation": p.pose.translation.as_slice(),
            "scale": p.pose.scale,
        },
    });
    println!("{summary}");
    Ok(())
}
