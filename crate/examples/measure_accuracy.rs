//! Measurement benchmark against ISO 20685-1 (docs/measurements.md#accuracy-against-iso-20685-1):
//! synthetic subjects with ground truth (`bodyspace synth`), each fitted by the one path
//! (`subject::fit_subject`, the defaults, at `base` or `fine`) from its true landmarks, from ten
//! of them (the partial file of issue 31: Sellion, Suprasternale and the pairs of Acromions,
//! Dactylions, ASIS and Lateral Malleoli; the estimate fills in the rest) and without landmarks,
//! every fit and the true body measured by the same code (`bodyspace measure`'s: moved rigidly
//! onto the template, then `BodyMeasurer`), never tuned on.
//!
//! `cargo run --release --example measure_accuracy -- DIR [--n N] [--fits CACHE]
//!  [--from landmarks|given10|free|both|all] [--resolution base|fine]`
//!
//! `both` (the default) is `landmarks` and `free`; `all` adds `given10`. DIR holds
//! `scan_XXX.ply`, `landmarks_XXX.lnd` and `truth_XXX.ply` (any `bodyspace synth` output, the
//! scanner zoo's too). `--fits CACHE` keeps each fit (`CACHE/{landmarks,given10,free}_XXX.ply` at
//! `base`, `…_fine_XXX.ply` at `fine`; template frame, metres) and reuses it when it is there,
//! so the measurements of one set of fits can be compared before and after a change of the
//! measurements alone. Prints per kind of fit and measurement: the mean difference (fit − truth),
//! sd, MAE, the 95 % interval of the mean (mean ± 1.96·sd/√n), the ISO 20685-1 limit and
//! verdict; then how many of the judged measurements are within the standard and the mean MAE
//! over them (each subject's differences go to stderr); then the trust the subject report gives
//! each measurement (`measure/trust.rs`) against the truth: its verdicts, the mean expected error
//! against the MAE, the doubtful ones that were within the limit and the trusted ones that were
//! out (the cache keeps beside each fit what its trust is judged from, `….support.json`: the
//! landmarks' origins and the fit's distances to the scan; each body-defined measurement's support
//! per subject goes to stderr); with `--from both` or `all`, the fit's own error of each
//! measurement in `measure/fit_error.csv`'s format (its MAE over the fits its support did not
//! call doubtful, from the true landmarks and landmark-free); and per subject how far below the true crown the scan's highest point lies (the
//! scanner's cut: the fit's crown there is the alignment's extrapolation), and the time to
//! measure one fit natively.

