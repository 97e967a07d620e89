//! `bodyspace measure`: the measurements of `crate::measure` (docs/measurements.md) of one fit as
//! JSON (`--mesh FIT`, with `--model MODEL` also its percentile among the model's training
//! subjects, with `--report R` each value's trust from the subject report `align` wrote), of
//! every fit of a folder as one CSV (`--fits DIR --csv OUT.csv`; beside a batch's `reports/`, a
//! last column `doubtful` names each fit's doubtful measurements), or their
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
    /// With --mesh: the subject report `align --report` wrote for this fit; each measurement is
    /// then printed with its trust (placed, body_defined, estimated or doubtful) and the doubtful
    /// ones in words.
    #[arg(long, requires = "mesh")]
    pub report: Option<PathBuf>,
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
            if let Some(path) = &args.report {
                let trust = report_trust(path)?;
                summary["report"] = serde_json::json!(path.display().to_string());
                summary["trust"] = trust
                    .iter()
                    .map(|t| (t.name.clone(), serde_json::json!(t.verdict())))
                    .collect::<serde_json::Map<_, _>>()
                    .into();
                summary["doubtful"] = trust
                    .iter()
                    .filter(|t| t.doubtful)
                    .map(|t| t.words.clone())
                    .collect();
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
            let reports = dir
                .parent()
                .map(|p| p.join("reports"))
                .filter(|r| r.is_dir());
            let mut doubtful = Vec::with_capacity(fits.len());
            for fit in &fits {
                let mesh = read_fit(fit)?;
                let m = measure_any_frame(&measurer, &base, &mesh.positions)
                    .map_err(|e| format!("{}: {e}", fit.display()))?;
                if let Some(reports) = &reports {
                    let report = reports.join(format!("{}.json", subject_of(fit)));
                    let names: Vec<String> = match report.exists() {
                        true => report_trust(&report)?
                            .into_iter()
                            .filter(|t| t.doubtful)
                            .map(|t| t.name)
                            .collect(),
                        false => Vec::new(),
                    };
                    doubtful.push(names.join(" "));
                }
                rows.push((subject_of(fit), m));
            }
            let mut text = population_csv(&rows);
            if reports.is_some() {
                text = with_doubtful_column(&text, &doubtful);
            }
            std::fs::write(csv, text).map_err(|e| format!("{}: {e}", csv.display()))?;
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

/// One measurement's trust as a subject report wrote it (`measure/trust.rs`).
struct ReportedTrust {
    name: String,
    trust: String,
    doubtful: bool,
    words: String,
}

impl ReportedTrust {
    /// `placed`, `body_defined`, `estimated`, or `doubtful` for a doubtful one.
    fn verdict(&self) -> &str {
        if self.doubtful {
            "doubtful"
        } else {
            &self.trust
        }
    }
}

/// The `measurement_trust` of the subject report at `path` (`align --report`, a batch's
/// `reports/SUBJECT.json`).
fn report_trust(path: &Path) -> Result<Vec<ReportedTrust>, String> {
    let text = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let report: serde_json::Value =
        serde_json::from_slice(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    let rows = report["measurement_trust"].as_array().ok_or_else(|| {
        format!(
            "{}: no measurement_trust (not a subject report, or one from before it: align again)",
            path.display()
        )
    })?;
    Ok(rows
        .iter()
        .map(|t| ReportedTrust {
            name: t["name"].as_str().unwrap_or_default().to_string(),
            trust: t["trust"].as_str().unwrap_or_default().to_string(),
            doubtful: t["doubtful"].as_bool().unwrap_or(false),
            words: t["words"].as_str().unwrap_or_default().to_string(),
        })
        .collect())
}

/// `csv` (a header and one line per row) with a last column `doubtful`: each row's names,
/// space-separated.
fn with_doubtful_column(csv: &str, doubtful: &[String]) -> String {
    let mut out = String::with_capacity(csv.len());
    for (i, line) in csv.lines().enumerate() {
        let last = match i {
            0 => "doubtful",
            _ => doubtful.get(i - 1).map_or("", String::as_str),
        };
        writeln!(out, "{line},{last}").ok();
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
