//! `bodyspace build-model --fits DIR[,DIR…] --out MODEL [--exclude-flagged] [--variance 0.99 |
//! --modes N] [--scale] [--f16] [--csv DIR] [--gltf FILE.glb]`.

use super::manifest::{read_manifest, Status};
use super::model::{read_fit, template_for_vertex_count};
use crate::anthropometry::outliers::{far_subjects, far_threshold};
use crate::model_file::export::{eigenvalues_csv, quality_csv, scores_csv};
use crate::model_file::file::{write_model, BasisPrecision};
use crate::pca::{
    build_body_model, BuildParams, GpaParams, PoseRemoval, QualityParams, TrainingSet,
};
use crate::template::Segment;
use std::collections::{BTreeMap, HashSet};
use std::path::{Path, PathBuf};

/// Arguments of `bodyspace build-model`.
#[derive(clap::Args, Debug)]
pub struct BuildModelArgs {
    /// Directory of fitted meshes (PLY, OBJ, STL, optionally .gz) in template vertex order; all
    /// are used. Repeat the flag or give a comma list to pool several folders (e.g. the shards
    /// of a `bodyspace batch`); subjects are taken in file-name order whatever the folder.
    #[arg(long, required = true, value_delimiter = ',')]
    pub fits: Vec<PathBuf>,
    /// Leave out subjects that `bodyspace batch` flagged or failed: each fits folder must sit in
    /// a batch output beside its manifest.csv (`OUT/fits` → `OUT/manifest.csv`).
    #[arg(long)]
    pub exclude_flagged: bool,
    /// The model file to write.
    #[arg(long)]
    pub out: PathBuf,
    /// Keep the leading modes explaining this fraction of the variance (never more than N−1).
    #[arg(long, default_value_t = 0.99)]
    pub variance: f64,
    /// Also remove each subject's size (similarity GPA); recorded in the model.
    #[arg(long)]
    pub scale: bool,
    /// Cap on the modes kept per model.
    #[arg(long, conflicts_with = "modes")]
    pub max_modes: Option<usize>,
    /// Keep exactly min(N, subjects − 1) modes per model, overriding the variance cut
    /// (recorded in the model's settings).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub modes: Option<u32>,
    /// Store the basis in half precision (half the file size).
    #[arg(long)]
    pub f16: bool,
    /// Write eigenvalues.csv, scores.csv and quality.csv into this directory.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Also write the whole-body model as binary glTF (GLB) with its modes as morph targets
    /// (morph weight = slider value in standard deviations).
    #[arg(long)]
    pub gltf: Option<PathBuf>,
    /// Skip generalization and specificity (compactness is always computed).
    #[arg(long)]
    pub no_quality: bool,
    /// Quality curves up to this many modes.
    #[arg(long, default_value_t = 20)]
    pub quality_modes: usize,
    /// Random shapes per mode count for specificity.
    #[arg(long, default_value_t = 100)]
    pub specificity_samples: usize,
}

