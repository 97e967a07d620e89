//! `bodyspace measure`: the measurements of `crate::measure` (docs/measurements.md) of one fit as
//! JSON (`--mesh FIT`, with `--model MODEL` also its percentile among the model's training
//! subjects), of every fit of a folder as one CSV (`--fits DIR --csv OUT.csv`), or their
//! distribution in a model (`--model MODEL --distribution [--samples N] [--csv OUT.csv]`,
//! [`crate::anthropometry::measurement_distribution`]).

use super::build_model::{fit_files, subject_of};
use super::model::{base_measurer, load_model, measure_any_frame, read_fit};
use crate::anthropometry::measurement_distribution::{
    measurement_distribution, training_measurements, DistributionParams, PopulationMeasurements,
};
use crate::measure::{BodyMeasurer, Measure, Measurements};
use crate::template::Template;
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// Arguments of `bodyspace measure`.
#[derive(clap::Args, Debug)]
pub struct MeasureArgs {
    /// A fitted mesh (PLY, OBJ, STL, optionally .gz) in template vertex order, base or fine, in
    /// any frame and in metres or millimetres (as `align` writes it).
    #[arg(
        long,
        conflicts_with_all = ["fits", "distribution"],
        required_unless_present_any = ["fits", "distribution"]
    )]
    pub mesh: Option<PathBuf>,
    /// With --mesh: also each measurement's percentile among the model's training subjects.
    /// With --distribution: the model whose distribution is printed.
    #[arg(long)]
    pub model: Option<PathBuf>,
    /// A folder of fits (`batch`'s OUT/fits): one CSV row per fit, with --csv.
    #[arg(long, requires = "csv", conflicts_with_all = ["distribution", "model"])]
    pub fits: Option<PathBuf>,
    /// Every measurement over the model's training subjects and over bodies sampled from it:
    /// sorted values, percentiles 5/25/50/75/95, mean, sd and correlations, as JSON.
    #[arg(long, requires = "model")]
    pub distribution: bool,
    /// With --distribution: bodies sampled from the model (default 300).
    #[arg(long, requires = "distribution")]
    pub samples: Option<usize>,
    /// With --distribution: the seed of the samples (default 1).
    #[arg(long, requires = "distribution")]
    pub seed: Option<u64>,
    /// The population's CSV: `subject` then one column per measurement (m, m³, m²; empty: not
    /// taken). With --fits: rows in file-name order; with --distribution: the training subjects
    /// (`training:NAME`) then the samples (`sample_0001`, …).
    #[arg(long)]
    pub csv: Option<PathBuf>,
}

/// Runs `bodyspace measure`; the error is the one-line message for stderr.
pub fn run(args: &MeasureArgs) -> Result<(), String> {
    let base = Template::embedded().map_err(|e| format!("embedded template: {e}"))?;
    let measurer = base_measurer()?;
    if args.distribution {
        let model = args
            .model
            .as_deref()
            .ok_or("--distribution needs --model MODEL")?;
        return distribution(model, &measurer, args);
    }
    match (&args.mesh, &args.fits, &args.csv) {
        (Some(_), _, Some(_)) => Err("--csv goes with --fits DIR or --distribution".into()),
        (Some(mesh), _, _) => {
            let fit = read_fit(mesh)?;
            let m = measure_any_frame(&measurer, &base, &fit.positions)
                .map_err(|e| format!("{}: {e}", mesh.display()))?;
            let mut summary = serde_json::json!({
                "mesh": mesh.display().to_string(),
                "measurements": m,
            });
            if let Some(path) = &args.model {
                let (model, _) = load_model(path)?;
                let population = PopulationMeasurements::of_bodies(
                    training_measurements(&model.whole, &measurer).map_err(|e| e.to_string())?,
                );
                summary["model"] = serde_json::json!(path.display().to_string());
                summary["percentiles"] = percentiles(&m, &population);
            }
            println!("{summary}");
            Ok(())
        }
        (None, Some(dir), Some(csv)) => {
            let mut fits = fit_files(dir)?;
            fits.sort();
            if fits.is_empty() {
                return Err(format!(
                    "{}: no fits (PLY, OBJ, STL) in the folder",
                    dir.display()
                ));
            }
            let mut rows = Vec::with_capacity(fits.len());
            for fit in &fits {
                let mesh = read_fit(fit)?;
                let m = measure_any_frame(&measurer, &base, &mesh.positions)
                    .map_err(|e| format!("{}: {e}", fit.display()))?;
                rows.push((subject_of(fit), m));
            }
            std::fs::write(csv, population_csv(&rows))
                .map_err(|e| format!("{}: {e}", csv.display()))?;
            println!(
                "{}",
                serde_json::json!({ "fits": fits.len(), "csv": csv.display().to_string() })
            );
            Ok(())
        }
        _ => Err("give --mesh FIT, or --fits DIR --csv OUT.csv".into()),
    }
}

/// `subject,stature,…` then one row per subject (values in m, m³, m²; empty when not taken).
pub fn population_csv(rows: &[(String, Measurements)]) -> String {
    let mut out = String::from("subject");
    for m in Measure::ALL {
        out.push(',');
        out.push_str(m.definition().name);
    }
    out.push('\n');
    for (subject, values) in rows {
        // Subject names come from file names: quote them, doubling quotes, as CSV does.
        write!(out, "\"{}\"", subject.replace('"', "\"\"")).ok();
        for m in Measure::ALL {
            out.push(',');
            if let Some(v) = values.get(m) {
                write!(out, "{v:.6}").ok();
            }
        }
        out.push('\n');
    }
    out
}

/// `{name: percentile}`: the share of `population` below each value, ties counted half (%).
fn percentiles(m: &Measurements, population: &PopulationMeasurements) -> serde_json::Value {
    let map = Measure::ALL
        .into_iter()
        .zip(population.percentiles_of(m))
        .map(|(k, p)| (k.definition().name.to_string(), serde_json::json!(p)))
        .collect();
    serde_json::Value::Object(map)
}

/// `measure --model MODEL --distribution`: the distribution as JSON, with --csv every body's row.
fn distribution(path: &Path, measurer: &BodyMeasurer, args: &MeasureArgs) -> Result<(), String> {
    let defaults = DistributionParams::default();
    let params = DistributionParams {
        samples: args.samples.unwrap_or(defaults.samples),
        seed: args.seed.unwrap_or(defaults.seed),
    };
    let (model, _) = load_model(path)?;
    let started = std::time::Instant::now();
    let d = measurement_distribution(&model.whole, measurer, &params, &mut |_| {})
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let seconds = started.elapsed().as_secs_f64();
    if let Some(csv) = &args.csv {
        let rows: Vec<(String, Measurements)> = model
            .subjects
            .iter()
            .map(|s| format!("training:{s}"))
            .zip(d.training.table.iter().cloned())
            .chain(
                (1..)
                    .map(|i| format!("sample_{i:04}"))
                    .zip(d.samples.table.iter().cloned()),
            )
            .collect();
        std::fs::write(csv, population_csv(&rows))
            .map_err(|e| format!("{}: {e}", csv.display()))?;
    }
    let mut summary = serde_json::to_value(&d).map_err(|e| e.to_string())?;
    summary["model"] = serde_json::json!(path.display().to_string());
    summary["measures"] = serde_json::json!(Measure::ALL
        .iter()
        .map(|m| m.definition().name)
        .collect::<Vec<_>>());
    summary["seconds"] = serde_json::json!(seconds);
    if let Some(csv) = &args.csv {
        summary["csv"] = serde_json::json!(csv.display().to_string());
    }
    println!("{summary}");
    Ok(())
}
