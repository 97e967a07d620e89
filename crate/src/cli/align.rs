//! `bodyspace align --scan SCAN --landmarks FILE --rough-only --out warped.ply [...]`.
//!
//! Structure (the fine-alignment step extends this file): [`AlignArgs`] → [`load`] the scan,
//! its landmarks and the template → [`rough`] (paper §3.1, RBF warp) → write the PLY and print
//! the JSON report. Without `--rough-only` the fine step (paper §3.2, [`crate::align::fine_align`])
//! follows: the warped template, in metres, is fitted to the scan by per-vertex affine transforms;
//! the result is written in template vertex order, in the scan's frame and units.

use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::time::Instant;

use serde_json::{json, Value};

use crate::io::{read_landmarks, read_scan, write_ply};
use crate::landmarks::LandmarkSet;
use crate::mesh::Mesh;
use crate::rbf::{rbf_warp_mesh, Kernel, RbfParams, RbfWarp};
use crate::template::{Resolution, Template};

/// Arguments of `bodyspace align`.
#[derive(clap::Args, Debug)]
pub struct AlignArgs {
    /// The scan: PLY, OBJ or STL, optionally gzip-compressed, in any frame and units.
    #[arg(long)]
    pub scan: PathBuf,
    /// The scan's landmarks: CSV, CAESAR .lnd or JSON (missing ones are skipped).
    #[arg(long)]
    pub landmarks: PathBuf,
    /// Stop after the RBF rough deformation (paper §3.1).
    #[arg(long)]
    pub rough_only: bool,
    /// Where to write the warped template (PLY, template vertex order, scan frame and units).
    #[arg(long)]
    pub out: PathBuf,
    /// Radial basis function: thin-plate (default, measured best; docs/rbf.md), gaussian or
    /// multiquadric.
    #[arg(long, default_value = "thin-plate")]
    pub kernel: String,
    /// Kernel parameter in template metres: Gaussian width c or multiquadric stiffness s
    /// (default 0.1 for c, 0.01 for s; see docs/rbf.md).
    #[arg(long)]
    pub kernel_param: Option<f64>,
    /// Smoothing λ ≥ 0 added to the kernel diagonal (0 interpolates the landmarks exactly).
    #[arg(long, default_value_t = 0.0)]
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
    /// Weight a of the data error in fine alignment (paper Fig. 9: 0.96).
    #[arg(long, default_value_t = 0.96)]
    pub a: f64,
    /// Weight b of the smoothness error in fine alignment (paper Fig. 9: 0.04).
    #[arg(long, default_value_t = 0.04)]
    pub b: f64,
    /// Limit on fine-alignment L-BFGS iterations (at `fine`: of the base stage).
    #[arg(long, default_value_t = 200)]
    pub max_iterations: usize,
    /// At `fine`: limit on the iterations of the fine stage after the base fit.
    /// Default: CoarseToFineParams::default().fine.max_iterations.
    #[arg(long)]
    pub fine_iterations: Option<usize>,
    /// Weight of the landmark anchors in fine alignment (0 = off, the paper; see
    /// docs/fine-alignment.md). Default: FineAlignParams::default().landmark_weight.
    #[arg(long)]
    pub landmark_weight: Option<f64>,
    /// Weight of the scan-to-template term in fine alignment (scan points pull the template's
    /// triangles; 0 = off, the paper's energy; see docs/fine-alignment.md). Default:
    /// FineAlignParams::default().scan_term_weight.
    #[arg(long)]
    pub scan_term_weight: Option<f64>,
    /// Also write the JSON report to this file.
    #[arg(long)]
    pub report: Option<PathBuf>,
    /// Ground truth for a synthetic subject: PLY whose vertex i is template (base) vertex i on
    /// the subject, scan frame and units; adds the mean correspondence error to the report (at
    /// `fine`, over the base vertices, which come first).
    #[arg(long)]
    pub truth: Option<PathBuf>,
}

/// What `align` works on.
pub struct Inputs {
    pub scan: Mesh,
    pub scan_landmarks: LandmarkSet,
    pub template: Template,
}

