//! The flags `bodyspace align` and `bodyspace batch` share: every choice of the core's one path
//! from files to a fit ([`SubjectOptions`]), each default read from the core.

use std::path::{Path, PathBuf};
use std::str::FromStr;

use crate::align::{AlignParams, FineAlignParams, FineStageParams, Preset, QualityThresholds};
use crate::estimate::{Axis, Orientation};
use crate::rbf::{Kernel, RbfParams};
use crate::subject::options::NEARLY_FULL;
use crate::subject::SubjectOptions;
use crate::template::Resolution;

/// The frame a fit is written in.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Frame {
    /// The scan's own frame and units (the default: the fit lies on its scan).
    Scan,
    /// The template's frame: upright, y up, metres, facing +z (where bodies are compared).
    Template,
}

/// Options of the path from a subject's files to its fit.
#[derive(clap::Args, Debug, Clone)]
pub struct SubjectArgs {
    /// Template resolution: base or fine. Fine is aligned coarse to fine: the base template is
    /// warped and fitted, carried to fine by the subdivision operator, then fitted briefly at
    /// fine (docs/fine-alignment.md).
    #[arg(long, default_value = "base")]
    pub resolution: String,
    /// Parameter preset: paper (the paper's method, the default) or anchored (issue 12's
    /// additions; docs/fine-alignment.md). The options below change the preset's values.
    #[arg(long, default_value = "paper", value_parser = ["paper", "anchored"])]
    pub preset: String,
    /// Stop after the RBF rough deformation (paper §3.1).
    #[arg(long)]
    pub rough_only: bool,
    #[command(flatten)]
    pub rbf: RbfArgs,
    #[command(flatten)]
    pub fine: FineArgs,
    /// Take given landmark files as they are: no check for suspicious landmarks (the check is
    /// cheap; docs/batch.md).
    #[arg(long)]
    pub no_landmark_check: bool,
    /// A landmark file with at least this many of the 73 CAESAR landmarks is checked, not filled
    /// in by the estimate; its missing landmarks stay absent.
    #[arg(long, default_value_t = NEARLY_FULL)]
    pub nearly_full: usize,
    #[command(flatten)]
    pub quality: QualityArgs,
    /// The frame the fit is written in: scan (its scan's frame and units) or template (upright,
    /// y up, metres, facing +z). The report records the motion between the two either way.
    #[arg(long, value_enum, default_value = "scan")]
    pub frame: Frame,
    #[command(flatten)]
    pub orientation: OrientationArgs,
}

/// The RBF warp's flags (paper §3.1; [`RbfParams`]).
#[derive(clap::Args, Debug, Clone)]
pub struct RbfArgs {
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
}

impl RbfArgs {
    /// The preset's RBF parameters `defaults` with what the flags set, checked.
    pub fn params(&self, defaults: RbfParams) -> Result<RbfParams, String> {
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
        Ok(RbfParams {
            kernel,
            affine: !self.no_affine,
            lambda: self.lambda,
            virtual_landmarks: !self.no_virtual,
            ..defaults
        })
    }
}

/// Fine alignment's flags (paper §3.2; [`FineAlignParams`], [`FineStageParams`]).
#[derive(clap::Args, Debug, Clone)]
pub struct FineArgs {
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
}

impl FineArgs {
    /// The preset's fine-alignment parameters `defaults` with what the flags set.
    pub fn params(&self, defaults: &FineAlignParams) -> FineAlignParams {
        FineAlignParams {
            a: self.a.unwrap_or(defaults.a),
            b: self.b.unwrap_or(defaults.b),
            max_iterations: self.max_iterations.unwrap_or(defaults.max_iterations),
            landmark_weight: self.landmark_weight.unwrap_or(defaults.landmark_weight),
            scan_term_weight: self.scan_term_weight.unwrap_or(defaults.scan_term_weight),
            ..defaults.clone()
        }
    }
}

/// The quality check's flags ([`QualityThresholds`]; docs/batch.md).
#[derive(clap::Args, Debug, Clone)]
pub struct QualityArgs {
    /// Flag fits whose scan → template RMS exceeds this (mm).
    #[arg(long, default_value_t = QualityThresholds::default().max_rms_mm)]
    pub max_rms_mm: f64,
    /// Flag fits where more than this fraction of weighted template vertices had no data match.
    #[arg(long, default_value_t = QualityThresholds::default().max_unmatched_fraction)]
    pub max_unmatched: f64,
    /// Flag fits where more than this fraction of template triangles folded over.
    #[arg(long, default_value_t = QualityThresholds::default().max_folded_fraction)]
    pub max_folded: f64,
}

impl QualityArgs {
    /// The thresholds the flags set, checked (each a finite number ≥ 0).
    pub fn thresholds(&self) -> Result<QualityThresholds, String> {
        for (flag, value) in [
            ("--max-rms-mm", self.max_rms_mm),
            ("--max-unmatched", self.max_unmatched),
            ("--max-folded", self.max_folded),
        ] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(format!("{flag} {value}: must be a finite number ≥ 0"));
            }
        }
        Ok(QualityThresholds {
            max_rms_mm: self.max_rms_mm,
            max_unmatched_fraction: self.max_unmatched,
            max_folded_fraction: self.max_folded,
            ..QualityThresholds::default()
        })
    }
}

/// Which way is up on a scan, when a person knows it.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct OrientationArgs {
    /// The scan axis pointing from the feet to the head: +x, -x, +y, -y, +z or -z (CAESAR: +z).
    /// The landmark estimate then tries only this way up (default: it finds it).
    #[arg(long)]
    pub up: Option<String>,
    /// The scan axis the body faces (across `--up`); needs `--up` (default: both ways are tried).
    #[arg(long, requires = "up")]
    pub facing: Option<String>,
}

