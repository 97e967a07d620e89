//! `bodyspace align --scan SCAN [--landmarks FILE] --out fit.ply [...]`: the arguments become one
//! [`AlignParams`] (every default read from the core), the files one [`AlignInput`]; the core's
//! [`align_scan`] does the rest. Writes the fit (or, with `--rough-only`, the RBF-warped template)
//! as PLY in template vertex order, in the scan's frame and units, and prints the
//! [`crate::align::AlignmentReport`] as JSON. Without `--landmarks` the landmarks are estimated
//! first ([`super::landmarks::estimate`]); the report then has `landmarks_estimated: true` and the
//! estimate's report under `estimate`.

use std::path::PathBuf;
use std::str::FromStr;

use serde::Serialize;

use super::read_file;
use super::truth::read_truth;
use crate::align::{align_scan, AlignInput, AlignParams, AlignmentReport, FineStageParams, Preset};
use crate::estimate::EstimateReport;
use crate::io::{read_landmarks, read_scan, write_ply};
use crate::landmarks::LandmarkSet;
use crate::mesh::Mesh;
use crate::rbf::{Kernel, RbfParams};
use crate::template::{Resolution, Template};

/// Arguments of `bodyspace align`.
#[derive(clap::Args, Debug)]
pub struct AlignArgs {
    /// The scan: PLY, OBJ or STL, optionally gzip-compressed, in any frame and units.
    #[arg(long)]
    pub scan: PathBuf,
    /// The scan's landmarks: CSV, CAESAR .lnd or JSON (missing ones are skipped). Without it
    /// the 73 landmarks are estimated from the scan first (`bodyspace landmarks`).
    #[arg(long)]
    pub landmarks: Option<PathBuf>,
    /// Stop after the RBF rough deformation (paper §3.1).
    #[arg(long)]
    pub rough_only: bool,
    /// Where to write the fitted template (PLY, template vertex order, scan frame and units).
    #[arg(long)]
    pub out: PathBuf,
    /// Radial basis function: thin-plate, gaussian or multiquadric (docs/rbf.md).
    #[arg(long, default_value = RbfParams::default().kernel.name())]
    pub kernel: String,
    /// Kernel parameter in template metres: Gaussian width c or multiquadric stiffness s
    /// (default: the kernel's own, docs/rbf.md).
    #[arg(long)]
    pub kernel_param: Option<f64>,
    /// Smoothing λ ≥ 0 added to the kernel diagonal (0 interpolates the landmarks exactly).
    #[arg(long, default_value_t = RbfParams::default().lambda)]
    pub lambda: f64,
    /// Leave out the affine term of the RBF.
    #[arg(long)]
    pub no_affine: bool,
    /// Leave out the 12 virtual landmarks.
    #[arg(long)]
    pub no_virtual: bool,
    /// Template resolution: base or fine. Fine is aligned coarse to fine: the base template is
    /// warped and fitted, carried to fine by the subdivision operator, then fitted briefly at
    /// fine (docs/fine-alignment.md).
    #[arg(long, default_value = "base")]
    pub resolution: String,
    /// Parameter preset: paper (the paper's method, today's default) or anchored (issue 12's
    /// additions; docs/fine-alignment.md). The options below change the preset's values.
    #[arg(long, default_value = "paper", value_parser = ["paper", "anchored"])]
    pub preset: String,
    /// Weight a of the data error in fine alignment (paper Fig. 9; default: the preset's, 0.96).
    #[arg(long)]
    pub a: Option<f64>,
    /// Weight b of the smoothness error in fine alignment (paper Fig. 9; default: the preset's,
    /// paper 0.04).
    #[arg(long)]
    pub b: Option<f64>,
    /// Limit on fine-alignment L-BFGS iterations (at `fine`: of the base stage; default: the
    /// preset's, 200).
    #[arg(long)]
    pub max_iterations: Option<usize>,
    /// At `fine`: limit on the iterations of the fine stage after the base fit.
    #[arg(long, default_value_t = FineStageParams::default().max_iterations)]
    pub fine_iterations: usize,
    /// Weight of the landmark anchors in fine alignment (0 = off, the paper; see
    /// docs/fine-alignment.md; default: the preset's, 0).
    #[arg(long)]
    pub landmark_weight: Option<f64>,
    /// Weight of the scan-to-template term in fine alignment (scan points pull the template's
    /// triangles; 0 = off, the paper's energy; see docs/fine-alignment.md; default: the
    /// preset's, 1).
    #[arg(long)]
    pub scan_term_weight: Option<f64>,
    /// Also write the JSON report to this file.
    #[arg(long)]
    pub report: Option<PathBuf>,
    /// Ground truth for a synthetic subject: PLY whose vertex i is template (base) vertex i on
    /// the subject, scan frame and units; adds the correspondence error to the report (at
    /// `fine`, over the base vertices, which come first).
    #[arg(long)]
    pub truth: Option<PathBuf>,
}

