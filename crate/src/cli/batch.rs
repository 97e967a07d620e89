//! `bodyspace batch --scans DIR --out OUT [--landmarks DIR] [--jobs N] [--resolution base|fine]
//! [--shard K/N] [align's options]`: every scan of a folder through the core's one path from
//! files to a fit ([`fit_subject`], as `bodyspace align` and the app take it), several subjects
//! at once, with the options `align` shares ([`SubjectArgs`]).
//!
//! Writes `OUT/fits/<subject>.ply` (as `bodyspace align` writes it), `OUT/reports/<subject>.json`
//! (the core's [`SubjectReport`] plus the batch's `batch` record) and
//! `OUT/manifest.csv`. A subject that fails is recorded and never stops the others; a rerun of
//! the same command does only what is missing or failed. docs/batch.md has the whole story.

use std::io::IsTerminal;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Instant;

use serde::Serialize;

use super::batch_subjects::{list_subjects, Shard, Subject};
use super::manifest::{manifest_csv, write_atomically, Status, SubjectRecord};
use super::subject_args::{
    compare_with_truth_file, fit_ply, read_subject_files, Frame, SubjectArgs,
};
use super::truth::find_truth_file;
use crate::subject::{fit_subject, SubjectOptions, SubjectReport};
use crate::template::{Resolution, Template};

/// Arguments of `bodyspace batch`.
#[derive(clap::Args, Debug)]
pub struct BatchArgs {
    /// Folder of scans: every PLY, OBJ and STL file (optionally .gz) in it is a subject, named by
    /// its file name without extensions.
    #[arg(long)]
    pub scans: PathBuf,
    /// Output folder (created if missing): fits/, reports/, manifest.csv.
    #[arg(long)]
    pub out: PathBuf,
    /// Folder of landmark files (default: the scans folder, which is also searched): a scan's
    /// landmarks are <subject>.lnd, .csv or .json (first found, in that order); a scan named
    /// scan_ID also takes landmarks_ID (the `bodyspace synth` layout).
    #[arg(long)]
    pub landmarks: Option<PathBuf>,
    /// Subjects aligned at once (default: the number of cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub jobs: Option<u32>,
    /// Threads inside each subject's alignment (correspondence search); default: cores / jobs,
    /// at least 1 (docs/batch.md measures why).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub threads_per_job: Option<u32>,
    /// Take only the K-th of N disjoint shares of the sorted subjects (K = 1..N): subject i
    /// (0-based) when i % N = K − 1. For job arrays (docs/batch.md).
    #[arg(long)]
    pub shard: Option<String>,
    /// Folder of ground truths of synthetic subjects (`truth_ID.ply` for `scan_ID`, as
    /// `bodyspace synth` writes, else `<subject>.ply`): adds the correspondence error to each report, as
    /// `align --truth` does. A subject without its truth fails.
    #[arg(long)]
    pub truth: Option<PathBuf>,
    #[command(flatten)]
    pub subject: SubjectArgs,
}

/// What every job shares.
struct Context<'a> {
    template: &'a Template,
    base_template: Option<&'a Template>,
    options: SubjectOptions,
    frame: Frame,
    resolution: &'static str,
    fits: PathBuf,
    reports: PathBuf,
    truth: Option<&'a Path>,
}

/// A subject's report file: the batch's record and the core's subject report.
#[derive(Serialize)]
struct ReportFile<'a> {
    batch: &'a SubjectRecord,
    #[serde(flatten)]
    subject: Option<&'a SubjectReport>,
}

