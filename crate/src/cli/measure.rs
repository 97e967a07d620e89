//! `bodyspace measure`: the measurements of `crate::measure` (docs/measurements.md) of one fit as
//! JSON (`--mesh FIT`, with `--model MODEL` also its percentile among the model's training
//! subjects), or of every fit of a folder as one CSV (`--fits DIR --csv OUT.csv`).

use super::build_model::{fit_files, subject_of};
use super::model::{base_measurer, load_model, measure_any_frame, read_fit};
use crate::measure::{BodyMeasurer, Measure, Measurements};
use crate::template::Template;
use nalgebra::Point3;
use std::fmt::Write;
use std::path::PathBuf;

/// Arguments of `bodyspace measure`.
#[derive(clap::Args, Debug)]
pub struct MeasureArgs {
    /// A fitted mesh (PLY, OBJ, STL, optionally .gz) in template vertex order, base or fine, in
    /// any frame and in metres or millimetres (as `align` writes it).
    #[arg(long, conflicts_with = "fits", required_unless_present = "fits")]
    pub mesh: Option<PathBuf>,
    /// With --mesh: also each measurement's percentile among the model's training subjects.
    #[arg(long, requires = "mesh")]
    pub model: Option<PathBuf>,
    /// A folder of fits (`batch`'s OUT/fits): one CSV row per fit, with --csv.
    #[arg(long, requires = "csv")]
    pub fits: Option<PathBuf>,
    /// The population's CSV: `subject` then one column per measurement (m, m³, m²; empty: not
    /// taken), rows in file-name order.
    #[arg(long, requires = "fits")]
    pub csv: Option<PathBuf>,
}

/// Runs `bodyspace measure`; the error is the one-line message for stderr.
pub fn run(args: &MeasureArgs) -> Result<(), String> {
    let base = Template::embedded().map_err(|e| format!("embedded template: {e}"))?;
    let measurer = base_measurer()?;
    match (&args.mesh, &args.fits, &args.csv) {
        (Some(mesh), _, _) => {
            let fit = read_fit(mesh)?;
            let m = measure_any_frame(&measurer, &base, &fit.positions)
                .map_err(|e| format!("{}: {e}", mesh.display()))?;
            let mut summary = serde_json::json!({
                "mesh": mesh.display().to_string(),
                "measurements": m,
            });
            if let Some(path) = &args.model {
                let population = training_measurements(path, &measurer, &base)?;
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

/// The measurements of every training subject of the model at `path` (whole-body scores).
fn training_measurements(
    path: &std::path::Path,
    measurer: &BodyMeasurer,
    base: &Template,
) -> Result<Vec<Measurements>, String> {
    let (model, _) = load_model(path)?;
    let whole = &model.whole;
    (0..model.subjects.len())
        .map(|i| {
            let scores: Vec<f64> = whole
                .subject_scores(i)
                .ok_or_else(|| format!("{}: subject {i} has no scores", path.display()))?
                .iter()
                .map(|&x| x as f64)
                .collect();
            let flat = whole.reconstruct(&scores).map_err(|e| e.to_string())?;
            let points: Vec<Point3<f64>> = flat
                .chunks_exact(3)
                .map(|p| Point3::new(p[0], p[1], p[2]))
                .collect();
            measure_any_frame(measurer, base, &points)
        })
        .collect()
}

/// `{name: percentile}`: the share of `population` below each value, ties counted half (%).
fn percentiles(m: &Measurements, population: &[Measurements]) -> serde_json::Value {
    let mut out = serde_json::Map::new();
    for k in Measure::ALL {
        let value = m.get(k).and_then(|x| {
            let values: Vec<f64> = population.iter().filter_map(|p| p.get(k)).collect();
            (!values.is_empty()).then(|| {
                let below = values.iter().filter(|&&v| v < x).count() as f64;
                let equal = values.iter().filter(|&&v| v == x).count() as f64;
                100.0 * (below + 0.5 * equal) / values.len() as f64
            })
        });
        out.insert(k.definition().name.into(), serde_json::json!(value));
    }
    serde_json::Value::Object(out)
}