impl AlignArgs {
    /// The pipeline's parameters: the core's defaults with what the command line sets.
    pub fn params(&self) -> Result<AlignParams, String> {
        let kernel = Kernel::from_name(&self.kernel, self.kernel_param).ok_or_else(|| {
            format!(
                "--kernel {}: unknown kernel; use gaussian, thin-plate or multiquadric",
                self.kernel
            )
        })?;
        kernel
            .validate()
            .map_err(|e| format!("--kernel-param: {e}"))?;
        if !(self.lambda.is_finite() && self.lambda >= 0.0) {
            return Err(format!("--lambda {}: must be finite and >= 0", self.lambda));
        }
        let preset = Preset::from_name(&self.preset)
            .ok_or_else(|| format!("--preset {}: paper or anchored", self.preset))?;
        let defaults = preset.params();
        let mut fine = defaults.fine.clone();
        fine.a = self.a.unwrap_or(fine.a);
        fine.b = self.b.unwrap_or(fine.b);
        fine.max_iterations = self.max_iterations.unwrap_or(fine.max_iterations);
        fine.landmark_weight = self.landmark_weight.unwrap_or(fine.landmark_weight);
        fine.scan_term_weight = self.scan_term_weight.unwrap_or(fine.scan_term_weight);
        let params = AlignParams {
            preset,
            pose_parts: defaults.pose_parts,
            rbf: RbfParams {
                kernel,
                affine: !self.no_affine,
                lambda: self.lambda,
                virtual_landmarks: !self.no_virtual,
                ..defaults.rbf
            },
            fine,
            fine_stage: FineStageParams {
                max_iterations: self.fine_iterations,
                ..defaults.fine_stage
            },
            rough_only: self.rough_only,
        };
        params.validate().map_err(|e| e.to_string())?;
        Ok(params)
    }
}

/// Runs `bodyspace align`; the error is the one-line message for stderr.
pub fn run(args: &AlignArgs) -> Result<(), String> {
    let params = args.params()?;
    let resolution = Resolution::from_str(&args.resolution)
        .map_err(|e| format!("--resolution {}: {e}", args.resolution))?;
    let scan_name = args.scan.display().to_string();
    let scan = read_scan(&read_file(&args.scan)?, &scan_name).map_err(|e| e.to_string())?;
    let template = Template::embedded()
        .map_err(|e| format!("embedded template: {e}"))?
        .at_resolution(resolution);
    let (landmarks, estimate) = match &args.landmarks {
        Some(path) => (
            read_landmarks(&read_file(path)?, &path.display().to_string())
                .map_err(|e| e.to_string())?,
            None,
        ),
        None => {
            let estimate =
                super::landmarks::estimate(&template, &scan, &LandmarkSet::default(), &args.scan)?;
            (estimate.to_set(), Some(estimate.report))
        }
    };
    let input = AlignInput {
        template: &template,
        base_template: None,
        scan: &scan,
        landmarks: &landmarks,
        units: None,
    };
    let mut alignment = align_scan(&input, &params, &mut ()).map_err(|e| match e {
        crate::align::PipelineError::Scan(e) => format!("{scan_name}: {e}"),
        e => e.to_string(),
    })?;
    if let Some(path) = &args.truth {
        let expected = [
            template.base_vertex_count(),
            template.mesh().positions.len(),
        ];
        let truth = read_truth(path, &expected, alignment.scale_to_metres)?;
        alignment.compare_with_truth(&template, &truth);
    }

    let to_m = alignment.scale_to_metres;
    let fitted = Mesh::new(
        alignment.positions.iter().map(|p| p / to_m).collect(),
        template.mesh().triangles.clone(),
    );
    std::fs::write(&args.out, write_ply(&fitted)).map_err(|e| {
        format!(
            "{}: cannot write the fitted template: {e}",
            args.out.display()
        )
    })?;
    let report = Report {
        landmarks_estimated: estimate.is_some(),
        estimate: estimate.as_ref(),
        alignment: &alignment.report,
    };
    let text = serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?;
    if let Some(path) = &args.report {
        std::fs::write(path, &text)
            .map_err(|e| format!("{}: cannot write the report: {e}", path.display()))?;
    }
    println!("{text}");
    Ok(())
}

/// What `align` prints: the alignment report, and whether (and how) the landmarks were estimated.
#[derive(Serialize)]
struct Report<'a> {
    landmarks_estimated: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    estimate: Option<&'a EstimateReport>,
    #[serde(flatten)]
    alignment: &'a AlignmentReport,
}
