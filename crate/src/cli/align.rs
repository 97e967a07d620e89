//! `bodyspace align --scan SCAN [--landmarks FILE] --out fit.ply [...]`: one subject through the
//! core's one path from files to a fit ([`fit_subject`]: the units rule, the landmark policy, RBF
//! warp, fine alignment, quality check, frame), with the options `batch` shares
//! ([`SubjectArgs`]). Writes the fit (or, with `--rough-only`, the RBF-warped template) as PLY in
//! template vertex order, in the scan's frame and units or with `--frame template` in the
//! template's, and prints the [`crate::subject::SubjectReport`] as JSON.

use std::path::PathBuf;

use super::subject_args::{
    compare_with_truth_file, fit_ply, ReportArgs, SubjectArgs, SubjectFiles,
};
use crate::subject::fit_subject;
use crate::template::{Resolution, Template};

/// Arguments of `bodyspace align`.
#[derive(clap::Args, Debug)]
pub struct AlignArgs {
    #[command(flatten)]
    pub files: SubjectFiles,
    /// Where to write the fitted template (PLY, template vertex order).
    #[arg(long)]
    pub out: PathBuf,
    #[command(flatten)]
    pub subject: SubjectArgs,
    #[command(flatten)]
    pub report: ReportArgs,
    /// Ground truth for a synthetic subject: PLY whose vertex i is template (base) vertex i on
    /// the subject, scan frame and units; adds the correspondence error to the report (at
    /// `fine`, over the base vertices, which come first).
    #[arg(long)]
    pub truth: Option<PathBuf>,
}

/// Runs `bodyspace align`; the error is the one-line message for stderr.
pub fn run(args: &AlignArgs) -> Result<(), String> {
    let options = args.subject.options()?;
    let resolution = args.subject.resolution()?;
    let input = args.files.read()?;
    let template = Template::embedded()
        .map_err(|e| format!("embedded template: {e}"))?
        .at_resolution(resolution);
    let base = (resolution != Resolution::Base).then(|| template.at_resolution(Resolution::Base));
    let mut fit = fit_subject(&template, base.as_ref(), &input, None, &options, &mut ())
        .map_err(|e| e.to_string())?;
    if let Some(path) = &args.truth {
        compare_with_truth_file(&mut fit, &template, path)?;
    }
    std::fs::write(&args.out, fit_ply(&fit, &template, args.subject.frame)).map_err(|e| {
        format!(
            "{}: cannot write the fitted template: {e}",
            args.out.display()
        )
    })?;
    // The report carries every measurement's trust; the doubtful ones are also said on stderr.
    for t in fit.report.doubtful_measurements() {
        eprintln!("doubtful measurement: {}", t.words);
    }
    args.report.print(&fit.report)
}