/// Aligns one subject and writes its fit and report; the record says how it went. Nothing here
/// stops the batch: every error becomes a failed record.
fn process(subject: &Subject, ctx: &Context<'_>) -> SubjectRecord {
    let start = Instant::now();
    let mut record = SubjectRecord {
        subject: subject.name.clone(),
        status: Status::Failed,
        reason: String::new(),
        rms_mm: None,
        flags: Vec::new(),
        seconds: 0.0,
        resolution: ctx.resolution.to_string(),
        scan: subject.scan.display().to_string(),
        landmarks: subject
            .landmarks
            .as_ref()
            .map(|p| p.display().to_string())
            .unwrap_or_default(),
    };
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        align_and_write(subject, ctx, &mut record, start)
    }))
    .unwrap_or_else(|panic| {
        let what = panic
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        Err(format!(
            "{}: internal error ({what}); please report it with this scan",
            subject.scan.display()
        ))
    });
    record.seconds = start.elapsed().as_secs_f64();
    if let Err(reason) = outcome {
        record.status = Status::Failed;
        record.reason = reason;
        record.rms_mm = None;
        record.flags.clear();
        let report = ReportFile {
            batch: &record,
            subject: None,
        };
        if let Err(e) = write_report(ctx, &record.subject, &report) {
            record.reason = format!("{}; and {e}", record.reason);
        }
    }
    record
}

fn align_and_write(
    subject: &Subject,
    ctx: &Context<'_>,
    record: &mut SubjectRecord,
    start: Instant,
) -> Result<(), String> {
    let input = read_subject_files(&subject.scan, subject.landmarks.as_deref())?;
    let mut fit = fit_subject(
        ctx.template,
        ctx.base_template,
        &input,
        None,
        &ctx.options,
        &mut (),
    )
    .map_err(|e| e.to_string())?;
    if let Some(folder) = ctx.truth {
        let path = find_truth_file(&subject.name, folder).ok_or_else(|| {
            format!(
                "{}: no ground truth for {} (--truth wants truth_ID.ply for scan_ID, else {}.ply)",
                folder.display(),
                subject.name,
                subject.name
            )
        })?;
        compare_with_truth_file(&mut fit, ctx.template, &path)?;
    }
    let quality = fit.report.quality.as_ref();
    record.rms_mm = quality.and_then(|q| q.rms_mm);
    record.flags = quality
        .map(|q| q.flags.iter().map(|f| f.name().to_string()).collect())
        .unwrap_or_default();
    record.status = if record.flags.is_empty() {
        Status::Ok
    } else {
        Status::Flagged
    };
    record.reason = record.flags.join(";");

    // The fit first, the report last: a report that says "done" always has its fit.
    write_atomically(
        &ctx.fits.join(format!("{}.ply", subject.name)),
        &fit_ply(&fit, ctx.template, ctx.frame),
    )?;
    record.seconds = start.elapsed().as_secs_f64();
    let report = ReportFile {
        batch: record,
        subject: Some(&fit.report),
    };
    write_report(ctx, &subject.name, &report)
}

fn write_report(ctx: &Context<'_>, subject: &str, report: &ReportFile<'_>) -> Result<(), String> {
    let text =
        serde_json::to_vec_pretty(report).map_err(|e| format!("report of {subject}: {e}"))?;
    write_atomically(&ctx.reports.join(format!("{subject}.json")), &text)
}

/// The `batch` record of a report file, if it is one.
fn read_record(path: &Path) -> Option<SubjectRecord> {
    let bytes = std::fs::read(path).ok()?;
    let value: serde_json::Value = serde_json::from_slice(&bytes).ok()?;
    serde_json::from_value(value.get("batch")?.clone()).ok()
}

/// The record of a subject done by an earlier run at this resolution (fitted, fit on disk), if any.
fn done_before(
    subject: &Subject,
    fits: &Path,
    reports: &Path,
    resolution: &str,
) -> Option<SubjectRecord> {
    let record = read_record(&reports.join(format!("{}.json", subject.name)))?;
    (record.status.fitted()
        && record.resolution == resolution
        && fits.join(format!("{}.ply", subject.name)).is_file())
    .then_some(record)
}

