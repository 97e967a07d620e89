//! Accuracy benchmark of the whole alignment (RBF warp, paper §3.1, then fine alignment, §3.2) on
//! synthetic subjects with ground truth (`bodyspace synth`).
//!
//! `cargo run --release --example align_accuracy -- DIR [--n N] [--kernel K] [--kernel-param P]
//!  [--lambda L] [--a A] [--b B] [--max-iterations N] [--iterations-per-round N] [--anneal INIT:DECAY]
//!  [--relative-tolerance T] [--displacement-tolerance M] [--landmark-weight W] [--scan-term W]
//!  [--scan-term-samples N] [--scan-term-from STIFFNESS] [--scan-term-max-distance M]
//!  [--skip-boundary-matches 0|1] [--max-match-distance M] [--tangential-weight W] [--sole-weight W] [--follow 0|1]
//!  [--virtual-landmarks 0|1] [--pose-parts 0|1]
//!  [--preset paper|anchored (first: later options change it)] [--quiet]
//!  [--export DIR] [--first K] [--resolution fine [--fine-max-iterations N]
//!  [--fine-iterations-per-round N] [--fine-anneal INIT:DECAY] [--fine-displacement-tolerance M]
//!  [--fine-memory M] [--fine-tangential-weight W]]`
//!
//! DIR holds `scan_XXX.ply`, `landmarks_XXX.lnd` and `truth_XXX.ply` (the `base` template's
//! vertices on the subject, scan frame and units). Prints per subject and the mean: scan→template
//! RMS, mean correspondence error (fitted vertex vs truth) after the RBF warp and after fine
//! alignment, the same per segment (each vertex counted in its dominant segment), iterations and
//! times; then per body part (head, torso, arms, hands, legs, feet; `template::body_part`) the
//! mean over subjects of each subject's mean, 95th percentile and largest error, and the largest
//! of all. The first line names the population (`subjects.json`'s profile and seed, if present). Unset options keep the library defaults. `--export DIR` also writes each subject's
//! RBF-warped template (`warped_XXX.ply`, metres) and landmark anchors (`anchors_XXX.json`) so
//! the peer (`bench/peer/nricp.py`) starts from the same place, and the fit's base vertices
//! (`fitted_XXX.ply`, metres) for `correspondence_split`. `--resolution fine` aligns the
//! `fine` template coarse to fine (`coarse_to_fine_align`; the options set its base stage, the
//! `--fine-*` ones its fine stage) and measures the correspondence error on the base vertices,
//! which come first; the RMS column is then the fine fit's, and the times are base stage +
//! subdivision (`idx_ms` stays the scan index) and fine stage. `--first K` starts at subject K.

