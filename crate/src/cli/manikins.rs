//! `bodyspace manikins --model MODEL --measure stature --measure waist_girth --coverage 0.9
//! --out DIR`: the boundary manikins of 2–4 measurements ([`crate::anthropometry::boundary_manikins`]),
//! one PLY per manikin and `manikins.csv` in DIR, the summary as JSON on stdout.

use super::model::{base_measurer, load_model, write_ply};
use crate::anthropometry::boundary_manikins::{boundary_manikins, ManikinParams};
use crate::anthropometry::from_measurements::FromMeasurementsParams;
use crate::anthropometry::measurement_distribution::{
    sampled_measurements, DistributionParams, PopulationMeasurements,
};
use crate::measure::Measure;
use std::path::PathBuf;

/// Arguments of `bodyspace manikins`.
#[derive(clap::Args, Debug)]
pub struct ManikinsArgs {
    /// The model file.
    #[arg(long)]
    pub model: PathBuf,
    /// A measurement by name (stature, waist_girth, …; docs/measurements.md); give 2 to 4.
    #[arg(long = "measure", required = true)]
    pub measures: Vec<String>,
    /// Share of the population inside the boundary (default 0.9).
    #[arg(long)]
    pub coverage: Option<f64>,
    /// Points around the ellipse for two measurements (default 8).
    #[arg(long)]
    pub points: Option<usize>,
    /// Bodies sampled from the model to estimate the measurements' covariance (default 300).
    #[arg(long)]
    pub samples: Option<usize>,
    /// The folder to write `manikin_01.ply`, … and `manikins.csv` into (created if missing).
    #[arg(long)]
    pub out: PathBuf,
}

/// Runs `bodyspace manikins`; the error is the one-line message for stderr.
pub fn run(args: &ManikinsArgs) -> Result<(), String> {
    let measures = args
        .measures
        .iter()
        .map(|name| {
            Measure::from_name(name.trim()).ok_or_else(|| {
                let names: Vec<&str> = Measure::ALL.iter().map(|m| m.definition().name).collect();
                format!(
                    "--measure {name}: unknown measurement (one of {})",
                    names.join(", ")
                )
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    let defaults = ManikinParams::default();
    let params = ManikinParams {
        coverage: args.coverage.unwrap_or(defaults.coverage),
        ellipse_points: args.points.unwrap_or(defaults.ellipse_points),
    };
    let sampling = DistributionParams {
        samples: args
            .samples
            .unwrap_or(DistributionParams::default().samples),
        ..DistributionParams::default()
    };
    let (model, _) = load_model(&args.model)?;
    let measurer = base_measurer()?;
    let started = std::time::Instant::now();
    let population = PopulationMeasurements::of_bodies(
        sampled_measurements(
            &model.whole,
            &measurer,
            sampling.samples,
            sampling.seed,
            &mut |_| {},
        )
        .map_err(|e| e.to_string())?,
    );
    let found = boundary_manikins(
        &model.whole,
        &measurer,
        &population,
        &measures,
        &params,
        &FromMeasurementsParams::default(),
        &mut |_| {},
    )
    .map_err(|e| e.to_string())?;
    let seconds = started.elapsed().as_secs_f64();
    std::fs::create_dir_all(&args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    let mut files = Vec::new();
    for m in &found.manikins {
        let positions = model
            .whole
            .body_at_sigma(&m.body.sigma)
            .map_err(|e| e.to_string())?;
        let path = args.out.join(format!("{}.ply", m.name));
        write_ply(&path, &positions, &model.triangles)?;
        files.push(path.display().to_string());
    }
    let csv = args.out.join("manikins.csv");
    std::fs::write(&csv, found.to_csv()).map_err(|e| format!("{}: {e}", csv.display()))?;
    let mut summary = serde_json::to_value(&found).map_err(|e| e.to_string())?;
    summary["samples"] = serde_json::json!(sampling.samples);
    summary["files"] = serde_json::json!(files);
    summary["csv"] = serde_json::json!(csv.display().to_string());
    summary["seconds"] = serde_json::json!(seconds);
    println!("{summary}");
    Ok(())
}