impl OrientationArgs {
    /// The orientation stated, checked; `None` when `--up` is not given.
    pub fn orientation(&self) -> Result<Option<Orientation>, String> {
        let axis = |flag: &str, name: &str| {
            Axis::from_name(name)
                .ok_or_else(|| format!("--{flag} {name}: one of +x, -x, +y, -y, +z, -z"))
        };
        let Some(up) = &self.up else {
            return Ok(None);
        };
        let orientation = Orientation {
            up: axis("up", up)?,
            facing: self
                .facing
                .as_deref()
                .map(|f| axis("facing", f))
                .transpose()?,
        };
        orientation.validate()?;
        Ok(Some(orientation))
    }
}

impl SubjectArgs {
    /// The template resolution asked for.
    pub fn resolution(&self) -> Result<Resolution, String> {
        Resolution::from_str(&self.resolution)
            .map_err(|e| format!("--resolution {}: {e}", self.resolution))
    }

    /// The core's options with what the command line sets.
    pub fn options(&self) -> Result<SubjectOptions, String> {
        let preset = Preset::from_name(&self.preset)
            .ok_or_else(|| format!("--preset {}: paper or anchored", self.preset))?;
        let defaults = preset.params();
        let rbf = self.rbf.params(defaults.rbf)?;
        let thresholds = self.quality.thresholds()?;
        let params = AlignParams {
            preset,
            pose_parts: defaults.pose_parts,
            rbf,
            fine: self.fine.params(&defaults.fine),
            fine_stage: FineStageParams {
                max_iterations: self.fine.fine_iterations,
                ..defaults.fine_stage
            },
            rough_only: self.rough_only,
        };
        params.validate().map_err(|e| e.to_string())?;
        Ok(SubjectOptions {
            params,
            check_landmarks: !self.no_landmark_check,
            thresholds,
            nearly_full: self.nearly_full,
            orientation: self.orientation.orientation()?,
            strays: Default::default(),
            ..SubjectOptions::default()
        })
    }
}

/// One subject's files, as `align` and `landmarks` take them.
#[derive(clap::Args, Debug, Clone)]
pub struct SubjectFiles {
    /// The scan: PLY, OBJ or STL, optionally gzip-compressed, in any frame and units.
    #[arg(long)]
    pub scan: PathBuf,
    /// The scan's landmarks: CSV (the scan's units), CAESAR .lnd (millimetres) or JSON (the
    /// scan's units). `align` checks a nearly full file and leaves its suspicious landmarks out;
    /// a partial file is filled in by the landmark estimate; without a file all 73 are estimated.
    #[arg(long)]
    pub landmarks: Option<PathBuf>,
}

impl SubjectFiles {
    /// The subject read by the core's rule (`subject/input.rs`).
    pub fn read(&self) -> Result<crate::subject::SubjectInput, String> {
        read_subject_files(&self.scan, self.landmarks.as_deref())
    }
}

/// The JSON report of `align` and `landmarks`: printed, and also written to a file when asked.
#[derive(clap::Args, Debug, Clone)]
pub struct ReportArgs {
    /// Also write the JSON report to this file.
    #[arg(long)]
    pub report: Option<PathBuf>,
}

impl ReportArgs {
    /// Prints `report` as indented JSON on stdout, after writing the same text to `--report`.
    pub fn print(&self, report: &impl serde::Serialize) -> Result<(), String> {
        let text = serde_json::to_string_pretty(report).map_err(|e| e.to_string())?;
        if let Some(path) = &self.report {
            std::fs::write(path, &text)
                .map_err(|e| format!("{}: cannot write the report: {e}", path.display()))?;
        }
        println!("{text}");
        Ok(())
    }
}

/// A subject read from its files by the core's rule (`subject/input.rs`): the scan and, when
/// there is one, its landmark file.
pub fn read_subject_files(
    scan: &Path,
    landmarks: Option<&Path>,
) -> Result<crate::subject::SubjectInput, String> {
    let scan_name = scan.display().to_string();
    let scan_bytes = super::read_file(scan)?;
    let landmark_file = match landmarks {
        Some(path) => Some((super::read_file(path)?, path.display().to_string())),
        None => None,
    };
    crate::subject::read_subject(
        (&scan_bytes, &scan_name),
        landmark_file
            .as_ref()
            .map(|(bytes, name)| (bytes.as_slice(), name.as_str())),
        None,
    )
    .map_err(|e| e.to_string())
}

/// Adds the correspondence error against the ground truth in `truth` (`bodyspace synth`'s
/// `truth_ID.ply`: template vertex order, the scan's frame and units) to the fit's report.
pub fn compare_with_truth_file(
    fit: &mut crate::subject::SubjectFit,
    template: &crate::template::Template,
    truth: &Path,
) -> Result<(), String> {
    let expected = [
        template.base_vertex_count(),
        template.mesh().positions.len(),
    ];
    let truth = super::truth::read_truth(truth, &expected, fit.alignment.scale_to_metres)?;
    fit.compare_with_truth(template, &truth);
    Ok(())
}

/// The fit as a PLY file in `frame`, template vertex order.
pub fn fit_ply(
    fit: &crate::subject::SubjectFit,
    template: &crate::template::Template,
    frame: Frame,
) -> Vec<u8> {
    let positions = match frame {
        Frame::Scan => fit.positions_in_scan_units(),
        Frame::Template => fit.positions_in_template_frame(),
    };
    crate::io::write_ply(&crate::mesh::Mesh::new(
        positions,
        template.mesh().triangles.clone(),
    ))
}
