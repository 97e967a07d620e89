//! Whether the fit's self-check catches every landmark-free fit that went wrong (issue 31's goal:
//! the landmark-free fit within 0.2 mm RMS of the fit from the true landmarks, or flagged).
//! Synthetic subjects with ground truth (`bodyspace synth`, the scanner zoo's too), each fitted by
//! the one path (`subject::fit_subject`, the defaults, `base`) from its true landmarks and
//! without landmarks, never tuned on.
//!
//! `cargo run --release --example fit_self_check -- DIR [--n N] [--fits CACHE]`
//!
//! DIR holds `scan_XXX.ply`, `landmarks_XXX.lnd` and `truth_XXX.ply`. `--fits CACHE` keeps what
//! each fit is judged from (`CACHE/{landmarks,free}_XXX.check.json`: RMS, correspondence, the
//! flags and each base vertex's distance to the scan) and reuses it, so that a change of the
//! check alone is measured in seconds. Prints per subject: the RMS and correspondence of both
//! fits, the landmark-free fit's excess RMS, its flags (as cached), the template vertices beyond
//! 20 mm from the scan, the limb part farthest from it against the other side's (RMS, soles left
//! out: what `uneven_limb` judges), and the share of the scan beyond 10 and 20 mm from the fit
//! with the part nearest most of it (what `uncovered_scan` judges, `align/quality.rs`); then how
//! many fits are good (within 0.2 mm), flagged, and silently worse, and how uneven the limbs of the
//! fits without `uneven_limb` are.

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use bodyspace::align::UnevenFit;
    use bodyspace::cli::subject_args::compare_with_truth_file;
    use bodyspace::subject::{fit_subject, read_subject, SubjectOptions};
    use bodyspace::template::Template;
    use std::path::{Path, PathBuf};

    /// What a fit is judged from.
    #[derive(serde::Serialize, serde::Deserialize)]
    struct Judged {
        rms_mm: f64,
        correspondence_mm: f64,
        flags: Vec<String>,
        reasons: Vec<String>,
        distances_mm: Vec<f32>,
        /// Scan vertices beyond 5 mm from the fit: (distance mm, nearest template vertex).
        scan_far: Vec<(f32, u32)>,
        scan_vertices: usize,
    }

    fn bytes(path: &Path) -> Result<Vec<u8>, String> {
        std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))
    }

    fn fit(
        dir: &Path,
        cache: Option<&Path>,
        template: &Template,
        id: usize,
        with_landmarks: bool,
    ) -> Result<Judged, String> {
        let kind = if with_landmarks { "landmarks" } else { "free" };
        let cached = cache.map(|c| c.join(format!("{kind}_{id:03}.check.json")));
        if let Some(path) = cached.as_ref().filter(|p| p.exists()) {
            return serde_json::from_slice(&bytes(path)?).map_err(|e| e.to_string());
        }
        let scan_path = dir.join(format!("scan_{id:03}.ply"));
        let lnd_path = dir.join(format!("landmarks_{id:03}.lnd"));
        let scan = bytes(&scan_path)?;
        let lnd = bytes(&lnd_path)?;
        let landmarks = with_landmarks.then(|| (&lnd[..], "landmarks.lnd"));
        let input = read_subject((&scan, &scan_path.display().to_string()), landmarks, None)
            .map_err(|e| e.to_string())?;
        let mut fitted = fit_subject(
            template,
            None,
            &input,
            None,
            &SubjectOptions::default(),
            &mut (),
        )
        .map_err(|e| e.to_string())?;
        compare_with_truth_file(
            &mut fitted,
            template,
            &dir.join(format!("truth_{id:03}.ply")),
        )?;
        let report = &fitted.report;
        let quality = report.quality.as_ref();
        let judged = Judged {
            rms_mm: quality.and_then(|q| q.rms_mm).unwrap_or(f64::NAN),
            correspondence_mm: report
                .alignment
                .correspondence
                .as_ref()
                .map_or(f64::NAN, |c| c.fitted.mean_mm),
            flags: quality.map_or(Vec::new(), |q| {
                q.flags.iter().map(|f| f.name().to_string()).collect()
            }),
            reasons: quality.map_or(Vec::new(), |q| q.landmark_estimate.clone()),
            distances_mm: fitted
                .alignment
                .per_vertex_distance
                .iter()
                .map(|&d| (d * 1e3) as f32)
                .collect(),
            scan_far: fitted
                .alignment
                .scan_distances
                .iter()
                .filter(|s| s.distance.abs() > 0.005)
                .map(|s| ((s.distance * 1e3) as f32, s.nearest_vertex))
                .collect(),
            scan_vertices: fitted.alignment.scan_distances.len(),
        };
        if let Some(path) = cached {
            std::fs::write(
                &path,
                serde_json::to_vec(&judged).map_err(|e| e.to_string())?,
            )
            .map_err(|e| format!("{}: {e}", path.display()))?;
        }
        Ok(judged)
    }

    pub fn main() -> Result<(), String> {
        let mut args = std::env::args().skip(1);
        let dir = PathBuf::from(
            args.next()
                .ok_or("usage: fit_self_check DIR [--n N] [--fits CACHE]")?,
        );
        let (mut n, mut cache) = (8usize, None::<PathBuf>);
        while let Some(flag) = args.next() {
            let value = args.next().ok_or(format!("{flag} needs a value"))?;
            match flag.as_str() {
                "--n" => n = value.parse().map_err(|e| format!("--n: {e}"))?,
                "--fits" => cache = Some(PathBuf::from(value)),
                _ => return Err(format!("unknown option {flag}")),
            }
        }
        if let Some(c) = &cache {
            std::fs::create_dir_all(c).map_err(|e| e.to_string())?;
        }
        let template = Template::embedded().map_err(|e| e.to_string())?;
        let parts = bodyspace::template::parts::parts(&template);
        let part_of: Vec<usize> = (0..template.mesh().vertex_count() as u32)
            .map(|v| bodyspace::template::parts::dominant_part(&parts, v))
            .collect();
        let part_names: Vec<&str> = parts.iter().map(|p| p.name).collect();
        let weights = bodyspace::align::data_weights(
            &template,
            bodyspace::align::FineAlignParams::default().sole_weight,
        );
        let without_soles = bodyspace::align::data_weights(&template, 0.0);

        // Each limb part's RMS to the scan against its other side's, soles left out (no scanner
        // sees them): what `uneven_limb` judges.
        let limb_pairs = |judged: &Judged| {
            let distances_m: Vec<f64> = judged
                .distances_mm
                .iter()
                .map(|&d| d as f64 / 1e3)
                .collect();
            bodyspace::align::uneven_fits(
                &distances_m,
                &without_soles,
                &part_of,
                &part_names,
                (1.0, f64::NEG_INFINITY),
            )
        };
        let worse_better = |u: &UnevenFit| {
            (
                u.left_rms_mm.max(u.right_rms_mm),
                u.left_rms_mm.min(u.right_rms_mm),
            )
        };
        let ratio = |u: &UnevenFit| {
            let (worse, better) = worse_better(u);
            worse / better
        };
        let farthest_limb = |judged: &Judged| {
            limb_pairs(judged)
                .iter()
                .max_by(|a, b| ratio(a).total_cmp(&ratio(b)))
                .map_or("none".to_string(), |u| {
                    let side = if u.left_rms_mm > u.right_rms_mm {
                        "left"
                    } else {
                        "right"
                    };
                    let (worse, better) = worse_better(u);
                    format!(
                        "{side} {} {worse:.1} / {better:.1} ({:.1}×)",
                        u.part,
                        ratio(u)
                    )
                })
        };
        // Over the fits that do not raise `uneven_limb`: the largest ratio and difference.
        let mut unflagged_limbs = (0.0f64, 0.0f64);
        println!("| subject | RMS with / without (mm) | excess | correspondence with / without (mm) | flags without | far > 20 mm | limb part farthest from the scan against its other side, soles left out, with / without landmarks: RMS / other (mm) | scan > 10 / 20 mm (‰) | most of it near |");
        println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
        let (mut good, mut flagged, mut silent) = (0, 0, Vec::new());
        for id in 1..=n {
            if !dir.join(format!("scan_{id:03}.ply")).exists() {
                continue;
            }
            let with = fit(&dir, cache.as_deref(), &template, id, true)?;
            let without = fit(&dir, cache.as_deref(), &template, id, false)?;
            let excess = without.rms_mm - with.rms_mm;
            for judged in [&with, &without] {
                if !judged.flags.iter().any(|f| f == "uneven_limb") {
                    for u in limb_pairs(judged) {
                        let (worse, better) = worse_better(&u);
                        unflagged_limbs.0 = unflagged_limbs.0.max(ratio(&u));
                        unflagged_limbs.1 = unflagged_limbs.1.max(worse - better);
                    }
                }
            }
            let far = without
                .distances_mm
                .iter()
                .zip(&weights)
                .filter(|&(&d, &w)| w > 0.0 && d.abs() > 20.0)
                .count();
            let worst_limb = farthest_limb(&without);
            let beyond = |mm: f32| without.scan_far.iter().filter(|s| s.0.abs() > mm).count();
            let per_mille = |k: usize| 1000.0 * k as f64 / without.scan_vertices.max(1) as f64;
            let mut near = vec![0usize; parts.len()];
            for s in without.scan_far.iter().filter(|s| s.0.abs() > 10.0) {
                near[part_of[s.1 as usize]] += 1;
            }
            let most = (0..parts.len()).max_by_key(|&p| near[p]).unwrap();
            println!(
                "| {id:03} | {:.3} / {:.3} | {excess:+.3} | {:.2} / {:.2} | {} | {far} | {} / {worst_limb} | {:.1} / {:.1} | {} {} |",
                with.rms_mm,
                without.rms_mm,
                with.correspondence_mm,
                without.correspondence_mm,
                if without.flags.is_empty() { "none".to_string() } else { without.flags.join(", ") },
                farthest_limb(&with),
                per_mille(beyond(10.0)),
                per_mille(beyond(20.0)),
                parts[most].name,
                near[most],
            );
            if !without.reasons.is_empty() {
                eprintln!("{id:03}: {}", without.reasons.join("; "));
            }
            if excess <= 0.2 {
                good += 1;
            } else if !without.flags.is_empty() {
                flagged += 1;
            } else {
                silent.push(id);
            }
        }
        println!(
            "\nwithin 0.2 mm: {good}; worse but flagged: {flagged}; silently worse: {} {silent:?}",
            silent.len()
        );
        println!(
            "fits without uneven_limb: limb parts at most {:.2} times and {:.1} mm farther from the scan than the other side",
            unflagged_limbs.0, unflagged_limbs.1
        );
        Ok(())
    }
}

fn main() {
    #[cfg(not(target_arch = "wasm32"))]
    if let Err(e) = native::main() {
        eprintln!("{e}");
        std::process::exit(1);
    }
}