/// Runs `bodyspace build-model`; the error is the one-line message for stderr.
pub fn run(args: &BuildModelArgs) -> Result<(), String> {
    let mut files: Vec<PathBuf> = Vec::new();
    for dir in &args.fits {
        let excluded = if args.exclude_flagged {
            flagged_subjects(dir)?
        } else {
            HashSet::new()
        };
        files.extend(
            fit_files(dir)?
                .into_iter()
                .filter(|f| !excluded.contains(&subject_of(f))),
        );
    }
    // By file name, then folder: one folder's order as before, and pooled shards in the order
    // of their union.
    files.sort_by(|a, b| a.file_name().cmp(&b.file_name()).then(a.cmp(b)));
    let mut seen: BTreeMap<String, &PathBuf> = BTreeMap::new();
    for f in &files {
        if let Some(other) = seen.insert(subject_of(f), f) {
            return Err(format!(
                "{} and {}: the same subject twice; pass each fits folder once",
                other.display(),
                f.display()
            ));
        }
    }
    let folders = args
        .fits
        .iter()
        .map(|d| d.display().to_string())
        .collect::<Vec<_>>()
        .join(", ");
    if files.len() < 2 {
        return Err(format!(
            "{folders}: {} PLY/OBJ fits found{}, a model needs at least 2",
            files.len(),
            if args.exclude_flagged {
                " (without flagged ones)"
            } else {
                ""
            }
        ));
    }
    let mut shapes = Vec::with_capacity(files.len());
    let mut names = Vec::with_capacity(files.len());
    for f in &files {
        shapes.push(read_fit(f)?.positions);
        names.push(
            f.file_stem()
                .and_then(|s| s.to_str())
                .unwrap_or("?")
                .to_string(),
        );
    }
    let template = template_for_vertex_count(shapes[0].len())
        .map_err(|e| format!("{}: {e}", files[0].display()))?;
    // The core brings each fit (in its scan's frame and units) into the template's frame.
    let set = TrainingSet::on_template(&template, names, shapes);
    let params = BuildParams {
        variance: args.variance,
        max_modes: args.max_modes,
        modes: args.modes.map(|n| n as usize),
        gpa: GpaParams {
            pose: if args.scale {
                PoseRemoval::Similarity
            } else {
                PoseRemoval::Rigid
            },
            ..GpaParams::default()
        },
        compute_quality: !args.no_quality,
        quality: QualityParams {
            max_modes: args.quality_modes,
            specificity_samples: args.specificity_samples,
            ..QualityParams::default()
        },
    };
    let model = build_body_model(&set, &params).map_err(|e| {
        let index = match &e {
            crate::pca::PcaError::VertexCountMismatch { subject, .. } => {
                set.names.iter().position(|n| n == subject)
            }
            _ => None,
        };
        match index {
            Some(i) => format!("{}: {e}", files[i].display()),
            None => e.to_string(),
        }
    })?;
    let precision = if args.f16 {
        BasisPrecision::F16
    } else {
        BasisPrecision::F32
    };
    let bytes = write_model(&model, precision);
    std::fs::write(&args.out, &bytes).map_err(|e| format!("{}: {e}", args.out.display()))?;
    if let Some(gltf) = &args.gltf {
        let glb = crate::model_file::gltf::model_glb(&model, usize::MAX);
        std::fs::write(gltf, glb).map_err(|e| format!("{}: {e}", gltf.display()))?;
    }
    if let Some(csv) = &args.csv {
        std::fs::create_dir_all(csv).map_err(|e| format!("{}: {e}", csv.display()))?;
        for (name, text) in [
            ("eigenvalues.csv", eigenvalues_csv(&model)),
            ("scores.csv", scores_csv(&model)),
            ("quality.csv", quality_csv(&model)),
        ] {
            let p = csv.join(name);
            std::fs::write(&p, text).map_err(|e| format!("{}: {e}", p.display()))?;
        }
    }
    let modes: serde_json::Map<String, serde_json::Value> =
        std::iter::once(("whole".to_string(), &model.whole))
            .chain(
                Segment::ALL
                    .iter()
                    .map(|s| (s.name().to_string(), model.segment(*s))),
            )
            .map(|(n, m)| {
                (
                    n,
                    serde_json::json!({
                        "vertices": m.vertex_count(),
                        "modes": m.mode_count(),
                        "sd": m.standard_deviations(),
                        "explained": m.quality.compactness.get(m.mode_count().saturating_sub(1)),
                    }),
                )
            })
            .collect();
    // Subjects far outside the whole-body model: kept, but listed (docs/batch.md).
    let far: Vec<serde_json::Value> = far_subjects(&model.whole)
        .into_iter()
        .map(|(i, d)| {
            eprintln!(
                "bodyspace build-model: {} is far outside the model (Mahalanobis distance {d:.1} > {:.1}); check its fit",
                model.subjects[i],
                far_threshold(model.whole.mode_count())
            );
            serde_json::json!({ "subject": model.subjects[i], "mahalanobis": d })
        })
        .collect();
    let summary = serde_json::json!({
        "far_from_model": far,
        "far_threshold": far_threshold(model.whole.mode_count()),
        "model": args.out.display().to_string(),
        "bytes": bytes.len(),
        "subjects": model.subjects.len(),
        "template": model.template,
        "pose_removal": model.settings.gpa.pose,
        "basis": precision,
        "models": modes,
        "csv": args.csv.as_ref().map(|d| d.display().to_string()),
        "gltf": args.gltf.as_ref().map(|d| d.display().to_string()),
    });
    println!("{summary}");
    Ok(())
}

/// The fit files (PLY, OBJ, STL, optionally .gz) in `dir`.
pub fn fit_files(dir: &Path) -> Result<Vec<PathBuf>, String> {
    Ok(std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            let ext = p
                .extension()
                .and_then(|e| e.to_str())
                .unwrap_or("")
                .to_ascii_lowercase();
            let name = p.to_string_lossy().to_ascii_lowercase();
            ["ply", "obj", "stl"].contains(&ext.as_str())
                || [".ply.gz", ".obj.gz", ".stl.gz"]
                    .iter()
                    .any(|e| name.ends_with(e))
        })
        .collect())
}

/// A fit's subject name: its file name without extensions (`a.ply.gz` → `a`), as
/// `bodyspace batch` names subjects.
pub fn subject_of(fit: &Path) -> String {
    let name = fit
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let name = name.strip_suffix(".gz").unwrap_or(&name);
    match name.rfind('.') {
        Some(dot) if dot > 0 => name[..dot].to_string(),
        _ => name.to_string(),
    }
}

/// Subjects of the batch whose fits are in `fits` (`OUT/fits`) that its manifest
/// (`OUT/manifest.csv`) lists as flagged or failed.
fn flagged_subjects(fits: &Path) -> Result<HashSet<String>, String> {
    let manifest = fits
        .canonicalize()
        .map_err(|e| format!("{}: {e}", fits.display()))?
        .parent()
        .map(|out| out.join("manifest.csv"))
        .filter(|m| m.is_file())
        .ok_or_else(|| {
            format!(
                "{}: --exclude-flagged needs the batch manifest beside this fits folder (../manifest.csv); point --fits at a `bodyspace batch` OUT/fits",
                fits.display()
            )
        })?;
    Ok(read_manifest(&manifest)?
        .into_iter()
        .filter(|row| row.status != Status::Ok)
        .map(|row| row.subject)
        .collect())
}
