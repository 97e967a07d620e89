//! `bodyspace body --model MODEL --measure stature=1.75 --measure waist_girth=0.82 --out
//! body.ply`: the most likely body of the model with those measurements
//! ([`crate::anthropometry::from_measurements`]); prints its coefficients and achieved vs target as JSON.

use super::model::{base_measurer, load_model, write_ply};
use crate::anthropometry::from_measurements::{body_from_measurements, FromMeasurementsParams};
use crate::measure::Measure;
use std::path::PathBuf;

/// Arguments of `bodyspace body`.
#[derive(clap::Args, Debug)]
pub struct BodyArgs {
    /// The model file.
    #[arg(long)]
    pub model: PathBuf,
    /// A target NAME=VALUE in m, m³ or m² (names as docs/measurements.md: stature,
    /// waist_girth, …); repeat for more.
    #[arg(long = "measure", required = true)]
    pub measures: Vec<String>,
    /// Where to write the body (binary PLY, metres, template vertex order).
    #[arg(long)]
    pub out: PathBuf,
}

/// `NAME=VALUE` → (measurement, value).
fn parse_target(s: &str) -> Result<(Measure, f64), String> {
    let (name, value) = s
        .split_once('=')
        .ok_or_else(|| format!("--measure {s}: expected NAME=VALUE"))?;
    let m = Measure::from_name(name.trim()).ok_or_else(|| {
        let names: Vec<&str> = Measure::ALL.iter().map(|m| m.definition().name).collect();
        format!(
            "--measure {s}: unknown measurement {name:?} (one of {})",
            names.join(", ")
        )
    })?;
    let v: f64 = value
        .trim()
        .parse()
        .map_err(|_| format!("--measure {s}: {value:?} is not a number"))?;
    Ok((m, v))
}

/// Runs `bodyspace body`; the error is the one-line message for stderr.
pub fn run(args: &BodyArgs) -> Result<(), String> {
    let targets = args
        .measures
        .iter()
        .map(|s| parse_target(s))
        .collect::<Result<Vec<_>, _>>()?;
    let (model, _) = load_model(&args.model)?;
    let measurer = base_measurer()?;
    let params = FromMeasurementsParams::default();
    let found = body_from_measurements(&model.whole, &measurer, &targets, &params)
        .map_err(|e| e.to_string())?;
    let positions = model
        .whole
        .body_at_sigma(&found.sigma)
        .map_err(|e| e.to_string())?;
    write_ply(&args.out, &positions, &model.triangles)?;
    let summary = serde_json::json!({
        "out": args.out.display().to_string(),
        "sigma": found.sigma,
        "mahalanobis": found.mahalanobis,
        "iterations": found.iterations,
        "achieved": found.achieved,
        "met": found.achieved.iter().all(|a| a.met),
    });
    println!("{summary}");
    Ok(())
}