/// Every subject record in `reports` (this run's and earlier runs'), sorted by subject.
fn records_on_disk(reports: &Path) -> Vec<SubjectRecord> {
    let mut records: Vec<SubjectRecord> = std::fs::read_dir(reports)
        .map(|entries| {
            entries
                .flatten()
                .map(|e| e.path())
                .filter(|p| {
                    p.extension().is_some_and(|e| e == "json")
                        && !p
                            .file_name()
                            .is_some_and(|n| n.to_string_lossy().starts_with('.'))
                })
                .filter_map(|p| read_record(&p))
                .collect()
        })
        .unwrap_or_default();
    records.sort_by(|a, b| a.subject.cmp(&b.subject));
    records
}

/// Progress on stderr: one rewritten line with an ETA on a terminal, plain lines otherwise.
struct ProgressLine {
    total: usize,
    done: usize,
    counts: [usize; 3],
    start: Instant,
    terminal: bool,
}

impl ProgressLine {
    fn record(&mut self, r: &SubjectRecord) {
        self.done += 1;
        self.counts[r.status as usize] += 1;
        let elapsed = self.start.elapsed().as_secs_f64();
        let eta = elapsed / self.done as f64 * (self.total - self.done) as f64;
        let [ok, flagged, failed] = self.counts;
        let rms = r
            .rms_mm
            .map(|x| format!(" rms {x:.2} mm"))
            .unwrap_or_default();
        if self.terminal {
            eprint!(
                "\r\x1b[2K[{}/{}] ok {ok} flagged {flagged} failed {failed} · ETA {} · {} {}{rms}",
                self.done,
                self.total,
                format_seconds(eta),
                r.subject,
                r.status.name(),
            );
            if self.done == self.total {
                eprintln!();
            }
        } else {
            let reason = if r.reason.is_empty() {
                String::new()
            } else {
                format!(" ({})", r.reason)
            };
            eprintln!(
                "bodyspace batch: [{}/{}] {} {}{rms} {:.1} s{reason}; ETA {}",
                self.done,
                self.total,
                r.subject,
                r.status.name(),
                r.seconds,
                format_seconds(eta),
            );
        }
    }
}

fn format_seconds(s: f64) -> String {
    let s = s.round() as u64;
    if s >= 3600 {
        format!("{}h{:02}m", s / 3600, s % 3600 / 60)
    } else if s >= 60 {
        format!("{}m{:02}s", s / 60, s % 60)
    } else {
        format!("{s}s")
    }
}