#[cfg(not(target_arch = "wasm32"))]
#[path = "../tests/synth_support/partial.rs"]
#[allow(dead_code)]
mod partial;

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use super::partial::PARTIAL_FILES;
    use bodyspace::cli::model::{measure_any_frame, read_fit};
    use bodyspace::io::{read_scan, write_ply};
    use bodyspace::measure::{
        upright, Agreement, BodyMeasurer, Measure, MeasureParams, MeasurementTrust, Measurements,
        Origin, Trust, TrustParams,
    };
    use bodyspace::mesh::similarity::similarity;
    use bodyspace::mesh::units::detect_units;
    use bodyspace::mesh::{bounding_extent, Mesh};
    use bodyspace::subject::{fit_measurements_trust, fit_subject, read_subject, SubjectOptions};
    use bodyspace::template::{Resolution, Template};
    use std::path::{Path, PathBuf};

    /// The ten landmarks of the `given10` fits: issue 31's partial file, as the tests hold it.
    fn given10() -> &'static [&'static str] {
        PARTIAL_FILES
            .iter()
            .find(|(name, _)| *name == "issue-10")
            .map(|(_, names)| *names)
            .expect("the tests' partial files hold issue 31's ten")
    }

    #[derive(Clone, Copy, PartialEq)]
    enum From {
        Landmarks,
        Given10,
        Free,
    }

    impl From {
        fn name(self) -> &'static str {
            match self {
                From::Landmarks => "landmarks",
                From::Given10 => "given10",
                From::Free => "free",
            }
        }
        fn title(self) -> &'static str {
            match self {
                From::Landmarks => "fit from the true landmarks",
                From::Given10 => "fit from 10 true landmarks (the rest estimated)",
                From::Free => "landmark-free fit",
            }
        }
    }

    struct Options {
        dir: PathBuf,
        n: Option<usize>,
        cache: Option<PathBuf>,
        from: Vec<From>,
        resolution: Resolution,
    }

    fn parse() -> Result<Options, String> {
        let mut args = std::env::args().skip(1);
        let dir = PathBuf::from(args.next().ok_or("usage: measure_accuracy DIR [options]")?);
        let mut o = Options {
            dir,
            n: None,
            cache: None,
            from: vec![From::Landmarks, From::Free],
            resolution: Resolution::Base,
        };
        while let Some(flag) = args.next() {
            let value = args.next().ok_or(format!("{flag} needs a value"))?;
            match flag.as_str() {
                "--n" => o.n = Some(value.parse().map_err(|e| format!("--n: {e}"))?),
                "--fits" => o.cache = Some(PathBuf::from(value)),
                "--from" => {
                    o.from = match value.as_str() {
                        "landmarks" => vec![From::Landmarks],
                        "given10" => vec![From::Given10],
                        "free" => vec![From::Free],
                        "both" => vec![From::Landmarks, From::Free],
                        "all" => vec![From::Landmarks, From::Given10, From::Free],
                        _ => {
                            return Err(format!(
                                "--from {value}: landmarks, given10, free, both or all"
                            ))
                        }
                    }
                }
                "--resolution" => o.resolution = value.parse().map_err(|e| format!("{e}"))?,
                _ => return Err(format!("unknown option {flag}")),
            }
        }
        Ok(o)
    }

    fn bytes(path: &Path) -> Result<Vec<u8>, String> {
        std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))
    }

    /// One measurement's trust: (trust, expected error E in mm, chance P over the limit,
    /// doubtful, doubtful by its support).
    type TrustRow = (String, Option<f64>, Option<f64>, bool, bool);

    /// What the trust of a fit is judged from, kept beside a cached fit (`….support.json`):
    /// where each CAESAR landmark came from and each base vertex's distance to the scan (mm).
    #[derive(serde::Serialize, serde::Deserialize)]
    struct Judged {
        origins: Vec<Origin>,
        distances_mm: Vec<f32>,
    }

    /// The fit of subject `id` at `template`'s resolution (`base` given at `fine`; template
    /// frame, metres) and its measurements' trust (`subject::fit_measurements_trust`, the rule
    /// the subject report uses, judged anew on a cached fit), from the cache or fitted now.
    fn fit(
        o: &Options,
        (template, base): (&Template, Option<&Template>),
        id: usize,
        from: From,
    ) -> Result<(Vec<nalgebra::Point3<f64>>, Vec<MeasurementTrust>), String> {
        let fine = if base.is_some() { "_fine" } else { "" };
        let base_template = base.unwrap_or(template);
        let nb = base_template.mesh().vertex_count();
        let trust = |positions: &[nalgebra::Point3<f64>], judged: &Judged| {
            let distances: Vec<f64> = judged
                .distances_mm
                .iter()
                .map(|&d| d as f64 * 1e-3)
                .collect();
            fit_measurements_trust(
                base_template,
                positions,
                &distances,
                &judged.origins,
                &TrustParams::default(),
            )
        };
        let cached = o
            .cache
            .as_ref()
            .map(|c| c.join(format!("{}{fine}_{id:03}.ply", from.name())));
        let judged_path = cached.as_ref().map(|p| p.with_extension("support.json"));
        if let (Some(path), Some(judged)) = (
            cached.as_ref().filter(|p| p.exists()),
            judged_path.as_ref().filter(|p| p.exists()),
        ) {
            let judged: Judged =
                serde_json::from_slice(&bytes(judged)?).map_err(|e| e.to_string())?;
            let positions = read_fit(path)?.positions;
            let rows = trust(&positions, &judged);
            return Ok((positions, rows));
        }
        let scan_path = o.dir.join(format!("scan_{id:03}.ply"));
        let lnd_path = o.dir.join(format!("landmarks_{id:03}.lnd"));
        let scan = bytes(&scan_path)?;
        let lnd = bytes(&lnd_path)?;
        let landmarks = (from != From::Free).then(|| (&lnd[..], "landmarks.lnd"));
        let mut input = read_subject((&scan, &scan_path.display().to_string()), landmarks, None)
            .map_err(|e| e.to_string())?;
        if let (From::Given10, Some(given)) = (from, input.given.as_mut()) {
            given
                .set
                .landmarks
                .retain(|l| given10().contains(&l.name.as_str()));
        }
        let fitted = fit_subject(
            template,
            base,
            &input,
            None,
            &SubjectOptions::default(),
            &mut (),
        )
        .map_err(|e| e.to_string())?;
        let positions = fitted.positions_in_template_frame();
        let judged = Judged {
            origins: fitted.landmark_origins.clone(),
            distances_mm: fitted.alignment.per_vertex_distance[..nb]
                .iter()
                .map(|&d| (d * 1e3) as f32)
                .collect(),
        };
        let rows = fitted.report.measurement_trust.clone();
        if let (Some(path), Some(judged_path)) = (cached, judged_path) {
            let mesh = Mesh::new(positions.clone(), template.mesh().triangles.clone());
            std::fs::write(&path, write_ply(&mesh))
                .map_err(|e| format!("{}: {e}", path.display()))?;
            let text = serde_json::to_vec(&judged).map_err(|e| e.to_string())?;
            std::fs::write(&judged_path, text)
                .map_err(|e| format!("{}: {e}", judged_path.display()))?;
        }
        Ok((positions, rows))
    }

    /// A measurement's trust as the table counts it.
    fn row(t: &MeasurementTrust) -> TrustRow {
        (
            trust_name(t.trust),
            t.expected_error_mm,
            t.chance_over_limit,
            t.doubtful,
            t.support.as_ref().is_some_and(|s| s.doubtful),
        )
    }

    /// Each body-defined measurement's support on one fit, on stderr: the unsupported share,
    /// the largest distance (mm) and the verdict.
    fn support_lines(from: From, id: usize, trust: &[MeasurementTrust]) {
        let parts: Vec<String> = trust
            .iter()
            .filter_map(|t| {
                let s = t.support.as_ref()?;
                Some(format!(
                    "{} {:.0} % of {} ≤ {:.0} mm{}",
                    t.name,
                    100.0 * s.unsupported_share,
                    s.vertices,
                    s.max_distance_mm,
                    if s.doubtful { " doubtful" } else { "" }
                ))
            })
            .collect();
        eprintln!("{} {id:03} support: {}", from.name(), parts.join("; "));
    }

    fn trust_name(t: Trust) -> String {
        serde_json::to_value(t)
            .ok()
            .and_then(|v| v.as_str().map(String::from))
            .unwrap_or_default()
    }

    /// The trust the reports gave each measurement against the truth: the verdicts (placed,
    /// body-defined, estimated; doubtful), the mean expected error E against the MAE, the mean
    /// chance P of an error over the limit against the share of subjects over it, the doubtful
    /// ones within the limit (false alarms) and the trusted ones out of it (false trust), counted
    /// per subject.
    fn trust_table(title: &str, rows: &[(Measurements, Measurements)], trust: &[Vec<TrustRow>]) {
        println!("\n{title}: each measurement's trust against the truth");
        println!(
            "| measurement | limit (mm) | verdicts | E (mm) | MAE (mm) | P | over the limit | doubtful but within | trusted but out |"
        );
        println!("| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: |");
        let (mut alarms, mut doubtful_total, mut missed, mut trusted_total) = (0, 0, 0, 0);
        for m in Measure::ALL {
            let Some(class) = m.iso_class() else {
                continue;
            };
            let limit = class.limit();
            let mut verdicts = std::collections::BTreeMap::<String, usize>::new();
            let (mut e_sum, mut e_n, mut abs_sum, mut n) = (0.0, 0, 0.0, 0);
            let (mut p_sum, mut p_n, mut over) = (0.0, 0, 0);
            let (mut alarm, mut miss) = (0, 0);
            for ((fit, truth), t) in rows.iter().zip(trust) {
                let (name, e, p, doubtful, _) = &t[m.index()];
                if let Some(p) = p {
                    p_sum += p;
                    p_n += 1;
                }
                let key = if *doubtful {
                    format!("{name}, doubtful")
                } else {
                    name.clone()
                };
                *verdicts.entry(key).or_default() += 1;
                if let Some(e) = e {
                    e_sum += e;
                    e_n += 1;
                }
                let Some(d) = fit.get(m).zip(truth.get(m)).map(|(f, t)| (f - t).abs()) else {
                    continue;
                };
                abs_sum += d;
                n += 1;
                over += usize::from(d > limit);
                if *doubtful {
                    doubtful_total += 1;
                    alarm += usize::from(d <= limit);
                } else {
                    trusted_total += 1;
                    miss += usize::from(d > limit);
                }
            }
            alarms += alarm;
            missed += miss;
            let verdicts: Vec<String> = verdicts.iter().map(|(k, c)| format!("{c} {k}")).collect();
            let e = if e_n > 0 {
                format!("{:.1}", e_sum / e_n as f64)
            } else {
                "—".into()
            };
            let p = if p_n > 0 {
                format!("{:.0} %", 100.0 * p_sum / p_n as f64)
            } else {
                "—".into()
            };
            println!(
                "| {} | {:.0} | {} | {e} | {:.1} | {p} | {over} of {n} | {alarm} | {miss} |",
                m.definition().name,
                limit * 1e3,
                verdicts.join("; "),
                abs_sum / n.max(1) as f64 * 1e3
            );
        }
        println!(
            "{title}: doubtful {doubtful_total}, of them within the limit {alarms}; trusted \
             {trusted_total}, of them out of the limit {missed} (subject × measurement)"
        );
    }

    /// Each measurement's MAE (mm) over the fits its support did not call doubtful: the fit's
    /// own error, `measure/fit_error.csv`'s column for this kind of fit; `None` without a limit.
    fn own_error(
        rows: &[(Measurements, Measurements)],
        trust: &[Vec<TrustRow>],
    ) -> Vec<Option<f64>> {
        Measure::ALL
            .into_iter()
            .map(|m| {
                m.iso_class()?;
                let d: Vec<f64> = rows
                    .iter()
                    .zip(trust)
                    .filter(|(_, t)| !t[m.index()].4)
                    .filter_map(|((fit, truth), _)| Some((fit.get(m)? - truth.get(m)?).abs()))
                    .collect();
                Some(d.iter().sum::<f64>() / d.len().max(1) as f64 * 1e3)
            })
            .collect()
    }

    /// How far below the true crown the scan's highest point lies (mm): both moved by the rigid
    /// motion that brings the truth onto the template (y up).
    fn crown_cut_mm(o: &Options, template: &Template, id: usize) -> Result<f64, String> {
        let read = |stem: &str| {
            let path = o.dir.join(format!("{stem}_{id:03}.ply"));
            read_scan(&bytes(&path)?, &path.display().to_string()).map_err(|e| e.to_string())
        };
        let (truth, scan) = (read("truth")?, read("scan")?);
        // The scan is in its truth's units.
        let to_m = detect_units(bounding_extent(&truth.positions)).scale_to_metres();
        let base: Vec<_> = truth.positions[..template.mesh().vertex_count()]
            .iter()
            .map(|p| p * to_m)
            .collect();
        let rigid =
            similarity(&base, &template.mesh().positions, false).ok_or("degenerate truth")?;
        let top = |ps: &mut dyn Iterator<Item = nalgebra::Point3<f64>>| {
            ps.map(|p| rigid.apply(&p).y)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        let truth_top = top(&mut base.iter().copied());
        let scan_top = top(&mut scan.positions.iter().map(|p| p * to_m));
        Ok((truth_top - scan_top) * 1e3)
    }

    fn table(title: &str, rows: &[(Measurements, Measurements)]) {
        // Each subject's differences, for finding the one behind a large sd.
        for (i, (fit, truth)) in rows.iter().enumerate() {
            let d: Vec<String> = Measure::ALL
                .iter()
                .filter(|m| m.iso_class().is_some())
                .map(|&m| match (fit.get(m), truth.get(m)) {
                    (Some(f), Some(t)) => format!("{:+.1}", (f - t) * 1e3),
                    _ => "—".into(),
                })
                .collect();
            eprintln!("{title}, subject {:03} (mm): {}", i + 1, d.join(" "));
        }
        println!("\n{title}: {} subjects", rows.len());
        println!(
            "| measurement | limit (mm) | mean (mm) | sd (mm) | MAE (mm) | 95 % interval (mm) | ISO 20685-1 |"
        );
        println!("| --- | ---: | ---: | ---: | ---: | ---: | --- |");
        let (mut within, mut judged, mut mae_sum) = (0, 0, 0.0);
        for m in Measure::ALL {
            let Some(class) = m.iso_class() else {
                continue;
            };
            let d: Vec<f64> = rows
                .iter()
                .filter_map(|(fit, truth)| Some(fit.get(m)? - truth.get(m)?))
                .collect();
            let Some(a) = Agreement::of(&d) else {
                println!("| {} | — | not taken | | | | |", m.definition().name);
                continue;
            };
            let limit = class.limit();
            let ok = a.within(limit) && a.n == rows.len();
            judged += 1;
            within += usize::from(ok);
            mae_sum += a.mae;
            println!(
                "| {} | {:.0} | {:+.1} | {:.1} | {:.1} | {:+.1} … {:+.1} | {} |",
                m.definition().name,
                limit * 1e3,
                a.mean * 1e3,
                a.sd * 1e3,
                a.mae * 1e3,
                (a.mean - a.half_interval) * 1e3,
                (a.mean + a.half_interval) * 1e3,
                if ok { "within" } else { "**outside**" }
            );
        }
        println!(
            "{title}: within ISO 20685-1 {within} of {judged}; mean MAE {:.2} mm",
            mae_sum / judged.max(1) as f64 * 1e3
        );
    }

    pub fn main() -> Result<(), String> {
        let o = parse()?;
        if let Some(c) = &o.cache {
            std::fs::create_dir_all(c).map_err(|e| format!("{}: {e}", c.display()))?;
        }
        let template = Template::embedded().map_err(|e| e.to_string())?;
        let fine =
            (o.resolution == Resolution::Fine).then(|| template.at_resolution(Resolution::Fine));
        let fitting = match &fine {
            Some(f) => (f, Some(&template)),
            None => (&template, None),
        };
        let measurer = BodyMeasurer::of_template(&template, MeasureParams::default())
            .map_err(|e| e.to_string())?;
        let population = std::fs::read_to_string(o.dir.join("subjects.json")).unwrap_or_default();
        let about: serde_json::Value = serde_json::from_str(&population).unwrap_or_default();
        println!(
            "population: profile {}, seed {}; fits at {}",
            about["profile"],
            about["seed"],
            o.resolution.name()
        );
        let found = (1..)
            .take_while(|id| o.dir.join(format!("truth_{id:03}.ply")).exists())
            .count();
        let n = o.n.unwrap_or(found).min(found);
        if n == 0 {
            return Err(format!("{}: no truth_001.ply", o.dir.display()));
        }
        let mut truths = Vec::with_capacity(n);
        let mut cuts = Vec::with_capacity(n);
        for id in 1..=n {
            let truth = read_fit(&o.dir.join(format!("truth_{id:03}.ply")))?;
            truths.push(measure_any_frame(&measurer, &template, &truth.positions)?);
            cuts.push(crown_cut_mm(&o, &template, id)?);
        }
        println!(
            "the scan's highest point below the true crown (mm), per subject: {}",
            cuts.iter()
                .map(|c| format!("{c:.1}"))
                .collect::<Vec<_>>()
                .join(", ")
        );
        let mut times = Vec::new();
        let mut own = Vec::new();
        for &from in &o.from {
            let mut rows = Vec::with_capacity(n);
            let mut trust = Vec::with_capacity(n);
            for (id, truth) in (1..=n).zip(&truths) {
                let started = std::time::Instant::now();
                let (positions, trusted) = fit(&o, fitting, id, from)?;
                support_lines(from, id, &trusted);
                trust.push(trusted.iter().map(row).collect());
                // The base vertices come first at `fine`: measured on them, as `bodyspace measure` does.
                let positions = &positions[..template.mesh().vertex_count()];
                let stood = upright(positions, &template.mesh().positions)
                    .ok_or("the fit could not be brought onto the template")?;
                let measuring = std::time::Instant::now();
                let fitted = measurer.measure(&stood).map_err(|e| e.to_string())?;
                times.push(measuring.elapsed().as_secs_f64() * 1e3);
                eprintln!(
                    "{} {id:03}: {:.1} s",
                    from.name(),
                    started.elapsed().as_secs_f64()
                );
                rows.push((fitted, truth.clone()));
            }
            table(from.title(), &rows);
            trust_table(from.title(), &rows, &trust);
            own.push((from, own_error(&rows, &trust)));
        }
        let column = |f: From| own.iter().find(|(from, _)| *from == f).map(|(_, e)| e);
        if let (Some(placed), Some(free)) = (column(From::Landmarks), column(From::Free)) {
            println!(
                "\nthe fit's own error (MAE of the supported fits, mm; measure/fit_error.csv):"
            );
            println!("measurement,placed_mm,estimated_mm");
            for m in Measure::ALL {
                if let (Some(p), Some(e)) = (placed[m.index()], free[m.index()]) {
                    println!("{},{p:.2},{e:.2}", m.definition().name);
                }
            }
        }
        times.sort_by(f64::total_cmp);
        println!(
            "\nmeasuring one upright fit (all {}): median {:.2} ms, max {:.2} ms natively",
            Measure::ALL.len(),
            times[times.len() / 2],
            times[times.len() - 1]
        );
        Ok(())
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    if let Err(e) = native::main() {
        eprintln!("measure_accuracy: {e}");
        std::process::exit(1);
    }
}

#[cfg(target_arch = "wasm32")]
fn main() {}