/// Runs `bodyspace align`; the error is the one-line message for stderr.
pub fn run(args: &AlignArgs) -> Result<(), String> {
    if !args.rough_only {
        return super::align_fine::run_full(args);
    }
    let params = rough_params(args)?;
    let inputs = load(args)?;
    let started = Instant::now();
    let warp = rough(&inputs.template, &inputs, &params)?;
    let seconds = started.elapsed().as_secs_f64();
    let fitted = Mesh::new(
        warp.positions.clone(),
        inputs.template.mesh().triangles.clone(),
    );
    let out = args.out.display().to_string();
    std::fs::write(&args.out, write_ply(&fitted))
        .map_err(|e| format!("{out}: cannot write the warped template: {e}"))?;
    let report = rough_report(&inputs, &warp, &params, seconds, &out);
    println!(
        "{}",
        serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?
    );
    Ok(())
}

/// The RBF parameters from the command line.
pub fn rough_params(args: &AlignArgs) -> Result<RbfParams, String> {
    let kernel = Kernel::from_name(&args.kernel, args.kernel_param).ok_or_else(|| {
        format!(
            "--kernel {}: unknown kernel; use gaussian, thin-plate or multiquadric",
            args.kernel
        )
    })?;
    let params = RbfParams {
        kernel,
        affine: !args.no_affine,
        lambda: args.lambda,
        virtual_landmarks: !args.no_virtual,
        ..RbfParams::default()
    };
    kernel
        .validate()
        .map_err(|e| format!("--kernel-param: {e}"))?;
    if !(args.lambda.is_finite() && args.lambda >= 0.0) {
        return Err(format!("--lambda {}: must be finite and >= 0", args.lambda));
    }
    Ok(params)
}

fn read_file(path: &Path) -> Result<(Vec<u8>, String), String> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| format!("{name}: cannot read the file: {e}"))?;
    Ok((bytes, name))
}

/// Reads the scan, its landmarks and the embedded template at the requested resolution.
pub fn load(args: &AlignArgs) -> Result<Inputs, String> {
    let resolution = Resolution::from_str(&args.resolution)
        .map_err(|e| format!("--resolution {}: {e}", args.resolution))?;
    let (bytes, name) = read_file(&args.scan)?;
    let scan = read_scan(&bytes, &name).map_err(|e| e.to_string())?;
    let (bytes, name) = read_file(&args.landmarks)?;
    let scan_landmarks = read_landmarks(&bytes, &name).map_err(|e| e.to_string())?;
    let template = Template::embedded()
        .map_err(|e| format!("embedded template: {e}"))?
        .at_resolution(resolution);
    Ok(Inputs {
        scan,
        scan_landmarks,
        template,
    })
}

/// The rough step: `template` (the inputs' template, or its base for coarse-to-fine alignment)
/// warped onto the scan by its landmarks (paper §3.1).
pub fn rough(template: &Template, inputs: &Inputs, params: &RbfParams) -> Result<RbfWarp, String> {
    rbf_warp_mesh(
        template.mesh(),
        &template.landmark_positions(),
        &inputs.scan,
        &inputs.scan_landmarks,
        params,
    )
    .map_err(|e| format!("RBF warp: {e}"))
}

/// The JSON report of the rough step. Distances are in the scan's units.
pub fn rough_report(
    inputs: &Inputs,
    warp: &RbfWarp,
    params: &RbfParams,
    seconds: f64,
    out: &str,
) -> Value {
    let s = &warp.similarity;
    let rows = |m: &nalgebra::Matrix3<f64>| -> Vec<[f64; 3]> {
        (0..3).map(|r| [m[(r, 0)], m[(r, 1)], m[(r, 2)]]).collect()
    };
    let max = |f: fn(&crate::rbf::LandmarkResidual) -> f64| {
        warp.residuals.iter().map(f).fold(0.0, f64::max)
    };
    json!({
        "step": "rough",
        "out": out,
        "template_resolution": inputs.template.resolution().name(),
        "template_vertices": warp.positions.len(),
        "scan_vertices": inputs.scan.positions.len(),
        "kernel": params.kernel.name(),
        "kernel_param": params.kernel.param(),
        "affine": params.affine,
        "lambda": params.lambda,
        "virtual_landmarks": params.virtual_landmarks,
        "landmarks_used": warp.used.len(),
        "used": warp.used,
        "skipped": warp.skipped,
        "virtual_off_surface": warp.virtual_off_surface,
        "rcond": warp.network.rcond(),
        "similarity": {
            "scale": s.scale,
            "rotation": rows(&s.rotation),
            "translation": [s.translation.x, s.translation.y, s.translation.z],
        },
        "max_residual_before": max(|r| r.before),
        "max_residual_after": max(|r| r.after),
        "residuals": warp.residuals,
        "seconds": seconds,
    })
}