/// Runs `bodyspace batch`; the error is the one-line message for stderr.
pub fn run(args: &BatchArgs) -> Result<(), String> {
    let started = Instant::now();
    let resolution = args.subject.resolution()?;
    let shard = args.shard.as_deref().map(Shard::from_str).transpose()?;
    let options = args.subject.options()?;

    let all = list_subjects(&args.scans, args.landmarks.as_deref())?;
    if all.is_empty() {
        return Err(format!(
            "{}: no PLY, OBJ or STL scans (optionally .gz) in this folder",
            args.scans.display()
        ));
    }
    let subjects: Vec<Subject> = all
        .into_iter()
        .enumerate()
        .filter(|(i, _)| shard.is_none_or(|s| s.takes(*i)))
        .map(|(_, s)| s)
        .collect();

    let fits = args.out.join("fits");
    let reports = args.out.join("reports");
    for dir in [&fits, &reports] {
        std::fs::create_dir_all(dir).map_err(|e| {
            format!(
                "{}: cannot create the output folder ({e}); check --out",
                dir.display()
            )
        })?;
    }
    let resolution_name = resolution.name();
    let mut records: Vec<Option<SubjectRecord>> = subjects
        .iter()
        .map(|s| done_before(s, &fits, &reports, resolution_name))
        .collect();
    let pending: Vec<usize> = (0..subjects.len())
        .filter(|&i| records[i].is_none())
        .collect();
    let skipped = subjects.len() - pending.len();

    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let jobs = (args.jobs.map_or(cores, |j| j as usize))
        .min(pending.len())
        .max(1);
    let threads_per_job = args
        .threads_per_job
        .map_or((cores / jobs).max(1), |t| t as usize);

    if !pending.is_empty() {
        let template = Template::embedded()
            .map_err(|e| format!("embedded template: {e}"))?
            .at_resolution(resolution);
        let base =
            (resolution != Resolution::Base).then(|| template.at_resolution(Resolution::Base));
        let ctx = Context {
            template: &template,
            base_template: base.as_ref(),
            options,
            frame: args.subject.frame,
            resolution: resolution_name,
            fits: fits.clone(),
            reports: reports.clone(),
            truth: args.truth.as_deref(),
        };
        eprintln!(
            "bodyspace batch: {} subjects to align ({skipped} done before), {jobs} at a time, {threads_per_job} thread(s) each",
            pending.len()
        );
        let next = AtomicUsize::new(0);
        let (sender, receiver) = mpsc::channel::<(usize, SubjectRecord)>();
        let mut progress = ProgressLine {
            total: pending.len(),
            done: 0,
            counts: [0; 3],
            start: Instant::now(),
            terminal: std::io::stderr().is_terminal(),
        };
        std::thread::scope(|scope| -> Result<(), String> {
            for _ in 0..jobs {
                let sender = sender.clone();
                let (ctx, next, pending, subjects) = (&ctx, &next, &pending, &subjects);
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads_per_job)
                    .build()
                    .map_err(|e| format!("cannot start a thread pool: {e}"))?;
                scope.spawn(move || loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&index) = pending.get(i) else { break };
                    let record = pool.install(|| process(&subjects[index], ctx));
                    if sender.send((index, record)).is_err() {
                        break;
                    }
                });
            }
            drop(sender);
            for (index, record) in receiver {
                progress.record(&record);
                records[index] = Some(record);
            }
            Ok(())
        })?;
    }

    let records: Vec<SubjectRecord> = records.into_iter().flatten().collect();
    let manifest_path = args.out.join("manifest.csv");
    write_atomically(&manifest_path, &manifest_csv(&records_on_disk(&reports))?)?;

    let count = |s: Status| records.iter().filter(|r| r.status == s).count();
    let (ok, flagged, failed) = (
        count(Status::Ok),
        count(Status::Flagged),
        count(Status::Failed),
    );
    let rms: Vec<f64> = records.iter().filter_map(|r| r.rms_mm).collect();
    let mean_rms = (!rms.is_empty()).then(|| rms.iter().sum::<f64>() / rms.len() as f64);
    let seconds = started.elapsed().as_secs_f64();
    let aligned = pending.len();
    eprintln!(
        "bodyspace batch: {} subjects: {ok} ok, {flagged} flagged, {failed} failed ({skipped} skipped, done before); mean RMS {}; {seconds:.1} s",
        records.len(),
        mean_rms.map_or("–".to_string(), |r| format!("{r:.2} mm")),
    );
    println!(
        "{}",
        serde_json::json!({
            "subjects": records.len(),
            "ok": ok,
            "flagged": flagged,
            "failed": failed,
            "skipped": skipped,
            "aligned": aligned,
            "mean_rms_mm": mean_rms,
            "seconds": seconds,
            "subjects_per_second": if aligned > 0 { aligned as f64 / seconds } else { 0.0 },
            "jobs": jobs,
            "threads_per_job": threads_per_job,
            "resolution": resolution_name,
            "shard": args.shard,
            "manifest": manifest_path.display().to_string(),
        })
    );
    // An empty share (more tasks than subjects) has nothing to do, which is not a failure.
    if !records.is_empty() && ok + flagged == 0 {
        return Err(format!(
            "no subject was fitted; {} lists each reason",
            manifest_path.display()
        ));
    }
    Ok(())
}