#[cfg(not(target_arch = "wasm32"))]
#[path = "support/subject_files.rs"]
mod subject_files;

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use super::subject_files::{read_subject, SubjectFiles};
    use bodyspace::align::{
        align_scan, landmark_anchors, scan_to_template_distances, AlignInput, AlignParams,
        DistanceStats, Preset, SurfaceIndex,
    };
    use bodyspace::io::write_ply;
    use bodyspace::mesh::Mesh;
    use bodyspace::rbf::Kernel;
    use bodyspace::template::{BodyPart, Resolution, Segment, Template};
    use nalgebra::Point3;
    use std::path::{Path, PathBuf};

    struct Options {
        dir: PathBuf,
        n: usize,
        params: AlignParams,
        resolution: Resolution,
        first: usize,
        quiet: bool,
        export: Option<PathBuf>,
    }

    fn parse() -> Result<Options, String> {
        let mut args = std::env::args().skip(1);
        let dir = PathBuf::from(args.next().ok_or("usage: align_accuracy DIR [options]")?);
        let mut options = Options {
            dir,
            n: 10,
            params: AlignParams::default(),
            resolution: Resolution::Base,
            first: 1,
            quiet: false,
            export: None,
        };
        let mut kernel_name: Option<String> = None;
        let mut kernel_param: Option<f64> = None;
        while let Some(flag) = args.next() {
            if flag == "--quiet" {
                options.quiet = true;
                continue;
            }
            let value = args.next().ok_or(format!("{flag}: missing value"))?;
            let num = || -> Result<f64, String> {
                value
                    .parse::<f64>()
                    .map_err(|e| format!("{flag} {value}: {e}"))
            };
            match flag.as_str() {
                "--export" => options.export = Some(PathBuf::from(&value)),
                "--first" => options.first = num()? as usize,
                "--resolution" => match value.as_str() {
                    "base" => options.resolution = Resolution::Base,
                    "fine" => options.resolution = Resolution::Fine,
                    _ => return Err(format!("--resolution {value}: base or fine")),
                },
                "--fine-max-iterations" => {
                    fine_stage(&mut options, &flag)?.max_iterations = num()? as usize
                }
                "--fine-iterations-per-round" => {
                    fine_stage(&mut options, &flag)?.iterations_per_round = num()? as usize
                }
                "--fine-displacement-tolerance" => {
                    fine_stage(&mut options, &flag)?.displacement_tolerance = num()?
                }
                "--fine-tangential-weight" => {
                    fine_stage(&mut options, &flag)?.tangential_weight = num()?
                }
                "--fine-memory" => fine_stage(&mut options, &flag)?.lbfgs_memory = num()? as usize,
                "--fine-anneal" => {
                    let (init, decay) = value.split_once(':').ok_or("--fine-anneal INIT:DECAY")?;
                    let fine = fine_stage(&mut options, &flag)?;
                    fine.initial_stiffness = init.parse().map_err(|_| "--fine-anneal INIT")?;
                    fine.stiffness_decay = decay.parse().map_err(|_| "--fine-anneal DECAY")?;
                }
                "--n" => options.n = num()? as usize,
                "--kernel" => kernel_name = Some(value.clone()),
                "--kernel-param" => kernel_param = Some(num()?),
                "--lambda" => options.params.rbf.lambda = num()?,
                "--a" => options.params.fine.a = num()?,
                "--b" => options.params.fine.b = num()?,
                "--max-iterations" => options.params.fine.max_iterations = num()? as usize,
                "--iterations-per-round" => {
                    options.params.fine.iterations_per_round = num()? as usize
                }
                "--relative-tolerance" => options.params.fine.relative_tolerance = num()?,
                "--displacement-tolerance" => options.params.fine.displacement_tolerance = num()?,
                "--landmark-weight" => options.params.fine.landmark_weight = num()?,
                "--scan-term" => options.params.fine.scan_term_weight = num()?,
                "--scan-term-samples" => options.params.fine.scan_term_samples = num()? as usize,
                "--scan-term-from" => options.params.fine.scan_term_from_stiffness = num()?,
                "--scan-term-max-distance" => options.params.fine.scan_term_max_distance = num()?,
                "--skip-boundary-matches" => {
                    options.params.fine.skip_boundary_matches = num()? != 0.0
                }
                "--max-match-distance" => options.params.fine.max_match_distance = num()?,
                "--tangential-weight" => options.params.fine.tangential_weight = num()?,
                "--sole-weight" => options.params.fine.sole_weight = num()?,
                "--pose-parts" => options.params.pose_parts = num()? != 0.0,
                "--virtual-landmarks" => options.params.rbf.virtual_landmarks = num()? != 0.0,
                "--follow" => options.params.fine.unseen_follow_neighbours = num()? != 0.0,
                "--preset" => {
                    options.params = Preset::from_name(&value)
                        .ok_or(format!("--preset {value}: paper or anchored"))?
                        .params()
                }
                "--anneal" => {
                    let (init, decay) = value.split_once(':').ok_or("--anneal INIT:DECAY")?;
                    options.params.fine.initial_stiffness =
                        init.parse().map_err(|_| "--anneal INIT")?;
                    options.params.fine.stiffness_decay =
                        decay.parse().map_err(|_| "--anneal DECAY")?;
                }
                _ => return Err(format!("unknown option {flag}")),
            }
        }
        if kernel_name.is_some() || kernel_param.is_some() {
            let name = kernel_name.unwrap_or_else(|| options.params.rbf.kernel.name().to_string());
            options.params.rbf.kernel =
                Kernel::from_name(&name, kernel_param).ok_or(format!("unknown kernel {name}"))?;
        }
        Ok(options)
    }

    /// The fine stage's schedule, which means something only after `--resolution fine`.
    fn fine_stage<'a>(
        options: &'a mut Options,
        flag: &str,
    ) -> Result<&'a mut bodyspace::align::FineStageParams, String> {
        match options.resolution {
            Resolution::Base => Err(format!("{flag}: needs --resolution fine first")),
            _ => Ok(&mut options.params.fine_stage),
        }
    }

    /// One subject's figures; lengths in mm, times in ms.
    #[derive(Default, Clone)]
    struct Row {
        scan_vertices: usize,
        rms: f64,
        signed: f64,
        truth_rms: f64,
        rough_error: f64,
        fine_error: f64,
        /// 95th percentile and largest correspondence error after fine alignment.
        p95: f64,
        max: f64,
        segments: [f64; 6],
        /// Per body part ([`BodyPart::ALL`] order): mean, 95th percentile, largest error.
        parts: [[f64; 3]; 6],
        iterations: usize,
        rough_ms: f64,
        index_ms: f64,
        fine_ms: f64,
        /// Coarse to fine: the fine stage alone (included in `fine_ms`).
        fine_stage_ms: f64,
    }

    /// Subject `id`, aligned at the resolution of `template`; `base` is the base template.
    fn run_subject(
        options: &Options,
        template: &Template,
        base: &Template,
        id: usize,
    ) -> Result<Row, String> {
        let SubjectFiles {
            scan,
            truth,
            landmarks,
        } = read_subject(&options.dir, id)?;
        let input = AlignInput {
            template,
            base_template: Some(base),
            scan: &scan,
            landmarks: &landmarks,
            units: None,
        };
        let mut alignment =
            align_scan(&input, &options.params, &mut ()).map_err(|e| e.to_string())?;
        let to_m = alignment.scale_to_metres;
        let truth: Vec<Point3<f64>> = truth.positions.iter().map(|p| p * to_m).collect();
        alignment.compare_with_truth(base, &truth);
        if let Some(dir) = &options.export {
            let anchors =
                landmark_anchors(base, &alignment.warped, &alignment.report.warp.pairing.used);
            let fitted = &alignment.positions[..base.mesh().positions.len()];
            export_start(dir, id, &alignment.warped, fitted, base, &anchors)?;
        }
        // The ground truth's own distance to the scan: the noise floor of the RMS column.
        let scan_m = Mesh::new(
            scan.positions.iter().map(|p| p * to_m).collect(),
            scan.triangles.clone(),
        );
        let index = SurfaceIndex::new(&scan_m).map_err(|e| e.to_string())?;
        let truth_stats = DistanceStats::of(
            scan_to_template_distances(&truth, &base.mesh().triangles, &index)
                .map_err(|e| e.to_string())?
                .iter()
                .map(|s| s.distance),
        );
        let report = &alignment.report;
        let fine = report.fine.as_ref().ok_or("no fine alignment")?;
        let correspondence = report.correspondence.as_ref().ok_or("no correspondence")?;
        let mut segments = [0.0; 6];
        for (s, e) in segments.iter_mut().zip(&correspondence.segments) {
            *s = e.error.mean_mm;
        }
        let mut parts = [[0.0; 3]; 6];
        for (p, e) in parts.iter_mut().zip(&correspondence.parts) {
            *p = [e.error.mean_mm, e.error.p95_mm, e.error.max_mm];
        }
        let fine_stage_ms = fine
            .stages
            .as_ref()
            .map_or(0.0, |s| fine.elapsed_ms - s.base.elapsed_ms);
        Ok(Row {
            scan_vertices: scan.positions.len(),
            rms: fine.scan_to_template.rms_mm,
            signed: fine.scan_to_template.mean_mm,
            truth_rms: truth_stats.rms * 1e3,
            rough_error: correspondence.rough.mean_mm,
            fine_error: correspondence.fitted.mean_mm,
            p95: correspondence.fitted.p95_mm,
            max: correspondence.fitted.max_mm,
            segments,
            parts,
            iterations: fine.iterations,
            rough_ms: report.rough_ms,
            index_ms: report.index_ms,
            fine_ms: fine.elapsed_ms,
            fine_stage_ms,
        })
    }

    /// For the peer (bench/peer/nricp.py): the RBF-warped template (PLY, metres) and the landmark
    /// anchors (template vertex, target in metres) of subject `id`; for the common / own split
    /// (`correspondence_split`), our fit's base vertices (`fitted_XXX.ply`, metres).
    fn export_start(
        dir: &Path,
        id: usize,
        warped: &[Point3<f64>],
        fitted: &[Point3<f64>],
        template: &Template,
        anchors: &[(u32, Point3<f64>)],
    ) -> Result<(), String> {
        for (stem, positions) in [("warped", warped), ("fitted", fitted)] {
            let mesh = Mesh::new(positions.to_vec(), template.mesh().triangles.clone());
            let ply = dir.join(format!("{stem}_{id:03}.ply"));
            std::fs::write(&ply, write_ply(&mesh))
                .map_err(|e| format!("{}: {e}", ply.display()))?;
        }
        let json = serde_json::json!({
            "vertices": anchors.iter().map(|(v, _)| *v).collect::<Vec<_>>(),
            "targets": anchors.iter().map(|(_, p)| [p.x, p.y, p.z]).collect::<Vec<_>>(),
        });
        let path = dir.join(format!("anchors_{id:03}.json"));
        std::fs::write(&path, json.to_string()).map_err(|e| format!("{}: {e}", path.display()))
    }

    fn print_row(label: &str, r: &Row) {
        println!(
            "{label:>7} {:>7} {:>7.3} {:>6.3} {:>6.3} {:>7.2} {:>7.2} {:>6.2} {:>6.2} | {} | {:>5} {:>6.0} {:>6.0} {:>7.0} {:>8.0}",
            r.scan_vertices,
            r.rms,
            r.signed,
            r.truth_rms,
            r.rough_error,
            r.fine_error,
            r.p95,
            r.max,
            r.segments
                .iter()
                .map(|e| format!("{e:>6.2}"))
                .collect::<Vec<_>>()
                .join(" "),
            r.iterations,
            r.rough_ms,
            r.index_ms,
            r.fine_ms,
            r.fine_stage_ms,
        );
    }

    pub fn main() {
        let options = match parse() {
            Ok(o) => o,
            Err(e) => {
                eprintln!("{e}");
                std::process::exit(2);
            }
        };
        let template = match Template::embedded() {
            Ok(t) => t.at_resolution(Resolution::Base),
            Err(e) => {
                eprintln!("embedded template: {e}");
                std::process::exit(2);
            }
        };
        let names: Vec<&str> = Segment::ALL.iter().map(|s| s.name()).collect();
        println!("population: {}", population(&options.dir));
        println!(
        "preset {}; pose_parts={}; rbf {:?} virtual_landmarks={}; fine a={} b={} max_it={} it/round={} anneal={}:{} rel_tol={} disp_tol={} landmark_weight={} scan_term={}x{}@{}<{} skip_rims={} tangential={} soles={} follow={}",
        options.params.preset.name(),
        options.params.pose_parts,
        options.params.rbf.kernel,
        options.params.rbf.virtual_landmarks,
        options.params.fine.a,
        options.params.fine.b,
        options.params.fine.max_iterations,
        options.params.fine.iterations_per_round,
        options.params.fine.initial_stiffness,
        options.params.fine.stiffness_decay,
        options.params.fine.relative_tolerance,
        options.params.fine.displacement_tolerance,
        options.params.fine.landmark_weight,
        options.params.fine.scan_term_weight,
        options.params.fine.scan_term_samples,
        options.params.fine.scan_term_from_stiffness,
        options.params.fine.scan_term_max_distance,
        options.params.fine.skip_boundary_matches,
        options.params.fine.tangential_weight,
        options.params.fine.sole_weight,
        options.params.fine.unseen_follow_neighbours,
    );
        println!(
        "subject   scanV  RMS_mm signed truthRMS rbf_mm fine_mm  p95_mm max_mm | mean correspondence error after fine per segment (mm): {} | iters rbf_ms idx_ms fine_ms stage_ms",
        names.join(" ")
    );
        let mut rows = Vec::new();
        let aligned = template.at_resolution(options.resolution);
        if options.resolution != Resolution::Base {
            let stage = &options.params.fine_stage;
            println!(
                "coarse to fine, fine stage: max_it={} it/round={} anneal={}:{} disp_tol={} memory={}",
                stage.max_iterations,
                stage.iterations_per_round,
                stage.initial_stiffness,
                stage.stiffness_decay,
                stage.displacement_tolerance,
                stage.lbfgs_memory,
            );
        }
        for id in options.first..options.first + options.n {
            match run_subject(&options, &aligned, &template, id) {
                Ok(row) => {
                    if !options.quiet {
                        print_row(&format!("{id:03}"), &row);
                    }
                    rows.push(row);
                }
                Err(e) => {
                    eprintln!("subject {id:03}: {e}");
                    std::process::exit(1);
                }
            }
        }
        let k = rows.len().max(1) as f64;
        let mut mean = Row::default();
        for r in &rows {
            mean.scan_vertices += r.scan_vertices / rows.len().max(1);
            mean.rms += r.rms / k;
            mean.signed += r.signed / k;
            mean.truth_rms += r.truth_rms / k;
            mean.rough_error += r.rough_error / k;
            mean.fine_error += r.fine_error / k;
            mean.p95 += r.p95 / k;
            mean.max += r.max / k;
            for s in 0..6 {
                mean.segments[s] += r.segments[s] / k;
            }
            mean.iterations += r.iterations;
            mean.rough_ms += r.rough_ms / k;
            mean.index_ms += r.index_ms / k;
            mean.fine_ms += r.fine_ms / k;
            mean.fine_stage_ms += r.fine_stage_ms / k;
        }
        mean.iterations /= rows.len().max(1);
        print_row("mean", &mean);
        print_parts(&rows);
    }

    /// Per body part: mean over subjects of the mean, 95th percentile and largest error, and the
    /// largest error of any subject.
    fn print_parts(rows: &[Row]) {
        let k = rows.len().max(1) as f64;
        println!("part    mean_mm  p95_mm  max_mm  worst_mm");
        for part in BodyPart::ALL {
            let i = part.index();
            let avg = |j: usize| rows.iter().map(|r| r.parts[i][j]).sum::<f64>() / k;
            let worst = rows.iter().map(|r| r.parts[i][2]).fold(0.0, f64::max);
            println!(
                "{:<6} {:>8.2} {:>7.2} {:>7.2} {:>9.2}",
                part.name(),
                avg(0),
                avg(1),
                avg(2),
                worst
            );
        }
        let worst = rows.iter().map(|r| r.max).fold(0.0, f64::max);
        println!("all vertices: worst {worst:.2} mm");
    }

    /// The population `subjects.json` in `dir` describes (profile and seed), if any.
    fn population(dir: &Path) -> String {
        let text = std::fs::read_to_string(dir.join("subjects.json")).unwrap_or_default();
        match serde_json::from_str::<serde_json::Value>(&text) {
            Ok(v) => format!(
                "profile {}, seed {}",
                v["profile"].as_str().unwrap_or("tuning (before profiles)"),
                v["seed"]
            ),
            Err(_) => "unknown (no subjects.json)".into(),
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    native::main()
}

/// The benchmark reads files and uses the native CLI helpers; nothing to run on wasm32.
#[cfg(target_arch = "wasm32")]
fn main() {}
